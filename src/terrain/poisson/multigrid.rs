//! The multigrid driver: full-multigrid start, V- or W-cycles with residual correction, the
//! relative-residual stopping rule, warm starts, and the per-solve report.
//!
//! Why one file of about 800 lines: it is the `Solver` type, whose loading, cold and warm starts,
//! full-multigrid start, cycle loop and conjugate-gradient acceleration all work on its private
//! level hierarchy and scratch buffers.

use super::galerkin::coarsen_rows;
use super::grid::{GridSpec, Split};
use super::level::Level;
use super::local::{self, Rect};
use super::ops::{
    apply_operator, dot, prolong, residual, residual_norm2, residual_restrict, restrict_rhs,
    smooth, smooth_reverse, update_direction, update_solution,
};
use super::problem::Problem;
use super::PoissonError;
use crate::terrain::cancel::Cancel;

/// Default stopping tolerance on the relative residual `‖b − A h‖₂ / ‖b‖₂`.
pub const DEFAULT_TOLERANCE: f64 = 1e-6;
/// With [`Acceleration::Auto`], a plain cycle that reduces the residual by less than this factor
/// hands over to conjugate gradients (preconditioned by the same cycle) for the rest of the solve.
pub const AUTO_SWITCH_FACTOR: f64 = 0.3;
/// Default cap on finest-level cycles per solve.
pub const DEFAULT_MAX_CYCLES: usize = 40;
/// Finest-level cycles [`Solver::solve_on`] asks a device for: a V-cycle reduces the residual
/// about tenfold, so 16 reach the `f32` floor from a cold start (`tests/gpu_poisson.rs` reaches
/// `1e-5` in 20 on a constrained 129² problem).
pub const DEVICE_CYCLES: usize = 16;
/// Gauss–Seidel sweeps on the coarsest level (its shorter side has one interior sample, so every
/// sweep reduces the error at least fourfold: 30 sweeps reach `f64` rounding).
pub const COARSEST_SWEEPS: usize = 30;

/// Recursion of the coarse-grid correction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cycle {
    /// One coarse-grid visit per level.
    V,
    /// Two coarse-grid visits per level.
    W,
}

/// Krylov acceleration of the finest-level cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Acceleration {
    /// Plain cycles while each reduces the residual by at least [`AUTO_SWITCH_FACTOR`], then
    /// conjugate gradients preconditioned by the cycle (plain V-cycles slow down to about 0.35
    /// per cycle around isolated fixed points once the residual is small; W-cycles do not).
    Auto,
    /// Plain multigrid cycles.
    None,
    /// Conjugate gradients preconditioned by one cycle.
    ConjugateGradient,
}

/// Solver settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolveOptions {
    /// Stop when `‖b − A h‖₂ / ‖b‖₂` is at most this (> 0; default [`DEFAULT_TOLERANCE`]).
    pub tolerance: f64,
    /// Most finest-level cycles per solve (default [`DEFAULT_MAX_CYCLES`]); a solve that reaches
    /// it reports `converged: false`.
    pub max_cycles: usize,
    /// Red-black sweeps before the coarse-grid correction on the coarse levels (default 1). On
    /// the finest level they are done after the correction, together with `post_smooth` (so the
    /// residual of the current iterate is the one the next cycle restricts, and the stopping test
    /// costs no extra pass; the cycle is cyclically equivalent).
    pub pre_smooth: usize,
    /// Red-black sweeps after the coarse-grid correction (default 1).
    pub post_smooth: usize,
    /// V- or W-cycles (default V).
    pub cycle: Cycle,
    /// Cycles per level in the full-multigrid start (default 1).
    pub fmg_cycles: usize,
    /// Krylov acceleration (default [`Acceleration::Auto`]).
    pub acceleration: Acceleration,
    /// Worker threads (`None`: rayon's global pool, one per core). Results do not depend on it.
    pub threads: Option<usize>,
}

impl Default for SolveOptions {
    fn default() -> Self {
        Self {
            tolerance: DEFAULT_TOLERANCE,
            max_cycles: DEFAULT_MAX_CYCLES,
            pre_smooth: 1,
            post_smooth: 1,
            cycle: Cycle::V,
            fmg_cycles: 1,
            acceleration: Acceleration::Auto,
            threads: None,
        }
    }
}

