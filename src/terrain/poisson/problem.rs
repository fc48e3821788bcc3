//! The reconstruction problem: a target gradient field on the edges of the grid, and Dirichlet
//! constraints on any set of samples.
//!
//! Discretisation (staggered, "per edge"): `gx[j·(nx−1) + i]` is the target slope `∂h/∂x` on the
//! x-edge between samples `(i, j)` and `(i+1, j)`, and `gz[j·nx + i]` the target `∂h/∂z` on the
//! z-edge between `(i, j)` and `(i, j+1)`. Minimising `Σ_edges (difference/δ − g)²` over the free
//! samples gives, at every free sample, the 5-point equation
//!
//! `h_{i−1,j} + h_{i+1,j} + h_{i,j−1} + h_{i,j+1} − 4 h_ij = δ · (gx_{i+½,j} − gx_{i−½,j} +
//! gz_{i,j+½} − gz_{i,j−½})`,
//!
//! the discrete `Δh = ∇·g` of the paper (§3, times `δ²`). With gradients extracted by
//! [`super::gradient::extract_edges`] the reconstruction of an unedited field returns the
//! original heights up to rounding, and for a smooth field sampled at edge midpoints the error is
//! `O(δ²)`.

use super::grid::GridSpec;
use super::level::Level;
use super::local::Rect;
use super::PoissonError;
use rayon::prelude::*;

/// One reconstruction problem, borrowed from the caller.
#[derive(Clone, Copy, Debug)]
pub struct Problem<'a> {
    /// Grid (sides `2^k + 1`, spacing in metres).
    pub grid: GridSpec,
    /// Target slopes `∂h/∂x` on the x-edges, m/m, `(nx − 1) · nz`, index `j · (nx − 1) + i`.
    pub gx: &'a [f32],
    /// Target slopes `∂h/∂z` on the z-edges, m/m, `nx · (nz − 1)`, index `j · nx + i`.
    pub gz: &'a [f32],
    /// True where the height is fixed (a hard Dirichlet constraint), `nx · nz` row-major. Border
    /// samples are always fixed, whatever this mask says.
    pub fixed: &'a [bool],
    /// Heights in metres, `nx · nz` row-major; read at the fixed samples (including the border),
    /// ignored elsewhere.
    pub heights: &'a [f32],
}

/// A problem that owns its fields, for callers that build one (benchmarks, tests, tools).
#[derive(Clone, Debug, PartialEq)]
pub struct OwnedProblem {
    /// Grid (sides `2^k + 1`, spacing in metres).
    pub grid: GridSpec,
    /// Target slopes `∂h/∂x` on the x-edges, m/m (layout of [`Problem::gx`]).
    pub gx: Vec<f32>,
    /// Target slopes `∂h/∂z` on the z-edges, m/m (layout of [`Problem::gz`]).
    pub gz: Vec<f32>,
    /// True where the height is fixed, `nx · nz` row-major.
    pub fixed: Vec<bool>,
    /// Heights in metres, `nx · nz` row-major (read at the fixed samples and the border).
    pub heights: Vec<f32>,
}

impl OwnedProblem {
    /// The problem whose solution is `heights` (`nx · nz`, metres): their forward-difference
    /// slopes ([`super::gradient::extract_edges`]) with only the border fixed.
    ///
    /// # Panics
    /// If `heights` does not have one value per sample (a programming error of the caller).
    pub fn from_heights(grid: GridSpec, heights: Vec<f32>) -> Self {
        let mut gx = vec![0.0; grid.x_edges()];
        let mut gz = vec![0.0; grid.z_edges()];
        super::gradient::extract_edges(grid, &heights, &mut gx, &mut gz);
        Self {
            grid,
            gx,
            gz,
            fixed: vec![false; grid.len()],
            heights,
        }
    }

    /// Fixes sample `(i, j)` at `height_m` metres (a hard Dirichlet constraint).
    ///
    /// # Panics
    /// If `(i, j)` is outside the grid.
    pub fn fix(&mut self, i: usize, j: usize, height_m: f32) {
        assert!(
            i < self.grid.nx && j < self.grid.nz,
            "({i}, {j}) is outside the grid"
        );
        let n = j * self.grid.nx + i;
        self.fixed[n] = true;
        self.heights[n] = height_m;
    }

    /// The borrowed view the solver takes.
    pub fn problem(&self) -> Problem<'_> {
        Problem {
            grid: self.grid,
            gx: &self.gx,
            gz: &self.gz,
            fixed: &self.fixed,
            heights: &self.heights,
        }
    }
}

