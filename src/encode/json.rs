//! The `strata.tile.v1` JSON encoding of a height tile.
//!
//! One object; per-vertex arrays have 4225 entries indexed `j·65 + i` (`i` east, `j` south).
//! Numbers are serialised by `serde_json` (shortest round-trip form of each `f32`), so the bytes
//! are a deterministic function of the tile. Field by field, with units, in
//! `api/tile_format_v1.md` §JSON.

use super::{height_range, TILE_FORMAT};
use crate::terrain::world::MATERIALS;
use crate::terrain::{Tile, WorldPlan, TILE_VERTS};
use serde::Serialize;

/// A tile address as it appears in JSON products.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct KeyJson {
    /// Level of detail.
    pub lod: u32,
    /// Tile column (east is +x).
    pub x: i64,
    /// Tile row (south is +z).
    pub z: i64,
}

impl From<crate::terrain::TileKey> for KeyJson {
    fn from(k: crate::terrain::TileKey) -> Self {
        Self {
            lod: k.lod,
            x: k.x,
            z: k.z,
        }
    }
}

/// The JSON document; field order is the serialisation order.
#[derive(Debug, Serialize)]
struct TileJson<'a> {
    /// Always [`TILE_FORMAT`].
    format: &'static str,
    /// Address.
    key: KeyJson,
    /// World seed as a decimal string (u64 exceeds JavaScript's exact integers).
    seed: String,
    /// Vertices per side, 65.
    size: usize,
    /// Vertex spacing, metres.
    spacing_m: f32,
    /// World `[x, z]` of vertex `(0, 0)`, metres.
    origin_m: [f64; 2],
    /// World water level, metres.
    sea_level_m: f32,
    /// Skirt depth, metres.
    skirt_depth_m: f32,
    /// Lowest height, metres.
    min_height_m: f32,
    /// Highest height, metres.
    max_height_m: f32,
    /// Biome names; `weights[v][b]` is the weight of `biomes[b]`.
    biomes: Vec<&'a str>,
    /// Material names; `materials[v]` indexes this list.
    material_names: &'static [&'static str],
    /// Heights, metres.
    heights: &'a [f32],
    /// Biome weights per vertex, each summing to 1.
    weights: Vec<&'a [f32]>,
    /// Unit normals `[x, y, z]`, y up.
    normals: &'a [[f32; 3]],
    /// Material id per vertex.
    materials: &'a [u8],
    /// Water depth above the ground, metres (0 on land).
    water_depth: &'a [f32],
    /// Vertices a volume region overrides (indices), when any.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    volume_override: Vec<u32>,
}

/// Encodes a tile as `strata.tile.v1` JSON.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    let (min_height_m, max_height_m) = height_range(tile);
    let k = tile.biome_count.max(1);
    let doc = TileJson {
        format: TILE_FORMAT,
        key: tile.key.into(),
        seed: plan.seed.to_string(),
        size: TILE_VERTS,
        spacing_m: tile.spacing_m,
        origin_m: [tile.origin_x_m(), tile.origin_z_m()],
        sea_level_m: plan.params.sea_level_m,
        skirt_depth_m: tile.skirt_depth_m,
        min_height_m,
        max_height_m,
        biomes: plan.params.biomes.iter().map(|b| b.name.as_str()).collect(),
        material_names: &MATERIALS,
        heights: &tile.heights,
        weights: tile.weights.chunks(k).collect(),
        normals: &tile.normals,
        materials: &tile.materials,
        water_depth: &tile.water_depth,
        volume_override: tile
            .volume_override
            .iter()
            .enumerate()
            .filter(|(_, &m)| m != 0)
            .map(|(v, _)| v as u32)
            .collect(),
    };
    // Serialising plain structs of numbers and strings into a Vec cannot fail.
    serde_json::to_vec(&doc).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::{plan, tile};
    use crate::terrain::TILE_VERTEX_COUNT;

    #[test]
    fn fields_and_counts() {
        let t = tile(0, -1, 2);
        let bytes = encode(plan(), &t);
        assert_eq!(bytes, encode(plan(), &t), "deterministic");
        let v: serde_json::Value = serde_json::from_slice(&bytes).expect("valid JSON");
        assert_eq!(v["format"], "strata.tile.v1");
        assert_eq!(v["key"]["x"], -1);
        assert_eq!(v["seed"], "7");
        assert_eq!(
            v["heights"].as_array().map(Vec::len),
            Some(TILE_VERTEX_COUNT)
        );
        assert_eq!(
            v["weights"][0].as_array().map(Vec::len),
            Some(plan().biome_count())
        );
        assert_eq!(v["origin_m"][0], -64.0);
        // f32 values round-trip exactly.
        let h0 = v["heights"][100].as_f64().expect("number") as f32;
        assert_eq!(h0.to_bits(), t.heights[100].to_bits());
    }
}
