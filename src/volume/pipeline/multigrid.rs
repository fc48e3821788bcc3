//! The O(n) harmonic fill of the diffusions (Becher §4.3–4.4, and §8's call for multigrid instead
//! of thousands of Jacobi sweeps): Laplace's equation `Σ_nb (u − u_nb) = 0` at the free samples,
//! Dirichlet values at the fixed ones, homogeneous Neumann borders.
//!
//! Why one file of about 850 lines: the hierarchy, its sweeps and transfers, the cascade and the
//! V-cycles below are one solver on the private `Level` type (edge weights, sinks, dead samples),
//! and the fixed order of its sums is what keeps the result independent of the thread count.
//!
//! **Hierarchy.** Level `l + 1` halves level `l` per axis (cell-centred: coarse sample `X` covers
//! fine samples `2X` and `2X + 1`). The coarse operators are built from Galerkin products
//! `Pᵀ A P` for the piecewise-constant `P` on the fine level's unknowns (free samples): a coarse
//! edge weighs the fine free–free edges crossing its face, and a coarse sample's *sink* (its
//! coupling to fixed samples) is the sum of its children's sinks. The edge weights are then
//! halved ([`EDGE_SCALE`]): the piecewise-constant Galerkin operator is twice as stiff as the
//! fine one for a smooth function, and with halved edges it is, away from constraints, exactly
//! the 7-point operator rediscretised at twice the spacing, while the coupling to constraints
//! keeps its Galerkin weight. (Doubling the whole correction instead over-corrects next to
//! constraints and diverged on the arch scene.) Constants are reproduced exactly on every level.
//! A coarse sample is *dead* (no unknown, zero correction) only when all its children are; a thin
//! constraint (a curve one voxel wide) is not inflated on the coarse levels as it was when a
//! coarse sample was fixed as soon as one child was (that hierarchy reduced the residual by only
//! 0.44–0.58 per V-cycle). All weights are dyadic fractions, exact in `f32`. The hierarchy is
//! built once per call, for all channels together.
//!
//! **Cascade** (Bornemann & Deuflhard 1996): the right-hand side of the fine problem for the free
//! samples, `b = Σ_{fixed nb} u_nb`, is restricted (`Pᵀ`, the sum over the children) down the
//! pyramid; the coarsest level (≤ [`COARSEST`] samples) is solved by `coarsest_sweeps` red-black
//! Gauss–Seidel sweeps; each finer level starts from the trilinear interpolation of the coarser
//! solution (dead coarse samples holding the mean of their children's constraint values) and
//! runs `fine_sweeps` sweeps: red-black Gauss–Seidel on the coarse levels, Jacobi on the finest.
//!
//! **V-cycles** then remove the remaining error: on the finest level two damped Jacobi sweeps
//! (`ω = 6/7`, the optimal smoothing weight of the 7-point Laplacian) before and after the
//! coarse-grid correction, two red-black Gauss–Seidel sweeps on every coarse level; the residual
//! restricted by `Pᵀ`, the correction prolongated trilinearly onto the unknowns. Measured
//! residual reduction on the arch scene: 0.14–0.25 per cycle at 64 × 32 × 64, 0.16–0.34 at
//! 128 × 64 × 128 (`tests/volume_pipeline.rs`, `multigrid_cycles_reduce_the_residual_steadily`).
//!
//! All channels go through every pass together (one pass over the fixed mask per sweep), every
//! pass is parallel over z-slabs and writes disjoint samples from read-only inputs (the
//! Gauss–Seidel colours included), and every sum has a fixed order, so the result does not
//! depend on the thread count.

use super::diffuse::{keep_fixed, laplace_sweep, rows, DiffuseParams, COARSEST};
use super::grid::par_slabs_multi;
use crate::terrain::cancel::Cancel;

/// Smoothing step of the finest level's V-cycle sweeps: `ω/6` with `ω = 6/7`, the optimal
/// damping of Jacobi for the 7-point Laplacian.
const SMOOTH_WEIGHT: f32 = 1.0 / 7.0;

/// Smoothing sweeps before and after the coarse-grid correction on every level.
const SMOOTH_SWEEPS: u32 = 2;

/// Factor of the coarse edge weights: the Galerkin sum of the crossing fine edges, halved. The
/// piecewise-constant Galerkin operator has twice the stiffness of the fine one for a smooth
/// function (its correction would be half the needed one); halving the edges (not the sinks)
/// makes it, in an unconstrained region, exactly the 7-point operator rediscretised at twice the
/// spacing, while the coupling to constraints keeps its Galerkin weight. (Doubling the whole
/// correction instead over-corrects next to constraints and diverges on the arch scene.)
const EDGE_SCALE: f32 = 0.5;

