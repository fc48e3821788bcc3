//! Basis functions (issue 17 item 9, Schneider et al. §3): a tileable greyscale image that
//! replaces the world's noise lattice in the relief texture at scales up to its period, as the
//! `basis` operation of a region, composed with the world's own texture by convex weights.
//!
//! The image (8- or 16-bit greyscale PNG) is tiled over world position with period `period_m`
//! (pixel `(0, 0)` at the world origin, so the texture is the same wherever a region puts it),
//! bilinear with wrap-around, and scaled to zero mean and RMS `amplitude_m`: that is `B(p)`.
//! The world's own texture at those scales is `T(p) = h(p) − low(p)`, `h` the world's heights
//! averaged over one region sample's footprint and `low` over one period's (the sketch's
//! summed-area low-pass, [`super::sketch`]). With the weight `w(p) = weight · taper(p)` (the
//! sketch's smoothstep taper over `blend_m` inside the bbox edge) the operation targets
//!
//! `D(p) = w(p) · (B(p) − T(p))`
//!
//! so the texture becomes `(1 − w)·T + w·B`, a convex combination of the noise lattice and the
//! image. Several `basis` operations in one region are composed as the paper's weights are:
//! with `W(p) = Σ wᵢ(p)`, each uses `wᵢ / max(1, W)`, and the noise keeps `max(0, 1 − W)`, so
//! the weights (the noise's included) sum to 1 at every position. The operation is soft like the
//! sketch (it adds the gradient of `D` to the region's target gradient, `D` being 0 on the
//! border), the world's detail finer than a region sample stays, and its texture above the
//! period (the large shape) is kept: `B` has zero mean over a period and `T` takes out only
//! what lies below it. The region's bbox is the scene element's: edits invalidate only the
//! tiles it touches.

use super::grid::RegionGrid;
use super::raster::Canvas;
use super::sketch::{taper, LowPass, MAX_BLEND_M, MAX_SKETCH_M};
use super::spec::{err, finite_in, SpecError, MAX_ELEVATION_M};
use super::spec_tools::MAX_HEIGHTMAP_BASE64;
use super::tools::basis::Basis as BasisOp;
use super::tools::Op;
use crate::terrain::WorldPlan;

/// Most pixels a side of a basis image.
pub const MAX_BASIS_SIDE: usize = 1024;
/// Longest period, metres.
pub const MAX_PERIOD_M: f64 = 65_536.0;
/// Least period, in region sample spacings.
pub const MIN_PERIOD_SAMPLES: f64 = 4.0;
/// Largest RMS amplitude, metres.
pub const MAX_AMPLITUDE_M: f64 = 5_000.0;

/// A decoded basis image: `width × height` values of zero mean and unit RMS, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Basis {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Values, zero mean, unit RMS.
    pub values: Vec<f64>,
}

/// Decodes a basis image: base64 of an 8- or 16-bit greyscale PNG of 2 to [`MAX_BASIS_SIDE`]
/// pixels a side, not flat; the values are normalised to zero mean and unit RMS.
///
/// # Errors
/// Why the text is not such an image.
pub fn decode(png_base64: &str) -> Result<Basis, String> {
    use base64::Engine;
    if png_base64.len() > MAX_HEIGHTMAP_BASE64 {
        return Err(format!(
            "at most {MAX_HEIGHTMAP_BASE64} base64 characters, got {}",
            png_base64.len()
        ));
    }
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(png_base64.as_bytes())
        .map_err(|e| format!("not base64: {e}"))?;
    // Read the size from the header before decoding (a flat image compresses well).
    if bytes.len() >= 24 && &bytes[12..16] == b"IHDR" {
        let w = u32::from_be_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]) as usize;
        let h = u32::from_be_bytes([bytes[20], bytes[21], bytes[22], bytes[23]]) as usize;
        if w > MAX_BASIS_SIDE || h > MAX_BASIS_SIDE {
            return Err(format!(
                "a basis image has at most {MAX_BASIS_SIDE} pixels a side, got {w}×{h}"
            ));
        }
    }
    let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes))
        .read_info()
        .map_err(|e| format!("not a PNG: {e}"))?;
    let info = reader.info();
    let (width, height) = (info.width as usize, info.height as usize);
    let (depth, color) = (info.bit_depth, info.color_type);
    if color != png::ColorType::Grayscale
        || !matches!(depth, png::BitDepth::Eight | png::BitDepth::Sixteen)
    {
        return Err(format!(
            "needs an 8- or 16-bit greyscale PNG, got {depth:?}-bit {color:?}"
        ));
    }
    if width < 2 || height < 2 {
        return Err("the image needs at least 2×2 pixels".into());
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| "image too large".to_string())?;
    let mut buf = vec![0u8; size];
    reader
        .next_frame(&mut buf)
        .map_err(|e| format!("not a PNG: {e}"))?;
    let raw: Vec<f64> = if depth == png::BitDepth::Sixteen {
        buf.chunks_exact(2)
            .take(width * height)
            .map(|b| f64::from(u16::from_be_bytes([b[0], b[1]])))
            .collect()
    } else {
        buf.iter()
            .take(width * height)
            .map(|b| f64::from(*b))
            .collect()
    };
    let n = raw.len() as f64;
    let mean = raw.iter().sum::<f64>() / n;
    let rms = (raw.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    if rms == 0.0 {
        return Err("the image is flat: a basis function needs some texture".into());
    }
    Ok(Basis {
        width,
        height,
        values: raw.iter().map(|v| (v - mean) / rms).collect(),
    })
}

