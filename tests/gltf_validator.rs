//! The glb tiles pass the Khronos glTF validator (npm `gltf-validator`) without errors.
//!
//! Validates tiles (LOD 0, 3 and 12, with and without seams, negative coordinates) and tiles with
//! river and lake water (the water primitive) with `common::gltf::validate`. Without Node.js the
//! test fails: it never skips.

use std::sync::Arc;
use strata::compute::Compute;
use strata::encode::{glb, water_glb};
use strata::terrain::{Tile, TileKey, WorldParams, WorldPlan};

mod common;

/// The vertices and triangles the validator should count in a tile's glb: the terrain's, plus
/// the water mesh's when the tile has one.
fn expected_counts(tile: &Tile) -> (usize, usize) {
    let water = water_glb::mesh(tile).map_or((0, 0), |w| (w.positions.len(), w.indices.len() / 3));
    (
        glb::VERTEX_COUNT + water.0,
        glb::SURFACE_TRIANGLES + glb::SKIRT_TRIANGLES + water.1,
    )
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn glb_tiles_pass_the_khronos_validator() {
    let plan = Arc::new(WorldPlan::new(20_240_611, WorldParams::default()).expect("default world"));
    let compute = Compute::cpu();
    let edge = plan.max_tile_coord(0);
    let cases: [(u32, i64, i64, [bool; 4]); 8] = [
        (0, 0, 0, [false; 4]),
        (0, -1, -2, [true; 4]),
        (0, 5, -7, [true, false, true, false]),
        (3, -2, 1, [false; 4]),
        (3, 2, -3, [false, true, false, true]),
        (3, -40, -40, [true; 4]),
        (12, -3, 3, [true; 4]),
        (0, edge, -edge, [true; 4]),
    ];
    let mut files = Vec::new();
    let mut counts = Vec::new();
    for (lod, x, z, seams) in cases {
        let tile = compute
            .tile(plan.clone(), TileKey { lod, x, z }, seams)
            .await;
        let bytes = glb::encode(&plan, &tile);
        let flags: String = seams.iter().map(|&s| if s { '1' } else { '0' }).collect();
        files.push((format!("tile_{lod}_{x}_{z}_seams{flags}.glb"), bytes));
        counts.push(expected_counts(&tile));
    }

    let reports = common::gltf::validate("glb", &files);
    let mut warnings = 0;
    for (r, (vertices, triangles)) in reports.iter().zip(counts) {
        assert_eq!(r["errors"], 0, "validator errors: {r}");
        assert_eq!(r["vertices"], vertices, "{r}");
        assert_eq!(r["triangles"], triangles, "{r}");
        warnings += r["warnings"].as_u64().unwrap_or(0);
    }
    if warnings > 0 {
        println!("{warnings} validator warnings (allowed), listed above");
    }
}

#[test]
fn glb_tiles_with_river_and_lake_water_pass_the_khronos_validator() {
    let plan = WorldPlan::new(42, WorldParams::default()).expect("default world");
    let lake = common::water::lake_tile(&plan, 4, 100, 10);
    let river = common::water::river_tile(&plan, 0, 10);
    let mut files = Vec::new();
    let mut counts = Vec::new();
    for (name, tile) in [("lake", &lake), ("river", &river)] {
        let water = water_glb::mesh(tile).expect("a tile with water has a water mesh");
        assert!(!water.indices.is_empty());
        let bytes = glb::encode(&plan, tile);
        let k = tile.key;
        files.push((format!("water_{name}_{}_{}_{}.glb", k.lod, k.x, k.z), bytes));
        counts.push(expected_counts(tile));
    }
    let reports = common::gltf::validate("glb-water", &files);
    for (r, (vertices, triangles)) in reports.iter().zip(counts) {
        assert_eq!(r["errors"], 0, "validator errors: {r}");
        assert_eq!(r["vertices"], vertices, "{r}");
        assert_eq!(r["triangles"], triangles, "{r}");
    }
}