/// Over-correction of the coarse-grid correction: the piecewise-constant Galerkin operator
/// halves the curvature of a smooth error, so its correction is doubled (in an unconstrained
/// region this is exactly the operator rediscretised at twice the spacing).
/// One level below the finest: its Galerkin operator, mask and per-channel buffers.
struct Level {
    dims: [usize; 3],
    /// `1` where every child is fixed (dead: no unknown, zero correction), else `0`.
    fixed: Vec<u8>,
    /// Weights of the edges to the `+x`, `+y`, `+z` neighbours (0 at the border).
    w: [Vec<f32>; 3],
    /// Diagonal of the operator (the sum of the sample's edge weights and its sink), and its
    /// inverse (0 at dead samples).
    diag: Vec<f32>,
    inv: Vec<f32>,
    /// Solution (cascade) or correction (V-cycle), per channel.
    u: Vec<Vec<f32>>,
    /// Right-hand side, per channel.
    b: Vec<Vec<f32>>,
    /// Ping-pong scratch, per channel.
    tmp: Vec<Vec<f32>>,
}

fn coarser(dims: [usize; 3]) -> Option<[usize; 3]> {
    let n = dims.iter().product::<usize>();
    let c = dims.map(|d| d.div_ceil(2));
    (n > COARSEST && c.iter().all(|&d| d >= 2)).then_some(c)
}

