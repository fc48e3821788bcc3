//! An upper bound of an export archive's size, known before any tile is synthesised.
//!
//! The server checks it against its disk budgets before it admits a job (`export_too_large`,
//! `export_quota_exceeded`), so the bound must never be below the real archive: a job that
//! passes the check can then never write more than it reserved. Each member's bound follows its
//! encoder's layout, not a measured typical size:
//!
//! - `bin`: the `STRT` v1 layout ([`crate::encode::bin`]) is fixed by the vertex and biome
//!   counts, plus the optional volume-override section.
//! - `json`: every number at its longest text ([`F32_TEXT`], [`F64_TEXT`]), every name escaped
//!   at its longest (six bytes per byte, `\u00XX`), and a fixed allowance for keys and
//!   punctuation.
//! - `png`: 65 rows of 131 filtered bytes through deflate, bounded by the 9/8 worst case of a
//!   fixed-Huffman block (an encoder that picks stored blocks stays below it too), plus the
//!   chunk headers and the four `tEXt` chunks.
//! - `glb`: the surface and skirt mesh ([`crate::encode::glb`]) plus a water mesh as large as the
//!   whole surface ([`crate::encode::water_glb`]), and a fixed allowance for the JSON chunk.
//! - `scatter`: one point per candidate ([`crate::terrain::scatter::candidates`]) at its longest
//!   text.
//!
//! Each member adds its 512-byte tar header and up to 511 bytes of padding; the manifest gets a
//! per-member allowance; the archive ends with two zero blocks. `tests/export_size.rs` checks the
//! bound against real archives, and the tests below against incompressible and wet tiles.

use super::{ExportSpec, Product, Shard};
use crate::encode::{bin, glb, Format};
use crate::terrain::world::MATERIALS;
use crate::terrain::{WorldPlan, TILE_VERTEX_COUNT, TILE_VERTS};

/// Longest JSON text of an `f32` (`-1.2345678e-38` is 14 bytes) plus its separator, bytes.
pub const F32_TEXT: u64 = 16;
/// Longest JSON text of an `f64` (`-1.2345678901234567e-308` is 24 bytes) plus its separator, bytes.
pub const F64_TEXT: u64 = 26;
/// Longest JSON text of an `i64` or `u64` plus its separator, bytes.
pub const INT_TEXT: u64 = 22;
/// A tar member's header, bytes.
const TAR_HEADER: u64 = 512;
/// The end-of-archive marker, bytes.
const TAR_END: u64 = 1024;
/// A manifest entry (name up to 100 bytes, size, 64 hex digits, indentation), bytes.
const MANIFEST_ENTRY: u64 = 320;
/// The manifest without its entries (format, seed, spec, shard), bytes.
const MANIFEST_FIXED: u64 = 1024;
/// The keys, punctuation and small fields of a JSON tile or glb JSON chunk, bytes.
const JSON_FIXED: u64 = 4096;

/// Upper bound of one tile member in `format` of the world `plan`, bytes.
pub fn tile_member_bound(plan: &WorldPlan, format: Format) -> u64 {
    let v = TILE_VERTEX_COUNT as u64;
    let k = plan.biome_count().max(1) as u64;
    let pad4 = |n: u64| n.div_ceil(4) * 4;
    match format {
        Format::Bin => {
            // Heights, normals (3 × f32), weights (k × u8), materials, water depth, override.
            bin::HEADER_LEN as u64 + 4 * v + 12 * v + pad4(k * v) + pad4(v) + 4 * v + pad4(v)
        }
        Format::Json => {
            let names = escaped(plan.params.biomes.iter().map(|b| b.name.as_str()))
                + escaped(MATERIALS.iter().copied());
            let per_vertex = F32_TEXT // height
                + 3 + k * F32_TEXT // weights: [w, …],
                + 3 + 3 * F32_TEXT // normal: [x, y, z],
                + 4 // material
                + F32_TEXT // water depth
                + 5; // a volume-override index below 4225
            JSON_FIXED + 8 * F64_TEXT + names + v * per_vertex
        }
        Format::Png => {
            let side = TILE_VERTS as u64;
            let raw = side * (1 + 2 * side);
            let deflate = raw + raw / 8 + 64;
            let idat_chunks = 1 + deflate / 4096;
            let text = 4 * (12 + 32 + 64);
            8 + 25 + text + 12 * idat_chunks + 6 + deflate + 12
        }
        Format::Glb => {
            let vertices = glb::VERTEX_COUNT as u64;
            let triangles = (glb::SURFACE_TRIANGLES + glb::SKIRT_TRIANGLES) as u64;
            let terrain = vertices * (12 + 12 + 8) + pad4(triangles * 3 * 2);
            let quads = ((TILE_VERTS - 1) * (TILE_VERTS - 1)) as u64;
            let water = v * (12 + 12) + pad4(quads * 6 * 2);
            12 + 8 + 2 * JSON_FIXED + 8 + terrain + water
        }
    }
}