/// Initial guess of a solve.
#[derive(Clone, Copy, Debug)]
pub enum Start<'a> {
    /// Full multigrid from the coarsest level.
    Cold,
    /// The solver's previous solution (after an edit); a cold start if there is none.
    Warm,
    /// The given heights (`nx · nz` metres, row-major) at the free samples.
    From(&'a [f32]),
}

/// Which start a solve actually used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StartKind {
    /// Full multigrid.
    Cold,
    /// The previous solution or given heights.
    Warm,
}

/// What one solve did.
#[derive(Clone, Debug, PartialEq)]
pub struct SolveReport {
    /// The start used.
    pub start: StartKind,
    /// Finest-level cycles.
    pub cycles: usize,
    /// `‖r‖₂ / ‖b‖₂` of the start (after the full-multigrid start, or of the warm guess), then
    /// after each cycle.
    pub relative_residuals: Vec<f64>,
    /// True if the last relative residual is at most the tolerance.
    pub converged: bool,
    /// `‖b‖₂`, metres.
    pub rhs_norm: f64,
    /// Local cycles of a warm re-solve ([`super::local`]) run before `cycles`; their residuals
    /// are estimates and are not listed in `relative_residuals`, whose first entry is then the
    /// measured global residual after them.
    pub local_cycles: usize,
    /// Red-black sweeps of the whole finest level run after the local cycles, before any
    /// global cycle, when the measured residual was above the tolerance but within
    /// [`local::LOCAL_FINISH_RANGE`] times it (at most [`local::LOCAL_FINISH_SWEEPS`]); the
    /// residual after each is listed in `relative_residuals` (so its length is
    /// `1 + finishing_sweeps + cycles`).
    pub finishing_sweeps: usize,
    /// Samples relaxed by the smoothers on all levels (each Gauss–Seidel sweep over a level or a
    /// window counts its samples): the work of the solve, independent of the machine.
    pub samples_relaxed: u64,
    /// Finest-level cycles a device ran in `f32` before the CPU's `cycles`
    /// ([`Solver::solve_on`]); 0 for a solve on the CPU alone.
    pub device_cycles: usize,
}

impl SolveReport {
    /// Residual reduction factor of each cycle.
    pub fn factors(&self) -> Vec<f64> {
        self.relative_residuals
            .windows(2)
            .map(|w| w[1] / w[0])
            .collect()
    }
}

/// A multigrid solver for one grid size: the level hierarchy (allocated once), the current
/// solution (for warm starts) and, optionally, its own thread pool.
#[derive(Debug)]
pub struct Solver {
    options: SolveOptions,
    levels: Vec<Level>,
    krylov: Option<Krylov>,
    scratch: Vec<f64>,
    /// The window buffers of [`local::resolve`].
    windows: local::LocalScratch,
    /// Each finest row's contribution to `‖b‖²` for the loaded problem (`nz` values once a
    /// problem is loaded), so that [`Self::resolve_in`] reloads only the damaged rows.
    rhs_rows: Vec<f64>,
    has_solution: bool,
    /// True when the previous solve converged (the background residual of a local re-solve is
    /// within the tolerance).
    last_converged: bool,
    pool: Option<rayon::ThreadPool>,
    /// Polled before every finest-level cycle ([`Self::set_cancel`]).
    cancel: Cancel,
}

impl Solver {
    /// A solver for `grid`.
    ///
    /// # Errors
    /// [`PoissonError::Field`] naming `tolerance`, `max_cycles`, `threads` or `fmg_cycles` if an
    /// option is out of range (tolerance finite and > 0, `threads ≥ 1`).
    pub fn new(grid: GridSpec, options: SolveOptions) -> Result<Self, PoissonError> {
        if !(options.tolerance.is_finite() && options.tolerance > 0.0) {
            return Err(PoissonError::field(
                "tolerance",
                format!("{}; must be finite and > 0", options.tolerance),
            ));
        }
        if options.pre_smooth + options.post_smooth == 0 {
            return Err(PoissonError::field(
                "post_smooth",
                "pre_smooth + post_smooth must be at least 1".to_string(),
            ));
        }
        let pool = match options.threads {
            None => None,
            Some(0) => {
                return Err(PoissonError::field("threads", "0; must be ≥ 1".to_string()));
            }
            Some(n) => Some(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(|e| PoissonError::field("threads", format!("{n}: {e}")))?,
            ),
        };
        let mut levels = vec![Level::new(grid)];
        while let Some(c) = levels.last().and_then(Level::coarsen) {
            levels.push(c);
        }
        Ok(Self {
            options,
            levels,
            krylov: None,
            scratch: Vec::new(),
            windows: local::LocalScratch::default(),
            rhs_rows: Vec::new(),
            has_solution: false,
            last_converged: false,
            pool,
            cancel: Cancel::never(),
        })
    }

