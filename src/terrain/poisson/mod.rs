//! Poisson reconstruction of heights from a gradient field by geometric multigrid (issue 4).
//!
//! Guérin, Peytavie, Masnou, Digne, Sauvage, Gain, Galin, *Gradient Terrain Authoring* (Computer
//! Graphics Forum 41(2), 2022), §3: the heights `h` of an authored region are recovered from a
//! (user-edited) gradient field `g` by solving `Δh = ∇·g`, with Dirichlet conditions
//! `h = c` on any subset `Ω` of the samples (points, curves, regions are just fixed samples).
//! Gradient targets are soft (the least-squares target of the reconstruction), elevation
//! constraints are hard: where they conflict, the constraint holds exactly and the gradient is not
//! met (the paper's Fig. 16 behaviour).
//!
//! # Discretisation
//! A grid of `nx × nz` samples (`2^k + 1` per side, [`grid::GridSpec`]), spacing `δ` metres. The
//! gradient lives on the edges ([`problem`]): `gx` on the x-edges `(i + ½, j)`, `gz` on the
//! z-edges `(i, j + ½)`. The normal equations of `min Σ_edges (Dh − g)²` are the 5-point
//! equations `h_W + h_E + h_N + h_S − 4 h = δ · div_δ g` at every free sample: a clean 5-point
//! Laplacian, exact for fields extracted with [`gradient::extract_edges`] (forward differences),
//! second-order accurate for smooth fields sampled at edge midpoints. The paper's per-sample
//! central-difference gradients (its §3 extraction and its two-channel gradient-map encoding) are
//! converted by averaging onto the edges ([`gradient::edges_from_samples`]); putting the
//! central-difference divergence of per-sample gradients on the 5-point operator would decouple
//! the grid into four sub-lattices.
//!
//! # Boundary rules
//! The border of the domain is always Dirichlet (an authored region's border takes the procedural
//! heights, so it meets the world without a step). Any interior sample may be fixed too.
//!
//! # Multigrid
//! The paper runs a "half V-cycle": from the coarsest 9 × 9 level upwards, `50 + 20ℓ` iterations
//! per level, with no residual going back down. **Deviations:** we run full multigrid (FMG) with
//! residual correction instead ([`multigrid`]), on Galerkin coarse operators ([`galerkin`]):
//! - every coarse level carries `A_c = Pᵀ A P`, with `P` bilinear interpolation from the coarse
//!   free samples to the fine free samples (zero at fixed samples) and `Pᵀ` the restriction (full
//!   weighting times 4); a coarse sample is fixed exactly when its fine counterpart is. Coarse
//!   operators are 9-point: one default stencil per level plus the stencils of the few samples
//!   near interior constraints that differ from it. So the coarse-grid correction stays the
//!   energy-optimal one whatever the constraints (points, curves, painted regions). Measured
//!   (`tests/poisson.rs`, terrain-like fields, 1 + 1 sweeps): border only, 0.05–0.065 per V-cycle
//!   and 0.05–0.06 per W-cycle; with a point, a curve and a painted disc, 0.06–0.08 per W-cycle,
//!   steady. Plain V-cycles with interior constraints reduce by 0.04–0.09 for the first four
//!   cycles, then settle at a steady 0.37: an isolated fixed point makes a logarithmic dip that
//!   no coarse level can shape (bilinear coarse functions only see a one-sample hole), and the
//!   error of a V-cycle's coarse solves accumulates over the levels; the W-cycle's second visit
//!   removes it. (Re-discretised coarse operators, the previous version, gave 0.65 per V-cycle.)
//!   [`Acceleration::Auto`] runs plain cycles and hands over to conjugate gradients
//!   preconditioned by the cycle once a cycle reduces by less than [`AUTO_SWITCH_FACTOR`];
//! - smoothing is Gauss–Seidel in place on colour-split arrays ([`grid`]): red-black on the
//!   finest level (5-point), four colours (colour array × row parity) on the 9-point coarse
//!   levels; rows in parallel bands ([`ops`]);
//! - full multigrid works on the correction equation: the finest free samples start from the
//!   transfinite interpolation of the border heights, the residual of that start is restricted
//!   to every level, the coarsest level (shorter side 3) is solved by Gauss–Seidel sweeps, and
//!   each level's correction is interpolated bilinearly to the next finer one followed by one
//!   cycle there ([`SolveOptions::fmg_cycles`]);
//! - on the finest level, correction cycles (V by default, W optional) run until the stopping
//!   rule holds: residual `r = b − A h` restricted by `Pᵀ`, a coarse-grid correction from zero,
//!   prolongation by `P`, red-black smoothing (1 + 1 sweeps);
//! - optionally ([`Acceleration`]) the symmetric cycle (post-smoothing in the reverse colour
//!   order) preconditions conjugate gradients.
//!
//! # Stopping rule and precision
//! A solve stops when `‖b − A h‖₂ / ‖b‖₂ ≤ tolerance` (default `1e-6`), where `A` is the 5-point
//! operator over the free samples and `b` the right-hand side with the fixed neighbours moved to
//! it; the norm is that of the current iterate (the finest-level cycle restricts the residual it
//! measures, so the test costs nothing). Storage is `f64` throughout: `f32` storage cannot reach
//! `1e-6` on large grids, because rounding the heights to `f32` alone leaves a relative residual
//! of about `2·ε_f32·√n` (≈ 1.3e-6 at 1025², 2.6e-6 at 4097²). The output is rounded to `f32` at
//! the end (fixed samples are the imposed `f32` heights, bit for bit). The WGSL twin
//! (`shaders/poisson.wgsl` and its host module `gpu::poisson`) runs the same kernels in `f32`.
//!
//! # Warm start
//! After an edit, [`Start::Warm`] starts from the previous solution (no FMG). The solver finds
//! what changed: the mask is compared while it is installed ([`level::Level::set_fixed`]), the
//! right-hand side and the fixed heights while they are loaded ([`Problem::load_tracked`]), and
//! only the coarse rows within reach of changed rows get new masks and Galerkin stencils
//! ([`galerkin::coarsen_rows`], rows in parallel). A caller that knows where it edited (a brush
//! knows its bounds) calls [`Solver::resolve_in`] with that rectangle instead: validation, mask
//! comparison and loading then cover only the rows of the rectangle (and one row either side),
//! and `‖b‖²` is the row-ordered sum of per-row partials the solver keeps, so the result is bit
//! for bit that of the scanning warm solve (tested; debug builds check the caller's rectangle
//! over the whole grid). If the previous solve converged and the
//! changed samples fit in a small rectangle, [`local`] runs *local* cycles: fine levels work only
//! in windows around the change (FAC-style composite correction), the first level whose window
//! would cover a quarter of it and all coarser ones work globally; the composite correction is
//! then interpolated to the whole grid and smoothed in a band around the window. The stopping
//! rule is still the true global relative residual, measured over the whole grid after the local
//! cycles; if it is above the tolerance but within [`local::LOCAL_FINISH_RANGE`] times it, up to
//! [`local::LOCAL_FINISH_SWEEPS`] red-black sweeps of the whole finest level follow (each
//! followed by the measured residual), and if it is still above, ordinary global cycles continue
//! (large edits go to global cycles directly). [`SolveReport::local_cycles`],
//! [`SolveReport::finishing_sweeps`] and [`SolveReport::samples_relaxed`] say what a solve did.
//! Measured (`strata bench poisson`, brush of 32 samples, brush + `resolve_in` timed together,
//! release, 2 threads, load average 4.4–5.2 from other builds): 2 local cycles at every size, no
//! global cycle; the residual after the write-back is within the tolerance at 1025², 2049² and
//! 4097², and one finishing sweep takes 513² from 1.5e-6 to 6.7e-7. Warm over cold, wall (process
//! CPU): 513² 16–19 % (18–22 %), 1025² 6–9 % (10 %), 2049² 6–7 % (7 %), 4097² 6 % (4 %); the
//! scanning `solve(Start::Warm)` takes 3–4 times as long as `resolve_in`. What remains of the cost is the local
//! cycles (sequential window kernels, about 1.3 ms whatever the grid), the write-back (one
//! prolongation per level over the whole grid plus the band sweeps) and the global residual
//! check.
//!
//! # Limits
//! Sides `2^k + 1` from 3 to 8193 samples ([`MAX_SIDE`]); memory about 23 bytes per sample for
//! the hierarchy (17 bytes per sample and level, times 4/3) plus about 100 bytes per special
//! coarse stencil (a few per constrained sample), plus 33 bytes per finest sample for the
//! conjugate-gradient vectors when they are used. A local re-solve takes the windows of
//! [`local`] (a finest window of at most [`local::LOCAL_MAX_FRACTION`] of the grid, else global
//! cycles) and allocates about 60 bytes per window sample while it runs.
//!
//! # Measured (release, 2 threads, `strata bench poisson`, load average 1.3)
//! Cold to 1e-6: 513² 15.3 ms, 1025² 54.6 ms, 2049² 236 ms (5 cycles after FMG, median factor
//! 0.076–0.079 per iteration); right after a constraint change (mask rows and Galerkin stencils
//! rebuilt incrementally, rows in parallel): 16.4, 55.6 and 243 ms. In the same run PyAMG took
//! 69×, 90× and 99× longer; ours border-only was 1.3×, 1.2× and 1.5× the DST solve's time.

