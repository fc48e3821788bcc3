//! What a session sends: the products of a view (tiles, and in protocol v2 volume chunks) and
//! their order, nearest first.

use super::view::ViewTile;
use crate::terrain::TileKey;
use crate::volume::chunk::{ChunkKey, CHUNK_CELLS};

/// The address of one streamed product.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Product {
    /// A height tile.
    Tile(TileKey),
    /// A volume chunk (protocol v2).
    Chunk(ChunkKey),
    /// A batch of Ptex pages (protocol v2), by the session's serial number: never superseded.
    Ptex(u64),
}

/// One frame to produce: a tile with its seam flags, or a chunk.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Work {
    /// A tile of the view.
    Tile(ViewTile),
    /// A chunk of the view.
    Chunk(ChunkKey),
}

impl Work {
    /// The product it makes.
    pub fn product(&self) -> Product {
        match self {
            Work::Tile(t) => Product::Tile(t.key),
            Work::Chunk(c) => Product::Chunk(*c),
        }
    }
}

/// Distance from the camera `(x, y, z)` to the centre of chunk `key`, metres; `cell_m` is the
/// LOD-0 cell size.
pub fn chunk_distance(key: ChunkKey, camera: [f64; 3], cell_m: f64) -> f64 {
    let side = CHUNK_CELLS as f64 * cell_m * (1u64 << key.lod) as f64;
    let centre = [key.x, key.y, key.z].map(|c| (c as f64 + 0.5) * side);
    let d: [f64; 3] = std::array::from_fn(|i| centre[i] - camera[i]);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

/// Distance in the ground plane from the camera `(x, z)` to the centre of tile `key`, metres.
pub fn tile_distance(key: TileKey, x: f64, z: f64, cell_m: f64) -> f64 {
    let size = 64.0 * cell_m * (1u64 << key.lod) as f64;
    ((key.x as f64 + 0.5) * size - x).hypot((key.z as f64 + 0.5) * size - z)
}

/// Merges a view's tiles (already nearest first) and chunks (already nearest first) into one
/// nearest-first list; on equal distances the tile comes first.
pub fn merge(
    tiles: impl IntoIterator<Item = ViewTile>,
    chunks: impl IntoIterator<Item = ChunkKey>,
    camera: [f64; 3],
    cell_m: f64,
) -> Vec<Work> {
    let mut tiles = tiles.into_iter().peekable();
    let mut chunks = chunks.into_iter().peekable();
    let mut out = Vec::new();
    loop {
        let take_tile = match (tiles.peek(), chunks.peek()) {
            (None, None) => return out,
            (Some(_), None) => true,
            (None, Some(_)) => false,
            (Some(t), Some(c)) => {
                tile_distance(t.key, camera[0], camera[2], cell_m)
                    <= chunk_distance(*c, camera, cell_m)
            }
        };
        if take_tile {
            out.extend(tiles.next().map(Work::Tile));
        } else {
            out.extend(chunks.next().map(Work::Chunk));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merging_keeps_both_orders_and_interleaves_by_distance() {
        let t = |x| ViewTile {
            key: TileKey { lod: 0, x, z: 0 },
            seams: [false; 4],
        };
        let c = |x| ChunkKey {
            lod: 0,
            x,
            y: 0,
            z: 0,
        };
        // Tile centres at 32 and 96 m, chunk centres at 16 and 80 m (cell 1 m).
        let out = merge([t(0), t(1)], [c(0), c(2)], [0.0, 16.0, 16.0], 1.0);
        let kinds: Vec<Product> = out.iter().map(Work::product).collect();
        assert_eq!(
            kinds,
            vec![
                Product::Chunk(c(0)),
                Product::Tile(t(0).key),
                Product::Chunk(c(2)),
                Product::Tile(t(1).key)
            ]
        );
    }
}
