//! Solving a region: rasterise its operations, reconstruct the displacement, and apply it to
//! lattice heights.

use super::basis::{self, BasisOp};
use super::grid::{Procedural, RegionGrid};
use super::hydraulic::{droplet_seed, Droplets};
use super::paste::{PasteSource, Placement, Warp};
use super::raster::Canvas;
use super::sketch::decode;
use super::spec::{Op, RegionSpec, Shape};
use super::spec_tools::resolve_elevations;
use super::tensor::orientation;
use crate::terrain::lattice::Window;
use crate::terrain::poisson::{GridSpec, PoissonError, Problem, SolveOptions, Solver, Start};
use crate::terrain::WorldPlan;

/// Why a region could not be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RegionError {
    /// The solver refused the problem.
    #[error("region solver: {0}")]
    Solver(#[from] PoissonError),
    /// An operation's input could not be used (a copy-paste source unreadable, a network node
    /// without an elevation): the operation index and the reason.
    #[error("/ops/{op}: {message}")]
    Source {
        /// Index of the operation.
        op: usize,
        /// Why.
        message: String,
    },
}

/// A solved region: the displacement `d` to add to procedural heights (see [`super`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Displacement {
    /// Element id.
    pub id: String,
    /// The grid.
    pub grid: RegionGrid,
    /// `d` at the samples, metres, row-major `n × n` (0 on the border and outside the bbox).
    pub d: Vec<f32>,
    /// Procedural heights at the samples, metres.
    pub base: Vec<f32>,
    /// Which samples were fixed by hard constraints or lie outside the bbox.
    pub fixed: Vec<bool>,
    /// Finest-level cycles of the last solve.
    pub cycles: usize,
}

impl Displacement {
    /// Bilinear `d` at a world position, metres; 0 outside the grid.
    pub fn at(&self, x: f64, z: f64) -> f32 {
        let g = &self.grid;
        if x < g.origin[0] || z < g.origin[1] || x > g.max[0] || z > g.max[1] {
            return 0.0;
        }
        let (u, v) = g.grid_coords(x, z);
        let last = (g.n - 1) as f64;
        if u >= last || v >= last {
            return 0.0;
        }
        let (iu, iv) = (u.floor(), v.floor());
        let (fu, fv) = (u - iu, v - iv);
        let (i, j) = (iu as usize, iv as usize);
        let s = |i: usize, j: usize| f64::from(self.d[j * g.n + i]);
        crate::terrain::lattice::lerp2(s(i, j), s(i + 1, j), s(i, j + 1), s(i + 1, j + 1), fu, fv)
            as f32
    }

    /// Adds `d` to the heights of a lattice `window` (row-major).
    pub fn add_to_lattice(&self, window: Window, heights: &mut [f32]) {
        window.visit_mut(heights, |x, z, h| {
            let d = self.at(x, z);
            if d != 0.0 {
                *h += d;
            }
        });
    }
}