/// The fine level's operator as seen by [`coarsen`]: the finest level (unit weights between free
/// samples, a sink of one per fixed neighbour) or a coarse level.
#[derive(Clone, Copy)]
enum Fine<'a> {
    Finest(&'a [u8]),
    Coarse(&'a Level),
}

/// The Galerkin product `Pᵀ A P` of the fine operator for the piecewise-constant `P` on the
/// fine level's live samples: coarse edge weights are the sums of the fine edges crossing the
/// coarse face, the sink (coupling to fixed samples) is the sum of the children's sinks. Every
/// weight is a small integer, exact in `f32`. Parallel over coarse z-slices; each writes only
/// its own slice.
fn coarsen(fine_dims: [usize; 3], fine: Fine<'_>, cd: [usize; 3], m: usize) -> Level {
    let [nx, ny, nz] = fine_dims;
    let [cx, cy, cz] = cd;
    let cn = cx * cy * cz;
    // Per coarse sample: live children, edge weights +x/+y/+z, sink.
    let mut live = vec![0.0f32; cn];
    let mut wx = vec![0.0f32; cn];
    let mut wy = vec![0.0f32; cn];
    let mut wz = vec![0.0f32; cn];
    let mut sink = vec![0.0f32; cn];
    let slice_c = cx * cy;
    par_slabs_multi(
        vec![&mut live, &mut wx, &mut wy, &mut wz, &mut sink],
        slice_c,
        |cz0, out| {
            let [live, wx, wy, wz, sink] = out else {
                unreachable!("five outputs")
            };
            let zc_n = live.len() / slice_c;
            let mut scratch = [
                vec![0.0f32; nx],
                vec![0.0f32; nx],
                vec![0.0f32; nx],
                vec![0.0f32; nx],
            ];
            for z in 2 * cz0..(2 * (cz0 + zc_n)).min(nz) {
                for y in 0..ny {
                    let cl = cx * (y / 2 + cy * (z / 2 - cz0));
                    let Fine::Finest(f) = fine else {
                        coarse_children_row(fine, [y, z], cl, [live, wx, wy, wz, sink]);
                        continue;
                    };
                    // The finest level, row by row: a free sample's sink is its number of fixed
                    // neighbours (a missing neighbour is the sample itself, which is free).
                    let r = rows(fine_dims, y, z);
                    finest_children_row(
                        [
                            &f[r.o..r.o + nx],
                            &f[r.u..r.u + nx],
                            &f[r.d..r.d + nx],
                            &f[r.n..r.n + nx],
                            &f[r.s..r.s + nx],
                        ],
                        [y % 2 == 1 && r.u != r.o, z % 2 == 1 && r.n != r.o],
                        &mut scratch,
                        [
                            &mut live[cl..cl + cx],
                            &mut wx[cl..cl + cx],
                            &mut wy[cl..cl + cx],
                            &mut wz[cl..cl + cx],
                            &mut sink[cl..cl + cx],
                        ],
                    );
                }
            }
        },
    );
    let mut fixed = vec![0u8; cn];
    let mut diag = vec![0.0f32; cn];
    let mut inv = vec![0.0f32; cn];
    for z in 0..cz {
        for y in 0..cy {
            for x in 0..cx {
                let i = x + cx * (y + cy * z);
                if live[i] == 0.0 {
                    fixed[i] = 1;
                    continue;
                }
                let mut d = sink[i] + wx[i] + wy[i] + wz[i];
                if x > 0 {
                    d += wx[i - 1];
                }
                if y > 0 {
                    d += wy[i - cx];
                }
                if z > 0 {
                    d += wz[i - slice_c];
                }
                diag[i] = d;
                inv[i] = if d > 0.0 { 1.0 / d } else { 0.0 };
            }
        }
    }
    let bufs = || (0..m).map(|_| vec![0.0f32; cn]).collect::<Vec<_>>();
    Level {
        dims: cd,
        fixed,
        w: [wx, wy, wz],
        diag,
        inv,
        u: bufs(),
        b: bufs(),
        tmp: bufs(),
    }
}

/// [`coarsen`] of one row of the finest level: `f = [row, up, down, north, south]` fixed flags
/// (the row itself where a neighbour is missing), `cross = [the row's up edges cross to the next
/// coarse row, its north edges cross to the next coarse slice]`, into the coarse row's
/// `[live, wx, wy, wz, sink]`. Branch-free passes over the row.
fn finest_children_row(
    f: [&[u8]; 5],
    cross: [bool; 2],
    scratch: &mut [Vec<f32>; 4],
    out: [&mut [f32]; 5],
) {
    let nx = f[0].len();
    let [c, up, dn, no, so] = f.map(|r| &r[..nx]);
    let [free, sk, fu, fnn] = scratch;
    let (free, sk, fu, fnn) = (
        &mut free[..nx],
        &mut sk[..nx],
        &mut fu[..nx],
        &mut fnn[..nx],
    );
    let flag = |v: u8| f32::from(u8::from(v != 0));
    for x in 0..nx {
        free[x] = 1.0 - flag(c[x]);
        fu[x] = 1.0 - flag(up[x]);
        fnn[x] = 1.0 - flag(no[x]);
        sk[x] = flag(up[x]) + flag(dn[x]) + flag(no[x]) + flag(so[x]);
    }
    for x in 1..nx {
        sk[x] += flag(c[x - 1]);
        sk[x - 1] += flag(c[x]);
    }
    let [live, wx, wy, wz, sink] = out;
    let pairs = nx / 2;
    for k in 0..pairs {
        let (a, b) = (2 * k, 2 * k + 1);
        live[k] = live[k].max(free[a] + free[b]);
        sink[k] += free[a] * sk[a] + free[b] * sk[b];
        if cross[0] {
            wy[k] += EDGE_SCALE * (free[a] * fu[a] + free[b] * fu[b]);
        }
        if cross[1] {
            wz[k] += EDGE_SCALE * (free[a] * fnn[a] + free[b] * fnn[b]);
        }
        if b + 1 < nx {
            wx[k] += EDGE_SCALE * (free[b] * free[b + 1]);
        }
    }
    if nx % 2 == 1 {
        let (k, a) = (pairs, nx - 1);
        live[k] = live[k].max(free[a]);
        sink[k] += free[a] * sk[a];
        if cross[0] {
            wy[k] += EDGE_SCALE * free[a] * fu[a];
        }
        if cross[1] {
            wz[k] += EDGE_SCALE * free[a] * fnn[a];
        }
    }
}

/// [`coarsen`] of fine row `(y, z)` of a coarse level (`cl`: offset of the coarse row in the
/// slab's outputs `[live, wx, wy, wz, sink]`).
fn coarse_children_row(fine: Fine<'_>, [y, z]: [usize; 2], cl: usize, out: [&mut [f32]; 5]) {
    let Fine::Coarse(l) = fine else {
        return;
    };
    let [live, wx, wy, wz, sink] = out;
    let [nx, ny, nz] = l.dims;
    let o = nx * (y + ny * z);
    for x in 0..nx {
        let i = o + x;
        if l.fixed[i] != 0 {
            continue;
        }
        let k = cl + x / 2;
        live[k] = 1.0;
        sink[k] += l.diag[i] - fine_edges(l, i, [x, y, z]);
        if x % 2 == 1 && x + 1 < nx {
            wx[k] += EDGE_SCALE * l.w[0][i];
        }
        if y % 2 == 1 && y + 1 < ny {
            wy[k] += EDGE_SCALE * l.w[1][i];
        }
        if z % 2 == 1 && z + 1 < nz {
            wz[k] += EDGE_SCALE * l.w[2][i];
        }
    }
}

/// The sum of the weights of the edges of sample `i` (at `p`) of level `l` to live neighbours.
fn fine_edges(l: &Level, i: usize, p: [usize; 3]) -> f32 {
    let [nx, ny, _] = l.dims;
    let [x, y, z] = p;
    let mut s = l.w[0][i] + l.w[1][i] + l.w[2][i];
    if x > 0 {
        s += l.w[0][i - 1];
    }
    if y > 0 {
        s += l.w[1][i - nx];
    }
    if z > 0 {
        s += l.w[2][i - nx * ny];
    }
    s
}

/// The coarse levels below `dims` with their Galerkin operators.
fn hierarchy(dims: [usize; 3], fixed: &[u8], m: usize) -> Vec<Level> {
    let mut levels: Vec<Level> = Vec::new();
    let mut fd = dims;
    while let Some(cd) = coarser(fd) {
        let fine = levels.last().map_or(Fine::Finest(fixed), Fine::Coarse);
        let l = coarsen(fd, fine, cd, m);
        levels.push(l);
        fd = cd;
    }
    levels
}

/// A coarse level's operator, borrowed apart from its buffers.
#[derive(Clone, Copy)]
struct Op<'a> {
    dims: [usize; 3],
    w: [&'a [f32]; 3],
    diag: &'a [f32],
    inv: &'a [f32],
    fixed: &'a [u8],
}

impl Level {
    fn op(&self) -> Op<'_> {
        Op {
            dims: self.dims,
            w: [&self.w[0], &self.w[1], &self.w[2]],
            diag: &self.diag,
            inv: &self.inv,
            fixed: &self.fixed,
        }
    }
}

