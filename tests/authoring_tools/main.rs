//! The authoring tools through the library's public API: each tool's defining property checked
//! on a solved region (region `[1000, 2000]–[1128, 2128]` of seed 11's classic world, 1 m
//! spacing at 129 samples), and the parsing and validation of the operations.

mod fitting;
mod hill;
mod landforms;
mod spec;

use serde_json::json;
use strata::authoring::{solve_region, Displacement, RegionSpec};
use strata::element::Element;
use strata::terrain::{WorldParams, WorldPlan};

/// The world the regions edit: seed 11, classic settings.
pub fn plan() -> WorldPlan {
    WorldPlan::new(11, WorldParams::classic()).expect("plan")
}

/// The region `[1000, 2000]–[1128, 2128]` at `samples` per side with operations `ops`.
pub fn spec(samples: usize, ops: serde_json::Value) -> RegionSpec {
    let element: Element = serde_json::from_value(json!({
        "id": "r", "bbox": {"min": [1000, 2000], "max": [1128, 2128]},
        "samples": samples, "ops": ops}))
    .expect("element");
    RegionSpec::from_element(&element).expect("spec")
}

/// The solved height at sample `(i, j)`, metres.
pub fn height(r: &Displacement, i: usize, j: usize) -> f64 {
    let v = j * r.grid.n + i;
    f64::from(r.base[v]) + f64::from(r.d[v])
}

/// Nearest sample to a world position.
pub fn sample_at(r: &Displacement, x: f64, z: f64) -> (usize, usize) {
    let (u, v) = r.grid.grid_coords(x, z);
    (u.round() as usize, v.round() as usize)
}

/// The region at 129 samples with operations `ops`, solved.
pub fn solve(ops: serde_json::Value) -> Displacement {
    solve_region(&plan(), &spec(129, ops)).expect("solved")
}

/// The procedural height at a world position, rounded to a metre.
pub fn ground(x: f64, z: f64) -> f64 {
    let flat = solve(json!([]));
    let (i, j) = sample_at(&flat, x, z);
    height(&flat, i, j).round()
}
