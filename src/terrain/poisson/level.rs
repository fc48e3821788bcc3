//! One level of the multigrid hierarchy.
//!
//! The finest level carries the 5-point operator of the problem; every coarser level carries the
//! Galerkin product `Pᵀ A P` of its finer neighbour ([`super::galerkin`]), with the mask restricted
//! by injection (a coarse sample is fixed exactly when its fine counterpart is). The paper
//! restricts constraints so that "hard constraints have the highest priority and automatically
//! apply at the lowest resolution" (§3); with Galerkin operators the coarse levels need no
//! constraint values at all: they solve for corrections, which are zero at every fixed sample.

use super::galerkin::{coarsen_into, NinePoint};
use super::grid::{GridSpec, Split};
use super::local::Rect;
use rayon::prelude::*;

/// One multigrid level: the unknowns, the right-hand side and the free-sample mask, each stored as
/// two colour arrays (see [`super::grid`]).
#[derive(Clone, Debug)]
pub struct Level {
    /// Grid of this level (spacing doubles at each coarser level).
    pub grid: GridSpec,
    /// Colour-split layout of `grid`.
    pub split: Split,
    /// Unknowns, metres: heights on the finest level and in the full-multigrid start, corrections
    /// in the correction cycles. Fixed samples hold their value and are never written by a
    /// smoother.
    pub h: [Vec<f64>; 2],
    /// Right-hand side `b` of `A h = b` with `(A h)_ij = h_{i−1,j} + h_{i+1,j} + h_{i,j−1} +
    /// h_{i,j+1} − 4 h_ij` (metres). Zero at fixed samples and padding slots.
    pub rhs: [Vec<f64>; 2],
    /// 1 where the sample is free (an unknown), 0 where it is fixed or a padding slot.
    pub free: [Vec<u8>; 2],
    /// The Galerkin 9-point operator of a coarse level; `None` on the finest level (5-point).
    pub nine: Option<NinePoint>,
    /// Samples relaxed by the smoothers on this level so far (sweeps times `nx · nz`): the work
    /// counter behind [`super::SolveReport::samples_relaxed`].
    pub relaxed: u64,
}

impl Level {
    /// A level of `grid` with every sample fixed at zero.
    pub fn new(grid: GridSpec) -> Self {
        let split = Split::new(grid.nx, grid.nz);
        let n = split.len();
        Self {
            grid,
            split,
            h: [vec![0.0; n], vec![0.0; n]],
            rhs: [vec![0.0; n], vec![0.0; n]],
            free: [vec![0; n], vec![0; n]],
            nine: None,
            relaxed: 0,
        }
    }

    /// A level of `grid` whose free samples are those of the natural row-major mask `free`
    /// (border samples are fixed whatever the mask says).
    pub fn with_mask(grid: GridSpec, free: &[bool]) -> Self {
        let mut level = Self::new(grid);
        level.set_mask(free);
        level
    }

    /// Replaces the free mask by the natural row-major `free` (the border stays fixed).
    pub fn set_mask(&mut self, free: &[bool]) {
        let g = self.grid;
        for j in 0..g.nz {
            for i in 0..g.nx {
                let (c, k) = self.split.locate(i, j);
                self.free[c][k] = u8::from(free[j * g.nx + i] && !g.is_border(i, j));
            }
        }
    }

    /// Sets the free mask from the row-major `fixed` flags (`nx · nz`; border samples stay fixed)
    /// and returns the rectangle of the samples whose flag changed, if any. Rows run in parallel.
    pub fn set_fixed(&mut self, fixed: &[bool]) -> Option<Rect> {
        self.set_fixed_rows(fixed, 0, self.grid.nz - 1)
    }

    /// [`Self::set_fixed`] for rows `j0..=j1` only (clipped to the grid).
    pub fn set_fixed_rows(&mut self, fixed: &[bool], j0: usize, j1: usize) -> Option<Rect> {
        let g = self.grid;
        let split = self.split;
        let st = split.stride;
        let j1 = j1.min(g.nz - 1);
        if j0 > j1 {
            return None;
        }
        let span = j0 * st..(j1 + 1) * st;
        let [f0, f1] = &mut self.free;
        let mut rows = vec![None::<(usize, usize)>; j1 + 1 - j0];
        f0[span.clone()]
            .par_chunks_mut(st)
            .zip(f1[span].par_chunks_mut(st))
            .zip(rows.par_iter_mut())
            .enumerate()
            .with_min_len(16)
            .for_each(|(dj, ((r0, r1), out))| {
                let j = j0 + dj;
                let fixed_row = &fixed[j * g.nx..(j + 1) * g.nx];
                let inner_row = j > 0 && j + 1 < g.nz;
                let flag =
                    |i: usize| u8::from(inner_row & (i > 0) & (i + 1 < g.nx) & !fixed_row[i]);
                let mut span: Option<(usize, usize)> = None;
                for (c, row) in [r0, r1].into_iter().enumerate() {
                    let s = Split::shift(c, j);
                    let row = &mut row[..split.count(c, j)];
                    // A branch-free comparison first; the changed columns are searched (and the
                    // flags written) only when one differs.
                    let same = row
                        .iter()
                        .enumerate()
                        .fold(true, |ok, (k, &v)| ok & (v == flag(2 * k + s)));
                    if same {
                        continue;
                    }
                    for (k, slot) in row.iter_mut().enumerate() {
                        let i = 2 * k + s;
                        let v = flag(i);
                        if *slot != v {
                            *slot = v;
                            span = Some(span.map_or((i, i), |(a, b)| (a.min(i), b.max(i))));
                        }
                    }
                }
                *out = span;
            });
        Rect::of_row_spans(j0, &rows)
    }