/// `acc = b + Σ_nb w_nb·u_nb` over row `(y, z)` of a coarse level (a missing neighbour has
/// weight 0 and contributes nothing). Fixed summation order.
fn coarse_acc_row(op: Op<'_>, u: &[f32], b: &[f32], y: usize, z: usize, acc: &mut [f32]) {
    let [nx, ny, nz] = op.dims;
    let slice = nx * ny;
    let o = nx * (y + ny * z);
    let acc = &mut acc[..nx];
    acc.copy_from_slice(&b[o..o + nx]);
    let c = &u[o..o + nx];
    let wx = &op.w[0][o..o + nx];
    {
        let (a, w, e) = (&mut acc[..nx - 1], &wx[..nx - 1], &c[1..]);
        for x in 0..nx - 1 {
            a[x] += w[x] * e[x];
        }
        let (a, w, e) = (&mut acc[1..], &wx[..nx - 1], &c[..nx - 1]);
        for x in 0..nx - 1 {
            a[x] += w[x] * e[x];
        }
    }
    if y + 1 < ny {
        axpy(acc, &op.w[1][o..o + nx], &u[o + nx..o + 2 * nx]);
    }
    if y > 0 {
        axpy(acc, &op.w[1][o - nx..o], &u[o - nx..o]);
    }
    if z + 1 < nz {
        axpy(acc, &op.w[2][o..o + nx], &u[o + slice..o + slice + nx]);
    }
    if z > 0 {
        axpy(
            acc,
            &op.w[2][o - slice..o - slice + nx],
            &u[o - slice..o - slice + nx],
        );
    }
}

/// `acc += w·v` element-wise (separate parameters, so that the loop vectorises).
#[inline(never)]
fn axpy(acc: &mut [f32], w: &[f32], v: &[f32]) {
    let n = acc.len();
    let (w, v) = (&w[..n], &v[..n]);
    for x in 0..n {
        acc[x] += w[x] * v[x];
    }
}

/// `sweeps` red-black Gauss–Seidel sweeps on a coarse level for `A u = b`: the samples with
/// `x + y + z` even, then the odd ones, each from the other colour's current values. Each half
/// sweep writes `tmp` from `u` (parallel over z-slabs, disjoint writes) and swaps, so the result
/// does not depend on the thread count.
fn gauss_seidel(l: &mut Level, sweeps: u32) {
    let Level {
        u, b, tmp, dims, ..
    } = l;
    let dims = *dims;
    let [nx, ny, _] = dims;
    let op = Op {
        dims,
        w: [&l.w[0], &l.w[1], &l.w[2]],
        diag: &l.diag,
        inv: &l.inv,
        fixed: &l.fixed,
    };
    for _ in 0..sweeps {
        for colour in 0..2usize {
            {
                let src: &[Vec<f32>] = u;
                let b: &[Vec<f32>] = b;
                let outs: Vec<&mut [f32]> = tmp.iter_mut().map(|c| c.as_mut_slice()).collect();
                par_slabs_multi(outs, nx * ny, |z0, out| {
                    let mut acc = vec![0.0f32; nx];
                    // `parity[p][x] = (x + p) & 1`: the samples of the other colour.
                    let parity: [Vec<u8>; 2] =
                        [0, 1].map(|p| (0..nx).map(|x| ((x + p) & 1) as u8).collect());
                    for zl in 0..out[0].len() / (nx * ny) {
                        let z = z0 + zl;
                        for y in 0..ny {
                            let o = nx * (y + ny * z);
                            let ol = nx * (y + ny * zl);
                            let (inv, fx) = (&op.inv[o..o + nx], &op.fixed[o..o + nx]);
                            for (ch, dst) in out.iter_mut().enumerate() {
                                coarse_acc_row(op, &src[ch], &b[ch], y, z, &mut acc);
                                let cur = &src[ch][o..o + nx];
                                let dst = &mut dst[ol..ol + nx];
                                let other = &parity[(y + z + colour) & 1][..nx];
                                let acc = &acc[..nx];
                                for x in 0..nx {
                                    dst[x] = keep_fixed(fx[x] | other[x], cur[x], acc[x] * inv[x]);
                                }
                            }
                        }
                    }
                });
            }
            for (a, t) in u.iter_mut().zip(tmp.iter_mut()) {
                std::mem::swap(a, t);
            }
        }
    }
}

