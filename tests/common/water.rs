//! Tiles with water of the default world, found through the library the way a client would:
//! river tiles from the river lines of a few LOD-6 tiles around the origin, lake tiles from the
//! lake vertices of the coarsest carved tiles (LOD `rivers::MAX_CARVE_LOD`) around it.

use strata::terrain::earth::{rivers, tile_rivers};
use strata::terrain::{synthesize, Tile, TileKey, WorldPlan};

/// The LOD-`lod` tile of `plan` holding world point `(x, z)`, metres.
pub fn key_at(plan: &WorldPlan, lod: u32, x: f64, z: f64) -> TileKey {
    let span = 64.0 * plan.lods[lod as usize].spacing_m as f64;
    TileKey {
        lod,
        x: (x / span).floor() as i64,
        z: (z / span).floor() as i64,
    }
}

/// How many vertices of `tile` have water of kind `kind`.
pub fn count(tile: &Tile, kind: u8) -> usize {
    tile.water_kind.iter().filter(|&&k| k == kind).count()
}

/// The LOD-`lod` tiles (`lod` ≤ 2, where channels span vertices) on the river lines of the
/// LOD-6 tiles around the origin, until one has at least `min` river vertices. Panics if none
/// has.
pub fn river_tile(plan: &WorldPlan, lod: u32, min: usize) -> Tile {
    let earth = plan.earth.as_ref().expect("an earth-1 world");
    for (x, z) in [(0, 0), (-1, 1), (1, 1), (-1, 0), (0, -1), (-1, -1)] {
        let key = TileKey { lod: 6, x, z };
        for line in tile_rivers(earth, key, plan.lods[6].spacing_m) {
            // Points between the network's nodes lie mid-channel, away from confluences.
            for p in line.points.iter().skip(1).step_by(2) {
                let tile = synthesize(plan, key_at(plan, lod, p[0] as f64, p[1] as f64));
                if count(&tile, rivers::kind::RIVER) >= min {
                    return tile;
                }
            }
        }
    }
    panic!("no LOD-{lod} tile with {min} river vertices on the rivers near the origin");
}

/// The LOD-`lod` tiles holding lake vertices of the coarsest carved tiles around the origin
/// (LOD [`rivers::MAX_CARVE_LOD`], where lakes show; shore vertices first), until one has
/// at least `lakes` lake and `streams` river vertices. Panics if none has.
pub fn lake_tile(plan: &WorldPlan, lod: u32, lakes: usize, streams: usize) -> Tile {
    for (x, z) in [
        (0, 0),
        (-1, 0),
        (0, -1),
        (-1, -1),
        (1, 0),
        (0, 1),
        (1, 1),
        (-1, 1),
        (1, -1),
    ] {
        let coarsest = rivers::MAX_CARVE_LOD as u32;
        let coarse = synthesize(
            plan,
            TileKey {
                lod: coarsest,
                x,
                z,
            },
        );
        let s = coarse.spacing_m as f64;
        // Lake vertices on the shore (a dry 4-neighbour), where rivers come in, before the
        // others.
        let kinds = &coarse.water_kind;
        let shore = |v: usize| {
            let (i, j) = (v % 65, v / 65);
            (i > 0 && kinds[v - 1] == rivers::kind::NONE)
                || (i < 64 && kinds[v + 1] == rivers::kind::NONE)
                || (j > 0 && kinds[v - 65] == rivers::kind::NONE)
                || (j < 64 && kinds[v + 65] == rivers::kind::NONE)
        };
        let lake: Vec<usize> = (0..kinds.len())
            .filter(|&v| kinds[v] == rivers::kind::LAKE)
            .collect();
        let wet = lake
            .iter()
            .filter(|&&v| shore(v))
            .step_by(3)
            .take(12)
            .chain(lake.iter().step_by(7).take(8));
        for &v in wet {
            let wx = coarse.origin_x_m() + (v % 65) as f64 * s;
            let wz = coarse.origin_z_m() + (v / 65) as f64 * s;
            let tile = synthesize(plan, key_at(plan, lod, wx, wz));
            if count(&tile, rivers::kind::LAKE) >= lakes
                && count(&tile, rivers::kind::RIVER) >= streams
            {
                return tile;
            }
        }
    }
    panic!("no LOD-{lod} tile with {lakes} lake and {streams} river vertices near the origin");
}

/// A point where a river line of the default world runs through a lake: of the line points over a
/// lake vertex of the first LOD-6 tile that has such points 300–800 m from the shore (its lakes
/// found as [`lake_tile`] finds them), the one nearest the shore. A river line runs on through a
/// lake at the lake's level, so a client that took the line's water for the river's would cut
/// the lake's sheet along it. Panics if none is found.
pub fn river_into_lake(plan: &WorldPlan) -> (f64, f64) {
    let earth = plan.earth.as_ref().expect("an earth-1 world");
    let coarsest = rivers::MAX_CARVE_LOD as u32;
    let mut best: Option<((f64, f64), f64)> = None;
    for (x, z) in [(0, 0), (-1, 0), (0, -1), (-1, -1)] {
        let coarse = synthesize(
            plan,
            TileKey {
                lod: coarsest,
                x,
                z,
            },
        );
        let s = coarse.spacing_m as f64;
        let mut keys: Vec<TileKey> = (0..coarse.water_kind.len())
            .filter(|&v| coarse.water_kind[v] == rivers::kind::LAKE)
            .map(|v| {
                let wx = coarse.origin_x_m() + (v % 65) as f64 * s;
                let wz = coarse.origin_z_m() + (v / 65) as f64 * s;
                key_at(plan, 6, wx, wz)
            })
            .collect();
        keys.sort_by_key(|k| (k.x, k.z));
        keys.dedup();
        for key in keys {
            let tile = synthesize(plan, key);
            let d = tile.spacing_m as f64;
            let vertex = |px: f64, pz: f64| -> Option<usize> {
                let i = ((px - tile.origin_x_m()) / d).round();
                let j = ((pz - tile.origin_z_m()) / d).round();
                ((0.0..65.0).contains(&i) && (0.0..65.0).contains(&j))
                    .then_some(j as usize * 65 + i as usize)
            };
            let dry: Vec<(f64, f64)> = (0..65 * 65)
                .filter(|&v| tile.water_kind[v] == rivers::kind::NONE)
                .map(|v| {
                    (
                        tile.origin_x_m() + (v % 65) as f64 * d,
                        tile.origin_z_m() + (v / 65) as f64 * d,
                    )
                })
                .collect();
            for line in tile_rivers(earth, key, tile.spacing_m) {
                for p in &line.points {
                    let (px, pz) = (p[0] as f64, p[1] as f64);
                    let Some(v) = vertex(px, pz) else { continue };
                    if tile.water_kind[v] != rivers::kind::LAKE {
                        continue;
                    }
                    let to_shore = dry
                        .iter()
                        .map(|&(x, z)| (x - px).hypot(z - pz))
                        .fold(f64::INFINITY, f64::min);
                    // Well inside the lake (its sheet all around the line), the shore in view.
                    if (300.0..800.0).contains(&to_shore) && best.is_none_or(|(_, b)| to_shore < b)
                    {
                        best = Some(((px, pz), to_shore));
                    }
                }
            }
            if let Some((p, _)) = best {
                return p;
            }
        }
    }
    panic!("no river line through a lake near the origin");
}
