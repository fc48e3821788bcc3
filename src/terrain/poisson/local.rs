//! Localized warm re-solve after a small edit: correction cycles whose fine levels only work in
//! windows around the change, in the spirit of the fast adaptive composite-grid method (FAC:
//! McCormick & Thomas, *The fast adaptive composite grid method for elliptic equations*, Math.
//! Comp. 46, 1986) on our Galerkin hierarchy.
//!
//! Why one file of about 840 lines: the windows, their precomputed transfers and the composite
//! cycle described below are one algorithm over the private `Win` type, whose invariant (a window
//! covers the finer one and its ring) every part relies on; splitting it would expose those
//! internals to the rest of the solver.
//!
//! After an edit, the solver knows where the right-hand side, the fixed heights or the mask
//! changed (a rectangle of the finest level, see [`super::Solver`]). The correction `E` that
//! takes the previous solution to the new one solves `A E = r₀`, `r₀` the residual of the previous
//! solution for the new problem: large near the change, and elsewhere the previous solve's
//! residual (below the tolerance, left as it is). `E` is not local (a Green's function decays
//! slowly), but far from the change it is smooth, so coarse levels represent it well there.
//!
//! # Windows
//! The active window of the finest level is the change dilated by one sample (the residual of a
//! changed fixed height reaches its neighbours) and by [`LOCAL_MARGIN`]; each coarser level's
//! window covers the finer one's (with its one-sample ring) plus [`LOCAL_MARGIN`] of its own
//! samples, so in fine samples the margins double per level. The first level whose window would
//! cover a quarter of it (or the coarsest) is *full*: it and every coarser level run the ordinary
//! kernels of [`super::ops`]. If the finest window covers more than [`LOCAL_MAX_FRACTION`] of the
//! grid, the solver runs global cycles instead.
//!
//! # Composite correction
//! The correction is represented on the composite grid: the finest level's values in its window
//! (with the ring), each coarser level's accumulated correction `D_l` in its window, and `D_k` on
//! the full level `k`; outside a level's window, a level takes the bilinear interpolation `P` of
//! the next coarser one. One local cycle is a V-cycle on this composite problem:
//! - finest level: the residual `b − A h` in its window (its ring holds the interpolated coarse
//!   correction of the earlier cycles);
//! - level `l ≥ 1`: the right-hand side is `Pᵀ` of the finer level's residual where the finer
//!   window covers all nine fine samples of the restriction, and the composite residual
//!   `R_l − A_l D_l` elsewhere, with `R_l` the restriction of the initial residual `r₀` (zero
//!   outside the finest window) and `A_l` the Galerkin operator (so that, away from finer windows,
//!   `Pᵀ (r₀ − A P D_l) = R_l − A_l D_l`); pre-smoothing in the window from a zero correction,
//!   then the residual for the next level;
//! - the full level `k` runs [`super::multigrid`]'s cycle (V or W) on its composite right-hand
//!   side;
//! - going up: each level adds `P` of the coarser correction in its window and ring,
//!   post-smooths in its window and adds its correction to `D_l`; the finest level adds it to the
//!   heights and smooths (`pre_smooth + post_smooth` red-black sweeps, as the global cycle).
//!
//! Bilinear interpolation of the far correction leaves a residual proportional to its second
//! derivatives (a smooth field interpolated bilinearly has kinks along the coarse grid lines), so
//! the write-back smooths a band around each level's window: [`LOCAL_BAND`] samples around the
//! finest window (two red-black sweeps with `b`) and [`LOCAL_COARSE_BAND`] samples of level 1
//! around its window, halving per coarser level (one four-colour sweep of the correction outside
//! the window, where its right-hand side is zero). Measured on a 32-sample brush at nine positions
//! (`strata bench poisson`), the global relative residual after the write-back, the previous
//! solve's residual (5–8e-7) included, is 5.0–8.6e-7 at 513², 5.6–7.4e-7 at 1025² and 8.3e-7 at
//! 2049², under the tolerance, so no finishing sweep runs. With bands of 96 and 48 samples (two
//! sweeps on every level) it reached 1.5e-6 at 513², and a third of the positions needed a
//! finishing sweep of the whole grid, which costs more than the wider bands. (Larger margins,
//! FAC injection of the fine correction into the coarse one under the window, and full-level
//! smoothing of the coarse corrections each moved it by less than 25 % in our trials.)
//!
//! The windows' transfers are precomputed once per re-solve ([`link`]: `P` at every free window
//! sample and its transpose), and their buffers are kept between re-solves ([`LocalScratch`]).
//!
//! Local cycles run until an estimate of the global residual, `‖r_window‖² + Σ_l ‖ρ_l‖² / 4^l`
//! (`ρ_l` the composite residual of level `l` outside the finer window; a coarse residual value
//! stands for about `4^l` fine residuals of `1/4^l` of its size), is at most [`LOCAL_TARGET`]
//! times the tolerance, or [`LOCAL_MAX_CYCLES`]. Then the corrections are interpolated down the
//! hierarchy to the whole finest level (one prolongation per level) and the solver measures the
//! true global relative residual `‖b − A h‖ / ‖b‖`; if it is above the tolerance but within
//! [`LOCAL_FINISH_RANGE`] times it, up to [`LOCAL_FINISH_SWEEPS`] red-black sweeps of the whole
//! finest level follow (the interpolation residual is high-frequency across the coarse grid lines,
//! which a sweep damps: at 513² with a 96-sample band, one sweep took 1.5e-6 to 6.7e-7, for the
//! cost of a fraction of a global cycle), and if it is still above, global cycles continue from
//! there. The window kernels are sequential, the band sweeps update samples of one colour (and
//! row parity) that do not depend on each other, and the full levels use the deterministic
//! kernels, so results do not depend on the thread count.

