//! Lake shores (`rivers.lakes: 2` and later; `terrain::earth::rivers`' shores): a lake's water
//! ends where its ground rises to its level, so no lake has a straight side where the ground
//! beyond stays below the water; the first lakes (`lakes: 1`, worlds stored before) keep the
//! straight sides, which is how this test knows it can fail. Spilling lakes keep a sill where
//! their river leaves (`lakes: 4`, the default of new worlds), which `lakes: 3` lacks.

use strata::terrain::earth::rivers::{kind, LakeField};
use strata::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan};

mod common;

fn plan(lakes: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let rivers = params
        .earth
        .as_mut()
        .and_then(|e| e.rivers.as_mut())
        .expect("the default world has rivers");
    rivers.lakes = lakes;
    WorldPlan::new(42, params).expect("plan")
}

/// [`plan`] with every gully octave and `valleys: 6`, the default of new worlds when the range
/// of [`basins_closed_by_a_ranges_ridges_fill_to_their_outlets`] was chosen for its basins:
/// without the coarsest gully octave the range's ridges close other basins (19.5 % of the
/// square stays closed with `lakes: 5`), and with `valleys: 7` its small streams cut no valley.
fn plan_of_the_basins(lakes: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.gully_first = 0;
    let rivers = earth.rivers.as_mut().expect("the default world has rivers");
    (rivers.lakes, rivers.valleys) = (lakes, 6);
    WorldPlan::new(42, params).expect("plan")
}

/// Lake vertices of the LOD-8 tiles around the origin, one per lake (points at least 3 km
/// apart), at most `n`.
fn lake_points(plan: &WorldPlan, n: usize) -> Vec<(f64, f64)> {
    let mut points: Vec<(f64, f64)> = Vec::new();
    for (x, z) in [(0, 0), (-1, 0), (0, -1), (-1, -1), (1, 0), (0, 1)] {
        let t = synthesize(plan, TileKey { lod: 8, x, z });
        let s = t.spacing_m as f64;
        for (v, _) in t
            .water_kind
            .iter()
            .enumerate()
            .filter(|&(_, &k)| k == kind::LAKE)
        {
            let p = (
                t.origin_x_m() + (v % 65) as f64 * s,
                t.origin_z_m() + (v / 65) as f64 * s,
            );
            if points.iter().all(|q| (q.0 - p.0).hypot(q.1 - p.1) > 3000.0) {
                points.push(p);
            }
            if points.len() == n {
                return points;
            }
        }
    }
    points
}

/// Shore pairs of `tile`: a lake vertex and a dry 4-neighbour. Returns how many there are and
/// how many of the dry vertices lie more than a centimetre below the lake's surface there.
fn shore_pairs(tile: &Tile) -> (usize, usize) {
    let (mut pairs, mut low) = (0, 0);
    for j in 0..65i64 {
        for i in 0..65i64 {
            let v = (j * 65 + i) as usize;
            if tile.water_kind[v] != kind::LAKE {
                continue;
            }
            for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
                let (a, b) = (i + di, j + dj);
                if !(0..65).contains(&a) || !(0..65).contains(&b) {
                    continue;
                }
                let u = (b * 65 + a) as usize;
                if tile.water_kind[u] != kind::NONE {
                    continue;
                }
                pairs += 1;
                low += usize::from(tile.heights[u] < tile.heights[v] + tile.water_depth[v] - 0.01);
            }
        }
    }
    (pairs, low)
}

/// Shore pairs of the LOD-`lod` tiles (3 × 3) around each point.
fn shores_around(plan: &WorldPlan, points: &[(f64, f64)], lod: u32) -> (usize, usize) {
    let (mut pairs, mut low) = (0, 0);
    for &(x, z) in points {
        let c = common::water::key_at(plan, lod, x, z);
        for dz in -1..=1 {
            for dx in -1..=1 {
                let t = synthesize(
                    plan,
                    TileKey {
                        lod,
                        x: c.x + dx,
                        z: c.z + dz,
                    },
                );
                let (p, l) = shore_pairs(&t);
                pairs += p;
                low += l;
            }
        }
    }
    (pairs, low)
}

