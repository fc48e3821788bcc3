//! Galerkin coarse operators `A_c = Pᵀ A P` of the multigrid hierarchy.
//!
//! `P` is bilinear interpolation from the coarse free samples to the fine free samples: a fine
//! sample at offset `d` (each component −1, 0 or 1) from the counterpart `(2I, 2J)` of a coarse
//! sample receives the weight `w(d) = (1 − |d_x|/2)(1 − |d_z|/2)` of that coarse value. Its rows
//! at fixed fine samples are zero (a fixed sample takes no correction), its columns at fixed
//! coarse samples are dropped (a fixed coarse sample carries no correction), and a fine sample
//! at an odd-odd position takes no weight from a corner when both samples between them are fixed
//! ([`interpolation_weight`]): a constraint curve with a diagonal step separates them, and
//! interpolating across it would couple the corrections of its two sides. The restriction is
//! `Pᵀ` (full weighting times 4, [`super::ops`]), so `A_c` is the Galerkin product and the
//! coarse-grid correction is the energy-optimal one in the range of `P`, whatever the constraints:
//! this is what keeps the per-cycle reduction steady with interior Dirichlet samples.
//!
//! A coarse sample is fixed exactly when its fine counterpart is ("injection" of the mask). Any
//! interior fixed sample of the fine level changes the Galerkin stencils of the coarse samples
//! within two fine samples of it; elsewhere a coarse level's stencil is the same everywhere (the
//! Galerkin product of the finer level's default stencil, see [`galerkin_default`]; at coarse
//! samples next to the border the stencil is the default one too, because the fine border
//! samples interpolate only from coarse border samples, whose correction is zero). So a coarse
//! operator is stored as one default 3 × 3 stencil and the list of samples whose stencil differs
//! ([`NinePoint::special`]), found by computing the Galerkin product at every coarse sample within
//! reach of a fine non-default sample and keeping those that differ. The stencil values are sums
//! of products of dyadic fractions (the weights are 1, ½, ¼), exact in `f64` down to the deepest
//! levels of the largest grids, so the assembled operator is exactly symmetric.

use super::grid::Split;
use super::level::Level;

/// Index of the stencil entry of offset `(dx, dz)` (each in −1..=1): `(dz + 1) · 3 + (dx + 1)`.
/// Row `dz = −1` is the row above (`j − 1`).
#[inline]
pub fn entry(dx: isize, dz: isize) -> usize {
    ((dz + 1) * 3 + (dx + 1)) as usize
}

/// The finest level's 5-point operator as a 3 × 3 stencil.
pub const FIVE_POINT: [f64; 9] = [0.0, 1.0, 0.0, 1.0, -4.0, 1.0, 0.0, 1.0, 0.0];

/// A sample whose Galerkin stencil differs from its level's default stencil.
#[derive(Clone, Debug, PartialEq)]
pub struct Special {
    /// Colour array of the sample (0 red, 1 black).
    pub colour: usize,
    /// Index of the sample in its colour array (`j · stride + k`).
    pub slot: usize,
    /// Its 3 × 3 stencil ([`entry`] order).
    pub stencil: [f64; 9],
    /// `1 / stencil[4]`.
    pub inv_centre: f64,
}

/// A coarse level's 9-point operator: one default stencil and the samples that differ from it.
#[derive(Clone, Debug, PartialEq)]
pub struct NinePoint {
    /// The stencil of every free sample not listed in `special` ([`entry`] order).
    pub default: [f64; 9],
    /// `1 / default[4]`.
    pub inv_default: f64,
    /// Samples with their own stencil, sorted by row, then colour, then slot.
    pub special: Vec<Special>,
    /// `special[row_start[j]..row_start[j + 1]]` are the special samples of row `j`
    /// (`nz + 1` entries).
    pub row_start: Vec<usize>,
}

impl NinePoint {
    /// An operator with only the default stencil, for a level of `nz` rows.
    pub fn uniform(default: [f64; 9], nz: usize) -> Self {
        Self {
            default,
            inv_default: 1.0 / default[4],
            special: Vec::new(),
            row_start: vec![0; nz + 1],
        }
    }

