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
use rayon::prelude::*;

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
    coarse.nine = None;
    coarsen_rows(fine, coarse, 0, fine.grid.nz - 1);
}

/// Updates `coarse` after the mask or the operator of `fine` changed in fine rows `a..=b`: the
/// injected mask rows `2J ∈ a..=b` and the stencils of the coarse rows within reach
/// (`|2J − j| ≤ 2` for a changed fine row `j`), spliced into the special list. Returns the coarse
/// rows whose mask or stencils may have changed (for the next coarser level). Rows run in
/// parallel; a `coarse` without an operator yet gets a complete one.
pub fn coarsen_rows(fine: &Level, coarse: &mut Level, a: usize, b: usize) -> (usize, usize) {
    let cg = coarse.grid;
    let cs = coarse.split;
    let cst = cs.stride;
    let (m0, m1) = (a.div_ceil(2), (b / 2).min(cg.nz - 1));
    {
        let [f0, f1] = &mut coarse.free;
        f0.par_chunks_mut(cst)
            .zip(f1.par_chunks_mut(cst))
            .enumerate()
            .filter(|(jc, _)| (m0..=m1).contains(jc))
            .for_each(|(jc, (r0, r1))| {
                for (c, row) in [r0, r1].into_iter().enumerate() {
                    let s = Split::shift(c, jc);
                    for (k, slot) in row.iter_mut().enumerate().take(cs.count(c, jc)) {
                        let ic = 2 * k + s;
                        *slot = u8::from(!cg.is_border(ic, jc) && fine.is_free(2 * ic, 2 * jc));
                    }
                }
            });
    }
    let fine_default = fine.nine.as_ref().map_or(FIVE_POINT, |op| op.default);
    let default = galerkin_default(&fine_default);
    let (s0, s1) = match &coarse.nine {
        Some(op) if op.default == default => (
            a.saturating_sub(2).div_ceil(2),
            ((b + 2) / 2).min(cg.nz - 1),
        ),
        _ => (0, cg.nz - 1),
    };
    let rows: Vec<Vec<Special>> = (s0..=s1)
        .into_par_iter()
        .map(|jc| row_specials(fine, coarse, &default, jc))
        .collect();
    let old = coarse
        .nine
        .take()
        .filter(|op| op.default == default)
        .unwrap_or_else(|| NinePoint::uniform(default, cg.nz));
    let mut op = NinePoint::uniform(default, cg.nz);
    op.special
        .extend_from_slice(&old.special[..old.row_start[s0]]);
    op.row_start[..=s0].copy_from_slice(&old.row_start[..=s0]);
    for (jc, row) in (s0..=s1).zip(rows) {
        op.row_start[jc] = op.special.len();
        op.special.extend(row);
    }
    let tail = old.row_start[s1 + 1];
    let shift = op.special.len() as isize - tail as isize;
    op.special.extend_from_slice(&old.special[tail..]);
    for jc in s1 + 1..=cg.nz {
        op.row_start[jc] = (old.row_start[jc] as isize + shift) as usize;
    }
    coarse.nine = Some(op);
    (s0, s1)
}

/// The special stencils of coarse row `jc`: the coarse free samples within reach of a fine
/// non-default sample (an interior fixed sample, or one with its own stencil: `|2I − n| ≤ 2` in
/// both directions) whose Galerkin stencil differs from the masked default, in colour then slot
/// order.
fn row_specials(fine: &Level, coarse: &Level, default: &[f64; 9], jc: usize) -> Vec<Special> {
    let (cg, fg) = (coarse.grid, fine.grid);
    let mut out = Vec::new();
    if jc == 0 || jc + 1 >= cg.nz {
        return out;
    }
    let mut near = vec![false; cg.nx];
    let mut mark = |i: usize| {
        let (i0, i1) = (
            i.saturating_sub(2).div_ceil(2),
            ((i + 2) / 2).min(cg.nx - 1),
        );
        near[i0..=i1].fill(true);
    };
    let fs = fine.split;
    let mut any = false;
    for j in (2 * jc).saturating_sub(2).max(1)..=(2 * jc + 2).min(fg.nz - 2) {
        for c in 0..2 {
            let s = Split::shift(c, j);
            let row = &fine.free[c][j * fs.stride..(j + 1) * fs.stride];
            for (k, f) in row.iter().enumerate().take(fg.nx / 2).skip(1 - s) {
                if *f == 0 {
                    mark(2 * k + s);
                    any = true;
                }
            }
        }
        if let Some(op) = &fine.nine {
            for sp in op.row(j) {
                mark(2 * (sp.slot - j * fs.stride) + Split::shift(sp.colour, j));
                any = true;
            }
        }
    }
    if !any {
        return out;
    }
    for c in 0..2 {
        let s = Split::shift(c, jc);
        for k in 1 - s..cg.nx / 2 {
            let ic = 2 * k + s;
            if !near[ic] || !coarse.is_free(ic, jc) {
                continue;
            }
            let stencil = galerkin_at(fine, coarse, ic, jc);
            let mut masked = *default;
            for dz in -1..=1isize {
                for dx in -1..=1isize {
                    let (x, z) = ((ic as isize + dx) as usize, (jc as isize + dz) as usize);
                    if !coarse.is_free(x, z) {
                        masked[entry(dx, dz)] = 0.0;
                    }
                }
            }
            if stencil != masked {
                out.push(Special {
                    colour: c,
                    slot: jc * coarse.split.stride + k,
                    stencil,
                    inv_centre: 1.0 / stencil[4],
                });
            }
        }
    }
    out
}
