//! The `strata.tile.v1` and `strata.tile.v2` JSON encodings of a height tile.
//!
//! One object; per-vertex arrays have 4225 entries indexed `j·65 + i` (`i` east, `j` south).
//! Numbers are serialised by `serde_json` (shortest round-trip form of each `f32`), so the bytes
//! are a deterministic function of the tile. Field by field, with units, in
//! `api/tile_format_v1.md` §JSON; version 2 (`api/tile_format_v2.md`) names itself
//! `strata.tile.v2` and adds `water_surface_m` and `water_kind` after `water_depth`.

use super::{height_range, water, TileVersion, TILE_FORMAT, TILE_FORMAT_V2};
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
    /// [`TILE_FORMAT`] or [`TILE_FORMAT_V2`].
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
    /// Water surface height, metres (the ground height where dry); version 2 only.
    #[serde(skip_serializing_if = "Option::is_none")]
    water_surface_m: Option<Vec<f32>>,
    /// Water kind per vertex (0 none, 1 sea, 2 lake, 3 river); version 2 only.
    #[serde(skip_serializing_if = "Option::is_none")]
    water_kind: Option<Vec<u8>>,
    /// Vertices a volume region overrides (indices), when any.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    volume_override: Vec<u32>,
}

/// Encodes a tile as `strata.tile.v1` JSON.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    encode_version(plan, tile, TileVersion::V1)
}

/// Encodes a tile as JSON of `version`.
pub fn encode_version(plan: &WorldPlan, tile: &Tile, version: TileVersion) -> Vec<u8> {
    let (min_height_m, max_height_m) = height_range(tile);
    let k = tile.biome_count.max(1);
    let v2 = version == TileVersion::V2;
    let doc = TileJson {
        format: if v2 { TILE_FORMAT_V2 } else { TILE_FORMAT },
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
        water_surface_m: v2.then(|| water::surface(tile)),
        water_kind: v2.then(|| water::kinds(tile)),
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
        assert!(v.get("water_surface_m").is_none() && v.get("water_kind").is_none());
    }

    #[test]
    fn version_2_adds_the_water_surface_and_kind() {
        let mut t = tile(2, 1, 1);
        t.water_depth[5] = 0.75;
        t.water_kind = vec![0; TILE_VERTEX_COUNT];
        t.water_kind[5] = 3;
        let v: serde_json::Value =
            serde_json::from_slice(&encode_version(plan(), &t, TileVersion::V2)).expect("JSON");
        assert_eq!(v["format"], "strata.tile.v2");
        let surface: Vec<f32> = v["water_surface_m"]
            .as_array()
            .expect("surface")
            .iter()
            .map(|x| x.as_f64().expect("number") as f32)
            .collect();
        let want = water::surface(&t);
        assert_eq!(surface.len(), TILE_VERTEX_COUNT);
        for (a, b) in surface.iter().zip(&want) {
            assert_eq!(a.to_bits(), b.to_bits());
        }
        assert_eq!(surface[5], t.heights[5] + 0.75);
        assert_eq!(v["water_kind"][5], 3);
        assert_eq!(v["water_kind"][6], 0);
        // Everything else is the version 1 document.
        let mut v1: serde_json::Value = serde_json::from_slice(&encode(plan(), &t)).expect("JSON");
        let mut v2 = v.clone();
        for doc in [&mut v1, &mut v2] {
            let o = doc.as_object_mut().expect("object");
            for key in ["format", "water_surface_m", "water_kind"] {
                o.remove(key);
            }
        }
        assert_eq!(v1, v2);
    }
}