    /// The special samples of row `j`.
    #[inline]
    pub fn row(&self, j: usize) -> &[Special] {
        &self.special[self.row_start[j]..self.row_start[j + 1]]
    }

    /// The stencil of the sample in slot `slot` of colour `colour`, row `j`.
    pub fn stencil(&self, colour: usize, slot: usize, j: usize) -> [f64; 9] {
        self.row(j)
            .iter()
            .find(|s| s.colour == colour && s.slot == slot)
            .map_or(self.default, |s| s.stencil)
    }

    /// Bytes held by the special list.
    pub fn bytes(&self) -> usize {
        self.special.len() * std::mem::size_of::<Special>()
            + self.row_start.len() * std::mem::size_of::<usize>()
    }
}

/// Bilinear interpolation weight of a fine sample at offset `(x, z)` from a coarse counterpart
/// (zero beyond one sample).
#[inline]
fn weight(x: isize, z: isize) -> f64 {
    if x.abs() > 1 || z.abs() > 1 {
        return 0.0;
    }
    (1.0 - 0.5 * x.abs() as f64) * (1.0 - 0.5 * z.abs() as f64)
}

/// The Galerkin product of a constant stencil on an unbounded grid: the default stencil of the
/// next coarser level. (The 5-point stencil gives `¼ [1 2 1; 2 −12 2; 1 2 1]`.)
pub fn galerkin_default(fine: &[f64; 9]) -> [f64; 9] {
    let mut out = [0.0; 9];
    for dz in -1..=1isize {
        for dx in -1..=1isize {
            let mut sum = 0.0;
            for az in -1..=1isize {
                for ax in -1..=1isize {
                    let wa = weight(ax, az);
                    for ez in -1..=1isize {
                        for ex in -1..=1isize {
                            let a = fine[entry(ex, ez)];
                            if a == 0.0 {
                                continue;
                            }
                            sum += wa * a * weight(ax + ex - 2 * dx, az + ez - 2 * dz);
                        }
                    }
                }
            }
            out[entry(dx, dz)] = sum;
        }
    }
    out
}

/// The interpolation weight `P(f, I)` of coarse sample `(ci, cj)` at fine sample `(fi, fj)`: the
/// bilinear weight, except that a fine sample at an odd-odd position takes nothing from a corner
/// when both samples connecting it to that corner are fixed (the corner lies across a
/// constraint, e.g. a diagonal step of a curve).
pub fn interpolation_weight(fine: &Level, fi: usize, fj: usize, ci: usize, cj: usize) -> f64 {
    let (x, z) = (fi as isize - 2 * ci as isize, fj as isize - 2 * cj as isize);
    let w = weight(x, z);
    if w == 0.0 || x == 0 || z == 0 {
        return w;
    }
    let open = fine.is_free((fi as isize - x) as usize, fj)
        || fine.is_free(fi, (fj as isize - z) as usize);
    if open {
        w
    } else {
        0.0
    }
}

/// The stencil of fine sample `(i, j)` of `level` (5-point on the finest level).
fn fine_stencil(level: &Level, i: usize, j: usize) -> [f64; 9] {
    match &level.nine {
        None => FIVE_POINT,
        Some(op) => {
            let (c, k) = level.split.locate(i, j);
            op.stencil(c, k, j)
        }
    }
}

