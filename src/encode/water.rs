//! The water of a tile as the version 2 encodings and the glb write it (`api/tile_format_v2.md`).
//!
//! A [`Tile`] carries the depth of the water above each vertex and, in worlds with rivers, its
//! kind (`terrain::earth::rivers::kind`). The encodings derive two per-vertex values from them:
//!
//! - the **water surface height**, metres: `heights[v] + water_depth[v]` where the depth is
//!   positive, and the ground height `heights[v]` itself (bit for bit) where it is not, so every
//!   value is finite and a dry vertex's surface is its ground;
//! - the **water kind**: the tile's kind, or 0 everywhere when the tile carries none (classic
//!   worlds and `earth-1` worlds stored before rivers, whose water is all the sea's).
//!
//! Both are computed from the served heights, so on an edge snapped by `?seams` the surface
//! moves with the ground, as the depth stays that of the unsnapped tile.

use crate::terrain::{Tile, TILE_VERTEX_COUNT};

/// The water surface height of every vertex, metres (the ground height where the vertex is dry).
pub fn surface(tile: &Tile) -> Vec<f32> {
    (0..TILE_VERTEX_COUNT)
        .map(|v| {
            let h = tile.heights.get(v).copied().unwrap_or(0.0);
            match tile.water_depth.get(v) {
                Some(&d) if d > 0.0 => h + d,
                _ => h,
            }
        })
        .collect()
}

/// The water kind of every vertex (`terrain::earth::rivers::kind`), 0 where the tile carries
/// no kinds.
pub fn kinds(tile: &Tile) -> Vec<u8> {
    (0..TILE_VERTEX_COUNT)
        .map(|v| tile.water_kind.get(v).copied().unwrap_or(0))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::tile;

    #[test]
    fn the_surface_is_the_ground_plus_the_depth_and_the_ground_where_dry() {
        let mut t = tile(0, 0, 0);
        t.water_depth.fill(0.0);
        t.water_depth[7] = 2.5;
        t.water_kind = vec![0; TILE_VERTEX_COUNT];
        t.water_kind[7] = 3;
        let s = surface(&t);
        assert_eq!(s.len(), TILE_VERTEX_COUNT);
        assert_eq!(s[7], t.heights[7] + 2.5);
        for v in (0..TILE_VERTEX_COUNT).filter(|&v| v != 7) {
            assert_eq!(s[v].to_bits(), t.heights[v].to_bits(), "vertex {v}");
        }
        assert_eq!(kinds(&t)[7], 3);
        t.water_kind.clear();
        assert!(kinds(&t).iter().all(|&k| k == 0), "no kinds: all 0");
    }
}
