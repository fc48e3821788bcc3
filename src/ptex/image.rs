//! Uploaded images for the Ptex bake: image materials and decals (issue 20). A PNG is decoded
//! once into 8-bit RGBA with a box-filtered mip chain, and sampled bilinearly, wrapping (tiled
//! materials) or clamped (decals).
//!
//! Images are referenced by content hash (blake3 of the PNG bytes, [`image_hash`]), so a scene
//! version pins the exact bytes. Sides are powers of two from 1 to [`MAX_IMAGE_SIDE`]: a tiled
//! material's repeat then lines up across faces, and every mip level halves both sides exactly.
//!
//! Sampling is the CPU reference of `sample_image` in `shaders/ptex.wgsl`: texel `(x, y)` of
//! level `l` at `(u·w_l − ½, v·h_l − ½)`, bilinear in that cell on the channel bytes (whose
//! differences are exact), the result times `1/255`. With power-of-two sides the products are
//! exact, so the twin differs only in the rounding of the interpolations.

/// Largest PNG accepted, bytes (the server's request body limit).
pub const MAX_IMAGE_BYTES: usize = 2 << 20;
/// Largest image side, pixels.
pub const MAX_IMAGE_SIDE: u32 = 1024;

/// A decoded image: RGBA8 texels with their mip chain.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width of level 0, pixels (a power of two).
    pub width: u32,
    /// Height of level 0, pixels (a power of two).
    pub height: u32,
    /// Level `l` is `max(width >> l, 1) × max(height >> l, 1)` texels, rows top to bottom; the
    /// last level is 1 × 1.
    pub levels: Vec<Vec<[u8; 4]>>,
}

/// Why a PNG is refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct ImageError(pub String);

/// The content hash of an image's PNG bytes (blake3).
pub fn image_hash(png: &[u8]) -> [u8; 32] {
    *blake3::hash(png).as_bytes()
}

/// Lowercase hex of a hash.
pub fn hash_hex(hash: &[u8; 32]) -> String {
    hash.iter().map(|b| format!("{b:02x}")).collect()
}

/// The hash a 64-character lowercase hex string names.
pub fn parse_hash(hex: &str) -> Option<[u8; 32]> {
    if hex.len() != 64 || !hex.bytes().all(|b| matches!(b, b'0'..=b'9' | b'a'..=b'f')) {
        return None;
    }
    let mut out = [0u8; 32];
    for (i, o) in out.iter_mut().enumerate() {
        *o = u8::from_str_radix(&hex[2 * i..2 * i + 2], 16).ok()?;
    }
    Some(out)
}

fn side_ok(s: u32) -> bool {
    s.is_power_of_two() && s <= MAX_IMAGE_SIDE
}

/// The width and height a PNG's header states, checked against the limits before decoding.
///
/// # Errors
/// Not a PNG, over [`MAX_IMAGE_BYTES`], or a side that is not a power of two up to
/// [`MAX_IMAGE_SIDE`].
pub fn check_png(png: &[u8]) -> Result<(u32, u32), ImageError> {
    if png.len() > MAX_IMAGE_BYTES {
        return Err(ImageError(format!(
            "an image is at most {MAX_IMAGE_BYTES} bytes, got {}",
            png.len()
        )));
    }
    if png.len() < 24 || &png[..8] != b"\x89PNG\r\n\x1a\n" || &png[12..16] != b"IHDR" {
        return Err(ImageError("not a PNG".into()));
    }
    let w = u32::from_be_bytes([png[16], png[17], png[18], png[19]]);
    let h = u32::from_be_bytes([png[20], png[21], png[22], png[23]]);
    if !side_ok(w) || !side_ok(h) {
        return Err(ImageError(format!(
            "an image's sides are powers of two from 1 to {MAX_IMAGE_SIDE} pixels, got {w}×{h}"
        )));
    }
    Ok((w, h))
}

