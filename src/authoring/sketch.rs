//! The coarse sketch (issue 17 item 9): a low-resolution PNG16 base height field a designer
//! uploads (continents, ranges, seas) as the `sketch` operation of a region.
//!
//! The image spans the region's `bbox`, its corner pixels' centres on the bbox's corners, value
//! 0 → `min_m` and 65535 → `max_m`. At every region sample the operation targets the displacement
//!
//! `D(p) = w(p) · (sketch(p) − low(p))`
//!
//! where `sketch(p)` is the image interpolated bilinearly, `low(p)` the world's own heights
//! averaged over one sketch pixel's footprint centred on `p` (the low-pass of the procedural
//! field at the sketch's resolution: on `earth-1` the continents and the mountain belts, on a
//! classic world its biomes' large shapes) and `w` a smoothstep taper from 0 on the bbox edge
//! to 1 at `blend_m` inside it. Subtracting the low-pass rather than a model of it makes the
//! result's low-pass the sketch's, whatever the generator. The operation is soft: it adds the
//! gradient of `D` to the region's target gradient, so alone it reconstructs `D` (which is 0 on
//! the border, as the region's `d` is), and later operations (a mountain range, an elevation
//! constraint) edit on top of it. The world's detail below the pixel scale (relief, gullies, the
//! erosion filter) stays in the procedural heights the displacement is added to, so tiles show
//! the sketch's large shape with the world's detail, at every LOD and with the region's seams,
//! caching and invalidation. The climate (biomes, their erosion and roughness) still follows the
//! world's own large-scale elevation, not the sketch's.

use super::grid::MAX_LATTICE_SAMPLES;
use super::raster::Canvas;
use super::spec::{err, finite_in, SpecError, MAX_ELEVATION_M};
use super::spec_tools::Heightmap;
use crate::terrain::plan::MAX_LOD;
use crate::terrain::tile::{field, FieldJob};
use crate::terrain::WorldPlan;

/// Most pixels a side of a sketch.
pub const MAX_SKETCH_SIDE: usize = 1025;
/// Largest width or depth of a sketch's bbox, metres.
pub const MAX_SKETCH_M: f64 = 262_144.0;
/// Widest taper, metres.
pub const MAX_BLEND_M: f64 = 65_536.0;

/// A decoded sketch: `width × height` heights, metres, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Sketch {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Heights, metres.
    pub values: Vec<f32>,
}

/// Decodes a sketch's PNG16.
///
/// # Errors
/// Why the text is not a base64 16-bit greyscale PNG of 2 to [`MAX_SKETCH_SIDE`] pixels a side.
pub fn decode(png_base64: &str, min_m: f64, max_m: f64) -> Result<Sketch, String> {
    let h = Heightmap {
        png_base64: png_base64.to_owned(),
        lo_m: min_m,
        hi_m: max_m,
        spacing_m: 1.0,
    };
    let img = h.decode()?;
    if img.width > MAX_SKETCH_SIDE || img.height > MAX_SKETCH_SIDE {
        return Err(format!(
            "a sketch has at most {MAX_SKETCH_SIDE} pixels a side, got {}×{}",
            img.width, img.height
        ));
    }
    Ok(Sketch {
        width: img.width,
        height: img.height,
        values: img.values,
    })
}

/// Validates a `sketch` operation at `at` (`/ops/0`) of a region with bbox `min`..`max`.
pub fn validate(
    at: &str,
    op: (&str, f64, f64, f64),
    min: [f64; 2],
    max: [f64; 2],
) -> Result<(), SpecError> {
    let (png_base64, min_m, max_m, blend_m) = op;
    for k in 0..2 {
        if max[k] - min[k] > MAX_SKETCH_M {
            return Err(err(
                format!("/bbox/max/{k}"),
                format!("a sketch's region is at most {MAX_SKETCH_M} m wide and deep"),
            ));
        }
    }
    finite_in(
        format!("{at}/min_m"),
        min_m,
        -MAX_ELEVATION_M,
        MAX_ELEVATION_M,
    )?;
    finite_in(
        format!("{at}/max_m"),
        max_m,
        -MAX_ELEVATION_M,
        MAX_ELEVATION_M,
    )?;
    if max_m < min_m {
        return Err(err(format!("{at}/max_m"), "must not be less than min_m"));
    }
    finite_in(format!("{at}/blend_m"), blend_m, 0.0, MAX_BLEND_M)?;
    decode(png_base64, min_m, max_m)
        .map(|_| ())
        .map_err(|e| err(format!("{at}/png_base64"), e))
}

