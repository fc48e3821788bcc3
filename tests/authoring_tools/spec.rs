//! Parsing and validation of a region's operations: defaults, the droplet budget and the JSON
//! pointer of every refused field.

use serde_json::json;
use strata::authoring::spec::{SpecError, DEFAULT_SAMPLES};
use strata::authoring::spec_tools::{
    DROPLET_STEP_CELLS, MAX_ACCEPTED_SAMPLES, MAX_REGION_CELL_STEPS, SOLVE_CELL_STEPS,
};
use strata::authoring::tools::fitting::Regularize;
use strata::authoring::{Op, RegionSpec};
use strata::element::Element;

fn parse(region: serde_json::Value) -> Result<RegionSpec, SpecError> {
    let element: Element = serde_json::from_value(region).expect("an element");
    RegionSpec::from_element(&element)
}

#[test]
fn a_regions_droplet_steps_are_bounded_before_any_work() {
    // Issue 18, finding 4: 200,000 droplets × 512 steps took 21 s of CPU per tile request.
    let brush = |droplets: u64, steps: u64| {
        json!({"op": "hydraulic_erosion", "center": [50, 50], "radius_m": 20,
            "droplets": droplets, "steps": steps})
    };
    let region = |ops: Vec<serde_json::Value>| {
        parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "ops": ops}))
            .expect("a valid region")
    };
    // The default 257² grid: three solves (the final one and one before each brush).
    let cells = (DEFAULT_SAMPLES * DEFAULT_SAMPLES) as u64;
    let left = MAX_REGION_CELL_STEPS - 3 * SOLVE_CELL_STEPS * cells;
    let half = left / 2 / DROPLET_STEP_CELLS / 512;
    let at_limit = region(vec![brush(half, 512), brush(half, 512)]);
    assert!(at_limit.check_cost().is_ok());
    assert!(at_limit.cell_steps() <= MAX_REGION_CELL_STEPS);
    let e = region(vec![brush(200_000, 512)])
        .check_cost()
        .expect_err("the probe's brush");
    assert_eq!(e.pointer, "/ops/0/droplets");
    assert!(
        e.message.contains(&MAX_REGION_CELL_STEPS.to_string()),
        "{}",
        e.message
    );
    let e = region(vec![brush(half, 512), brush(half, 512), brush(1, 1)])
        .check_cost()
        .expect_err("the sum over brushes");
    assert_eq!(e.pointer, "/ops/2/droplets");
}

#[test]
fn a_regions_thermal_erosion_is_bounded_before_any_work() {
    // Thermal erosion sweeps the whole region grid every iteration: at the measured 10 ns a
    // cell step, 500 iterations at 2049² samples take about 20 s per brush, and a region may
    // hold 256 brushes.
    let brush = |iterations: u64| json!({"op": "erosion", "center": [50, 50], "radius_m": 20, "iterations": iterations});
    let region = |samples: u64, ops: Vec<serde_json::Value>| {
        parse(
            json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]},
            "samples": samples, "ops": ops}),
        )
        .expect("a valid region")
        .check_cost()
    };
    let cells = 1025 * 1025;
    let most = (MAX_REGION_CELL_STEPS - 3 * SOLVE_CELL_STEPS * cells) / cells;
    assert!(region(1025, vec![brush(most / 2), brush(most / 2)]).is_ok());
    let e = region(2049, vec![brush(500)]).expect_err("500 iterations at 2049²");
    assert_eq!(e.pointer, "/ops/0/iterations");
    assert!(
        e.message.contains(&MAX_REGION_CELL_STEPS.to_string()),
        "{}",
        e.message
    );
    let e = region(
        1025,
        vec![brush(most / 2), brush(most / 2), brush(most / 2)],
    )
    .expect_err("the sum over brushes");
    assert_eq!(e.pointer, "/ops/2/iterations");
    // The same brushes on a small grid cost little.
    assert!(region(129, vec![brush(500), brush(500)]).is_ok());
}

