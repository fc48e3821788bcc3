//! The coarse sketch (issue 17 item 9, done-when 7 first half): a region's `sketch` operation
//! shapes the world through the tile path (`solve_region`, then `edits::synthesize`), tiles
//! outside it are untouched and tiles meet bit for bit across its edge; a bad sketch is refused
//! naming the field; the server's own tile path serves the sketched world.

mod common;

use base64::Engine;
use serde_json::{json, Value};
use std::sync::Arc;
use strata::authoring::exchange::encode_png16;
use strata::authoring::{solve_region, RegionSpec};
use strata::compute::Compute;
use strata::edits::{synthesize, TileEdits};
use strata::element::Element;
use strata::scene::{Scene, SceneInputs};
use strata::server::AppState;
use strata::terrain::plan::TILE_VERTS;
use strata::terrain::{Tile, TileKey, WorldParams, WorldPlan};

const SEED: u64 = 17;
/// Pixels a side of the sketch.
const PX: usize = 64;
/// The sketch's bbox, ±`HALF` metres about the origin (not tile-aligned: tiles straddle edges).
const HALF: f64 = 16_000.0;
const BLEND_M: f64 = 2_000.0;
/// LOD of the tiles: 64 m vertices, 4 096 m tiles.
const LOD: u32 = 6;

/// A sketch with a ridge, a sea basin and a plateau, metres, row-major `PX × PX`.
fn sketch_heights() -> Vec<f32> {
    let mut h = Vec::with_capacity(PX * PX);
    for j in 0..PX {
        for i in 0..PX {
            let (u, v) = (i as f64 / (PX - 1) as f64, j as f64 / (PX - 1) as f64);
            // A ridge along the diagonal, 2.4 km high.
            let d_ridge = (u - v) / std::f64::consts::SQRT_2;
            let ridge = 2400.0 * (-(d_ridge / 0.08).powi(2)).exp();
            // A sea basin in the south-west, down to about −1.9 km.
            let d_sea = ((u - 0.25).powi(2) + (v - 0.75).powi(2)).sqrt();
            let sea = -2200.0 * (-(d_sea / 0.15).powi(2)).exp();
            // A plateau in the north-east.
            let plateau = 700.0 / (1.0 + (-(u + (1.0 - v) - 1.4) / 0.05).exp());
            h.push((300.0 + ridge + sea + plateau) as f32);
        }
    }
    h
}

fn sketch_op(h: &[f32]) -> Value {
    let png = encode_png16(PX, PX, h).expect("png");
    json!({"op": "sketch",
           "png_base64": base64::engine::general_purpose::STANDARD.encode(&png.bytes),
           "min_m": png.lo_m, "max_m": png.hi_m, "blend_m": BLEND_M})
}

fn region(op: Value) -> Value {
    json!({"id": "sketch", "bbox": {"min": [-HALF, -HALF], "max": [HALF, HALF]},
           "samples": 129, "ops": [op]})
}

