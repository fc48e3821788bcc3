//! The `STRT` version 1 binary encoding of a height tile (normative text:
//! `api/tile_format_v1.md` §Binary).
//!
//! All numbers are little-endian. A 128-byte header is followed by five sections, each starting
//! at the offset the header gives (a multiple of 4; single-byte sections are zero-padded to a
//! multiple of 4):
//!
//! | section | type | count |
//! |---|---|---|
//! | heights, metres | `f32` | 4225 |
//! | normals `x, y, z` | `f32` ×3 | 4225 |
//! | biome weights | `u8`, per vertex summing to exactly 255 | 4225·k |
//! | materials | `u8` | 4225 |
//! | water depth, metres | `f32` | 4225 |

use super::height_range;
use crate::terrain::{Tile, WorldPlan, TILE_VERTEX_COUNT, TILE_VERTS};

/// File magic.
pub const MAGIC: [u8; 4] = *b"STRT";
/// Format version.
pub const VERSION: u16 = 1;
/// Header length, bytes.
pub const HEADER_LEN: usize = 128;
/// `normals_encoding` value: three little-endian `f32` per vertex.
pub const NORMALS_F32X3: u8 = 0;
/// `weights_encoding` value: one `u8` per biome per vertex, summing to exactly 255 per vertex.
pub const WEIGHTS_U8_SUM255: u8 = 1;

/// Byte offsets of the header fields (see `api/tile_format_v1.md`).
pub mod offset {
    /// `[u8; 4]` magic `"STRT"`.
    pub const MAGIC: usize = 0;
    /// `u16` format version.
    pub const VERSION: usize = 4;
    /// `u16` header length in bytes (128).
    pub const HEADER_LEN: usize = 6;
    /// `u64` world seed.
    pub const SEED: usize = 8;
    /// `i64` tile column.
    pub const X: usize = 16;
    /// `i64` tile row.
    pub const Z: usize = 24;
    /// `u32` level of detail.
    pub const LOD: usize = 32;
    /// `u16` vertices per side (65).
    pub const SIZE: usize = 36;
    /// `u16` number of biomes `k`.
    pub const BIOME_COUNT: usize = 38;
    /// `u32` vertex count (4225).
    pub const VERTEX_COUNT: usize = 40;
    /// `f32` vertex spacing, metres.
    pub const SPACING_M: usize = 44;
    /// `f64` world X of vertex (0, 0), metres.
    pub const ORIGIN_X_M: usize = 48;
    /// `f64` world Z of vertex (0, 0), metres.
    pub const ORIGIN_Z_M: usize = 56;
    /// `f32` skirt depth, metres.
    pub const SKIRT_DEPTH_M: usize = 64;
    /// `f32` lowest height, metres.
    pub const MIN_HEIGHT_M: usize = 68;
    /// `f32` highest height, metres.
    pub const MAX_HEIGHT_M: usize = 72;
    /// `u8` normals encoding ([`super::NORMALS_F32X3`]).
    pub const NORMALS_ENCODING: usize = 76;
    /// `u8` weights encoding ([`super::WEIGHTS_U8_SUM255`]).
    pub const WEIGHTS_ENCODING: usize = 77;
    /// `u16` number of materials named in the format spec (6).
    pub const MATERIAL_COUNT: usize = 78;
    /// `u32` offset of the heights section.
    pub const HEIGHTS: usize = 80;
    /// `u32` offset of the normals section.
    pub const NORMALS: usize = 84;
    /// `u32` offset of the weights section.
    pub const WEIGHTS: usize = 88;
    /// `u32` offset of the materials section.
    pub const MATERIALS: usize = 92;
    /// `u32` offset of the water-depth section.
    pub const WATER_DEPTH: usize = 96;
    /// `u32` total length of the file in bytes.
    pub const TOTAL_LEN: usize = 100;
    /// `u32` offset of the volume-override section (`u8` per vertex), 0 when absent.
    pub const VOLUME_OVERRIDE: usize = 104;
    // 108..128: reserved, zero.
}

