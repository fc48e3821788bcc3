//! Guidance-field and noise-field diffusion (Becher §4.3–4.4), with an O(n) solver (§8).
//!
//! Why one file of about 770 lines (70 of tests): the Perona–Malik sweep with its wide and narrow
//! kernels, which must agree bit for bit, and the Laplace sweep share the row layout of `rows` and
//! the fixed-sample rule of `keep_fixed`, and the energies below measure those sweeps.
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
//! re-exported here as [`harmonic_fill`]: a pyramid of grids of half resolution whose operators
//! are Galerkin products of the fine one (constraints enter the coarse levels with exactly their
//! fine couplings instead of being inflated), the coarse problems solved from the coarsest
//! (≤ [`COARSEST`] samples) up, each finer level starting from the trilinear interpolation of the
//! coarser solution, then `vcycles` V-cycles, each of which reduces the residual by a factor of
//! about 0.2–0.35 on the arch scene (`tests/volume_pipeline.rs`). Total work is a small constant
//! times n. A warm start (a previous solution as the initial guess,
//! [`super::region::regenerate`]) skips the pyramid.
//!
//! **Defaults** ([`DiffuseParams::default`]): 2 cascade sweeps per level, 1 V-cycle, 6
//! Perona–Malik sweeps. With the Galerkin hierarchy one V-cycle leaves a smaller residual on the
//! 128 × 64 × 128 arch scene (0.90) than the previous rediscretised hierarchy did with 4 cascade
//! sweeps and 2 V-cycles (1.14), so the harmonic start of the anisotropic sweeps is at least as
//! close to the paper's converged Laplace fill as before; the 6 Perona–Malik sweeps are
//! unchanged, so the paper's edge-preserving result (§4.3) is reached from the same start.
//!
//! The noise parameters `α`, `β` (§4.4) are diffused with the same harmonic fill (the paper
//! solves Laplace's equation for them; no anisotropy).
//!
//! Every sweep is a pure function of the previous iterate (Jacobi), parallel over z-slabs on
//! rayon's pool; the result does not depend on the thread count. The Perona–Malik sweep is a
//! streaming flux computation: each edge's flux `g(|N_b − N_a|²/4)·(N_b − N_a)` is computed once
//! (one exact IEEE division per edge, no reciprocal approximation, so results agree across CPU
//! vendors) and added to one endpoint and subtracted from the other; the x fluxes of a row, the
//! y fluxes of the previous row and the z fluxes of the previous slice live in small scratch rows,
//! and the three channels are fused in one loop that vectorises. `|d|²`, `1 + q²` and the update
//! `v + ⅙·acc` are fused multiply-adds. Since `c·(w − v) = −(c·(v − w))` exactly and the terms
//! are summed in the formula's order, the sweep is bit-identical to evaluating the six
//! coefficients of the formula per sample, so `shaders/volume_diffuse.wgsl` (the GPU twin of
//! [`sweep`], which does exactly that, within the GPU's division accuracy) and the bricked sweeps
//! ([`super::brick`]) compute the same numbers. Loops keep fixed samples by a branch-free blend.
//!
//! The sweep is compute-bound (three exact divisions per sample). The build targets x86-64-v3
//! (8 lanes); on a CPU with AVX-512 the slab kernel runs a copy compiled for 16 lanes
//! (`pm_slab_wide`, chosen at run time). Both perform the same IEEE operations on every sample,
//! so their results are bit-identical (tested); only the speed differs.

use super::grid::par_slabs_multi;
use super::multigrid::harmonic_fill_with;
pub use super::multigrid::{harmonic_fill, harmonic_fill_on};
use crate::terrain::cancel::Cancel;
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
    /// Sweeps on every level of the cascade but the coarsest (Jacobi on the finest level,
    /// red-black Gauss–Seidel on the coarse ones); also the Laplace sweeps of a warm start.
    pub fine_sweeps: u32,
    /// Red-black Gauss–Seidel sweeps on the coarsest level (at most [`COARSEST`] samples).
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
            fine_sweeps: 2,
            coarsest_sweeps: 200,
            vcycles: 1,
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
            let inputs = PmInputs {
                dims,
                src,
                fixed,
                qk: 0.25 / k,
            };
            par_slabs_multi(outs, dims[0] * dims[1], |z0, out| pm_slab(inputs, z0, out));
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

