//! Which volume chunks a protocol-v2 client at a position needs: 3D LOD rings around the camera,
//! kept where the world's surface is not a heightfield (its volume regions and, through
//! [`super::cave_chunks`], its caves near the ground), plus the chunks the client asks for by
//! address.
//!
//! `chunk_rings = [A, B, C, D]` mirrors the tiles' rings in three dimensions: `A` rings of LOD-0
//! chunks around the camera's chunk, then `B` rings of LOD-1 chunks around that cube, and so on
//! up to LOD 3. Each level's cube is aligned to the next level's lattice (a coarser chunk covers
//! exactly eight finer ones), so levels nest without overlaps or holes ([`Rings`]). Of those
//! cubes only the chunks meeting a box of the world's volume regions, or holding the ground
//! over a cave that opens to it or comes near it, are streamed: elsewhere the tiles already
//! show the whole surface.

use super::protocol::VolumeView;
use super::session::StreamError;
use super::work::chunk_distance;
use crate::encode::Format;
use crate::terrain::WorldPlan;
use crate::volume::chunk::{max_chunk_xz, max_chunk_y, ChunkKey, CHUNK_CELLS, MAX_CHUNK_LOD};

/// Most chunk LOD levels a view may list (LOD 0 to [`MAX_CHUNK_LOD`]).
pub const MAX_CHUNK_LEVELS: usize = (MAX_CHUNK_LOD + 1) as usize;
/// Most rings per chunk level.
pub const MAX_CHUNK_RINGS: u32 = 4;
/// Most chunks a view may ask for by address.
pub const MAX_ASKED_CHUNKS: usize = 256;
/// Most chunks one view streams; the nearest are kept when the rings and regions select more.
pub const MAX_VIEW_CHUNKS: usize = 1024;

/// A world-space box, metres: `[min, max]`, each `[x, y, z]`.
pub type Box3 = [[f64; 3]; 2];

/// Inclusive cube of chunk coordinates at one level.
#[derive(Clone, Copy, Debug)]
struct Cube {
    lo: [i64; 3],
    hi: [i64; 3],
}

impl Cube {
    fn contains(&self, c: [i64; 3]) -> bool {
        (0..3).all(|i| c[i] >= self.lo[i] && c[i] <= self.hi[i])
    }
}

/// The world box of chunk `key`, metres.
pub fn chunk_box(key: ChunkKey, cell_m: f64) -> Box3 {
    let side = chunk_side(key.lod, cell_m);
    let lo = [key.x, key.y, key.z].map(|c| c as f64 * side);
    [lo, lo.map(|v| v + side)]
}

/// Side of a chunk of `lod`, metres.
pub fn chunk_side(lod: u32, cell_m: f64) -> f64 {
    CHUNK_CELLS as f64 * cell_m * (1u64 << lod) as f64
}

fn meets(a: &Box3, b: &Box3) -> bool {
    (0..3).all(|i| a[0][i] < b[1][i] && b[0][i] < a[1][i])
}

/// The nested cubes of `chunk_rings` around a camera, one per level (module docs).
#[derive(Clone, Debug)]
pub struct Rings {
    cubes: Vec<Cube>,
    cell_m: f64,
}

impl Rings {
    /// The cubes of `rings` around `camera` (metres) in a world of LOD-0 cell `cell_m`.
    pub fn new(camera: [f64; 3], rings: &[u32], cell_m: f64) -> Rings {
        let levels = rings.len().min(MAX_CHUNK_LEVELS);
        let mut cubes: Vec<Cube> = Vec::with_capacity(levels);
        for (l, &r) in rings.iter().take(levels).enumerate() {
            let side = chunk_side(l as u32, cell_m);
            let r = i64::from(r.min(MAX_CHUNK_RINGS));
            let cube = match cubes.last() {
                None => {
                    let c = camera.map(|v| (v / side).floor() as i64);
                    Cube {
                        lo: c.map(|v| v - r),
                        hi: c.map(|v| v + r),
                    }
                }
                Some(inner) => Cube {
                    lo: inner.lo.map(|v| v.div_euclid(2) - r),
                    hi: inner.hi.map(|v| v.div_euclid(2) + r),
                },
            };
            let aligned = Cube {
                lo: cube.lo.map(|v| v - v.rem_euclid(2)),
                hi: cube.hi.map(|v| v + 1 - v.rem_euclid(2)),
            };
            cubes.push(if l + 1 < levels { aligned } else { cube });
        }
        Rings { cubes, cell_m }
    }

