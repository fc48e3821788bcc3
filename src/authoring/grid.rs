//! A region's grid and the procedural heights beneath it.

use super::spec::RegionSpec;
use crate::terrain::cancel::{Cancel, Cancelled};
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

/// Lattice samples synthesised between two polls of the cancellation flag in
/// [`Procedural::sample_on`]: a band of rows of about this many samples (a few milliseconds).
const BAND_SAMPLES: usize = 1 << 16;

/// The heights of the lattice rectangle `job`, synthesised in bands of whole rows of about
/// [`BAND_SAMPLES`] samples with `cancel` polled before each. The field of a lattice sample
/// does not depend on the rectangle it is synthesised in (tiles sharing an edge agree on it bit
/// for bit), so the bands give the heights of one `field(plan, job)`.
fn lattice_heights(
    plan: &WorldPlan,
    job: FieldJob,
    cancel: &Cancel,
) -> Result<Vec<f32>, Cancelled> {
    let rows = (BAND_SAMPLES / job.w.max(1)).max(1);
    let mut heights = Vec::with_capacity(job.w * job.h);
    for j0 in (0..job.h).step_by(rows) {
        cancel.check()?;
        let band = FieldJob::new(
            job.lod,
            job.gx0,
            job.gz0 + j0 as i64,
            job.w,
            rows.min(job.h - j0),
        );
        heights.extend_from_slice(&field(plan, band).heights);
    }
    Ok(heights)
}

impl Procedural {
    /// Samples the world `plan` beneath `grid`.
    pub fn sample(plan: &WorldPlan, grid: &RegionGrid) -> Self {
        Self::sample_on(plan, grid, &Cancel::never()).expect("Cancel::never is never set")
    }

    /// [`Self::sample`], polling `cancel` between bands of the lattice's rows.
    ///
    /// # Errors
    /// [`Cancelled`] once `cancel` is set.
    pub fn sample_on(
        plan: &WorldPlan,
        grid: &RegionGrid,
        cancel: &Cancel,
    ) -> Result<Self, Cancelled> {
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
        let lattice = lattice_heights(plan, FieldJob::new(lod, gx0, gz0, w, h), cancel)?;
        let at = |i: i64, j: i64| {
            let i = i.clamp(0, w as i64 - 1) as usize;
            let j = j.clamp(0, h as i64 - 1) as usize;
            lattice[j * w + i] as f64
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
        Ok(Self { heights, lod })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::WorldParams;

    #[test]
    fn the_bands_give_the_heights_of_one_field() {
        for params in [WorldParams::classic(), WorldParams::earth()] {
            let plan = WorldPlan::new(42, params).expect("plan");
            for lod in [0, 3] {
                // Rows of 301 samples: bands of 217 rows, the last one short.
                let job = FieldJob::new(lod, -150, 200, 301, 700);
                let banded = lattice_heights(&plan, job, &Cancel::never()).expect("not cancelled");
                assert_eq!(banded, field(&plan, job).heights, "lod {lod}");
            }
        }
    }

    #[test]
    fn a_set_flag_stops_the_sampling() {
        let plan = WorldPlan::new(42, WorldParams::earth()).expect("plan");
        let grid = RegionGrid {
            origin: [0.0, 0.0],
            spacing_m: 1.0,
            n: 1025,
            max: [1024.0, 1024.0],
        };
        let cancel = Cancel::new();
        cancel.cancel();
        assert_eq!(Procedural::sample_on(&plan, &grid, &cancel), Err(Cancelled));
    }
}
