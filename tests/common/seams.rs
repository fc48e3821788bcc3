//! Seams of a square block of tiles.

use strata::terrain::plan::TILE_VERTS;
use strata::terrain::Tile;

/// Asserts that the `n × n` tiles (row-major, west to east then north to south) share their
/// edge vertices with their east and south neighbours bit for bit.
pub fn assert_grid_seams(tiles: &[Tile], n: usize) {
    let last = TILE_VERTS - 1;
    for tz in 0..n {
        for tx in 0..n {
            let t = &tiles[tz * n + tx];
            if tx + 1 < n {
                let e = &tiles[tz * n + tx + 1];
                for j in 0..TILE_VERTS {
                    assert_eq!(
                        t.heights[j * TILE_VERTS + last].to_bits(),
                        e.heights[j * TILE_VERTS].to_bits(),
                        "tile ({tx}, {tz}) east edge, row {j}"
                    );
                }
            }
            if tz + 1 < n {
                let s = &tiles[(tz + 1) * n + tx];
                for i in 0..TILE_VERTS {
                    assert_eq!(
                        t.heights[last * TILE_VERTS + i].to_bits(),
                        s.heights[i].to_bits(),
                        "tile ({tx}, {tz}) south edge, column {i}"
                    );
                }
            }
        }
    }
}
