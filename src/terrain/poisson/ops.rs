//! The multigrid kernels on one level or between two levels: red-black Gauss–Seidel half-sweeps,
//! the residual, full-weighting restriction (fused with the residual and its norm) and bilinear
//! prolongation. `shaders/poisson.wgsl` holds their WGSL twins.
//!
//! Why one file of about 1,000 lines (850 of kernels, the rest tests): each kernel is the CPU half
//! of a WGSL twin that must evaluate the same expressions in the same order, and all of them share
//! the private row, band and colour helpers below; kept together, the order stated here can be
//! checked against `shaders/poisson.wgsl` in one place.
//!
//! Every kernel works row by row on contiguous slices of the colour-split arrays
//! ([`super::grid`]); rows are distributed over rayon's threads in bands when a level has at least
//! [`PARALLEL_MIN_SAMPLES`] samples. Each output value is a fixed expression of its inputs (no
//! reduction across rows inside a value), so results do not depend on the band split or the thread
//! count. Residual norms are summed per row with eight interleaved accumulators and the row sums
//! are added in row order: also independent of the thread count.
//!
//! Operator, in the order the CPU and the WGSL twin evaluate it (`Σ = ((l + r) + u) + d`):
//! - smoother at a free sample: `h ← (Σ − b) · 0.25`;
//! - residual at a free sample: `r = b − (Σ − 4 h)`, zero at fixed samples;
//! - restriction: `b_c = ¼ · (4 r_c + 2 (r_w + r_e + r_n + r_s) + o r_nw + o r_ne + o r_sw +
//!   o r_se)`, the full-weighting average times 4 because the coarse operator has twice the
//!   spacing (`Pᵀ`);
//! - prolongation `P`: coarse values at even-even samples, the mean of two at even-odd and
//!   odd-even samples, `((o a + o b) + (o c + o d)) · 0.25` at odd-odd samples;
//! - `o` is 1, or 0 for a corner whose two connecting fine samples are both fixed (it lies across
//!   a constraint, [`super::galerkin::interpolation_weight`]);
//! - on coarse levels the 9-point smoother and residual of [`smooth_nine`] and the residual.

use super::grid::Split;
use super::level::Level;
use rayon::prelude::*;

/// Levels with at least this many samples run their loops on several threads.
pub const PARALLEL_MIN_SAMPLES: usize = 1 << 16;

/// Rows per parallel task for a level of `rows` rows.
fn band_rows(rows: usize) -> usize {
    let tasks = 4 * rayon::current_num_threads().max(1);
    rows.div_ceil(tasks).max(4)
}

fn parallel(split: &Split) -> bool {
    split.nx * split.nz >= PARALLEL_MIN_SAMPLES
}

/// Runs `f(first_row, rows)` over bands of `rows_of` rows of `data` (row length `stride`).
fn for_bands<T: Send>(
    data: &mut [T],
    stride: usize,
    par: bool,
    f: impl Fn(usize, &mut [T]) + Send + Sync,
) {
    let rows = data.len() / stride;
    let band = band_rows(rows);
    if par {
        data.par_chunks_mut(band * stride)
            .enumerate()
            .for_each(|(b, chunk)| f(b * band, chunk));
    } else {
        data.chunks_mut(band * stride)
            .enumerate()
            .for_each(|(b, chunk)| f(b * band, chunk));
    }
}

/// The slot range `k0..k1` of the interior samples of colour `c` in row `j`, and the column
/// parity `s` of that colour row: left neighbours are `other[j][k − 1 + s]`, right neighbours
/// `other[j][k + s]`, vertical neighbours `other[j ± 1][k]`.
#[inline]
fn interior(split: &Split, c: usize, j: usize) -> (usize, usize, usize) {
    let s = Split::shift(c, j);
    (1 - s, split.nx / 2, s)
}

/// One red-black Gauss–Seidel half-sweep over the free samples of colour `c`.
pub fn smooth_colour(level: &mut Level, c: usize) {
    let split = level.split;
    let st = split.stride;
    let par = parallel(&split);
    let [h0, h1] = &mut level.h;
    let (x, y) = if c == 0 { (h0, &*h1) } else { (h1, &*h0) };
    let b = &level.rhs[c];
    let f = &level.free[c];
    for_bands(x, st, par, |j0, rows| {
        for (dj, xrow) in rows.chunks_exact_mut(st).enumerate() {
            let j = j0 + dj;
            if j == 0 || j + 1 == split.nz {
                continue;
            }
            let (k0, k1, s) = interior(&split, c, j);
            let yc = &y[j * st..(j + 1) * st];
            smooth_row(
                &mut xrow[k0..k1],
                &yc[k0 + s - 1..k1 + s - 1],
                &yc[k0 + s..k1 + s],
                &y[(j - 1) * st + k0..(j - 1) * st + k1],
                &y[(j + 1) * st + k0..(j + 1) * st + k1],
                &b[j * st + k0..j * st + k1],
                &f[j * st + k0..j * st + k1],
            );
        }
    });
}

#[inline(always)]
fn smooth_row(x: &mut [f64], l: &[f64], r: &[f64], u: &[f64], d: &[f64], b: &[f64], f: &[u8]) {
    let n = x.len();
    let (l, r, u, d, b, f) = (&l[..n], &r[..n], &u[..n], &d[..n], &b[..n], &f[..n]);
    for k in 0..n {
        let v = (l[k] + r[k] + u[k] + d[k] - b[k]) * 0.25;
        x[k] = if f[k] != 0 { v } else { x[k] };
    }
}