    /// Makes every later solve poll `cancel` before each finest-level cycle: once it is set,
    /// the solve stops and answers [`PoissonError::Cancelled`], and the solver holds no
    /// solution (the next solve starts cold).
    pub fn set_cancel(&mut self, cancel: Cancel) {
        self.cancel = cancel;
    }

    /// The grid.
    pub fn grid(&self) -> GridSpec {
        self.levels[0].grid
    }

    /// Number of multigrid levels.
    pub fn level_count(&self) -> usize {
        self.levels.len()
    }

    /// The options.
    pub fn options(&self) -> &SolveOptions {
        &self.options
    }

    /// Bytes held by the hierarchy (unknowns, right-hand sides and masks of every level, the
    /// prolongation scratch and the windows of the last local re-solve).
    pub fn hierarchy_bytes(&self) -> usize {
        self.levels.iter().map(Level::bytes).sum::<usize>()
            + self.scratch.capacity() * std::mem::size_of::<f64>()
            + self.windows.bytes()
            + self.krylov.as_ref().map_or(0, |k| {
                k.zl.bytes() + 4 * k.zl.split.len() * std::mem::size_of::<f64>()
            })
    }

    /// Refuses a problem on another grid, naming the field `grid`.
    fn check_grid(&self, problem: &Problem) -> Result<(), PoissonError> {
        if problem.grid == self.grid() {
            return Ok(());
        }
        Err(PoissonError::field(
            "grid",
            format!(
                "{:?} differs from the solver's {:?}",
                problem.grid,
                self.grid()
            ),
        ))
    }

    /// Runs `work` on the solver's own thread pool if it has one, else on rayon's global pool.
    fn on_pool<T: Send>(&mut self, work: impl FnOnce(&mut Self) -> T + Send) -> T {
        let pool = self.pool.take();
        let out = match &pool {
            Some(p) => p.install(|| work(self)),
            None => work(self),
        };
        self.pool = pool;
        out
    }

    /// The hierarchy, finest level first (for diagnostics and the WGSL twin).
    pub fn levels(&self) -> &[Level] {
        &self.levels
    }

    /// Installs `problem` without solving: the mask on every level, the right-hand side and the
    /// fixed heights on the finest level (free samples keep their current values: zero in a new
    /// solver). Returns `‖b‖₂`.
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn load(&mut self, problem: &Problem) -> Result<f64, PoissonError> {
        self.check_grid(problem)?;
        problem.validate()?;
        Ok(self.on_pool(|s| {
            s.update_mask(problem, 0, usize::MAX);
            s.has_solution = true;
            s.last_converged = false;
            problem
                .load_tracked(&mut s.levels[0], &mut s.rhs_rows)
                .0
                .sqrt()
        }))
    }

    /// Solves `problem` from `start`; the solution stays in the solver (read it with
    /// [`Self::heights_into`]) and is the next warm start.
    ///
    /// # Errors
    /// [`PoissonError::Field`] if the problem is invalid ([`Problem::validate`]), its grid is not
    /// the solver's (`grid`), or `start` heights have the wrong length or non-finite values.
    pub fn solve(&mut self, problem: &Problem, start: Start) -> Result<SolveReport, PoissonError> {
        self.check_grid(problem)?;
        problem.validate()?;
        if let Start::From(h) = start {
            if h.len() != problem.grid.len() {
                return Err(PoissonError::field(
                    "start",
                    format!(
                        "{} heights; the grid has {} samples",
                        h.len(),
                        problem.grid.len()
                    ),
                ));
            }
            if let Some(i) = h.iter().position(|v| !v.is_finite()) {
                return Err(PoissonError::field(
                    "start",
                    format!("height {} at index {i} is not finite", h[i]),
                ));
            }
        }
        let report = self.on_pool(|s| s.run(problem, start));
        self.cancelled()?;
        Ok(report)
    }

    /// [`PoissonError::Cancelled`] (and no solution kept) if the cancellation flag is set.
    fn cancelled(&mut self) -> Result<(), PoissonError> {
        if self.cancel.is_cancelled() {
            self.has_solution = false;
            self.last_converged = false;
            return Err(PoissonError::Cancelled);
        }
        Ok(())
    }