/// The Perona–Malik coefficient `g(|d|²/4) = 1 / (1 + q²)`, `q = |d|² · qk` (`qk = 1/(4k)`) of
/// an edge whose endpoints differ by `d`, with fused multiply-adds: `|d|² = d₂² + (d₁² + d₀²)`
/// and `1 + q²` each rounded once. `d` and `−d` give the same coefficient, bit for bit.
#[inline(always)]
fn coefficient(d0: f32, d1: f32, d2: f32, qk: f32) -> f32 {
    let q = d2.mul_add(d2, d1.mul_add(d1, d0 * d0)) * qk;
    1.0 / q.mul_add(q, 1.0)
}

/// The Perona–Malik fluxes `g(|b − a|²/4)·(b_ch − a_ch)` of the edges between the rows `a` and
/// `b` (three channels each, `qk = 1/(4k)`) into `o0`, `o1`, `o2`. The outputs are separate
/// parameters so that they are known not to alias the inputs and the loop vectorises.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn edge_fluxes(
    a: [&[f32]; 3],
    b: [&[f32]; 3],
    qk: f32,
    o0: &mut [f32],
    o1: &mut [f32],
    o2: &mut [f32],
) {
    let n = o0.len();
    let (o1, o2) = (&mut o1[..n], &mut o2[..n]);
    let (a0, a1, a2) = (&a[0][..n], &a[1][..n], &a[2][..n]);
    let (b0, b1, b2) = (&b[0][..n], &b[1][..n], &b[2][..n]);
    for x in 0..n {
        let d0 = b0[x] - a0[x];
        let d1 = b1[x] - a1[x];
        let d2 = b2[x] - a2[x];
        let c = coefficient(d0, d1, d2, qk);
        o0[x] = c * d0;
        o1[x] = c * d1;
        o2[x] = c * d2;
    }
}

/// One row of the streaming Perona–Malik sweep, three channels (`ch = 0, 1, 2` in the names).
///
/// `c*` is the row, `u*` the row above and `n*` the row north (the row itself at a Neumann
/// border: the difference is then 0 and so is the flux). `x*` are the row's x-edge fluxes,
/// `nx + 1` entries, `x[i]` = flux of edge `(i − 1, i)`, zero at both ends. `d*` hold on entry the
/// fluxes of the y edges below the row and on return those above it; `s*` likewise for the z
/// edges. The update of sample `i` is `v + ⅙ (x[i+1] − x[i] + F_up − d[i] + F_north − s[i])`,
/// which is the per-direction formula of the module docs term for term and in its order
/// (`c_w (w − v) = −c_w (v − w)` exactly). Every input and output is a separate parameter so
/// that the loop vectorises without alias checks.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn pm_row(
    c0: &[f32],
    c1: &[f32],
    c2: &[f32],
    u0: &[f32],
    u1: &[f32],
    u2: &[f32],
    n0: &[f32],
    n1: &[f32],
    n2: &[f32],
    x0: &[f32],
    x1: &[f32],
    x2: &[f32],
    d0: &mut [f32],
    d1: &mut [f32],
    d2: &mut [f32],
    s0: &mut [f32],
    s1: &mut [f32],
    s2: &mut [f32],
    fixed: &[u8],
    qk: f32,
    o0: &mut [f32],
    o1: &mut [f32],
    o2: &mut [f32],
) {
    let m = o0.len();
    let (o1, o2, fixed) = (&mut o1[..m], &mut o2[..m], &fixed[..m]);
    let (c0, c1, c2) = (&c0[..m], &c1[..m], &c2[..m]);
    let (u0, u1, u2) = (&u0[..m], &u1[..m], &u2[..m]);
    let (n0, n1, n2) = (&n0[..m], &n1[..m], &n2[..m]);
    let (e0, e1, e2) = (&x0[1..m + 1], &x1[1..m + 1], &x2[1..m + 1]);
    let (w0, w1, w2) = (&x0[..m], &x1[..m], &x2[..m]);
    let (d0, d1, d2) = (&mut d0[..m], &mut d1[..m], &mut d2[..m]);
    let (s0, s1, s2) = (&mut s0[..m], &mut s1[..m], &mut s2[..m]);
    for i in 0..m {
        let (v0, v1, v2) = (c0[i], c1[i], c2[i]);
        let (a0, a1, a2) = (u0[i] - v0, u1[i] - v1, u2[i] - v2);
        let ca = coefficient(a0, a1, a2, qk);
        let (b0, b1, b2) = (n0[i] - v0, n1[i] - v1, n2[i] - v2);
        let cb = coefficient(b0, b1, b2, qk);
        let (fu0, fu1, fu2) = (ca * a0, ca * a1, ca * a2);
        let (fn0, fn1, fn2) = (cb * b0, cb * b1, cb * b2);
        let acc0 = e0[i] - w0[i] + fu0 - d0[i] + fn0 - s0[i];
        let acc1 = e1[i] - w1[i] + fu1 - d1[i] + fn1 - s1[i];
        let acc2 = e2[i] - w2[i] + fu2 - d2[i] + fn2 - s2[i];
        let f = fixed[i];
        o0[i] = keep_fixed(f, v0, acc0.mul_add(1.0 / 6.0, v0));
        o1[i] = keep_fixed(f, v1, acc1.mul_add(1.0 / 6.0, v1));
        o2[i] = keep_fixed(f, v2, acc2.mul_add(1.0 / 6.0, v2));
        (d0[i], d1[i], d2[i]) = (fu0, fu1, fu2);
        (s0[i], s1[i], s2[i]) = (fn0, fn1, fn2);
    }
}

