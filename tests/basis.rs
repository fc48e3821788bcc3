//! Basis functions (issue 17 item 9, done-when 7 second half; Schneider §3): a region's `basis`
//! operation changes the texture of the relief where its weight is high and nowhere else,
//! through the tile path (`solve_region`, then `edits::synthesize`); tiles outside it are the
//! world's bit for bit, the low-pass above the period is kept, tiles meet bit for bit; a bad
//! operation is refused naming the field.

mod common;

use base64::Engine;
use serde_json::{json, Value};
use std::f64::consts::TAU;
use std::sync::Arc;
use strata::authoring::exchange::encode_png16;
use strata::authoring::{solve_region, RegionSpec};
use strata::edits::{synthesize, TileEdits};
use strata::element::Element;
use strata::scene::Scene;
use strata::terrain::plan::TILE_VERTS;
use strata::terrain::{Tile, TileKey, WorldParams, WorldPlan};

const SEED: u64 = 17;
/// Pixels a side of the basis image.
const PX: usize = 32;
/// The region's bbox, ±`HALF` metres about the origin (not tile-aligned).
const HALF: f64 = 6_000.0;
const BLEND_M: f64 = 1_000.0;
const PERIOD_M: f64 = 1_024.0;
const AMPLITUDE_M: f64 = 150.0;
/// LOD of the tiles: 64 m vertices, 4 096 m tiles.
const LOD: u32 = 6;
/// Tiles `-T..T` a side: ±8 192 m, the outer ring straddling the bbox edge.
const T: i64 = 2;
/// Vertices a side of the tiles' mosaic.
const N: usize = (2 * T as usize) * (TILE_VERTS - 1) + 1;

/// The image's texture at `(u, v)` in periods: tileable (whole cycles a period), dunes and
/// cross ridges.
fn pattern(u: f64, v: f64) -> f64 {
    (TAU * u).sin() + 0.7 * (TAU * 2.0 * v).cos() + 0.5 * (TAU * (u + 2.0 * v)).sin()
}

fn image() -> Vec<f32> {
    let mut h = Vec::with_capacity(PX * PX);
    for j in 0..PX {
        for i in 0..PX {
            h.push(pattern(i as f64 / PX as f64, j as f64 / PX as f64) as f32);
        }
    }
    h
}

fn basis_op(weight: f64) -> Value {
    let png = encode_png16(PX, PX, &image()).expect("png");
    json!({"op": "basis",
           "png_base64": base64::engine::general_purpose::STANDARD.encode(&png.bytes),
           "period_m": PERIOD_M, "amplitude_m": AMPLITUDE_M, "weight": weight,
           "blend_m": BLEND_M})
}

fn region(ops: Vec<Value>) -> Value {
    json!({"id": "dunes", "bbox": {"min": [-HALF, -HALF], "max": [HALF, HALF]},
           "samples": 257, "ops": ops})
}

fn spec(ops: Vec<Value>) -> RegionSpec {
    let e: Element = serde_json::from_value(region(ops)).expect("element");
    RegionSpec::from_element(&e).expect("spec")
}

fn key(x: i64, z: i64) -> TileKey {
    TileKey { lod: LOD, x, z }
}

fn pearson(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma).powi(2);
        sbb += (y - mb).powi(2);
    }
    sab / (saa * sbb).sqrt()
}

/// The tiles `-T..T` a side, row-major.
fn tiles(plan: &WorldPlan, edits: &TileEdits) -> Vec<Tile> {
    let mut out = Vec::new();
    for z in -T..T {
        for x in -T..T {
            out.push(synthesize(plan, key(x, z), edits));
        }
    }
    out
}

/// The tiles' heights as one `N × N` mosaic from `(−T·4096, −T·4096)`, 64 m apart.
fn mosaic(tiles: &[Tile]) -> Vec<f64> {
    let mut m = vec![f64::NAN; N * N];
    let n = 2 * T as usize;
    for tz in 0..n {
        for tx in 0..n {
            let t = &tiles[tz * n + tx];
            for (v, h) in t.heights.iter().enumerate() {
                let (i, j) = (v % TILE_VERTS, v / TILE_VERTS);
                let (gi, gj) = (tx * (TILE_VERTS - 1) + i, tz * (TILE_VERTS - 1) + j);
                m[gj * N + gi] = f64::from(*h);
            }
        }
    }
    m
}

fn position(gi: usize, gj: usize) -> [f64; 2] {
    let o = -(T as f64) * 4096.0;
    [o + gi as f64 * 64.0, o + gj as f64 * 64.0]
}