/// The four colours of the 9-point smoother on coarse levels: `(colour array, row parity)`. No
/// two samples of one of them are neighbours in a 3 × 3 stencil.
const FOUR_COLOURS: [(usize, usize); 4] = [(0, 0), (0, 1), (1, 0), (1, 1)];

/// `sweeps` Gauss–Seidel sweeps: red then black on the finest level (5-point), the four colours
/// of [`FOUR_COLOURS`] in order on coarse levels (9-point).
pub fn smooth(level: &mut Level, sweeps: usize) {
    level.relaxed += (sweeps * level.grid.len()) as u64;
    for _ in 0..sweeps {
        if level.nine.is_some() {
            for (c, p) in FOUR_COLOURS {
                smooth_nine(level, c, p);
            }
        } else {
            smooth_colour(level, 0);
            smooth_colour(level, 1);
        }
    }
}

/// `sweeps` sweeps in the reverse colour order: the adjoint of [`smooth`], for post-smoothing, so
/// a cycle is a symmetric operator (a valid conjugate-gradient preconditioner).
pub fn smooth_reverse(level: &mut Level, sweeps: usize) {
    level.relaxed += (sweeps * level.grid.len()) as u64;
    for _ in 0..sweeps {
        if level.nine.is_some() {
            for (c, p) in FOUR_COLOURS.into_iter().rev() {
                smooth_nine(level, c, p);
            }
        } else {
            smooth_colour(level, 1);
            smooth_colour(level, 0);
        }
    }
}

/// The eight neighbour rows of a colour row on a 9-point level, each a slice aligned with the
/// row's interior slots `k0..k1`: `[uw, u, ue, w, e, dw, d, de]` (`u` the row above, `j − 1`).
type Neighbours<'a> = [&'a [f64]; 8];

/// Neighbour slices of the interior slots `k0..k1` of colour `c` in row `j`: `other` is the other
/// colour's array, `up` and `down` this colour's rows `j ∓ 1`.
#[inline]
fn neighbours<'a>(
    split: &Split,
    c: usize,
    j: usize,
    other: &'a [f64],
    up: &'a [f64],
    down: &'a [f64],
) -> (usize, usize, Neighbours<'a>) {
    let (k0, k1, _) = interior(split, c, j);
    (
        k0,
        k1,
        neighbours_of_slots(split, c, j, k0, k1, other, up, down),
    )
}

/// Neighbour slices of the slots `k0..k1` of colour `c` in row `j` (interior samples only): the
/// sample of slot `k` is column `2k + s`, `s` the row's shift, so its left and right neighbours
/// are slots `k + s − 1` and `k + s` of the other colour's row and of this colour's rows `j ∓ 1`.
#[inline]
#[allow(clippy::too_many_arguments)]
fn neighbours_of_slots<'a>(
    split: &Split,
    c: usize,
    j: usize,
    k0: usize,
    k1: usize,
    other: &'a [f64],
    up: &'a [f64],
    down: &'a [f64],
) -> Neighbours<'a> {
    let st = split.stride;
    let s = Split::shift(c, j);
    let (a, b) = (k0 + s - 1, k0 + s);
    let n = k1 - k0;
    let yc = &other[j * st..(j + 1) * st];
    [
        &up[a..a + n],
        &other[(j - 1) * st + k0..(j - 1) * st + k1],
        &up[b..b + n],
        &yc[a..a + n],
        &yc[b..b + n],
        &down[a..a + n],
        &other[(j + 1) * st + k0..(j + 1) * st + k1],
        &down[b..b + n],
    ]
}

/// `Σ` of the off-centre stencil terms at position `k` of the neighbour slices, in the order the
/// WGSL twin uses: `((w + e) + (u + d)) + ((uw + ue) + (dw + de))`, each term weighted.
#[inline(always)]
fn off_centre(s: &[f64; 9], nb: &Neighbours, k: usize) -> f64 {
    let [uw, u, ue, w, e, dw, d, de] = nb;
    ((s[3] * w[k] + s[5] * e[k]) + (s[1] * u[k] + s[7] * d[k]))
        + ((s[0] * uw[k] + s[2] * ue[k]) + (s[6] * dw[k] + s[8] * de[k]))
}

/// The rows `j` of parity `p` in `rows` of a colour array (row length `st`) as mutable slices
/// with their index, and every row as a shared slice (empty for the mutable ones): a half-sweep
/// writes the former and reads the neighbouring rows of the latter.
#[allow(clippy::type_complexity)]
fn split_rows(
    x: &mut [f64],
    st: usize,
    p: usize,
    rows: std::ops::RangeInclusive<usize>,
) -> (Vec<(usize, &mut [f64])>, Vec<&[f64]>) {
    let nz = x.len() / st;
    let mut mine = Vec::with_capacity(nz / 2 + 1);
    let mut same: Vec<&[f64]> = Vec::with_capacity(nz);
    for (j, row) in x.chunks_mut(st).enumerate() {
        if j % 2 == p && rows.contains(&j) {
            mine.push((j, row));
            same.push(&[]);
        } else {
            same.push(row);
        }
    }
    (mine, same)
}