/// Upper bound of one tile's scatter member at `lod`, bytes.
pub fn scatter_member_bound(plan: &WorldPlan, lod: u32) -> u64 {
    let longest =
        |names: &mut dyn Iterator<Item = &str>| 6 * names.map(str::len).max().unwrap_or(0) as u64;
    let biome = longest(&mut plan.params.biomes.iter().map(|b| b.name.as_str()));
    let kind = longest(
        &mut plan
            .params
            .biomes
            .iter()
            .flat_map(|b| b.scatter.iter().map(|k| k.kind.as_str())),
    );
    // {"x":…,"y":…,"z":…,"biome":"…","kind":"…","level":…},
    let point = 48 + 2 * F64_TEXT + F32_TEXT + biome + kind + INT_TEXT;
    256 + 4 * INT_TEXT + crate::terrain::scatter::candidates(plan, lod) * point
}

/// Upper bound of the members of one tile of `spec`, bytes, tar headers and padding included.
pub fn tile_bound(plan: &WorldPlan, spec: &ExportSpec) -> u64 {
    let member = |data: u64| TAR_HEADER + data.div_ceil(512) * 512 + MANIFEST_ENTRY;
    spec.products
        .iter()
        .map(|p| match p {
            Product::Tiles => spec
                .formats
                .iter()
                .filter_map(|f| Format::from_extension(f))
                .map(|f| member(tile_member_bound(plan, f)))
                .sum(),
            Product::Scatter => member(scatter_member_bound(plan, spec.lod)),
            Product::Ptex => member(ptx_member_bound(
                spec.ptex_res.unwrap_or(crate::ptex::MIN_RES),
            )),
        })
        .sum()
}

/// Upper bound of a tile's `.ptx` at `res` ([`crate::encode::ptx`]): its fixed blocks and every
/// zlib block's data (16 faces, 8 `f32` channels, every level) with deflate's worst-case growth
/// (stored blocks: 5 bytes per 65,535, plus the zlib header and checksum, bounded by 1/1000 + 64
/// bytes a block).
pub fn ptx_member_bound(res: u32) -> u64 {
    let faces = (crate::ptex::TILE_FACES * crate::ptex::TILE_FACES) as u64;
    let levels = u64::from(res.max(1).trailing_zeros()) + 1;
    let mut raw = faces * (20 + 4 * crate::encode::ptx::CHANNELS as u64);
    let mut blocks = 2;
    for l in 0..levels {
        let side = u64::from(res >> l);
        raw += faces * (4 * crate::encode::ptx::CHANNELS as u64 * side * side + 4);
        blocks += faces + 1;
    }
    104 + 16 * levels + 8 + raw + raw / 1000 + 64 * blocks
}

/// Upper bound of the archive of `shard` of `spec` (a validated spec), bytes.
pub fn archive_bound(plan: &WorldPlan, spec: &ExportSpec, shard: Shard) -> u64 {
    let total = spec.tile_count();
    let tiles = total * (shard.index as u64 + 1) / shard.count as u64
        - total * shard.index as u64 / shard.count as u64;
    let formats: u64 = spec.formats.iter().map(|f| f.len() as u64 + 4).sum();
    let manifest = MANIFEST_FIXED + formats + TAR_HEADER + 512;
    tiles.saturating_mul(tile_bound(plan, spec)) + manifest + TAR_END
}

/// Bytes of `names` as JSON strings at their longest: every byte escaped, quotes, separator.
fn escaped<'a>(names: impl Iterator<Item = &'a str>) -> u64 {
    names.map(|n| 6 * n.len() as u64 + 3).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::{self, TileVersion};
    use crate::terrain::{TileKey, WorldParams};

    fn plan() -> WorldPlan {
        WorldPlan::new(42, WorldParams::default()).expect("plan")
    }

    fn sizes(plan: &WorldPlan, tile: &crate::terrain::Tile) -> Vec<(Format, u64)> {
        Format::ALL
            .iter()
            .map(|&f| {
                let body = encode::tile(plan, tile, f, TileVersion::V1).expect("encode");
                (f, body.body.len() as u64)
            })
            .collect()
    }

    #[test]
    fn every_format_stays_below_its_bound_on_noise_and_water() {
        let plan = plan();
        // Incompressible heights, a volume override everywhere and water on every vertex.
        let mut tile = crate::edits::synthesize(
            &plan,
            TileKey {
                lod: 0,
                x: 3,
                z: -2,
            },
            &Default::default(),
        );
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        for h in &mut tile.heights {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            *h = -1.234_567_8e-30 * (state >> 11) as f32;
        }
        tile.volume_override = vec![1; TILE_VERTEX_COUNT];
        if tile.water_kind.len() == TILE_VERTEX_COUNT {
            tile.water_kind.fill(1);
        }
        for (f, len) in sizes(&plan, &tile) {
            let bound = tile_member_bound(&plan, f);
            assert!(len <= bound, "{f:?}: {len} bytes above the bound {bound}");
        }
    }

    #[test]
    fn the_bounds_are_not_vacuous() {
        let plan = plan();
        let tile =
            crate::edits::synthesize(&plan, TileKey { lod: 2, x: 0, z: 0 }, &Default::default());
        for (f, len) in sizes(&plan, &tile) {
            let bound = tile_member_bound(&plan, f);
            assert!(
                len <= bound && bound <= 4 * len.max(4096),
                "{f:?}: {len} bytes against the bound {bound}"
            );
        }
    }
}
