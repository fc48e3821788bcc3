//! One level of the multigrid hierarchy, and the restriction of the constraint mask and values.
//!
//! Fixed (Dirichlet) samples are restricted with the paper's priority rule ("hard constraints have
//! the highest priority and automatically apply at the lowest resolution", §3): a coarse sample is
//! fixed if any fine sample of its 3 × 3 restriction footprint `(2I + a, 2J + b)`, `a, b ∈ {−1, 0,
//! 1}`, is fixed, so a constraint curve one sample wide never slips between coarse samples. The
//! coarse sample's value (used only by the full-multigrid start) is its fine counterpart's value
//! `(2I, 2J)` when that one is fixed, and otherwise the mean of the fixed samples of its footprint
//! (the paper averages constraints of one type). In correction cycles every fixed sample carries a
//! zero correction on every level.

use super::grid::{GridSpec, Split};

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
    }

    /// The coarse level of this one, with the restricted mask (priority rule of the module docs).
    pub fn coarsen(&self) -> Option<Level> {
        let mut coarse = Level::new(self.grid.coarser()?);
        self.restrict_mask(&mut coarse);
        Some(coarse)
    }

    /// Recomputes the free mask of `coarse` (this level's coarser neighbour) from this level's.
    pub fn restrict_mask(&self, coarse: &mut Level) {
        let cg = coarse.grid;
        for jc in 1..cg.nz - 1 {
            for ic in 1..cg.nx - 1 {
                let free =
                    (0..3).all(|b| (0..3).all(|a| self.is_free(2 * ic + a - 1, 2 * jc + b - 1)));
                let (c, k) = coarse.split.locate(ic, jc);
                coarse.free[c][k] = u8::from(free);
            }
        }
    }

    /// Writes into the fixed samples of `coarse` (this level's coarser neighbour) the restricted
    /// fixed values of this level, and zero into its free samples: the start of its full problem.
    pub fn restrict_fixed_values(&self, coarse: &mut Level) {
        let cg = coarse.grid;
        let (fx, fz) = (self.grid.nx as isize, self.grid.nz as isize);
        for jc in 0..cg.nz {
            for ic in 0..cg.nx {
                let (c, k) = coarse.split.locate(ic, jc);
                if coarse.free[c][k] != 0 {
                    coarse.h[c][k] = 0.0;
                    continue;
                }
                let (i, j) = (2 * ic, 2 * jc);
                let value = if !self.is_free(i, j) {
                    self.value(i, j)
                } else {
                    let (mut sum, mut n) = (0.0f64, 0u32);
                    for b in -1isize..=1 {
                        for a in -1isize..=1 {
                            let (x, z) = (i as isize + a, j as isize + b);
                            if (0..fx).contains(&x)
                                && (0..fz).contains(&z)
                                && !self.is_free(x as usize, z as usize)
                            {
                                sum += self.value(x as usize, z as usize);
                                n += 1;
                            }
                        }
                    }
                    if n == 0 {
                        0.0
                    } else {
                        sum / f64::from(n)
                    }
                };
                coarse.h[c][k] = value;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fixed_sample_fixes_every_coarse_sample_whose_footprint_holds_it() {
        let g = GridSpec::new(17, 17, 1.0).expect("grid");
        let mut free = vec![true; 17 * 17];
        free[7 * 17 + 5] = false; // (5, 7): odd column, odd row.
        let fine = Level::with_mask(g, &free);
        let coarse = fine.coarsen().expect("coarse");
        let mut fixed = Vec::new();
        for j in 1..8 {
            for i in 1..8 {
                if !coarse.is_free(i, j) {
                    fixed.push((i, j));
                }
            }
        }
        assert_eq!(fixed, vec![(2, 3), (3, 3), (2, 4), (3, 4)]);
    }

    #[test]
    fn fixed_values_prefer_the_counterpart_then_average_the_footprint() {
        let g = GridSpec::new(9, 9, 1.0).expect("grid");
        let mut free = vec![true; 81];
        free[4 * 9 + 4] = false; // (4, 4) is the counterpart of coarse (2, 2).
        free[4 * 9 + 5] = false; // (5, 4) is in the footprints of coarse (2, 2) and (3, 2).
        free[3 * 9 + 5] = false; // (5, 3) is in the footprints of (2, 1), (3, 1), (2, 2), (3, 2).
        let mut fine = Level::with_mask(g, &free);
        for (i, j, v) in [(4, 4, 10.0), (5, 4, 20.0), (5, 3, 40.0)] {
            let (c, k) = fine.split.locate(i, j);
            fine.h[c][k] = v;
        }
        let mut coarse = fine.coarsen().expect("coarse");
        fine.restrict_fixed_values(&mut coarse);
        assert_eq!(coarse.value(2, 2), 10.0);
        assert_eq!(coarse.value(3, 2), 30.0);
        assert_eq!(coarse.value(3, 1), 40.0);
        assert!(coarse.is_free(1, 1) && coarse.value(1, 1) == 0.0);
    }
}