#[test]
fn every_solve_an_operation_forces_is_counted() {
    // Twenty small brushes at 1025² took 2.7 s of CPU before solves were counted: each brush
    // reads the heights solved before it, a reconstruction of the whole grid.
    let freeze = json!({"op": "freeze", "center": [50, 50], "radius_m": 5});
    let amplify = json!({"op": "amplify", "center": [50, 50], "radius_m": 20, "factor": 1.5});
    let region = |ops: Vec<serde_json::Value>| {
        parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "samples": 1025, "ops": ops}))
            .expect("a valid region")
    };
    let cells = 1025 * 1025;
    let solves = MAX_REGION_CELL_STEPS / (SOLVE_CELL_STEPS * cells);
    let pairs = |n: u64| {
        (0..n)
            .flat_map(|_| [amplify.clone(), freeze.clone()])
            .collect::<Vec<_>>()
    };
    // The final solve and one per freeze.
    assert!(region(pairs(solves - 1)).check_cost().is_ok());
    let e = region(pairs(solves))
        .check_cost()
        .expect_err("one solve too many");
    assert_eq!(e.pointer, format!("/ops/{}", 2 * solves - 1));
    // Operations that only rasterise cost no solve of their own.
    assert!(region(vec![amplify; 200]).check_cost().is_ok());
}

#[test]
fn the_largest_grid_loads_but_is_refused_when_accepted() {
    let region = |samples: usize| {
        parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "samples": samples, "ops": []}))
            .expect("every sample choice parses, so stored scenes keep loading")
    };
    assert!(region(MAX_ACCEPTED_SAMPLES).check_cost().is_ok());
    let e = region(2049).check_cost().expect_err("2049² when accepted");
    assert_eq!(e.pointer, "/samples");
    // Its solve alone crosses the work budget; an operation that adds no work is not blamed.
    let amplify = json!({"op": "amplify", "center": [50, 50], "radius_m": 20, "factor": 1.5});
    let e = parse(
        json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "samples": 2049,
        "ops": [amplify]}),
    )
    .expect("a valid region")
    .check_cost()
    .expect_err("2049² when accepted");
    assert_eq!(e.pointer, "/samples");
    assert!(
        e.message.contains(&MAX_ACCEPTED_SAMPLES.to_string()),
        "{}",
        e.message
    );
}

#[test]
fn the_new_tools_parse_with_defaults() {
    let r = parse(
        json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]},
        "ops": [{"op": "hydraulic_erosion", "center": [50, 50], "radius_m": 20, "droplets": 100},
                {"op": "regularize"},
                {"op": "contours", "lines": [{"points": [[1, 1], [9, 9]], "elevation_m": 3}]}]}),
    )
    .expect("valid");
    assert!(matches!(
        &r.ops[0],
        Op::HydraulicErosion(h) if h.steps == 64 && h.erosion_rate == 0.3 && h.seed == 0
    ));
    assert_eq!(r.ops[1], Op::Regularize(Regularize {}));
    assert!(matches!(&r.ops[2], Op::Contours(c) if c.detail == 0.0));
    // A copy-paste without a heightmap or seed serialises as before.
    let p = parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]},
        "ops": [{"op": "copy_paste", "source_min": [0, 0], "source_max": [9, 9], "target": [5, 5]}]}))
    .expect("valid");
    let text = serde_json::to_string(&p.ops[0]).expect("json");
    assert!(
        !text.contains("heightmap") && !text.contains("source_seed"),
        "{text}"
    );
}

#[test]
fn a_region_parses_with_defaults() {
    let r = parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 50]},
        "ops": [{"op": "elevation", "shape": {"point": [10, 10]}, "elevation_m": 5}]}))
    .expect("valid");
    assert_eq!(r.samples, DEFAULT_SAMPLES);
    assert_eq!(r.ops.len(), 1);
}

