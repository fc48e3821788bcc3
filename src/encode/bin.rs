//! The `STRT` binary encoding of a height tile, versions 1 and 2 (normative text:
//! `api/tile_format_v1.md` §Binary and `api/tile_format_v2.md`).
//!
//! All numbers are little-endian. A 128-byte header is followed by the sections, each starting
//! at the offset the header gives (a multiple of 4; single-byte sections are zero-padded to a
//! multiple of 4):
//!
//! | section | type | count | version |
//! |---|---|---|---|
//! | heights, metres | `f32` | 4225 | 1, 2 |
//! | normals `x, y, z` | `f32` ×3 | 4225 | 1, 2 |
//! | biome weights | `u8`, per vertex summing to exactly 255 | 4225·k | 1, 2 |
//! | materials | `u8` | 4225 | 1, 2 |
//! | water depth, metres | `f32` | 4225 | 1, 2 |
//! | water surface height, metres | `f32` | 4225 | 2 |
//! | water kind | `u8` | 4225 | 2 |
//! | volume override (optional) | `u8` | 4225 | 1, 2 |
//!
//! Version 1 ([`encode`]) is the default product and keeps its bytes; [`encode_version`] writes
//! either.

use super::{height_range, water, TileVersion};
use crate::terrain::{Tile, WorldPlan, TILE_VERTEX_COUNT, TILE_VERTS};

/// File magic.
pub const MAGIC: [u8; 4] = *b"STRT";
/// Format version of [`encode`].
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
    /// `u32` offset of the water-surface section (`f32` per vertex); version 2 only (reserved,
    /// zero, in version 1).
    pub const WATER_SURFACE: usize = 108;
    /// `u32` offset of the water-kind section (`u8` per vertex); version 2 only (reserved, zero,
    /// in version 1).
    pub const WATER_KIND: usize = 112;
    // 116..128: reserved, zero.
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

/// Where the sections of one tile's file start, bytes (0: the section is absent).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Heights.
    pub heights: usize,
    /// Normals.
    pub normals: usize,
    /// Biome weights.
    pub weights: usize,
    /// Materials.
    pub materials: usize,
    /// Water depth.
    pub water_depth: usize,
    /// Water surface height (version 2).
    pub water_surface: usize,
    /// Water kind (version 2).
    pub water_kind: usize,
    /// Volume override (when some vertex is marked).
    pub volume_override: usize,
    /// File length.
    pub total: usize,
}

impl Layout {
    /// The layout of a tile of `k` biomes in `version`, with a volume-override section when
    /// `marked`.
    pub fn new(k: usize, version: TileVersion, marked: bool) -> Self {
        let n = TILE_VERTEX_COUNT;
        let heights = HEADER_LEN;
        let normals = heights + 4 * n;
        let weights = normals + 12 * n;
        let materials = weights + pad4(n * k);
        let water_depth = materials + pad4(n);
        let mut end = water_depth + 4 * n;
        let (mut water_surface, mut water_kind) = (0, 0);
        if version == TileVersion::V2 {
            water_surface = end;
            water_kind = water_surface + 4 * n;
            end = water_kind + pad4(n);
        }
        let volume_override = if marked { end } else { 0 };
        let total = end + if marked { pad4(n) } else { 0 };
        Self {
            heights,
            normals,
            weights,
            materials,
            water_depth,
            water_surface,
            water_kind,
            volume_override,
            total,
        }
    }
}

/// Encodes a tile as `STRT` v1.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    encode_version(plan, tile, TileVersion::V1)
}