    /// [`Self::solve`] with the bulk of the work on `device`: the problem is loaded, the device
    /// runs [`DEVICE_CYCLES`] plain cycles in `f32` from the loaded state (the previous solution
    /// after an earlier solve, else the constraints and zeros), and the CPU then solves from the
    /// device's heights ([`Start::From`]) to the tolerance in `f64`, which from the device's
    /// `f32` floor (a relative residual of about `1e-5`) takes a cycle or two. This is mixed-
    /// precision iterative refinement: the answer meets the CPU's stopping test, and differs from
    /// a CPU-only solve only by where within the tolerance it stops (millimetres on heights of
    /// hundreds of metres; `tests/gpu_products.rs`). Without a device
    /// ([`PoissonOffload::has_device`](crate::terrain::offload::PoissonOffload::has_device)), and
    /// for a [`Start::From`], this is [`Self::solve`], bit for bit; when the device answers `None`
    /// or non-finite values, it is [`Self::solve`] from `start` on the loaded problem (a warm
    /// start then runs global cycles, not the local re-solve).
    ///
    /// # Errors
    /// As [`Self::solve`].
    pub fn solve_on(
        &mut self,
        problem: &Problem,
        start: Start,
        device: &dyn crate::terrain::offload::PoissonOffload,
    ) -> Result<SolveReport, PoissonError> {
        if !device.has_device() || matches!(start, Start::From(_)) {
            return self.solve(problem, start);
        }
        if self.load(problem)? == 0.0 {
            return self.solve(problem, start);
        }
        let plain = SolveOptions {
            acceleration: Acceleration::None,
            ..self.options
        };
        let answer = device
            .poisson_cycles(&self.levels, DEVICE_CYCLES, &plain)
            .filter(|h| {
                let split = &self.levels[0].split;
                h.iter().all(|c| c.len() == split.len())
                    && h.iter().flatten().all(|v| v.is_finite())
            });
        let Some(h) = answer else {
            return self.solve(problem, start);
        };
        let mut heights = vec![0.0f32; self.grid().len()];
        self.levels[0].split.merge_into(&h, &mut heights, |v| v);
        let mut report = self.solve(problem, Start::From(&heights))?;
        report.device_cycles = DEVICE_CYCLES;
        Ok(report)
    }

    /// A warm re-solve after an edit confined to `damage`, a rectangle of samples (bounds
    /// included) that the caller knows, such as a brush's bounds: only the rows of `damage` (and
    /// one row either side, whose right-hand side reads the edited edges and fixed heights) are
    /// validated, compared and reloaded, instead of the whole grid. The result is bit for bit that
    /// of [`Self::solve`] with [`Start::Warm`].
    ///
    /// Contract: compared with the problem of the solver's previous solve (or [`Self::load`]),
    /// every x-edge `(i + ½, j)`, z-edge `(i, j + ½)`, fixed flag and height that differs belongs
    /// to a sample `(i, j)` inside `damage`. Debug builds check it over the whole grid and panic
    /// if it does not hold; release builds trust it. Without a previous problem this is
    /// [`Self::solve`] with [`Start::Warm`].
    ///
    /// # Errors
    /// As [`Self::solve`] (validation covers the damaged rows), and [`PoissonError::Field`] naming
    /// `damage` if the rectangle is empty or leaves the grid.
    pub fn resolve_in(
        &mut self,
        problem: &Problem,
        damage: Rect,
    ) -> Result<SolveReport, PoissonError> {
        self.check_grid(problem)?;
        let g = self.grid();
        if damage.i0 > damage.i1 || damage.j0 > damage.j1 || damage.i1 >= g.nx || damage.j1 >= g.nz
        {
            return Err(PoissonError::field(
                "damage",
                format!(
                    "{damage:?} is empty or leaves the {}×{} grid (bounds are included)",
                    g.nx, g.nz
                ),
            ));
        }
        if !self.has_solution || self.rhs_rows.len() != g.nz {
            return self.solve(problem, Start::Warm);
        }
        problem.validate_rows(damage.j0, damage.j1)?;
        let report = self.on_pool(|s| {
            let relaxed_before = s.relaxed();
            let mask_change = s.update_mask(problem, damage.j0, damage.j1);
            let (bb, load_change) = problem.load_rows(
                &mut s.levels[0],
                &mut s.rhs_rows,
                damage.j0.saturating_sub(1),
                damage.j1 + 1,
            );
            #[cfg(debug_assertions)]
            {
                let outside_mask = s.levels[0].set_fixed(problem.fixed);
                let mut rows = Vec::new();
                let (full, outside) = problem.load_tracked(&mut s.levels[0], &mut rows);
                assert!(
                    outside_mask.is_none() && outside.is_none() && full.to_bits() == bb.to_bits(),
                    "resolve_in: the problem changed outside the damage rectangle {damage:?} \
                     (mask {outside_mask:?}, values {outside:?})"
                );
            }
            let change = match (mask_change, load_change) {
                (Some(a), Some(b)) => Some(a.union(b)),
                (a, b) => a.or(b),
            };
            s.finish(Start::Warm, bb, change, relaxed_before)
        });
        self.cancelled()?;
        Ok(report)
    }