use super::galerkin::{entry, interpolation_weight, FIVE_POINT};
use super::grid::Split;
use super::level::Level;
use super::multigrid::{cycle, gamma, SolveOptions};
use super::ops::{prolong, smooth_nine_spans};
use rayon::prelude::*;

/// Margin of every level's window around the finer window, in that level's samples.
pub const LOCAL_MARGIN: usize = 8;
/// Width of the band around the finest window smoothed after the write-back, in finest samples:
/// bilinear interpolation of the far correction leaves a residual proportional to its second
/// derivatives, largest next to the window.
pub const LOCAL_BAND: usize = 160;
/// Red-black sweeps over the finest band.
pub const LOCAL_BAND_SWEEPS: usize = 2;
/// Width of the band around the window of level 1, in its samples; it halves on every coarser
/// level (the same width in finest samples, where the correction is smoother).
pub const LOCAL_COARSE_BAND: usize = 96;
/// Four-colour sweeps over each coarse band.
pub const LOCAL_COARSE_BAND_SWEEPS: usize = 1;
/// The largest share of the finest grid the finest window may cover for a local re-solve.
pub const LOCAL_MAX_FRACTION: f64 = 0.125;
/// The most local cycles of one re-solve (then global cycles take over if needed).
pub const LOCAL_MAX_CYCLES: usize = 8;
/// Local cycles stop when the estimated relative residual is at most this times the tolerance.
/// The global residual after the write-back is dominated by the previous solve's residual and the
/// write-back's interpolation residual, not by the window: on a 32-sample brush at nine positions
/// of 513² (`strata bench poisson`), cycles cut the estimate about 13× each and two of them end
/// at 0.87–1.06 × 0.25, so with a target of 0.25 four positions ran a third cycle (+15 % of the
/// re-solve) that moved the global residual by less than 6 % (5.0–8.6e-7 either way). Where the
/// sum does exceed the tolerance, the check after the write-back catches it
/// ([`LOCAL_FINISH_RANGE`]).
pub const LOCAL_TARGET: f64 = 0.4;
/// After the write-back, if the measured global relative residual is above the tolerance but at
/// most this times it, the solver first runs red-black sweeps of the whole finest level (up to
/// [`LOCAL_FINISH_SWEEPS`]) instead of global cycles: the interpolation residual of the
/// write-back is concentrated along the coarse grid lines (kinks of the bilinear interpolation),
/// which a sweep damps, at a fraction of a cycle's cost.
pub const LOCAL_FINISH_RANGE: f64 = 4.0;
/// The most finishing sweeps after a local re-solve (then global cycles take over if needed).
pub const LOCAL_FINISH_SWEEPS: usize = 2;

/// A rectangle of samples of one level, bounds included.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    /// First column.
    pub i0: usize,
    /// First row.
    pub j0: usize,
    /// Last column.
    pub i1: usize,
    /// Last row.
    pub j1: usize,
}

impl Rect {
    /// The rectangle of one sample.
    pub fn point(i: usize, j: usize) -> Self {
        Self {
            i0: i,
            j0: j,
            i1: i,
            j1: j,
        }
    }

