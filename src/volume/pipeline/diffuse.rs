//! Guidance-field and noise-field diffusion (Becher §4.3–4.4), with an O(n) solver (§8).
//!
//! **The sweep** is the paper's discretised anisotropic diffusion (Perona & Malik 1990):
//!
//! `N' = N + ⅙ (c_E [∂N/∂x]⁺ + c_W [∂N/∂x]⁻ + c_U [∂N/∂y]⁺ + c_D [∂N/∂y]⁻ + c_N [∂N/∂z]⁺ + c_S [∂N/∂z]⁻)`
//!
//! with `[·]^±` the differences to the neighbour in that direction, homogeneous Neumann borders
//! (a missing neighbour contributes nothing), constrained samples (`Ω_N`) held fixed, and
//! `c = g(x)`, `g(x) = 1 / (1 + (x/k)²)`, `k = 0.01`. The paper's argument is
//! `x = (1 − N_a·N_b)/2`; we use `x = |N_a − N_b|²/4`, which is the same number for unit vectors
//! and makes the scheme a lagged-diffusivity (half-quadratic) iteration: every sweep is a gradient
//! step of length 1/12 on `Σ c_ab |N_a − N_b|²` (stable: the weighted Laplacian's spectral radius
//! is ≤ 12), so by concavity the Perona–Malik energy `E(N) = Σ_edges 4k·atan(|N_a − N_b|²/(4k))`
//! ([`pm_energy`]) never increases from one sweep to the next. `tests/volume_pipeline.rs` checks it.
//!
//! **Unset samples.** §4.3 says that for samples not yet reached (`N = 0`) `g` "evaluates to 1"
//! and the sweep becomes Laplace's equation; with the stated `x` it would be `g(½) ≈ 4·10⁻⁴` and
//! nothing would spread. We implement the stated intent in two phases: first the free samples
//! are filled with the harmonic (Laplace, `c ≡ 1`) interpolation of the constraints, then
//! normalised, then the anisotropic sweeps run on the dense unit field.
//!
//! **O(n) instead of thousands of Jacobi sweeps (§8).** The harmonic fill is a cascadic
//! multigrid (Bornemann & Deuflhard 1996) followed by V-cycles, in [`super::multigrid`] and
//! re-exported here as [`harmonic_fill`]: the constraints are restricted to a pyramid of grids
//! of half resolution (a coarse sample is constrained if any of its eight children is; its value
//! is their mean), the coarsest grid (≤ [`COARSEST`] samples) is solved with plain Jacobi
//! sweeps, each finer level starts from the trilinear interpolation of the coarser solution and
//! runs `fine_sweeps·2^level` sweeps, and `vcycles` V-cycles remove the remaining low-frequency
//! error. Total work is a small constant times n. A warm start (a previous solution as the
//! initial guess, [`super::region::regenerate`]) skips the pyramid.
//!
//! The noise parameters `α`, `β` (§4.4) are diffused with the same harmonic fill (the paper
//! solves Laplace's equation for them; no anisotropy).
//!
//! Every sweep is a pure function of the previous iterate (Jacobi), parallel over z-slabs on
//! rayon's pool; the result does not depend on the thread count. The Perona–Malik sweep computes
//! each edge's coefficient once (both samples of an edge use the same `g(|N_a − N_b|²/4)`,
//! symmetric to the last bit), so it is bit-identical to evaluating the six coefficients of the
//! formula per sample, at half the divisions. Loops keep fixed samples by a branch-free blend so
//! that they vectorise (x86-64-v3: 8 lanes). `shaders/volume_diffuse.wgsl` is the GPU twin of
//! [`sweep`]; its arithmetic is unchanged.

use super::grid::par_slabs_multi;
pub use super::multigrid::harmonic_fill;
use super::multigrid::harmonic_fill_with;
use rayon::prelude::*;

/// Most samples of the coarsest level of the cascade and the V-cycles.
pub const COARSEST: usize = 512;

/// The paper's Perona–Malik parameter `k`.
pub const K_PERONA_MALIK: f32 = 0.01;

/// Perona–Malik's edge-stopping function `g(x) = 1/(1 + (x/k)²)`.
#[inline]
pub fn g(x: f32, k: f32) -> f32 {
    let q = x / k;
    1.0 / (1.0 + q * q)
}