    /// The solution in metres, row-major `nx · nz`, rounded to `f32` (fixed samples are exactly
    /// the imposed heights).
    ///
    /// # Errors
    /// [`PoissonError::Field`] naming `out` if its length is not the grid's.
    pub fn heights_into(&self, out: &mut [f32]) -> Result<(), PoissonError> {
        self.check_out(out.len())?;
        let l = &self.levels[0];
        l.split.merge_into(&l.h, out, |v| v as f32);
        Ok(())
    }

    /// The solution in metres at full precision, row-major `nx · nz`.
    ///
    /// # Errors
    /// As [`Self::heights_into`].
    pub fn heights_f64_into(&self, out: &mut [f64]) -> Result<(), PoissonError> {
        self.check_out(out.len())?;
        let l = &self.levels[0];
        l.split.merge_into(&l.h, out, |v| v);
        Ok(())
    }

    fn check_out(&self, len: usize) -> Result<(), PoissonError> {
        let n = self.grid().len();
        if len != n {
            return Err(PoissonError::field(
                "out",
                format!("{len} values; the grid has {n} samples"),
            ));
        }
        Ok(())
    }

    fn run(&mut self, problem: &Problem, start: Start) -> SolveReport {
        let relaxed_before = self.relaxed();
        let mask_change = self.update_mask(problem, 0, usize::MAX);
        let (bb, load_change) = problem.load_tracked(&mut self.levels[0], &mut self.rhs_rows);
        let change = match (mask_change, load_change) {
            (Some(a), Some(b)) => Some(a.union(b)),
            (a, b) => a.or(b),
        };
        self.finish(start, bb, change, relaxed_before)
    }

    /// The solve after the problem is loaded: `bb = ‖b‖²`, `change` the rectangle of the finest
    /// samples whose mask, right-hand side or fixed height changed.
    fn finish(
        &mut self,
        start: Start,
        bb: f64,
        change: Option<Rect>,
        relaxed_before: u64,
    ) -> SolveReport {
        let bnorm = bb.sqrt();
        let local_ok = matches!(start, Start::Warm) && self.has_solution && self.last_converged;
        let kind = match start {
            Start::Warm if self.has_solution => StartKind::Warm,
            Start::From(h) => {
                let l = &mut self.levels[0];
                let g = l.grid;
                for j in 0..g.nz {
                    for i in 0..g.nx {
                        let (c, k) = l.split.locate(i, j);
                        if l.free[c][k] != 0 {
                            l.h[c][k] = f64::from(h[j * g.nx + i]);
                        }
                    }
                }
                StartKind::Warm
            }
            _ => StartKind::Cold,
        };
        self.has_solution = true;
        if bnorm == 0.0 {
            // b = 0 with zero constraints: the solution is zero.
            let l = &mut self.levels[0];
            for c in 0..2 {
                for (h, f) in l.h[c].iter_mut().zip(&l.free[c]) {
                    if *f != 0 {
                        *h = 0.0;
                    }
                }
            }
            self.last_converged = true;
            return SolveReport {
                start: kind,
                cycles: 0,
                relative_residuals: vec![0.0],
                converged: true,
                rhs_norm: 0.0,
                local_cycles: 0,
                finishing_sweeps: 0,
                samples_relaxed: 0,
                device_cycles: 0,
            };
        }
        let mut local_cycles = 0;
        let mut local_relaxed = 0;
        if kind == StartKind::Cold {
            self.full_multigrid();
        } else if let (true, Some(rect)) = (local_ok, change) {
            let o = self.options;
            let res = local::resolve(
                &mut self.levels,
                rect,
                &o,
                &mut self.scratch,
                &mut self.windows,
                o.tolerance * bnorm,
            );
            if let Some(out) = res {
                local_cycles = out.cycles;
                local_relaxed = out.relaxed;
            }
        }
        let (cycles, relative_residuals, finishing_sweeps) = self.cycles(bnorm, local_cycles > 0);
        let converged = relative_residuals
            .last()
            .is_some_and(|r| *r <= self.options.tolerance);
        self.last_converged = converged;
        SolveReport {
            start: kind,
            cycles,
            relative_residuals,
            converged,
            rhs_norm: bnorm,
            local_cycles,
            finishing_sweeps,
            samples_relaxed: self.relaxed() - relaxed_before + local_relaxed,
            device_cycles: 0,
        }
    }