fn pad4(n: usize) -> usize {
    n.div_ceil(4) * 4
}

/// Quantises one vertex's weights to `u8` summing to exactly 255 (largest-remainder method):
/// each weight `w_b / Σw · 255` is floored, and the units still missing go to the biomes with
/// the largest fractional parts, lower biome index first on ties. Every quantised weight is within
/// 1/255 of the normalised weight. A vertex with no positive finite weight gets 255 on biome 0.
pub fn quantize_weights(w: &[f32], out: &mut [u8]) {
    debug_assert_eq!(w.len(), out.len());
    let clean = |x: f32| {
        if x.is_finite() && x > 0.0 {
            x as f64
        } else {
            0.0
        }
    };
    let sum: f64 = w.iter().map(|&x| clean(x)).sum();
    if out.is_empty() {
        return;
    }
    if sum <= 0.0 {
        out.fill(0);
        out[0] = 255;
        return;
    }
    let mut total: u32 = 0;
    let mut frac = [0.0f64; crate::terrain::world::MAX_BIOMES];
    for (b, (&x, q)) in w.iter().zip(out.iter_mut()).enumerate() {
        let scaled = (clean(x) / sum * 255.0).min(255.0);
        let f = scaled.floor();
        *q = f as u8;
        total += f as u32;
        if let Some(slot) = frac.get_mut(b) {
            *slot = scaled - f;
        }
    }
    let mut missing = 255u32.saturating_sub(total);
    while missing > 0 {
        // The biome with the largest remainder that has not been topped up yet.
        let mut best: Option<usize> = None;
        for b in 0..out.len().min(frac.len()) {
            if frac[b] >= 0.0 && best.is_none_or(|c| frac[b] > frac[c]) {
                best = Some(b);
            }
        }
        let Some(b) = best else { break };
        out[b] = out[b].saturating_add(1);
        frac[b] = -1.0;
        missing -= 1;
    }
}