fn spec(op: Value) -> RegionSpec {
    let e: Element = serde_json::from_value(region(op)).expect("element");
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

/// Block averages of the tiles' heights over each sketch pixel (the vertices nearest its
/// centre), and the sketch, for the pixels the taper leaves at full weight.
fn low_pass(tiles: &[Tile], sketch: &[f32]) -> (Vec<f64>, Vec<f64>) {
    let pixel = 2.0 * HALF / (PX - 1) as f64;
    let (mut sum, mut count) = (vec![0.0f64; PX * PX], vec![0usize; PX * PX]);
    for t in tiles {
        let s = f64::from(t.spacing_m);
        for (v, h) in t.heights.iter().enumerate() {
            let x = t.origin_x_m() + (v % TILE_VERTS) as f64 * s;
            let z = t.origin_z_m() + (v / TILE_VERTS) as f64 * s;
            let (i, j) = (((x + HALF) / pixel).round(), ((z + HALF) / pixel).round());
            if (0.0..PX as f64).contains(&i) && (0.0..PX as f64).contains(&j) {
                let p = j as usize * PX + i as usize;
                sum[p] += f64::from(*h);
                count[p] += 1;
            }
        }
    }
    let margin = (BLEND_M / pixel).ceil() as usize;
    let (mut got, mut want) = (Vec::new(), Vec::new());
    for j in margin..PX - margin {
        for i in margin..PX - margin {
            let p = j * PX + i;
            assert!(count[p] > 0, "pixel ({i}, {j}) has no vertex");
            got.push(sum[p] / count[p] as f64);
            want.push(f64::from(sketch[p]));
        }
    }
    (got, want)
}

/// Block means of the tiles' heights over every sketch pixel (the vertices nearest its centre).
fn block_means(tiles: &[Tile]) -> Vec<f64> {
    let pixel = 2.0 * HALF / (PX - 1) as f64;
    let (mut sum, mut count) = (vec![0.0f64; PX * PX], vec![0usize; PX * PX]);
    for t in tiles {
        let s = f64::from(t.spacing_m);
        for (v, h) in t.heights.iter().enumerate() {
            let x = t.origin_x_m() + (v % TILE_VERTS) as f64 * s;
            let z = t.origin_z_m() + (v / TILE_VERTS) as f64 * s;
            let (i, j) = (((x + HALF) / pixel).round(), ((z + HALF) / pixel).round());
            if (0.0..PX as f64).contains(&i) && (0.0..PX as f64).contains(&j) {
                let p = j as usize * PX + i as usize;
                sum[p] += f64::from(*h);
                count[p] += 1;
            }
        }
    }
    sum.iter().zip(&count).map(|(s, c)| s / *c as f64).collect()
}

/// RMS of the tiles' heights about `large` (pixel-centre values, bilinear between them) over
/// the full-weight pixels: the detail on top of the large shape.
fn detail_rms(tiles: &[Tile], large: &[f64]) -> f64 {
    let pixel = 2.0 * HALF / (PX - 1) as f64;
    let lo = BLEND_M + pixel;
    let (mut sq, mut n) = (0.0, 0usize);
    for t in tiles {
        let s = f64::from(t.spacing_m);
        for (v, h) in t.heights.iter().enumerate() {
            let x = t.origin_x_m() + (v % TILE_VERTS) as f64 * s;
            let z = t.origin_z_m() + (v / TILE_VERTS) as f64 * s;
            if x.abs() > HALF - lo || z.abs() > HALF - lo {
                continue;
            }
            let (u, w) = ((x + HALF) / pixel, (z + HALF) / pixel);
            let (i, j) = (u.floor() as usize, w.floor() as usize);
            let (fu, fw) = (u - i as f64, w - j as f64);
            let at = |i: usize, j: usize| large[j * PX + i];
            let top = at(i, j) * (1.0 - fu) + at(i + 1, j) * fu;
            let bottom = at(i, j + 1) * (1.0 - fu) + at(i + 1, j + 1) * fu;
            sq += (f64::from(*h) - (top * (1.0 - fw) + bottom * fw)).powi(2);
            n += 1;
        }
    }
    (sq / n as f64).sqrt()
}

/// RMS of the tiles' discrete Laplacian at the vertices over the full-weight pixels: the
/// finest detail (relief, gullies, the erosion filter's channels).
fn laplacian_rms(tiles: &[Tile]) -> f64 {
    let lo = BLEND_M + 2.0 * HALF / (PX - 1) as f64;
    let (mut sq, mut n) = (0.0, 0usize);
    for t in tiles {
        let s = f64::from(t.spacing_m);
        for j in 1..TILE_VERTS - 1 {
            for i in 1..TILE_VERTS - 1 {
                let x = t.origin_x_m() + i as f64 * s;
                let z = t.origin_z_m() + j as f64 * s;
                if x.abs() > HALF - lo || z.abs() > HALF - lo {
                    continue;
                }
                let v = j * TILE_VERTS + i;
                let h = |v: usize| f64::from(t.heights[v]);
                let lap = h(v - 1) + h(v + 1) + h(v - TILE_VERTS) + h(v + TILE_VERTS) - 4.0 * h(v);
                sq += lap * lap;
                n += 1;
            }
        }
    }
    (sq / n as f64).sqrt()
}

#[test]
fn the_low_pass_of_the_tiles_follows_the_sketch_and_tiles_meet_across_its_edge() {
    let plan = WorldPlan::new(SEED, WorldParams::earth()).expect("plan");
    let h = sketch_heights();
    let d = solve_region(&plan, &spec(sketch_op(&h))).expect("solved");
    let edits = TileEdits {
        displacements: vec![Arc::new(d)],
        ..TileEdits::default()
    };
    // 8 × 8 tiles of 4 096 m cover the bbox; the outer ring straddles its edge.
    let range = -4..4i64;
    let mut tiles = Vec::new();
    let mut plain = Vec::new();
    for z in range.clone() {
        for x in range.clone() {
            tiles.push(synthesize(&plan, key(x, z), &edits));
            plain.push(synthesize(&plan, key(x, z), &TileEdits::default()));
        }
    }
    let (got, want) = low_pass(&tiles, &h);
    let r = pearson(&got, &want);
    let (before, _) = low_pass(&plain, &h);
    let r0 = pearson(&before, &want);
    println!(
        "low-pass vs sketch at {PX}×{PX} px ({} pixels): Pearson r = {r:.4} (unsketched world: {r0:.4})",
        got.len()
    );
    assert!(r >= 0.95, "correlation {r:.4} < 0.95");
    // The detail stays. At the vertices (64 m) the relief is the world's: the displacement is
    // smooth there.
    let (with, without) = (laplacian_rms(&tiles), laplacian_rms(&plain));
    println!("vertex Laplacian RMS: {with:.2} m sketched, {without:.2} m unsketched");
    assert!(
        (0.9..1.1).contains(&(with / without)),
        "Laplacian RMS {with:.2} m against the world's {without:.2} m"
    );
    // About the large shape (the sketch; the world's own block means), the relief between the
    // vertex and the pixel scale: the sketch replaces the world's box mean at the pixel scale,
    // so relief at wavelengths near a pixel (about 0.5 km) goes with the large shape.
    let sketch: Vec<f64> = h.iter().map(|v| f64::from(*v)).collect();
    let (with, without) = (
        detail_rms(&tiles, &sketch),
        detail_rms(&plain, &block_means(&plain)),
    );
    println!("relief about the large shape: RMS {with:.1} m sketched, {without:.1} m unsketched");
    assert!(
        (0.5..1.5).contains(&(with / without)),
        "relief RMS {with:.1} m against the world's {without:.1} m"
    );
    // Neighbouring tiles share their edge vertices bit for bit, across the bbox edge too.
    let n = range.clone().count();
    let last = TILE_VERTS - 1;
    common::seams::assert_grid_seams(&tiles, n);
    // Outside the bbox the tiles are the world's, bit for bit, and so is the straddling
    // tiles' edge shared with them.
    for (x, z) in [(4, 0), (-5, 0), (0, 4), (0, -5), (4, 4)] {
        let a = synthesize(&plan, key(x, z), &edits);
        let b = synthesize(&plan, key(x, z), &TileEdits::default());
        assert_eq!(a.heights, b.heights, "tile ({x}, {z}) outside the sketch");
        assert_eq!(a.normals, b.normals, "tile ({x}, {z}) normals");
    }
    let east = synthesize(&plan, key(4, 0), &edits);
    let inner = &tiles[4 * n + (n - 1)];
    for j in 0..TILE_VERTS {
        assert_eq!(
            inner.heights[j * TILE_VERTS + last].to_bits(),
            east.heights[j * TILE_VERTS].to_bits()
        );
    }
}

#[test]
fn a_bad_sketch_is_refused_naming_the_field() {
    let h = sketch_heights();
    let good = sketch_op(&h);
    let scene = |op: Value| json!({"regions": [region(op)]});
    Scene::from_value(&scene(good.clone())).expect("a good sketch is accepted");

    let refused = |v: Value| Scene::from_value(&v).expect_err("refused");
    let mut bad = good.clone();
    bad["png_base64"] = json!("not*base64");
    let e = refused(scene(bad));
    assert_eq!(e.pointer, "/regions/0/ops/0/png_base64", "{e}");

    let wide = encode_png16(1026, 2, &vec![0.0; 1026 * 2]).expect("png");
    let mut bad = good.clone();
    bad["png_base64"] = json!(base64::engine::general_purpose::STANDARD.encode(&wide.bytes));
    let e = refused(scene(bad));
    assert_eq!(e.pointer, "/regions/0/ops/0/png_base64", "{e}");
    assert!(e.message.contains("1025"), "{e}");

    let tiny = encode_png16(1, 4, &[0.0; 4]).expect("png");
    let mut bad = good.clone();
    bad["png_base64"] = json!(base64::engine::general_purpose::STANDARD.encode(&tiny.bytes));
    assert_eq!(refused(scene(bad)).pointer, "/regions/0/ops/0/png_base64");

    let mut bad = good.clone();
    bad["max_m"] = json!(-3000.0);
    assert_eq!(refused(scene(bad)).pointer, "/regions/0/ops/0/max_m");
    let mut bad = good.clone();
    bad["blend_m"] = json!(-1.0);
    assert_eq!(refused(scene(bad)).pointer, "/regions/0/ops/0/blend_m");

    let mut huge = scene(good.clone());
    huge["regions"][0]["bbox"]["max"][0] = json!(300_000.0);
    assert_eq!(refused(huge).pointer, "/regions/0/bbox/max/0");

    // The README's example.
    let readme = json!({"regions": [{"id": "continent",
        "bbox": {"min": [-16000, -16000], "max": [16000, 16000]}, "samples": 257,
        "ops": [{"op": "sketch", "png_base64": "iVBORw0KGgoAAAANSUhEUgAAAAQAAAAEEAAAAADcCh3hAAAALElEQVR42mNgYPBTOK3w/z8DA0PsgVcJpxUY5B1KDU4rzHEASpQa9CwoNQAA3DMMWSByqQoAAAAASUVORK5CYII=",
                 "min_m": -2000, "max_m": 3000, "blend_m": 2000}]}]});
    Scene::from_value(&readme).expect("the README's sketch is accepted");

    // A classic world takes a sketch too: its low-pass is the world's own.
    let mut classic = scene(good.clone());
    classic["world"] = serde_json::to_value(WorldParams::classic()).expect("classic");
    Scene::from_value(&classic).expect("a classic world's sketch is accepted");
    let plan = WorldPlan::new(SEED, WorldParams::classic()).expect("plan");
    solve_region(&plan, &spec(good)).expect("solved on a classic world");
}

#[tokio::test]
async fn the_server_path_serves_the_sketched_world() {
    // The same sketch as a scene's region, through the server's own tile path (region cache,
    // stage cache, compute): the low-pass follows the sketch there too.
    let h = sketch_heights();
    let scene = Scene::from_value(&json!({"regions": [region(sketch_op(&h))]})).expect("scene");
    let state = AppState::new(Compute::cpu());
    let plan = Arc::new(WorldPlan::new(SEED, scene.world.clone()).expect("plan"));
    let inputs = Arc::new(SceneInputs::new(&scene));
    let view = strata::server::view::WorldView::stored("sketch", 1, plan, inputs);
    let mut tiles = Vec::new();
    for z in -4..4 {
        for x in -4..4 {
            let t = state.tile(&view, key(x, z), [false; 4]).await;
            tiles.push(Tile::clone(&t));
        }
    }
    let (got, want) = low_pass(&tiles, &h);
    let r = pearson(&got, &want);
    println!("server tiles: Pearson r = {r:.4}");
    assert!(r >= 0.95, "correlation {r:.4} < 0.95");
}
