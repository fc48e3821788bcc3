//! Solving a region: rasterise its operations (each a [`super::tools`] tool, on a [`Raster`]),
//! reconstruct the displacement, and apply it to lattice heights.

use super::grid::{Procedural, RegionGrid};
use super::raster::Canvas;
use super::spec::RegionSpec;
use crate::terrain::cancel::{Cancel, Cancelled};
use crate::terrain::lattice::Window;
use crate::terrain::offload::{CpuOnly, PoissonOffload};
use crate::terrain::poisson::{GridSpec, PoissonError, Problem, SolveOptions, Solver, Start};
use crate::terrain::WorldPlan;

/// Why a region could not be solved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RegionError {
    /// The solver refused the problem.
    #[error("region solver: {0}")]
    Solver(PoissonError),
    /// The solve's cancellation flag was set ([`solve_region_on`]); nothing was solved.
    #[error("region solve cancelled")]
    Cancelled,
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

impl From<PoissonError> for RegionError {
    fn from(e: PoissonError) -> Self {
        match e {
            PoissonError::Cancelled => Self::Cancelled,
            e => Self::Solver(e),
        }
    }
}

impl From<Cancelled> for RegionError {
    fn from(_: Cancelled) -> Self {
        Self::Cancelled
    }
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

/// A region being rasterised: what a tool's [`super::tools::Tool::apply`] works on (the canvas, the world,
/// the operation's index) and the solver behind [`Raster::solved`].
pub struct Raster<'a> {
    /// The world.
    pub plan: &'a WorldPlan,
    /// The region.
    pub spec: &'a RegionSpec,
    /// Index of the operation being applied.
    pub index: usize,
    /// The grid's constraints and target gradient so far.
    pub canvas: Canvas,
    /// The `basis` operations' summed weights at the samples, computed by the first of them.
    pub basis_total: Option<Vec<f64>>,
    /// Polled while the world is sampled (the base, a copy-paste source), by the solver's
    /// cycles and by the erosion brushes' loops.
    pub cancel: Cancel,
    gspec: GridSpec,
    solver: Solver,
    /// Where the solver's cycles may run besides the CPU.
    offload: &'a dyn PoissonOffload,
    /// `d` solved from the canvas (0 before any solve).
    current: Vec<f32>,
    /// Whether `current` solves the canvas as it is.
    solved: bool,
    /// Whether the operation being applied declares that it reads the solved heights
    /// ([`super::tools::Tool::reads_solution`]): only such an operation may solve, since the
    /// region's work budget counts a solve for it alone.
    reads: bool,
    /// Whether no solve ran yet (the next one starts cold).
    first: bool,
    /// Finest-level cycles of the last solve.
    cycles: usize,
}

impl std::fmt::Debug for Raster<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Raster")
            .field("region", &self.spec.id)
            .field("index", &self.index)
            .field("solved", &self.solved)
            .field("cycles", &self.cycles)
            .finish_non_exhaustive()
    }
}

impl<'a> Raster<'a> {
    fn new(
        plan: &'a WorldPlan,
        spec: &'a RegionSpec,
        offload: &'a dyn PoissonOffload,
        cancel: &Cancel,
    ) -> Result<Self, RegionError> {
        let grid = RegionGrid::of(spec);
        let base = Procedural::sample_on(plan, &grid, cancel)?.heights;
        let canvas = Canvas::new(grid, base);
        let gspec = GridSpec::new(grid.n, grid.n, grid.spacing_m)?;
        let mut solver = Solver::new(gspec, SolveOptions::default())?;
        solver.set_cancel(cancel.clone());
        Ok(Self {
            plan,
            spec,
            index: 0,
            canvas,
            basis_total: None,
            cancel: cancel.clone(),
            gspec,
            solver,
            offload,
            current: vec![0.0f32; grid.n * grid.n],
            solved: true,
            reads: false,
            first: true,
            cycles: 0,
        })
    }

    /// Reconstructs `d` from the canvas as it is (cold the first time, warm after).
    fn solve(&mut self) -> Result<(), RegionError> {
        let c = &self.canvas;
        let problem = Problem {
            grid: self.gspec,
            gx: &c.gx,
            gz: &c.gz,
            fixed: &c.fixed,
            heights: &c.d,
        };
        let start = if self.first { Start::Cold } else { Start::Warm };
        let report = self.solver.solve_on(&problem, start, self.offload)?;
        self.solver.heights_into(&mut self.current)?;
        self.cycles = report.cycles;
        self.first = false;
        self.solved = true;
        Ok(())
    }

    /// The canvas and the displacement solved from what precedes this operation, solving first
    /// unless nothing changed since the last solve.
    ///
    /// # Errors
    /// [`RegionError::Solver`] if the solver refuses the problem, [`RegionError::Cancelled`]
    /// once the region's flag is set.
    pub fn solved(&mut self) -> Result<(&mut Canvas, &[f32]), RegionError> {
        debug_assert!(
            self.solved || self.reads,
            "operation {} solves without declaring Tool::reads_solution",
            self.index
        );
        if !self.solved {
            self.solve()?;
        }
        Ok((&mut self.canvas, &self.current))
    }

    /// This operation's input could not be used, for `message`.
    pub fn refuse(&self, message: String) -> RegionError {
        RegionError::Source {
            op: self.index,
            message,
        }
    }
}

/// Solves a region of the world `plan`: samples the procedural heights, rasterises the
/// operations in order (a tool reading the solved heights, like a freeze brush, solves what
/// precedes it first) and reconstructs `d`.
///
/// # Errors
/// [`RegionError`] if the solver refuses the problem or an operation's input is unusable.
pub fn solve_region(plan: &WorldPlan, spec: &RegionSpec) -> Result<Displacement, RegionError> {
    solve_region_on(plan, spec, &CpuOnly, &Cancel::never())
}

/// [`solve_region`] with the solver's cycles offered to `offload` ([`Solver::solve_on`]): the
/// result meets the same stopping test and differs from the CPU's only within the solver's
/// tolerance. The sampling of the world, the solver's cycles and the erosion brushes poll
/// `cancel` ([`Cancel`]).
///
/// # Errors
/// As [`solve_region`], and [`RegionError::Cancelled`] once `cancel` is set.
pub fn solve_region_on(
    plan: &WorldPlan,
    spec: &RegionSpec,
    offload: &dyn PoissonOffload,
    cancel: &Cancel,
) -> Result<Displacement, RegionError> {
    let mut r = Raster::new(plan, spec, offload, cancel)?;
    for (index, op) in spec.ops.iter().enumerate() {
        r.index = index;
        let tool = op.tool();
        r.reads = tool.reads_solution();
        tool.apply(&mut r)?;
        r.solved = tool.keeps_solution();
    }
    if !spec.ops.is_empty() && !r.solved {
        r.solve()?;
    }
    let Raster {
        canvas,
        mut current,
        cycles,
        ..
    } = r;
    // Fixed samples take their imposed values exactly (the solver keeps them, this makes it
    // independent of how it stores them).
    for (v, fixed) in canvas.fixed.iter().enumerate() {
        if *fixed {
            current[v] = canvas.d[v];
        }
    }
    Ok(Displacement {
        id: spec.id.clone(),
        grid: canvas.grid,
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