#[test]
fn lake_water_ends_where_its_ground_rises_to_its_level() {
    let shaped = plan(2);
    let first = plan(1);
    let points = lake_points(&first, 4);
    assert!(
        points.len() >= 2,
        "only {} lakes near the origin of seed 42",
        points.len()
    );
    println!("lakes at {points:?}");
    for lod in [2u32, 4, 6] {
        let (pairs, low) = shores_around(&shaped, &points, lod);
        let (pairs1, low1) = shores_around(&first, &points, lod);
        println!(
            "LOD {lod}: lakes 2: {pairs} shore pairs, {low} dry below the level; lakes 1: \
             {pairs1} pairs, {low1} below"
        );
        assert!(pairs >= 50, "LOD {lod}: only {pairs} shore pairs");
        assert_eq!(
            low, 0,
            "LOD {lod}: {low} of {pairs} dry shore vertices lie below their lake's level"
        );
        if lod <= 4 {
            assert!(
                low1 * 20 >= pairs1,
                "LOD {lod}: the first lakes should show their straight sides ({low1} of {pairs1})"
            );
        }
    }
}

/// Where the river of the spilling lake south of the origin of seed 42 leaves it: the valleys
/// there lie below the lake's level.
const OUTLET: (f64, f64) = (-400.0, 650.0);

/// A spilling lake keeps a sill where its river leaves (`lakes: 4`): the carve cuts no
/// floodplain or valley wall below the lake's level beside its water, so no dry vertex next to
/// the lake lies below its level. With `lakes: 3` the valley floors of the river that leaves the
/// lake, and of the rivers that join it there, lie dry below the level right beside the water
/// (a lake would flood them), which is how this test knows it can fail.
#[test]
fn spilling_lakes_keep_a_sill_where_their_river_leaves() {
    let (sills, spilling) = (plan(4), plan(3));
    let mut points = lake_points(&sills, 4);
    points.push(OUTLET);
    let mut low3 = 0;
    for lod in [2u32, 4, 6] {
        let (pairs, low) = shores_around(&sills, &points, lod);
        let (pairs3, l3) = shores_around(&spilling, &points, lod);
        println!(
            "LOD {lod}: lakes 4: {pairs} shore pairs, {low} dry below the level; lakes 3: \
             {pairs3} pairs, {l3} below"
        );
        assert!(pairs >= 50, "LOD {lod}: only {pairs} shore pairs");
        assert_eq!(
            low, 0,
            "LOD {lod}: {low} of {pairs} dry shore vertices lie below their lake's level"
        );
        low3 += l3;
    }
    assert!(
        low3 >= 20,
        "lakes 3 should leave valley floors dry below the level at the outlet ({low3})"
    );
}

/// The carve's faster paths (pruned bins, lanes) and the water grid give the scalar carve's
/// and water's bits on tiles with shaped shores, where the shores change heights before the
/// carve, and with sills (`lakes: 4` and 5), where the sills change the carve beside the lakes;
/// the lake fields of a row side by side (`RiverJob::lake_field_row`, which both faster paths
/// read) are each sample's `RiverJob::lake_field`, bit for bit, and the water grid given the
/// carve's fields (`RiverJob::water_grid_fields`, as a tile's water reads them) gives the same
/// water as computing them.
#[test]
fn shores_keep_the_faster_carve_and_water_paths_bit_exact() {
    for lakes in [2, 4, 5, 8] {
        faster_paths_are_bit_exact(lakes);
    }
}

