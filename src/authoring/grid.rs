//! A region's grid and the procedural heights beneath it.

use super::spec::RegionSpec;
use crate::terrain::plan::MAX_LOD;
use crate::terrain::tile::{field, FieldJob};
use crate::terrain::WorldPlan;

/// The square sample grid of a region: `n × n` samples from `origin`, `spacing_m` apart; the
/// samples beyond the region's `bbox` (east or south of it) are outside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegionGrid {
    /// World `[x, z]` of sample `(0, 0)`, metres (the bbox's west-north corner).
    pub origin: [f64; 2],
    /// Distance between samples, metres.
    pub spacing_m: f64,
    /// Samples per side, `2^k + 1`.
    pub n: usize,
    /// The bbox's east-south corner `[x, z]`, metres.
    pub max: [f64; 2],
}

impl RegionGrid {
    /// The grid of a region.
    pub fn of(spec: &RegionSpec) -> Self {
        let extent = (spec.max[0] - spec.min[0]).max(spec.max[1] - spec.min[1]);
        Self {
            origin: spec.min,
            spacing_m: extent / (spec.samples - 1) as f64,
            n: spec.samples,
            max: spec.max,
        }
    }

    /// World position of sample `(i, j)`, metres.
    pub fn position(&self, i: usize, j: usize) -> [f64; 2] {
        [
            self.origin[0] + i as f64 * self.spacing_m,
            self.origin[1] + j as f64 * self.spacing_m,
        ]
    }

    /// True where the displacement is free to move: off the grid's border, and far enough inside
    /// the bbox that the next sample east and south is still within it — so the bilinear
    /// displacement is exactly 0 on and beyond the bbox's edges.
    pub fn is_interior(&self, i: usize, j: usize) -> bool {
        let [x, z] = self.position(i, j);
        i > 0
            && j > 0
            && i + 1 < self.n
            && j + 1 < self.n
            && x + self.spacing_m <= self.max[0]
            && z + self.spacing_m <= self.max[1]
    }

    /// Fractional grid coordinates of a world position.
    pub fn grid_coords(&self, x: f64, z: f64) -> (f64, f64) {
        (
            (x - self.origin[0]) / self.spacing_m,
            (z - self.origin[1]) / self.spacing_m,
        )
    }
}

/// Most lattice samples synthesised to sample a region's procedural heights.
pub const MAX_LATTICE_SAMPLES: usize = 1 << 22;

/// Procedural heights at the samples of a region's grid: bilinear interpolation of the world's
/// lattice at the finest LOD whose covering rectangle has at most [`MAX_LATTICE_SAMPLES`] samples
/// (LOD 0, all octaves, for regions up to about 2 km a side at the default 1 m cell), so an
/// elevation constraint placed on a LOD-0 vertex shows there at its elevation.
#[derive(Clone, Debug, PartialEq)]
pub struct Procedural {
    /// Heights at the grid samples, metres, row-major `n × n`.
    pub heights: Vec<f32>,
    /// LOD of the lattice sampled.
    pub lod: u32,
}

impl Procedural {
    /// Samples the world `plan` beneath `grid`.
    pub fn sample(plan: &WorldPlan, grid: &RegionGrid) -> Self {
        let far = grid.position(grid.n - 1, grid.n - 1);
        let rect = |lod: u32| {
            let step = f64::from(plan.lods[lod as usize].spacing_m);
            let gx0 = (grid.origin[0] / step).floor() as i64;
            let gz0 = (grid.origin[1] / step).floor() as i64;
            let w = ((far[0] / step).floor() as i64 - gx0 + 2) as usize;
            let h = ((far[1] / step).floor() as i64 - gz0 + 2) as usize;
            (step, gx0, gz0, w, h)
        };
        let mut lod = 0u32;
        while lod < MAX_LOD && {
            let (.., w, h) = rect(lod);
            w * h > MAX_LATTICE_SAMPLES
        } {
            lod += 1;
        }
        let (step, gx0, gz0, w, h) = rect(lod);
        let f = field(plan, FieldJob::new(lod, gx0, gz0, w, h));
        let at = |i: i64, j: i64| {
            let i = i.clamp(0, w as i64 - 1) as usize;
            let j = j.clamp(0, h as i64 - 1) as usize;
            f.heights[j * w + i] as f64
        };
        let mut heights = Vec::with_capacity(grid.n * grid.n);
        for j in 0..grid.n {
            for i in 0..grid.n {
                let [x, z] = grid.position(i, j);
                let (u, v) = (x / step - gx0 as f64, z / step - gz0 as f64);
                let (iu, iv) = (u.floor(), v.floor());
                let (fu, fv) = (u - iu, v - iv);
                let (iu, iv) = (iu as i64, iv as i64);
                let top = at(iu, iv) * (1.0 - fu) + at(iu + 1, iv) * fu;
                let bottom = at(iu, iv + 1) * (1.0 - fu) + at(iu + 1, iv + 1) * fu;
                heights.push((top * (1.0 - fv) + bottom * fv) as f32);
            }
        }
        Self { heights, lod }
    }
}