/// The high-pass at the period: the value minus its mean over the `(PERIOD/64)` vertices
/// centred on each vertex (one period's footprint), at the vertices at least `margin` metres
/// inside the bbox.
fn high_pass(m: &[f64], margin: f64) -> Vec<f64> {
    let r = (PERIOD_M / 64.0 / 2.0) as usize;
    let mut out = Vec::new();
    for gj in r..N - r {
        for gi in r..N - r {
            let p = position(gi, gj);
            if p[0].abs() > HALF - margin || p[1].abs() > HALF - margin {
                continue;
            }
            // 2r vertices a side: exactly one period.
            let mut sum = 0.0;
            for j in gj - r..gj + r {
                for i in gi - r..gi + r {
                    sum += m[j * N + i];
                }
            }
            out.push(m[gj * N + gi] - sum / (4 * r * r) as f64);
        }
    }
    out
}

/// The image tiled over the mosaic's vertices (its expected texture, up to scale).
fn tiled() -> Vec<f64> {
    let mut m = vec![0.0; N * N];
    for gj in 0..N {
        for gi in 0..N {
            let p = position(gi, gj);
            m[gj * N + gi] = pattern(p[0] / PERIOD_M, p[1] / PERIOD_M);
        }
    }
    m
}

/// Means over blocks of 2 periods (32 × 32 vertices) inside the full-weight interior.
fn block_means(m: &[f64]) -> Vec<f64> {
    let b = (2.0 * PERIOD_M / 64.0) as usize;
    let mut out = Vec::new();
    let mut gj = 0;
    while gj + b <= N {
        let mut gi = 0;
        while gi + b <= N {
            let (lo, hi) = (position(gi, gj), position(gi + b - 1, gj + b - 1));
            let inside = |p: [f64; 2]| p[0].abs() <= HALF - BLEND_M && p[1].abs() <= HALF - BLEND_M;
            if inside(lo) && inside(hi) {
                let mut sum = 0.0;
                for j in gj..gj + b {
                    for i in gi..gi + b {
                        sum += m[j * N + i];
                    }
                }
                out.push(sum / (b * b) as f64);
            }
            gi += b;
        }
        gj += b;
    }
    out
}

#[test]
fn the_basis_function_replaces_the_texture_where_its_weight_is_high_and_nowhere_else() {
    let plan = WorldPlan::new(SEED, WorldParams::earth()).expect("plan");
    let d = solve_region(&plan, &spec(vec![basis_op(1.0)])).expect("solved");
    let edits = TileEdits {
        displacements: vec![Arc::new(d)],
        ..TileEdits::default()
    };
    let with = tiles(&plan, &edits);
    let plain = tiles(&plan, &TileEdits::default());
    let (m, m0) = (mosaic(&with), mosaic(&plain));
    // Where the weight is 1 (BLEND_M inside the edge) the texture below the period is the
    // image's.
    let want = high_pass(&tiled(), BLEND_M);
    let (got, before) = (high_pass(&m, BLEND_M), high_pass(&m0, BLEND_M));
    let r = pearson(&got, &want);
    let r0 = pearson(&before, &want);
    let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
    println!(
        "high-pass vs tiled image over {} full-weight vertices: Pearson r = {r:.4} (world \
         without the op: {r0:.4}); high-pass RMS {:.1} m (without: {:.1} m, image RMS {AMPLITUDE_M} m)",
        got.len(),
        rms(&got),
        rms(&before)
    );
    assert!(r >= 0.9, "correlation {r:.4} < 0.9");
    assert!(r0.abs() < 0.2, "the world alone correlates {r0:.4}");
    // The low-pass above the period stays the world's: means over 2-period blocks.
    let (a, b) = (block_means(&m), block_means(&m0));
    let diff = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    let mb = b.iter().sum::<f64>() / b.len() as f64;
    let spread = rms(&b.iter().map(|x| x - mb).collect::<Vec<_>>());
    println!(
        "2-period block means ({} blocks): max |change| {diff:.2} m (their spread about their \
         mean: {spread:.1} m)",
        a.len()
    );
    // The box low-pass does not split the scales sharply: the world's relief at one to three
    // periods leaks a little (17 m measured, 5 % of the blocks' spread).
    assert!(
        diff <= 25.0 && diff <= 0.1 * spread,
        "block means moved by {diff:.2} m"
    );
    // Seams, across the bbox edge too.
    common::seams::assert_grid_seams(&with, 2 * T as usize);
    // Outside the bbox the tiles are the world's, bit for bit.
    for (x, z) in [(T, 0), (-T - 1, 0), (0, T), (0, -T - 1), (T, T)] {
        let a = synthesize(&plan, key(x, z), &edits);
        let b = synthesize(&plan, key(x, z), &TileEdits::default());
        assert_eq!(a.heights, b.heights, "tile ({x}, {z}) outside the region");
        assert_eq!(a.normals, b.normals, "tile ({x}, {z}) normals");
    }
}