fn faster_paths_are_bit_exact(lakes: u32) {
    use strata::terrain::earth::rivers::{job_for, water_at, water_job_for};
    let p = plan(lakes);
    let earth = p.earth.as_ref().expect("earth-1");
    let rp = earth.rivers.as_ref().expect("rivers");
    let mut points = lake_points(&p, 2);
    if lakes >= 4 {
        points.push(OUTLET);
    }
    let n = 65usize;
    let (mut shored, mut lake, mut silled, mut fields) = (0usize, 0usize, 0usize, 0usize);
    for &(x, z) in &points {
        for lod in [0u32, 3, 5] {
            let key = common::water::key_at(&p, lod, x, z);
            let spacing = p.lods[lod as usize].spacing_m;
            let (gx0, gz0) = (key.x * 64, key.z * 64);
            let xs: Vec<f32> = (0..n as i64).map(|i| (gx0 + i) as f32 * spacing).collect();
            let zs: Vec<f32> = (0..n as i64).map(|j| (gz0 + j) as f32 * spacing).collect();
            let t = synthesize(&p, key);
            let full = job_for(earth, rp, spacing, gx0, gz0, n, n);
            // Heights before the carve are not at hand; the carved ones, raised, exercise the
            // shores' wedge on both sides.
            let raised: Vec<f32> = t.heights.iter().map(|h| h + 3.0).collect();
            let pruned = full.pruned(
                raised
                    .iter()
                    .enumerate()
                    .map(|(v, h)| (xs[v % n], zs[v / n], *h)),
            );
            let bits = |f: Option<LakeField>| f.map(|f| [f.level, f.weight, f.e].map(f32::to_bits));
            let mut row = vec![None; n];
            for &z in &zs {
                full.lake_field_row(&xs, z, &mut row);
                for (&x, &f) in xs.iter().zip(&row) {
                    assert_eq!(
                        bits(f),
                        bits(full.lake_field(x, z)),
                        "{key:?} ({x}, {z}): the lake field of the row differs"
                    );
                    fields += usize::from(f.is_some());
                }
            }
            let mut lanes = raised.clone();
            let carved_fields = full.carve_grid_fields(&xs, &zs, &mut lanes);
            let water = water_job_for(earth, rp, spacing, gx0, gz0, n, n);
            let sea = p.params.sea_level_m;
            let (mut surface, mut kinds) = (Vec::new(), Vec::new());
            water.water_grid(sea, &xs, &zs, &t.heights, &mut surface, &mut kinds);
            // The water grid given the carve's lake fields (as a tile's water reads them) gives
            // the same water as computing them.
            let (mut given_surface, mut given_kinds) = (Vec::new(), Vec::new());
            water.water_grid_fields(
                sea,
                (&xs, &zs),
                &t.heights,
                &carved_fields,
                &mut given_surface,
                &mut given_kinds,
            );
            let surface_bits = |s: &[f32]| s.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            assert_eq!(
                (surface_bits(&given_surface), &given_kinds),
                (surface_bits(&surface), &kinds),
                "{key:?}: the water grid given the carve's lake fields differs"
            );
            for (v, h) in raised.iter().enumerate() {
                let (x, z) = (xs[v % n], zs[v / n]);
                let one = full.carve_one(x, z, *h);
                shored += usize::from(full.shore(x, z, *h).to_bits() != h.to_bits());
                silled += usize::from(full.shore_sill(x, z, *h).1.s > 0.0);
                assert_eq!(
                    full.carve_pruned(&pruned, x, z, *h).to_bits(),
                    one.to_bits(),
                    "{key:?} vertex {v}: the pruned carve differs"
                );
                assert_eq!(
                    lanes[v].to_bits(),
                    one.to_bits(),
                    "{key:?} vertex {v}: the carve in lanes differs"
                );
                let (s_full, k_full) = water_at(&full, sea, x, z, t.heights[v]);
                assert_eq!(
                    (surface[v].to_bits(), kinds[v]),
                    (s_full.to_bits(), k_full),
                    "{key:?} vertex {v}: the water grid differs"
                );
                lake += usize::from(k_full == kind::LAKE);
            }
        }
    }
    println!(
        "lakes {lakes}: {shored} heights moved by the shores, {silled} under a sill, {lake} lake \
         vertices, {fields} lake fields"
    );
    assert!(fields > 1000, "only {fields} samples with a lake field");
    assert!(shored > 1000, "only {shored} heights moved by the shores");
    assert!(lake > 100, "only {lake} lake vertices");
    if lakes >= 4 {
        assert!(silled > 1000, "only {silled} heights under a sill");
    }
}

