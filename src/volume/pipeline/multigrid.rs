//! The O(n) harmonic fill of the diffusions (Becher §4.3–4.4, and §8's call for multigrid instead
//! of thousands of Jacobi sweeps): Laplace's equation `Σ_nb (u − u_nb) = 0` at the free samples,
//! Dirichlet values at the fixed ones, homogeneous Neumann borders.
//!
//! **Hierarchy.** Level `l + 1` halves level `l` per axis (cell-centred: coarse sample `X` covers
//! fine samples `2X` and `2X + 1`). A coarse sample is fixed when any of its children is; its
//! constraint value is the mean of its fixed children. The hierarchy (masks and every level's
//! buffers) is built once per call, for all channels together.
//!
//! **Cascade** (Bornemann & Deuflhard 1996): the coarsest level (≤ [`COARSEST`] samples) starts
//! from the mean of its constraints and runs `coarsest_sweeps` Jacobi sweeps; each finer level
//! starts from the trilinear interpolation of the coarser solution at its free samples and runs
//! `fine_sweeps·2^level` Jacobi sweeps.
//!
//! **V-cycles** then correct the cascade's low-frequency bias: on every level two damped Jacobi
//! sweeps (`ω = 6/7`, the optimal smoothing weight of the 7-point Laplacian) before and after the
//! coarse correction, the residual restricted by the mean of the children times 4 (the operator
//! rediscretised at twice the spacing), the correction prolongated trilinearly onto the free
//! samples; fixed coarse samples carry a zero correction.
//!
//! All channels go through every pass together (one pass over the fixed mask per sweep), every
//! pass is parallel over z-slabs and writes disjoint samples from read-only inputs, so the result
//! does not depend on the thread count.

use super::diffuse::{keep_fixed, laplace_sweep, rows, DiffuseParams, COARSEST};
use super::grid::par_slabs_multi;

/// Smoothing step of the V-cycles: `ω/6` with `ω = 6/7`.
const SMOOTH_WEIGHT: f32 = 1.0 / 7.0;

/// One level below the finest: its dimensions, mask and per-channel buffers.
struct Level {
    dims: [usize; 3],
    fixed: Vec<u8>,
    /// Solution (cascade) or correction (V-cycle), per channel.
    u: Vec<Vec<f32>>,
    /// Right-hand side of the V-cycle, per channel.
    b: Vec<Vec<f32>>,
    /// Ping-pong scratch, per channel.
    tmp: Vec<Vec<f32>>,
}

fn coarser(dims: [usize; 3]) -> Option<[usize; 3]> {
    let n = dims.iter().product::<usize>();
    let c = dims.map(|d| d.div_ceil(2));
    (n > COARSEST && c.iter().all(|&d| d >= 2)).then_some(c)
}