/// The Galerkin stencil of coarse sample `(ic, jc)` from `fine` and the coarse free mask.
fn galerkin_at(fine: &Level, coarse: &Level, ic: usize, jc: usize) -> [f64; 9] {
    let mut out = [0.0; 9];
    let (ci, cj) = (ic as isize, jc as isize);
    for az in -1..=1isize {
        for ax in -1..=1isize {
            let (ai, aj) = ((2 * ci + ax) as usize, (2 * cj + az) as usize);
            if !fine.is_free(ai, aj) {
                continue;
            }
            let wa = interpolation_weight(fine, ai, aj, ic, jc);
            if wa == 0.0 {
                continue;
            }
            let row = fine_stencil(fine, ai, aj);
            for ez in -1..=1isize {
                for ex in -1..=1isize {
                    let a = row[entry(ex, ez)];
                    if a == 0.0 {
                        continue;
                    }
                    let (bi, bj) = (ai as isize + ex, aj as isize + ez);
                    if !fine.is_free(bi as usize, bj as usize) {
                        continue;
                    }
                    for dz in -1..=1isize {
                        for dx in -1..=1isize {
                            let (jx, jz) = (ci + dx, cj + dz);
                            if weight(bi - 2 * jx, bj - 2 * jz) == 0.0
                                || !coarse.is_free(jx as usize, jz as usize)
                            {
                                continue;
                            }
                            let w = interpolation_weight(
                                fine,
                                bi as usize,
                                bj as usize,
                                jx as usize,
                                jz as usize,
                            );
                            out[entry(dx, dz)] += wa * a * w;
                        }
                    }
                }
            }
        }
    }
    out
}

/// Sets the free mask of `coarse` by injection from `fine` and computes its Galerkin operator.
pub fn coarsen_into(fine: &Level, coarse: &mut Level) {
    let (cg, fg) = (coarse.grid, fine.grid);
    for jc in 0..cg.nz {
        for ic in 0..cg.nx {
            let (c, k) = coarse.split.locate(ic, jc);
            coarse.free[c][k] = u8::from(!cg.is_border(ic, jc) && fine.is_free(2 * ic, 2 * jc));
        }
    }
    let fine_default = fine.nine.as_ref().map_or(FIVE_POINT, |op| op.default);
    let default = galerkin_default(&fine_default);
    // Coarse samples within reach of a fine non-default sample (an interior fixed sample, or a
    // sample with its own stencil): `|2I − n| ≤ 2` in both directions.
    let mut near = vec![false; cg.nx * cg.nz];
    let mut mark = |i: usize, j: usize| {
        let (i0, i1) = (
            i.saturating_sub(2).div_ceil(2),
            ((i + 2) / 2).min(cg.nx - 1),
        );
        let (j0, j1) = (
            j.saturating_sub(2).div_ceil(2),
            ((j + 2) / 2).min(cg.nz - 1),
        );
        for jc in j0..=j1 {
            for ic in i0..=i1 {
                near[jc * cg.nx + ic] = true;
            }
        }
    };
    let fs = fine.split;
    for j in 1..fg.nz - 1 {
        for c in 0..2 {
            let s = Split::shift(c, j);
            let row = &fine.free[c][j * fs.stride..(j + 1) * fs.stride];
            for (k, f) in row.iter().enumerate().take(fg.nx / 2).skip(1 - s) {
                if *f == 0 {
                    mark(2 * k + s, j);
                }
            }
        }
    }
    if let Some(op) = &fine.nine {
        for (j, sp) in (0..fg.nz).flat_map(|j| op.row(j).iter().map(move |s| (j, s))) {
            mark(
                2 * (sp.slot - j * fs.stride) + Split::shift(sp.colour, j),
                j,
            );
        }
    }
    let mut op = NinePoint::uniform(default, cg.nz);
    for jc in 1..cg.nz - 1 {
        op.row_start[jc] = op.special.len();
        for c in 0..2 {
            let s = Split::shift(c, jc);
            for k in 1 - s..cg.nx / 2 {
                let ic = 2 * k + s;
                if !near[jc * cg.nx + ic] || !coarse.is_free(ic, jc) {
                    continue;
                }
                let stencil = galerkin_at(fine, coarse, ic, jc);
                let mut masked = default;
                for dz in -1..=1isize {
                    for dx in -1..=1isize {
                        let (x, z) = ((ic as isize + dx) as usize, (jc as isize + dz) as usize);
                        if !coarse.is_free(x, z) {
                            masked[entry(dx, dz)] = 0.0;
                        }
                    }
                }
                if stencil != masked {
                    op.special.push(Special {
                        colour: c,
                        slot: jc * coarse.split.stride + k,
                        stencil,
                        inv_centre: 1.0 / stencil[4],
                    });
                }
            }
        }
    }
    op.row_start[cg.nz - 1] = op.special.len();
    op.row_start[cg.nz] = op.special.len();
    coarse.nine = Some(op);
}
