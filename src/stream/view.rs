//! Which tiles a client at a position needs: LOD rings after Choroś & Topolski §4.
//!
//! `rings = [A, B, C, …]` means `A` rings of LOD-0 tiles around the camera's tile, then `B` rings
//! of LOD-1 tiles around those, and so on. Level `l`'s square is aligned to level `l+1`'s lattice
//! (each coarser tile covers exactly four finer ones), so the levels nest without overlaps or
//! holes: level `l` contributes the tiles of its square that are not inside level `l−1`'s
//! footprint. An edge of a level-`l` tile that faces a level-`l+1` tile gets its seam flag, so the
//! client can ask for (and the server sends) edges snapped to the coarser neighbour: the mesh is
//! watertight.
//!
//! Order: nearest first (distance from the camera to the tile's centre), ties broken by angle
//! around the camera, then LOD — an outward spiral, deterministic for a given view.

use crate::terrain::{TileKey, MAX_LOD};

/// Most LOD levels a view may list.
pub const MAX_LEVELS: usize = (MAX_LOD + 1) as usize;
/// Most rings per level.
pub const MAX_RINGS_PER_LEVEL: u32 = 16;
/// Most tiles one view may select; a view asking for more is refused (`rings`).
pub const MAX_VIEW_TILES: usize = 4096;

/// A tile of a view and the edges it snaps to a coarser neighbour (`n, e, s, w`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ViewTile {
    /// Address.
    pub key: TileKey,
    /// Seam flags: the neighbour across the edge is one LOD coarser.
    pub seams: [bool; 4],
}

/// Inclusive square of tile coordinates at one level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Square {
    x0: i64,
    z0: i64,
    x1: i64,
    z1: i64,
}

impl Square {
    fn contains(&self, x: i64, z: i64) -> bool {
        x >= self.x0 && x <= self.x1 && z >= self.z0 && z <= self.z1
    }
}