/// One Gauss–Seidel pass over the free samples of colour `c` in the rows of parity `p` of a
/// coarse (9-point) level: `h ← (b − Σ) / s_c`. The rows written are disjoint from every row
/// read, so rows run in parallel.
pub fn smooth_nine(level: &mut Level, c: usize, p: usize) {
    let (nx, nz) = (level.split.nx, level.split.nz);
    smooth_nine_spans::<true>(level, c, p, 1..=nz - 2, |_| [Some((1, nx - 2)), None]);
}

/// The Gauss–Seidel update of [`smooth_nine`] restricted to the free samples of colour `c` in
/// the rows `j` of parity `p` in `rows` and, in each, the column spans `spans(j)` (at most two;
/// `None` for none) of a coarse (9-point) level, all interior (`1 ≤ i`, `i ≤ nx − 2`,
/// `1 ≤ j ≤ nz − 2`); with `RHS` false the right-hand side is taken as zero (the composite
/// correction of [`super::local`]). The rows written are disjoint from every row read, so rows
/// run in parallel on large levels; the result does not depend on it.
pub fn smooth_nine_spans<const RHS: bool>(
    level: &mut Level,
    c: usize,
    p: usize,
    rows: std::ops::RangeInclusive<usize>,
    spans: impl Fn(usize) -> [Option<(usize, usize)>; 2] + Sync,
) {
    let split = level.split;
    let st = split.stride;
    let nz = split.nz;
    let Some(op) = level.nine.as_ref() else {
        return;
    };
    debug_assert!(*rows.start() >= 1 && *rows.end() + 2 <= nz);
    let [h0, h1] = &mut level.h;
    let (x, y) = if c == 0 { (h0, &*h1) } else { (h1, &*h0) };
    let (b, f) = (&level.rhs[c], &level.free[c]);
    let (mut mine, same) = split_rows(x, st, p, rows);
    let work = |(j, xrow): &mut (usize, &mut [f64])| {
        let j = *j;
        let s = Split::shift(c, j);
        for (i_lo, i_hi) in spans(j).into_iter().flatten() {
            debug_assert!(i_lo >= 1 && i_hi + 2 <= split.nx);
            // Slots `k` with `i_lo ≤ 2k + s ≤ i_hi`.
            let (k0, k1) = ((i_lo + 1 - s) / 2, (i_hi - s) / 2 + 1);
            if k0 >= k1 {
                continue;
            }
            let nb = neighbours_of_slots(&split, c, j, k0, k1, y, same[j - 1], same[j + 1]);
            let xr = &mut xrow[k0..k1];
            let br = &b[j * st + k0..j * st + k1];
            let fr = &f[j * st + k0..j * st + k1];
            let bk = |k: usize| if RHS { br[k] } else { 0.0 };
            let (sd, inv) = (&op.default, op.inv_default);
            for k in 0..xr.len() {
                let v = (bk(k) - off_centre(sd, &nb, k)) * inv;
                xr[k] = if fr[k] != 0 { v } else { xr[k] };
            }
            for sp in op.row(j) {
                if sp.colour == c && (j * st + k0..j * st + k1).contains(&sp.slot) {
                    let k = sp.slot - j * st - k0;
                    if fr[k] != 0 {
                        xr[k] = (bk(k) - off_centre(&sp.stencil, &nb, k)) * sp.inv_centre;
                    }
                }
            }
        }
    };
    let band = band_rows(mine.len());
    if parallel(&split) {
        mine.par_iter_mut().with_min_len(band).for_each(work);
    } else {
        mine.iter_mut().for_each(work);
    }
}

/// Values per chunk of the flat vector operations (fixed, so sums do not depend on threads).
const CHUNK: usize = 1 << 14;

/// `Σ a·b` over two colour-array pairs, in a thread-count-independent order.
pub fn dot(a: &[Vec<f64>; 2], b: &[Vec<f64>; 2]) -> f64 {
    let mut total = 0.0;
    for c in 0..2 {
        let parts: Vec<f64> = a[c]
            .par_chunks(CHUNK)
            .zip(b[c].par_chunks(CHUNK))
            .map(|(x, y)| dot_slice(x, y))
            .collect();
        total += parts.iter().sum::<f64>();
    }
    total
}

#[inline]
fn dot_slice(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len().min(y.len());
    let (x, y) = (&x[..n], &y[..n]);
    let mut acc = [0.0f64; 8];
    let mut k = 0;
    while k + 8 <= n {
        for l in 0..8 {
            acc[l] += x[k + l] * y[k + l];
        }
        k += 8;
    }
    for l in 0..n - k {
        acc[l] += x[k + l] * y[k + l];
    }
    ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]))
}

/// `x += α p` and `r += α q` (element-wise on colour arrays); returns `‖r‖²`.
pub fn update_solution(
    x: &mut [Vec<f64>; 2],
    r: &mut [Vec<f64>; 2],
    p: &[Vec<f64>; 2],
    q: &[Vec<f64>; 2],
    alpha: f64,
) -> f64 {
    let mut total = 0.0;
    for c in 0..2 {
        let parts: Vec<f64> = x[c]
            .par_chunks_mut(CHUNK)
            .zip(r[c].par_chunks_mut(CHUNK))
            .zip(p[c].par_chunks(CHUNK))
            .zip(q[c].par_chunks(CHUNK))
            .map(|(((x, r), p), q)| {
                let n = x.len();
                let (r, p, q) = (&mut r[..n], &p[..n], &q[..n]);
                for k in 0..n {
                    x[k] += alpha * p[k];
                    r[k] += alpha * q[k];
                }
                sum_squares(r)
            })
            .collect();
        total += parts.iter().sum::<f64>();
    }
    total
}