/// Decodes a PNG of any colour type and bit depth into RGBA8 (grey fills R, G and B; a missing
/// alpha is 255; 16-bit channels keep their high byte) and builds its mip chain.
///
/// # Errors
/// What [`check_png`] refuses, or a PNG that does not decode.
pub fn decode_png(png: &[u8]) -> Result<Image, ImageError> {
    let (width, height) = check_png(png)?;
    let mut decoder = png::Decoder::new(std::io::Cursor::new(png));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder
        .read_info()
        .map_err(|e| ImageError(format!("not a PNG: {e}")))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| ImageError("image too large".into()))?;
    let mut buf = vec![0u8; size];
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| ImageError(format!("not a PNG: {e}")))?;
    let n = (width * height) as usize;
    let texels: Vec<[u8; 4]> = match frame.color_type {
        png::ColorType::Grayscale => buf[..n].iter().map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::GrayscaleAlpha => buf[..2 * n]
            .chunks_exact(2)
            .map(|c| [c[0], c[0], c[0], c[1]])
            .collect(),
        png::ColorType::Rgb => buf[..3 * n]
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2], 255])
            .collect(),
        png::ColorType::Rgba => buf[..4 * n]
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect(),
        png::ColorType::Indexed => {
            return Err(ImageError("an indexed PNG did not expand".into()));
        }
    };
    Ok(Image::new(width, height, texels))
}

impl Image {
    /// An image of `width × height` RGBA8 texels (powers of two), with its mip chain: each
    /// level's texel is the rounded mean `⌊(Σ + n/2)/n⌋` of the `n` (4, or 2 along a side of 1)
    /// texels below it.
    pub fn new(width: u32, height: u32, texels: Vec<[u8; 4]>) -> Self {
        let mut levels = vec![texels];
        let (mut w, mut h) = (width as usize, height as usize);
        while w > 1 || h > 1 {
            let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
            let prev = levels.last().map(Vec::as_slice).unwrap_or_default();
            let mut next = Vec::with_capacity(nw * nh);
            for y in 0..nh {
                for x in 0..nw {
                    let xs = [2 * x, (2 * x + 1).min(w - 1)];
                    let ys = [2 * y, (2 * y + 1).min(h - 1)];
                    let cols = if w > 1 { 2 } else { 1 };
                    let rows = if h > 1 { 2 } else { 1 };
                    let count = (cols * rows) as u32;
                    let texel = std::array::from_fn(|c| {
                        let mut sum = 0u32;
                        for yy in &ys[..rows] {
                            for xx in &xs[..cols] {
                                sum += u32::from(prev[yy * w + xx][c]);
                            }
                        }
                        ((sum + count / 2) / count) as u8
                    });
                    next.push(texel);
                }
            }
            levels.push(next);
            (w, h) = (nw, nh);
        }
        Self {
            width,
            height,
            levels,
        }
    }

    /// `log2` of the longer side.
    pub fn side_log2(&self) -> i32 {
        self.width.max(self.height).trailing_zeros() as i32
    }

    /// The size of level `l`.
    pub fn level_size(&self, l: usize) -> (u32, u32) {
        ((self.width >> l).max(1), (self.height >> l).max(1))
    }

    /// Bytes of the decoded texels, every level.
    pub fn bytes(&self) -> usize {
        self.levels.iter().map(|l| 4 * l.len()).sum()
    }

    /// Bilinear sample of level `l` (clamped to the chain) at `(u, v)`, `u` to the right and `v`
    /// down, the image spanning `[0, 1]²`: wrapping across the edges with `wrap`, else the edge
    /// texels repeated. Channels in `[0, 1]`.
    pub fn sample(&self, l: usize, u: f32, v: f32, wrap: bool) -> [f32; 4] {
        let l = l.min(self.levels.len() - 1);
        let (w, h) = self.level_size(l);
        let texels = &self.levels[l];
        let x = u * w as f32 - 0.5;
        let y = v * h as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let index = |i: i32, n: u32| -> usize {
            if wrap {
                i.rem_euclid(n as i32) as usize
            } else {
                i.clamp(0, n as i32 - 1) as usize
            }
        };
        let (x0, y0) = (x0 as i32, y0 as i32);
        let (xa, xb) = (index(x0, w), index(x0 + 1, w));
        let (ya, yb) = (index(y0, h), index(y0 + 1, h));
        let row = w as usize;
        let t = |xx: usize, yy: usize, c: usize| f32::from(texels[yy * row + xx][c]);
        std::array::from_fn(|c| {
            let top = t(xa, ya, c) + (t(xb, ya, c) - t(xa, ya, c)) * fx;
            let bottom = t(xa, yb, c) + (t(xb, yb, c) - t(xa, yb, c)) * fx;
            (top + (bottom - top) * fy) * (1.0 / 255.0)
        })
    }
}

