//! The scatter product as JSON: `{"format", "key", "seed", "points": [{x, y, z, biome, kind,
//! level}]}` with world positions in metres (`y` is the ground height), computed by
//! [`crate::terrain::scatter::scatter`] from the unsnapped tile.

use super::json::KeyJson;
use crate::terrain::scatter::ScatterPoint;
use crate::terrain::{Tile, WorldPlan};
use serde::Serialize;

/// Format identifier of the scatter JSON.
pub const SCATTER_FORMAT: &str = "strata.scatter.v1";

#[derive(Debug, Serialize)]
struct ScatterJson<'a> {
    format: &'static str,
    key: KeyJson,
    seed: String,
    points: &'a [ScatterPoint],
}

/// Encodes a tile's scatter points.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    let points = crate::terrain::scatter::scatter(plan, tile);
    let doc = ScatterJson {
        format: SCATTER_FORMAT,
        key: tile.key.into(),
        seed: plan.seed.to_string(),
        points: &points,
    };
    serde_json::to_vec(&doc).unwrap_or_default()
}