/// `p ← z + β p`.
pub fn update_direction(p: &mut [Vec<f64>; 2], z: &[Vec<f64>; 2], beta: f64) {
    for c in 0..2 {
        p[c].par_chunks_mut(CHUNK)
            .zip(z[c].par_chunks(CHUNK))
            .for_each(|(p, z)| {
                let n = p.len();
                let z = &z[..n];
                for k in 0..n {
                    p[k] = z[k] + beta * p[k];
                }
            });
    }
}

/// `q = K p` with `K = −A` (the symmetric positive definite form: `4 p − Σ neighbours`) at the
/// free samples of `mask` (zero elsewhere; `p` must be zero at fixed samples). Returns `p · q`.
pub fn apply_operator(mask: &Level, p: &[Vec<f64>; 2], q: &mut [Vec<f64>; 2]) -> f64 {
    let split = mask.split;
    let st = split.stride;
    let par = parallel(&split);
    let band = band_rows(split.nz);
    let mut partial = vec![0.0f64; split.nz];
    let [q0, q1] = q;
    let work = |b: usize, ((q0, q1), part): ((&mut [f64], &mut [f64]), &mut [f64])| {
        let rows = q0.len() / st;
        for dj in 0..rows {
            let j = b * band + dj;
            let mut ss = 0.0;
            for (c, qc) in [&mut *q0, &mut *q1].into_iter().enumerate() {
                let out = &mut qc[dj * st..(dj + 1) * st];
                out.fill(0.0);
                if j == 0 || j + 1 == split.nz {
                    continue;
                }
                let (k0, k1, s) = interior(&split, c, j);
                let x = &p[c][j * st..(j + 1) * st];
                let y = &p[1 - c];
                let yc = &y[j * st..(j + 1) * st];
                let o = &mut out[k0..k1];
                let n = o.len();
                let (xs, l, r) = (&x[k0..k1], &yc[k0 + s - 1..k1 + s - 1], &yc[k0 + s..k1 + s]);
                let (u, d) = (
                    &y[(j - 1) * st + k0..(j - 1) * st + k1],
                    &y[(j + 1) * st + k0..(j + 1) * st + k1],
                );
                let f = &mask.free[c][j * st + k0..j * st + k1];
                let (xs, l, r, u, d, f) = (&xs[..n], &l[..n], &r[..n], &u[..n], &d[..n], &f[..n]);
                for k in 0..n {
                    let v = 4.0 * xs[k] - (l[k] + r[k] + u[k] + d[k]);
                    o[k] = if f[k] != 0 { v } else { 0.0 };
                }
                ss += dot_slice(xs, o);
            }
            part[dj] = ss;
        }
    };
    if par {
        q0.par_chunks_mut(band * st)
            .zip(q1.par_chunks_mut(band * st))
            .zip(partial.par_chunks_mut(band))
            .enumerate()
            .for_each(|(b, x)| work(b, x));
    } else {
        q0.chunks_mut(band * st)
            .zip(q1.chunks_mut(band * st))
            .zip(partial.chunks_mut(band))
            .enumerate()
            .for_each(|(b, x)| work(b, x));
    }
    partial.iter().sum()
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn residual_row(
    out: &mut [f64],
    x: &[f64],
    l: &[f64],
    r: &[f64],
    u: &[f64],
    d: &[f64],
    b: &[f64],
    f: &[u8],
) {
    let n = out.len();
    let (x, l, r, u, d, b, f) = (
        &x[..n],
        &l[..n],
        &r[..n],
        &u[..n],
        &d[..n],
        &b[..n],
        &f[..n],
    );
    for k in 0..n {
        let v = b[k] - (l[k] + r[k] + u[k] + d[k] - 4.0 * x[k]);
        out[k] = if f[k] != 0 { v } else { 0.0 };
    }
}

/// Sum of squares with eight interleaved accumulators (vectorisable and deterministic).
#[inline]
fn sum_squares(v: &[f64]) -> f64 {
    let mut acc = [0.0f64; 8];
    let chunks = v.chunks_exact(8);
    let tail = chunks.remainder();
    for c in chunks {
        for (a, x) in acc.iter_mut().zip(c) {
            *a += x * x;
        }
    }
    for (a, x) in acc.iter_mut().zip(tail) {
        *a += x * x;
    }
    ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]))
}

/// Residual of row `j` (both colours) into `out[0]`, `out[1]` (each `stride` long; border slots
/// zero). Returns its sum of squares.
fn residual_of_row(level: &Level, j: usize, out: &mut [Vec<f64>; 2]) -> f64 {
    let split = &level.split;
    let st = split.stride;
    out[0].fill(0.0);
    out[1].fill(0.0);
    if j == 0 || j + 1 == split.nz {
        return 0.0;
    }
    let mut ss = 0.0;
    for (c, o) in out.iter_mut().enumerate() {
        let (k0, k1, s) = interior(split, c, j);
        let x = &level.h[c][j * st..(j + 1) * st];
        let y = &level.h[1 - c];
        let b = &level.rhs[c][j * st + k0..j * st + k1];
        let f = &level.free[c][j * st + k0..j * st + k1];
        match &level.nine {
            None => {
                let yc = &y[j * st..(j + 1) * st];
                residual_row(
                    &mut o[k0..k1],
                    &x[k0..k1],
                    &yc[k0 + s - 1..k1 + s - 1],
                    &yc[k0 + s..k1 + s],
                    &y[(j - 1) * st + k0..(j - 1) * st + k1],
                    &y[(j + 1) * st + k0..(j + 1) * st + k1],
                    b,
                    f,
                );
            }
            Some(op) => {
                let hc = &level.h[c];
                let (up, down) = (&hc[(j - 1) * st..j * st], &hc[(j + 1) * st..(j + 2) * st]);
                let (_, _, nb) = neighbours(split, c, j, y, up, down);
                let (xs, or) = (&x[k0..k1], &mut o[k0..k1]);
                let sd = &op.default;
                for k in 0..or.len() {
                    let v = b[k] - (off_centre(sd, &nb, k) + sd[4] * xs[k]);
                    or[k] = if f[k] != 0 { v } else { 0.0 };
                }
                for sp in op.row(j) {
                    if sp.colour == c {
                        let k = sp.slot - j * st - k0;
                        let st9 = &sp.stencil;
                        or[k] = b[k] - (off_centre(st9, &nb, k) + st9[4] * xs[k]);
                    }
                }
            }
        }
        ss += sum_squares(&o[k0..k1]);
    }
    ss
}