/// Parameters of the diffusions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffuseParams {
    /// Jacobi sweeps on the finest level of the cascade (doubling per coarser level).
    pub fine_sweeps: u32,
    /// Jacobi sweeps on the coarsest level (at most [`COARSEST`] samples).
    pub coarsest_sweeps: u32,
    /// Multigrid V-cycles after the cascade (each: two sweeps before and after the coarse
    /// correction on every level).
    pub vcycles: u32,
    /// Anisotropic (Perona–Malik) sweeps after the harmonic fill of `N`.
    pub pm_sweeps: u32,
    /// Perona–Malik `k`.
    pub k: f32,
}

impl Default for DiffuseParams {
    fn default() -> Self {
        Self {
            fine_sweeps: 4,
            coarsest_sweeps: 200,
            vcycles: 2,
            pm_sweeps: 6,
            k: K_PERONA_MALIK,
        }
    }
}

/// Row offsets of row `(y, z)` and of its neighbours up, down, north and south (the row itself at
/// a Neumann border, where the difference then contributes zero).
#[derive(Clone, Copy)]
pub(crate) struct Rows {
    pub(crate) o: usize,
    pub(crate) u: usize,
    pub(crate) d: usize,
    pub(crate) n: usize,
    pub(crate) s: usize,
}

#[inline]
pub(crate) fn rows(dims: [usize; 3], y: usize, z: usize) -> Rows {
    let [nx, ny, nz] = dims;
    let o = nx * (y + ny * z);
    Rows {
        o,
        u: if y + 1 < ny { o + nx } else { o },
        d: if y > 0 { o - nx } else { o },
        n: if z + 1 < nz { o + nx * ny } else { o },
        s: if z > 0 { o - nx * ny } else { o },
    }
}

/// The Laplace update of one sample from its value `v`, the east and west neighbours `e`, `w`
/// and the up, down, north and south ones: `v + (Σ_nb (v_nb − v) + b)·weight` (`b` ignored when
/// `RHS` is false), `v` itself when `fixed != 0`. At a Neumann border the caller passes `v` as
/// the missing neighbour, whose difference is then zero.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn laplace_at<const RHS: bool>(
    v: f32,
    e: f32,
    w: f32,
    u: f32,
    d: f32,
    no: f32,
    so: f32,
    b: f32,
    fixed: u8,
    weight: f32,
) -> f32 {
    let acc = (e - v) + (w - v) + (u - v) + (d - v) + (no - v) + (so - v);
    let nv = if RHS {
        v + (acc + b) * weight
    } else {
        v + acc * weight
    };
    keep_fixed(fixed, v, nv)
}

/// The Laplace update of one row (see [`laplace_at`]): `c` is the row itself, `u`, `d`, `no`,
/// `so` the rows up, down, north and south (the row itself at a Neumann border), `b` the
/// right-hand side (empty when `RHS` is false). The x neighbours are read as the row shifted by
/// one sample, so the interior loop is a plain vectorisable pass over equal-length slices; the
/// two border samples repeat themselves as their missing neighbour (Neumann).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn laplace_row<const RHS: bool>(
    c: &[f32],
    u: &[f32],
    d: &[f32],
    no: &[f32],
    so: &[f32],
    b: &[f32],
    fx: &[u8],
    weight: f32,
    dst: &mut [f32],
) {
    let nx = dst.len();
    let (c, u, d, no, so, fx) = (
        &c[..nx],
        &u[..nx],
        &d[..nx],
        &no[..nx],
        &so[..nx],
        &fx[..nx],
    );
    let b = &b[..if RHS { nx } else { 0 }];
    let bx = |x: usize| if RHS { b[x] } else { 0.0 };
    if nx == 1 {
        dst[0] = laplace_at::<RHS>(
            c[0],
            c[0],
            c[0],
            u[0],
            d[0],
            no[0],
            so[0],
            bx(0),
            fx[0],
            weight,
        );
        return;
    }
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
        let bi = &b[if RHS { 1 } else { 0 }..if RHS { nx - 1 } else { 0 }];
        let out = &mut dst[1..nx - 1];
        for x in 0..m {
            let bv = if RHS { bi[x] } else { 0.0 };
            out[x] = laplace_at::<RHS>(
                cv[x], ce[x], cw[x], u[x], d[x], no[x], so[x], bv, fxi[x], weight,
            );
        }
    }
    dst[0] = laplace_at::<RHS>(
        c[0],
        c[1],
        c[0],
        u[0],
        d[0],
        no[0],
        so[0],
        bx(0),
        fx[0],
        weight,
    );
    let l = nx - 1;
    dst[l] = laplace_at::<RHS>(
        c[l],
        c[l],
        c[l - 1],
        u[l],
        d[l],
        no[l],
        so[l],
        bx(l),
        fx[l],
        weight,
    );
}