#[test]
fn several_basis_functions_are_renormalised_to_convex_weights() {
    // Two ops of weight 1 with the same image share the weight 1/2 each where the taper is 1:
    // the displacement there is one op's of weight 1 (in the taper, 2t < 1 is kept and 2t ≥ 1
    // renormalised to 1, so it differs there, as it should). Two of weight 0.3 sum to 0.6 < 1
    // and are kept as they are everywhere.
    let plan = WorldPlan::new(SEED, WorldParams::earth()).expect("plan");
    let solve = |ops: Vec<Value>| solve_region(&plan, &spec(ops)).expect("solved").d;
    let n = 257;
    let spacing = 2.0 * HALF / (n - 1) as f64;
    let inside = |v: usize| {
        let (x, z) = (
            -HALF + (v % n) as f64 * spacing,
            -HALF + (v / n) as f64 * spacing,
        );
        x.abs() <= HALF - BLEND_M && z.abs() <= HALF - BLEND_M
    };
    let max_diff = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .enumerate()
            .filter(|(v, _)| inside(*v))
            .map(|(_, (x, y))| (x - y).abs())
            .fold(0.0f32, f32::max)
    };
    let one = solve(vec![basis_op(1.0)]);
    let two = solve(vec![basis_op(1.0), basis_op(1.0)]);
    let e1 = max_diff(&one, &two);
    let part = solve(vec![basis_op(0.6)]);
    let parts = solve(vec![basis_op(0.3), basis_op(0.3)]);
    let e2 = max_diff(&part, &parts);
    let peak = one.iter().fold(0.0f32, |m, x| m.max(x.abs()));
    println!("max |difference|: {e1:.4} m (1 + 1 against 1), {e2:.4} m (0.3 + 0.3 against 0.6); peak |D| {peak:.1} m");
    assert!(e1 < 0.05 && e2 < 0.05, "{e1} m, {e2} m");
}

#[test]
fn a_bad_basis_op_is_refused_naming_the_field() {
    let scene = |op: Value| json!({"regions": [region(vec![op])]});
    let good = basis_op(0.7);
    Scene::from_value(&scene(good.clone())).expect("a good basis op is accepted");
    let refused = |v: Value| Scene::from_value(&v).expect_err("refused");
    let field = |f: &str, v: Value| {
        let mut bad = good.clone();
        bad[f] = v;
        refused(scene(bad))
    };
    assert_eq!(
        field("png_base64", json!("not*base64")).pointer,
        "/regions/0/ops/0/png_base64"
    );
    let flat = encode_png16(4, 4, &[1.0; 16]).expect("png");
    let e = field(
        "png_base64",
        json!(base64::engine::general_purpose::STANDARD.encode(&flat.bytes)),
    );
    assert_eq!(e.pointer, "/regions/0/ops/0/png_base64", "{e}");
    assert!(e.message.contains("flat"), "{e}");
    let wide =
        encode_png16(1025, 2, &(0..2050).map(|v| v as f32).collect::<Vec<_>>()).expect("png");
    let e = field(
        "png_base64",
        json!(base64::engine::general_purpose::STANDARD.encode(&wide.bytes)),
    );
    assert_eq!(e.pointer, "/regions/0/ops/0/png_base64", "{e}");
    assert!(e.message.contains("1024"), "{e}");
    // 4 region spacings: 12 000 m / 256 × 4 = 187.5 m.
    let e = field("period_m", json!(150.0));
    assert_eq!(e.pointer, "/regions/0/ops/0/period_m", "{e}");
    assert!(e.message.contains("187.5"), "{e}");
    assert_eq!(
        field("period_m", json!(1.0e6)).pointer,
        "/regions/0/ops/0/period_m"
    );
    assert_eq!(
        field("amplitude_m", json!(-1.0)).pointer,
        "/regions/0/ops/0/amplitude_m"
    );
    assert_eq!(
        field("amplitude_m", json!(6000.0)).pointer,
        "/regions/0/ops/0/amplitude_m"
    );
    assert_eq!(
        field("weight", json!(1.5)).pointer,
        "/regions/0/ops/0/weight"
    );
    assert_eq!(
        field("weight", json!(-0.1)).pointer,
        "/regions/0/ops/0/weight"
    );
    assert_eq!(
        field("blend_m", json!(-1.0)).pointer,
        "/regions/0/ops/0/blend_m"
    );

    // The README's example: an 8-bit 4×4 image.
    let readme = json!({"regions": [{"id": "dunes",
        "bbox": {"min": [0, 0], "max": [4096, 4096]}, "samples": 129,
        "ops": [{"op": "basis", "png_base64": "iVBORw0KGgoAAAANSUhEUgAAAAQAAAAECAAAAACMmsGiAAAAEElEQVR42mP438BQz4BKAABTxAf5l+Fu2QAAAABJRU5ErkJggg==",
                 "period_m": 512, "amplitude_m": 40, "weight": 0.8, "blend_m": 500}]}]});
    Scene::from_value(&readme).expect("the README's basis op is accepted");
    let plan = WorldPlan::new(SEED, WorldParams::earth()).expect("plan");
    let e: Element = serde_json::from_value(readme["regions"][0].clone()).expect("element");
    let d = solve_region(&plan, &RegionSpec::from_element(&e).expect("spec")).expect("solved");
    assert!(
        d.d.iter().any(|v| v.abs() > 1.0),
        "the README's op displaces the ground"
    );
}