/// The squared Euclidean norm of the residual `b − A h` (the value [`residual`] returns, summed
/// in the same order) without storing the residual.
pub fn residual_norm2(level: &Level) -> f64 {
    let split = level.split;
    let st = split.stride;
    let band = band_rows(split.nz);
    let mut partial = vec![0.0f64; split.nz];
    let work = |b: usize, part: &mut [f64]| {
        let mut rows = [vec![0.0; st], vec![0.0; st]];
        for (dj, p) in part.iter_mut().enumerate() {
            *p = residual_of_row(level, b * band + dj, &mut rows);
        }
    };
    if parallel(&split) {
        partial
            .par_chunks_mut(band)
            .enumerate()
            .for_each(|(b, p)| work(b, p));
    } else {
        partial
            .chunks_mut(band)
            .enumerate()
            .for_each(|(b, p)| work(b, p));
    }
    partial.iter().sum()
}

/// The residual `b − A h` of every sample (zero at fixed ones) into two colour arrays, and its
/// squared Euclidean norm.
pub fn residual(level: &Level, out: &mut [Vec<f64>; 2]) -> f64 {
    let split = level.split;
    let st = split.stride;
    let par = parallel(&split);
    let band = band_rows(split.nz);
    let mut partial = vec![0.0f64; split.nz];
    let [o0, o1] = out;
    let work = |b: usize, ((o0, o1), part): ((&mut [f64], &mut [f64]), &mut [f64])| {
        let mut rows = [vec![0.0; st], vec![0.0; st]];
        for dj in 0..o0.len() / st {
            part[dj] = residual_of_row(level, b * band + dj, &mut rows);
            o0[dj * st..(dj + 1) * st].copy_from_slice(&rows[0]);
            o1[dj * st..(dj + 1) * st].copy_from_slice(&rows[1]);
        }
    };
    if par {
        o0.par_chunks_mut(band * st)
            .zip(o1.par_chunks_mut(band * st))
            .zip(partial.par_chunks_mut(band))
            .enumerate()
            .for_each(|(b, x)| work(b, x));
    } else {
        o0.chunks_mut(band * st)
            .zip(o1.chunks_mut(band * st))
            .zip(partial.chunks_mut(band))
            .enumerate()
            .for_each(|(b, x)| work(b, x));
    }
    partial.iter().sum()
}

/// Full weighting of fine rows `up = 2J − 1`, `mid = 2J`, `down = 2J + 1` (each as two colour
/// rows) into the natural coarse row `out` (interior columns `1..ncx − 1`), times 4: `Pᵀ`. The
/// black free masks of the three rows (`fu`, `fm`, `fd`) give the corner weights: a corner
/// sample contributes only if one of the two samples connecting it to the coarse sample (its
/// edge neighbours `(2I, 2J ± 1)`, `(2I ± 1, 2J)`) is free, as in [`prolong`].
fn full_weighting(
    up: &[Vec<f64>; 2],
    mid: &[Vec<f64>; 2],
    down: &[Vec<f64>; 2],
    masks: [&[u8]; 3],
    out: &mut [f64],
) {
    // Row 2J is even: red holds even columns (2I at slot I), black odd columns (2I ± 1 at slots
    // I − 1 and I). Rows 2J ± 1 are odd: red holds odd columns (2I ± 1 at I − 1, I), black even
    // columns (2I at I).
    let n = out.len() - 2;
    let o = &mut out[1..n + 1];
    let (mr, mb0, mb1) = (&mid[0][1..n + 1], &mid[1][..n], &mid[1][1..n + 1]);
    let (ub, db) = (&up[1][1..n + 1], &down[1][1..n + 1]);
    let (ur0, ur1) = (&up[0][..n], &up[0][1..n + 1]);
    let (dr0, dr1) = (&down[0][..n], &down[0][1..n + 1]);
    let [fu, fm, fd] = masks;
    let (fu, fd) = (&fu[1..n + 1], &fd[1..n + 1]);
    let (fl, fr) = (&fm[..n], &fm[1..n + 1]);
    for k in 0..n {
        let edges = (mb0[k] + mb1[k]) + (ub[k] + db[k]);
        let corners = (open(fl[k] | fu[k]) * ur0[k] + open(fr[k] | fu[k]) * ur1[k])
            + (open(fl[k] | fd[k]) * dr0[k] + open(fr[k] | fd[k]) * dr1[k]);
        o[k] = (4.0 * mr[k] + 2.0 * edges + corners) * 0.25;
    }
}