    /// Whether `key` is a chunk of the rings: inside its level's cube and not inside the finer
    /// level's (which covers a coarser chunk's eight children exactly or not at all).
    pub fn holds(&self, key: ChunkKey) -> bool {
        let l = key.lod as usize;
        let c = [key.x, key.y, key.z];
        self.cubes.get(l).is_some_and(|cube| cube.contains(c))
            && (l == 0 || !self.cubes[l - 1].contains(c.map(|v| 2 * v)))
    }

    /// Every chunk of the rings, level by level.
    pub fn chunks(&self) -> impl Iterator<Item = ChunkKey> + '_ {
        self.cubes.iter().enumerate().flat_map(move |(l, cube)| {
            (cube.lo[1]..=cube.hi[1]).flat_map(move |y| {
                (cube.lo[2]..=cube.hi[2]).flat_map(move |z| {
                    (cube.lo[0]..=cube.hi[0])
                        .map(move |x| ChunkKey {
                            lod: l as u32,
                            x,
                            y,
                            z,
                        })
                        .filter(|k| self.holds(*k))
                })
            })
        })
    }

    /// The chunk columns `(lod, x, z)` of the rings, each with the range of chunk `y` its
    /// level's cube spans.
    pub fn columns(&self) -> impl Iterator<Item = (u32, i64, i64, [i64; 2])> + '_ {
        self.cubes.iter().enumerate().flat_map(|(l, cube)| {
            (cube.lo[2]..=cube.hi[2]).flat_map(move |z| {
                (cube.lo[0]..=cube.hi[0]).map(move |x| (l as u32, x, z, [cube.lo[1], cube.hi[1]]))
            })
        })
    }

    /// The ground area the rings cover, metres: `[x0, z0, x1, z1]` (`None` without levels).
    pub fn area(&self) -> Option<[f64; 4]> {
        let l = self.cubes.len().checked_sub(1)?;
        let side = chunk_side(l as u32, self.cell_m);
        let c = self.cubes[l];
        Some([
            c.lo[0] as f64 * side,
            c.lo[2] as f64 * side,
            (c.hi[0] + 1) as f64 * side,
            (c.hi[2] + 1) as f64 * side,
        ])
    }
}

/// The chunks of the rings around `camera` (metres) that meet one of `regions`, nearest first
/// (distance from the camera to the chunk's centre, then LOD, then address), at most
/// [`MAX_VIEW_CHUNKS`]. `valid` drops chunks outside the world's limits.
pub fn select_chunks(
    camera: [f64; 3],
    rings: &[u32],
    cell_m: f64,
    regions: &[Box3],
    valid: impl Fn(ChunkKey) -> bool,
) -> Vec<ChunkKey> {
    if regions.is_empty() {
        return Vec::new();
    }
    let rings = Rings::new(camera, rings, cell_m);
    let mut out: Vec<ChunkKey> = rings
        .chunks()
        .filter(|k| {
            let b = chunk_box(*k, cell_m);
            valid(*k) && regions.iter().any(|r| meets(r, &b))
        })
        .collect();
    sort_nearest(&mut out, camera, cell_m);
    out.truncate(MAX_VIEW_CHUNKS);
    out
}

/// Whether chunk `key` is within the world's chunk limits (`api/chunk_format_v1.md`).
pub fn within_limits(plan: &WorldPlan, key: ChunkKey) -> bool {
    key.lod <= MAX_CHUNK_LOD
        && key.y.unsigned_abs() <= max_chunk_y(key.lod).unsigned_abs()
        && [key.x, key.z]
            .iter()
            .all(|c| c.unsigned_abs() <= max_chunk_xz(plan.max_tile_coord(key.lod)).unsigned_abs())
}

fn refused(code: &'static str, field: &'static str, message: String) -> StreamError {
    StreamError {
        code,
        message,
        field: Some(field.into()),
    }
}