    /// True if sample `(i, j)` is free.
    pub fn is_free(&self, i: usize, j: usize) -> bool {
        let (c, k) = self.split.locate(i, j);
        self.free[c][k] != 0
    }

    /// Unknown at sample `(i, j)`.
    pub fn value(&self, i: usize, j: usize) -> f64 {
        let (c, k) = self.split.locate(i, j);
        self.h[c][k]
    }

    /// Sets every unknown (free and fixed) to zero: the start of a correction cycle.
    pub fn zero_h(&mut self) {
        self.h[0].fill(0.0);
        self.h[1].fill(0.0);
    }

    /// Bytes of the level's arrays.
    pub fn bytes(&self) -> usize {
        2 * self.split.len() * (2 * std::mem::size_of::<f64>() + 1)
            + self.nine.as_ref().map_or(0, NinePoint::bytes)
    }

    /// The coarse level of this one: the mask restricted by injection and the Galerkin operator.
    pub fn coarsen(&self) -> Option<Level> {
        let mut coarse = Level::new(self.grid.coarser()?);
        coarsen_into(self, &mut coarse);
        Some(coarse)
    }

    /// Recomputes the free mask and the Galerkin operator of `coarse` (this level's coarser
    /// neighbour) from this level's.
    pub fn restrict_mask(&self, coarse: &mut Level) {
        coarsen_into(self, coarse);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::poisson::galerkin::{entry, galerkin_default, FIVE_POINT};

    #[test]
    fn the_mask_is_restricted_by_injection() {
        let g = GridSpec::new(17, 17, 1.0).expect("grid");
        let fixed_coarse = |i: usize, j: usize| {
            let mut free = vec![true; 17 * 17];
            free[j * 17 + i] = false;
            let coarse = Level::with_mask(g, &free).coarsen().expect("coarse");
            let mut fixed = Vec::new();
            for jc in 1..8 {
                for ic in 1..8 {
                    if !coarse.is_free(ic, jc) {
                        fixed.push((ic, jc));
                    }
                }
            }
            fixed
        };
        assert_eq!(fixed_coarse(4, 6), vec![(2, 3)]);
        assert_eq!(fixed_coarse(5, 6), vec![]);
        assert_eq!(fixed_coarse(5, 7), vec![]);
    }

    #[test]
    fn an_incremental_rebuild_equals_a_full_one() {
        // A 65 × 65 grid with a disc and a curve; then a point is added, a curve sample freed
        // and the disc moved by one column. Updating the coarse rows within reach of the changed
        // rows gives exactly the masks and operators of a hierarchy built from scratch.
        let g = GridSpec::new(65, 65, 1.0).expect("grid");
        let mut fixed = vec![false; 65 * 65];
        for t in 0..30 {
            fixed[(10 + t / 2) * 65 + 12 + t] = true;
        }
        let disc = |fixed: &mut Vec<bool>, ci: usize, on: bool| {
            for j in 40..52usize {
                for i in ci - 6..=ci + 6 {
                    if (i.abs_diff(ci).pow(2) + j.abs_diff(46).pow(2)) <= 30 {
                        fixed[j * 65 + i] = on;
                    }
                }
            }
        };
        disc(&mut fixed, 44, true);
        let build = |fixed: &[bool]| {
            let mut levels = vec![Level::new(g)];
            levels[0].set_fixed(fixed);
            while let Some(c) = levels.last().and_then(Level::coarsen) {
                levels.push(c);
            }
            levels
        };
        let mut levels = build(&fixed);
        fixed[20 * 65 + 50] = true;
        fixed[(10 + 7) * 65 + 12 + 14] = false;
        disc(&mut fixed, 44, false);
        disc(&mut fixed, 45, true);
        let change = levels[0].set_fixed(&fixed).expect("a change");
        assert_eq!((change.j0, change.j1), (17, 51), "{change:?}");
        let (mut a, mut b) = (change.j0, change.j1);
        for l in 1..levels.len() {
            let (x, y) = levels.split_at_mut(l);
            (a, b) = crate::terrain::poisson::galerkin::coarsen_rows(&x[l - 1], &mut y[0], a, b);
        }
        let fresh = build(&fixed);
        for (l, (u, f)) in levels.iter().zip(&fresh).enumerate() {
            assert_eq!(u.free, f.free, "mask of level {l}");
            assert_eq!(u.nine, f.nine, "operator of level {l}");
        }
        assert!(
            levels[0].set_fixed(&fixed).is_none(),
            "no change the second time"
        );
    }

    #[test]
    fn the_default_coarse_stencil_is_the_galerkin_nine_point_laplacian() {
        let s = galerkin_default(&FIVE_POINT);
        assert_eq!(
            s,
            [0.25, 0.5, 0.25, 0.5, -3.0, 0.5, 0.25, 0.5, 0.25],
            "¼ [1 2 1; 2 −12 2; 1 2 1]"
        );
    }

    /// The level's operator as a dense matrix over its free samples (natural order).
    fn dense(level: &Level) -> (Vec<(usize, usize)>, Vec<Vec<f64>>) {
        let g = level.grid;
        let free: Vec<(usize, usize)> = (0..g.nz)
            .flat_map(|j| (0..g.nx).map(move |i| (i, j)))
            .filter(|(i, j)| level.is_free(*i, *j))
            .collect();
        let index = |i: usize, j: usize| free.iter().position(|p| *p == (i, j));
        let mut a = vec![vec![0.0; free.len()]; free.len()];
        for (r, (i, j)) in free.iter().enumerate() {
            let st = match &level.nine {
                None => FIVE_POINT,
                Some(op) => {
                    let (c, k) = level.split.locate(*i, *j);
                    op.stencil(c, k, *j)
                }
            };
            for dz in -1..=1isize {
                for dx in -1..=1isize {
                    let (x, z) = ((*i as isize + dx) as usize, (*j as isize + dz) as usize);
                    if let Some(col) = index(x, z) {
                        a[r][col] += st[entry(dx, dz)];
                    }
                }
            }
        }
        (free, a)
    }

    #[test]
    fn coarse_operators_are_the_galerkin_products_with_the_masked_interpolation() {
        // Two levels below a 17 × 17 grid with a point at an odd-odd sample, a short curve and a
        // sample next to the border: each coarse operator equals Pᵀ A P computed densely, with
        // P the bilinear interpolation restricted to free samples, and is symmetric.
        let g = GridSpec::new(17, 17, 1.0).expect("grid");
        let mut free = vec![true; 17 * 17];
        for (i, j) in [
            (5, 7),
            (8, 10),
            (9, 10),
            (10, 11),
            (11, 11),
            (1, 4),
            (12, 4),
        ] {
            free[j * 17 + i] = false;
        }
        let fine = Level::with_mask(g, &free);
        let mid = fine.coarsen().expect("level 1");
        let coarse = mid.coarsen().expect("level 2");
        assert!(!mid.nine.as_ref().expect("nine").special.is_empty());
        for (f, c) in [(&fine, &mid), (&mid, &coarse)] {
            let (ff, a) = dense(f);
            let (cf, ac) = dense(c);
            let p: Vec<Vec<f64>> = ff
                .iter()
                .map(|(i, j)| {
                    cf.iter()
                        .map(|(ic, jc)| {
                            let (x, z) = (
                                *i as isize - 2 * *ic as isize,
                                *j as isize - 2 * *jc as isize,
                            );
                            if x.abs() > 1 || z.abs() > 1 {
                                return 0.0;
                            }
                            // A corner across a diagonal step of a constraint gives nothing.
                            let blocked = x != 0
                                && z != 0
                                && !f.is_free((*i as isize - x) as usize, *j)
                                && !f.is_free(*i, (*j as isize - z) as usize);
                            if blocked {
                                0.0
                            } else {
                                (1.0 - 0.5 * x.abs() as f64) * (1.0 - 0.5 * z.abs() as f64)
                            }
                        })
                        .collect()
                })
                .collect();
            for r in 0..cf.len() {
                for col in 0..cf.len() {
                    let mut want = 0.0;
                    for x in 0..ff.len() {
                        if p[x][r] == 0.0 {
                            continue;
                        }
                        for y in 0..ff.len() {
                            want += p[x][r] * a[x][y] * p[y][col];
                        }
                    }
                    assert!(
                        (ac[r][col] - want).abs() < 1e-12,
                        "{:?} → {:?}: {} vs PᵀAP {want}",
                        cf[r],
                        cf[col],
                        ac[r][col]
                    );
                    assert_eq!(
                        ac[r][col], ac[col][r],
                        "symmetry at {:?}, {:?}",
                        cf[r], cf[col]
                    );
                }
            }
        }
    }
}