/// The smoothstep taper at `p`: 0 on the bbox edge, 1 from `blend_m` inside it.
pub(super) fn taper(p: [f64; 2], min: [f64; 2], max: [f64; 2], blend_m: f64) -> f64 {
    let inside = (p[0] - min[0])
        .min(max[0] - p[0])
        .min(p[1] - min[1])
        .min(max[1] - p[1]);
    if inside <= 0.0 {
        return 0.0;
    }
    if inside >= blend_m {
        return 1.0;
    }
    let t = inside / blend_m;
    t * t * (3.0 - 2.0 * t)
}

impl Sketch {
    /// The sketch's height at world `p` over the bbox `min`..`max`: bilinear between pixel
    /// centres, the corner pixels on the bbox's corners, clamped at the edges.
    pub fn at(&self, p: [f64; 2], min: [f64; 2], max: [f64; 2]) -> f64 {
        let coord = |k: usize, size: usize| {
            let span = max[k] - min[k];
            let last = (size - 1) as f64;
            let u = if span > 0.0 {
                (p[k] - min[k]) / span * last
            } else {
                0.0
            };
            let u = u.clamp(0.0, last);
            let i = (u.floor() as usize).min(size - 2);
            (i, u - i as f64)
        };
        let (i, fu) = coord(0, self.width);
        let (j, fv) = coord(1, self.height);
        let s = |i: usize, j: usize| f64::from(self.values[j * self.width + i]);
        crate::terrain::lattice::lerp2(s(i, j), s(i + 1, j), s(i, j + 1), s(i + 1, j + 1), fu, fv)
    }
}

/// The world's heights averaged over a sketch pixel's footprint, at world positions: a
/// summed-area table of one LOD's lattice over the bbox (the finest with at most
/// [`MAX_LATTICE_SAMPLES`] samples, and no finer than an eighth of a pixel).
pub(super) struct LowPass {
    step: f64,
    gx0: i64,
    gz0: i64,
    w: usize,
    h: usize,
    /// `(w + 1) × (h + 1)` prefix sums.
    sums: Vec<f64>,
    /// Half the pixel's footprint `[x, z]`, metres.
    half: [f64; 2],
}

impl LowPass {
    pub(super) fn new(plan: &WorldPlan, min: [f64; 2], max: [f64; 2], pixel: [f64; 2]) -> Self {
        let half = [0.5 * pixel[0], 0.5 * pixel[1]];
        let rect = |lod: u32| {
            let step = f64::from(plan.lods[lod as usize].spacing_m);
            let gx0 = ((min[0] - half[0]) / step).floor() as i64;
            let gz0 = ((min[1] - half[1]) / step).floor() as i64;
            let w = (((max[0] + half[0]) / step).ceil() as i64 - gx0 + 1) as usize;
            let h = (((max[1] + half[1]) / step).ceil() as i64 - gz0 + 1) as usize;
            (step, gx0, gz0, w, h)
        };
        let target = pixel[0].min(pixel[1]) / 8.0;
        let mut lod = 0u32;
        while lod < MAX_LOD && f64::from(plan.lods[lod as usize + 1].spacing_m) <= target {
            lod += 1;
        }
        while lod < MAX_LOD && {
            let (.., w, h) = rect(lod);
            w * h > MAX_LATTICE_SAMPLES
        } {
            lod += 1;
        }
        let (step, gx0, gz0, w, h) = rect(lod);
        let f = field(plan, FieldJob::new(lod, gx0, gz0, w, h));
        let mut sums = vec![0.0f64; (w + 1) * (h + 1)];
        for j in 0..h {
            let mut row = 0.0;
            for i in 0..w {
                row += f64::from(f.heights[j * w + i]);
                sums[(j + 1) * (w + 1) + i + 1] = sums[j * (w + 1) + i + 1] + row;
            }
        }
        Self {
            step,
            gx0,
            gz0,
            w,
            h,
            sums,
            half,
        }
    }