/// Validates the volume part of a v2 view against the world `plan`: the camera height, the
/// chunk rings, the asked chunks (each within the chunk limits) and the chunk format; returns
/// the asked chunks and the format. Errors name the field.
pub fn chunk_view_of(
    volume: &VolumeView,
    plan: &WorldPlan,
) -> Result<(Vec<ChunkKey>, Format), StreamError> {
    let limit = crate::volume::chunk::CHUNK_Y_LIMIT_CELLS as f64 * f64::from(plan.params.cell_m);
    if !volume.y.is_finite() || volume.y.abs() > limit {
        return Err(refused(
            "coordinate_out_of_range",
            "y",
            format!("y must be within ±{limit} m"),
        ));
    }
    if volume.chunk_rings.len() > MAX_CHUNK_LEVELS
        || volume.chunk_rings.iter().any(|r| *r > MAX_CHUNK_RINGS)
    {
        return Err(refused(
            "bad_rings",
            "chunk_rings",
            format!("chunk_rings: 0 to {MAX_CHUNK_LEVELS} levels of 0 to {MAX_CHUNK_RINGS} rings"),
        ));
    }
    if volume.chunks.len() > MAX_ASKED_CHUNKS {
        return Err(refused(
            "too_many_chunks",
            "chunks",
            format!(
                "{} chunks asked; at most {MAX_ASKED_CHUNKS}",
                volume.chunks.len()
            ),
        ));
    }
    let mut asked = Vec::with_capacity(volume.chunks.len());
    for (i, [lod, x, y, z]) in volume.chunks.iter().copied().enumerate() {
        let key = u32::try_from(lod).ok().map(|lod| ChunkKey { lod, x, y, z });
        match key {
            Some(key) if within_limits(plan, key) => {
                if !asked.contains(&key) {
                    asked.push(key);
                }
            }
            _ => {
                return Err(refused(
                    "coordinate_out_of_range",
                    "chunks",
                    format!(
                        "chunks[{i}] = [{lod}, {x}, {y}, {z}] is outside the chunk limits (lod 0..={MAX_CHUNK_LOD}, \
                         |y| ≤ ⌊16384 / (32·2^lod)⌋ − 1, |x|, |z| ≤ 2·max_tile_coord(lod) − 1)"
                    ),
                ))
            }
        }
    }
    let format = match volume.chunk_format.as_deref() {
        None | Some("bin") => Format::Bin,
        Some("json") => Format::Json,
        Some("glb") => Format::Glb,
        Some(other) => {
            return Err(refused(
                "unknown_format",
                "chunk_format",
                format!(
                    "unknown chunk format {:?}; chunks are bin, json or glb",
                    other.chars().take(40).collect::<String>()
                ),
            ))
        }
    };
    Ok((asked, format))
}

/// Sorts chunks nearest first: distance from `camera` to the centre, then LOD, then address.
pub fn sort_nearest(chunks: &mut [ChunkKey], camera: [f64; 3], cell_m: f64) {
    chunks.sort_by(|a, b| {
        chunk_distance(*a, camera, cell_m)
            .total_cmp(&chunk_distance(*b, camera, cell_m))
            .then(a.lod.cmp(&b.lod))
            .then((a.x, a.y, a.z).cmp(&(b.x, b.y, b.z)))
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    #[test]
    fn levels_nest_without_overlaps_and_only_regions_are_kept() {
        let everything = [[[-1e9; 3], [1e9; 3]]];
        let chunks = select_chunks([10.0, 5.0, -40.0], &[1, 1, 1], 1.0, &everything, |_| true);
        // Every LOD-0 cell of the covered cube is covered exactly once.
        let mut cover: HashMap<[i64; 3], usize> = HashMap::new();
        for c in &chunks {
            let s = 1i64 << c.lod;
            for dy in 0..s {
                for dz in 0..s {
                    for dx in 0..s {
                        *cover
                            .entry([c.x * s + dx, c.y * s + dy, c.z * s + dz])
                            .or_default() += 1;
                    }
                }
            }
        }
        assert!(cover.values().all(|n| *n == 1), "a chunk is covered twice");
        let extent = |i: usize| {
            let v: Vec<i64> = cover.keys().map(|k| k[i]).collect();
            v.iter().max().unwrap_or(&0) - v.iter().min().unwrap_or(&0) + 1
        };
        assert_eq!(
            cover.len() as i64,
            extent(0) * extent(1) * extent(2),
            "no holes"
        );
        assert_eq!(
            chunks[0],
            ChunkKey {
                lod: 0,
                x: 0,
                y: 0,
                z: -2
            },
            "the camera's chunk comes first"
        );
        // A region meets only the chunks of its box.
        let region = [[[0.0, 0.0, 0.0], [40.0, 10.0, 20.0]]];
        let near = select_chunks([10.0, 5.0, 10.0], &[2], 1.0, &region, |_| true);
        let want: Vec<ChunkKey> = [0, 1]
            .into_iter()
            .map(|x| ChunkKey {
                lod: 0,
                x,
                y: 0,
                z: 0,
            })
            .collect();
        assert_eq!(near, want);
        assert!(select_chunks([0.0; 3], &[2], 1.0, &[], |_| true).is_empty());
    }
}