/// The basins a mountain belt's ridges close fill to their outlets (`lakes: 5`):
/// in the range around (112 km, −100 km), 65 km square at 64 m (the basins
/// lie wholly inside: the fill drains the square's edges), the
/// land that a priority-flood fill of the water surface (lakes and rivers included) raises by
/// more than 2 m falls from over a fifth with the floods of `lakes: 4`, whose search stops at
/// 256 nodes within 12 spacings and leaves a lake in each basin's bottom below a dry closed
/// floor hundreds of metres deep, to a few percent; and fewer of the range's flows end inland.
#[test]
fn basins_closed_by_a_ranges_ridges_fill_to_their_outlets() {
    use strata::bench::realism::sample;
    let square = |lakes: u32| {
        let p = plan_of_the_basins(lakes);
        let n = 16;
        let first = (
            sample::first_tile(&p, 6, 112_000.0, n),
            sample::first_tile(&p, 6, -100_000.0, n),
        );
        closed_n(&p, 6, first, n)
    };
    let (four, five) = (square(4), square(5));
    println!(
        "closed depressions > 2 m: lakes 4 {:.2} % of the land, lakes 5 {:.2} %",
        100.0 * four,
        100.0 * five
    );
    assert!(four > 0.2, "lakes 4: {four}");
    assert!(five < 0.05, "lakes 5: {five}");

    // The network's view: the flows from the range's nodes end inland (in a lake that does not
    // spill) at fewer places with `lakes: 5`, a subset of those of `lakes: 4`: lakes whose
    // floods stopped at 12 spacings found their outlets and spill towards the sea. (Four ends
    // against six here: two basins more than 30 spacings long still stop their floods, and
    // two lakes upstream of one cannot spill into it, whose level is higher.)
    let inland_ends = |lakes: u32| {
        let p = plan_of_the_basins(lakes);
        let earth = p.earth.as_ref().expect("earth-1");
        let rp = earth.rivers.as_ref().expect("rivers");
        let mut net = strata::terrain::earth::rivers::Network::new(earth, rp);
        let mut ends = std::collections::BTreeSet::new();
        for k in -116..-84 {
            for i in 96..128 {
                let mut at = (i, k);
                for _ in 0..100_000 {
                    match net.down(at.0, at.1) {
                        Some(next) => at = next,
                        None => break,
                    }
                }
                let end = net.node(at.0, at.1);
                assert!(end.down.is_none(), "the flow from {:?} ends", (i, k));
                if !end.sea {
                    ends.insert(at);
                }
            }
        }
        ends
    };
    let (four, five) = (inland_ends(4), inland_ends(5));
    println!("flows ending inland: lakes 4 at {four:?}, lakes 5 at {five:?}");
    assert!(
        five.is_subset(&four) && five.len() < four.len(),
        "lakes 4 ends the flows at {four:?}, lakes 5 at {five:?}"
    );
}

/// `lakes: 6` (new worlds until `7`): the network sees the hollows of a plain, and a flow
/// ends where it first reaches a lake's water. With `lakes: 5` the node heights were the LOD
/// of four node spacings', which stood up to 90 m above the bowls of the origin's plain (node
/// `(−11, 8)`: 177 m over ground at 94 m), so a bowl kilometres wide held neither river nor
/// lake, and a river that crossed a lake's water without meeting its pit (or ended in a pit
/// submerged by a higher lake) was cut below the water. Over the origin's 33 km square at 64 m
/// the land in closed depressions deeper than 2 m falls from over 5 % to under 2 %; over 80 × 80
/// nodes around the origin no flow's water level lies more than 1 m below the first lake it
/// reaches, where with the hollows alone (the flow still ending at a pit) hundreds do.
#[test]
fn the_network_sees_the_plains_hollows_and_rivers_rest_on_the_lakes_they_reach() {
    use strata::terrain::earth::rivers::Network;
    let (five, six) = (plan(5), plan(6));
    let (c5, c6) = (closed(&five, 6, (-4, -4)), closed(&six, 6, (-4, -4)));
    println!(
        "origin at 64 m, closed depressions > 2 m: lakes 5 {:.2} %, lakes 6 {:.2} %",
        100.0 * c5,
        100.0 * c6
    );
    assert!(c5 > 0.05, "lakes 5: {c5}");
    assert!(c6 < 0.02, "lakes 6: {c6}");

    let earth = six.earth.as_ref().expect("earth-1");
    let rp = earth.rivers.as_ref().expect("rivers");
    // The bowl west of the origin holds a lake now.
    let mut net = Network::new(earth, rp);
    let bowl = net.node(-11, 8);
    assert!(
        bowl.lake.is_some_and(|l| l > bowl.h),
        "the bowl's node holds a lake: {bowl:?}"
    );
    // Water levels of the flows that reach a lake, against the lake's level.
    let below = |plan: &strata::terrain::earth::rivers::RiverPlan| {
        let mut net = Network::new(earth, plan);
        let (mut reach, mut below) = (0, 0);
        for k in -40..40 {
            for i in -40..40 {
                if net.lake(i, k).is_some() {
                    continue;
                }
                let w = net.water_level(i, k);
                let mut at = (i, k);
                for _ in 0..400 {
                    let Some(next) = net.down(at.0, at.1) else {
                        break;
                    };
                    at = next;
                    if let Some(level) = net.lake(at.0, at.1) {
                        reach += 1;
                        below += usize::from(w < level - 1.0);
                        break;
                    }
                }
            }
        }
        (reach, below)
    };
    // The same network ending its flows at pits only: its own fingerprint, so no cached block
    // of the other is read.
    let mut at_pits = rp.clone();
    at_pits.lake_ends = false;
    at_pits.fingerprint ^= 0x9e37_79b9;
    let ((reach, under), (reach_pits, under_pits)) = (below(rp), below(&at_pits));
    println!(
        "flows reaching a lake: {reach}, {under} below its level; ending at pits: {reach_pits}, \
         {under_pits} below"
    );
    assert!(reach > 1000, "{reach}");
    assert_eq!(under, 0, "every flow rests on the lake it reaches");
    assert!(
        under_pits > 100,
        "ending at pits cuts below the lakes: {under_pits}"
    );
}