/// The coarse levels below `dims` with their masks.
fn hierarchy(dims: [usize; 3], fixed: &[u8], m: usize) -> Vec<Level> {
    let mut levels: Vec<Level> = Vec::new();
    let mut fd = dims;
    while let Some(cd) = coarser(fd) {
        let ff: &[u8] = levels.last().map_or(fixed, |l| &l.fixed);
        let [nx, ny, nz] = fd;
        let [cx, cy, _] = cd;
        let cn = cd.iter().product::<usize>();
        let mut cf = vec![0u8; cn];
        for z in 0..nz {
            for y in 0..ny {
                let o = nx * (y + ny * z);
                let co = cx * (y / 2 + cy * (z / 2));
                for x in 0..nx {
                    cf[co + x / 2] |= ff[o + x];
                }
            }
        }
        let bufs = || (0..m).map(|_| vec![0.0f32; cn]).collect::<Vec<_>>();
        levels.push(Level {
            dims: cd,
            fixed: cf,
            u: bufs(),
            b: bufs(),
            tmp: bufs(),
        });
        fd = cd;
    }
    levels
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

/// Fine children of coarse index `c` along an axis of `n` fine samples: 1 or 2.
#[inline]
fn children(c: usize, n: usize) -> usize {
    if 2 * c + 1 < n {
        2
    } else {
        1
    }
}

/// The coarse constraint values: the mean of the fixed children of every fixed coarse sample.
fn restrict_constraints(
    fine: [usize; 3],
    u: &[Vec<f32>],
    fixed: &[u8],
    coarse: [usize; 3],
    cu: &mut [Vec<f32>],
) {
    let [nx, ny, nz] = fine;
    let [cx, cy, _] = coarse;
    let cn = coarse.iter().product::<usize>();
    let mut count = vec![0u32; cn];
    for c in cu.iter_mut() {
        c.fill(0.0);
    }
    for z in 0..nz {
        for y in 0..ny {
            let o = nx * (y + ny * z);
            let co = cx * (y / 2 + cy * (z / 2));
            for x in 0..nx {
                if fixed[o + x] != 0 {
                    count[co + x / 2] += 1;
                    for (cc, c) in cu.iter_mut().zip(u) {
                        cc[co + x / 2] += c[o + x];
                    }
                }
            }
        }
    }
    for cc in cu.iter_mut() {
        for (v, k) in cc.iter_mut().zip(&count) {
            if *k > 0 {
                *v /= *k as f32;
            }
        }
    }
}

/// The residual `b − Σ_nb (u − u_nb)` (0 at fixed samples) restricted to the coarse grid:
/// `4 ×` the mean over each coarse sample's children, into `cb`.
fn residual_restrict(
    fine: [usize; 3],
    u: &[Vec<f32>],
    b: Option<&[Vec<f32>]>,
    fixed: &[u8],
    coarse: [usize; 3],
    cb: &mut [Vec<f32>],
) {
    let [nx, ny, nz] = fine;
    let [cx, cy, _] = coarse;
    let outs: Vec<&mut [f32]> = cb.iter_mut().map(|c| c.as_mut_slice()).collect();
    par_slabs_multi(outs, cx * cy, |cz0, out| {
        let mut r = vec![0.0f32; nx];
        for czl in 0..out[0].len() / (cx * cy) {
            let cz = cz0 + czl;
            let kz = children(cz, nz);
            for cyy in 0..cy {
                let ky = children(cyy, ny);
                let co = cx * (cyy + cy * czl);
                for (ch, c) in u.iter().enumerate() {
                    let acc = &mut out[ch][co..co + cx];
                    acc.fill(0.0);
                    for z in 2 * cz..2 * cz + kz {
                        for y in 2 * cyy..2 * cyy + ky {
                            let rw = rows(fine, y, z);
                            let row = |o: usize| &c[o..o + nx];
                            let rb = b.map(|b| &b[ch][rw.o..rw.o + nx]);
                            residual_row(
                                [row(rw.o), row(rw.u), row(rw.d), row(rw.n), row(rw.s)],
                                rb,
                                &fixed[rw.o..rw.o + nx],
                                &mut r,
                            );
                            let (pairs, odd) = r.split_at(nx & !1);
                            for (a, p) in acc.iter_mut().zip(pairs.chunks_exact(2)) {
                                *a += p[0] + p[1];
                            }
                            if let Some(last) = odd.first() {
                                acc[nx / 2] += last;
                            }
                        }
                    }
                    for (xc, a) in acc.iter_mut().enumerate() {
                        let k = children(xc, nx) * ky * kz;
                        *a = 4.0 * *a / k as f32;
                    }
                }
            }
        }
    });
}

/// The residual `b − Σ_nb (u − u_nb)` of one row (`r = [row, up, down, north, south]`, the row
/// itself where a neighbour is missing), 0 at fixed samples, into `out`.
fn residual_row(r: [&[f32]; 5], b: Option<&[f32]>, fx: &[u8], out: &mut [f32]) {
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
    if let Some(b) = b {
        let b = &b[..nx];
        for x in 0..nx {
            out[x] += keep_fixed(fx[x], 0.0, b[x]);
        }
    }
}

/// The cascade from level `l` (0 = the caller's grid `u`, `fixed`) down.
fn cascade(
    l: usize,
    dims: [usize; 3],
    u: &mut [Vec<f32>],
    tmp: &mut [Vec<f32>],
    fixed: &[u8],
    levels: &mut [Level],
    p: &DiffuseParams,
) {
    let Some((next, rest)) = levels.split_first_mut() else {
        // Coarsest level: start from the mean of the constraints.
        for c in u.iter_mut() {
            let (mut s, mut k) = (0.0f64, 0usize);
            for (v, f) in c.iter().zip(fixed) {
                if *f != 0 {
                    s += f64::from(*v);
                    k += 1;
                }
            }
            let mean = if k > 0 { (s / k as f64) as f32 } else { 0.0 };
            for (v, f) in c.iter_mut().zip(fixed) {
                if *f == 0 {
                    *v = mean;
                }
            }
        }
        relax(dims, u, tmp, None, fixed, 1.0 / 6.0, p.coarsest_sweeps);
        return;
    };
    restrict_constraints(dims, u, fixed, next.dims, &mut next.u);
    cascade(
        l + 1,
        next.dims,
        &mut next.u,
        &mut next.tmp,
        &next.fixed,
        rest,
        p,
    );
    prolong::<false>(dims, next.dims, &next.u, fixed, u);
    let k = p.fine_sweeps << l.min(6);
    relax(dims, u, tmp, None, fixed, 1.0 / 6.0, k);
}

/// One V-cycle on level `u` (dims, mask `fixed`, right-hand side `b`, `None` = 0).
#[allow(clippy::too_many_arguments)]
fn vcycle(
    dims: [usize; 3],
    u: &mut [Vec<f32>],
    tmp: &mut [Vec<f32>],
    b: Option<&[Vec<f32>]>,
    fixed: &[u8],
    levels: &mut [Level],
    coarsest_sweeps: u32,
) {
    let Some((next, rest)) = levels.split_first_mut() else {
        relax(dims, u, tmp, b, fixed, SMOOTH_WEIGHT, coarsest_sweeps);
        return;
    };
    relax(dims, u, tmp, b, fixed, SMOOTH_WEIGHT, 2);
    residual_restrict(dims, u, b, fixed, next.dims, &mut next.b);
    for c in next.u.iter_mut() {
        c.fill(0.0);
    }
    vcycle(
        next.dims,
        &mut next.u,
        &mut next.tmp,
        Some(&next.b),
        &next.fixed,
        rest,
        coarsest_sweeps,
    );
    prolong::<true>(dims, next.dims, &next.u, fixed, u);
    relax(dims, u, tmp, b, fixed, SMOOTH_WEIGHT, 2);
}

/// Fills the free samples (`fixed == 0`) of every channel with the harmonic interpolation of the
/// fixed ones: the cascade, then `p.vcycles` V-cycles (module docs). Channels without any fixed
/// sample become 0.
pub fn harmonic_fill(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], p: &DiffuseParams) {
    let mut tmp: Vec<Vec<f32>> = chans.iter().map(|c| vec![0.0f32; c.len()]).collect();
    harmonic_fill_with(dims, chans, fixed, p, &mut tmp);
}

/// [`harmonic_fill`] with a caller-owned scratch field of the same shape as `chans` (its
/// contents are overwritten).
pub(crate) fn harmonic_fill_with(
    dims: [usize; 3],
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    p: &DiffuseParams,
    tmp: &mut [Vec<f32>],
) {
    if chans.is_empty() {
        return;
    }
    let mut levels = hierarchy(dims, fixed, chans.len());
    let tmp = &mut tmp[..chans.len()];
    cascade(0, dims, chans, tmp, fixed, &mut levels, p);
    for _ in 0..p.vcycles {
        vcycle(
            dims,
            chans,
            tmp,
            None,
            fixed,
            &mut levels,
            p.coarsest_sweeps,
        );
    }
}