/// Validates a `basis` operation at `at` (`/ops/0`) of a region with bbox `min`..`max` and
/// sample spacing `spacing_m`.
pub fn validate(
    at: &str,
    op: &BasisOp,
    min: [f64; 2],
    max: [f64; 2],
    spacing_m: f64,
) -> Result<(), SpecError> {
    for k in 0..2 {
        if max[k] - min[k] > MAX_SKETCH_M {
            return Err(err(
                format!("/bbox/max/{k}"),
                format!("a basis function's region is at most {MAX_SKETCH_M} m wide and deep"),
            ));
        }
    }
    let least = MIN_PERIOD_SAMPLES * spacing_m;
    if !op.period_m.is_finite() || op.period_m < least || op.period_m > MAX_PERIOD_M {
        return Err(err(
            format!("{at}/period_m"),
            format!(
                "must be in [{least}, {MAX_PERIOD_M}] m: at least {MIN_PERIOD_SAMPLES} region \
                 sample spacings ({spacing_m} m)"
            ),
        ));
    }
    finite_in(
        format!("{at}/amplitude_m"),
        op.amplitude_m,
        0.0,
        MAX_AMPLITUDE_M.min(MAX_ELEVATION_M),
    )?;
    finite_in(format!("{at}/weight"), op.weight, 0.0, 1.0)?;
    finite_in(format!("{at}/blend_m"), op.blend_m, 0.0, MAX_BLEND_M)?;
    decode(&op.png_base64)
        .map(|_| ())
        .map_err(|e| err(format!("{at}/png_base64"), e))
}

impl Basis {
    /// The image tiled over world position with period `period_m`: bilinear, wrapping around,
    /// pixel `(i, j)` at `(i, j) · period_m / (width, height)` modulo the period.
    pub fn at(&self, p: [f64; 2], period_m: f64) -> f64 {
        let coord = |c: f64, size: usize| {
            let u = (c / period_m).rem_euclid(1.0) * size as f64;
            let i = (u.floor() as usize).min(size - 1);
            (i, (i + 1) % size, u - i as f64)
        };
        let (i0, i1, fu) = coord(p[0], self.width);
        let (j0, j1, fv) = coord(p[1], self.height);
        let s = |i: usize, j: usize| self.values[j * self.width + i];
        crate::terrain::lattice::lerp2(s(i0, j0), s(i1, j0), s(i0, j1), s(i1, j1), fu, fv)
    }
}

/// The sum `W(p)` of the `basis` operations' weights `weight · taper` at the grid's samples,
/// or `None` when the region has none.
pub fn total_weight(ops: &[Op], g: &RegionGrid) -> Option<Vec<f64>> {
    let bases: Vec<&BasisOp> = ops
        .iter()
        .filter_map(|op| match op {
            Op::Basis(b) => Some(b),
            _ => None,
        })
        .collect();
    if bases.is_empty() {
        return None;
    }
    let n = g.n;
    Some(
        (0..n * n)
            .map(|v| {
                let p = g.position(v % n, v / n);
                bases
                    .iter()
                    .map(|b| b.weight * taper(p, g.origin, g.max, b.blend_m))
                    .sum()
            })
            .collect(),
    )
}

impl Canvas {
    /// The `basis` operation: adds the gradient of `D = w · (B − T)` (0 at the samples the
    /// region keeps at 0) to the target gradient, `w = weight · taper / max(1, W)` with `W` the
    /// region's [`total_weight`] at the sample.
    pub fn basis(&mut self, plan: &WorldPlan, basis: &Basis, op: &BasisOp, total: &[f64]) {
        let g = self.grid;
        let n = g.n;
        let fine = LowPass::new(plan, g.origin, g.max, [g.spacing_m; 2]);
        let coarse = LowPass::new(plan, g.origin, g.max, [op.period_m; 2]);
        let target: Vec<f64> = (0..n * n)
            .map(|v| {
                let (i, j) = (v % n, v / n);
                if !g.is_interior(i, j) {
                    return 0.0;
                }
                let p = g.position(i, j);
                let w = op.weight * taper(p, g.origin, g.max, op.blend_m) / total[v].max(1.0);
                if w == 0.0 {
                    return 0.0;
                }
                let b = op.amplitude_m * basis.at(p, op.period_m);
                let t = fine.at(p) - coarse.at(p);
                w * (b - t)
            })
            .collect();
        self.add_target_gradient(&target);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_image_tiles_with_its_period() {
        let b = Basis {
            width: 2,
            height: 2,
            values: vec![-1.0, 1.0, 1.0, -1.0],
        };
        assert_eq!(b.at([0.0, 0.0], 100.0), -1.0);
        assert_eq!(b.at([50.0, 0.0], 100.0), 1.0);
        assert_eq!(b.at([100.0, 0.0], 100.0), -1.0);
        assert_eq!(b.at([-50.0, 0.0], 100.0), 1.0);
        assert_eq!(b.at([75.0, 0.0], 100.0), 0.0);
        assert_eq!(b.at([25.0, 25.0], 100.0), 0.0);
    }
}