    /// The mean of the lattice samples within the pixel footprint centred on `p`.
    pub(super) fn at(&self, p: [f64; 2]) -> f64 {
        let range = |c: f64, half: f64, g0: i64, size: usize| {
            let lo = ((c - half) / self.step).ceil() as i64 - g0;
            let hi = ((c + half) / self.step).floor() as i64 - g0;
            let lo = lo.clamp(0, size as i64 - 1) as usize;
            let hi = (hi.clamp(0, size as i64 - 1) as usize).max(lo);
            (lo, hi + 1)
        };
        let (i0, i1) = range(p[0], self.half[0], self.gx0, self.w);
        let (j0, j1) = range(p[1], self.half[1], self.gz0, self.h);
        let s = |i: usize, j: usize| self.sums[j * (self.w + 1) + i];
        let total = s(i1, j1) - s(i0, j1) - s(i1, j0) + s(i0, j0);
        total / ((i1 - i0) * (j1 - j0)) as f64
    }
}

impl Canvas {
    /// The `sketch` operation: adds the gradient of `D = w · (sketch − low)` (0 at the samples
    /// the region keeps at 0: its border and beyond its bbox) to the target gradient, `low`
    /// being the world's heights averaged over a sketch pixel.
    pub fn sketch(&mut self, plan: &WorldPlan, sketch: &Sketch, blend_m: f64) {
        let g = self.grid;
        let n = g.n;
        let pixel = [
            (g.max[0] - g.origin[0]) / (sketch.width - 1) as f64,
            (g.max[1] - g.origin[1]) / (sketch.height - 1) as f64,
        ];
        let low = LowPass::new(plan, g.origin, g.max, pixel);
        let target: Vec<f64> = (0..n * n)
            .map(|v| {
                let (i, j) = (v % n, v / n);
                if !g.is_interior(i, j) {
                    return 0.0;
                }
                let p = g.position(i, j);
                let w = taper(p, g.origin, g.max, blend_m);
                w * (sketch.at(p, g.origin, g.max) - low.at(p))
            })
            .collect();
        self.add_target_gradient(&target);
    }

    /// Adds the gradient of `target` (heights at the samples, row-major) to the target gradient.
    pub(super) fn add_target_gradient(&mut self, target: &[f64]) {
        let n = self.grid.n;
        let inv = 1.0 / self.grid.spacing_m;
        for j in 0..n {
            for i in 0..n - 1 {
                let a = j * n + i;
                self.gx[j * (n - 1) + i] += ((target[a + 1] - target[a]) * inv) as f32;
            }
        }
        for j in 0..n - 1 {
            for i in 0..n {
                let a = j * n + i;
                self.gz[a] += ((target[a + n] - target[a]) * inv) as f32;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_taper_is_zero_on_the_edge_and_one_inside() {
        let (min, max) = ([0.0, 0.0], [100.0, 50.0]);
        assert_eq!(taper([0.0, 25.0], min, max, 10.0), 0.0);
        assert_eq!(taper([50.0, 50.0], min, max, 10.0), 0.0);
        assert_eq!(taper([50.0, 25.0], min, max, 10.0), 1.0);
        assert!((taper([5.0, 25.0], min, max, 10.0) - 0.5).abs() < 1e-12);
        assert_eq!(taper([5.0, 25.0], min, max, 0.0), 1.0);
    }

    #[test]
    fn the_sketch_is_bilinear_between_pixel_centres() {
        let s = Sketch {
            width: 2,
            height: 2,
            values: vec![0.0, 10.0, 20.0, 30.0],
        };
        let (min, max) = ([0.0, 0.0], [10.0, 10.0]);
        assert_eq!(s.at([0.0, 0.0], min, max), 0.0);
        assert_eq!(s.at([10.0, 10.0], min, max), 30.0);
        assert_eq!(s.at([5.0, 5.0], min, max), 15.0);
        assert_eq!(s.at([-5.0, 20.0], min, max), 20.0);
    }
}