/// The Perona–Malik sweep of the z-slab starting at `z0` into `out` (three channels), as a
/// streaming flux computation.
///
/// Each edge's flux `g(|N_b − N_a|²/4)·(N_b − N_a)` is computed once (one division per edge,
/// exact IEEE) and used by both of its samples, with opposite signs: the x edges of a row in a
/// row of `nx + 1` fluxes, the y edges below the current row in one row of fluxes carried from
/// the previous row, the z edges below the current slice in one slice of fluxes carried from the
/// previous slice (the first slice of a slab computes those of the edges to the slice below it,
/// exactly as the slab below computes them). A missing (Neumann) neighbour has flux 0. The
/// arithmetic per sample is exactly that of the per-direction formula in the module docs
/// ([`pm_row`]), so the result does not depend on the slab partition.
fn pm_slab(inputs: PmInputs, z0: usize, out: &mut [&mut [f32]]) {
    #[cfg(target_arch = "x86_64")]
    if wide_vectors() {
        // SAFETY: the CPU has the AVX-512 subsets `pm_slab_wide` is compiled for (checked at
        // run time by `wide_vectors`).
        unsafe { pm_slab_wide(inputs, z0, out) };
        return;
    }
    pm_slab_narrow(inputs, z0, out);
}

/// The read-only inputs of a Perona–Malik sweep: grid, the three channels, the constraint mask
/// and `qk = 1/(4k)`.
#[derive(Clone, Copy)]
struct PmInputs<'a> {
    dims: [usize; 3],
    src: [&'a [f32]; 3],
    fixed: &'a [u8],
    qk: f32,
}

/// True when the CPU has AVX-512 F, VL, BW and DQ.
#[cfg(target_arch = "x86_64")]
fn wide_vectors() -> bool {
    std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512vl")
        && std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512dq")
}

/// [`pm_slab_body`] compiled for AVX-512 (16 lanes). The arithmetic is the same IEEE operations
/// per sample as [`pm_slab_narrow`], so the results are bit-identical; only the vector width
/// differs.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq")]
#[inline(never)]
fn pm_slab_wide(inputs: PmInputs, z0: usize, out: &mut [&mut [f32]]) {
    pm_slab_body(inputs, z0, out);
}

