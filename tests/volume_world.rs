//! Volume regions in the world (issue 5, "Volume chunks everywhere"): a `volumes` element with the
//! arch curves puts an arch into the volume chunks, the chunks beside the box are untouched bit
//! for bit (the region meets the heightfield without a gap), and the element is validated with
//! errors naming the field.

use serde_json::{json, Value};
use std::sync::Arc;
use strata::authoring::{solve_region, RegionSpec};
use strata::edits::{synthesize, TileEdits};
use strata::scene::{Element, Scene};
use strata::subsurface::carve::mesh_world_chunk;
use strata::terrain::{Tile, TileKey, WorldParams, WorldPlan};
use strata::volume::chunk::{tiles_needed, ChunkKey, ChunkMesh};
use strata::volume::element::{solve_volume, SolvedVolume, VolumeSpec};
use strata::volume::mesh::{QuadClass, QuadMesh};

mod common;

const SEED: u64 = 7;

fn plan() -> WorldPlan {
    WorldPlan::new(SEED, WorldParams::default()).expect("default world")
}

/// The default world without rivers: the origin tile is level enough that a box region's
/// heights hold its whole footprint (seed 7 cuts a river valley wall across it).
fn plan_without_rivers() -> WorldPlan {
    let mut params = WorldParams::default();
    if let Some(earth) = params.earth.as_mut() {
        earth.rivers = None;
    }
    WorldPlan::new(SEED, params).expect("default world without rivers")
}

fn tiles(plan: &WorldPlan, key: ChunkKey) -> Vec<(TileKey, Tile)> {
    tiles_needed(key)
        .into_iter()
        .map(|(x, z)| {
            let tk = TileKey { lod: key.lod, x, z };
            (tk, synthesize(plan, tk, &TileEdits::default()))
        })
        .collect()
}

fn chunk(plan: &WorldPlan, key: ChunkKey, volumes: &[Arc<SolvedVolume>]) -> ChunkMesh {
    let tiles = tiles(plan, key).into_iter().collect();
    let cols = common::columns::columns(key, &tiles);
    mesh_world_chunk(
        key,
        plan,
        &cols,
        volumes,
        &[],
        &mut QuadMesh::default(),
        &strata::volume::offload::CpuOnly,
    )
    .expect("mesh")
}

