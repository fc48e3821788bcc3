//! The region's sample grid and the slab-parallel helper every stage uses.
//!
//! Shared convention with the mesher ([`crate::volume::mesh`]): a grid has `dims = [nx, ny, nz]`
//! samples, sample `(x, y, z)` is at index `x + nx·(y + ny·z)` and at world position
//! `origin + spacing·(x, y, z)`, y points up, and `S < 0` is inside the solid. Becher et al. speak
//! of voxels (cells); here the cell of a sample is the cube of side `spacing` centred on it, so a
//! "voxel" and a "sample" are the same thing.

use super::PipelineError;
use rayon::prelude::*;

/// Most samples along one axis.
pub const MAX_DIM: usize = 2048;
/// Most samples in one grid (64 Mi: about 1.3 GB of working fields). Larger regions are solved in
/// bricks ([`super::brick`]).
pub const MAX_SAMPLES: usize = 1 << 26;

/// A regular sample grid in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Samples along x, y (up) and z.
    pub dims: [usize; 3],
    /// World position of sample (0, 0, 0), metres.
    pub origin: [f32; 3],
    /// Distance between neighbouring samples, metres.
    pub spacing: f32,
}

impl Grid {
    /// A validated grid.
    ///
    /// # Errors
    /// [`PipelineError::Invalid`] naming `dims`, `spacing` or `origin` when a dimension is below 2
    /// or above [`MAX_DIM`], the sample count exceeds [`MAX_SAMPLES`], the spacing is not a
    /// positive finite number or the origin is not finite.
    pub fn new(dims: [usize; 3], origin: [f32; 3], spacing: f32) -> Result<Self, PipelineError> {
        if dims.iter().any(|&d| !(2..=MAX_DIM).contains(&d)) {
            return Err(PipelineError::invalid(
                "dims",
                format!("every dimension must be in 2..={MAX_DIM}, got {dims:?}"),
            ));
        }
        if dims.iter().product::<usize>() > MAX_SAMPLES {
            return Err(PipelineError::invalid(
                "dims",
                format!("{dims:?} exceeds {MAX_SAMPLES} samples; use bricks"),
            ));
        }
        if !(spacing.is_finite() && spacing > 0.0) {
            return Err(PipelineError::invalid(
                "spacing",
                format!("must be a positive number of metres, got {spacing}"),
            ));
        }
        if origin.iter().any(|o| !o.is_finite()) {
            return Err(PipelineError::invalid("origin", "must be finite"));
        }
        Ok(Self {
            dims,
            origin,
            spacing,
        })
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.dims[0] * self.dims[1] * self.dims[2]
    }

    /// Whether the grid has no samples (never true for a validated grid).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Index of sample `(x, y, z)`.
    #[inline]
    pub fn index(&self, x: usize, y: usize, z: usize) -> usize {
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// `(x, y, z)` of an index.
    #[inline]
    pub fn coords(&self, i: usize) -> [usize; 3] {
        let [nx, ny, _] = self.dims;
        [i % nx, (i / nx) % ny, i / (nx * ny)]
    }

    /// World position of sample `(x, y, z)`, metres.
    #[inline]
    pub fn position(&self, x: usize, y: usize, z: usize) -> [f32; 3] {
        [
            self.origin[0] + self.spacing * x as f32,
            self.origin[1] + self.spacing * y as f32,
            self.origin[2] + self.spacing * z as f32,
        ]
    }

    /// Continuous grid coordinates of a world position (sample units).
    #[inline]
    pub fn to_grid(&self, p: [f32; 3]) -> [f32; 3] {
        let inv = 1.0 / self.spacing;
        [
            (p[0] - self.origin[0]) * inv,
            (p[1] - self.origin[1]) * inv,
            (p[2] - self.origin[2]) * inv,
        ]
    }

    /// Samples in one z-slice.
    pub fn slice_len(&self) -> usize {
        self.dims[0] * self.dims[1]
    }
}

/// Worker threads for the slab-parallel loops: rayon's pool size, at most 16. Results never
/// depend on it (every parallel loop writes disjoint samples from read-only inputs).
pub fn threads() -> usize {
    rayon::current_num_threads().clamp(1, 16)
}

/// Fewest samples for which a slab loop is worth distributing over threads.
const PAR_MIN: usize = 1 << 14;

/// Runs `f(z0, slab)` on disjoint z-slabs of `out` (whole z-slices of `slice` samples each, about
/// two slabs per thread) on rayon's pool. `f` must only read shared inputs.
pub fn par_slabs<T: Send, F>(out: &mut [T], slice: usize, f: F)
where
    F: Fn(usize, &mut [T]) + Sync,
{
    let slice = slice.max(1);
    let nz = out.len() / slice;
    let t = (2 * threads()).min(nz.max(1));
    if t <= 1 || out.len() < PAR_MIN {
        f(0, out);
        return;
    }
    let per = nz.div_ceil(t);
    out.par_chunks_mut(per * slice)
        .enumerate()
        .for_each(|(k, chunk)| f(k * per, chunk));
}

#[inline]
pub(crate) fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub(crate) fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub(crate) fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline]
pub(crate) fn scale(a: [f32; 3], s: f32) -> [f32; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

#[inline]
pub(crate) fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline]
pub(crate) fn length(a: [f32; 3]) -> f32 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or zero for a (near) zero vector.
#[inline]
pub(crate) fn normalize(a: [f32; 3]) -> [f32; 3] {
    let l = length(a);
    if l > 1e-12 {
        scale(a, 1.0 / l)
    } else {
        [0.0; 3]
    }
}

/// [`par_slabs`] for several outputs of the same length: `f(z0, slabs)` gets the same z-slab of
/// every output.
pub fn par_slabs_multi<F>(outs: Vec<&mut [f32]>, slice: usize, f: F)
where
    F: Fn(usize, &mut [&mut [f32]]) + Sync,
{
    let slice = slice.max(1);
    let len = outs.first().map_or(0, |o| o.len());
    let nz = len / slice;
    let t = (2 * threads()).min(nz.max(1));
    if t <= 1 || len < PAR_MIN {
        let mut outs = outs;
        f(0, &mut outs);
        return;
    }
    let per = nz.div_ceil(t);
    let mut slabs: Vec<Vec<&mut [f32]>> = (0..t).map(|_| Vec::new()).collect();
    for o in outs {
        for (k, chunk) in o.chunks_mut(per * slice).enumerate() {
            slabs[k].push(chunk);
        }
    }
    slabs
        .into_par_iter()
        .enumerate()
        .filter(|(_, slab)| !slab.is_empty())
        .for_each(|(k, mut slab)| f(k * per, &mut slab));
}
