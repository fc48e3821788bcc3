//! Rivers and lakes of the default `earth-1` world (`terrain::earth::rivers`): they flow
//! downhill to the sea, a lake or a larger river, everywhere (near the origin, far out, at
//! negative coordinates, in mountains); lakes fill their depressions to the outlet; and every
//! tile is the same bytes whatever was computed before it, with water that meets its neighbours
//! bit for bit.

use std::collections::HashSet;
use strata::terrain::earth::rivers::{kind, LineEnd, Network, NodeId, RiverPlan};
use strata::terrain::earth::{clear_caches, tile_rivers, EarthPlan};
use strata::terrain::{synthesize, TileKey, WorldParams, WorldPlan};

fn plan() -> WorldPlan {
    WorldPlan::new(42, WorldParams::default()).expect("default world")
}

fn parts(p: &WorldPlan) -> (&EarthPlan, &RiverPlan) {
    let e = p.earth.as_ref().expect("the default world is earth-1");
    (e, e.rivers.as_ref().expect("the default world has rivers"))
}

/// Named areas (world metres): the origin, far out (693 km), negative coordinates, and the
/// mountain belt east of the origin.
const AREAS: [(&str, f32, f32); 4] = [
    ("origin", 0.0, 0.0),
    ("far", 620e3, 310e3),
    ("west", -120e3, -40e3),
    ("mountains", 110e3, -40e3),
];

/// Follows the flow from `start` to its end and checks every step: heights fall strictly (or
/// stay below the level of the lake the step leaves), the water level never rises, the
/// discharge never falls. Returns the end and whether it is a lake.
fn trace(net: &mut Network, start: NodeId, done: &mut HashSet<NodeId>) -> usize {
    let mut at = start;
    let mut steps = 0;
    loop {
        if !done.insert(at) {
            return steps;
        }
        let n = net.node(at.0, at.1);
        let Some(d) = n.down else {
            // The end: the sea, or a lake whose level is at least the pit's height.
            assert!(
                n.sea || n.lake.is_some_and(|l| l >= n.h),
                "flow from {start:?} ends at {at:?}, neither sea nor lake: {n:?}"
            );
            return steps;
        };
        let m = net.node(d.0, d.1);
        // Out of a lake that spills (`lakes: 3`) the flow climbs to the lake's outlet, which
        // lies below its level.
        assert!(
            m.h < n.h || n.lake.is_some_and(|l| m.h < l),
            "height rises from {at:?} to {d:?}: {n:?} → {m:?}"
        );
        assert!(
            m.w <= n.w,
            "water rises from {at:?} to {d:?}: {n:?} → {m:?}"
        );
        assert!(
            m.q >= n.q,
            "discharge falls from {at:?} to {d:?}: {n:?} → {m:?}"
        );
        steps += 1;
        assert!(steps < 20_000, "flow from {start:?} never ends");
        at = d;
    }
}

/// Traces the flow from every river node of `rp`'s network within `half` nodes of each of
/// [`AREAS`] ([`trace`]) and checks that each area holds more than 50 of them.
fn trace_areas(earth: &EarthPlan, rp: &RiverPlan, half: i64) {
    let mut net = Network::new(earth, rp);
    let s = rp.spacing_m;
    let mut done = HashSet::new();
    for (name, x, z) in AREAS {
        let (ci, ck) = ((x / s) as i64, (z / s) as i64);
        let mut wet = 0;
        for k in ck - half..ck + half {
            for i in ci - half..ci + half {
                let n = net.node(i, k);
                if n.q >= rp.wet_q && !n.sea {
                    wet += 1;
                    trace(&mut net, (i, k), &mut done);
                }
            }
        }
        let km = 2.0 * half as f32 * s / 1e3;
        assert!(wet > 50, "{name}: only {wet} river nodes in {km} × {km} km");
    }
}

#[test]
fn every_river_descends_and_ends_in_the_sea_a_lake_or_a_larger_river() {
    let p = plan();
    let (earth, rp) = parts(&p);
    trace_areas(earth, rp, 24);
}

#[test]
fn tile_lines_descend_and_end_where_they_should() {
    let p = plan();
    let (earth, rp) = parts(&p);
    let lod = 6;
    let spacing = p.lods[lod as usize].spacing_m;
    let span = 64.0 * spacing;
    let mut net = Network::new(earth, rp);
    let mut ends = [0usize; 4];
    for (name, x, z) in AREAS {
        let (tx, tz) = ((x / span).floor() as i64, (z / span).floor() as i64);
        let mut lines = 0;
        for tz in tz - 2..tz + 2 {
            for tx in tx - 2..tx + 2 {
                let key = TileKey { lod, x: tx, z: tz };
                for line in tile_rivers(earth, key, spacing) {
                    lines += 1;
                    assert_eq!(line.points.len(), line.width_m.len());
                    assert_eq!(line.points.len(), line.discharge_m3s.len());
                    for w in line.points.windows(2) {
                        assert!(
                            w[1][2] <= w[0][2],
                            "{name} {key:?}: level rises in {line:?}"
                        );
                    }
                    for w in line.discharge_m3s.windows(2) {
                        assert!(w[1] >= w[0], "{name} {key:?}: discharge falls");
                    }
                    let to = net.node(line.to[0], line.to[1]);
                    match line.ends {
                        LineEnd::Sea => {
                            ends[0] += 1;
                            assert!(to.sea);
                        }
                        LineEnd::Lake => {
                            ends[1] += 1;
                            // A lake that does not spill, or (`lakes: 6`) one whose water
                            // leaves over a saddle beyond its pit's neighbours: its line
                            // starts there.
                            let spills = to
                                .down
                                .is_some_and(|(i, k)| (i - to.i).abs() > 1 || (k - to.k).abs() > 1);
                            assert!(
                                (to.down.is_none() || spills) && !to.sea && to.lake.is_some(),
                                "{name} {key:?}: {to:?}"
                            );
                        }
                        LineEnd::River => {
                            ends[2] += 1;
                            // A confluence: the main stem in, at least as large, goes on.
                            let main = net.main_upstream(to.i, to.k).expect("a confluence");
                            let last = line.discharge_m3s[line.discharge_m3s.len() - 2];
                            let main_q = net.node(main.0, main.1).q;
                            let main_m3s =
                                strata::terrain::earth::rivers::discharge_m3s(main_q, rp.spacing_m);
                            assert!(to.down.is_some(), "{line:?}");
                            assert!(main_m3s >= last, "{name} {key:?}: joins a smaller river");
                        }
                        LineEnd::Continues => {
                            ends[3] += 1;
                            // The next edge goes on outside this tile's reach: some tile nearby
                            // has a line through the node.
                            assert!(to.down.is_some());
                            let found = (-1..=1).any(|dz| {
                                (-1..=1).any(|dx| {
                                    let k2 = TileKey {
                                        lod,
                                        x: tx + dx,
                                        z: tz + dz,
                                    };
                                    (dx, dz) != (0, 0)
                                        && tile_rivers(earth, k2, spacing).iter().any(|l| {
                                            l.points.iter().any(|q| q[0] == to.x && q[1] == to.z)
                                        })
                                })
                            });
                            assert!(found, "{name} {key:?}: nothing continues {line:?}");
                        }
                    }
                }
            }
        }
        assert!(lines > 0, "{name}: no river lines in 16 LOD-6 tiles");
    }
    assert!(ends[2] > 0 && ends[3] > 0, "ends seen: {ends:?}");
}