/// `cb[ch][I] = Σ_i row_ch(i)` over the fine children `i` of every coarse sample `I`,
/// where `row(ch, y, z, out)` writes the fine row `(y, z)` of channel `ch` (0 at samples without
/// an unknown). Parallel over coarse z-slabs; fixed summation order.
fn restrict_sum<F>(fine: [usize; 3], coarse: [usize; 3], cb: &mut [Vec<f32>], row: F)
where
    F: Fn(usize, usize, usize, &mut [f32]) + Sync,
{
    let [nx, ny, nz] = fine;
    let [cx, cy, _] = coarse;
    let outs: Vec<&mut [f32]> = cb.iter_mut().map(|c| c.as_mut_slice()).collect();
    par_slabs_multi(outs, cx * cy, |cz0, out| {
        let mut r = vec![0.0f32; nx];
        for czl in 0..out[0].len() / (cx * cy) {
            let cz = cz0 + czl;
            for cyy in 0..cy {
                let co = cx * (cyy + cy * czl);
                for (ch, dst) in out.iter_mut().enumerate() {
                    let acc = &mut dst[co..co + cx];
                    acc.fill(0.0);
                    for z in 2 * cz..(2 * cz + 2).min(nz) {
                        for y in 2 * cyy..(2 * cyy + 2).min(ny) {
                            row(ch, y, z, &mut r);
                            let (pairs, odd) = r.split_at(nx & !1);
                            for (a, p) in acc.iter_mut().zip(pairs.chunks_exact(2)) {
                                *a += p[0] + p[1];
                            }
                            if let Some(last) = odd.first() {
                                acc[nx / 2] += last;
                            }
                        }
                    }
                }
            }
        }
    });
}

/// The finest level's residual `Σ_nb (u_nb − u)` (0 at fixed samples) restricted by
/// `Pᵀ` (the sum over the children) into `cb`.
fn restrict_finest_residual(
    dims: [usize; 3],
    u: &[Vec<f32>],
    fixed: &[u8],
    coarse: [usize; 3],
    cb: &mut [Vec<f32>],
) {
    let nx = dims[0];
    restrict_sum(dims, coarse, cb, |ch, y, z, out| {
        let rw = rows(dims, y, z);
        let c = &u[ch];
        let row = |o: usize| &c[o..o + nx];
        residual_row(
            [row(rw.o), row(rw.u), row(rw.d), row(rw.n), row(rw.s)],
            &fixed[rw.o..rw.o + nx],
            out,
        );
    });
}

/// A coarse level's residual `b − A u` (0 at dead samples) restricted by `Pᵀ` into
/// `cb`.
fn restrict_coarse_residual(l: &Level, coarse: [usize; 3], cb: &mut [Vec<f32>]) {
    let op = l.op();
    let nx = l.dims[0];
    restrict_sum(l.dims, coarse, cb, |ch, y, z, out| {
        coarse_acc_row(op, &l.u[ch], &l.b[ch], y, z, out);
        let o = nx * (y + l.dims[1] * z);
        let (u, d, fx) = (
            &l.u[ch][o..o + nx],
            &op.diag[o..o + nx],
            &op.fixed[o..o + nx],
        );
        for x in 0..nx {
            out[x] = keep_fixed(fx[x], 0.0, out[x] - d[x] * u[x]);
        }
    });
}
/// `k` sweeps on `u` (ping-pong through `tmp`) for `Σ_nb (u − u_nb) = b` with step `weight`.
fn relax(
    dims: [usize; 3],
    u: &mut [Vec<f32>],
    tmp: &mut [Vec<f32>],
    b: Option<&[Vec<f32>]>,
    fixed: &[u8],
    weight: f32,
    k: u32,
) {
    for _ in 0..k {
        {
            let src: Vec<&[f32]> = u.iter().map(|c| c.as_slice()).collect();
            let rhs: Option<Vec<&[f32]>> = b.map(|b| b.iter().map(|c| c.as_slice()).collect());
            let outs: Vec<&mut [f32]> = tmp.iter_mut().map(|c| c.as_mut_slice()).collect();
            laplace_sweep(dims, &src, rhs.as_deref(), fixed, weight, outs);
        }
        for (a, t) in u.iter_mut().zip(tmp.iter_mut()) {
            std::mem::swap(a, t);
        }
    }
}

