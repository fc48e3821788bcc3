//! Authored regions in the world's tiles (issue 4, Done-when 3): tiles that meet a region serve
//! its reconstructed heights, neighbouring tiles still share edges bit for bit across and inside
//! the region, and the region's edge meets the procedural world with no step. Tiles come through
//! the server's own path (`AppState::tile`: region cache, stage cache, compute).

use serde_json::json;
use std::sync::Arc;
use strata::compute::Compute;
use strata::scene::{Scene, SceneInputs};
use strata::server::view::WorldView;
use strata::server::AppState;
use strata::terrain::{Tile, TileKey, WorldPlan, TILE_VERTS};

const SEED: u64 = 5;
/// The constrained point and its elevation.
const PEAK: [f64; 2] = [100.0, 100.0];
const PEAK_M: f64 = 420.0;

fn scene() -> Scene {
    Scene::from_value(&json!({"regions": [{
        "id": "hill", "bbox": {"min": [40, 40], "max": [200, 168]}, "samples": 65,
        "ops": [
            {"op": "elevation", "shape": {"point": PEAK}, "elevation_m": PEAK_M, "radius_m": 2},
            {"op": "crest", "points": [[60, 140], [190, 140]], "elevation_m": 200, "slope_deg": 25, "width_m": 12}
        ]}]}))
    .expect("valid scene")
}

struct World {
    state: AppState,
    plan: Arc<WorldPlan>,
    edited: Arc<SceneInputs>,
    bare: Arc<SceneInputs>,
}

impl World {
    fn new() -> Self {
        let scene = scene();
        Self {
            state: AppState::new(Compute::cpu()),
            plan: Arc::new(WorldPlan::new(SEED, scene.world.clone()).expect("plan")),
            edited: Arc::new(SceneInputs::new(&scene)),
            bare: Arc::new(SceneInputs::bare(&scene.world)),
        }
    }

    async fn tile(&self, edited: bool, lod: u32, x: i64, z: i64) -> Arc<Tile> {
        let inputs = if edited { &self.edited } else { &self.bare };
        let view = WorldView::stored("authoring", 1, self.plan.clone(), inputs.clone());
        self.state
            .tile(&view, TileKey { lod, x, z }, [false; 4])
            .await
    }
}

fn at(i: usize, j: usize) -> usize {
    j * TILE_VERTS + i
}

#[tokio::test]
async fn tiles_across_a_region_share_edges_bit_for_bit() {
    let w = World::new();
    let mut compared = 0;
    for lod in 0..=2u32 {
        let size = 64.0 * f64::from(1u32 << lod);
        let span = (0..=(200.0 / size) as i64 + 1).collect::<Vec<_>>();
        for &z in &span {
            for &x in &span {
                let t = w.tile(true, lod, x, z).await;
                let east = w.tile(true, lod, x + 1, z).await;
                let south = w.tile(true, lod, x, z + 1).await;
                for k in 0..TILE_VERTS {
                    let pairs = [
                        (at(TILE_VERTS - 1, k), at(0, k), &east),
                        (at(k, TILE_VERTS - 1), at(k, 0), &south),
                    ];
                    for (a, b, other) in pairs {
                        assert_eq!(
                            t.heights[a].to_bits(),
                            other.heights[b].to_bits(),
                            "lod {lod} tile ({x}, {z})"
                        );
                        for c in 0..3 {
                            assert_eq!(t.normals[a][c].to_bits(), other.normals[b][c].to_bits());
                        }
                        compared += 1;
                    }
                }
            }
        }
    }
    assert!(compared > 1000);
}

#[tokio::test]
async fn the_region_shows_in_tiles_and_meets_the_world_without_a_step() {
    let w = World::new();
    // Tiles (0..=3, 0..=2) at LOD 0 cover the region and its surroundings.
    let mut max_inside_change = 0.0f32;
    for z in 0..=2 {
        for x in 0..=3 {
            let edited = w.tile(true, 0, x, z).await;
            let bare = w.tile(false, 0, x, z).await;
            for j in 0..TILE_VERTS {
                for i in 0..TILE_VERTS {
                    let v = at(i, j);
                    let (wx, wz) = ((x * 64) as f64 + i as f64, (z * 64) as f64 + j as f64);
                    let inside = (40.0..=200.0).contains(&wx) && (40.0..=168.0).contains(&wz);
                    let (a, b) = (edited.heights[v], bare.heights[v]);
                    if !inside {
                        assert_eq!(
                            a.to_bits(),
                            b.to_bits(),
                            "outside the region at ({wx}, {wz})"
                        );
                    } else {
                        max_inside_change = max_inside_change.max((a - b).abs());
                    }
                    // On the bbox's edge the displacement is zero: no step against the world.
                    let on_edge =
                        inside && (wx == 40.0 || wx == 200.0 || wz == 40.0 || wz == 168.0);
                    if on_edge {
                        assert_eq!(
                            a.to_bits(),
                            b.to_bits(),
                            "edge of the region at ({wx}, {wz})"
                        );
                    }
                    // One metre inside, the change is small (continuity), not a cliff.
                    let near_edge = inside && (wx == 41.0 || wz == 41.0);
                    if near_edge {
                        assert!((a - b).abs() < 25.0, "step of {} m at ({wx}, {wz})", a - b);
                    }
                }
            }
        }
    }
    assert!(
        max_inside_change > 100.0,
        "the region's edit shows: {max_inside_change} m"
    );
    // The constrained point: its LOD-0 vertex stands at the imposed elevation (the region's
    // grid sample is that vertex; the procedural heights it was measured against are LOD 0's).
    let t = w.tile(true, 0, 1, 1).await;
    let h = t.heights[at(100 - 64, 100 - 64)];
    assert!(
        (f64::from(h) - PEAK_M).abs() < 0.05,
        "peak at {h} m, imposed {PEAK_M} m"
    );
}