/// The tiles of a view, nearest first. `cell_m` is the LOD-0 vertex spacing.
pub fn select(x_m: f64, z_m: f64, rings: &[u32], cell_m: f64) -> Vec<ViewTile> {
    let levels = rings.len().min(MAX_LEVELS);
    let mut squares: Vec<Square> = Vec::with_capacity(levels);
    for (l, &r) in rings.iter().take(levels).enumerate() {
        let size = 64.0 * cell_m * (1u64 << l) as f64;
        let r = r.min(MAX_RINGS_PER_LEVEL) as i64;
        let sq = match squares.last() {
            None => {
                let cx = (x_m / size).floor() as i64;
                let cz = (z_m / size).floor() as i64;
                Square {
                    x0: cx - r,
                    z0: cz - r,
                    x1: cx + r,
                    z1: cz + r,
                }
            }
            Some(inner) => {
                // The finer square's footprint at this level, grown by r rings.
                Square {
                    x0: inner.x0.div_euclid(2) - r,
                    z0: inner.z0.div_euclid(2) - r,
                    x1: inner.x1.div_euclid(2) + r,
                    z1: inner.z1.div_euclid(2) + r,
                }
            }
        };
        // Align to the next level's lattice so the next level can tile around it.
        let aligned = Square {
            x0: sq.x0 - sq.x0.rem_euclid(2),
            z0: sq.z0 - sq.z0.rem_euclid(2),
            x1: sq.x1 + 1 - sq.x1.rem_euclid(2),
            z1: sq.z1 + 1 - sq.z1.rem_euclid(2),
        };
        squares.push(if l + 1 < levels { aligned } else { sq });
    }
    let mut out = Vec::new();
    for (l, sq) in squares.iter().enumerate() {
        for z in sq.z0..=sq.z1 {
            for x in sq.x0..=sq.x1 {
                if l > 0 {
                    let inner = &squares[l - 1];
                    // Level l−1's square covers this tile's four children exactly or not at all.
                    if inner.contains(2 * x, 2 * z) {
                        continue;
                    }
                }
                let coarser_outside = |nx: i64, nz: i64| l + 1 < levels && !sq.contains(nx, nz);
                let seams = [
                    coarser_outside(x, z - 1),
                    coarser_outside(x + 1, z),
                    coarser_outside(x, z + 1),
                    coarser_outside(x - 1, z),
                ];
                out.push(ViewTile {
                    key: TileKey {
                        lod: l as u32,
                        x,
                        z,
                    },
                    seams,
                });
            }
        }
    }
    let centre = |t: &ViewTile| {
        let size = 64.0 * cell_m * (1u64 << t.key.lod) as f64;
        (
            (t.key.x as f64 + 0.5) * size - x_m,
            (t.key.z as f64 + 0.5) * size - z_m,
        )
    };
    out.sort_by(|a, b| {
        let (ax, az) = centre(a);
        let (bx, bz) = centre(b);
        (ax * ax + az * az)
            .total_cmp(&(bx * bx + bz * bz))
            .then(az.atan2(ax).total_cmp(&bz.atan2(bx)))
            .then(a.key.cmp(&b.key))
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    /// Marks the LOD-0-sized cells each tile covers; every cell of the covered area exactly once.
    fn coverage(tiles: &[ViewTile]) -> std::collections::HashMap<(i64, i64), usize> {
        let mut m = std::collections::HashMap::new();
        for t in tiles {
            let s = 1i64 << t.key.lod;
            for dz in 0..s {
                for dx in 0..s {
                    *m.entry((t.key.x * s + dx, t.key.z * s + dz)).or_insert(0) += 1;
                }
            }
        }
        m
    }

    #[test]
    fn rings_nest_without_overlaps_or_holes() {
        for (x, z) in [(10.0, 10.0), (-1000.0, 345.0), (70.0, -64.5)] {
            let tiles = select(x, z, &[2, 1, 2, 4, 8], 1.0);
            let cov = coverage(&tiles);
            assert!(cov.values().all(|n| *n == 1), "a cell is covered twice");
            // The covered area is a filled square: no holes.
            let xs: Vec<i64> = cov.keys().map(|k| k.0).collect();
            let zs: Vec<i64> = cov.keys().map(|k| k.1).collect();
            let (x0, x1) = (
                *xs.iter().min().unwrap_or(&0),
                *xs.iter().max().unwrap_or(&0),
            );
            let (z0, z1) = (
                *zs.iter().min().unwrap_or(&0),
                *zs.iter().max().unwrap_or(&0),
            );
            assert_eq!(cov.len() as i64, (x1 - x0 + 1) * (z1 - z0 + 1));
            // The camera's own LOD-0 tile is first.
            assert_eq!(
                tiles[0].key,
                TileKey {
                    lod: 0,
                    x: (x / 64.0).floor() as i64,
                    z: (z / 64.0).floor() as i64
                }
            );
            let keys: HashSet<_> = tiles.iter().map(|t| t.key).collect();
            assert_eq!(keys.len(), tiles.len());
        }
    }

    #[test]
    fn seams_face_exactly_the_coarser_neighbours() {
        let tiles = select(5.0, 5.0, &[1, 1, 1], 1.0);
        let at: std::collections::HashMap<_, _> = tiles.iter().map(|t| (t.key, t)).collect();
        let cov = |lod: u32, x: i64, z: i64| {
            tiles
                .iter()
                .find(|t| {
                    let s = 1i64 << (t.key.lod as i64 - lod as i64).max(0);
                    t.key.lod >= lod && t.key.x == x.div_euclid(s) && t.key.z == z.div_euclid(s)
                })
                .map(|t| t.key.lod)
        };
        for t in &tiles {
            let (x, z, l) = (t.key.x, t.key.z, t.key.lod);
            for (i, (nx, nz)) in [(x, z - 1), (x + 1, z), (x, z + 1), (x - 1, z)]
                .into_iter()
                .enumerate()
            {
                let neighbour = cov(l, nx, nz);
                assert_eq!(
                    t.seams[i],
                    neighbour == Some(l + 1),
                    "{:?} edge {i}: neighbour {neighbour:?}",
                    t.key
                );
                assert!(
                    neighbour.is_none()
                        || neighbour >= Some(l)
                        || at.contains_key(&TileKey {
                            lod: l,
                            x: nx,
                            z: nz
                        })
                        || neighbour == Some(l - 1)
                );
            }
        }
    }

    #[test]
    fn nearest_first_and_bounded() {
        let tiles = select(0.0, 0.0, &[2, 1, 2, 4, 8], 1.0);
        assert!(tiles.len() <= MAX_VIEW_TILES);
        // The largest view the limits allow stays a few times the bound, so it can be counted
        // and refused without exhausting memory.
        let largest = select(0.0, 0.0, &[MAX_RINGS_PER_LEVEL; MAX_LEVELS], 1.0).len();
        assert!(largest < 10 * MAX_VIEW_TILES, "{largest}");
        let d = |t: &ViewTile| {
            let s = 64.0 * (1u64 << t.key.lod) as f64;
            ((t.key.x as f64 + 0.5) * s).hypot((t.key.z as f64 + 0.5) * s)
        };
        assert!(tiles.windows(2).all(|w| d(&w[0]) <= d(&w[1])));
    }
}
