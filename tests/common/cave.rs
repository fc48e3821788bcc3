//! A `strata` element holding exactly one cave that opens to the ground near the origin, for
//! the stream and viewer tests of cave chunks (issue 19).

use std::sync::Arc;
use strata::subsurface::world::{carved_at, memos};
use strata::subsurface::{ElementKind, Geology, StrataSpec, SubsurfaceConfig};

/// Voxel side of the element, metres: caves of the configuration are 24 to 48 m across.
pub const VOXEL_M: f64 = 2.0;

/// The cave: its element and where it is.
pub struct Cave {
    /// The `strata` element (JSON), its bbox the cave's bounding square grown by a voxel, so
    /// the element holds this cave and no other.
    pub element: serde_json::Value,
    /// West-north corner of the cave's bounding square, metres.
    pub min: [f64; 2],
    /// East-south corner, metres.
    pub max: [f64; 2],
    /// Columns (metres, on the LOD-0 lattice) where the cave breaches the ground, row by row.
    pub breached: Vec<(i64, i64)>,
    /// The element bound to the seed.
    pub geology: Arc<Geology>,
}

/// B2 (one cave material) with a cave in every lattice cell, taller than the preset's so some
/// reach the ground.
pub fn config() -> SubsurfaceConfig {
    let mut c = SubsurfaceConfig::preset("B2").expect("B2");
    c.general.cave_density = 1.0;
    c.general.cave_thickness = 14.0;
    c
}

fn spec(min: [f64; 2], max: [f64; 2], config: &SubsurfaceConfig) -> StrataSpec {
    StrataSpec {
        id: "cave".into(),
        min,
        max,
        config: config.clone(),
        voxel_m: VOXEL_M,
        carve: true,
        mark_openings: true,
    }
}

/// The cave of world seed `seed` near the origin that breaches the ground over the most LOD-0
/// columns.
pub fn cave(seed: u64) -> Cave {
    let config = config();
    let wide = Arc::new(Geology::new(
        seed,
        spec([-4000.0, -4000.0], [4000.0, 4000.0], &config),
    ));
    let mut best: Option<Cave> = None;
    for cz in -3..3 {
        for cx in -3..3 {
            let Some(e) = wide.plan.element(ElementKind::Cave, (cx, cz)) else {
                continue;
            };
            let min = [
                f64::from(e.origin.0) * VOXEL_M,
                f64::from(e.origin.1) * VOXEL_M,
            ];
            let max = [
                f64::from(e.origin.0 + e.side) * VOXEL_M,
                f64::from(e.origin.1 + e.side) * VOXEL_M,
            ];
            let lo = [(min[0] - VOXEL_M).floor(), (min[1] - VOXEL_M).floor()];
            let hi = [(max[0] + VOXEL_M).ceil(), (max[1] + VOXEL_M).ceil()];
            let geology = Arc::new(Geology::new(seed, spec(lo, hi, &config)));
            let geos = vec![geology.clone()];
            let mut m = memos(&geos);
            let mut breached = Vec::new();
            for z in lo[1] as i64..=hi[1] as i64 {
                for x in lo[0] as i64..=hi[0] as i64 {
                    if carved_at(&geos, &mut m, x as f64, z as f64).is_some_and(|(_, b)| b > 0.0) {
                        breached.push((x, z));
                    }
                }
            }
            if best
                .as_ref()
                .is_some_and(|b| b.breached.len() >= breached.len())
            {
                continue;
            }
            let element = serde_json::json!({
                "id": "cave",
                "bbox": {"min": lo, "max": hi},
                "config": serde_json::to_value(&config).expect("config JSON"),
                "voxel_m": VOXEL_M,
                "carve": true,
                "mark_openings": true,
            });
            best = Some(Cave {
                element,
                min,
                max,
                breached,
                geology,
            });
        }
    }
    let cave = best.expect("a cave near the origin");
    assert!(
        cave.breached.len() > 20,
        "the cave breaches the ground over {} columns",
        cave.breached.len()
    );
    cave
}