/// `v` where `fixed != 0`, else `nv`, as a branch-free bit blend: the loops compute `nv` for
/// every sample and vectorise with plain loads (a branch makes the compiler mask the loads).
#[inline(always)]
pub(crate) fn keep_fixed(fixed: u8, v: f32, nv: f32) -> f32 {
    let keep = u32::from(fixed != 0).wrapping_neg();
    f32::from_bits((v.to_bits() & keep) | (nv.to_bits() & !keep))
}

/// One Jacobi sweep over all channels: Laplace (`pm = None`, `c ≡ 1`) or Perona–Malik with
/// `Some(k)` (then exactly three channels, the components of `N`). `fixed[i] != 0` keeps
/// sample `i`. Parallel over z-slabs; the result does not depend on the partition.
pub fn sweep(
    dims: [usize; 3],
    src: &[&[f32]],
    fixed: &[u8],
    pm: Option<f32>,
    dst: &mut [&mut [f32]],
) {
    let m = src.len();
    assert!(
        pm.is_none() || m == 3,
        "Perona–Malik sweeps take three channels"
    );
    assert_eq!(m, dst.len(), "as many outputs as inputs");
    let outs: Vec<&mut [f32]> = dst.iter_mut().map(|d| &mut **d).collect();
    match pm {
        Some(k) => {
            let src = [src[0], src[1], src[2]];
            par_slabs_multi(outs, dims[0] * dims[1], |z0, out| {
                pm_slab(dims, src, fixed, 0.25 / k, z0, out);
            });
        }
        None => laplace_sweep(dims, src, None, fixed, 1.0 / 6.0, outs),
    }
}

/// One (damped) Jacobi sweep of every channel for `Σ_nb (u − u_nb) = b` (`b = 0` when `rhs`
/// is `None`) with step `weight` (`1/6`: plain Jacobi, the paper's sweep).
pub(crate) fn laplace_sweep(
    dims: [usize; 3],
    src: &[&[f32]],
    rhs: Option<&[&[f32]]>,
    fixed: &[u8],
    weight: f32,
    outs: Vec<&mut [f32]>,
) {
    let [nx, ny, _] = dims;
    par_slabs_multi(outs, nx * ny, |z0, out| {
        for zl in 0..out[0].len() / (nx * ny) {
            for y in 0..ny {
                let r = rows(dims, y, z0 + zl);
                let ol = zl * nx * ny + y * nx;
                let fx = &fixed[r.o..r.o + nx];
                for (ch, src) in src.iter().enumerate() {
                    let row = |o: usize| &src[o..o + nx];
                    let dst = &mut out[ch][ol..ol + nx];
                    let (c, u, d, no, so) = (row(r.o), row(r.u), row(r.d), row(r.n), row(r.s));
                    match rhs {
                        Some(b) => laplace_row::<true>(
                            c,
                            u,
                            d,
                            no,
                            so,
                            &b[ch][r.o..r.o + nx],
                            fx,
                            weight,
                            dst,
                        ),
                        None => laplace_row::<false>(c, u, d, no, so, &[], fx, weight, dst),
                    }
                }
            }
        }
    });
}

/// The Perona–Malik coefficients `g(|N_a − N_b|²/4)` of the edges between the rows `a` and `b`
/// into `out` (`qk = 1/(4k)`).
#[inline(always)]
fn edge_weights(a: [&[f32]; 3], b: [&[f32]; 3], qk: f32, out: &mut [f32]) {
    let n = out.len();
    let (a0, a1, a2) = (&a[0][..n], &a[1][..n], &a[2][..n]);
    let (b0, b1, b2) = (&b[0][..n], &b[1][..n], &b[2][..n]);
    for x in 0..n {
        let d0 = b0[x] - a0[x];
        let d1 = b1[x] - a1[x];
        let d2 = b2[x] - a2[x];
        let q = (d0 * d0 + d1 * d1 + d2 * d2) * qk;
        out[x] = 1.0 / (1.0 + q * q);
    }
}