/// Per-axis interpolation table of the prolongation: fine sample `i` lies at coarse position
/// `i/2 − 1/4`, clamped; `(i0, i1, weight of i1)`.
fn axis_table(nf: usize, nc: usize) -> Vec<(usize, usize, f32)> {
    (0..nf)
        .map(|i| {
            let f = (i as f32 * 0.5 - 0.25).clamp(0.0, (nc - 1) as f32);
            let i0 = (f.floor() as usize).min(nc - 1);
            let i1 = (i0 + 1).min(nc - 1);
            (i0, i1, f - i0 as f32)
        })
        .collect()
}

/// Trilinear interpolation of every coarse channel onto the free fine samples: replacing their
/// values (`ADD = false`, the cascade) or adding to them (`ADD = true`, the V-cycle's correction).
fn prolong<const ADD: bool>(
    fine: [usize; 3],
    coarse: [usize; 3],
    cc: &[Vec<f32>],
    fixed: &[u8],
    out: &mut [Vec<f32>],
) {
    let [nx, ny, nz] = fine;
    let [cx, cy, cz] = coarse;
    let (ay, az) = (axis_table(ny, cy), axis_table(nz, cz));
    let outs: Vec<&mut [f32]> = out.iter_mut().map(|c| c.as_mut_slice()).collect();
    par_slabs_multi(outs, nx * ny, |zs, out| {
        let mut line = vec![0.0f32; cx];
        // The x interpolation of `line` at the even (`2j`, coarse position `j − ¼`) and odd
        // (`2j + 1`, position `j + ¼`) fine samples, clamped at the borders as `axis_table`.
        let mut even = vec![0.0f32; cx];
        let mut odd = vec![0.0f32; cx];
        for zl in 0..out[0].len() / (nx * ny) {
            let (z0, z1, wz) = az[zs + zl];
            for y in 0..ny {
                let (y0, y1, wy) = ay[y];
                let o = nx * (y + ny * (zs + zl));
                let fx = &fixed[o..o + nx];
                let ol = nx * (y + ny * zl);
                for (ch, c) in cc.iter().enumerate() {
                    let row = |yy: usize, zz: usize| &c[cx * (yy + cy * zz)..][..cx];
                    let (r00, r10, r01, r11) = (row(y0, z0), row(y1, z0), row(y0, z1), row(y1, z1));
                    let line = &mut line[..cx];
                    for x in 0..cx {
                        let a = r00[x] + wy * (r10[x] - r00[x]);
                        let b = r01[x] + wy * (r11[x] - r01[x]);
                        line[x] = a + wz * (b - a);
                    }
                    interpolate_x(line, &mut even, &mut odd);
                    let dst = &mut out[ch][ol..ol + nx];
                    let blend = |d: &mut f32, f: f32, fx: u8| {
                        let v = if ADD { *d + f } else { f };
                        *d = keep_fixed(fx, *d, v);
                    };
                    let pairs = nx / 2;
                    let (dp, dt) = dst.split_at_mut(2 * pairs);
                    let (fp, ft) = fx.split_at(2 * pairs);
                    for (((d, f), e), o) in dp
                        .chunks_exact_mut(2)
                        .zip(fp.chunks_exact(2))
                        .zip(&even[..pairs])
                        .zip(&odd[..pairs])
                    {
                        blend(&mut d[0], *e, f[0]);
                        blend(&mut d[1], *o, f[1]);
                    }
                    if let (Some(d), Some(f)) = (dt.first_mut(), ft.first()) {
                        blend(d, even[pairs], *f);
                    }
                }
            }
        }
    });
}

/// The linear interpolation of a coarse line at the fine samples `2j` (`even[j]`, coarse
/// position `j − ¼`) and `2j + 1` (`odd[j]`, position `j + ¼`), positions clamped to the line:
/// the same numbers as [`axis_table`]'s `l[i0] + w·(l[i1] − l[i0])`, as plain vectorisable
/// passes.
fn interpolate_x(line: &[f32], even: &mut [f32], odd: &mut [f32]) {
    let n = line.len();
    let (even, odd) = (&mut even[..n], &mut odd[..n]);
    even[0] = line[0];
    odd[n - 1] = line[n - 1];
    if n > 1 {
        let (lo, hi) = (&line[..n - 1], &line[1..]);
        let e = &mut even[1..];
        for j in 0..n - 1 {
            e[j] = lo[j] + 0.75 * (hi[j] - lo[j]);
        }
        let o = &mut odd[..n - 1];
        for j in 0..n - 1 {
            o[j] = lo[j] + 0.25 * (hi[j] - lo[j]);
        }
    }
}