/// The mip level to sample for a texel whose finest noise octave is `kmax` (`2^kmax` cycles per
/// metre ≤ half a texel's frequency, [`super::bake::finest_octave`]) when the image has
/// `2^density_log2` pixels per metre: the level at which one pixel is no smaller than a texel,
/// `density_log2 − (kmax + 1)`, within the chain. Integer arithmetic, the same on every device.
pub fn mip_level(density_log2: i32, kmax: i32, levels: usize) -> usize {
    (density_log2 - (kmax + 1)).clamp(0, levels as i32 - 1) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    fn png(w: u32, h: u32, color: png::ColorType, data: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(color);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().expect("header");
        writer.write_image_data(data).expect("data");
        writer.finish().expect("finish");
        out
    }

    #[test]
    fn decodes_grey_and_rgba_and_builds_the_chain() {
        let grey = png(2, 2, png::ColorType::Grayscale, &[0, 100, 200, 255]);
        let img = decode_png(&grey).expect("grey");
        assert_eq!(img.levels[0][1], [100, 100, 100, 255]);
        assert_eq!(img.levels.len(), 2);
        // (0 + 100 + 200 + 255 + 2) / 4 = 139.
        assert_eq!(img.levels[1][0], [139, 139, 139, 255]);
        let rgba = png(4, 1, png::ColorType::Rgba, &[9; 16]);
        let img = decode_png(&rgba).expect("rgba");
        assert_eq!(img.levels.len(), 3, "4×1, 2×1, 1×1");
        assert_eq!(img.levels[2], vec![[9; 4]]);
    }

    #[test]
    fn refuses_bad_sides_sizes_and_non_pngs() {
        let e = check_png(&png(3, 2, png::ColorType::Grayscale, &[0; 6])).expect_err("3 wide");
        assert!(e.0.contains("powers of two"), "{e}");
        assert!(check_png(b"GIF89a........................").is_err());
        let big = vec![0u8; MAX_IMAGE_BYTES + 1];
        assert!(check_png(&big).expect_err("big").0.contains("bytes"));
    }

    #[test]
    fn bilinear_wraps_or_clamps() {
        let img = Image::new(2, 1, vec![[0; 4], [255; 4]]);
        // Texel centres at u = 0.25 and 0.75.
        assert_eq!(img.sample(0, 0.25, 0.5, true)[0], 0.0);
        assert_eq!(img.sample(0, 0.75, 0.5, true)[0], 1.0);
        assert!((img.sample(0, 0.5, 0.5, true)[0] - 0.5).abs() < 1e-6);
        // At u = 0 the wrap blends the last texel in; the clamp does not.
        assert!((img.sample(0, 0.0, 0.5, true)[0] - 0.5).abs() < 1e-6);
        assert_eq!(img.sample(0, 0.0, 0.5, false)[0], 0.0);
        assert_eq!(mip_level(10, 3, 11), 6);
        assert_eq!(mip_level(2, 3, 3), 0);
        assert_eq!(mip_level(30, -9, 3), 2);
    }

    #[test]
    fn hashes_round_trip_as_hex() {
        let h = image_hash(b"x");
        assert_eq!(parse_hash(&hash_hex(&h)), Some(h));
        assert_eq!(parse_hash("AB"), None);
        assert_eq!(parse_hash(&"G".repeat(64)), None);
    }
}