    /// The smallest rectangle holding the spans `(i0, i1)` of rows `j0, j0 + 1, …` (`None`: the
    /// row holds nothing), or `None` when no row does.
    pub fn of_row_spans(j0: usize, spans: &[Option<(usize, usize)>]) -> Option<Self> {
        spans
            .iter()
            .enumerate()
            .filter_map(|(dj, s)| {
                s.map(|(i0, i1)| Self {
                    i0,
                    j0: j0 + dj,
                    i1,
                    j1: j0 + dj,
                })
            })
            .reduce(Self::union)
    }

    /// The smallest rectangle holding both.
    pub fn union(self, o: Self) -> Self {
        Self {
            i0: self.i0.min(o.i0),
            j0: self.j0.min(o.j0),
            i1: self.i1.max(o.i1),
            j1: self.j1.max(o.j1),
        }
    }

    /// Grown by `m` samples on every side, clipped to an `nx × nz` grid.
    pub fn dilate(self, m: usize, nx: usize, nz: usize) -> Self {
        Self {
            i0: self.i0.saturating_sub(m),
            j0: self.j0.saturating_sub(m),
            i1: (self.i1 + m).min(nx - 1),
            j1: (self.j1 + m).min(nz - 1),
        }
    }

    /// The coarse samples whose interpolation reaches this rectangle of the finer level.
    pub fn coarsen(self) -> Self {
        Self {
            i0: self.i0 / 2,
            j0: self.j0 / 2,
            i1: self.i1.div_ceil(2),
            j1: self.j1.div_ceil(2),
        }
    }

    /// Columns.
    pub fn width(&self) -> usize {
        self.i1 - self.i0 + 1
    }

    /// Samples.
    pub fn area(&self) -> usize {
        self.width() * (self.j1 - self.j0 + 1)
    }

    fn full(nx: usize, nz: usize) -> Self {
        Self {
            i0: 0,
            j0: 0,
            i1: nx - 1,
            j1: nz - 1,
        }
    }
}

/// Buffers of the windows, kept by the solver between local re-solves so that a re-solve
/// reuses them instead of allocating.
#[derive(Default)]
pub struct LocalScratch {
    wins: Vec<Win>,
}

impl std::fmt::Debug for LocalScratch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LocalScratch")
            .field("windows", &self.wins.len())
            .field("bytes", &self.bytes())
            .finish()
    }
}

impl LocalScratch {
    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.wins
            .iter()
            .map(|w| {
                8 * (w.c.capacity()
                    + w.rho.capacity()
                    + w.s.capacity()
                    + w.d.capacity()
                    + w.r.capacity())
                    + w.free.capacity()
                    + w.inner.capacity()
                    + std::mem::size_of::<u32>() * w.special_of.capacity()
                    + std::mem::size_of::<[f64; 9]>() * w.specials.capacity()
                    + std::mem::size_of::<Restriction>() * w.restr.capacity()
                    + std::mem::size_of::<Prolongation>() * w.prol.capacity()
            })
            .sum()
    }
}

/// What a local re-solve did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalOutcome {
    /// Local cycles run.
    pub cycles: usize,
    /// Samples relaxed in the windows (the full levels count in their [`Level::relaxed`]).
    pub relaxed: u64,
}

/// One level's window: natural-order arrays over `ext` (the active window and its ring).
struct Win {
    act: Rect,
    ext: Rect,
    free: Vec<bool>,
    /// The level's default stencil (coarse levels; the finest level is 5-point, see `five`).
    default: [f64; 9],
    /// Per sample: 0 for the default stencil, else `1 +` its index in `specials`.
    special_of: Vec<u32>,
    /// The special stencils of the window's samples (next to constraints).
    specials: Vec<[f64; 9]>,
    /// True where the finer level's window covers the restriction of this sample.
    inner: Vec<bool>,
    /// This cycle's correction (on the finest level: the heights).
    c: Vec<f64>,
    /// This cycle's right-hand side (on the finest level: `b`).
    rho: Vec<f64>,
    /// The residual after pre-smoothing (on the finest level: of the heights).
    s: Vec<f64>,
    /// The accumulated correction `D_l`.
    d: Vec<f64>,
    /// The restriction `R_l` of the initial residual.
    r: Vec<f64>,
    /// True on the finest level, whose operator is the 5-point Laplacian everywhere.
    five: bool,
    /// `Pᵀ` from the finer window, precomputed: one entry per free active sample whose
    /// restriction reads the finer level's active window ([`link`]).
    restr: Vec<Restriction>,
    /// `P` from the coarser window, precomputed: one entry per free sample of the window and
    /// its ring ([`link`]).
    prol: Vec<Prolongation>,
}