fn ground_at(plan: &WorldPlan, x: i64, z: i64) -> f32 {
    let t = synthesize(plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[(z * 65 + x) as usize]
}

fn element(v: Value) -> Element {
    serde_json::from_value(v).expect("element")
}

/// Sign changes of the solid along the vertical line through global column `(gx, gz)`: the
/// quads whose grid edge is vertical there.
fn crossings(meshes: &[ChunkMesh], gx: i64, gz: i64) -> usize {
    meshes
        .iter()
        .map(|m| {
            m.classes
                .iter()
                .zip(&m.global_edges)
                .filter(|(c, e)| {
                    matches!(c, QuadClass::PosY | QuadClass::NegY) && e[0] == gx && e[2] == gz
                })
                .count()
        })
        .sum()
}

#[test]
fn a_volume_element_puts_an_arch_into_the_chunks_and_leaves_the_rest() {
    let plan = plan();
    let ground = ground_at(&plan, 32, 24);
    let spec = VolumeSpec::from_element(&element(common::arch::arch_element(ground)))
        .expect("valid element");
    let solved = Arc::new(solve_volume(&plan, &spec, &TileEdits::default()).expect("solved"));
    let volumes = vec![solved];
    let ys = ((ground - 12.0) as i64).div_euclid(32)..=((ground + 36.0) as i64).div_euclid(32);
    let mut with = Vec::new();
    let mut without = Vec::new();
    for y in ys.clone() {
        let key = ChunkKey {
            lod: 0,
            x: 1,
            y,
            z: 0,
        };
        with.push(chunk(&plan, key, &volumes));
        without.push(chunk(&plan, key, &[]));
    }
    // Under the arch's crown (x = 32, z = 24): ground, intrados and extrados.
    let (n_with, n_without) = (crossings(&with, 32, 24), crossings(&without, 32, 24));
    eprintln!("crossings under the crown: {n_with} with the arch, {n_without} without");
    assert_eq!(n_without, 1, "the heightfield crosses once");
    assert!(n_with >= 3, "the arch adds its span: {n_with} crossings");
    // Beside the box (x < 0), the chunks are the heightfield's, bit for bit.
    for y in ys {
        let key = ChunkKey {
            lod: 0,
            x: -1,
            y,
            z: 0,
        };
        let (a, b) = (chunk(&plan, key, &volumes), chunk(&plan, key, &[]));
        assert_eq!(a.positions, b.positions);
        assert_eq!(a.normals, b.normals);
        assert_eq!(a.quads, b.quads);
    }
}

#[test]
fn volume_elements_are_validated_with_the_field_named() {
    let plan = plan();
    let good = common::arch::arch_element(ground_at(&plan, 32, 24));
    let scene = |v: Value| Scene::from_value(&json!({ "volumes": [v] }));
    scene(good.clone()).expect("the arch element is valid");
    let mut bad = good.clone();
    bad["y_m"] = json!([10, 5]);
    assert_eq!(scene(bad).expect_err("refused").pointer, "/volumes/0/y_m");
    let mut bad = good.clone();
    bad["curves"][2]["control_points"] = json!([[0, 0, 0]]);
    assert!(scene(bad)
        .expect_err("refused")
        .pointer
        .starts_with("/volumes/0/curves/2"));
    let mut bad = good;
    bad["spacing_m"] = json!(0.25);
    assert_eq!(
        scene(bad).expect_err("refused").pointer,
        "/volumes/0/spacing_m"
    );
}

#[test]
fn height_tiles_mark_the_vertices_a_volume_region_overrides() {
    let plan = plan_without_rivers();
    let ground = ground_at(&plan, 32, 24);
    let spec = Arc::new(
        VolumeSpec::from_element(&element(common::arch::arch_element(ground))).expect("valid"),
    );
    let edits = TileEdits {
        volumes: vec![spec.clone()],
        ..TileEdits::default()
    };
    let key = TileKey { lod: 0, x: 0, z: 0 };
    let tile = synthesize(&plan, key, &edits);
    let bare = synthesize(&plan, key, &TileEdits::default());
    assert!(bare.volume_override.is_empty(), "no region, no marks");
    assert_eq!(tile.heights, bare.heights, "marks change no height");
    let mut marked = 0;
    for (v, &m) in tile.volume_override.iter().enumerate() {
        let (x, z) = ((v % 65) as f64, (v / 65) as f64);
        let h = tile.heights[v];
        let inside = (0.0..=64.0).contains(&x)
            && (0.0..=48.0).contains(&z)
            && (spec.y_m[0]..=spec.y_m[1]).contains(&h);
        assert_eq!(m == 1, inside, "vertex ({x}, {z}) at {h} m");
        marked += usize::from(m);
    }
    assert_eq!(
        marked,
        65 * 49,
        "the box covers 65 × 49 vertices of this tile"
    );
    // The neighbour east shares the edge x = 64 and marks it the same.
    let east = synthesize(&plan, TileKey { lod: 0, x: 1, z: 0 }, &edits);
    for j in 0..65 {
        assert_eq!(
            tile.volume_override[j * 65 + 64],
            east.volume_override[j * 65]
        );
    }
    // The wire formats and the disk cache carry the marks.
    let json: Value =
        serde_json::from_slice(&strata::encode::json::encode(&plan, &tile)).expect("json");
    assert_eq!(
        json["volume_override"].as_array().map(Vec::len),
        Some(marked)
    );
    let bin = strata::encode::bin::encode(&plan, &tile);
    let at = |o: usize| u32::from_le_bytes(bin[o..o + 4].try_into().expect("u32")) as usize;
    let off = at(strata::encode::bin::offset::VOLUME_OVERRIDE);
    assert_eq!(&bin[off..off + 65 * 65], tile.volume_override.as_slice());
    assert_eq!(at(strata::encode::bin::offset::TOTAL_LEN), bin.len());
    let hash = [7u8; 32];
    let disk = strata::cache::decode_tile(&strata::cache::encode_tile(&hash, &tile), &hash)
        .expect("decoded");
    assert_eq!(disk, tile);
    let plain = strata::cache::decode_tile(&strata::cache::encode_tile(&hash, &bare), &hash)
        .expect("decoded");
    assert_eq!(plain, bare);
}

/// The height of the top of the solid in column `(x, z)` of a solved region (world metres): the
/// highest grid sample there whose filtered distance is negative.
fn top_of_solid(v: &SolvedVolume, x: f32, z: f32) -> f32 {
    let g = &v.fields.grid;
    let i = ((x - g.origin[0]) / g.spacing).round() as usize;
    let k = ((z - g.origin[2]) / g.spacing).round() as usize;
    (0..g.dims[1])
        .rev()
        .find(|&j| v.fields.surface[g.index(i, j, k)] < 0.0)
        .map(|j| g.origin[1] + j as f32 * g.spacing)
        .expect("solid in the column")
}

/// The ground a volume region's pipeline takes is the world's edited ground: an authored region
/// raising a point inside the box raises the region's solid there, as it raises the tiles.
#[test]
fn the_volume_ground_takes_the_authored_regions_over_the_box() {
    let plan = plan();
    let spec = VolumeSpec::from_element(&element(common::arch::arch_element(ground_at(
        &plan, 32, 24,
    ))))
    .expect("valid element");
    let (x, z) = (56.0f32, 8.0f32);
    let base = ground_at(&plan, 56, 8);
    let peak = base + 12.0;
    let scene = Scene::from_value(&json!({"regions": [{
        "id": "hill", "bbox": {"min": [32, -16], "max": [96, 48]}, "samples": 65,
        "ops": [{"op": "elevation", "shape": {"point": [x, z]}, "elevation_m": peak,
                 "radius_m": 4}]}]}))
    .expect("scene");
    let region = RegionSpec::from_element(&scene.regions[0]).expect("region");
    let hill = Arc::new(solve_region(&plan, &region).expect("solved region"));
    let edits = TileEdits {
        displacements: vec![hill],
        ..TileEdits::default()
    };
    let plain = solve_volume(&plan, &spec, &TileEdits::default()).expect("solved");
    let raised = solve_volume(&plan, &spec, &edits).expect("solved");
    let (before, after) = (top_of_solid(&plain, x, z), top_of_solid(&raised, x, z));
    eprintln!("top of the solid at ({x}, {z}): {before} m without the hill, {after} m with it (ground {base} m, peak {peak} m)");
    // One grid spacing (1 m) of sampling, plus the Gaussian filter's rounding of the peak.
    assert!((before - base).abs() <= 2.0, "{before} vs ground {base}");
    assert!((after - peak).abs() <= 2.0, "{after} vs peak {peak}");
}