/// The Perona–Malik update of one sample from its value `v`, its six neighbours
/// `[e, w, u, d, n, s]` and the coefficients of the six edges: `v + ⅙ Σ c_nb (v_nb − v)`, `v`
/// itself when `fixed != 0`.
#[inline(always)]
fn pm_at(v: f32, nb: [f32; 6], c: [f32; 6], fixed: u8) -> f32 {
    let acc = c[0] * (nb[0] - v)
        + c[1] * (nb[1] - v)
        + c[2] * (nb[2] - v)
        + c[3] * (nb[3] - v)
        + c[4] * (nb[4] - v)
        + c[5] * (nb[5] - v);
    keep_fixed(fixed, v, v + acc * (1.0 / 6.0))
}

/// The Perona–Malik update of one row of all three channels: `r[ch] = [row, up, down, north,
/// south]` (the row itself where a neighbour is missing), `k = [x edges, up, down, north,
/// south]` coefficients shared by the channels, the x edges `k[0][x]` = edge `(x − 1, x)` with
/// `nx + 1` entries whose first and last (Neumann borders) are 1. The interior is one
/// vectorisable pass over shifted slices that loads every coefficient and mask byte once for the
/// three channels (the outputs are separate parameters so that they are known not to alias the
/// inputs); the border samples use themselves as the missing neighbour, whose term is then `1·0`.
#[inline(always)]
fn pm_row3(
    r: [[&[f32]; 5]; 3],
    k: [&[f32]; 5],
    fx: &[u8],
    d0: &mut [f32],
    d1: &mut [f32],
    d2: &mut [f32],
) {
    let nx = d0.len();
    let (d1, d2) = (&mut d1[..nx], &mut d2[..nx]);
    let (kx, ku, kd, kn, ks) = (
        &k[0][..nx + 1],
        &k[1][..nx],
        &k[2][..nx],
        &k[3][..nx],
        &k[4][..nx],
    );
    let fx = &fx[..nx];
    let border = |x: usize, e: usize, w: usize, ch: usize| {
        let [c, u, d, no, so] = r[ch];
        pm_at(
            c[x],
            [c[e], c[w], u[x], d[x], no[x], so[x]],
            [kx[x + 1], kx[x], ku[x], kd[x], kn[x], ks[x]],
            fx[x],
        )
    };
    if nx == 1 {
        let v = [border(0, 0, 0, 0), border(0, 0, 0, 1), border(0, 0, 0, 2)];
        (d0[0], d1[0], d2[0]) = (v[0], v[1], v[2]);
        return;
    }
    let l = nx - 1;
    let first = [border(0, 1, 0, 0), border(0, 1, 0, 1), border(0, 1, 0, 2)];
    let last = [
        border(l, l, l - 1, 0),
        border(l, l, l - 1, 1),
        border(l, l, l - 1, 2),
    ];
    interior3(
        r,
        [
            &kx[2..],
            &kx[1..l],
            &ku[1..l],
            &kd[1..l],
            &kn[1..l],
            &ks[1..l],
        ],
        &fx[1..l],
        &mut d0[1..l],
        &mut d1[1..l],
        &mut d2[1..l],
    );
    (d0[0], d1[0], d2[0]) = (first[0], first[1], first[2]);
    (d0[l], d1[l], d2[l]) = (last[0], last[1], last[2]);
}

/// The interior samples `1..nx − 1` of [`pm_row3`]: `k` the six coefficient rows and `fx` the
/// mask already cut to the interior, the outputs the interior of the three rows. Not inlined, so
/// that the outputs keep their no-alias guarantee as parameters.
#[inline(never)]
fn interior3(
    r: [[&[f32]; 5]; 3],
    k: [&[f32]; 6],
    fx: &[u8],
    o0: &mut [f32],
    o1: &mut [f32],
    o2: &mut [f32],
) {
    let m = o0.len();
    let (o1, o2, fx) = (&mut o1[..m], &mut o2[..m], &fx[..m]);
    let k = k.map(|s| &s[..m]);
    let [ke, kw, ku, kd, kn, ks] = k;
    let cut = |ch: usize| {
        let [c, u, d, no, so] = r[ch];
        [
            &c[2..m + 2],
            &c[..m],
            &c[1..m + 1],
            &u[1..m + 1],
            &d[1..m + 1],
            &no[1..m + 1],
            &so[1..m + 1],
        ]
    };
    let [e0, w0, c0, u0, dn0, n0, s0] = cut(0);
    let [e1, w1, c1, u1, dn1, n1, s1] = cut(1);
    let [e2, w2, c2, u2, dn2, n2, s2] = cut(2);
    for x in 0..m {
        let kk = [ke[x], kw[x], ku[x], kd[x], kn[x], ks[x]];
        let f = fx[x];
        o0[x] = pm_at(c0[x], [e0[x], w0[x], u0[x], dn0[x], n0[x], s0[x]], kk, f);
        o1[x] = pm_at(c1[x], [e1[x], w1[x], u1[x], dn1[x], n1[x], s1[x]], kk, f);
        o2[x] = pm_at(c2[x], [e2[x], w2[x], u2[x], dn2[x], n2[x], s2[x]], kk, f);
    }
}