/// The taps of `Pᵀ` at one coarse window sample: the fine samples of its 3 × 3 neighbourhood
/// in the finer active window (index in the finer window, interpolation weight), in the order
/// row by row, zero weights where a sample is outside the finer window or blocked.
struct Restriction {
    at: usize,
    inner: bool,
    taps: [(usize, f64); 9],
}

/// The taps of `P` at one fine window sample: its one, two or four coarse samples (index in the
/// coarser window, interpolation weight), row by row, padded with zero weights.
struct Prolongation {
    at: usize,
    taps: [(usize, f64); 4],
}

/// `Σ w · v[i]` over the taps, in their order.
#[inline]
fn tap_sum<const N: usize>(taps: &[(usize, f64); N], v: &[f64]) -> f64 {
    taps.iter().fold(0.0, |sum, &(i, w)| sum + w * v[i])
}

impl Win {
    /// A window of no samples, to be [`Win::reset`].
    fn empty() -> Self {
        Self {
            act: Rect::point(0, 0),
            ext: Rect::point(0, 0),
            free: Vec::new(),
            default: FIVE_POINT,
            special_of: Vec::new(),
            specials: Vec::new(),
            inner: Vec::new(),
            c: Vec::new(),
            rho: Vec::new(),
            s: Vec::new(),
            d: Vec::new(),
            r: Vec::new(),
            five: true,
            restr: Vec::new(),
            prol: Vec::new(),
        }
    }

    /// Makes this the window `act` of `level` (`finer`: the finer level's active window), reusing
    /// the buffers: zero fields, the mask and the stencils read from the level, no transfers.
    fn reset(&mut self, level: &Level, act: Rect, finer: Option<Rect>) {
        let g = level.grid;
        let ext = act.dilate(1, g.nx, g.nz);
        let n = ext.area();
        (self.act, self.ext, self.five) = (act, ext, level.nine.is_none());
        for v in [
            &mut self.c,
            &mut self.rho,
            &mut self.s,
            &mut self.d,
            &mut self.r,
        ] {
            v.clear();
            v.resize(n, 0.0);
        }
        for v in [&mut self.free, &mut self.inner] {
            v.clear();
            v.resize(n, false);
        }
        self.special_of.clear();
        self.special_of.resize(n, 0);
        self.specials.clear();
        self.default = level.nine.as_ref().map_or(FIVE_POINT, |op| op.default);
        self.restr.clear();
        self.prol.clear();
        for j in ext.j0..=ext.j1 {
            for i in ext.i0..=ext.i1 {
                let x = self.idx(i, j);
                let (c, k) = level.split.locate(i, j);
                self.free[x] = level.free[c][k] != 0;
                self.inner[x] = finer
                    .is_some_and(|f| 2 * i > f.i0 && 2 * i < f.i1 && 2 * j > f.j0 && 2 * j < f.j1);
            }
            if let Some(op) = &level.nine {
                for sp in op.row(j) {
                    let i = 2 * (sp.slot - j * level.split.stride)
                        + super::grid::Split::shift(sp.colour, j);
                    if (ext.i0..=ext.i1).contains(&i) {
                        let x = self.idx(i, j);
                        self.specials.push(sp.stencil);
                        self.special_of[x] = self.specials.len() as u32;
                    }
                }
            }
        }
    }

    #[inline]
    fn idx(&self, i: usize, j: usize) -> usize {
        (j - self.ext.j0) * self.ext.width() + (i - self.ext.i0)
    }

    /// The off-centre terms of `(A v)(i, j)` with this level's stencil (on the finest level the
    /// four edge neighbours, `(w + e) + (u + d)`, the order of the global kernels).
    #[inline]
    fn off_centre(&self, v: &[f64], x: usize) -> f64 {
        let w = self.ext.width();
        let (up, down) = (x - w, x + w);
        if self.five {
            return (v[x - 1] + v[x + 1]) + (v[up] + v[down]);
        }
        let st = self.stencil(x);
        ((st[entry(-1, 0)] * v[x - 1] + st[entry(1, 0)] * v[x + 1])
            + (st[entry(0, -1)] * v[up] + st[entry(0, 1)] * v[down]))
            + ((st[entry(-1, -1)] * v[up - 1] + st[entry(1, -1)] * v[up + 1])
                + (st[entry(-1, 1)] * v[down - 1] + st[entry(1, 1)] * v[down + 1]))
    }