/// The coarse constraint values: the mean of the fixed children of every coarse sample that has
/// fixed children (0 elsewhere), into `cu`.
fn restrict_constraints(
    fine: [usize; 3],
    u: &[Vec<f32>],
    fixed: &[u8],
    coarse: [usize; 3],
    cu: &mut [Vec<f32>],
) {
    let nx = fine[0];
    let mut count = vec![vec![0.0f32; coarse.iter().product()]];
    restrict_sum(fine, coarse, &mut count, |_, y, z, out| {
        let o = nx * (y + fine[1] * z);
        for (v, f) in out[..nx].iter_mut().zip(&fixed[o..o + nx]) {
            *v = f32::from(*f != 0);
        }
    });
    restrict_sum(fine, coarse, cu, |ch, y, z, out| {
        let o = nx * (y + fine[1] * z);
        let (src, fx) = (&u[ch][o..o + nx], &fixed[o..o + nx]);
        for x in 0..nx {
            out[x] = keep_fixed(fx[x], src[x], 0.0);
        }
    });
    for c in cu.iter_mut() {
        for (v, k) in c.iter_mut().zip(&count[0]) {
            if *k > 0.0 {
                *v /= *k;
            }
        }
    }
}

/// The residual `Σ_nb (u_nb − u)` of one row (`r = [row, up, down, north, south]`, the row
/// itself where a neighbour is missing), 0 at fixed samples, into `out`.
fn residual_row(r: [&[f32]; 5], fx: &[u8], out: &mut [f32]) {
    let nx = out.len();
    let (c, u, d, no, so, fx) = (
        &r[0][..nx],
        &r[1][..nx],
        &r[2][..nx],
        &r[3][..nx],
        &r[4][..nx],
        &fx[..nx],
    );
    // The Laplacian in the summation order of the sweeps (`diffuse::laplace_at`).
    let lap = |v: f32, e: f32, w: f32, x: usize| {
        (e - v) + (w - v) + (u[x] - v) + (d[x] - v) + (no[x] - v) + (so[x] - v)
    };
    if nx == 1 {
        out[0] = keep_fixed(fx[0], 0.0, lap(c[0], c[0], c[0], 0));
    } else {
        let m = nx - 2;
        {
            let (ce, cv, cw) = (&c[2..], &c[1..nx - 1], &c[..m]);
            let (u, d, no, so, fxi) = (
                &u[1..nx - 1],
                &d[1..nx - 1],
                &no[1..nx - 1],
                &so[1..nx - 1],
                &fx[1..nx - 1],
            );
            let o = &mut out[1..nx - 1];
            for x in 0..m {
                let v = cv[x];
                let l =
                    (ce[x] - v) + (cw[x] - v) + (u[x] - v) + (d[x] - v) + (no[x] - v) + (so[x] - v);
                o[x] = keep_fixed(fxi[x], 0.0, l);
            }
        }
        out[0] = keep_fixed(fx[0], 0.0, lap(c[0], c[1], c[0], 0));
        out[nx - 1] = keep_fixed(
            fx[nx - 1],
            0.0,
            lap(c[nx - 1], c[nx - 1], c[nx - 2], nx - 1),
        );
    }
}

/// The cascade on the coarse levels: solves the problem of `levels[0]` (its right-hand side `b`
/// and the values of its dead samples set) from the coarser ones down, `fine_sweeps`
/// Gauss–Seidel sweeps per level, `coarsest_sweeps` on the coarsest.
fn cascade_coarse(levels: &mut [Level], p: &DiffuseParams) {
    let Some((cur, rest)) = levels.split_first_mut() else {
        return;
    };
    let Some(next) = rest.first_mut() else {
        gauss_seidel(cur, p.coarsest_sweeps);
        return;
    };
    restrict_constraints(cur.dims, &cur.u, &cur.fixed, next.dims, &mut next.u);
    let nx = cur.dims[0];
    let (cdims, b) = (cur.dims, &cur.b);
    restrict_sum(cdims, next.dims, &mut next.b, |ch, y, z, out| {
        let o = nx * (y + cdims[1] * z);
        out[..nx].copy_from_slice(&b[ch][o..o + nx]);
    });
    cascade_coarse(rest, p);
    let next = &rest[0];
    prolong::<false>(cur.dims, next.dims, &next.u, &cur.fixed, &mut cur.u);
    gauss_seidel(cur, p.fine_sweeps);
}

/// One V-cycle on the coarse levels for the correction equation of `levels[0]` (`u` = 0 on
/// entry, right-hand side `b`): two Gauss–Seidel sweeps, the coarse-grid correction, two
/// sweeps; `coarsest_sweeps` on the coarsest level.
fn vcycle_coarse(levels: &mut [Level], p: &DiffuseParams) {
    let Some((cur, rest)) = levels.split_first_mut() else {
        return;
    };
    let Some(next) = rest.first_mut() else {
        gauss_seidel(cur, p.coarsest_sweeps);
        return;
    };
    gauss_seidel(cur, SMOOTH_SWEEPS);
    restrict_coarse_residual(cur, next.dims, &mut next.b);
    for c in next.u.iter_mut() {
        c.fill(0.0);
    }
    vcycle_coarse(rest, p);
    let next = &rest[0];
    prolong::<true>(cur.dims, next.dims, &next.u, &cur.fixed, &mut cur.u);
    gauss_seidel(cur, SMOOTH_SWEEPS);
}