#[test]
fn lakes_fill_their_depressions_to_the_outlet_and_shallow_pits_drain() {
    let p = plan();
    let (earth, rp) = parts(&p);
    let mut net = Network::new(earth, rp);
    let (mut lakes, mut full) = (0, 0);
    for k in -64..64 {
        for i in -64..64 {
            let n = net.node(i, k);
            if n.sea || n.down.is_some() {
                continue;
            }
            let (level, flooded, outlet) = (*net.flood(i, k)).clone();
            lakes += 1;
            assert!(level >= n.h);
            for (fi, fk) in &flooded {
                assert!(
                    net.height(*fi, *fk) <= level,
                    "a flooded node is above the lake"
                );
            }
            if let Some(o) = outlet {
                full += 1;
                // The outlet is beyond the saddle: lower than the level, and the lake is deep
                // enough to stay (a shallower one would have drained over the saddle), or its
                // outlet is higher than the pit.
                let ho = net.height(o.0, o.1);
                assert!(ho < level);
                assert!(
                    level - n.h >= strata::terrain::earth::rivers::BREACH_DEPTH_M || ho >= n.h,
                    "pit {:?} should have drained to {o:?}",
                    (i, k)
                );
                assert!(!flooded.contains(&o));
            }
            assert_eq!(
                net.lake(i, k),
                Some(net.lake(i, k).unwrap_or(level).max(level))
            );
        }
    }
    assert!(
        lakes > 0 && full > 0,
        "{lakes} lakes, {full} filled to an outlet"
    );
}

/// `lakes: 3` (asked for by name): a lake whose flood found an outlet spills there, and its
/// river goes on down to the sea or to a lake whose level is lower, never back into itself;
/// every flow still descends and ends as [`trace`] checks.
#[test]
fn lakes_spill_over_their_outlet_to_the_sea_or_a_lower_lake() {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").lakes = 3;
    let p = WorldPlan::new(42, params).expect("lakes 3 world");
    let (earth, rp) = parts(&p);
    assert_eq!(rp.lakes, 3);
    let mut net = Network::new(earth, rp);
    let (mut spills, mut done) = (0, HashSet::new());
    for (_, x, z) in AREAS {
        let (ci, ck) = ((x / rp.spacing_m) as i64, (z / rp.spacing_m) as i64);
        for k in ck - 40..ck + 40 {
            for i in ci - 40..ci + 40 {
                let n = net.node(i, k);
                let (Some(level), Some(d)) = (n.lake, n.down) else {
                    continue;
                };
                let o = net.node(d.0, d.1);
                if o.h <= n.h {
                    continue;
                }
                // A step up out of a lake: its spill to the outlet, which lies below the level.
                spills += 1;
                assert!(o.h < level, "{:?} spills above its level: {o:?}", (i, k));
                assert!(
                    o.w <= n.w,
                    "the water rises over the outlet of {:?}",
                    (i, k)
                );
                trace(&mut net, (i, k), &mut done);
                let mut at = o;
                let mut steps = 0;
                loop {
                    if let Some(l) = at.lake.filter(|_| at.h < o.h) {
                        assert!(l <= level, "{:?} spills into a higher lake", (i, k));
                        break;
                    }
                    let Some(next) = at.down else {
                        assert!(at.sea, "{:?} spills into a closed basin at {at:?}", (i, k));
                        break;
                    };
                    at = net.node(next.0, next.1);
                    steps += 1;
                    assert!(steps < 20_000, "the spill of {:?} never ends", (i, k));
                }
            }
        }
    }
    assert!(spills >= 5, "only {spills} lakes spill over 4 × 80 × 80 km");
}

fn tile_bits(t: &strata::terrain::Tile) -> Vec<u32> {
    let mut v: Vec<u32> = t.heights.iter().map(|h| h.to_bits()).collect();
    v.extend(t.water_depth.iter().map(|d| d.to_bits()));
    v.extend(t.water_kind.iter().map(|&k| k as u32));
    v.extend(t.materials.iter().map(|&m| m as u32));
    v
}