    /// The stencil at window index `x` (coarse levels).
    #[inline]
    fn stencil(&self, x: usize) -> &[f64; 9] {
        match self.special_of[x] {
            0 => &self.default,
            k => &self.specials[k as usize - 1],
        }
    }

    /// The centre weight of the stencil at window index `x`.
    #[inline]
    fn centre(&self, x: usize) -> f64 {
        if self.five {
            -4.0
        } else {
            self.stencil(x)[4]
        }
    }

    /// `(A v)` at window index `x`.
    #[inline]
    fn apply(&self, v: &[f64], x: usize) -> f64 {
        self.off_centre(v, x) + self.centre(x) * v[x]
    }

    /// Gauss–Seidel sweeps on `c` in the active window: red-black on the finest level, the four
    /// colours (colour, row parity) of the global smoother on coarse levels. Returns the samples
    /// relaxed.
    fn smooth(&mut self, sweeps: usize, finest: bool) -> u64 {
        let a = self.act;
        let groups: &[(usize, Option<usize>)] = if finest {
            &[(0, None), (1, None)]
        } else {
            &[(0, Some(0)), (0, Some(1)), (1, Some(0)), (1, Some(1))]
        };
        for _ in 0..sweeps {
            for &(colour, parity) in groups {
                for j in a.j0..=a.j1 {
                    if parity.is_some_and(|p| j % 2 != p) {
                        continue;
                    }
                    let first = a.i0 + ((a.i0 + j + colour) & 1);
                    let mut x = self.idx(first, j);
                    for _ in (first..=a.i1).step_by(2) {
                        if self.free[x] {
                            self.c[x] =
                                (self.rho[x] - self.off_centre(&self.c, x)) / self.centre(x);
                        }
                        x += 2;
                    }
                }
            }
        }
        (sweeps * a.area()) as u64
    }

    /// `s = rho − A c` in the active window (zero at fixed samples); returns `‖s‖²`.
    fn residual(&mut self) -> f64 {
        let a = self.act;
        let mut ss = 0.0;
        for j in a.j0..=a.j1 {
            for i in a.i0..=a.i1 {
                let x = self.idx(i, j);
                let v = if self.free[x] {
                    self.rho[x] - self.apply(&self.c, x)
                } else {
                    0.0
                };
                self.s[x] = v;
                ss += v * v;
            }
        }
        ss
    }

    /// The composite residual `R − A D` at the active samples the finer window does not cover,
    /// into `rho`; returns its squared norm.
    fn outer_residual(&mut self) -> f64 {
        let a = self.act;
        let mut ss = 0.0;
        for j in a.j0..=a.j1 {
            for i in a.i0..=a.i1 {
                let x = self.idx(i, j);
                if self.inner[x] {
                    continue;
                }
                let v = if self.free[x] {
                    self.r[x] - self.apply(&self.d, x)
                } else {
                    0.0
                };
                self.rho[x] = v;
                ss += v * v;
            }
        }
        ss
    }
}

/// Precomputes the transfers between the windows of levels `l` (`fine`, on `fine_level`) and
/// `l + 1` (`coarse`): `P` of the coarse window at the free samples of the fine window and ring
/// (which the coarse active window covers), and its transpose `Pᵀ` of the fine active window at
/// the coarse samples it reaches. (Fixed fine samples are left out of `Pᵀ`: the fields restricted
/// are residuals, zero there.)
fn link(fine_level: &Level, fine: &mut Win, coarse: &mut Win) {
    let (e, a) = (fine.ext, fine.act);
    fine.prol.reserve(e.area());
    // `entry_of[x]`: the index in `coarse.restr` of coarse window sample `x`, if any.
    let mut entry_of = vec![usize::MAX; coarse.c.len()];
    for j in e.j0..=e.j1 {
        for i in e.i0..=e.i1 {
            let x = fine.idx(i, j);
            if !fine.free[x] {
                continue;
            }
            // The coarse samples `(i / 2 + di, j / 2 + dj)` with their bilinear weights; only an
            // odd-odd sample can have a blocked corner.
            let (ci, cj) = (i / 2, j / 2);
            let w = |di: usize, dj: usize| interpolation_weight(fine_level, i, j, ci + di, cj + dj);
            let near: [(usize, usize, f64); 4] = match (i % 2, j % 2) {
                (0, 0) => [(0, 0, 1.0), (0, 0, 0.0), (0, 0, 0.0), (0, 0, 0.0)],
                (1, 0) => [(0, 0, 0.5), (1, 0, 0.5), (0, 0, 0.0), (0, 0, 0.0)],
                (0, _) => [(0, 0, 0.5), (0, 1, 0.5), (0, 0, 0.0), (0, 0, 0.0)],
                _ => [
                    (0, 0, w(0, 0)),
                    (1, 0, w(1, 0)),
                    (0, 1, w(0, 1)),
                    (1, 1, w(1, 1)),
                ],
            };
            let taps = near.map(|(di, dj, w)| (coarse.idx(ci + di, cj + dj), w));
            fine.prol.push(Prolongation { at: x, taps });
            if i < a.i0 || i > a.i1 || j < a.j0 || j > a.j1 {
                continue;
            }
            // The transpose: the tap of fine sample `(2 ic + dx, 2 jc + dz)` is entry
            // `(dz + 1) · 3 + dx + 1` of coarse sample `(ic, jc)`.
            for (&(di, dj, w), &(cx, _)) in near.iter().zip(&taps) {
                if w == 0.0 || !coarse.free[cx] {
                    continue;
                }
                if entry_of[cx] == usize::MAX {
                    entry_of[cx] = coarse.restr.len();
                    coarse.restr.push(Restriction {
                        at: cx,
                        inner: coarse.inner[cx],
                        taps: [(0, 0.0); 9],
                    });
                }
                let (ic, jc) = (ci + di, cj + dj);
                let t = (j + 1 - 2 * jc) * 3 + (i + 1 - 2 * ic);
                coarse.restr[entry_of[cx]].taps[t] = (x, w);
            }
        }
    }
}

