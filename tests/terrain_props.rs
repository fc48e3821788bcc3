//! Properties of the procedural world function that clients rely on: seams, determinism,
//! normalised weights, latitude bands, scatter.

use strata::terrain::scatter::{candidates, scatter, MAX_CANDIDATES, MAX_LEVEL};
use strata::terrain::tile::{snap_edges, Edge};
use strata::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan, TILE_VERTS};

/// The classic world (the first wave's generator, which stored worlds keep).
fn plan(seed: u64) -> WorldPlan {
    WorldPlan::new(seed, WorldParams::classic()).expect("classic world is valid")
}

/// Both generators' worlds: the default `earth-1` and the classic one. The seam, determinism and
/// weight properties hold for each.
fn plans(seed: u64) -> [WorldPlan; 2] {
    [
        WorldPlan::new(seed, WorldParams::default()).expect("default world is valid"),
        plan(seed),
    ]
}

fn edge_values(t: &Tile, e: Edge) -> Vec<(u32, [u32; 3], Vec<u32>, u8)> {
    let k = t.biome_count;
    (0..TILE_VERTS)
        .map(|i| {
            let v = e.vertex(i);
            (
                t.heights[v].to_bits(),
                t.normals[v].map(f32::to_bits),
                t.weights[v * k..(v + 1) * k]
                    .iter()
                    .map(|w| w.to_bits())
                    .collect(),
                t.materials[v],
            )
        })
        .collect()
}

#[test]
fn same_lod_neighbours_share_edges_bit_for_bit() {
    for p in plans(1234) {
        same_lod_edges(&p);
    }
}

fn same_lod_edges(p: &WorldPlan) {
    let p = p.clone();
    for lod in [0u32, 1, 2, 3, 4, 7, 10] {
        for (x, z) in [(-1i64, -1i64), (0, 0), (-3, 2), (5, -7)] {
            let a = synthesize(&p, TileKey { lod, x, z });
            let east = synthesize(&p, TileKey { lod, x: x + 1, z });
            let south = synthesize(&p, TileKey { lod, x, z: z + 1 });
            assert_eq!(
                edge_values(&a, Edge::East),
                edge_values(&east, Edge::West),
                "lod {lod} ({x},{z}) east"
            );
            assert_eq!(
                edge_values(&a, Edge::South),
                edge_values(&south, Edge::North),
                "lod {lod} ({x},{z}) south"
            );
        }
    }
}

#[test]
fn edges_match_where_biomes_blend() {
    // Classic biome cells are 512 m (LOD 0 finds a border), earth-1 cells 32 km (LOD 6 does).
    let [earth, classic] = plans(77);
    edges_match_where_blended(&classic, 0);
    edges_match_where_blended(&earth, 6);
}

/// Finds a tile whose vertices blend biomes, then checks two of its neighbours.
fn edges_match_where_blended(p: &WorldPlan, lod: u32) {
    let blended = (0..400)
        .map(|i| TileKey {
            lod,
            x: i % 20 - 10,
            z: i / 20 - 10,
        })
        .find(|k| {
            synthesize(p, *k)
                .weights
                .iter()
                .any(|w| *w > 0.05 && *w < 0.95)
        })
        .expect("a tile on a biome border within 20×20 tiles");
    let t = synthesize(p, blended);
    let e = synthesize(
        p,
        TileKey {
            x: blended.x + 1,
            ..blended
        },
    );
    let n = synthesize(
        p,
        TileKey {
            z: blended.z - 1,
            ..blended
        },
    );
    assert_eq!(edge_values(&t, Edge::East), edge_values(&e, Edge::West));
    assert_eq!(edge_values(&t, Edge::North), edge_values(&n, Edge::South));
}

#[test]
fn seams_snap_to_the_coarser_neighbour_watertight() {
    for p in plans(99) {
        seams_snap(&p);
    }
}