/// [`pm_slab_body`] for the build's target (x86-64-v3: 8 lanes).
#[inline(never)]
fn pm_slab_narrow(inputs: PmInputs, z0: usize, out: &mut [&mut [f32]]) {
    pm_slab_body(inputs, z0, out);
}

#[inline(always)]
fn pm_slab_body(inputs: PmInputs, z0: usize, out: &mut [&mut [f32]]) {
    let PmInputs {
        dims,
        src,
        fixed,
        qk,
    } = inputs;
    let [nx, ny, _] = dims;
    let slice = nx * ny;
    let nzs = out[0].len() / slice;
    let at = |o: usize| [&src[0][o..o + nx], &src[1][o..o + nx], &src[2][o..o + nx]];
    let zeros = |n: usize| [vec![0.0f32; n], vec![0.0f32; n], vec![0.0f32; n]];
    // Fluxes of the z edges below the current slice, of the y edges below the current row and of
    // the x edges of the current row (`fx[i]` = edge `(i − 1, i)`; entries 0 and `nx` stay 0).
    let [mut fz0, mut fz1, mut fz2] = zeros(slice);
    let [mut fy0, mut fy1, mut fy2] = zeros(nx);
    let [mut fx0, mut fx1, mut fx2] = zeros(nx + 1);
    if z0 > 0 {
        for y in 0..ny {
            let o = nx * (y + ny * z0);
            let r = y * nx..y * nx + nx;
            edge_fluxes(
                at(o - slice),
                at(o),
                qk,
                &mut fz0[r.clone()],
                &mut fz1[r.clone()],
                &mut fz2[r],
            );
        }
    }
    let [o0, o1, o2] = out else {
        unreachable!("three output channels")
    };
    for zl in 0..nzs {
        let z = z0 + zl;
        fy0.fill(0.0);
        fy1.fill(0.0);
        fy2.fill(0.0);
        for y in 0..ny {
            let r = rows(dims, y, z);
            let [c0, c1, c2] = at(r.o);
            let [u0, u1, u2] = at(r.u);
            let [n0, n1, n2] = at(r.n);
            edge_fluxes(
                [&c0[..nx - 1], &c1[..nx - 1], &c2[..nx - 1]],
                [&c0[1..], &c1[1..], &c2[1..]],
                qk,
                &mut fx0[1..nx],
                &mut fx1[1..nx],
                &mut fx2[1..nx],
            );
            let p = y * nx..y * nx + nx;
            let ol = zl * slice + y * nx..zl * slice + y * nx + nx;
            pm_row(
                c0,
                c1,
                c2,
                u0,
                u1,
                u2,
                n0,
                n1,
                n2,
                &fx0,
                &fx1,
                &fx2,
                &mut fy0,
                &mut fy1,
                &mut fy2,
                &mut fz0[p.clone()],
                &mut fz1[p.clone()],
                &mut fz2[p],
                &fixed[r.o..r.o + nx],
                qk,
                &mut o0[ol.clone()],
                &mut o1[ol.clone()],
                &mut o2[ol],
            );
        }
    }
}

/// `sweeps` Jacobi sweeps (see [`sweep`]) in place, ping-ponging through a scratch copy.
pub fn sweeps(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], pm: Option<f32>, n: u32) {
    if n == 0 {
        return;
    }
    let mut other: Vec<Vec<f32>> = chans.iter().map(|c| vec![0.0; c.len()]).collect();
    sweeps_with(dims, chans, fixed, pm, n, &mut other, &Cancel::never());
}