/// Writes the natural coarse row `nat` of row `jc` into the coarse right-hand side colour rows
/// `r0`, `r1` (zero at fixed samples).
fn scatter_rhs(
    coarse_split: &Split,
    jc: usize,
    nat: &[f64],
    r0: &mut [f64],
    r1: &mut [f64],
    free: [&[u8]; 2],
) {
    for (c, r) in [r0, r1].into_iter().enumerate() {
        let s = Split::shift(c, jc);
        let count = coarse_split.count(c, jc);
        for k in 0..count {
            let v = nat[2 * k + s];
            r[k] = if free[c][k] != 0 { v } else { 0.0 };
        }
    }
}

/// Computes the residual of `fine`, restricts it by full weighting into the right-hand side of
/// `coarse` (zero at coarse fixed samples), and returns the squared norm of the fine residual.
pub fn residual_restrict(fine: &Level, coarse: &mut Level) -> f64 {
    restrict_impl(fine, coarse, true)
}

/// Restricts the right-hand side of `fine` by full weighting into that of `coarse`: the coarse
/// full problem of the full-multigrid start.
pub fn restrict_rhs(fine: &Level, coarse: &mut Level) {
    restrict_impl(fine, coarse, false);
}

fn restrict_impl(fine: &Level, coarse: &mut Level, residual: bool) -> f64 {
    let cs = coarse.split;
    let cst = cs.stride;
    let fst = fine.split.stride;
    let par = parallel(&fine.split);
    let nzc = cs.nz;
    let band = band_rows(nzc);
    let free = &coarse.free;
    let [r0, r1] = &mut coarse.rhs;
    let mut partial = vec![0.0f64; nzc];
    let work = |b: usize, (c0, c1, part): (&mut [f64], &mut [f64], &mut [f64])| {
        let mut bufs: [[Vec<f64>; 2]; 3] =
            std::array::from_fn(|_| [vec![0.0; fst], vec![0.0; fst]]);
        let mut nat = vec![0.0f64; cs.nx];
        let fine_row = |j: usize, out: &mut [Vec<f64>; 2]| -> f64 {
            if residual {
                residual_of_row(fine, j, out)
            } else {
                out[0].copy_from_slice(&fine.rhs[0][j * fst..(j + 1) * fst]);
                out[1].copy_from_slice(&fine.rhs[1][j * fst..(j + 1) * fst]);
                0.0
            }
        };
        let j0 = b * band;
        let rows = c0.len() / cst;
        // `bufs[2]` holds fine row 2J + 1 of the previous coarse row, reused as row 2J − 1.
        let mut have_down = None;
        let mut down_ss = 0.0;
        for dj in 0..rows {
            let jc = j0 + dj;
            let (o0, o1) = (
                &mut c0[dj * cst..(dj + 1) * cst],
                &mut c1[dj * cst..(dj + 1) * cst],
            );
            if jc == 0 || jc + 1 == nzc {
                o0.fill(0.0);
                o1.fill(0.0);
                continue;
            }
            // Coarse row J owns the norms of fine rows 2J − 1 and 2J (and 2J + 1 for the last
            // interior coarse row).
            let mut ss = if have_down == Some(jc - 1) {
                bufs.swap(0, 2);
                down_ss
            } else {
                fine_row(2 * jc - 1, &mut bufs[0])
            };
            ss += fine_row(2 * jc, &mut bufs[1]);
            down_ss = fine_row(2 * jc + 1, &mut bufs[2]);
            have_down = Some(jc);
            if jc + 2 == nzc {
                ss += down_ss;
            }
            part[dj] = ss;
            let fb = &fine.free[1];
            let masks = [
                &fb[(2 * jc - 1) * fst..2 * jc * fst],
                &fb[2 * jc * fst..(2 * jc + 1) * fst],
                &fb[(2 * jc + 1) * fst..(2 * jc + 2) * fst],
            ];
            full_weighting(&bufs[0], &bufs[1], &bufs[2], masks, &mut nat);
            let fr = [
                &free[0][jc * cst..(jc + 1) * cst],
                &free[1][jc * cst..(jc + 1) * cst],
            ];
            scatter_rhs(&cs, jc, &nat, o0, o1, fr);
        }
    };
    if par {
        r0.par_chunks_mut(band * cst)
            .zip(r1.par_chunks_mut(band * cst))
            .zip(partial.par_chunks_mut(band))
            .enumerate()
            .for_each(|(b, ((c0, c1), p))| work(b, (c0, c1, p)));
    } else {
        r0.chunks_mut(band * cst)
            .zip(r1.chunks_mut(band * cst))
            .zip(partial.chunks_mut(band))
            .enumerate()
            .for_each(|(b, ((c0, c1), p))| work(b, (c0, c1, p)));
    }
    partial.iter().sum()
}