#[test]
fn bad_fields_are_named() {
    let base = |ops: serde_json::Value| json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "ops": ops});
    let cases = [
        (
            json!({"id": "a", "bbox": {"min": [0, 0], "max": [1, 1]}, "samples": 100}),
            "/samples",
        ),
        (
            base(json!([{"op": "amplify", "center": [0, 0], "radius_m": 5, "factor": 9}])),
            "/ops/0/factor",
        ),
        (
            base(json!([{"op": "freeze", "center": [0, 0], "radius_m": -1}])),
            "/ops/0/radius_m",
        ),
        (
            base(json!([{"op": "elevation", "shape": {"point": [0, 0]}}])),
            "/ops/0/elevation_m",
        ),
        (
            base(
                json!([{"op": "elevation", "shape": {"polyline": [[0, 0], [1, 1]]}, "elevations_m": [1]}]),
            ),
            "/ops/0/elevations_m",
        ),
        (
            base(
                json!([{"op": "crest", "points": [], "elevation_m": 1, "slope_deg": 10, "width_m": 5}]),
            ),
            "/ops/0/points",
        ),
        (
            base(
                json!([{"op": "cliff", "points": [[0, 0], [9, 0]], "top_elevation_m": 1, "slope_deg": 95, "width_m": 5}]),
            ),
            "/ops/0/slope_deg",
        ),
        (
            base(json!([{"op": "fault", "points": [[0, 0]], "throw_m": 3, "width_m": 5}])),
            "/ops/0/points",
        ),
        (
            base(
                json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5], "scale": 20}]),
            ),
            "/ops/0/scale",
        ),
        (
            base(
                json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 0], "target": [5, 5]}]),
            ),
            "/ops/0/source_max/1",
        ),
        (
            base(json!([{"op": "erosion", "center": [0, 0], "radius_m": 5, "iterations": 0}])),
            "/ops/0/iterations",
        ),
        (
            base(
                json!([{"op": "directional_tensor", "center": [0, 0], "radius_m": 5, "angle_deg": 0, "strength": 2}]),
            ),
            "/ops/0/strength",
        ),
        (
            base(
                json!([{"op": "river", "points": [[0, 0], [9, 0]], "bed_elevation_m": 1, "bank_slope_deg": 45, "bank_width_m": 5}]),
            ),
            "/ops/0/bank_slope_deg",
        ),
        (base(json!([{"op": "melt"}])), "/ops/0"),
        (
            base(
                json!([{"op": "hydraulic_erosion", "center": [0, 0], "radius_m": 5, "droplets": 0}]),
            ),
            "/ops/0/droplets",
        ),
        (
            base(
                json!([{"op": "hydraulic_erosion", "center": [0, 0], "radius_m": 5, "droplets": 9, "erosion_rate": 2}]),
            ),
            "/ops/0/erosion_rate",
        ),
        (
            base(json!([{"op": "contours", "lines": []}])),
            "/ops/0/lines",
        ),
        (
            base(json!([{"op": "contours", "lines": [{"points": [[0, 0]], "elevation_m": 1e9}]}])),
            "/ops/0/lines/0/elevation_m",
        ),
        (
            base(json!([{"op": "network",
                "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9], "elevation_m": 5}],
                "edges": [{"from": 0, "to": 1, "kind": "river"}]}])),
            "/ops/0/edges/0/to",
        ),
        (
            base(json!([{"op": "network",
                "nodes": [{"at": [0, 0], "elevation_m": 1}],
                "edges": [{"from": 0, "to": 3, "kind": "ridge"}]}])),
            "/ops/0/edges/0/to",
        ),
        (
            base(
                json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5],
                    "heightmap": {"png_base64": "not*base64", "lo_m": 0, "hi_m": 1, "spacing_m": 1}}]),
            ),
            "/ops/0/heightmap/png_base64",
        ),
        (
            base(
                json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5],
                    "source_seed": 4, "heightmap": {"png_base64": "", "lo_m": 0, "hi_m": 1, "spacing_m": 1}}]),
            ),
            "/ops/0/source_seed",
        ),
        (base(json!([{"op": "regularize", "x": 1}])), "/ops/0"),
        (
            base(json!([{"op": "network",
                "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9]}],
                "edges": [{"from": 0, "to": 1, "kind": "ridge"}]}])),
            "/ops/0/nodes/1/elevation_m",
        ),
        (
            base(json!([{"op": "network",
                "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9]}],
                "edges": [{"from": 0, "to": 1, "kind": "river", "grade_deg": 5}]}])),
            "/ops/0/edges/0/to",
        ),
        (
            json!({"id": "a", "bbox": {"min": [0, 0], "max": [0, 10]}}),
            "/bbox",
        ),
    ];
    for (region, pointer) in cases {
        let e = parse(region.clone()).expect_err("refused");
        assert!(
            e.pointer.starts_with(pointer),
            "{region}: got {e}, want {pointer}"
        );
    }
}
