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

impl Problem<'_> {
    /// Checks the lengths and that every value the solver reads is finite.
    ///
    /// # Errors
    /// [`PoissonError::Field`] naming `gx`, `gz`, `fixed` or `heights`.
    pub fn validate(&self) -> Result<(), PoissonError> {
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
        // Branch-free scans first (they vectorise); the searches that name the culprit run only
        // when a scan fails.
        for (name, values) in [("gx", self.gx), ("gz", self.gz)] {
            if !all_finite(values) {
                let i = values.iter().position(|v| !v.is_finite()).unwrap_or(0);
                return Err(PoissonError::field(
                    name,
                    format!("value {} at index {i} is not finite", values[i]),
                ));
            }
        }
        let fixed_ok = self
            .fixed
            .iter()
            .zip(self.heights)
            .fold(true, |ok, (&f, h)| ok & (!f | h.is_finite()));
        let border_ok = all_finite(&self.heights[..g.nx])
            && all_finite(&self.heights[g.len() - g.nx..])
            && (0..g.nz).all(|j| {
                self.heights[j * g.nx].is_finite() && self.heights[j * g.nx + g.nx - 1].is_finite()
            });
        if !(fixed_ok && border_ok) {
            for j in 0..g.nz {
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
        self.load_tracked(level).0
    }

    /// [`Self::load`], also returning the rectangle of the samples whose right-hand side (free
    /// samples) or height (fixed samples) differs from what `level` held before, if any.
    pub fn load_tracked(&self, level: &mut Level) -> (f64, Option<Rect>) {
        let g = self.grid;
        let (nx, nz) = (g.nx, g.nz);
        let st = level.split.stride;
        let delta = g.spacing_m;
        let band = (nz / (4 * rayon::current_num_threads().max(1))).max(8);
        let mut partial = vec![(0.0f64, None::<(usize, usize)>); nz];
        let [r0, r1] = &mut level.rhs;
        let [h0, h1] = &mut level.h;
        let free = &level.free;
        let me = *self;
        r0.par_chunks_mut(band * st)
            .zip(r1.par_chunks_mut(band * st))
            .zip(h0.par_chunks_mut(band * st))
            .zip(h1.par_chunks_mut(band * st))
            .zip(partial.par_chunks_mut(band))
            .enumerate()
            .for_each(|(b, ((((r0, r1), h0), h1), part))| {
                for (dj, slot) in part.iter_mut().enumerate() {
                    let j = b * band + dj;
                    let mut ss = 0.0f64;
                    let mut span: Option<(usize, usize)> = None;
                    let mut note = |i: usize| {
                        span = Some(
                            span.map_or((i, i), |(a, b): (usize, usize)| (a.min(i), b.max(i))),
                        );
                    };
                    for i in 0..nx {
                        let n = j * nx + i;
                        let (c, k) = ((i + j) & 1, dj * st + i / 2);
                        let (rr, hh) = if c == 0 {
                            (&mut *r0, &mut *h0)
                        } else {
                            (&mut *r1, &mut *h1)
                        };
                        if free[c][j * st + i / 2] == 0 {
                            let v = f64::from(me.heights[n]);
                            if rr[k] != 0.0 || hh[k] != v {
                                note(i);
                            }
                            rr[k] = 0.0;
                            hh[k] = v;
                            continue;
                        }
                        let ex = n - j;
                        let div = (f64::from(me.gx[ex]) - f64::from(me.gx[ex - 1]))
                            + (f64::from(me.gz[n]) - f64::from(me.gz[n - nx]));
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
                            if border || me.fixed[m] {
                                beff -= f64::from(me.heights[m]);
                            }
                        }
                        ss += beff * beff;
                    }
                    *slot = (ss, span);
                }
            });
        let norm = partial.iter().map(|p| p.0).sum();
        let change = partial
            .iter()
            .enumerate()
            .filter_map(|(j, p)| {
                p.1.map(|(a, b)| Rect {
                    i0: a,
                    j0: j,
                    i1: b,
                    j1: j,
                })
            })
            .reduce(Rect::union);
        (norm, change)
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