    /// Samples relaxed so far on every level (and the conjugate-gradient work level).
    fn relaxed(&self) -> u64 {
        self.levels.iter().map(|l| l.relaxed).sum::<u64>()
            + self.krylov.as_ref().map_or(0, |k| k.zl.relaxed)
    }

    /// Installs the problem's mask of rows `j0..=j1` on the finest level and updates the coarse
    /// masks and operators in the rows within reach of the samples that changed. Returns the
    /// rectangle of the changed samples.
    fn update_mask(&mut self, problem: &Problem, j0: usize, j1: usize) -> Option<Rect> {
        let change = self.levels[0].set_fixed_rows(problem.fixed, j0, j1)?;
        let (mut a, mut b) = (change.j0, change.j1);
        for l in 1..self.levels.len() {
            let (x, y) = self.levels.split_at_mut(l);
            (a, b) = coarsen_rows(&x[l - 1], &mut y[0], a, b);
        }
        Some(change)
    }

    /// Full multigrid on the correction equation. The free samples of the finest level start
    /// from the transfinite (Coons) interpolation of the border heights, which matches the border
    /// and is smooth, so the remaining correction has no boundary layer; its right-hand side (the
    /// residual of that start) is restricted to every level, the coarsest level is solved by
    /// sweeps, and each level's correction is interpolated bilinearly to the next finer one and
    /// improved by `fmg_cycles` cycles there; the finest level adds it.
    fn full_multigrid(&mut self) {
        let n = self.levels.len();
        coons_start(&mut self.levels[0]);
        if n == 1 {
            return;
        }
        {
            let (a, b) = self.levels.split_at_mut(1);
            residual_restrict(&a[0], &mut b[0]);
        }
        for l in 2..n {
            let (a, b) = self.levels.split_at_mut(l);
            restrict_rhs(&a[l - 1], &mut b[0]);
        }
        self.levels[n - 1].zero_h();
        smooth(&mut self.levels[n - 1], COARSEST_SWEEPS);
        for l in (0..n - 1).rev() {
            let (a, b) = self.levels.split_at_mut(l + 1);
            if l == 0 {
                prolong::<true>(&b[0], &mut a[0], &mut self.scratch);
            } else {
                a[l].zero_h();
                prolong::<false>(&b[0], &mut a[l], &mut self.scratch);
                for _ in 0..self.options.fmg_cycles {
                    cycle(&mut self.levels, l, &self.options, &mut self.scratch, false);
                }
            }
        }
    }

    /// Finest-level cycles until the tolerance or the cycle cap. Returns the cycle count, the
    /// relative residual history and the finishing sweeps run first (only `after_local`: see
    /// [`SolveReport::finishing_sweeps`]).
    fn cycles(&mut self, bnorm: f64, after_local: bool) -> (usize, Vec<f64>, usize) {
        let o = self.options;
        let mut history = Vec::new();
        let mut sweeps = 0;
        if after_local && self.levels.len() > 1 {
            loop {
                let rel = residual_norm2(&self.levels[0]).sqrt() / bnorm;
                history.push(rel);
                if rel <= o.tolerance
                    || rel > local::LOCAL_FINISH_RANGE * o.tolerance
                    || sweeps == local::LOCAL_FINISH_SWEEPS
                {
                    break;
                }
                smooth(&mut self.levels[0], 1);
                sweeps += 1;
            }
            if history[history.len() - 1] <= o.tolerance {
                return (0, history, sweeps);
            }
            history.pop();
        }
        let (done, tail) = self.cycles_from(bnorm);
        history.extend(tail);
        (done, history, sweeps)
    }