fn seams_snap(p: &WorldPlan) {
    for lod in [0u32, 1, 2, 3, 8] {
        for (x, z) in [(-1i64, -2i64), (1, 3), (-4, -4)] {
            let key = TileKey { lod, x, z };
            let mut t = synthesize(p, key);
            snap_edges(p, &mut t, [true; 4]);
            // The coarser tile containing each edge's world positions.
            for edge in Edge::ALL {
                for s in 0..TILE_VERTS {
                    let v = edge.vertex(s);
                    let (i, j) = ((v % TILE_VERTS) as i64, (v / TILE_VERTS) as i64);
                    let (gx, gz) = (x * 64 + i, z * 64 + j);
                    if s % 2 == 0 {
                        assert!(gx % 2 == 0 && gz % 2 == 0);
                        let (cx, cz) = ((gx / 2).div_euclid(64), (gz / 2).div_euclid(64));
                        let c = synthesize(
                            p,
                            TileKey {
                                lod: lod + 1,
                                x: cx,
                                z: cz,
                            },
                        );
                        let cv = ((gz / 2 - cz * 64) * 65 + (gx / 2 - cx * 64)) as usize;
                        assert_eq!(
                            t.heights[v].to_bits(),
                            c.heights[cv].to_bits(),
                            "lod {lod} {edge:?} vertex {s}"
                        );
                    } else {
                        let (a, b) = (t.heights[edge.vertex(s - 1)], t.heights[edge.vertex(s + 1)]);
                        assert_eq!(
                            t.heights[v],
                            (a + b) * 0.5,
                            "odd vertex on the coarse segment"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn tiles_are_identical_across_thread_counts() {
    // The same tiles, synthesised in parallel on rayon pools of 1, 2 and 7 threads (so the work
    // is split and interleaved differently), in reverse order, equal the serial run; a fresh
    // plan (as after a restart) gives the same tiles.
    use rayon::prelude::*;
    for p in plans(5) {
        let keys: Vec<TileKey> = (0..24)
            .map(|i| TileKey {
                lod: (i % 4) as u32 * 2,
                x: i - 12,
                z: 5 - i,
            })
            .collect();
        let serial: Vec<Tile> = keys.iter().map(|k| synthesize(&p, *k)).collect();
        for threads in [1, 2, 7] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            let mut parallel: Vec<Tile> =
                pool.install(|| keys.par_iter().rev().map(|k| synthesize(&p, *k)).collect());
            parallel.reverse();
            assert!(serial == parallel, "{threads} threads changed a tile");
        }
        let again = WorldPlan::new(5, p.params.clone()).expect("plan");
        assert_eq!(serial[3], synthesize(&again, keys[3]));
    }
}

#[test]
fn weights_are_in_unit_range_and_sum_to_one() {
    for p in plans(31) {
        weights_sum_to_one(&p);
    }
}

fn weights_sum_to_one(p: &WorldPlan) {
    for i in 0..40 {
        let t = synthesize(
            p,
            TileKey {
                lod: (i % 5) as u32,
                x: i * 3 - 60,
                z: 40 - i * 2,
            },
        );
        for v in 0..t.heights.len() {
            let k = t.biome_count;
            let w = &t.weights[v * k..(v + 1) * k];
            assert!(w.iter().all(|x| (0.0..=1.0).contains(x)), "{w:?}");
            // 1e-5: the weights are divided by their f32 sum, which leaves a rounding error of a
            // few ulp per channel.
            let s: f32 = w.iter().sum();
            assert!((s - 1.0).abs() < 1e-5, "sum {s}");
        }
    }
}

#[test]
fn latitude_puts_arctic_toward_the_pole_and_desert_toward_the_equator() {
    let p = plan(8);
    let params = WorldParams::classic();
    let cell = params.layout.cell_size_m as f64;
    let speed = params.layout.latitude_speed_cells as f64;
    // Mean arctic (0) and desert (3) weights over a row of LOD-4 tiles at a given world z.
    let band = |z_m: f64| {
        let lod = 4u32;
        let span = 64.0 * 16.0;
        let z = (z_m / span).floor() as i64;
        let (mut arctic, mut desert, mut n) = (0.0f64, 0.0f64, 0.0f64);
        for x in -12..12 {
            let t = synthesize(&p, TileKey { lod, x, z });
            for v in 0..t.heights.len() {
                arctic += t.weights[v * 4] as f64;
                desert += t.weights[v * 4 + 3] as f64;
                n += 1.0;
            }
        }
        (arctic / n, desert / n)
    };
    let (pole_arctic, pole_desert) = band(0.5 * cell);
    let (eq_arctic, eq_desert) = band(speed * cell);
    assert!(
        pole_arctic > 0.5 && pole_desert == 0.0,
        "pole: arctic {pole_arctic}, desert {pole_desert}"
    );
    assert!(
        eq_desert > 0.5 && eq_arctic == 0.0,
        "equator: arctic {eq_arctic}, desert {eq_desert}"
    );
}

#[test]
fn coarser_lods_sum_fewer_octaves() {
    let p = plan(3);
    let classic = WorldParams::classic();
    let g = classic.biomes[2]
        .generator
        .as_ref()
        .expect("a classic biome generator");
    // Effective octave count: each octave's amplitude over its full `r^{-kH}` (1 for a whole
    // octave, the fraction for the blended last one).
    let counts: Vec<f32> = (0..=6)
        .map(|lod| {
            p.lods[lod].fractals[2]
                .octaves
                .iter()
                .enumerate()
                .map(|(k, o)| o.amp / g.lacunarity.powf(-(k as f32) * g.hurst))
                .sum()
        })
        .collect();
    assert!(counts.windows(2).all(|w| w[1] < w[0]), "{counts:?}");
    // The fractional octave makes the count continuous: one LOD step removes 1/H octaves.
    assert!(
        (counts[3] - counts[4] - 1.0 / g.hurst).abs() < 1e-3,
        "{counts:?}"
    );
    assert!(counts[6] < counts[0]);
}

#[test]
fn scatter_is_deterministic_inside_the_tile_and_coarse_positions_are_a_subset() {
    let p = plan(11);
    // Mid-latitude (z ≈ 2 km), away from the sparse arctic.
    let key = TileKey {
        lod: 1,
        x: -3,
        z: 16,
    };
    let coarse = scatter(&p, &synthesize(&p, key));
    assert_eq!(coarse, scatter(&p, &synthesize(&p, key)));
    assert!(!coarse.is_empty(), "a 128 m tile carries objects");
    let mut fine = Vec::new();
    for (dx, dz) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let k = TileKey {
            lod: 0,
            x: key.x * 2 + dx,
            z: key.z * 2 + dz,
        };
        fine.extend(scatter(&p, &synthesize(&p, k)));
    }
    let span = 128.0;
    let mut kept = 0;
    for pt in &coarse {
        assert!(
            pt.x >= -3.0 * span && pt.x < -2.0 * span && pt.z >= 16.0 * span && pt.z < 17.0 * span
        );
        assert!(pt.level >= 1);
        if fine
            .iter()
            .any(|f| f.x == pt.x && f.z == pt.z && f.kind == pt.kind)
        {
            kept += 1;
        }
    }
    // Positions never change across LODs; the kind or the slope test can, where the coarser
    // tile's weights or normals differ (biome borders, steep ground), so most objects persist.
    assert!(
        kept * 10 >= coarse.len() * 8,
        "{kept} of {} coarse objects persist at LOD 0",
        coarse.len()
    );
}

#[test]
fn levels_scatter_costs_the_same_at_every_lod_while_scan_grows_fourfold() {
    let [levels, scan] = plans(42);
    let base = candidates(&levels, 0);
    assert!(base > 100, "a LOD-0 tile visits candidates ({base})");
    for lod in 0..=strata::terrain::MAX_LOD {
        let n = candidates(&levels, lod);
        assert!(
            n <= 2 * base,
            "LOD {lod}: {n} candidates against {base} at LOD 0"
        );
        assert!(n <= MAX_CANDIDATES, "LOD {lod}");
    }
    for lod in 0..6 {
        let (a, b) = (candidates(&scan, lod), candidates(&scan, lod + 1));
        assert!(
            b > 3 * a && b <= 4 * a + 4 * (a as f64).sqrt() as u64 + 4,
            "{a} → {b}"
        );
    }
    assert!(
        candidates(&scan, 7) > MAX_CANDIDATES,
        "scan tiles pass the limit at LOD 7"
    );
    assert_eq!(
        MAX_LEVEL,
        strata::terrain::MAX_LOD,
        "the coarsest tiles keep candidates"
    );
}

#[test]
fn levels_scatter_keeps_coarse_positions_and_thins_fourfold_per_level() {
    let [p, _] = plans(42);
    let key = TileKey { lod: 2, x: 0, z: 0 };
    let coarse = scatter(&p, &synthesize(&p, key));
    assert_eq!(coarse, scatter(&p, &synthesize(&p, key)));
    let mut fine = Vec::new();
    for dz in 0..4 {
        for dx in 0..4 {
            let k = TileKey {
                lod: 0,
                x: dx,
                z: dz,
            };
            fine.extend(scatter(&p, &synthesize(&p, k)));
        }
    }
    assert!(
        fine.len() > 200,
        "16 LOD-0 tiles carry objects ({})",
        fine.len()
    );
    assert!(!coarse.is_empty(), "a 256 m tile carries objects");
    let span = 256.0;
    let mut kept = 0;
    for pt in &coarse {
        assert!(
            pt.x >= 0.0 && pt.x < span && pt.z >= 0.0 && pt.z < span,
            "{pt:?}"
        );
        assert!(pt.level >= 2, "{pt:?}");
        if fine
            .iter()
            .any(|f| f.x == pt.x && f.z == pt.z && f.level == pt.level)
        {
            kept += 1;
        }
    }
    assert!(
        kept * 10 >= coarse.len() * 8,
        "{kept} of {} coarse objects persist at LOD 0",
        coarse.len()
    );
    // The objects of level ≥ L thin by about 4 per level (binomial counts: wide bounds).
    let at_least = |l: u32| fine.iter().filter(|f| f.level >= l).count() as f64;
    let r1 = at_least(1) / at_least(0);
    assert!((0.15..0.35).contains(&r1), "level ≥ 1 over level ≥ 0: {r1}");
    assert!(
        at_least(2) < at_least(1) && at_least(1) < at_least(0),
        "counts fall with the level"
    );
}