/// [`sweeps`] ping-ponging through a caller-owned scratch field of the same shape as `chans`,
/// stopping before the next sweep once `cancel` is set (the field is then left part-way, for a
/// caller that discards it).
fn sweeps_with(
    dims: [usize; 3],
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    pm: Option<f32>,
    n: u32,
    other: &mut [Vec<f32>],
    cancel: &Cancel,
) {
    for _ in 0..n {
        if cancel.is_cancelled() {
            return;
        }
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
/// elsewhere). The anisotropic sweeps come from `dev` when it answers. Once `cancel` is set
/// the stage stops at its next sweep or V-cycle and leaves `n` part-way: the caller checks
/// `cancel` and discards it.
pub fn diffuse_normals(
    dims: [usize; 3],
    n: &mut [Vec<f32>],
    fixed: &[u8],
    p: &DiffuseParams,
    warm: bool,
    dev: &dyn crate::volume::offload::VolumeOffload,
    cancel: &Cancel,
) {
    // One scratch field for the fill and the sweeps.
    let mut tmp: Vec<Vec<f32>> = n.iter().map(|c| vec![0.0f32; c.len()]).collect();
    if warm {
        sweeps_with(dims, n, fixed, None, p.fine_sweeps, &mut tmp, cancel);
    } else {
        harmonic_fill_with(dims, n, fixed, p, &mut tmp, cancel);
    }
    if cancel.is_cancelled() {
        return;
    }
    normalize_field(n, fixed);
    match dev.pm_sweeps(dims, n, fixed, p.k, p.pm_sweeps) {
        Some(swept) if swept.len() == n.len() => {
            for (c, s) in n.iter_mut().zip(swept) {
                *c = s;
            }
        }
        _ => sweeps_with(dims, n, fixed, Some(p.k), p.pm_sweeps, &mut tmp, cancel),
    }
    normalize_field(n, fixed);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Near-unit normals with differences around `4k`, where the coefficients vary most, and a
    /// few fixed samples.
    fn field(dims: [usize; 3]) -> (Vec<Vec<f32>>, Vec<u8>) {
        let n = dims.iter().product::<usize>();
        let hash = |i: usize, c: usize| {
            let h = (i as u32 ^ (c as u32).wrapping_mul(0x9e37_79b9)).wrapping_mul(0x85eb_ca6b);
            ((h ^ (h >> 13)).wrapping_mul(0xc2b2_ae35) >> 8) as f32 / (1u32 << 24) as f32
        };
        let chans = (0..3)
            .map(|c| {
                (0..n)
                    .map(|i| [0.3, 0.9, 0.3][c] + 0.06 * (hash(i, c) - 0.5))
                    .collect()
            })
            .collect();
        let fixed = (0..n).map(|i| u8::from(i % 13 == 0)).collect();
        (chans, fixed)
    }

    #[test]
    fn the_wide_and_narrow_perona_malik_kernels_agree_bit_for_bit() {
        // Row lengths that leave every remainder of the 8- and 16-lane loops.
        for dims in [[37, 5, 4], [48, 3, 3], [17, 4, 2]] {
            let (chans, fixed) = field(dims);
            let inputs = PmInputs {
                dims,
                src: [&chans[0][..], &chans[1][..], &chans[2][..]],
                fixed: &fixed,
                qk: 25.0,
            };
            let n = chans[0].len();
            let run = |wide: bool| {
                let mut out: Vec<Vec<f32>> = (0..3).map(|_| vec![0.0f32; n]).collect();
                let mut o: Vec<&mut [f32]> = out.iter_mut().map(|c| c.as_mut_slice()).collect();
                #[cfg(target_arch = "x86_64")]
                if wide {
                    // SAFETY: only called when the CPU has the features (checked below).
                    unsafe { pm_slab_wide(inputs, 0, &mut o) };
                    return out;
                }
                assert!(!wide, "no wide kernel on this architecture");
                pm_slab_narrow(inputs, 0, &mut o);
                out
            };
            let narrow = run(false);
            assert!(
                narrow[0].iter().zip(&chans[0]).any(|(a, b)| a != b),
                "the sweep moved values"
            );
            #[cfg(target_arch = "x86_64")]
            if wide_vectors() {
                let wide = run(true);
                for c in 0..3 {
                    for i in 0..n {
                        assert_eq!(
                            wide[c][i].to_bits(),
                            narrow[c][i].to_bits(),
                            "channel {c} sample {i} of {dims:?}"
                        );
                    }
                }
                continue;
            }
            println!("this CPU has no AVX-512: only the narrow kernel runs here");
        }
    }
}