    fn cycles_from(&mut self, bnorm: f64) -> (usize, Vec<f64>) {
        let o = self.options;
        if o.acceleration == Acceleration::ConjugateGradient && self.levels.len() > 1 {
            return self.conjugate_gradients(bnorm, o.max_cycles);
        }
        let auto = o.acceleration == Acceleration::Auto;
        let mut history = Vec::new();
        let mut done = 0;
        if self.levels.len() == 1 {
            let l = &mut self.levels[0];
            let mut r = [vec![0.0; l.split.len()], vec![0.0; l.split.len()]];
            loop {
                let rel = residual(l, &mut r).sqrt() / bnorm;
                history.push(rel);
                if rel <= o.tolerance || done == o.max_cycles || self.cancel.is_cancelled() {
                    return (done, history);
                }
                smooth(l, o.pre_smooth + o.post_smooth);
                done += 1;
            }
        }
        loop {
            let (a, b) = self.levels.split_at_mut(1);
            let rel = residual_restrict(&a[0], &mut b[0]).sqrt() / bnorm;
            history.push(rel);
            if rel <= o.tolerance || done == o.max_cycles || self.cancel.is_cancelled() {
                return (done, history);
            }
            let slow = done > 0 && rel > AUTO_SWITCH_FACTOR * history[history.len() - 2];
            if auto && slow {
                // Continue from the current iterate with conjugate gradients.
                let (more, tail) = self.conjugate_gradients(bnorm, o.max_cycles - done);
                history.extend_from_slice(&tail[1..]);
                return (done + more, history);
            }
            b[0].zero_h();
            for _ in 0..gamma(o.cycle) {
                cycle(&mut self.levels, 1, &o, &mut self.scratch, false);
            }
            let (a, b) = self.levels.split_at_mut(1);
            prolong::<true>(&b[0], &mut a[0], &mut self.scratch);
            smooth(&mut a[0], o.pre_smooth + o.post_smooth);
            done += 1;
        }
    }
}

impl Solver {
    /// Conjugate gradients on `K h = −b` (`K = −A`, symmetric positive definite over the free
    /// samples), preconditioned by one symmetric cycle (pre-smoothing red→black, post-smoothing
    /// black→red, restriction = prolongationᵀ). The residual kept is `r = b − A h = −(−b − K h)`.
    fn conjugate_gradients(&mut self, bnorm: f64, max_cycles: usize) -> (usize, Vec<f64>) {
        let o = self.options;
        let mut kr = match self.krylov.take() {
            Some(k) if k.zl.grid == self.levels[0].grid => k,
            _ => Krylov::new(&self.levels[0]),
        };
        kr.zl.free.clone_from(&self.levels[0].free);
        let mut history = Vec::new();
        let mut done = 0;
        let rr = residual(&self.levels[0], &mut kr.zl.rhs);
        history.push(rr.sqrt() / bnorm);
        if history[0] <= o.tolerance || max_cycles == 0 {
            self.krylov = Some(kr);
            return (0, history);
        }
        precondition(&mut kr.zl, &mut self.levels, &o, &mut self.scratch);
        kr.p.clone_from(&kr.zl.h);
        let mut rho = -dot(&kr.zl.rhs, &kr.zl.h);
        loop {
            let pq = apply_operator(&self.levels[0], &kr.p, &mut kr.q);
            if !(pq > 0.0 && rho.is_finite()) {
                break;
            }
            let alpha = rho / pq;
            let rr = update_solution(&mut self.levels[0].h, &mut kr.zl.rhs, &kr.p, &kr.q, alpha);
            done += 1;
            let rel = rr.sqrt() / bnorm;
            history.push(rel);
            if rel <= o.tolerance || done == max_cycles || self.cancel.is_cancelled() {
                break;
            }
            precondition(&mut kr.zl, &mut self.levels, &o, &mut self.scratch);
            let next = -dot(&kr.zl.rhs, &kr.zl.h);
            let beta = next / rho;
            rho = next;
            update_direction(&mut kr.p, &kr.zl.h, beta);
        }
        self.krylov = Some(kr);
        (done, history)
    }
}

/// Work arrays of the conjugate gradients on the finest level: `zl` holds the preconditioned
/// residual `z` (its unknowns) and the residual `r` (its right-hand side) with the finest mask;
/// `p` is the search direction and `q = K p`.
#[derive(Debug)]
struct Krylov {
    zl: Level,
    p: [Vec<f64>; 2],
    q: [Vec<f64>; 2],
}