/// Encodes a tile as `STRT` v1.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    let n = TILE_VERTEX_COUNT;
    let k = tile.biome_count;
    let heights_off = HEADER_LEN;
    let normals_off = heights_off + 4 * n;
    let weights_off = normals_off + 12 * n;
    let materials_off = weights_off + pad4(n * k);
    let water_off = materials_off + pad4(n);
    let marked = !tile.volume_override.is_empty();
    let override_off = if marked { water_off + 4 * n } else { 0 };
    let total = water_off + 4 * n + if marked { pad4(n) } else { 0 };

    let mut out = vec![0u8; total];
    let put = |out: &mut Vec<u8>, at: usize, bytes: &[u8]| {
        out[at..at + bytes.len()].copy_from_slice(bytes)
    };
    let (min_h, max_h) = height_range(tile);
    put(&mut out, offset::MAGIC, &MAGIC);
    put(&mut out, offset::VERSION, &VERSION.to_le_bytes());
    put(
        &mut out,
        offset::HEADER_LEN,
        &(HEADER_LEN as u16).to_le_bytes(),
    );
    put(&mut out, offset::SEED, &plan.seed.to_le_bytes());
    put(&mut out, offset::X, &tile.key.x.to_le_bytes());
    put(&mut out, offset::Z, &tile.key.z.to_le_bytes());
    put(&mut out, offset::LOD, &tile.key.lod.to_le_bytes());
    put(&mut out, offset::SIZE, &(TILE_VERTS as u16).to_le_bytes());
    put(&mut out, offset::BIOME_COUNT, &(k as u16).to_le_bytes());
    put(&mut out, offset::VERTEX_COUNT, &(n as u32).to_le_bytes());
    put(&mut out, offset::SPACING_M, &tile.spacing_m.to_le_bytes());
    put(
        &mut out,
        offset::ORIGIN_X_M,
        &tile.origin_x_m().to_le_bytes(),
    );
    put(
        &mut out,
        offset::ORIGIN_Z_M,
        &tile.origin_z_m().to_le_bytes(),
    );
    put(
        &mut out,
        offset::SKIRT_DEPTH_M,
        &tile.skirt_depth_m.to_le_bytes(),
    );
    put(&mut out, offset::MIN_HEIGHT_M, &min_h.to_le_bytes());
    put(&mut out, offset::MAX_HEIGHT_M, &max_h.to_le_bytes());
    out[offset::NORMALS_ENCODING] = NORMALS_F32X3;
    out[offset::WEIGHTS_ENCODING] = WEIGHTS_U8_SUM255;
    let materials = crate::terrain::world::MATERIALS.len() as u16;
    put(&mut out, offset::MATERIAL_COUNT, &materials.to_le_bytes());
    for (field, value) in [
        (offset::HEIGHTS, heights_off),
        (offset::NORMALS, normals_off),
        (offset::WEIGHTS, weights_off),
        (offset::MATERIALS, materials_off),
        (offset::WATER_DEPTH, water_off),
        (offset::TOTAL_LEN, total),
        (offset::VOLUME_OVERRIDE, override_off),
    ] {
        put(&mut out, field, &(value as u32).to_le_bytes());
    }

    for (v, h) in tile.heights.iter().take(n).enumerate() {
        put(&mut out, heights_off + 4 * v, &h.to_le_bytes());
    }
    for (v, nrm) in tile.normals.iter().take(n).enumerate() {
        for (c, x) in nrm.iter().enumerate() {
            put(&mut out, normals_off + 12 * v + 4 * c, &x.to_le_bytes());
        }
    }
    if k > 0 {
        let dst = &mut out[weights_off..weights_off + n * k];
        for (w, q) in tile.weights.chunks(k).zip(dst.chunks_mut(k)) {
            quantize_weights(w, q);
        }
    }
    let m = tile.materials.len().min(n);
    out[materials_off..materials_off + m].copy_from_slice(&tile.materials[..m]);
    for (v, d) in tile.water_depth.iter().take(n).enumerate() {
        put(&mut out, water_off + 4 * v, &d.to_le_bytes());
    }
    if marked {
        let m = tile.volume_override.len().min(n);
        out[override_off..override_off + m].copy_from_slice(&tile.volume_override[..m]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::{plan, tile};

    #[test]
    fn quantised_weights_sum_to_255_and_stay_close() {
        let cases: [&[f32]; 6] = [
            &[1.0, 0.0, 0.0, 0.0],
            &[0.25, 0.25, 0.25, 0.25],
            &[1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
            &[0.5, 0.5],
            &[0.0, 0.0, 0.0],
            &[0.1, 0.2, 0.3, 0.4, f32::NAN],
        ];
        for w in cases {
            let mut q = vec![0u8; w.len()];
            quantize_weights(w, &mut q);
            assert_eq!(
                q.iter().map(|&x| x as u32).sum::<u32>(),
                255,
                "{w:?} -> {q:?}"
            );
            let s: f32 = w.iter().filter(|x| x.is_finite()).sum();
            if s > 0.0 {
                for (a, b) in w.iter().zip(&q) {
                    let a = if a.is_finite() { a / s } else { 0.0 };
                    assert!(
                        (a - *b as f32 / 255.0).abs() < 1.0 / 255.0,
                        "{w:?} -> {q:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn header_and_sections() {
        let t = tile(2, 3, -4);
        let b = encode(plan(), &t);
        assert_eq!(&b[0..4], b"STRT");
        let u32_at = |o: usize| u32::from_le_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]]) as usize;
        assert_eq!(u32_at(offset::TOTAL_LEN), b.len());
        for o in [
            offset::HEIGHTS,
            offset::NORMALS,
            offset::WEIGHTS,
            offset::MATERIALS,
            offset::WATER_DEPTH,
        ] {
            assert_eq!(u32_at(o) % 4, 0);
        }
        let h = u32_at(offset::HEIGHTS);
        assert_eq!(&b[h..h + 4], &t.heights[0].to_le_bytes());
    }
}