/// Solves a region of the world `plan`: samples the procedural heights, rasterises the
/// operations in order (a freeze brush solves what precedes it first) and reconstructs `d`.
///
/// # Errors
/// [`RegionError`] if the solver refuses the problem.
pub fn solve_region(plan: &WorldPlan, spec: &RegionSpec) -> Result<Displacement, RegionError> {
    let grid = RegionGrid::of(spec);
    let base = Procedural::sample(plan, &grid).heights;
    let mut canvas = Canvas::new(grid, base);
    let gspec = GridSpec::new(grid.n, grid.n, grid.spacing_m)?;
    let mut solver = Solver::new(gspec, SolveOptions::default())?;
    let mut current = vec![0.0f32; grid.n * grid.n];
    let mut solved = true;
    let mut cycles = 0;
    let mut solve =
        |c: &Canvas, current: &mut Vec<f32>, cold: bool| -> Result<usize, RegionError> {
            let problem = Problem {
                grid: gspec,
                gx: &c.gx,
                gz: &c.gz,
                fixed: &c.fixed,
                heights: &c.d,
            };
            let report = solver.solve(&problem, if cold { Start::Cold } else { Start::Warm })?;
            solver.heights_into(current)?;
            Ok(report.cycles)
        };
    let mut first = true;
    let mut basis_total: Option<Vec<f64>> = None;
    for (index, op) in spec.ops.iter().enumerate() {
        match op {
            Op::Elevation {
                shape,
                elevation_m,
                elevations_m,
                radius_m,
            } => {
                let es = match (elevation_m, elevations_m) {
                    (_, Some(es)) => es.clone(),
                    (Some(e), None) => vec![*e],
                    (None, None) => vec![0.0],
                };
                match shape {
                    Shape::Point(p) => canvas.elevation(&[*p], &es, *radius_m),
                    Shape::Polyline(pts) => canvas.elevation(pts, &es, *radius_m),
                    Shape::Region(poly) => canvas.elevation_region(poly, es[0], *radius_m),
                }
            }
            Op::Freeze { center, radius_m } => {
                if !solved {
                    cycles = solve(&canvas, &mut current, first)?;
                    first = false;
                }
                canvas.freeze(*center, *radius_m, &current);
            }
            Op::Amplify {
                center,
                radius_m,
                factor,
            } => canvas.amplify(*center, *radius_m, *factor),
            Op::Crest {
                points,
                elevation_m,
                slope_deg,
                width_m,
            } => canvas.crest(points, *elevation_m, *slope_deg, *width_m),
            Op::Noise {
                center,
                radius_m,
                amplitude_m,
                wavelength_m,
                seed,
                anisotropy,
                angle_deg,
            } => {
                let m = orientation(angle_deg.to_radians());
                let k = *anisotropy;
                canvas.noise(
                    plan.seed,
                    *center,
                    *radius_m,
                    *amplitude_m,
                    *wavelength_m,
                    *seed,
                    [[k * m[0][0], k * m[0][1]], [k * m[1][0], k * m[1][1]]],
                )
            }
            Op::SlopePoint {
                center,
                radius_m,
                slope_deg,
                direction_deg,
            } => canvas.slope_point(*center, *radius_m, *slope_deg, *direction_deg),
            Op::SlopeCurve {
                points,
                slope_left_deg,
                slope_right_deg,
                width_m,
            } => canvas.slope_curve(points, *slope_left_deg, *slope_right_deg, *width_m),
            Op::Cliff {
                points,
                top_elevation_m,
                slope_deg,
                width_m,
            } => canvas.cliff(points, *top_elevation_m, *slope_deg, *width_m),
            Op::River {
                points,
                bed_elevation_m,
                bed_width_m,
                bank_slope_deg,
                bank_width_m,
            } => canvas.river(
                points,
                *bed_elevation_m,
                *bed_width_m,
                *bank_slope_deg,
                *bank_width_m,
            ),
            Op::FreeCrest {
                points,
                slope_deg,
                width_m,
            } => canvas.free_crest(points, 1.0, *slope_deg, *width_m),
            Op::Ravine {
                points,
                slope_deg,
                width_m,
            } => canvas.free_crest(points, -1.0, *slope_deg, *width_m),
            Op::Fault {
                points,
                throw_m,
                width_m,
            } => canvas.fault(points, *throw_m, *width_m),
            Op::MountainRange {
                points,
                height_m,
                width_m,
                seed,
            } => canvas.mountain_range(points, *height_m, *width_m, plan.seed, *seed),
            Op::Mesa {
                center,
                radius_m,
                elevation_m,
                slope_deg,
                cliff_width_m,
            } => canvas.mesa(*center, *radius_m, *elevation_m, *slope_deg, *cliff_width_m),
            Op::CopyPaste {
                source_min,
                source_max,
                target,
                rotation_deg,
                scale,
                source_seed,
                heightmap,
                warp_m,
                warp_wavelength_m,
                warp_seed,
            } => {
                let spacing = grid.spacing_m / scale;
                let source_err = |message: String| RegionError::Source {
                    op: index,
                    message: format!("copy-paste source: {message}"),
                };
                let src = match (heightmap, source_seed) {
                    (Some(h), _) => {
                        let img = h.decode().map_err(source_err)?;
                        PasteSource::from_image(
                            &img,
                            h.spacing_m,
                            *source_min,
                            *source_max,
                            spacing,
                        )
                    }
                    (None, Some(seed)) => {
                        let other = WorldPlan::new(*seed, plan.params.clone())
                            .map_err(|e| source_err(e.to_string()))?;
                        PasteSource::sample(&other, *source_min, *source_max, spacing)
                    }
                    (None, None) => PasteSource::sample(plan, *source_min, *source_max, spacing),
                };
                let at = Placement {
                    target: *target,
                    rotation_deg: *rotation_deg,
                    scale: *scale,
                    warp: Warp::new(plan.seed, *warp_seed, *warp_m, *warp_wavelength_m),
                };
                canvas.paste(&src, &at);
            }
            Op::DirectionalTensor {
                center,
                radius_m,
                angle_deg,
                strength,
            } => canvas.directional_tensor(*center, *radius_m, *angle_deg, *strength),
            Op::SkeletonTensor {
                points,
                radius_m,
                angle_deg,
                strength,
            } => canvas.skeleton_tensor(points, *radius_m, *angle_deg, *strength),
            Op::StrokeTensor {
                points,
                radius_m,
                strength,
            } => canvas.stroke_tensor(points, *radius_m, *strength),
            Op::Erosion {
                center,
                radius_m,
                talus_deg,
                iterations,
            } => {
                if !solved {
                    cycles = solve(&canvas, &mut current, first)?;
                    first = false;
                }
                canvas.erode(*center, *radius_m, *talus_deg, *iterations, &current);
            }
            Op::HydraulicErosion {
                center,
                radius_m,
                droplets,
                steps,
                erosion_rate,
                seed,
            } => {
                if !solved {
                    cycles = solve(&canvas, &mut current, first)?;
                    first = false;
                }
                let d = Droplets {
                    count: *droplets,
                    steps: *steps,
                    erosion_rate: *erosion_rate,
                    seed: droplet_seed(plan.seed, *seed),
                };
                canvas.hydraulic_erode(*center, *radius_m, &d, &current);
            }
            Op::Contours { lines, detail } => canvas.contours(lines, *detail),
            Op::Network {
                nodes,
                edges,
                detail,
            } => {
                let elevations =
                    resolve_elevations(nodes, edges).map_err(|k| RegionError::Source {
                        op: index,
                        message: format!("node {k} has no elevation"),
                    })?;
                canvas.network(nodes, &elevations, edges, *detail)
            }
            Op::Regularize {} => {
                if !solved {
                    cycles = solve(&canvas, &mut current, first)?;
                    first = false;
                }
                canvas.regularize(&current);
            }
            Op::Sketch {
                png_base64,
                min_m,
                max_m,
                blend_m,
            } => {
                let source_err = |message: String| RegionError::Source {
                    op: index,
                    message: format!("sketch: {message}"),
                };
                let img = decode(png_base64, *min_m, *max_m).map_err(source_err)?;
                canvas.sketch(plan, &img, *blend_m);
            }
            Op::Basis { .. } => {
                let b = BasisOp::of(op).expect("a basis op");
                let img = basis::decode(b.png_base64).map_err(|message| RegionError::Source {
                    op: index,
                    message: format!("basis: {message}"),
                })?;
                let total = basis_total.get_or_insert_with(|| {
                    basis::total_weight(&spec.ops, &grid).expect("a basis op")
                });
                canvas.basis(plan, &img, &b, total);
            }
        }
        solved = matches!(op, Op::Freeze { .. });
    }
    if !spec.ops.is_empty() && !solved {
        cycles = solve(&canvas, &mut current, first)?;
    }
    // Fixed samples take their imposed values exactly (the solver keeps them, this makes it
    // independent of how it stores them).
    for (v, fixed) in canvas.fixed.iter().enumerate() {
        if *fixed {
            current[v] = canvas.d[v];
        }
    }
    Ok(Displacement {
        id: spec.id.clone(),
        grid,
        d: current,
        base: canvas.base,
        fixed: canvas.fixed,
        cycles,
    })
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::element::Element;
    use crate::terrain::WorldParams;
    use serde_json::json;

    pub(crate) fn plan() -> WorldPlan {
        WorldPlan::new(11, WorldParams::classic()).expect("plan")
    }

    pub(crate) fn spec(samples: usize, ops: serde_json::Value) -> RegionSpec {
        let element: Element = serde_json::from_value(json!({
            "id": "r", "bbox": {"min": [1000, 2000], "max": [1128, 2128]},
            "samples": samples, "ops": ops}))
        .expect("element");
        RegionSpec::from_element(&element).expect("spec")
    }

    pub(crate) fn height(r: &Displacement, i: usize, j: usize) -> f64 {
        let v = j * r.grid.n + i;
        f64::from(r.base[v]) + f64::from(r.d[v])
    }

    /// Nearest sample to a world position.
    pub(crate) fn sample_at(r: &Displacement, x: f64, z: f64) -> (usize, usize) {
        let (u, v) = r.grid.grid_coords(x, z);
        (u.round() as usize, v.round() as usize)
    }

    #[test]
    fn an_unedited_region_changes_nothing() {
        let r = solve_region(&plan(), &spec(65, json!([]))).expect("solved");
        assert!(r.d.iter().all(|d| *d == 0.0));
    }

    #[test]
    fn an_elevation_constraint_holds_and_the_border_stays_procedural() {
        let ops = json!([{"op": "elevation", "shape": {"point": [1064, 2064]}, "elevation_m": 400, "radius_m": 3}]);
        let r = solve_region(&plan(), &spec(65, ops)).expect("solved");
        let (i, j) = sample_at(&r, 1064.0, 2064.0);
        assert!(
            (height(&r, i, j) - 400.0).abs() < 1e-3,
            "{}",
            height(&r, i, j)
        );
        let n = r.grid.n;
        for t in 0..n {
            for (a, b) in [(t, 0), (t, n - 1), (0, t), (n - 1, t)] {
                assert_eq!(r.d[b * n + a], 0.0, "border sample ({a}, {b})");
            }
        }
        // Smooth: the displacement falls off without jumps between neighbours.
        let max_step = (0..n - 1)
            .flat_map(|j| (0..n - 1).map(move |i| (i, j)))
            .map(|(i, j)| {
                let v = j * n + i;
                (r.d[v + 1] - r.d[v]).abs().max((r.d[v + n] - r.d[v]).abs())
            })
            .fold(0.0f32, f32::max);
        let rise = r.d[j * n + i].abs();
        assert!(
            rise > 10.0 && max_step < rise / 3.0,
            "rise {rise}, steepest step {max_step}"
        );
    }

    #[test]
    fn a_hard_constraint_beats_a_conflicting_soft_one() {
        // A noise brush and an amplify brush (soft) over an elevation constraint (hard).
        let ops = json!([
            {"op": "elevation", "shape": {"point": [1064, 2064]}, "elevation_m": 250, "radius_m": 2},
            {"op": "noise", "center": [1064, 2064], "radius_m": 50, "amplitude_m": 30, "wavelength_m": 20},
            {"op": "amplify", "center": [1064, 2064], "radius_m": 50, "factor": 4}
        ]);
        let r = solve_region(&plan(), &spec(65, ops)).expect("solved");
        let (i, j) = sample_at(&r, 1064.0, 2064.0);
        assert!((height(&r, i, j) - 250.0).abs() < 1e-3);
    }

    #[test]
    fn a_crest_has_its_ridge_at_the_elevation_and_flanks_at_the_slope() {
        // A ridge 15 m above the ground, so 30° flanks over 30 m can reach the surroundings.
        let flat = solve_region(&plan(), &spec(129, json!([]))).expect("solved");
        let (i, j) = sample_at(&flat, 1064.0, 2064.0);
        let ridge = height(&flat, i, j).round() + 15.0;
        let ops = json!([{"op": "crest", "points": [[1020, 2064], [1108, 2064]],
            "elevation_m": ridge, "slope_deg": 30, "width_m": 30}]);
        let r = solve_region(&plan(), &spec(129, ops)).expect("solved");
        let h = r.grid.spacing_m;
        for x in [1040.0, 1064.0, 1090.0] {
            let (i, j) = sample_at(&r, x, 2064.0);
            assert!((height(&r, i, j) - ridge).abs() < 1e-3, "ridge at x = {x}");
            // Flanks: the mean slope over the first 10 m on either side.
            let k = (10.0 / h).round() as usize;
            for side in [j - k, j + k] {
                let drop = ridge - height(&r, i, side);
                let slope = (drop / (k as f64 * h)).atan().to_degrees();
                assert!(
                    (20.0..40.0).contains(&slope),
                    "flank slope {slope:.1}° at x = {x}"
                );
            }
        }
    }

    #[test]
    fn freeze_keeps_heights_against_later_constraints() {
        let ops = json!([
            {"op": "elevation", "shape": {"point": [1064, 2064]}, "elevation_m": 350, "radius_m": 2},
            {"op": "freeze", "center": [1064, 2064], "radius_m": 20},
            {"op": "elevation", "shape": {"point": [1070, 2064]}, "elevation_m": 0, "radius_m": 2}
        ]);
        let frozen = solve_region(&plan(), &spec(65, ops)).expect("solved");
        let first = json!([{"op": "elevation", "shape": {"point": [1064, 2064]}, "elevation_m": 350, "radius_m": 2}]);
        let before = solve_region(&plan(), &spec(65, first)).expect("solved");
        let (i, j) = sample_at(&frozen, 1070.0, 2064.0);
        let v = j * frozen.grid.n + i;
        assert_eq!(
            frozen.d[v], before.d[v],
            "the later constraint must not move a frozen sample"
        );
    }

    /// Mean |slope| in the core of a brush over the procedural one's.
    fn amplify_ratio(factor: f64) -> f64 {
        let ops =
            json!([{"op": "amplify", "center": [1064, 2064], "radius_m": 60, "factor": factor}]);
        let r = solve_region(&plan(), &spec(129, ops)).expect("solved");
        let n = r.grid.n;
        let (ci, cj) = sample_at(&r, 1064.0, 2064.0);
        let (mut proc, mut edited) = (0.0, 0.0);
        for j in cj - 8..cj + 8 {
            for i in ci - 8..ci + 8 {
                let v = j * n + i;
                proc += (f64::from(r.base[v + 1]) - f64::from(r.base[v])).abs()
                    + (f64::from(r.base[v + n]) - f64::from(r.base[v])).abs();
                edited += (height(&r, i + 1, j) - height(&r, i, j)).abs()
                    + (height(&r, i, j + 1) - height(&r, i, j)).abs();
            }
        }
        edited / proc
    }

    #[test]
    fn amplify_scales_the_slopes_in_the_brush() {
        // The scaled field is not a gradient (the factor varies), so the least-squares
        // reconstruction meets it only in part: the slopes grow or shrink, toward the factor.
        let up = amplify_ratio(2.5);
        let down = amplify_ratio(0.3);
        assert!(
            (1.5..2.6).contains(&up),
            "amplify ×2.5: slope ratio {up:.2}"
        );
        assert!(
            (0.25..0.7).contains(&down),
            "suppress ×0.3: slope ratio {down:.2}"
        );
        println!("slope ratios in the brush core: ×2.5 → {up:.2}, ×0.3 → {down:.2}");
    }

    /// A 2 × 2 window of the lattice of spacing `s` at `(gx0, gz0)`.
    fn window(spacing_m: f32, gx0: i64, gz0: i64) -> Window {
        Window {
            spacing_m,
            gx0,
            gz0,
            w: 2,
            h: 2,
        }
    }

    #[test]
    fn tiles_add_the_displacement_as_a_function_of_position() {
        let ops = json!([{"op": "elevation", "shape": {"point": [1064, 2064]}, "elevation_m": 400, "radius_m": 3}]);
        let r = solve_region(&plan(), &spec(65, ops)).expect("solved");
        // The same world point through two lattices (LOD 0 and LOD 1) gets the same `d`.
        let mut a = vec![0.0f32; 4];
        let mut b = vec![0.0f32; 4];
        r.add_to_lattice(window(1.0, 1060, 2060), &mut a);
        r.add_to_lattice(window(2.0, 530, 1030), &mut b);
        assert_eq!(a[0], b[0]);
        assert!(a[0] > 10.0);
        // Outside the bbox nothing changes.
        let mut c = vec![0.0f32; 4];
        r.add_to_lattice(window(1.0, 1129, 2000), &mut c);
        assert!(c.iter().all(|v| *v == 0.0));
    }
}
