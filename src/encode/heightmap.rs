//! The 16-bit greyscale PNG heightmap of a tile.
//!
//! A 65×65 image, row `j` (north to south, +Z) and column `i` (west to east, +X), so pixel
//! `(i, j)` is vertex `j·65 + i`. Heights map linearly from the tile's own range: with
//! `offset = min_height_m` and `scale = (max_height_m − min_height_m) / 65535` (metres per unit;
//! 0 for a flat tile), a vertex stores `round((h − offset) / scale)` and decodes as
//! `h ≈ offset + value · scale`, within `scale / 2`. The server sends the mapping in the headers
//! `X-Strata-Height-Offset-M` and `X-Strata-Height-Scale-M`; the file carries it too, in `tEXt`
//! chunks `strata:height_offset_m` and `strata:height_scale_m`, plus `strata:key` and
//! `strata:seed`. Decimal forms are Rust's shortest round-trip forms of the `f64` values.

use super::height_range;
use crate::terrain::{Tile, WorldPlan, TILE_VERTEX_COUNT, TILE_VERTS};

/// Largest stored value.
pub const MAX_VALUE: u16 = u16::MAX;

/// The linear height mapping of one PNG tile: `h = offset_m + value · scale_m`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightMapping {
    /// Height of value 0, metres (the tile's lowest height).
    pub offset_m: f64,
    /// Metres per unit of the stored value (0 when the tile is flat).
    pub scale_m: f64,
}

impl HeightMapping {
    /// The mapping of a tile: its own `[min, max]` spread over `0..=65535`.
    pub fn of(tile: &Tile) -> Self {
        let (lo, hi) = height_range(tile);
        Self {
            offset_m: lo as f64,
            scale_m: (hi as f64 - lo as f64) / MAX_VALUE as f64,
        }
    }

    /// The stored value of a height.
    pub fn quantize(&self, h: f32) -> u16 {
        if self.scale_m <= 0.0 || !h.is_finite() {
            return 0;
        }
        ((h as f64 - self.offset_m) / self.scale_m)
            .round()
            .clamp(0.0, MAX_VALUE as f64) as u16
    }

    /// The height a stored value stands for, metres.
    pub fn height(&self, value: u16) -> f64 {
        self.offset_m + value as f64 * self.scale_m
    }
}

/// An encoded heightmap and its mapping.
#[derive(Clone, Debug, PartialEq)]
pub struct PngTile {
    /// The PNG file.
    pub bytes: Vec<u8>,
    /// How values map to metres.
    pub mapping: HeightMapping,
}

/// Encodes a tile's heights as a 16-bit greyscale PNG.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Result<PngTile, png::EncodingError> {
    let mapping = HeightMapping::of(tile);
    let mut data = Vec::with_capacity(2 * TILE_VERTEX_COUNT);
    for v in 0..TILE_VERTEX_COUNT {
        let h = tile.heights.get(v).copied().unwrap_or(f32::NAN);
        // PNG stores 16-bit samples big-endian.
        data.extend_from_slice(&mapping.quantize(h).to_be_bytes());
    }
    let mut bytes = Vec::new();
    {
        let side = TILE_VERTS as u32;
        let mut enc = png::Encoder::new(&mut bytes, side, side);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Sixteen);
        enc.set_compression(png::Compression::Balanced);
        let key = tile.key;
        enc.add_text_chunk(
            "strata:key".into(),
            format!("{}/{}/{}", key.lod, key.x, key.z),
        )?;
        enc.add_text_chunk("strata:seed".into(), plan.seed.to_string())?;
        enc.add_text_chunk(
            "strata:height_offset_m".into(),
            mapping.offset_m.to_string(),
        )?;
        enc.add_text_chunk("strata:height_scale_m".into(), mapping.scale_m.to_string())?;
        let mut writer = enc.write_header()?;
        writer.write_image_data(&data)?;
        writer.finish()?;
    }
    Ok(PngTile { bytes, mapping })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::{plan, tile};

    #[test]
    fn decodes_within_one_step() {
        let t = tile(1, 0, 0);
        let p = encode(plan(), &t).expect("encodes");
        assert_eq!(
            p.bytes,
            encode(plan(), &t).expect("encodes").bytes,
            "deterministic"
        );
        let mut reader = png::Decoder::new(std::io::Cursor::new(&p.bytes))
            .read_info()
            .expect("png");
        let mut buf = vec![0u8; reader.output_buffer_size().expect("size")];
        let info = reader.next_frame(&mut buf).expect("frame");
        assert_eq!((info.width, info.height), (65, 65));
        assert_eq!(info.bit_depth, png::BitDepth::Sixteen);
        for (v, &h) in t.heights.iter().enumerate() {
            let value = u16::from_be_bytes([buf[2 * v], buf[2 * v + 1]]);
            assert!((p.mapping.height(value) - h as f64).abs() <= p.mapping.scale_m * 0.5 + 1e-6);
        }
    }

    #[test]
    fn flat_tile_maps_to_zero() {
        let mut t = tile(0, 0, 0);
        t.heights.fill(3.5);
        let m = HeightMapping::of(&t);
        assert_eq!(
            m,
            HeightMapping {
                offset_m: 3.5,
                scale_m: 0.0
            }
        );
        assert_eq!(m.quantize(3.5), 0);
        assert_eq!(m.height(0), 3.5);
    }
}