/// `lakes: 6`: the water of a lake that spills over an outlet beyond its pit's neighbours leaves
/// it at the saddle the outlet was found beyond, and the pit's edge is drawn and carved from
/// there. From the pit, the edge (tens of kilometres at the origin, where a lake's flood took
/// in the long lake beside it) cut a trench across the hills beside the water, its floor falling
/// from the lake's level to the outlet's, and its river line floated up to 72 m above the
/// ground beyond the trench.
#[test]
fn a_spilling_lake_leaves_over_its_saddle() {
    use strata::terrain::earth::rivers::{Network, BREACH_DEPTH_M, JITTER};
    let six = plan(6);
    let earth = six.earth.as_ref().expect("earth-1");
    let rp = earth.rivers.as_ref().expect("rivers");
    // The spilling lakes' edges within 40 nodes of the origin: the distance from the edge's
    // first point to the outlet, in node spacings.
    let starts = |plan: &strata::terrain::earth::rivers::RiverPlan| {
        let mut net = Network::new(earth, plan);
        let mut out = Vec::new();
        for k in -40..40 {
            for i in -40..40 {
                let n = net.node(i, k);
                let Some(o) = n.down else { continue };
                let long = (o.0 - i).abs() > 1 || (o.1 - k).abs() > 1;
                if !long || n.lake.is_none() || n.q < plan.wet_q {
                    continue;
                }
                // A lake's pit spills to its flood's outlet; a shallow pit (under 20 m,
                // `BREACH_DEPTH_M`) drains to it as a river, its breach carved from the pit.
                let lake = net.flood(i, k);
                let breached = lake.0 - n.h < BREACH_DEPTH_M && net.height(o.0, o.1) < n.h;
                if lake.2 != Some(o) || breached {
                    continue;
                }
                let e = net.edge(i, k).expect("an edge");
                let to = net.node(o.0, o.1);
                let d = (e.points[0][0] - to.x).hypot(e.points[0][1] - to.z) / plan.spacing_m;
                out.push(((i, k), d));
            }
        }
        out
    };
    let mut from_pits = rp.clone();
    from_pits.saddles = false;
    from_pits.fingerprint ^= 0x85eb_ca6b;
    let (saddles, pits) = (starts(rp), starts(&from_pits));
    println!("spilling lakes' edges, first point to outlet in spacings: {saddles:?}; from the pits: {pits:?}");
    assert!(!saddles.is_empty(), "spilling lakes near the origin");
    // A saddle is linked to its outlet: at most a diagonal apart, jitter included.
    let most = std::f32::consts::SQRT_2 * (1.0 + 2.0 * JITTER);
    for &(pit, d) in &saddles {
        assert!(
            d <= most,
            "the edge of {pit:?} starts {d} spacings from its outlet"
        );
    }
    assert!(
        pits.iter().any(|&(_, d)| d > 10.0),
        "from the pits some edge crosses kilometres: {pits:?}"
    );
}