/// The Perona–Malik sweep of the z-slab starting at `z0` into `out` (three channels).
///
/// Each edge's coefficient is computed once and used by both of its samples (`g` depends on
/// `|N_a − N_b|²`, which is symmetric to the last bit): the x edges of a row, the y edges in a
/// rolling pair of rows and the z edges in a rolling pair of z-slices. A missing (Neumann)
/// neighbour gets coefficient 1 and contributes `1·0`. The arithmetic per sample is exactly
/// that of the per-direction formula in the module docs.
fn pm_slab(
    dims: [usize; 3],
    src: [&[f32]; 3],
    fixed: &[u8],
    qk: f32,
    z0: usize,
    out: &mut [&mut [f32]],
) {
    let [nx, ny, nz] = dims;
    let slice = nx * ny;
    let nzs = out[0].len() / slice;
    let at = |o: usize| [&src[0][o..o + nx], &src[1][o..o + nx], &src[2][o..o + nx]];
    // Coefficients of the z edges below (z − 1, z) and above (z, z + 1) the current slice.
    let mut cz_lo = vec![1.0f32; slice];
    let mut cz_hi = vec![1.0f32; slice];
    if z0 > 0 {
        for y in 0..ny {
            let o = nx * (y + ny * z0);
            edge_weights(at(o - slice), at(o), qk, &mut cz_lo[y * nx..y * nx + nx]);
        }
    }
    let mut cy_lo = vec![1.0f32; nx];
    let mut cy_hi = vec![1.0f32; nx];
    // x edges: `cx[x]` is the edge (x − 1, x); `cx[0]` and `cx[nx]` are the Neumann borders.
    let mut cx = vec![1.0f32; nx + 1];
    for zl in 0..nzs {
        let z = z0 + zl;
        cy_lo.fill(1.0);
        for y in 0..ny {
            let r = rows(dims, y, z);
            let c = at(r.o);
            if y + 1 < ny {
                edge_weights(c, at(r.u), qk, &mut cy_hi);
            } else {
                cy_hi.fill(1.0);
            }
            let czh = &mut cz_hi[y * nx..y * nx + nx];
            if z + 1 < nz {
                edge_weights(c, at(r.n), qk, czh);
            } else {
                czh.fill(1.0);
            }
            edge_weights(
                [&c[0][..nx - 1], &c[1][..nx - 1], &c[2][..nx - 1]],
                [&c[0][1..], &c[1][1..], &c[2][1..]],
                qk,
                &mut cx[1..nx],
            );
            let (cu, cd) = (&cy_hi[..nx], &cy_lo[..nx]);
            let (cn, cs) = (&cz_hi[y * nx..y * nx + nx], &cz_lo[y * nx..y * nx + nx]);
            let fx = &fixed[r.o..r.o + nx];
            let ol = zl * slice + y * nx;
            let rows5 = |ch: usize| {
                let row = |o: usize| &src[ch][o..o + nx];
                [c[ch], row(r.u), row(r.d), row(r.n), row(r.s)]
            };
            let [o0, o1, o2] = out else {
                unreachable!("three output channels")
            };
            pm_row3(
                [rows5(0), rows5(1), rows5(2)],
                [&cx[..], cu, cd, cn, cs],
                fx,
                &mut o0[ol..ol + nx],
                &mut o1[ol..ol + nx],
                &mut o2[ol..ol + nx],
            );
            std::mem::swap(&mut cy_lo, &mut cy_hi);
        }
        std::mem::swap(&mut cz_lo, &mut cz_hi);
    }
}

/// `sweeps` Jacobi sweeps (see [`sweep`]) in place, ping-ponging through a scratch copy.
pub fn sweeps(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], pm: Option<f32>, n: u32) {
    if n == 0 {
        return;
    }
    let mut other: Vec<Vec<f32>> = chans.iter().map(|c| vec![0.0; c.len()]).collect();
    sweeps_with(dims, chans, fixed, pm, n, &mut other);
}

