//! Copy-paste of gradients (Guérin et al. 2022, §4.1): a rectangle of the procedural world is
//! copied, rotated and scaled, and its gradients replace the target gradient of the heights over
//! the pasted footprint. The reconstruction blends the paste seamlessly into its surroundings,
//! as in Poisson image editing: elevations are matched across the footprint's boundary, only the
//! gradients are carried over.
//!
//! Mapping: a point `p` of the footprint reads the source at `c_s + R(−θ)(p − c_t)/s` for the
//! source centre `c_s`, the target centre `c_t`, the rotation `θ` (from +x toward +z: clockwise
//! on a north-up map) and the scale `s`. Heights are copied, not scaled, so the pasted gradient is
//! `R(θ)·∇h_src / s`. An optional smooth [`Warp`] displaces `p` before the mapping. The source is the procedural world of this world or of another seed
//! (before any edit; [`PasteSource::sample`]), or an uploaded PNG16 heightmap
//! ([`PasteSource::from_image`]), resampled on a square grid at the target's spacing over the
//! scale.

use super::exchange::Image;
use super::grid::{Procedural, RegionGrid};
use super::raster::Canvas;
use crate::terrain::cancel::{Cancel, Cancelled};
use crate::terrain::hash::stream;
use crate::terrain::noise::lattice;
use crate::terrain::WorldPlan;

/// Most samples per side of a paste's source grid; a larger source is sampled more coarsely.
pub const MAX_SOURCE_SAMPLES: usize = 2049;

/// The procedural heights of a paste's source rectangle.
#[derive(Clone, Debug, PartialEq)]
pub struct PasteSource {
    /// The source grid (square, from the rectangle's west-north corner).
    pub grid: RegionGrid,
    /// Heights at the grid's samples, metres, row-major.
    pub heights: Vec<f32>,
    /// The source rectangle's centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Half the source rectangle's width and depth, metres.
    pub half: [f64; 2],
}

impl PasteSource {
    /// Samples the world's procedural heights over `min..max` every `spacing_m` (coarser if
    /// that needs more than [`MAX_SOURCE_SAMPLES`] per side).
    pub fn sample(plan: &WorldPlan, min: [f64; 2], max: [f64; 2], spacing_m: f64) -> Self {
        let grid = source_grid(min, max, spacing_m);
        Self::over(grid, Procedural::sample(plan, &grid).heights)
    }

    /// [`Self::sample`], polling `cancel` while the world is sampled
    /// ([`Procedural::sample_on`]).
    ///
    /// # Errors
    /// [`Cancelled`] once `cancel` is set.
    pub fn sample_on(
        plan: &WorldPlan,
        min: [f64; 2],
        max: [f64; 2],
        spacing_m: f64,
        cancel: &Cancel,
    ) -> Result<Self, Cancelled> {
        let grid = source_grid(min, max, spacing_m);
        Ok(Self::over(
            grid,
            Procedural::sample_on(plan, &grid, cancel)?.heights,
        ))
    }

    /// Resamples (bilinearly, clamped at its edges) a heightmap image whose pixels lie
    /// `image_spacing_m` apart from `[0, 0]` at its west-north pixel, over `min..max` (metres in
    /// the image) every `spacing_m` (coarser past [`MAX_SOURCE_SAMPLES`] per side).
    pub fn from_image(
        img: &Image<Vec<f32>>,
        image_spacing_m: f64,
        min: [f64; 2],
        max: [f64; 2],
        spacing_m: f64,
    ) -> Self {
        let grid = source_grid(min, max, spacing_m);
        let (w, h) = (img.width, img.height);
        let at = |i: usize, j: usize| f64::from(img.values[j.min(h - 1) * w + i.min(w - 1)]);
        let mut heights = Vec::with_capacity(grid.n * grid.n);
        for j in 0..grid.n {
            for i in 0..grid.n {
                let p = grid.position(i, j);
                let u = (p[0] / image_spacing_m).clamp(0.0, (w - 1) as f64);
                let v = (p[1] / image_spacing_m).clamp(0.0, (h - 1) as f64);
                let (iu, iv) = (u.floor() as usize, v.floor() as usize);
                let (fu, fv) = (u - iu as f64, v - iv as f64);
                let top = at(iu, iv) * (1.0 - fu) + at(iu + 1, iv) * fu;
                let bottom = at(iu, iv + 1) * (1.0 - fu) + at(iu + 1, iv + 1) * fu;
                heights.push((top * (1.0 - fv) + bottom * fv) as f32);
            }
        }
        Self::over(grid, heights)
    }