/// Fills the free samples (`fixed == 0`) of every channel with the harmonic interpolation of the
/// fixed ones: the cascade, then `p.vcycles` V-cycles (module docs). Channels without any fixed
/// sample become 0.
pub fn harmonic_fill(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], p: &DiffuseParams) {
    harmonic_fill_on(dims, chans, fixed, p, &Cancel::never());
}

/// [`harmonic_fill`] that stops before its next V-cycle once `cancel` is set, leaving `chans`
/// part-way (for a caller that checks `cancel` and discards them).
pub fn harmonic_fill_on(
    dims: [usize; 3],
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    p: &DiffuseParams,
    cancel: &Cancel,
) {
    let mut tmp: Vec<Vec<f32>> = chans.iter().map(|c| vec![0.0f32; c.len()]).collect();
    harmonic_fill_with(dims, chans, fixed, p, &mut tmp, cancel);
}

/// [`harmonic_fill_on`] with a caller-owned scratch field of the same shape as `chans` (its
/// contents are overwritten).
pub(crate) fn harmonic_fill_with(
    dims: [usize; 3],
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    p: &DiffuseParams,
    tmp: &mut [Vec<f32>],
    cancel: &Cancel,
) {
    if chans.is_empty() {
        return;
    }
    let tmp = &mut tmp[..chans.len()];
    let mut levels = hierarchy(dims, fixed, chans.len());
    // The cascade's finest step: the free samples start at 0, so the residual is the coupling
    // to the constraints, `b = Σ_{fixed nb} u_nb`, whose restriction is the first coarse
    // right-hand side.
    for c in chans.iter_mut() {
        for (v, f) in c.iter_mut().zip(fixed) {
            *v = keep_fixed(*f, *v, 0.0);
        }
    }
    if let Some(first) = levels.first_mut() {
        restrict_constraints(dims, chans, fixed, first.dims, &mut first.u);
        restrict_finest_residual(dims, chans, fixed, first.dims, &mut first.b);
        cascade_coarse(&mut levels, p);
        prolong::<false>(dims, levels[0].dims, &levels[0].u, fixed, chans);
        relax(dims, chans, tmp, None, fixed, 1.0 / 6.0, p.fine_sweeps);
    } else {
        // A grid that is its own coarsest level.
        relax(dims, chans, tmp, None, fixed, 1.0 / 6.0, p.coarsest_sweeps);
    }
    for _ in 0..p.vcycles {
        if cancel.is_cancelled() {
            return;
        }
        vcycle(dims, chans, tmp, fixed, &mut levels, p);
    }
}

/// One V-cycle on the finest level: two damped Jacobi sweeps, the coarse-grid correction, two
/// sweeps.
fn vcycle(
    dims: [usize; 3],
    u: &mut [Vec<f32>],
    tmp: &mut [Vec<f32>],
    fixed: &[u8],
    levels: &mut [Level],
    p: &DiffuseParams,
) {
    let Some(first) = levels.first_mut() else {
        relax(dims, u, tmp, None, fixed, SMOOTH_WEIGHT, p.coarsest_sweeps);
        return;
    };
    relax(dims, u, tmp, None, fixed, SMOOTH_WEIGHT, SMOOTH_SWEEPS);
    restrict_finest_residual(dims, u, fixed, first.dims, &mut first.b);
    for c in first.u.iter_mut() {
        c.fill(0.0);
    }
    vcycle_coarse(levels, p);
    prolong::<true>(dims, levels[0].dims, &levels[0].u, fixed, u);
    relax(dims, u, tmp, None, fixed, SMOOTH_WEIGHT, SMOOTH_SWEEPS);
}

/// The Euclidean norm of the Laplace residual `Σ_nb (u_nb − u)` over the free samples of all
/// channels (homogeneous Neumann borders), summed in a fixed order in `f64`: the measure of
/// [`harmonic_fill`]'s convergence.
pub fn harmonic_residual(dims: [usize; 3], chans: &[Vec<f32>], fixed: &[u8]) -> f64 {
    let [nx, ny, nz] = dims;
    let mut r = vec![0.0f32; nx];
    let mut sum = 0.0f64;
    for c in chans {
        for z in 0..nz {
            for y in 0..ny {
                let rw = rows(dims, y, z);
                let row = |o: usize| &c[o..o + nx];
                residual_row(
                    [row(rw.o), row(rw.u), row(rw.d), row(rw.n), row(rw.s)],
                    &fixed[rw.o..rw.o + nx],
                    &mut r,
                );
                sum += r.iter().map(|v| f64::from(*v) * f64::from(*v)).sum::<f64>();
            }
        }
    }
    sum.sqrt()
}