/// Bilinear prolongation of `coarse.h` into `fine.h` at the free samples of `fine`: added when
/// `ADD` (coarse-grid correction), assigned otherwise (full-multigrid interpolation).
/// `scratch` (at least `coarse` samples long) receives the natural coarse values.
pub fn prolong<const ADD: bool>(coarse: &Level, fine: &mut Level, scratch: &mut Vec<f64>) {
    let cs = coarse.split;
    scratch.resize(cs.nx * cs.nz, 0.0);
    cs.merge_into(&coarse.h, scratch, |v| v);
    let nat: &[f64] = scratch;
    let ncx = cs.nx;
    let fs = fine.split;
    let st = fs.stride;
    let par = parallel(&fs);
    let band = band_rows(fs.nz);
    let [h0, h1] = &mut fine.h;
    let free = &fine.free;
    let work = |b: usize, (x0, x1): (&mut [f64], &mut [f64])| {
        let rows = x0.len() / st;
        for dj in 0..rows {
            let j = b * band + dj;
            if j == 0 || j + 1 == fs.nz {
                continue;
            }
            let jc = j / 2;
            let e0 = &nat[jc * ncx..(jc + 1) * ncx];
            for (c, x) in [&mut *x0, &mut *x1].into_iter().enumerate() {
                let (k0, k1, s) = interior(&fs, c, j);
                let xr = &mut x[dj * st + k0..dj * st + k1];
                let f = &free[c][j * st + k0..j * st + k1];
                let n = xr.len();
                if j.is_multiple_of(2) {
                    if s == 0 {
                        // Even column 2k: coarse sample k.
                        let a = &e0[k0..k0 + n];
                        apply::<ADD>(xr, f, |k| a[k]);
                    } else {
                        // Odd column 2k + 1: mean of coarse k and k + 1.
                        let (a, bb) = (&e0[k0..k0 + n], &e0[k0 + 1..k0 + 1 + n]);
                        apply::<ADD>(xr, f, |k| (a[k] + bb[k]) * 0.5);
                    }
                } else {
                    let e1 = &nat[(jc + 1) * ncx..(jc + 2) * ncx];
                    if s == 0 {
                        let (a, d) = (&e0[k0..k0 + n], &e1[k0..k0 + n]);
                        apply::<ADD>(xr, f, |k| (a[k] + d[k]) * 0.5);
                    } else {
                        // Odd-odd sample: a corner whose two connecting samples are both
                        // fixed lies across a constraint and gives no weight.
                        let (a, bb) = (&e0[k0..k0 + n], &e0[k0 + 1..k0 + 1 + n]);
                        let (d, e) = (&e1[k0..k0 + n], &e1[k0 + 1..k0 + 1 + n]);
                        let fo = &free[1 - c];
                        let (fl, fr) = (&fo[j * st + k0..], &fo[j * st + k0 + 1..]);
                        let (fu, fd) = (&fo[(j - 1) * st + k0..], &fo[(j + 1) * st + k0..]);
                        apply::<ADD>(xr, f, |k| {
                            ((open(fl[k] | fu[k]) * a[k] + open(fr[k] | fu[k]) * bb[k])
                                + (open(fl[k] | fd[k]) * d[k] + open(fr[k] | fd[k]) * e[k]))
                                * 0.25
                        });
                    }
                }
            }
        }
    };
    if par {
        h0.par_chunks_mut(band * st)
            .zip(h1.par_chunks_mut(band * st))
            .enumerate()
            .for_each(|(b, p)| work(b, p));
    } else {
        h0.chunks_mut(band * st)
            .zip(h1.chunks_mut(band * st))
            .enumerate()
            .for_each(|(b, p)| work(b, p));
    }
}

/// The weight factor of a corner: 1 if one of its two connecting samples is free (`flags ≠ 0`),
/// else 0.
#[inline(always)]
fn open(flags: u8) -> f64 {
    if flags != 0 {
        1.0
    } else {
        0.0
    }
}