/// Adds `P` of `coarse.c` to `fine.c` at the free samples of the fine window and ring.
fn prolong_window(fine: &mut Win, coarse: &Win) {
    for p in &fine.prol {
        fine.c[p.at] += tap_sum(&p.taps, &coarse.c);
    }
}

/// The windows of a change of the finest level: the active rectangles of levels `0..=k`, the
/// last one full. `None` if the finest window is too large or there is a single level.
fn windows(levels: &[Level], change: Rect) -> Option<Vec<Rect>> {
    if levels.len() < 2 {
        return None;
    }
    let g = levels[0].grid;
    let act = change.dilate(1 + LOCAL_MARGIN, g.nx, g.nz);
    if act.area() as f64 > LOCAL_MAX_FRACTION * g.len() as f64 {
        return None;
    }
    let mut acts = vec![act];
    for l in 1..levels.len() {
        let (fg, cg) = (levels[l - 1].grid, levels[l].grid);
        let full = Rect::full(cg.nx, cg.nz);
        let a = acts[l - 1]
            .dilate(1, fg.nx, fg.nz)
            .coarsen()
            .dilate(LOCAL_MARGIN, cg.nx, cg.nz);
        if l + 1 == levels.len() || 4 * a.area() >= full.area() {
            acts.push(full);
            break;
        }
        acts.push(a);
    }
    Some(acts)
}