    fn over(grid: RegionGrid, heights: Vec<f32>) -> Self {
        let (min, max) = (grid.origin, grid.max);
        Self {
            grid,
            heights,
            center: [0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1])],
            half: [0.5 * (max[0] - min[0]), 0.5 * (max[1] - min[1])],
        }
    }

    /// Bilinear source height at a world position (clamped to the grid), metres.
    pub fn height(&self, p: [f64; 2]) -> f64 {
        let g = &self.grid;
        let (u, v) = g.grid_coords(p[0], p[1]);
        crate::terrain::lattice::bilinear_clamped(&self.heights, g.n, g.n, u, v)
    }
}

/// The square grid a source rectangle is sampled on.
fn source_grid(min: [f64; 2], max: [f64; 2], spacing_m: f64) -> RegionGrid {
    let extent = (max[0] - min[0]).max(max[1] - min[1]);
    let wanted = (extent / spacing_m).ceil() as usize + 2;
    let n = wanted.clamp(2, MAX_SOURCE_SAMPLES);
    let spacing_m = if wanted > MAX_SOURCE_SAMPLES {
        extent / (n - 2) as f64
    } else {
        spacing_m
    };
    RegionGrid {
        origin: min,
        spacing_m,
        n,
        max,
    }
}

/// Hash purpose of the paste warp's noise.
const WARP_PURPOSE: u32 = 0x4a_0004;

/// A smooth warp of the paste's footprint (the paper's "warping as needed to fit the
/// destination terrain", §1): the target point `p` reads the source as if it were at
/// `p + amplitude·(n₁(p/λ), n₂(p/λ))`, `n₁`, `n₂` two lattice noises of unit variance hashed
/// from the world seed and the operation's seed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Warp {
    /// Displacement amplitude, metres (0: no warp).
    pub amplitude_m: f64,
    /// Wavelength of the displacement field, metres.
    pub wavelength_m: f64,
    /// Hash stream of the two noises.
    pub stream: u32,
}

impl Warp {
    /// A warp of `amplitude_m` and `wavelength_m` whose noise is hashed from the world seed and
    /// `seed`.
    pub fn new(world_seed: u64, seed: u32, amplitude_m: f64, wavelength_m: f64) -> Self {
        Self {
            amplitude_m,
            wavelength_m,
            stream: stream(world_seed, WARP_PURPOSE, seed),
        }
    }

    /// The warped position of `p`.
    pub fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        if self.amplitude_m == 0.0 {
            return p;
        }
        let (u, v) = (
            (p[0] / self.wavelength_m) as f32,
            (p[1] / self.wavelength_m) as f32,
        );
        [
            p[0] + self.amplitude_m * f64::from(lattice(u, v, self.stream)),
            p[1] + self.amplitude_m * f64::from(lattice(u, v, self.stream ^ 0x9e37_79b9)),
        ]
    }
}

/// Where the pasted copy lies: target centre, rotation, scale and warp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Centre of the pasted copy `[x, z]`, metres.
    pub target: [f64; 2],
    /// Rotation, degrees (from +x toward +z).
    pub rotation_deg: f64,
    /// Horizontal scale of the copy.
    pub scale: f64,
    /// Warp of the footprint.
    pub warp: Warp,
}

impl Placement {
    /// The source position a target point reads, and whether it lies in the source rectangle.
    pub fn source_of(&self, src: &PasteSource, p: [f64; 2]) -> ([f64; 2], bool) {
        let p = self.warp.apply(p);
        let (s, c) = self.rotation_deg.to_radians().sin_cos();
        let l = [p[0] - self.target[0], p[1] - self.target[1]];
        let local = [
            (c * l[0] + s * l[1]) / self.scale,
            (-s * l[0] + c * l[1]) / self.scale,
        ];
        let inside = local[0].abs() <= src.half[0] && local[1].abs() <= src.half[1];
        ([src.center[0] + local[0], src.center[1] + local[1]], inside)
    }
}

impl Canvas {
    /// Copy-paste: on every edge whose two ends fall in the pasted footprint, the target
    /// gradient of the heights becomes the source's height difference along the mapped edge
    /// over the edge's length (soft, replacing).
    pub fn paste(&mut self, src: &PasteSource, at: &Placement) {
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, _, (a, b)| {
            let n = c.grid.n;
            let (sa, ina) = at.source_of(src, c.grid.position(a % n, a / n));
            let (sb, inb) = at.source_of(src, c.grid.position(b % n, b / n));
            if !(ina && inb) {
                return;
            }
            let target = (src.height(sb) - src.height(sa)) * inv;
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (target - proc) as f32;
        });
    }
}
