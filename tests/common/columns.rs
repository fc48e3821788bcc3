//! A chunk's columns from a map of synthesised tiles, for the tests that mesh volume chunks
//! without the server.

use std::collections::HashMap;
use strata::terrain::{Tile, TileKey};
use strata::volume::chunk::{gather_columns, tiles_needed, ChunkKey, Columns, TileColumns};

/// Gathers the columns of chunk `key` from `tiles`, which must hold every tile of
/// [`tiles_needed`] at the chunk's LOD.
pub fn columns(key: ChunkKey, tiles: &HashMap<TileKey, Tile>) -> Columns {
    let views: Vec<TileColumns<'_>> = tiles_needed(key)
        .iter()
        .map(|&(x, z)| {
            let t = &tiles[&TileKey { lod: key.lod, x, z }];
            TileColumns {
                tile: (x, z),
                heights: &t.heights,
                normals: &t.normals,
                materials: &t.materials,
            }
        })
        .collect();
    gather_columns(key, &views).expect("tiles present")
}
