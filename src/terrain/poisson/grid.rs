//! Grid geometry and the red-black ("colour-split") storage layout of the solver.
//!
//! A grid has `nx × nz` samples, `nx = 2^a + 1` and `nz = 2^b + 1`, spacing `spacing_m` metres in
//! both directions. Sample `(i, j)` (column `i`, row `j`) has colour `(i + j) mod 2`: 0 is red,
//! 1 is black. The 5-point stencil of a red sample touches only black samples and vice versa, which
//! is what makes red-black Gauss–Seidel parallel.
//!
//! The solver stores every per-sample field as two arrays, one per colour, each with `nz` rows of
//! `stride = (nx + 1) / 2` slots. Row `j` of colour `c` holds the samples `i = 2k + s` for
//! `k = 0, 1, …`, where `s = (c + j) mod 2` is the column parity of that colour in that row. A row
//! holds `(nx + 1) / 2` samples when `s = 0` and `(nx − 1) / 2` when `s = 1` (its last slot is
//! padding, always zero and never free). With this layout the four neighbours of the samples of one
//! colour row are contiguous slices of the other colour:
//!
//! - `s = 0` (samples at even `i = 2k`): left `other[j][k − 1]`, right `other[j][k]`, up and down
//!   `other[j ± 1][k]`;
//! - `s = 1` (samples at odd `i = 2k + 1`): left `other[j][k]`, right `other[j][k + 1]`, up and
//!   down `other[j ± 1][k]`.
//!
//! So every inner loop runs over plain contiguous slices (vectorisable, no gathers), and a half-sweep
//! mutates one colour array while it only reads the other: the parallel loops are safe Rust.

use super::PoissonError;

/// Largest number of samples on a side (`2^13 + 1`, the paper's largest grid in Table 1).
pub const MAX_SIDE: usize = 8193;
/// Smallest number of samples on a side (one interior sample between two border samples).
pub const MIN_SIDE: usize = 3;

/// Size and spacing of a solver grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridSpec {
    /// Samples along x (columns): `2^a + 1`, in `MIN_SIDE..=MAX_SIDE`.
    pub nx: usize,
    /// Samples along z (rows): `2^b + 1`, in `MIN_SIDE..=MAX_SIDE`.
    pub nz: usize,
    /// Distance between neighbouring samples, metres (finite, > 0).
    pub spacing_m: f64,
}

impl GridSpec {
    /// A validated grid.
    ///
    /// # Errors
    /// [`PoissonError::Field`] naming `nx`, `nz` or `spacing_m` if a side is not `2^k + 1` within
    /// `MIN_SIDE..=MAX_SIDE`, or the spacing is not finite and positive.
    pub fn new(nx: usize, nz: usize, spacing_m: f64) -> Result<Self, PoissonError> {
        for (name, n) in [("nx", nx), ("nz", nz)] {
            if !(MIN_SIDE..=MAX_SIDE).contains(&n) || !(n - 1).is_power_of_two() {
                return Err(PoissonError::field(
                    name,
                    format!("{n} samples; a side must be 2^k + 1 in {MIN_SIDE}..={MAX_SIDE}"),
                ));
            }
        }
        if !(spacing_m.is_finite() && spacing_m > 0.0) {
            return Err(PoissonError::field(
                "spacing_m",
                format!("{spacing_m}; the spacing must be finite and > 0 metres"),
            ));
        }
        Ok(Self { nx, nz, spacing_m })
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.nx * self.nz
    }

    /// Always false: a grid has at least 3 × 3 samples.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Number of x-edges `(i + ½, j)`: `(nx − 1) · nz`.
    pub fn x_edges(&self) -> usize {
        (self.nx - 1) * self.nz
    }

    /// Number of z-edges `(i, j + ½)`: `nx · (nz − 1)`.
    pub fn z_edges(&self) -> usize {
        self.nx * (self.nz - 1)
    }

    /// The grid of the next coarser multigrid level, if both sides can be halved and stay ≥ 3.
    pub fn coarser(&self) -> Option<Self> {
        if self.nx < 5 || self.nz < 5 {
            return None;
        }
        Some(Self {
            nx: (self.nx - 1) / 2 + 1,
            nz: (self.nz - 1) / 2 + 1,
            spacing_m: self.spacing_m * 2.0,
        })
    }

    /// True for samples on the border of the domain (always Dirichlet).
    pub fn is_border(&self, i: usize, j: usize) -> bool {
        i == 0 || j == 0 || i + 1 == self.nx || j + 1 == self.nz
    }
}