/// Runs local cycles for a change of the finest level inside `change`, then writes the composite
/// correction to every finest sample. `levels[0]` holds the previous solution and the new
/// right-hand side and mask. Returns `None` (nothing done) when the change is too large for a
/// local re-solve. `tolerance_abs` is the tolerance times `‖b‖`; `cache` holds the window
/// buffers between calls.
pub fn resolve(
    levels: &mut [Level],
    change: Rect,
    o: &SolveOptions,
    scratch: &mut Vec<f64>,
    cache: &mut LocalScratch,
    tolerance_abs: f64,
) -> Option<LocalOutcome> {
    let acts = windows(levels, change)?;
    let k = acts.len() - 1;
    if cache.wins.len() <= k {
        cache.wins.resize_with(k + 1, Win::empty);
    }
    let wins = &mut cache.wins[..=k];
    wins.par_iter_mut()
        .enumerate()
        .for_each(|(l, w)| w.reset(&levels[l], acts[l], (l > 0).then(|| acts[l - 1])));
    for l in 0..k {
        let (a, b) = wins.split_at_mut(l + 1);
        link(&levels[l], &mut a[l], &mut b[0]);
    }
    {
        let (l0, w0) = (&levels[0], &mut wins[0]);
        for j in w0.ext.j0..=w0.ext.j1 {
            for i in w0.ext.i0..=w0.ext.i1 {
                let (c, s) = l0.split.locate(i, j);
                let x = w0.idx(i, j);
                w0.c[x] = l0.h[c][s];
                w0.rho[x] = l0.rhs[c][s];
            }
        }
    }
    let target = LOCAL_TARGET * tolerance_abs;
    let mut out = LocalOutcome {
        cycles: 0,
        relaxed: 0,
    };
    loop {
        let mut est = wins[0].residual();
        if out.cycles == 0 {
            let w0 = &mut wins[0];
            w0.r.clone_from(&w0.s);
            for l in 1..=k {
                let (a, b) = wins.split_at_mut(l);
                let (fine, coarse) = (&a[l - 1], &mut b[0]);
                for t in &coarse.restr {
                    coarse.r[t.at] = tap_sum(&t.taps, &fine.r);
                }
            }
        }
        let mut scale = 1.0;
        for w in wins.iter_mut().skip(1) {
            scale *= 0.25;
            est += scale * w.outer_residual();
        }
        if est.sqrt() <= target || out.cycles == LOCAL_MAX_CYCLES {
            break;
        }
        // Down: restricted residuals inside the finer windows, pre-smoothing in the windows.
        for l in 1..=k {
            let (a, b) = wins.split_at_mut(l);
            let (fine, coarse) = (&a[l - 1], &mut b[0]);
            // Every free inner sample has taps (its centre is in the finer window); the fixed
            // ones keep `rho = 0`.
            for t in coarse.restr.iter().filter(|t| t.inner) {
                coarse.rho[t.at] = tap_sum(&t.taps, &fine.s);
            }
            if l < k {
                coarse.c.fill(0.0);
                out.relaxed += coarse.smooth(o.pre_smooth, false);
                coarse.residual();
            }
        }
        // The full level: the ordinary cycle on its composite right-hand side.
        {
            let (lk, wk) = (&mut levels[k], &mut wins[k]);
            for j in 0..lk.grid.nz {
                for i in 0..lk.grid.nx {
                    let (c, s) = lk.split.locate(i, j);
                    let x = wk.idx(i, j);
                    lk.rhs[c][s] = if wk.free[x] { wk.rho[x] } else { 0.0 };
                }
            }
            lk.zero_h();
        }
        for _ in 0..gamma(o.cycle) {
            cycle(levels, k, o, scratch, false);
        }
        {
            let (lk, wk) = (&levels[k], &mut wins[k]);
            for j in 0..lk.grid.nz {
                for i in 0..lk.grid.nx {
                    let (c, s) = lk.split.locate(i, j);
                    let x = wk.idx(i, j);
                    wk.c[x] = lk.h[c][s];
                    wk.d[x] += wk.c[x];
                }
            }
        }
        // Up: prolongation into the windows and rings, post-smoothing, accumulation.
        for l in (0..k).rev() {
            let (a, b) = wins.split_at_mut(l + 1);
            let (fine, coarse) = (&mut a[l], &b[0]);
            prolong_window(fine, coarse);
            if l > 0 {
                out.relaxed += fine.smooth(o.post_smooth, false);
                for x in 0..fine.c.len() {
                    fine.d[x] += fine.c[x];
                }
            } else {
                out.relaxed += fine.smooth(o.pre_smooth + o.post_smooth, true);
            }
        }
        out.cycles += 1;
    }
    // Write back: every level's composite correction, interpolated down to the finest level.
    {
        let (lk, wk) = (&mut levels[k], &wins[k]);
        lk.zero_h();
        for j in 0..lk.grid.nz {
            for i in 0..lk.grid.nx {
                let (c, s) = lk.split.locate(i, j);
                lk.h[c][s] = wk.d[wk.idx(i, j)];
            }
        }
    }
    for l in (0..k).rev() {
        let (a, b) = levels.split_at_mut(l + 1);
        let (fine, coarse) = (&mut a[l], &b[0]);
        if l > 0 {
            fine.zero_h();
            prolong::<false>(coarse, fine, scratch);
        } else {
            prolong::<true>(coarse, fine, scratch);
        }
        let w = &wins[l];
        let values = if l > 0 { &w.d } else { &w.c };
        for j in w.ext.j0..=w.ext.j1 {
            for i in w.ext.i0..=w.ext.i1 {
                let x = w.idx(i, j);
                if w.free[x] {
                    let (c, s) = fine.split.locate(i, j);
                    fine.h[c][s] = values[x];
                }
            }
        }
        // Smooth the interpolation residual next to the window (on coarse levels outside the
        // window, where the correction's right-hand side is zero; on the finest level
        // everywhere in the band, with `b`).
        let g = fine.grid;
        let (width, sweeps) = match l {
            0 => (LOCAL_BAND, LOCAL_BAND_SWEEPS),
            _ => (LOCAL_COARSE_BAND >> (l - 1), LOCAL_COARSE_BAND_SWEEPS),
        };
        let band = w.act.dilate(width, g.nx, g.nz);
        let hole = (l > 0).then_some(w.ext);
        out.relaxed += smooth_band(fine, band, hole, sweeps);
    }
    Some(out)
}

