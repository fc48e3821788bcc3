//! The volume chunks a protocol-v2 view streams for caves (issue 19): where a `strata`
//! element's caves breach the ground or may come within
//! [`NEAR_GROUND_M`](crate::subsurface::openings::NEAR_GROUND_M) of it.
//!
//! 1. The **sites** ([`crate::subsurface::openings`]) of the elements meeting the ground area of
//!    the view's chunk rings: the bounding squares of those caves, from the elements' bounded
//!    data, without evaluating a column.
//! 2. The chunk **columns** `(lod, x, z)` of the rings whose ground square meets a site.
//! 3. Per column, the **ground span**: the lowest and highest height of the columns the chunk
//!    reads (the vertices of the height tiles of its LOD, [`tiles_needed`]: the tiles the
//!    chunk's own product reads). The column's chunks are those of the rings whose height range
//!    meets `[lowest + floor − 2·s, highest + 2·s]` (`floor` the deepest floor of the sites
//!    meeting the column, `s` the LOD's cell): the ground and everything carved below it.
//!
//! So the selection costs the site search (bounded by its cell budget) and the height tiles of
//! the columns that meet a site, which the chunks selected there read anyway.

use super::chunks::{chunk_side, Rings};
use crate::subsurface::openings::CaveSite;
use crate::terrain::plan::{TILE_QUADS, TILE_VERTS};
use crate::terrain::Tile;
use crate::volume::chunk::{tiles_needed, ChunkKey, CHUNK_CELLS};

/// A chunk column of the rings that meets a site.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaveColumn {
    /// LOD of its chunks.
    pub lod: u32,
    /// Chunk x.
    pub x: i64,
    /// Chunk z.
    pub z: i64,
    /// The range of chunk `y` the level's cube spans.
    pub cube_y: [i64; 2],
    /// The deepest floor of the sites meeting it, metres below the ground (≤ 0).
    pub floor_m: f64,
}

/// The chunk columns of `rings` whose ground square meets one of `sites`.
pub fn cave_columns(rings: &Rings, cell_m: f64, sites: &[CaveSite]) -> Vec<CaveColumn> {
    if sites.is_empty() {
        return Vec::new();
    }
    rings
        .columns()
        .filter_map(|(lod, x, z, cube_y)| {
            let side = chunk_side(lod, cell_m);
            let (x0, z0) = (x as f64 * side, z as f64 * side);
            let floor = sites
                .iter()
                .filter(|s| {
                    s.min[0] < x0 + side && x0 < s.max[0] && s.min[1] < z0 + side && z0 < s.max[1]
                })
                .map(|s| s.floor_m)
                .reduce(f64::min)?;
            Some(CaveColumn {
                lod,
                x,
                z,
                cube_y,
                floor_m: floor,
            })
        })
        .collect()
}

/// The tiles whose vertices give the ground of column `c` ([`tiles_needed`]).
pub fn column_tiles(c: &CaveColumn) -> Vec<(i64, i64)> {
    tiles_needed(ChunkKey {
        lod: c.lod,
        x: c.x,
        y: 0,
        z: c.z,
    })
}

/// The lowest and highest ground height of the columns chunk column `c` reads, from the
/// height tiles of its LOD given as `((tile x, tile z), tile)`; `None` when they hold none.
pub fn ground_span(c: &CaveColumn, tiles: &[((i64, i64), &Tile)]) -> Option<(f32, f32)> {
    let first = |v: i64| v * CHUNK_CELLS as i64 - 1;
    let (gx0, gz0) = (first(c.x), first(c.z));
    let (gx1, gz1) = (gx0 + CHUNK_CELLS as i64 + 1, gz0 + CHUNK_CELLS as i64 + 1);
    let mut span: Option<(f32, f32)> = None;
    for ((tx, tz), tile) in tiles {
        let (ox, oz) = (tx * TILE_QUADS, tz * TILE_QUADS);
        for j in (gz0 - oz).max(0)..=(gz1 - oz).min(TILE_QUADS) {
            for i in (gx0 - ox).max(0)..=(gx1 - ox).min(TILE_QUADS) {
                let Some(&h) = tile.heights.get(j as usize * TILE_VERTS + i as usize) else {
                    continue;
                };
                span = Some(span.map_or((h, h), |(a, b)| (a.min(h), b.max(h))));
            }
        }
    }
    span
}

/// The chunks of column `c` held by `rings` whose height range meets the ground span
/// `(lowest, highest)` widened down by the column's floor and by two cells each way (module
/// docs); `valid` drops chunks outside the world's limits.
pub fn column_chunks(
    rings: &Rings,
    cell_m: f64,
    c: &CaveColumn,
    ground: (f32, f32),
    valid: impl Fn(ChunkKey) -> bool,
) -> Vec<ChunkKey> {
    let side = chunk_side(c.lod, cell_m);
    let margin = 2.0 * cell_m * (1u64 << c.lod) as f64;
    let lo = f64::from(ground.0) + c.floor_m - margin;
    let hi = f64::from(ground.1) + margin;
    let (y0, y1) = (
        ((lo / side).floor() as i64).max(c.cube_y[0]),
        ((hi / side).floor() as i64).min(c.cube_y[1]),
    );
    (y0..=y1)
        .map(|y| ChunkKey {
            lod: c.lod,
            x: c.x,
            y,
            z: c.z,
        })
        .filter(|k| rings.holds(*k) && valid(*k))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_site_selects_the_chunks_from_its_floor_to_the_ground_and_no_other() {
        let rings = Rings::new([10.0, 100.0, 10.0], &[2, 1], 1.0);
        let site = CaveSite {
            min: [4.0, 4.0],
            max: [28.0, 28.0],
            floor_m: -20.0,
        };
        let columns = cave_columns(&rings, 1.0, &[site]);
        // The LOD-0 column (0, 0) and the LOD-1 column (0, 0) hold the site.
        let at: Vec<(u32, i64, i64)> = columns.iter().map(|c| (c.lod, c.x, c.z)).collect();
        assert_eq!(at, vec![(0, 0, 0), (1, 0, 0)]);
        let c = columns[0];
        assert_eq!((c.cube_y, c.floor_m), ([0, 5], -20.0));
        assert_eq!(column_tiles(&c), vec![(-1, -1), (0, -1), (-1, 0), (0, 0)]);
        // From 60 − 20 − 2 = 38 (chunk y 1) to 70 + 2 = 72 (chunk y 2).
        let chunks = column_chunks(&rings, 1.0, &c, (60.0, 70.0), |_| true);
        let ys: Vec<i64> = chunks.iter().map(|k| k.y).collect();
        assert_eq!(ys, vec![1, 2]);
        // The LOD-1 chunks there lie inside the LOD-0 cube: none.
        assert!(column_chunks(&rings, 1.0, &columns[1], (60.0, 70.0), |_| true).is_empty());
        assert!(column_chunks(&rings, 1.0, &c, (60.0, 70.0), |_| false).is_empty());
        assert!(cave_columns(&rings, 1.0, &[]).is_empty());
    }
}