/// The colour-split layout of one grid (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Split {
    /// Samples along x.
    pub nx: usize,
    /// Samples along z.
    pub nz: usize,
    /// Slots per row of each colour array: `(nx + 1) / 2`.
    pub stride: usize,
}

impl Split {
    /// The layout of an `nx × nz` grid.
    pub fn new(nx: usize, nz: usize) -> Self {
        Self {
            nx,
            nz,
            stride: nx.div_ceil(2),
        }
    }

    /// Length of each colour array (`nz · stride`).
    pub fn len(&self) -> usize {
        self.nz * self.stride
    }

    /// Always false: a grid has at least one row.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Column parity `s` of colour `c` in row `j`.
    #[inline]
    pub fn shift(c: usize, j: usize) -> usize {
        (c + j) & 1
    }

    /// Number of samples of colour `c` in row `j`.
    #[inline]
    pub fn count(&self, c: usize, j: usize) -> usize {
        if Self::shift(c, j) == 0 {
            self.stride
        } else {
            self.nx / 2
        }
    }

    /// `(colour, index into that colour's array)` of sample `(i, j)`.
    #[inline]
    pub fn locate(&self, i: usize, j: usize) -> (usize, usize) {
        let c = (i + j) & 1;
        (c, j * self.stride + i / 2)
    }

    /// Splits a row-major natural array (`nx · nz`, index `j · nx + i`) into the two colours.
    pub fn split<T: Copy + Default>(&self, natural: &[T]) -> [Vec<T>; 2] {
        let mut out = [
            vec![T::default(); self.len()],
            vec![T::default(); self.len()],
        ];
        self.split_into(natural, &mut out);
        out
    }

    /// [`Self::split`] into existing colour arrays (padding slots are left untouched).
    pub fn split_into<T: Copy>(&self, natural: &[T], out: &mut [Vec<T>; 2]) {
        for (j, row) in natural.chunks_exact(self.nx).enumerate().take(self.nz) {
            for (i, v) in row.iter().enumerate() {
                let (c, k) = self.locate(i, j);
                out[c][k] = *v;
            }
        }
    }

    /// The row-major natural array of two colour arrays, converted by `f`.
    pub fn merge_into<T: Copy, U>(&self, colours: &[Vec<T>; 2], out: &mut [U], f: impl Fn(T) -> U) {
        for (j, row) in out.chunks_exact_mut(self.nx).enumerate().take(self.nz) {
            for (i, v) in row.iter_mut().enumerate() {
                let (c, k) = self.locate(i, j);
                *v = f(colours[c][k]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_sizes_are_validated() {
        assert!(GridSpec::new(3, 3, 1.0).is_ok());
        assert!(GridSpec::new(1025, 65, 2.5).is_ok());
        for (nx, nz, s, field) in [
            (2, 3, 1.0, "nx"),
            (3, 4, 1.0, "nz"),
            (1024, 1025, 1.0, "nx"),
            (16385, 3, 1.0, "nx"),
            (3, 3, 0.0, "spacing_m"),
            (3, 3, f64::NAN, "spacing_m"),
        ] {
            match GridSpec::new(nx, nz, s) {
                Err(PoissonError::Field { field: f, .. }) => assert_eq!(f, field),
                other => {
                    panic!("{nx}×{nz} spacing {s}: expected an error on {field}, got {other:?}")
                }
            }
        }
    }

    #[test]
    fn coarsening_halves_both_sides_down_to_three() {
        let g = GridSpec::new(17, 5, 1.0).expect("grid");
        let c = g.coarser().expect("coarser");
        assert_eq!((c.nx, c.nz, c.spacing_m), (9, 3, 2.0));
        assert!(c.coarser().is_none());
    }

    #[test]
    fn split_and_merge_round_trip_and_colours_alternate() {
        let s = Split::new(9, 5);
        let natural: Vec<u32> = (0..45).collect();
        let colours = s.split(&natural);
        let mut back = vec![0u32; 45];
        s.merge_into(&colours, &mut back, |v| v);
        assert_eq!(back, natural);
        for j in 0..5 {
            for c in 0..2 {
                let sh = Split::shift(c, j);
                for k in 0..s.count(c, j) {
                    let i = 2 * k + sh;
                    assert_eq!((i + j) & 1, c);
                    assert_eq!(colours[c][j * s.stride + k], (j * 9 + i) as u32);
                }
            }
        }
    }
}