impl Krylov {
    fn new(finest: &Level) -> Self {
        let n = finest.split.len();
        Self {
            zl: Level::new(finest.grid),
            p: [vec![0.0; n], vec![0.0; n]],
            q: [vec![0.0; n], vec![0.0; n]],
        }
    }
}

/// `zl.h ← M zl.rhs`: one symmetric cycle from zero on the finest-level correction `zl`, with
/// the coarse levels of `levels`.
fn precondition(zl: &mut Level, levels: &mut [Level], o: &SolveOptions, scratch: &mut Vec<f64>) {
    zl.zero_h();
    smooth(zl, o.pre_smooth);
    residual_restrict(zl, &mut levels[1]);
    levels[1].zero_h();
    for _ in 0..gamma(o.cycle) {
        cycle(levels, 1, o, scratch, true);
    }
    prolong::<true>(&levels[1], zl, scratch);
    smooth_reverse(zl, o.post_smooth);
}

/// Sets the free samples of `level` (the finest) to the transfinite interpolation of its border
/// values: `H(x, z) = (1 − x) h(0, z) + x h(1, z) + (1 − z) h(x, 0) + z h(x, 1)` minus the bilinear
/// interpolation of the four corners (`x`, `z` in `[0, 1]` across the grid).
fn coons_start(level: &mut Level) {
    let g = level.grid;
    let (nx, nz) = (g.nx, g.nz);
    let west: Vec<f64> = (0..nz).map(|j| level.value(0, j)).collect();
    let east: Vec<f64> = (0..nz).map(|j| level.value(nx - 1, j)).collect();
    let north: Vec<f64> = (0..nx).map(|i| level.value(i, 0)).collect();
    let south: Vec<f64> = (0..nx).map(|i| level.value(i, nz - 1)).collect();
    let (c00, c10, c01, c11) = (north[0], north[nx - 1], south[0], south[nx - 1]);
    let st = level.split.stride;
    for c in 0..2 {
        let (h, f) = (&mut level.h[c], &level.free[c]);
        for j in 1..nz - 1 {
            let z = j as f64 / (nz - 1) as f64;
            let s = Split::shift(c, j);
            for k in 0..st {
                let slot = j * st + k;
                if f[slot] == 0 {
                    continue;
                }
                let i = 2 * k + s;
                let x = i as f64 / (nx - 1) as f64;
                let edges = (1.0 - x) * west[j] + x * east[j] + (1.0 - z) * north[i] + z * south[i];
                let corners = (1.0 - x) * (1.0 - z) * c00
                    + x * (1.0 - z) * c10
                    + (1.0 - x) * z * c01
                    + x * z * c11;
                h[slot] = edges - corners;
            }
        }
    }
}

pub(crate) fn gamma(c: Cycle) -> usize {
    match c {
        Cycle::V => 1,
        Cycle::W => 2,
    }
}

/// One cycle on level `l` (≥ 1 in the correction cycles): pre-smoothing, residual restriction,
/// coarse-grid correction (recursively), prolongation, post-smoothing. The coarsest level is
/// solved by [`COARSEST_SWEEPS`] sweeps.
///
/// With `symmetric`, post-smoothing runs black→red (the adjoint of the pre-smoother), as the
/// conjugate-gradient preconditioner needs; plain cycles smooth red→black both times, which
/// converges faster after bilinear prolongation.
pub(crate) fn cycle(
    levels: &mut [Level],
    l: usize,
    o: &SolveOptions,
    scratch: &mut Vec<f64>,
    symmetric: bool,
) {
    if l + 1 == levels.len() {
        smooth(&mut levels[l], COARSEST_SWEEPS);
        return;
    }
    smooth(&mut levels[l], o.pre_smooth);
    {
        let (a, b) = levels.split_at_mut(l + 1);
        residual_restrict(&a[l], &mut b[0]);
        b[0].zero_h();
    }
    for _ in 0..gamma(o.cycle) {
        cycle(levels, l + 1, o, scratch, symmetric);
    }
    let (a, b) = levels.split_at_mut(l + 1);
    prolong::<true>(&b[0], &mut a[l], scratch);
    if symmetric {
        smooth_reverse(&mut a[l], o.post_smooth);
    } else {
        smooth(&mut a[l], o.post_smooth);
    }
}