#[test]
fn tiles_alone_and_in_shuffled_orders_give_identical_bytes() {
    let mut keys = Vec::new();
    for lod in [0u32, 3, 6, 9] {
        let span = 64.0 * (1u64 << lod) as f32;
        for (_, x, z) in AREAS {
            let (tx, tz) = ((x / span).floor() as i64, (z / span).floor() as i64);
            keys.push(TileKey { lod, x: tx, z: tz });
            keys.push(TileKey {
                lod,
                x: tx + 1,
                z: tz - 1,
            });
        }
    }
    // Each tile alone, from empty caches.
    let alone: Vec<Vec<u32>> = keys
        .iter()
        .map(|k| {
            clear_caches();
            tile_bits(&synthesize(&plan(), *k))
        })
        .collect();
    // All in one world, in a shuffled order (a fixed permutation), so the caches hold what
    // other tiles computed first (the other tests of this file run at the same time and fill
    // and use them too).
    let shared = plan();
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by_key(|&i| (i * 7919) % keys.len());
    for &i in &order {
        assert_eq!(
            tile_bits(&synthesize(&shared, keys[i])),
            alone[i],
            "{:?} differs after other tiles",
            keys[i]
        );
    }
    // And from several threads at once.
    let threads: Vec<_> = (0..3)
        .map(|t| {
            let keys = keys.clone();
            std::thread::spawn(move || {
                let p = plan();
                keys.iter()
                    .rev()
                    .skip(t)
                    .step_by(3)
                    .map(|k| (*k, tile_bits(&synthesize(&p, *k))))
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    for th in threads {
        for (k, bits) in th.join().expect("thread") {
            let i = keys.iter().position(|x| *x == k).expect("key");
            assert_eq!(bits, alone[i], "{k:?} differs on another thread");
        }
    }
    let wet = keys
        .iter()
        .map(|k| synthesize(&shared, *k))
        .filter(|t| {
            t.water_kind
                .iter()
                .any(|&w| w == kind::RIVER || w == kind::LAKE)
        })
        .count();
    assert!(wet > 0, "no tile of the sample holds river or lake water");
}

#[test]
fn water_meets_across_tile_edges_bit_for_bit() {
    let p = plan();
    let (earth, rp) = parts(&p);
    let mut net = Network::new(earth, rp);
    // Tiles of LOD 3 over a river: find a wet node near the origin.
    let river = (0..40)
        .flat_map(|k| (0..40).map(move |i| (i - 20, k - 20)))
        .find(|&(i, k)| net.q(i, k) >= 4 * rp.wet_q)
        .expect("a river near the origin");
    let (x, z) = rp.position(river.0, river.1);
    let lod = 3;
    let span = 64.0 * 8.0;
    let (tx, tz) = ((x / span).floor() as i64, (z / span).floor() as i64);
    let mut checked = 0;
    let mut wet_edges = 0;
    for dz in -1..=1 {
        for dx in -1..=1 {
            let a = synthesize(
                &p,
                TileKey {
                    lod,
                    x: tx + dx,
                    z: tz + dz,
                },
            );
            let east = synthesize(
                &p,
                TileKey {
                    lod,
                    x: tx + dx + 1,
                    z: tz + dz,
                },
            );
            let south = synthesize(
                &p,
                TileKey {
                    lod,
                    x: tx + dx,
                    z: tz + dz + 1,
                },
            );
            for t in 0..65 {
                for (va, vb, b) in [(t * 65 + 64, t * 65, &east), (64 * 65 + t, t, &south)] {
                    assert_eq!(a.heights[va].to_bits(), b.heights[vb].to_bits());
                    assert_eq!(a.water_depth[va].to_bits(), b.water_depth[vb].to_bits());
                    assert_eq!(a.water_kind[va], b.water_kind[vb]);
                    if a.water_kind[va] == kind::RIVER || a.water_kind[va] == kind::LAKE {
                        wet_edges += 1;
                    }
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 1000);
    assert!(
        wet_edges > 0,
        "no tile edge crosses water around the river at {river:?}"
    );
}

#[test]
fn rivers_follow_the_scene_settings() {
    let wet = |density: Option<f32>| {
        let mut params = WorldParams::default();
        match density {
            Some(d) => {
                params
                    .earth
                    .as_mut()
                    .expect("earth")
                    .rivers
                    .as_mut()
                    .expect("rivers")
                    .density = d
            }
            None => {
                params
                    .earth
                    .as_mut()
                    .expect("earth")
                    .rivers
                    .as_mut()
                    .expect("rivers")
                    .enabled = false
            }
        }
        let p = WorldPlan::new(42, params).expect("plan");
        let key = TileKey { lod: 6, x: 0, z: 0 };
        let t = synthesize(&p, key);
        let lines = p
            .earth
            .as_ref()
            .map_or(0, |e| tile_rivers(e, key, p.lods[6].spacing_m).len());
        (lines, t)
    };
    let (sparse, _) = wet(Some(0.5));
    let (dense, _) = wet(Some(3.0));
    assert!(
        dense > sparse,
        "density 3 gives {dense} lines, 0.5 gives {sparse}"
    );
    let (none, off) = wet(None);
    assert_eq!(none, 0);
    assert!(
        off.water_kind.is_empty(),
        "a world with rivers off has no water kinds"
    );
    let mut stored = WorldParams::default();
    stored.earth.as_mut().expect("earth").rivers = None;
    let old = synthesize(
        &WorldPlan::new(42, stored).expect("plan"),
        TileKey { lod: 6, x: 0, z: 0 },
    );
    assert_eq!(
        tile_bits(&old),
        tile_bits(&off),
        "off is the river-free world"
    );
}

/// A straight `valleys: 2` piece along +x from (0, 0) to (100, 0), water at 50 m, a channel
/// 4 m wide and 1 m deep, a floodplain 60 m wide each side, walls from 120 m out to the reach.
fn floodplain_piece() -> strata::terrain::earth::rivers::Piece {
    strata::terrain::earth::rivers::Piece {
        ax: 0.0,
        az: 0.0,
        bx: 100.0,
        bz: 0.0,
        wa: 50.0,
        wb: 50.0,
        half_width: 2.0,
        depth: 1.0,
        valley: 120.0,
        wet: 1.0,
        reach: 1000.0,
        inv_len2: 1.0 / (100.0 * 100.0 + strata::terrain::earth::rivers::PIECE_LEN2_EPS),
        floodplain: 60.0,
        sax: 0.0,
        saz: 0.0,
        sbx: 0.0,
        sbz: 0.0,
        floodplain_b: 60.0,
        slope_a: strata::terrain::earth::rivers::WALL_SLOPE,
        slope_b: strata::terrain::earth::rivers::WALL_SLOPE,
        spur_a: 0.0,
        spur_b: 0.0,
    }
}

#[test]
fn a_floodplain_valley_is_flat_to_its_edge_then_climbs_walls_and_leaves_the_land_beyond() {
    use strata::terrain::earth::rivers::{profile, WALL_SLOPE};
    let p = floodplain_piece();
    // On the floodplain the ground is the water level, whatever its height was.
    for (d, h) in [(5.0, 51.0), (30.0, 80.0), (59.0, 300.0)] {
        let (c, _) = profile(&p, 50.0, d, h);
        assert_eq!(c, 50.0, "floodplain at {d} m, ground {h} m");
    }
    // In the channel the bed is below the water, and the vertex is river water.
    let (c, water) = profile(&p, 50.0, 0.0, 60.0);
    assert_eq!((c, water), (49.0, Some(50.0)));
    // The walls rise from the floodplain's edge and end where they have climbed the height
    // above the water at WALL_SLOPE: beyond that the ground keeps its height, bit for bit.
    let h = 90.0f32;
    let edge = 60.0 + (h - 50.0) / WALL_SLOPE;
    let mut last = 50.0;
    for i in 1..40 {
        let d = 60.0 + (edge - 60.0) * i as f32 / 40.0;
        let (c, _) = profile(&p, 50.0, d, h);
        assert!(c >= last && c < h, "the wall climbs at {d} m: {c}");
        last = c;
    }
    for d in [edge + 0.5, 400.0, 999.0, 1500.0] {
        assert_eq!(profile(&p, 50.0, d, h).0.to_bits(), h.to_bits(), "{d} m");
    }
    // Below the water nothing changes outside the channel.
    assert_eq!(profile(&p, 50.0, 30.0, 45.0).0, 45.0);
    // The carved height moves by no more than the ground does (the LOD bound relies on it).
    for d in [61.0f32, 80.0, 120.0, 200.0, 400.0] {
        for h in [52.0f32, 60.0, 100.0, 200.0, 400.0] {
            let (a, b) = (profile(&p, 50.0, d, h).0, profile(&p, 50.0, d, h + 0.5).0);
            let slope = (b - a) / 0.5;
            assert!((-0.26..=1.0001).contains(&slope), "{d} m, {h} m: {slope}");
        }
    }
}

/// `valleys: 4`: a piece's floodplain and wall slope are linear between its ends, the bound
/// on the carve's slope in `h` holds for every mix of them, and the default world's valleys get
/// widths and slopes across most of their ranges (not one value).
#[test]
fn a_varied_valley_narrows_and_steepens_along_its_piece_within_the_carve_bound() {
    use strata::terrain::earth::rivers::{profile, FLOOR_SCALE, SLOPE_SCALE};
    // Floodplain 60 m at the upstream end, 20 m at the downstream end; walls of slope 0.3 and
    // 0.7 there.
    let p = strata::terrain::earth::rivers::Piece {
        floodplain_b: 20.0,
        slope_a: 0.3,
        slope_b: 0.7,
        ..floodplain_piece()
    };
    // Halfway the floor reaches 40 m: flat at the water level inside, rising just beyond.
    assert_eq!(profile(&p, 50.0, 39.5, 90.0).0, 50.0);
    assert!(profile(&p, 50.0, 41.0, 90.0).0 > 50.0);
    // The walls end where they have climbed the height above the water at the local slope (or
    // at the piece's narrowest valley, 120 m, whichever is wider).
    for (x, fp, slope) in [(0.0f32, 60.0f32, 0.3f32), (100.0, 20.0, 0.7)] {
        let h = 90.0f32;
        let edge = (fp + (h - 50.0) / slope).max(p.valley);
        assert!(
            profile(&p, x, edge - 2.0, h).0 < h,
            "inside the wall at x {x}"
        );
        let beyond = profile(&p, x, edge + 0.5, h).0;
        assert_eq!(beyond.to_bits(), h.to_bits(), "beyond the wall at x {x}");
    }
    // The carved height moves by no more than the ground does, anywhere along the piece.
    for x in [0.0f32, 25.0, 50.0, 75.0, 100.0] {
        for d in [21.0f32, 45.0, 61.0, 80.0, 120.0, 200.0, 400.0] {
            for h in [52.0f32, 60.0, 100.0, 200.0, 400.0] {
                let (a, b) = (profile(&p, x, d, h).0, profile(&p, x, d, h + 0.5).0);
                let slope = (b - a) / 0.5;
                assert!(
                    (-0.26..=1.0001).contains(&slope),
                    "{x}, {d} m, {h} m: {slope}"
                );
            }
        }
    }
    // A `valleys: 4` world's valley shapes along a line of 2,000 points 150 m apart.
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").valleys = 4;
    let plan = WorldPlan::new(42, params).expect("valleys 4 world");
    let (_, rivers) = parts(&plan);
    let (mut f_lo, mut f_hi, mut s_lo, mut s_hi) = (f32::MAX, f32::MIN, f32::MAX, f32::MIN);
    for i in 0..2000 {
        let (x, z) = (i as f32 * 150.0 - 150_000.0, i as f32 * 37.0);
        let (f, s) = rivers.valley_shape(x, z, 100.0);
        let (f, s) = (f / 100.0, s / strata::terrain::earth::rivers::WALL_SLOPE);
        assert!(
            (FLOOR_SCALE.0 * 0.999..=FLOOR_SCALE.1 * 1.001).contains(&f),
            "{f}"
        );
        assert!(
            (SLOPE_SCALE.0 * 0.999..=SLOPE_SCALE.1 * 1.001).contains(&s),
            "{s}"
        );
        (f_lo, f_hi, s_lo, s_hi) = (f_lo.min(f), f_hi.max(f), s_lo.min(s), s_hi.max(s));
    }
    let span = |lo: f32, hi: f32, (a, b): (f32, f32)| (hi - lo) / (b - a);
    assert!(
        span(f_lo, f_hi, FLOOR_SCALE) > 0.7,
        "floodplain factors {f_lo}..{f_hi}"
    );
    assert!(
        span(s_lo, s_hi, SLOPE_SCALE) > 0.7,
        "slope factors {s_lo}..{s_hi}"
    );
}

/// Two shortcuts of the tile path against the full river job, over tiles that hold river lines
/// at LOD 0, 3, 6 and 8 in every named area (LOD 8's bins are 4 × 4 samples, carved in the
/// narrower lanes): the carve with each bin pruned to the pieces that can
/// reach its highest sample (`RiverJob::pruned`, `RiverJob::carve_pruned`, and the same a bin
/// at a time, `RiverJob::carve_grid`) gives every height of the full job, and the
/// water job (`water_job_for`: wet channels only, and the same for a whole grid,
/// `RiverJob::water_grid`) gives every sample's water surface and kind, bit for bit. The heights carved are the tile's raised by 40 m, so the valleys' walls apply.
#[test]
fn pruned_bins_and_the_water_job_give_the_full_jobs_heights_and_water() {
    // The default world (`valleys: 6`, whose walls' spurs the lanes read at each foot and whose
    // walls' slopes fall with the relief), and `valleys: 3`, without spurs or varied floodplains.
    for p in [plan(), valleys_plan(3)] {
        pruned_and_water_jobs_agree(&p);
    }
}

/// The `(2r + 1)²` LOD-`lod` tiles of `p` around the one holding world point `(cx, cz)`, row by
/// row.
fn tiles_around(p: &WorldPlan, lod: u32, (cx, cz): (f32, f32), r: i64) -> Vec<TileKey> {
    let span = 64.0 * p.lods[lod as usize].spacing_m;
    let (tx, tz) = ((cx / span).floor() as i64, (cz / span).floor() as i64);
    (-r..=r)
        .flat_map(|b| {
            (-r..=r).map(move |a| TileKey {
                lod,
                x: tx + a,
                z: tz + b,
            })
        })
        .collect()
}

/// The default world with `valleys`, and the lakes of the worlds the valleys were written for
/// (`lakes: 4`; with `lakes: 5` a lake fills the basin of the `mountains` area, where no valley
/// wall would be left to compare).
fn valleys_plan(valleys: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    let rivers = earth.rivers.as_mut().expect("rivers");
    (rivers.valleys, rivers.lakes) = (valleys, 4);
    WorldPlan::new(42, params).expect("a valleys world")
}

fn pruned_and_water_jobs_agree(p: &WorldPlan) {
    use strata::terrain::earth::rivers::{job_for, water_at, water_job_for};
    let (earth, rp) = parts(p);
    let n = 65usize;
    let (mut tiles, mut wet, mut left_out) = (0, 0, 0usize);
    for (name, cx, cz) in AREAS {
        for lod in [0u32, 3, 6, 8] {
            let spacing = p.lods[lod as usize].spacing_m;
            let keys = tiles_around(p, lod, (cx, cz), 3)
                .into_iter()
                .filter(|k| !tile_rivers(earth, *k, spacing).is_empty())
                .take(3);
            for key in keys {
                tiles += 1;
                let t = synthesize(p, key);
                let (gx0, gz0) = (key.x * 64, key.z * 64);
                let at = |v: usize| {
                    let x = (gx0 + (v % n) as i64) as f32 * spacing;
                    let z = (gz0 + (v / n) as i64) as f32 * spacing;
                    (x, z)
                };
                let full = job_for(earth, rp, spacing, gx0, gz0, n, n);
                let raised: Vec<f32> = t.heights.iter().map(|h| h + 40.0).collect();
                let pruned = full.pruned(raised.iter().enumerate().map(|(v, h)| {
                    let (x, z) = at(v);
                    (x, z, *h)
                }));
                left_out += full.bin_pieces.len() - pruned.entries.len();
                let mut lanes = raised.clone();
                let xs: Vec<f32> = (0..n).map(|i| at(i).0).collect();
                let zs: Vec<f32> = (0..n).map(|j| at(j * n).1).collect();
                full.carve_grid(&xs, &zs, &mut lanes);
                let water = water_job_for(earth, rp, spacing, gx0, gz0, n, n);
                let sea = p.params.sea_level_m;
                let (mut grid_surface, mut grid_kinds) = (Vec::new(), Vec::new());
                water.water_grid(
                    sea,
                    &xs,
                    &zs,
                    &t.heights,
                    &mut grid_surface,
                    &mut grid_kinds,
                );
                for (v, h) in raised.iter().enumerate() {
                    let (x, z) = at(v);
                    assert_eq!(
                        full.carve_pruned(&pruned, x, z, *h).to_bits(),
                        full.carve_one(x, z, *h).to_bits(),
                        "{name} {key:?} vertex {v}: the pruned carve differs"
                    );
                    assert_eq!(
                        lanes[v].to_bits(),
                        full.carve_one(x, z, *h).to_bits(),
                        "{name} {key:?} vertex {v}: the carve in lanes differs"
                    );
                    let carved = t.heights[v];
                    let (s_full, k_full) = water_at(&full, sea, x, z, carved);
                    let (s, k) = water_at(&water, sea, x, z, carved);
                    assert_eq!(
                        (s.to_bits(), k),
                        (s_full.to_bits(), k_full),
                        "{name} {key:?} vertex {v}: the water job's water differs"
                    );
                    assert_eq!(
                        (grid_surface[v].to_bits(), grid_kinds[v]),
                        (s.to_bits(), k),
                        "{name} {key:?} vertex {v}: the grid's water differs"
                    );
                    wet += usize::from(k == kind::RIVER);
                }
            }
        }
    }
    assert!(tiles >= 8, "only {tiles} tiles with river lines");
    assert!(wet > 0, "no sample of the tiles lies in a river channel");
    assert!(left_out > 0, "the pruning left no piece out of any bin");
}

/// `valleys: 5`: the spur value bends a wall's place between the floor and the valley's edge
/// without breaking its rise (so the spurs add no pit along the way down to the river), keeps
/// its ends, and with no spur gives the plain smoothstep's bits; a piece's spur value is linear
/// between its ends.
#[test]
fn a_spur_bends_the_wall_and_keeps_it_rising() {
    use strata::terrain::earth::rivers::{spur_step, SPUR};
    let smooth = |x: f32| {
        let t = ((x - 40.0) / 360.0_f32).clamp(0.0, 1.0);
        t * t * (3.0 - 2.0 * t)
    };
    for k in 0..=20 {
        let s = SPUR * (k as f32 / 10.0 - 1.0);
        assert_eq!(
            spur_step(40.0, 400.0, 40.0, s),
            0.0,
            "{s}: the floor's edge"
        );
        assert_eq!(
            spur_step(40.0, 400.0, 400.0, s),
            1.0,
            "{s}: the valley's edge"
        );
        let mut last = 0.0f32;
        for i in 0..=3600 {
            let d = 40.0 + i as f32 * 0.1;
            let g = spur_step(40.0, 400.0, d, s);
            assert!(g >= last, "{s}: the wall falls at {d} m ({last} then {g})");
            last = g;
            if s == 0.0 {
                assert_eq!(g.to_bits(), smooth(d).to_bits(), "{d} m: no spur");
            }
        }
    }
    // Halfway up the wall a full spur raises the ground by a fifth of the wall's height or more
    // and a full hollow lowers it as much.
    let (up, down) = (
        spur_step(40.0, 400.0, 220.0, SPUR),
        spur_step(40.0, 400.0, 220.0, -SPUR),
    );
    assert!(
        up - smooth(220.0) > 0.2 && smooth(220.0) - down > 0.2,
        "{down} {up}"
    );
    // A piece whose spur value runs from a full spur upstream to a full hollow downstream: its
    // wall stands higher than the spurless one at the upstream end, lower at the downstream
    // end, as high halfway (the value is 0 there), and rises away from the river everywhere.
    use strata::terrain::earth::rivers::{profile, Piece};
    let plain = floodplain_piece();
    let spurred = Piece {
        spur_a: SPUR,
        spur_b: -SPUR,
        ..plain
    };
    let (h, d) = (300.0f32, 300.0f32);
    assert!(profile(&spurred, 0.0, d, h).0 > profile(&plain, 0.0, d, h).0 + 10.0);
    assert!(profile(&spurred, 100.0, d, h).0 < profile(&plain, 100.0, d, h).0 - 10.0);
    assert_eq!(
        profile(&spurred, 50.0, d, h).0.to_bits(),
        profile(&plain, 50.0, d, h).0.to_bits()
    );
    for x in [0.0f32, 25.0, 75.0, 100.0] {
        let mut last = f32::MIN;
        for i in 0..=1000 {
            let c = profile(&spurred, x, i as f32, h).0;
            assert!(c >= last, "{x}, {i} m: the wall falls ({last} then {c})");
            last = c;
        }
    }
}

/// `valleys: 5` against `valleys: 4` on the default world's carved tiles: the spurs move the
/// valley walls (by metres in every area, by tens of metres in most; where a valley is cut by
/// the full `CARVE_MAX_M`, as in much of the mountains' area, the limit holds the wall), while the rivers, lakes and seas
/// kinds of water over every vertex stay as they were.
#[test]
fn spurs_move_the_walls_and_leave_the_rivers() {
    let (four, five) = (valleys_plan(4), valleys_plan(5));
    let mut highest = 0.0f32;
    for (name, cx, cz) in AREAS {
        let (mut moved, mut most) = (0usize, 0.0f32);
        for k in tiles_around(&four, 5, (cx, cz), 2) {
            let (a, b) = (synthesize(&four, k), synthesize(&five, k));
            assert_eq!(
                a.water_kind, b.water_kind,
                "{name} {k:?}: the spurs moved water"
            );
            for (ha, hb) in a.heights.iter().zip(&b.heights) {
                moved += usize::from(ha.to_bits() != hb.to_bits());
                most = most.max((ha - hb).abs());
            }
        }
        println!("{name}: {moved} heights moved, at most {most:.1} m");
        assert!(
            moved > 100 && most > 2.0,
            "{name}: {moved} heights, {most} m"
        );
        highest = highest.max(most);
    }
    assert!(
        highest > 50.0,
        "the spurs move mountain walls by {highest} m at most"
    );
}

/// `valleys: 6` (the default) against `valleys: 5` on the default world's carved tiles: gentler
/// walls only widen valleys, so no height rises (each wall's profile falls as its slope does, and
/// the lowest profile and the carve's limit keep that), the water stays where it was, and in the
/// low relief of the origin's plains the walls move by metres over many samples.
#[test]
fn gentler_walls_in_low_relief_widen_the_valleys_and_leave_the_rivers() {
    let (five, six) = (valleys_plan(5), valleys_plan(6));
    for (name, cx, cz) in AREAS {
        let (mut lower, mut most) = (0usize, 0.0f32);
        for k in tiles_around(&five, 5, (cx, cz), 1) {
            let (a, b) = (synthesize(&five, k), synthesize(&six, k));
            assert_eq!(
                a.water_kind, b.water_kind,
                "{name} {k:?}: the walls moved water"
            );
            for (h5, h6) in a.heights.iter().zip(&b.heights) {
                assert!(h6 <= h5, "{name} {k:?}: a gentler wall raised {h5} to {h6}");
                lower += usize::from(h6 < h5);
                most = most.max(h5 - h6);
            }
        }
        println!("{name}: {lower} heights lowered, at most {most:.1} m");
        if name == "origin" {
            assert!(
                lower > 1000 && most > 2.0,
                "{name}: {lower} heights, {most} m"
            );
        }
    }
}

/// `valleys: 7` (the default) against `valleys: 6`: where the relief is high only the larger
/// rivers carve, so in the range at (114.7 km, 114.7 km) no height falls, most rise by tens of
/// metres (the walls of a stream every kilometre cut a median 250 m there) and river water stays
/// only where the larger rivers run; in the plains of the origin, where the relief is
/// under `RELIEF_SOURCE_FROM`, every edge still carves and the tiles keep their bits.
#[test]
fn in_high_relief_only_the_larger_rivers_carve() {
    let (six, seven) = (valleys_plan(6), valleys_plan(7));
    let (mut risen, mut samples, mut sum) = (0usize, 0usize, 0.0f64);
    let mut rivers = (0usize, 0usize);
    let range = |lod, r| tiles_around(&six, lod, (114_700.0, 114_700.0), r);
    // 2.6 km at 8 m and 20 km at 32 m, where the larger rivers run.
    for k in range(3, 2).into_iter().chain(range(5, 2)) {
        let (a, b) = (synthesize(&six, k), synthesize(&seven, k));
        for v in 0..a.heights.len() {
            let (h6, h7) = (a.heights[v], b.heights[v]);
            assert!(
                h7 >= h6,
                "{k:?} vertex {v}: fewer valleys lowered {h6} to {h7}"
            );
            risen += usize::from(h7 > h6 + 1.0);
            sum += f64::from(h7 - h6);
            samples += 1;
            let river = |t: &strata::terrain::tile::Tile| t.water_kind[v] == kind::RIVER;
            assert!(
                !river(&b) || river(&a),
                "{k:?} vertex {v}: a river where valleys: 6 has none"
            );
            rivers.0 += usize::from(river(&a));
            rivers.1 += usize::from(river(&b));
        }
    }
    let mean = sum / samples as f64;
    println!(
        "range at 8 and 32 m: {risen} of {samples} heights risen by more than 1 m, {mean:.0} m \
         on average; river vertices {} -> {}",
        rivers.0, rivers.1
    );
    assert!(
        risen * 2 > samples && mean > 50.0,
        "{risen} of {samples} risen, {mean} m"
    );
    assert!(
        rivers.1 > 0 && rivers.1 < rivers.0,
        "the larger rivers keep their water, the small streams lose theirs: {rivers:?}"
    );
    for k in tiles_around(&six, 5, (0.0, 0.0), 1) {
        let (a, b) = (synthesize(&six, k), synthesize(&seven, k));
        assert_eq!(a.heights, b.heights, "{k:?}: the plains keep their valleys");
        assert_eq!(a.water_kind, b.water_kind, "{k:?}: and their rivers");
    }
}

/// The default world with `valleys` (and today's lakes).
fn sized_plan(valleys: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").valleys = valleys;
    WorldPlan::new(42, params).expect("a valleys world")
}

/// The distance (metres) of the middle point of each edge out of the `n × n` nodes from
/// `(i0, k0)` from the chord between its nodes, by the edge's discharge.
fn bends(plan: &WorldPlan, i0: i64, k0: i64, n: i64) -> Vec<(u32, f32)> {
    let (e, rp) = parts(plan);
    let mut net = Network::new(e, rp);
    let mut out = Vec::new();
    for k in k0..k0 + n {
        for i in i0..i0 + n {
            let q = net.q(i, k);
            let Some(edge) = net.edge(i, k) else { continue };
            let (a, b) = (edge.points[0], edge.points[edge.points.len() - 1]);
            let m = edge.points[edge.points.len() / 2];
            let (dx, dz) = (b[0] - a[0], b[1] - a[1]);
            let off = ((m[0] - a[0]) * dz - (m[1] - a[1]) * dx).abs() / dx.hypot(dz);
            out.push((q, off));
        }
    }
    out
}

/// `valleys: 8` (the default) against `valleys: 7`: a valley is sized by its river. The dry
/// valleys of the plains around the origin have floodplains of 19 m median half-width, a
/// source's 8 m, where `valleys: 7` gave every one 40 m or more (a median 53 m: canals at 8 m
/// spacing); a small river's edge bends
/// less, a large one's (`SIZED_Q` and more) as before, bit for bit; and the floors a LOD-6
/// tile widens to half its spacing keep the 64 m surface from reading the narrow floors as
/// chains of pits: its closed depressions are as before (without that floor, 5.52 % of the
/// land of `bench realism`'s origin square against 5.32 %).
#[test]
fn valleys_are_sized_by_their_rivers() {
    use strata::terrain::earth::rivers::{job_for, SIZED_Q};
    let (seven, eight) = (sized_plan(7), sized_plan(8));
    // Floodplains of the dry pieces over 4 km of the origin's plains at 8 m.
    let floors = |p: &WorldPlan| {
        let (e, rp) = parts(p);
        let job = job_for(e, rp, 8.0, -256, -256, 512, 512);
        let mut f: Vec<f32> = job
            .pieces
            .iter()
            .filter(|p| p.wet == 0.0)
            .map(|p| p.floodplain)
            .collect();
        f.sort_by(f32::total_cmp);
        f
    };
    let (f7, f8) = (floors(&seven), floors(&eight));
    let median = |v: &[f32]| v[v.len() / 2];
    println!(
        "dry floodplains, half-width m: valleys 7 median {} ({} pieces), valleys 8 median {} ({})",
        median(&f7),
        f7.len(),
        median(&f8),
        f8.len()
    );
    assert!(f7.len() > 50 && f8.len() > 50, "{} {}", f7.len(), f8.len());
    assert!(median(&f7) >= 40.0, "valleys 7: {}", median(&f7));
    assert!(
        median(&f8) < 0.5 * median(&f7) && f8[f8.len() / 10] < 10.0,
        "valleys 8: median {}, 10th percentile {}",
        median(&f8),
        f8[f8.len() / 10]
    );

    let (b7, b8) = (bends(&seven, -20, -20, 40), bends(&eight, -20, -20, 40));
    assert_eq!(b7.len(), b8.len(), "the same network");
    let (mut small, mut large) = ((0.0f64, 0.0f64), 0usize);
    for (&(q, o7), &(q8, o8)) in b7.iter().zip(&b8) {
        assert_eq!(q, q8, "the same discharges");
        if q as f32 >= SIZED_Q {
            assert_eq!(o7.to_bits(), o8.to_bits(), "a large river bends as before");
            large += 1;
        } else if q <= 2 {
            small.0 += f64::from(o7);
            small.1 += f64::from(o8);
        }
    }
    println!(
        "small edges' middle off the chord: {:.0} -> {:.0} m in all; {large} large edges alike",
        small.0, small.1
    );
    assert!(large > 10, "{large} large edges");
    assert!(small.1 < 0.75 * small.0, "small edges bend less: {small:?}");

    let (d7, _) = depressions(&seven, 6, (-4, -4), 8);
    let (d8, _) = depressions(&eight, 6, (-4, -4), 8);
    println!(
        "LOD 6 at the origin: closed depressions {:.2} % -> {:.2} %",
        100.0 * d7,
        100.0 * d8
    );
    assert!(d8 <= d7 + 0.0005, "{d7} -> {d8}");
}

/// `valleys: 7` carves the edges out of and into a lake whatever their discharge: west of the
/// range's lake at (112.1 km, 126.5 km), where the mountains stand 800 m above its water, the
/// shores' change (at most `SHORE_MAX_M`, faded in over the lake weight) met uncarved slopes as
/// a wall, 0.6 % of the 8 m steps steeper than 63° and the steepest 74.6°; with the lake's
/// small streams carved none is (the steepest 56.3°).
#[test]
fn a_lake_among_mountains_meets_them_without_a_wall() {
    use strata::bench::realism::{metrics, sample};
    let p = valleys_plan(7);
    let n = 6;
    let s = sample::sample(
        &p,
        3,
        sample::first_tile(&p, 3, 112_080.0, n),
        sample::first_tile(&p, 3, 126_500.0, n),
        n,
        n,
    );
    let slopes = metrics::slopes(&s.grid, 0.0);
    println!(
        "west of the range's lake at 8 m: steepest step {:.1}°, {:.3} % of the steps steeper \
         than 63°",
        slopes.steepest_step_deg,
        100.0 * slopes.cliff_fraction
    );
    assert!(
        s.water.iter().any(|w| !w.is_nan()),
        "the lake is in the square"
    );
    assert!(
        slopes.cliff_fraction == 0.0 && slopes.steepest_step_deg < 63.0,
        "a wall beside the lake: {slopes:?}"
    );
}

/// Largest turn, degrees, between the end of each piece and the start of the next along the
/// edges out of the `n × n` nodes from `(i0, k0)`: the direction of a piece at its ends is the
/// tangent of its parabola, `(b − a) ± s`, and for straight pieces the chord.
fn turns(plan: &WorldPlan, i0: i64, k0: i64, n: i64) -> Vec<f32> {
    let (e, rp) = parts(plan);
    let mut net = Network::new(e, rp);
    let mut out = Vec::new();
    for k in k0..k0 + n {
        for i in i0..i0 + n {
            let Some(edge) = net.edge(i, k) else { continue };
            // The piece's direction at an end: the chord plus the offset's slope there.
            let tangent = |j: usize, end: bool| {
                let (a, b, s) = (edge.points[j], edge.points[j + 1], edge.bends[j]);
                if end {
                    (b[0] - a[0] - s[2], b[1] - a[1] - s[3])
                } else {
                    (b[0] - a[0] + s[0], b[1] - a[1] + s[1])
                }
            };
            for j in 0..edge.bends.len() - 1 {
                let (ux, uz) = tangent(j, true);
                let (vx, vz) = tangent(j + 1, false);
                let cos = (ux * vx + uz * vz) / (ux.hypot(uz) * vx.hypot(vz));
                out.push(cos.clamp(-1.0, 1.0).acos().to_degrees());
            }
        }
    }
    out.sort_by(f32::total_cmp);
    out
}

/// `valleys: 3` (and `4`, `5`, the default) bends each piece so that it leaves and reaches its ends
/// along the river curve's tangents: consecutive pieces meet without a corner (below a degree at
/// the 99th percentile; only hairpins, whose tangents are clamped to 45° off the chord, turn
/// more) where `valleys: 2`'s eight straight pieces turn corners of about ten degrees, so the
/// valley walls follow the curve without a facet per piece.
#[test]
fn bent_pieces_meet_their_neighbours_without_corners() {
    let new = plan();
    let mut old_params = WorldParams::default();
    old_params
        .earth
        .as_mut()
        .and_then(|e| e.rivers.as_mut())
        .expect("rivers")
        .valleys = 2;
    let old = WorldPlan::new(42, old_params).expect("valleys 2 world");
    let (bent, straight) = (turns(&new, -20, -20, 40), turns(&old, -20, -20, 40));
    assert!(bent.len() > 1000, "{} joins", bent.len());
    let p = |v: &[f32], q: f64| v[((v.len() - 1) as f64 * q) as usize];
    let report = format!(
        "turns at joins, degrees: bent p50 {:.2} p99 {:.2} max {:.2}; straight p50 {:.2} p99 {:.2} max {:.2}",
        p(&bent, 0.5), p(&bent, 0.99), p(&bent, 1.0), p(&straight, 0.5), p(&straight, 0.99), p(&straight, 1.0)
    );
    assert!(p(&bent, 0.99) < 1.0, "{report}");
    assert!(p(&straight, 0.5) > 5.0, "{report}");
}

/// The default world with `coarse` (0: tiles coarser than LOD 8 keep their uncarved heights).
fn coarse_plan(coarse: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").coarse = coarse;
    WorldPlan::new(42, params).expect("a coarse world")
}

#[test]
fn the_coarse_network_descends_and_ends_in_the_sea_a_lake_or_a_larger_river() {
    let p = plan();
    let earth = p.earth.as_ref().expect("earth-1");
    let cp = earth
        .coarse_rivers
        .as_ref()
        .expect("new worlds have the coarse network");
    assert_eq!(cp.spacing_m, 4.0 * parts(&p).1.spacing_m);
    assert_eq!(cp.q_scale, 16);
    assert!(earth.carve_plan(9).is_some_and(|c| c == cp));
    assert!(earth.carve_plan(10).is_some_and(|c| c == cp));
    assert!(earth.carve_plan(11).is_none());
    trace_areas(earth, cp, 12);
}

/// The land of `p`'s LOD-`lod` tiles `(tx0.., tz0..)` (`n × n`) in closed depressions deeper
/// than 2 m, as `bench realism` measures it (lakes and rivers flat at their level), and the
/// river vertices.
fn depressions(p: &WorldPlan, lod: u32, (tx0, tz0): (i64, i64), n: usize) -> (f64, usize) {
    use strata::bench::realism::{metrics, sample};
    let s = sample::sample(p, lod, tx0, tz0, n, n);
    let d = metrics::depressions(&s.surface(), p.params.sea_level_m as f64, 2.0);
    let rivers = (0..n as i64)
        .flat_map(|b| (0..n as i64).map(move |a| (a, b)))
        .map(|(a, b)| {
            let t = synthesize(
                p,
                TileKey {
                    lod,
                    x: tx0 + a,
                    z: tz0 + b,
                },
            );
            t.water_kind.iter().filter(|&&k| k == kind::RIVER).count()
        })
        .sum();
    (d.fraction, rivers)
}

/// At 512 m (LOD 9) the uncarved relief holds closed basins over a sixth of the land around
/// the origin (16.5 % in `bench realism`'s 262 km square; Jacksboro block-averaged to 512 m
/// 9.8 %); the coarse network drains most of them through its valleys, whose floors
/// (`COARSE_FLOOR_M` each side) are wide enough that the 512 m samples along them descend
/// (the basins its floods leave closed, as the fine network's do with `lakes: 4`, remain).
#[test]
fn coarse_tiles_drain_the_closed_basins_of_the_uncarved_relief() {
    // 4 × 4 LOD-9 tiles (131 km) around the origin: plains, hills and the range's west flank.
    let first = (-2, -2);
    let (before, dry) = depressions(&coarse_plan(0), 9, first, 4);
    let (after, wet) = depressions(&coarse_plan(1), 9, first, 4);
    println!(
        "LOD 9 around the origin: closed depressions {:.2} % -> {:.2} % of the land, river \
         vertices {dry} -> {wet}",
        100.0 * before,
        100.0 * after
    );
    assert_eq!(dry, 0, "without the coarse network LOD 9 carves no river");
    assert!(wet > 100, "the coarse network's rivers hold water at LOD 9");
    assert!(
        before > 0.1,
        "the uncarved relief should hold closed basins: {before}"
    );
    assert!(
        after <= 0.1 && after < 0.5 * before,
        "closed depressions {before} -> {after}"
    );
}

#[test]
fn coarse_tiles_meet_their_neighbours_bit_for_bit() {
    let p = plan();
    for lod in [9u32, 10] {
        let (mut checked, mut wet) = (0, 0);
        for (tx, tz) in [(0i64, 0i64), (-1, -1), (1, 0)] {
            let t = |x, z| synthesize(&p, TileKey { lod, x, z });
            let (a, east, south) = (t(tx, tz), t(tx + 1, tz), t(tx, tz + 1));
            for v in 0..65 {
                for (va, vb, b) in [(v * 65 + 64, v * 65, &east), (64 * 65 + v, v, &south)] {
                    assert_eq!(a.heights[va].to_bits(), b.heights[vb].to_bits());
                    assert_eq!(a.water_depth[va].to_bits(), b.water_depth[vb].to_bits());
                    assert_eq!(a.water_kind[va], b.water_kind[vb]);
                    wet += usize::from(a.water_kind[va] == kind::RIVER);
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 3 * 2 * 65);
        println!("LOD {lod}: {wet} river vertices on the checked edges");
    }
}

/// River-kind vertices of the LOD-3 tiles (8 m) within `r` tiles of `centre` that lie farther
/// than a vertex spacing beyond the channel of every river line of their tile, and all of them.
fn water_off_the_lines(p: &WorldPlan, centre: (f32, f32), r: i64) -> (usize, usize) {
    let (earth, _) = parts(p);
    let (mut off, mut total) = (0, 0);
    for key in tiles_around(p, 3, centre, r) {
        let t = synthesize(p, key);
        let s = t.spacing_m as f64;
        let lines = tile_rivers(earth, key, t.spacing_m);
        for v in (0..65 * 65).filter(|&v| t.water_kind[v] == kind::RIVER) {
            total += 1;
            let x = t.origin_x_m() + (v % 65) as f64 * s;
            let z = t.origin_z_m() + (v / 65) as f64 * s;
            let beyond = lines
                .iter()
                .flat_map(|l| {
                    l.points.windows(2).zip(l.width_m.windows(2)).map(|(p, w)| {
                        let (ax, az) = (p[0][0] as f64, p[0][1] as f64);
                        let (dx, dz) = (p[1][0] as f64 - ax, p[1][1] as f64 - az);
                        let t = (((x - ax) * dx + (z - az) * dz) / (dx * dx + dz * dz).max(1e-9))
                            .clamp(0.0, 1.0);
                        (ax + t * dx - x).hypot(az + t * dz - z) - 0.5 * w[0].max(w[1]) as f64
                    })
                })
                .fold(f64::INFINITY, f64::min);
            off += usize::from(beyond > s);
        }
    }
    (off, total)
}

/// A client draws a river along its tile's river lines and leaves out the tile's river water
/// within the channel's half-width and a vertex spacing of a line (the viewer's ribbons,
/// `web/src/riverMask.ts`). With `lines: 2` (new worlds) the lines follow each piece's curve
/// within `LINE_TOLERANCE_M` and include the long edges of breached pits and spilling lakes, so
/// every river vertex of an 8 m tile lies along a line; with a bent piece's middle alone
/// (`lines: 1`) a fifth of them lay up to 30 m beside it, drawn as dashes of water beside the
/// ribbon. Around a river that enters a lake, near the origin, 690 km out and at negative
/// coordinates.
#[test]
fn river_water_lies_along_the_tile_lines() {
    let with_lines = |lines: u32| {
        let mut params = WorldParams::default();
        let rivers = params.earth.as_mut().and_then(|e| e.rivers.as_mut());
        rivers.expect("rivers").lines = lines;
        WorldPlan::new(42, params).expect("plan")
    };
    let (dense, first) = (with_lines(2), with_lines(1));
    let (mut all, mut before) = ((0, 0), 0);
    for centre in [
        (16_884.0, 10_733.0),
        (-2_528.0, 4_012.0),
        (624_640.0, 301_056.0),
        (-38_912.0, -14_336.0),
    ] {
        let (off, total) = water_off_the_lines(&dense, centre, 4);
        let (off1, total1) = water_off_the_lines(&first, centre, 4);
        println!("around {centre:?}: {off} of {total} river vertices off the lines ({off1} with lines 1)");
        assert_eq!(total, total1, "the lines change no tile");
        (all.0, all.1, before) = (all.0 + off, all.1 + total, before + off1);
    }
    assert!(all.1 > 500, "only {} river vertices", all.1);
    assert_eq!(
        all.0, 0,
        "{} of {} river vertices off the lines",
        all.0, all.1
    );
    assert!(
        before * 10 > all.1,
        "lines 1 left {before} of {} off",
        all.1
    );
}
