//! Import and export of a region (issue 4, item 4): the solved heights as a 16-bit greyscale PNG,
//! and the gradient map as a two-channel image with the paper's encoding (Guérin et al. 2022, §3:
//! `(r, g) = 2^{p−1}(1 + g/m)`, `m` the component-wise maximum, `p` the bits per channel), stored
//! as the red and green channels of a 16-bit RGB PNG (blue 0), as the paper does to "fit the
//! pipeline" of image tools.
//!
//! Heights map linearly: sample value `k` is `lo + k·(hi − lo)/65535` metres; the range travels
//! beside the image (and in `strata:lo_m` / `strata:hi_m` text chunks). The gradient map's `m`
//! travels the same way (`strata:m`). Per-sample gradients are the paper's central differences
//! ([`crate::terrain::poisson::gradient::extract_samples`]).

use super::region::Displacement;
use crate::terrain::poisson::gradient::{decode_map, encode_map, extract_samples};
use crate::terrain::poisson::GridSpec;

/// Largest image side accepted on import, pixels.
pub const MAX_IMPORT_SIDE: u32 = 8193;

/// Why an image could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum ExchangeError {
    /// The PNG encoder failed.
    #[error("png encoding: {0}")]
    Encode(#[from] png::EncodingError),
    /// The PNG decoder failed.
    #[error("png decoding: {0}")]
    Decode(#[from] png::DecodingError),
    /// The image is not what was expected (the field and the reason).
    #[error("{field}: {message}")]
    Invalid {
        /// The offending field or property.
        field: &'static str,
        /// Why.
        message: String,
    },
}

fn invalid(field: &'static str, message: impl Into<String>) -> ExchangeError {
    ExchangeError::Invalid {
        field,
        message: message.into(),
    }
}

/// A region's heights as a 16-bit greyscale PNG.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightPng {
    /// The PNG file.
    pub bytes: Vec<u8>,
    /// Elevation of sample value 0, metres.
    pub lo_m: f64,
    /// Elevation of sample value 65535, metres.
    pub hi_m: f64,
}

/// A gradient map as a 16-bit RGB PNG (red `∂h/∂x`, green `∂h/∂z`, blue 0).
#[derive(Clone, Debug, PartialEq)]
pub struct GradientPng {
    /// The PNG file.
    pub bytes: Vec<u8>,
    /// The encoding's `m`: the largest absolute gradient component.
    pub m: f32,
}

/// A decoded image: `width × height` values, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Image<T> {
    /// Pixels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// Values, row-major.
    pub values: T,
}

/// Per-sample gradients `(∂h/∂x, ∂h/∂z)`, row-major.
pub type GradientPair = (Vec<f32>, Vec<f32>);

/// The solved heights `h_proc + d` of a region, metres, row-major `n × n`.
pub fn heights(r: &Displacement) -> Vec<f32> {
    r.base.iter().zip(&r.d).map(|(b, d)| b + d).collect()
}

fn write_png(
    (width, height): (u32, u32),
    color: png::ColorType,
    data: &[u8],
    text: &[(&str, String)],
) -> Result<Vec<u8>, ExchangeError> {
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, width, height);
        enc.set_color(color);
        enc.set_depth(png::BitDepth::Sixteen);
        for (k, v) in text {
            enc.add_text_chunk((*k).into(), v.clone())?;
        }
        let mut writer = enc.write_header()?;
        writer.write_image_data(data)?;
        writer.finish()?;
    }
    Ok(bytes)
}