/// `lakes: 7` (the default of new worlds): the coarse network's floods search 30 of its own
/// spacings, so the basins of the far area (around (620 km, 310 km)), a hundred kilometres
/// across, fill to their outlets in its 512 m square, where with `lakes: 6` the floods stopped
/// at 8 spacings, 20 to 40 km short of the outlets, and left over 10 % of the land closed; and
/// a flood its limits stop keeps only the lake it had filled before its level last rose, so
/// no node beside such a lake lies below its level. With `lakes: 6` the flood kept the nodes it
/// had reached beyond the rim that raised its level, beside unvisited neighbours as low: their
/// ground was flattened to a closed dry floor below the level, 30 km wide at 512 m with the
/// wider coarse floods (84 such neighbours beside the west basin's fine lakes).
#[test]
fn coarse_floods_fill_the_far_basins_and_a_stopped_flood_keeps_a_full_lake() {
    let (six, seven) = (plan(6), plan(7));
    let first = |p: &WorldPlan| centred(p, 9, (620e3, 310e3));
    let (c6, c7) = (
        closed(&six, 9, first(&six)),
        closed(&seven, 9, first(&seven)),
    );
    println!(
        "far at 512 m, closed depressions > 2 m: lakes 6 {:.2} %, lakes 7 {:.2} %",
        100.0 * c6,
        100.0 * c7
    );
    assert!(c6 > 0.08, "lakes 6: {c6}");
    assert!(c7 < 0.05, "lakes 7: {c7}");

    // The coarse nodes of that square, and the fine nodes within 40 km of the west basin at
    // (−40 km, 0), whose flood stops 30 spacings from its pit.
    for (what, coarse, centre, r) in [
        ("coarse, far", true, (151, 75), 32),
        ("fine, west basin", false, (-40, 0), 40),
    ] {
        let (s6, b6) = beside_below(&six, coarse, centre, r);
        let (s7, b7) = beside_below(&seven, coarse, centre, r);
        println!(
            "{what}: floods without outlet (nodes beside them below their level): \
             lakes 6 {s6} ({b6}), lakes 7 {s7} ({b7})"
        );
        assert!(s7 > 0, "{what}: some floods stop by their limits");
        assert_eq!(b7, 0, "{what}: a stopped flood keeps a full lake");
        if !coarse {
            assert!(
                b6 > 0,
                "{what}: lakes 6 keeps what its stopped floods reached"
            );
        }
    }
}

/// `lakes: 8` (the default of new worlds): the shores sink the ground inside a lake towards its
/// nodes' heights, and the coarse network's floods visit up to 2,048 nodes. In the crater lake
/// of `bench realism`'s worst 64 m area (around (−367 km, −534 km)) ridges between the fine
/// network's nodes stood up to 270 m above the level inside the lake and parted pools its
/// outlet did not drain (11 % of that square's land closed with `lakes: 7`); in its worst
/// 512 m area (around (375 km, 375 km)) a coarse flood stopped at 512 nodes left a basin about
/// 150 km across holding a lake in the bottom of a dry closed bowl (25 %).
#[test]
fn sunk_lake_floors_and_wider_coarse_floods_drain_the_worst_areas() {
    let (seven, eight) = (plan(7), plan(8));
    for (what, lod, (x, z), before, after) in [
        (
            "the crater lake at 64 m",
            6,
            (-366.8e3, -533.8e3),
            0.08,
            0.02,
        ),
        ("the largest basin at 512 m", 9, (375e3, 375e3), 0.2, 0.1),
    ] {
        let first = |p: &WorldPlan| centred(p, lod, (x, z));
        let (c7, c8) = (
            closed(&seven, lod, first(&seven)),
            closed(&eight, lod, first(&eight)),
        );
        println!(
            "{what}, closed depressions > 2 m: lakes 7 {:.2} %, lakes 8 {:.2} %",
            100.0 * c7,
            100.0 * c8
        );
        assert!(c7 > before, "{what}, lakes 7: {c7}");
        assert!(c8 < after, "{what}, lakes 8: {c8}");
    }
}

/// The fraction of the land closed by depressions deeper than 2 m (the surface a DEM records,
/// as `bench realism` measures it) over the 8 × 8 tiles of LOD `lod` from tile `first`.
fn closed(plan: &WorldPlan, lod: u32, first: (i64, i64)) -> f64 {
    closed_n(plan, lod, first, 8)
}

/// The first tile of the 8 × 8 tiles of LOD `lod` centred on world `(x, z)`, metres.
fn centred(plan: &WorldPlan, lod: u32, (x, z): (f64, f64)) -> (i64, i64) {
    use strata::bench::realism::sample;
    (
        sample::first_tile(plan, lod, x, 8),
        sample::first_tile(plan, lod, z, 8),
    )
}