/// Encodes a tile as `STRT` of `version`.
pub fn encode_version(plan: &WorldPlan, tile: &Tile, version: TileVersion) -> Vec<u8> {
    let n = TILE_VERTEX_COUNT;
    let k = tile.biome_count;
    let marked = !tile.volume_override.is_empty();
    let at = Layout::new(k, version, marked);

    let mut out = vec![0u8; at.total];
    let put = |out: &mut Vec<u8>, at: usize, bytes: &[u8]| {
        out[at..at + bytes.len()].copy_from_slice(bytes)
    };
    let (min_h, max_h) = height_range(tile);
    put(&mut out, offset::MAGIC, &MAGIC);
    put(&mut out, offset::VERSION, &version.number().to_le_bytes());
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
        (offset::HEIGHTS, at.heights),
        (offset::NORMALS, at.normals),
        (offset::WEIGHTS, at.weights),
        (offset::MATERIALS, at.materials),
        (offset::WATER_DEPTH, at.water_depth),
        (offset::TOTAL_LEN, at.total),
        (offset::VOLUME_OVERRIDE, at.volume_override),
        (offset::WATER_SURFACE, at.water_surface),
        (offset::WATER_KIND, at.water_kind),
    ] {
        put(&mut out, field, &(value as u32).to_le_bytes());
    }

    for (v, h) in tile.heights.iter().take(n).enumerate() {
        put(&mut out, at.heights + 4 * v, &h.to_le_bytes());
    }
    for (v, nrm) in tile.normals.iter().take(n).enumerate() {
        for (c, x) in nrm.iter().enumerate() {
            put(&mut out, at.normals + 12 * v + 4 * c, &x.to_le_bytes());
        }
    }
    if k > 0 {
        let dst = &mut out[at.weights..at.weights + n * k];
        for (w, q) in tile.weights.chunks(k).zip(dst.chunks_mut(k)) {
            quantize_weights(w, q);
        }
    }
    let m = tile.materials.len().min(n);
    out[at.materials..at.materials + m].copy_from_slice(&tile.materials[..m]);
    for (v, d) in tile.water_depth.iter().take(n).enumerate() {
        put(&mut out, at.water_depth + 4 * v, &d.to_le_bytes());
    }
    if version == TileVersion::V2 {
        for (v, s) in water::surface(tile).iter().enumerate() {
            put(&mut out, at.water_surface + 4 * v, &s.to_le_bytes());
        }
        out[at.water_kind..at.water_kind + n].copy_from_slice(&water::kinds(tile));
    }
    if marked {
        let m = tile.volume_override.len().min(n);
        out[at.volume_override..at.volume_override + m].copy_from_slice(&tile.volume_override[..m]);
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
        assert!(b[108..128].iter().all(|&x| x == 0), "reserved in v1");
    }

    #[test]
    fn version_2_is_version_1_plus_the_water_sections() {
        let mut t = tile(1, -2, 3);
        t.water_depth[10] = 1.5;
        t.water_kind = vec![0; TILE_VERTEX_COUNT];
        t.water_kind[10] = 2;
        let v1 = encode(plan(), &t);
        let v2 = encode_version(plan(), &t, TileVersion::V2);
        let u32_at = |o: usize| u32::from_le_bytes([v2[o], v2[o + 1], v2[o + 2], v2[o + 3]]);
        assert_eq!(u16::from_le_bytes([v2[4], v2[5]]), 2, "version");
        let at = Layout::new(t.biome_count, TileVersion::V2, false);
        assert_eq!(u32_at(offset::TOTAL_LEN) as usize, v2.len());
        assert_eq!(u32_at(offset::WATER_SURFACE) as usize, at.water_surface);
        assert_eq!(u32_at(offset::WATER_KIND) as usize, at.water_kind);
        assert_eq!(at.water_surface, at.water_depth + 4 * TILE_VERTEX_COUNT);
        assert_eq!(at.water_surface % 4, 0);
        assert_eq!(at.water_kind % 4, 0);
        // The shared sections are the same bytes; only the version and the new fields differ.
        let shared = at.water_surface;
        assert_eq!(v1.len(), shared);
        assert_eq!(&v1[HEADER_LEN..], &v2[HEADER_LEN..shared]);
        assert_eq!(&v1[..4], &v2[..4]);
        assert_eq!(&v1[6..offset::TOTAL_LEN], &v2[6..offset::TOTAL_LEN]);
        let f32_at = |o: usize| f32::from_le_bytes([v2[o], v2[o + 1], v2[o + 2], v2[o + 3]]);
        let s = f32_at(at.water_surface + 4 * 10);
        assert_eq!(s, t.heights[10] + 1.5);
        assert_eq!(f32_at(at.water_surface).to_bits(), t.heights[0].to_bits());
        assert_eq!(v2[at.water_kind + 10], 2);
        assert!(v2[at.water_kind + TILE_VERTEX_COUNT..]
            .iter()
            .all(|&x| x == 0));
    }

    #[test]
    fn the_default_world_layout_matches_the_spec() {
        let at = Layout::new(4, TileVersion::V2, false);
        assert_eq!(
            (at.water_depth, at.water_surface, at.water_kind, at.total),
            (88_856, 105_756, 122_656, 126_884)
        );
        let marked = Layout::new(4, TileVersion::V2, true);
        assert_eq!((marked.volume_override, marked.total), (126_884, 131_112));
        assert_eq!(Layout::new(4, TileVersion::V1, false).total, 105_756);
    }
}