/// Gauss–Seidel sweeps of `level.h` in `rect` minus `hole`, in the colour order of the global
/// smoother: red-black with `b` on the finest level (which has no hole); on coarse levels, whose
/// `h` holds the composite correction, four colours (colour, row parity) with a zero right-hand
/// side. Returns the samples relaxed.
fn smooth_band(level: &mut Level, rect: Rect, hole: Option<Rect>, sweeps: usize) -> u64 {
    if level.nine.is_none() {
        debug_assert!(hole.is_none(), "the finest level's band has no hole");
        smooth_band_five(level, rect, sweeps);
    } else {
        smooth_band_nine(level, rect, hole, sweeps);
    }
    (sweeps * rect.area()) as u64
}

/// [`smooth_band`] on a coarse (9-point) level: each row of the band is relaxed in at most two
/// spans, left and right of the hole, by the vectorised [`smooth_nine_spans`].
fn smooth_band_nine(level: &mut Level, rect: Rect, hole: Option<Rect>, sweeps: usize) {
    let split = level.split;
    let (i_lo, i_hi) = (rect.i0.max(1), rect.i1.min(split.nx - 2));
    let (j_lo, j_hi) = (rect.j0.max(1), rect.j1.min(split.nz - 2));
    if i_lo > i_hi || j_lo > j_hi {
        return;
    }
    // Each row of the band in at most two spans, left and right of the hole.
    let spans = |j: usize| match hole.filter(|h| (h.j0..=h.j1).contains(&j)) {
        Some(h) => [
            (h.i0 > i_lo).then(|| (i_lo, (h.i0 - 1).min(i_hi))),
            (h.i1 < i_hi).then(|| ((h.i1 + 1).max(i_lo), i_hi)),
        ],
        None => [Some((i_lo, i_hi)), None],
    };
    for _ in 0..sweeps {
        for (colour, parity) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            smooth_nine_spans::<false>(level, colour, parity, j_lo..=j_hi, spans);
        }
    }
}

/// Rows of the finest level's band per parallel task.
const BAND_ROWS_PER_TASK: usize = 32;

/// [`smooth_band`] on the finest level without a hole: red-black half-sweeps over contiguous
/// slot ranges of each colour row (the same expression as the global smoother, so it
/// vectorises; within a colour the updates are independent, so the order does not matter).
fn smooth_band_five(level: &mut Level, rect: Rect, sweeps: usize) {
    let split = level.split;
    let st = split.stride;
    let (i_lo, i_hi) = (rect.i0.max(1), rect.i1.min(split.nx - 2));
    let (j_lo, j_hi) = (rect.j0.max(1), rect.j1.min(split.nz - 2));
    if i_lo > i_hi || j_lo > j_hi {
        return;
    }
    for _ in 0..sweeps {
        for colour in 0..2 {
            let [h0, h1] = &mut level.h;
            let (x, y) = if colour == 0 { (h0, &*h1) } else { (h1, &*h0) };
            let (rhs, free) = (&level.rhs[colour], &level.free[colour]);
            let rows = &mut x[j_lo * st..(j_hi + 1) * st];
            let row = |(dj, xrow): (usize, &mut [f64])| {
                let j = j_lo + dj;
                let s = Split::shift(colour, j);
                // Slots `k` with `i_lo ≤ 2k + s ≤ i_hi`.
                let (k0, k1) = ((i_lo + 1 - s) / 2, (i_hi - s) / 2);
                if k0 > k1 {
                    return;
                }
                let (a, b) = (j * st + k0, j * st + k1 + 1);
                let xs = &mut xrow[k0..=k1];
                let (l, r) = (&y[a + s - 1..b + s - 1], &y[a + s..b + s]);
                let (u, d) = (&y[a - st..b - st], &y[a + st..b + st]);
                let (bs, fs) = (&rhs[a..b], &free[a..b]);
                for k in 0..xs.len() {
                    let v = ((l[k] + r[k]) + (u[k] + d[k]) - bs[k]) * 0.25;
                    xs[k] = if fs[k] != 0 { v } else { xs[k] };
                }
            };
            // The rows of one colour are independent (each reads only the other colour).
            rows.par_chunks_mut(st)
                .enumerate()
                .with_min_len(BAND_ROWS_PER_TASK)
                .for_each(row);
        }
    }
}