impl Problem<'_> {
    /// Checks the lengths and that every value the solver reads is finite.
    ///
    /// # Errors
    /// [`PoissonError::Field`] naming `gx`, `gz`, `fixed` or `heights`.
    pub fn validate(&self) -> Result<(), PoissonError> {
        self.validate_rows(0, usize::MAX)
    }

    /// [`Self::validate`] for the values of rows `j0..=j1` only (clipped to the grid): the
    /// x-edges and z-edges `(i, j + ½)` of those rows, and their fixed heights. The lengths are
    /// always checked in full.
    ///
    /// # Errors
    /// As [`Self::validate`].
    pub fn validate_rows(&self, j0: usize, j1: usize) -> Result<(), PoissonError> {
        let g = self.grid;
        for (name, len, want) in [
            ("gx", self.gx.len(), g.x_edges()),
            ("gz", self.gz.len(), g.z_edges()),
            ("fixed", self.fixed.len(), g.len()),
            ("heights", self.heights.len(), g.len()),
        ] {
            if len != want {
                return Err(PoissonError::field(
                    name,
                    format!("{len} values; the {}×{} grid needs {want}", g.nx, g.nz),
                ));
            }
        }
        let j1 = j1.min(g.nz - 1);
        if j0 > j1 {
            return Ok(());
        }
        // z-edge row `j` joins rows `j` and `j + 1`; the last row has none.
        let zrows = j0..(j1 + 1).min(g.nz - 1);
        // Branch-free scans first (they vectorise); the searches that name the culprit run only
        // when a scan fails.
        for (name, values, from) in [
            (
                "gx",
                &self.gx[j0 * (g.nx - 1)..(j1 + 1) * (g.nx - 1)],
                j0 * (g.nx - 1),
            ),
            (
                "gz",
                &self.gz[zrows.start * g.nx..zrows.end * g.nx],
                zrows.start * g.nx,
            ),
        ] {
            if !all_finite(values) {
                let i = values.iter().position(|v| !v.is_finite()).unwrap_or(0);
                return Err(PoissonError::field(
                    name,
                    format!("value {} at index {} is not finite", values[i], from + i),
                ));
            }
        }
        let rows = j0 * g.nx..(j1 + 1) * g.nx;
        let fixed_ok = self.fixed[rows.clone()]
            .iter()
            .zip(&self.heights[rows])
            .fold(true, |ok, (&f, h)| ok & (!f | h.is_finite()));
        let border_ok = (j0 > 0 || all_finite(&self.heights[..g.nx]))
            && (j1 + 1 < g.nz || all_finite(&self.heights[g.len() - g.nx..]))
            && (j0..=j1).all(|j| {
                self.heights[j * g.nx].is_finite() && self.heights[j * g.nx + g.nx - 1].is_finite()
            });
        if !(fixed_ok && border_ok) {
            for j in j0..=j1 {
                for i in 0..g.nx {
                    let n = j * g.nx + i;
                    if (self.fixed[n] || g.is_border(i, j)) && !self.heights[n].is_finite() {
                        return Err(PoissonError::field(
                            "heights",
                            format!(
                                "fixed sample ({i}, {j}) has the non-finite height {}",
                                self.heights[n]
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// True at the free samples (not fixed, not on the border), row-major.
    pub fn free_mask(&self) -> Vec<bool> {
        let g = self.grid;
        (0..g.len())
            .map(|n| !self.fixed[n] && !g.is_border(n % g.nx, n / g.nx))
            .collect()
    }

    /// The right-hand side `δ · div g` of the 5-point equations at the free samples (zero at fixed
    /// samples), row-major `nx · nz`: the data the solver loads, for peers and diagnostics.
    pub fn rhs_natural(&self) -> Vec<f64> {
        let g = self.grid;
        let nx = g.nx;
        (0..g.len())
            .map(|n| {
                let (i, j) = (n % nx, n / nx);
                if self.fixed[n] || g.is_border(i, j) {
                    return 0.0;
                }
                let ex = n - j;
                let div = (f64::from(self.gx[ex]) - f64::from(self.gx[ex - 1]))
                    + (f64::from(self.gz[n]) - f64::from(self.gz[n - nx]));
                g.spacing_m * div
            })
            .collect()
    }

    /// Writes the right-hand side of the 5-point equations (zero at fixed samples) and the fixed
    /// heights into `level` (the finest level, whose mask must already be this problem's), and
    /// returns `‖b‖²`, the squared norm of the right-hand side of the reduced system over the free
    /// samples (fixed neighbours moved to the right: `b − Σ_fixed neighbours h`).
    pub fn load(&self, level: &mut Level) -> f64 {
        let mut rows = Vec::new();
        self.load_tracked(level, &mut rows).0
    }

    /// [`Self::load`], also returning the rectangle of the samples whose right-hand side (free
    /// samples) or height (fixed samples) differs from what `level` held before, if any. `rows`
    /// receives the contribution of every row to `‖b‖²` (`nz` values, whose sum in row order is
    /// the returned norm), so that [`Self::load_rows`] can update it later. Rows run in parallel.
    pub fn load_tracked(&self, level: &mut Level, rows: &mut Vec<f64>) -> (f64, Option<Rect>) {
        rows.clear();
        rows.resize(self.grid.nz, 0.0);
        self.load_rows(level, rows, 0, self.grid.nz - 1)
    }

    /// [`Self::load_tracked`] restricted to the rows `j0..=j1`: the right-hand side, the fixed
    /// heights and the row contributions `rows[j]` (`nz` values, as [`Self::load_tracked`] left
    /// them) of those rows only. If the other rows' inputs did not change since `rows` was
    /// computed, the returned `(Σ rows, change)` is what [`Self::load_tracked`] would return, bit
    /// for bit (the sum runs in row order either way).
    pub fn load_rows(
        &self,
        level: &mut Level,
        rows: &mut [f64],
        j0: usize,
        j1: usize,
    ) -> (f64, Option<Rect>) {
        let st = level.split.stride;
        let j1 = j1.min(self.grid.nz - 1);
        let span = j0 * st..(j1 + 1) * st;
        let [r0, r1] = &mut level.rhs;
        let [h0, h1] = &mut level.h;
        let free = [&level.free[0][span.clone()], &level.free[1][span.clone()]];
        let mut spans = vec![None::<(usize, usize)>; j1 + 1 - j0];
        r0[span.clone()]
            .par_chunks_mut(st)
            .zip(r1[span.clone()].par_chunks_mut(st))
            .zip(h0[span.clone()].par_chunks_mut(st))
            .zip(h1[span].par_chunks_mut(st))
            .zip(rows[j0..=j1].par_iter_mut())
            .zip(spans.par_iter_mut())
            .enumerate()
            .with_min_len(8)
            .for_each(|(dj, (((((r0, r1), h0), h1), ss), span))| {
                let f = [
                    &free[0][dj * st..(dj + 1) * st],
                    &free[1][dj * st..(dj + 1) * st],
                ];
                (*ss, *span) = self.load_row(j0 + dj, [r0, r1], [h0, h1], f);
            });
        let change = Rect::of_row_spans(j0, &spans);
        (rows.iter().sum(), change)
    }

    /// Loads row `j` (its two colour rows of the right-hand side, unknowns and mask); returns its
    /// contribution to `‖b‖²` and the columns that changed.
    fn load_row(
        &self,
        j: usize,
        rhs: [&mut [f64]; 2],
        h: [&mut [f64]; 2],
        free: [&[u8]; 2],
    ) -> (f64, Option<(usize, usize)>) {
        let g = self.grid;
        let (nx, nz) = (g.nx, g.nz);
        let delta = g.spacing_m;
        let [r0, r1] = rhs;
        let [h0, h1] = h;
        let mut ss = 0.0f64;
        let mut span: Option<(usize, usize)> = None;
        let mut note = |i: usize| {
            span = Some(span.map_or((i, i), |(a, b): (usize, usize)| (a.min(i), b.max(i))));
        };
        for i in 0..nx {
            let n = j * nx + i;
            let (c, k) = ((i + j) & 1, i / 2);
            let (rr, hh) = if c == 0 {
                (&mut *r0, &mut *h0)
            } else {
                (&mut *r1, &mut *h1)
            };
            if free[c][k] == 0 {
                let v = f64::from(self.heights[n]);
                if rr[k] != 0.0 || hh[k] != v {
                    note(i);
                }
                rr[k] = 0.0;
                hh[k] = v;
                continue;
            }
            let ex = n - j;
            let div = (f64::from(self.gx[ex]) - f64::from(self.gx[ex - 1]))
                + (f64::from(self.gz[n]) - f64::from(self.gz[n - nx]));
            let rhs = delta * div;
            if rr[k] != rhs {
                note(i);
            }
            rr[k] = rhs;
            let mut beff = rhs;
            for (m, border) in [
                (n - 1, i == 1),
                (n + 1, i + 2 == nx),
                (n - nx, j == 1),
                (n + nx, j + 2 == nz),
            ] {
                if border || self.fixed[m] {
                    beff -= f64::from(self.heights[m]);
                }
            }
            ss += beff * beff;
        }
        (ss, span)
    }
}

/// True when every value is finite: a branch-free fold over fixed-size chunks, so it vectorises.
fn all_finite(values: &[f32]) -> bool {
    let chunks = values.chunks_exact(64);
    let tail = chunks.remainder().iter().all(|v| v.is_finite());
    tail && chunks
        .into_iter()
        .all(|c| c.iter().fold(true, |ok, v| ok & v.is_finite()))
}