/// [`closed`] over `n` × `n` tiles.
fn closed_n(plan: &WorldPlan, lod: u32, first: (i64, i64), n: usize) -> f64 {
    use strata::bench::realism::{metrics, sample};
    let s = sample::sample(plan, lod, first.0, first.1, n, n);
    metrics::depressions(&s.surface(), 0.0, 2.0).fraction
}

/// The lakes of `plan`'s fine or coarse network whose floods found no outlet, among the pits
/// within `r` nodes of node `c`, and the nodes beside them (the four axis neighbours, always
/// linked) lower than their level.
fn beside_below(plan: &WorldPlan, coarse: bool, c: (i64, i64), r: i64) -> (usize, usize) {
    use strata::terrain::earth::rivers::Network;
    let earth = plan.earth.as_ref().expect("earth-1");
    let rp = if coarse {
        earth.coarse_rivers.as_ref()
    } else {
        earth.rivers.as_ref()
    };
    let rp = rp.expect("the network");
    let mut net = Network::new(earth, rp);
    let (mut stopped, mut below) = (0, 0);
    for k in c.1 - r..c.1 + r {
        for i in c.0 - r..c.0 + r {
            let n = net.node(i, k);
            if n.down.is_some() || n.h < rp.sea_level_m {
                continue;
            }
            let lake = net.flood(i, k);
            if lake.2.is_some() {
                continue;
            }
            stopped += 1;
            let inside: std::collections::HashSet<_> = lake.1.iter().copied().collect();
            for &(a, b) in &lake.1 {
                for (da, db) in [(1, 0), (0, 1), (-1, 0), (0, -1)] {
                    let m = (a + da, b + db);
                    if !inside.contains(&m) && net.height(m.0, m.1) < lake.0 {
                        below += 1;
                    }
                }
            }
        }
    }
    (stopped, below)
}

/// `lakes: 7`: the shoreline's noise fades with the vertex spacing (`RiverPlan::shore_noise`),
/// as the relief layers do, so no octave shorter than two spacings moves the shore. With
/// `lakes: 6` the 384 m octave, read at 512 m spacing, is a random value per vertex, and the band
/// of lake weight it moves across the shore (a third of a 4 km node spacing each side) held
/// isolated lake vertices on the land around the coarse network's lakes (96 in the range's 4 × 4
/// LOD-9 tiles, 3 with the fade); tiles up to 32 m keep the noise in full, bit for bit.
#[test]
fn coarse_tiles_have_no_isolated_lake_vertices() {
    // Lake vertices whose four neighbours in their tile are all dry, over 4 × 4 LOD-9 tiles of
    // the range east of the origin, and how many lake vertices there are.
    let isolated = |p: &WorldPlan| {
        let (mut alone, mut lake) = (0, 0);
        for z in 2..6 {
            for x in 2..6 {
                let t = synthesize(p, TileKey { lod: 9, x, z });
                let wet = |i: usize, j: usize| t.water_kind[j * 65 + i] == kind::LAKE;
                for j in 1..64 {
                    for i in 1..64 {
                        if !wet(i, j) {
                            continue;
                        }
                        lake += 1;
                        if !(wet(i - 1, j) || wet(i + 1, j) || wet(i, j - 1) || wet(i, j + 1)) {
                            alone += 1;
                        }
                    }
                }
            }
        }
        (alone, lake)
    };
    let (a6, l6) = isolated(&plan(6));
    let (a7, l7) = isolated(&plan(7));
    println!("LOD 9, range: isolated lake vertices lakes 6 {a6} of {l6}, lakes 7 {a7} of {l7}");
    assert!(a6 > 20, "lakes 6: {a6}");
    assert!(l7 > 5_000, "the range's tiles hold lakes: {l7}");
    assert!(a7 * 20 < a6, "lakes 7: {a7} isolated against {a6}");
    // Tiles up to 32 m keep both octaves' constants (so their bits), 512 m tiles neither.
    let seven = plan(7);
    let earth = seven.earth.as_ref().expect("earth-1");
    let rp = earth.rivers.as_ref().expect("rivers");
    use strata::terrain::earth::rivers::{SHORE_N1, SHORE_N2};
    assert_eq!(rp.shore_noise(32.0), [SHORE_N1, SHORE_N2]);
    assert_eq!(rp.shore_noise(512.0), [0.0, 0.0]);
}