pub mod galerkin;
pub mod gradient;
pub mod grid;
pub mod level;
pub mod local;
pub mod multigrid;
pub mod ops;
pub mod problem;

pub use grid::{GridSpec, MAX_SIDE, MIN_SIDE};
pub use local::Rect;
pub use multigrid::{
    Acceleration, Cycle, SolveOptions, SolveReport, Solver, Start, StartKind, AUTO_SWITCH_FACTOR,
    DEFAULT_MAX_CYCLES, DEFAULT_TOLERANCE,
};
pub use problem::{OwnedProblem, Problem};

/// A problem or option the solver rejects, naming the offending field, or a solve stopped by its
/// cancellation flag.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PoissonError {
    /// A field is out of range.
    #[error("{field}: {message}")]
    Field {
        /// The field (`nx`, `gx`, `heights`, `tolerance`, …).
        field: &'static str,
        /// What is wrong with it.
        message: String,
    },
    /// The solve's cancellation flag was set ([`Solver::set_cancel`]); nothing was solved.
    #[error("cancelled")]
    Cancelled,
}

impl PoissonError {
    pub(crate) fn field(field: &'static str, message: String) -> Self {
        Self::Field { field, message }
    }
}

/// Solves `problem` cold with `options` and returns the heights (`nx · nz` metres, row-major) and
/// the report.
///
/// # Errors
/// As [`Solver::new`] and [`Solver::solve`].
pub fn reconstruct(
    problem: &Problem,
    options: SolveOptions,
) -> Result<(Vec<f32>, SolveReport), PoissonError> {
    let mut solver = Solver::new(problem.grid, options)?;
    let report = solver.solve(problem, Start::Cold)?;
    let mut out = vec![0.0; problem.grid.len()];
    solver.heights_into(&mut out)?;
    Ok((out, report))
}