/// [`sweeps`] ping-ponging through a caller-owned scratch field of the same shape as `chans`.
fn sweeps_with(
    dims: [usize; 3],
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    pm: Option<f32>,
    n: u32,
    other: &mut [Vec<f32>],
) {
    for _ in 0..n {
        {
            let src: Vec<&[f32]> = chans.iter().map(|c| c.as_slice()).collect();
            let mut dst: Vec<&mut [f32]> = other.iter_mut().map(|c| c.as_mut_slice()).collect();
            sweep(dims, &src, fixed, pm, &mut dst);
        }
        for (a, b) in chans.iter_mut().zip(other.iter_mut()) {
            std::mem::swap(a, b);
        }
    }
}

/// The Perona–Malik energy `Σ_edges 4k·atan(|N_a − N_b|²/(4k))` over the grid's edges; the
/// sweeps never increase it (module docs).
pub fn pm_energy(dims: [usize; 3], n: &[Vec<f32>], k: f32) -> f64 {
    edge_sum(dims, n, |u| {
        let k = f64::from(k);
        4.0 * k * (u / (4.0 * k)).atan()
    })
}

/// The Dirichlet energy `Σ_edges |v_a − v_b|²`, which Laplace sweeps never increase.
pub fn dirichlet_energy(dims: [usize; 3], chans: &[Vec<f32>]) -> f64 {
    edge_sum(dims, chans, |u| u)
}

fn edge_sum(dims: [usize; 3], chans: &[Vec<f32>], f: impl Fn(f64) -> f64) -> f64 {
    let [nx, ny, nz] = dims;
    let mut e = 0.0;
    let d2 = |a: usize, b: usize| -> f64 {
        chans
            .iter()
            .map(|c| {
                let d = f64::from(c[a]) - f64::from(c[b]);
                d * d
            })
            .sum()
    };
    for z in 0..nz {
        for y in 0..ny {
            for x in 0..nx {
                let i = x + nx * (y + ny * z);
                if x + 1 < nx {
                    e += f(d2(i, i + 1));
                }
                if y + 1 < ny {
                    e += f(d2(i, i + nx));
                }
                if z + 1 < nz {
                    e += f(d2(i, i + nx * ny));
                }
            }
        }
    }
    e
}

/// Normalises every non-zero vector of a three-channel field in place, except at the fixed
/// samples (which hold the constraints unchanged, bit for bit).
pub fn normalize_field(n: &mut [Vec<f32>], fixed: &[u8]) {
    let [a, b, c] = n else {
        panic!("normalize_field takes three channels");
    };
    let len = fixed.len();
    let (a, b, c) = (&mut a[..len], &mut b[..len], &mut c[..len]);
    let chunk = 1 << 14;
    a.par_chunks_mut(chunk)
        .zip(b.par_chunks_mut(chunk))
        .zip(c.par_chunks_mut(chunk))
        .zip(fixed.par_chunks(chunk))
        .for_each(|(((a, b), c), f)| {
            for i in 0..f.len() {
                let l2 = a[i] * a[i] + b[i] * b[i] + c[i] * c[i];
                if f[i] == 0 && l2 > 1e-24 {
                    let inv = 1.0 / l2.sqrt();
                    a[i] *= inv;
                    b[i] *= inv;
                    c[i] *= inv;
                }
            }
        });
}

/// Stage 2 of §4.1: the dense normal field. Harmonic fill of the free samples (cascadic, or the
/// caller's warm-start values when `warm` is set), normalisation, `pm_sweeps` anisotropic sweeps,
/// normalisation. `n` holds the constraints in `Ω_N` (and, with `warm`, the initial guess
/// elsewhere).
pub fn diffuse_normals(
    dims: [usize; 3],
    n: &mut [Vec<f32>],
    fixed: &[u8],
    p: &DiffuseParams,
    warm: bool,
) {
    // One scratch field for the fill and the sweeps.
    let mut tmp: Vec<Vec<f32>> = n.iter().map(|c| vec![0.0f32; c.len()]).collect();
    if warm {
        sweeps_with(dims, n, fixed, None, p.fine_sweeps, &mut tmp);
    } else {
        harmonic_fill_with(dims, n, fixed, p, &mut tmp);
    }
    normalize_field(n, fixed);
    sweeps_with(dims, n, fixed, Some(p.k), p.pm_sweeps, &mut tmp);
    normalize_field(n, fixed);
}