#[inline(always)]
fn apply<const ADD: bool>(x: &mut [f64], f: &[u8], v: impl Fn(usize) -> f64) {
    let n = x.len();
    let f = &f[..n];
    for k in 0..n {
        let e = v(k);
        let new = if ADD { x[k] + e } else { e };
        x[k] = if f[k] != 0 { new } else { x[k] };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::poisson::grid::GridSpec;

    fn level_with(nx: usize, nz: usize, h: impl Fn(usize, usize) -> f64) -> Level {
        let g = GridSpec::new(nx, nz, 1.0).expect("grid");
        let mut l = Level::with_mask(g, &vec![true; nx * nz]);
        for j in 0..nz {
            for i in 0..nx {
                let (c, k) = l.split.locate(i, j);
                l.h[c][k] = h(i, j);
            }
        }
        l
    }

    #[test]
    fn residual_of_a_quadratic_is_its_constant_laplacian() {
        // h = x² + 2 z² has A h = 2 + 4 = 6 everywhere; with b = 0 the residual is −6.
        let l = level_with(9, 17, |i, j| (i * i + 2 * j * j) as f64);
        let mut r = [vec![0.0; l.split.len()], vec![0.0; l.split.len()]];
        let ss = residual(&l, &mut r);
        for j in 0..17 {
            for i in 0..9 {
                let (c, k) = l.split.locate(i, j);
                let want = if l.grid.is_border(i, j) { 0.0 } else { -6.0 };
                assert_eq!(r[c][k], want, "({i}, {j})");
            }
        }
        assert_eq!(ss, 36.0 * 7.0 * 15.0);
    }

    #[test]
    fn restriction_is_four_times_full_weighting() {
        // A linear residual field restricts to four times itself (full weighting is exact on
        // linear functions); check through restrict_rhs.
        let mut fine = level_with(17, 9, |_, _| 0.0);
        for j in 1..8 {
            for i in 1..16 {
                let (c, k) = fine.split.locate(i, j);
                fine.rhs[c][k] = (3 * i + j) as f64;
            }
        }
        let mut coarse = fine.coarsen().expect("coarse");
        restrict_rhs(&fine, &mut coarse);
        for jc in 1..4 {
            for ic in 1..8 {
                let (c, k) = coarse.split.locate(ic, jc);
                assert_eq!(coarse.rhs[c][k], 4.0 * (6 * ic + 2 * jc) as f64);
            }
        }
    }

    #[test]
    fn prolongation_is_exact_on_bilinear_functions() {
        let coarse = level_with(9, 5, |i, j| (2 * i + 3 * j + i * j) as f64);
        let mut fine = level_with(17, 9, |_, _| 0.0);
        let mut scratch = Vec::new();
        prolong::<false>(&coarse, &mut fine, &mut scratch);
        for j in 1..8 {
            for i in 1..16 {
                let (x, z) = (i as f64 / 2.0, j as f64 / 2.0);
                let want = 2.0 * x + 3.0 * z + x * z;
                if (i == 1 || i == 15) && (j == 1 || j == 7) {
                    // Next to a grid corner both samples between it and the corner are border
                    // (fixed) samples: the corner gives no weight (in the solver its correction
                    // is zero anyway).
                    let corner =
                        coarse.value(if i == 1 { 0 } else { 8 }, if j == 1 { 0 } else { 4 });
                    assert_eq!(fine.value(i, j), want - 0.25 * corner, "({i}, {j})");
                    continue;
                }
                assert_eq!(fine.value(i, j), want, "({i}, {j})");
            }
        }
        prolong::<true>(&coarse, &mut fine, &mut scratch);
        assert_eq!(fine.value(3, 5), 2.0 * (2.0 * 1.5 + 3.0 * 2.5 + 1.5 * 2.5));
        assert_eq!(fine.value(0, 0), 0.0, "border samples are fixed");
    }

    /// A 9-point level with special stencils (level 1 below a 33² grid with a few fixed
    /// samples), with arbitrary heights and right-hand side.
    fn coarse_level_with_specials() -> Level {
        let g = GridSpec::new(33, 33, 1.0).expect("grid");
        let mut free = vec![true; 33 * 33];
        for (i, j) in [(9, 13), (16, 20), (17, 20), (18, 21), (3, 8), (24, 8)] {
            free[j * 33 + i] = false;
        }
        let mut l = Level::with_mask(g, &free).coarsen().expect("level 1");
        assert!(!l.nine.as_ref().expect("nine").special.is_empty());
        for j in 0..l.grid.nz {
            for i in 0..l.grid.nx {
                let (c, k) = l.split.locate(i, j);
                l.h[c][k] = ((i * 7 + j * 3) % 5) as f64;
                l.rhs[c][k] = ((i * 3 + j * 5) % 7) as f64 - 3.0;
            }
        }
        l
    }

    #[test]
    fn span_updates_equal_the_nine_point_half_sweep_and_leave_other_samples() {
        for (c, p) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            let mut whole = coarse_level_with_specials();
            let mut spans = coarse_level_with_specials();
            smooth_nine(&mut whole, c, p);
            let (nx, nz) = (spans.grid.nx, spans.grid.nz);
            // Two spans with a gap of columns 5..=7, the right one first.
            smooth_nine_spans::<true>(&mut spans, c, p, 1..=nz - 2, |_| {
                [Some((8, nx - 2)), Some((1, 4))]
            });
            for j in 0..nz {
                for i in 0..nx {
                    let (cc, k) = spans.split.locate(i, j);
                    let before = coarse_level_with_specials().h[cc][k];
                    if (5..=7).contains(&i) {
                        assert_eq!(spans.h[cc][k], before, "({i}, {j}) is in the gap");
                    } else {
                        assert_eq!(spans.h[cc][k], whole.h[cc][k], "({i}, {j}), {c} {p}");
                    }
                }
            }
        }
        // With a zero right-hand side the update is that of `b = 0`.
        let mut zero_b = coarse_level_with_specials();
        let mut no_rhs = coarse_level_with_specials();
        for b in &mut zero_b.rhs {
            b.fill(0.0);
        }
        smooth_nine(&mut zero_b, 1, 1);
        let (nx, nz) = (no_rhs.grid.nx, no_rhs.grid.nz);
        smooth_nine_spans::<false>(&mut no_rhs, 1, 1, 1..=nz - 2, |_| [Some((1, nx - 2)), None]);
        assert_eq!(zero_b.h, no_rhs.h);
    }

    #[test]
    fn the_residual_norm_equals_that_of_the_stored_residual() {
        let l = coarse_level_with_specials();
        let mut r = [vec![0.0; l.split.len()], vec![0.0; l.split.len()]];
        let ss = residual(&l, &mut r);
        assert!(ss > 1.0);
        assert_eq!(residual_norm2(&l).to_bits(), ss.to_bits());
    }

    #[test]
    fn a_half_sweep_solves_each_sample_of_its_colour() {
        let mut l = level_with(9, 9, |i, j| ((i * 7 + j * 3) % 5) as f64);
        smooth_colour(&mut l, 0);
        let mut r = [vec![0.0; l.split.len()], vec![0.0; l.split.len()]];
        residual(&l, &mut r);
        for j in 1..8 {
            for i in 1..8 {
                let (c, k) = l.split.locate(i, j);
                if c == 0 {
                    assert!(
                        r[c][k].abs() < 1e-12,
                        "red residual at ({i}, {j}): {}",
                        r[c][k]
                    );
                }
            }
        }
    }
}