/// Reads a 16-bit PNG of the given colour type; returns its size and big-endian samples.
fn read_png(bytes: &[u8], color: png::ColorType) -> Result<Image<Vec<u16>>, ExchangeError> {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info()?;
    let info = reader.info();
    let (w, h) = (info.width, info.height);
    if w > MAX_IMPORT_SIDE || h > MAX_IMPORT_SIDE {
        return Err(invalid(
            "size",
            format!("at most {MAX_IMPORT_SIDE} pixels a side, got {w}×{h}"),
        ));
    }
    if info.bit_depth != png::BitDepth::Sixteen || info.color_type != color {
        return Err(invalid(
            "format",
            format!(
                "needs 16-bit {color:?}, got {:?}-bit {:?}",
                info.bit_depth, info.color_type
            ),
        ));
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| invalid("size", "image too large"))?;
    let mut buf = vec![0u8; size];
    reader.next_frame(&mut buf)?;
    Ok(Image {
        width: w as usize,
        height: h as usize,
        values: buf
            .chunks_exact(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect(),
    })
}

/// Exports a region's solved heights as a 16-bit greyscale PNG of `n × n`, the range the
/// heights' own minimum to maximum (1 m wide for a flat region).
///
/// # Errors
/// [`ExchangeError::Encode`] if the PNG encoder fails.
pub fn export_png16(r: &Displacement) -> Result<HeightPng, ExchangeError> {
    encode_png16(r.grid.n, r.grid.n, &heights(r))
}

/// Encodes `width × height` heights (metres, row-major) as a 16-bit greyscale PNG, the range
/// their own minimum to maximum (1 m wide when flat).
///
/// # Errors
/// [`ExchangeError`] if the size does not match or the PNG encoder fails.
pub fn encode_png16(width: usize, height: usize, h: &[f32]) -> Result<HeightPng, ExchangeError> {
    if width * height != h.len() || width == 0 || height == 0 {
        return Err(invalid(
            "size",
            format!("{width}×{height} does not match {} heights", h.len()),
        ));
    }
    let lo = h.iter().fold(f64::INFINITY, |a, v| a.min(f64::from(*v)));
    let hi = h
        .iter()
        .fold(f64::NEG_INFINITY, |a, v| a.max(f64::from(*v)));
    let hi = if hi > lo { hi } else { lo + 1.0 };
    let scale = 65535.0 / (hi - lo);
    let data: Vec<u8> = h
        .iter()
        .flat_map(|v| {
            let k = ((f64::from(*v) - lo) * scale).round().clamp(0.0, 65535.0) as u16;
            k.to_be_bytes()
        })
        .collect();
    let text = [
        ("strata:lo_m", lo.to_string()),
        ("strata:hi_m", hi.to_string()),
    ];
    let bytes = write_png(
        (width as u32, height as u32),
        png::ColorType::Grayscale,
        &data,
        &text,
    )?;
    Ok(HeightPng {
        bytes,
        lo_m: lo,
        hi_m: hi,
    })
}

/// Imports a 16-bit greyscale PNG as heights, metres: value `k` becomes `lo_m + k·(hi_m −
/// lo_m)/65535`.
///
/// # Errors
/// [`ExchangeError`] if the bytes are not a 16-bit greyscale PNG of at most
/// [`MAX_IMPORT_SIDE`] a side, or the range is not finite.
pub fn import_png16(bytes: &[u8], lo_m: f64, hi_m: f64) -> Result<Image<Vec<f32>>, ExchangeError> {
    if !lo_m.is_finite() || !hi_m.is_finite() {
        return Err(invalid("lo_m", "the height range must be finite"));
    }
    let img = read_png(bytes, png::ColorType::Grayscale)?;
    let step = (hi_m - lo_m) / 65535.0;
    Ok(Image {
        width: img.width,
        height: img.height,
        values: img
            .values
            .iter()
            .map(|k| (lo_m + f64::from(*k) * step) as f32)
            .collect(),
    })
}

/// Exports the gradient map of a region's solved heights (per-sample central differences) with
/// the paper's 16-bit encoding.
///
/// # Errors
/// [`ExchangeError`] if the grid is invalid or the PNG encoder fails.
pub fn export_gradient_map(r: &Displacement) -> Result<GradientPng, ExchangeError> {
    let n = r.grid.n;
    let grid = GridSpec::new(n, n, r.grid.spacing_m).map_err(|e| invalid("grid", e.to_string()))?;
    let (mut sx, mut sz) = (vec![0.0; n * n], vec![0.0; n * n]);
    extract_samples(grid, &heights(r), &mut sx, &mut sz);
    let (red, green, m) = encode_map(&sx, &sz, 16);
    let data: Vec<u8> = red
        .iter()
        .zip(&green)
        .flat_map(|(a, b)| {
            let (a, b) = (a.to_be_bytes(), b.to_be_bytes());
            [a[0], a[1], b[0], b[1], 0, 0]
        })
        .collect();
    let bytes = write_png(
        (n as u32, n as u32),
        png::ColorType::Rgb,
        &data,
        &[("strata:m", m.to_string())],
    )?;
    Ok(GradientPng { bytes, m })
}

/// Imports a gradient map (16-bit RGB PNG, red and green channels) with the encoding's `m`:
/// the per-sample gradients `(∂h/∂x, ∂h/∂z)`.
///
/// # Errors
/// [`ExchangeError`] if the bytes are not a 16-bit RGB PNG of at most [`MAX_IMPORT_SIDE`] a
/// side, or `m` is not positive and finite.
pub fn import_gradient_map(bytes: &[u8], m: f32) -> Result<Image<GradientPair>, ExchangeError> {
    if !m.is_finite() || m <= 0.0 {
        return Err(invalid("m", "must be positive and finite"));
    }
    let img = read_png(bytes, png::ColorType::Rgb)?;
    let red: Vec<u16> = img.values.chunks_exact(3).map(|p| p[0]).collect();
    let green: Vec<u16> = img.values.chunks_exact(3).map(|p| p[1]).collect();
    Ok(Image {
        width: img.width,
        height: img.height,
        values: decode_map(&red, &green, m, 16),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::authoring::region::tests::{plan, spec};
    use crate::authoring::solve_region;
    use serde_json::json;

    fn region() -> Displacement {
        let ops = json!([{"op": "crest", "points": [[1010, 2064], [1118, 2064]],
            "elevation_m": 300, "slope_deg": 25, "width_m": 30}]);
        solve_region(&plan(), &spec(65, ops)).expect("solved")
    }

    #[test]
    fn heights_round_trip_through_png16_within_one_step() {
        let r = region();
        let png = export_png16(&r).expect("encodes");
        let back = import_png16(&png.bytes, png.lo_m, png.hi_m).expect("decodes");
        assert_eq!((back.width, back.height), (r.grid.n, r.grid.n));
        let step = (png.hi_m - png.lo_m) / 65535.0;
        for (a, b) in heights(&r).iter().zip(&back.values) {
            assert!(f64::from((a - b).abs()) <= 0.5 * step + 1e-4, "{a} vs {b}");
        }
        assert!(
            png.hi_m >= 299.99,
            "the crest is the highest point: {}",
            png.hi_m
        );
        // A gradient map is not a heightmap.
        let grad = export_gradient_map(&r).expect("encodes");
        assert!(matches!(
            import_png16(&grad.bytes, 0.0, 1.0),
            Err(ExchangeError::Invalid {
                field: "format",
                ..
            })
        ));
    }

    #[test]
    fn gradient_maps_round_trip_with_the_paper_encoding() {
        let r = region();
        let n = r.grid.n;
        let png = export_gradient_map(&r).expect("encodes");
        let back = import_gradient_map(&png.bytes, png.m).expect("decodes");
        let grid = GridSpec::new(n, n, r.grid.spacing_m).expect("grid");
        let (mut sx, mut sz) = (vec![0.0; n * n], vec![0.0; n * n]);
        extract_samples(grid, &heights(&r), &mut sx, &mut sz);
        let (dx, dz) = &back.values;
        // One quantisation step of the encoding is m / 2^15; rounding errs by half of it.
        let tol = png.m / 32768.0;
        for (a, b) in sx.iter().chain(&sz).zip(dx.iter().chain(dz)) {
            assert!((a - b).abs() <= tol, "{a} vs {b}");
        }
        // The crest's flanks: north of the ridge the slope rises southward (∂h/∂z > 0).
        let (i, j) = (32, (2064.0 - 2000.0) as usize / 2 - 5);
        assert!(dz[j * n + i] > 0.2, "{}", dz[j * n + i]);
        assert!(import_gradient_map(&png.bytes, 0.0).is_err());
    }
}
