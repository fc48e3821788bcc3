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
//! multigrid (Bornemann & Deuflhard 1996): the constraints are restricted to a pyramid of grids
//! of half resolution (a coarse sample is constrained if any of its eight children is; its value
//! is their mean), the coarsest grid (≤ [`COARSEST`] samples) is solved with plain Jacobi sweeps, and each
//! finer level starts from the trilinear interpolation of the coarser solution and runs
//! `fine_sweeps·2^level` sweeps. Total work is a small constant times n. A warm start (a previous
//! solution as the initial guess, [`super::region::regenerate`]) skips the pyramid.
//!
//! The noise parameters `α`, `β` (§4.4) are diffused with the same harmonic fill (the paper
//! solves Laplace's equation for them; no anisotropy).
//!
//! Every sweep is a pure function of the previous iterate (Jacobi), parallel over z-slabs; the
//! result does not depend on the thread count. `shaders/volume_diffuse.wgsl` is the GPU twin of
//! [`sweep`].

use super::grid::par_slabs_multi;

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

/// One row's neighbours: for each direction E, W, U, D, N, S the row of the neighbour (the row
/// itself at a Neumann border, contributing zero).
struct Rows {
    o: usize,
    u: usize,
    d: usize,
    n: usize,
    s: usize,
}

fn rows(dims: [usize; 3], y: usize, z: usize) -> Rows {
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

/// One Jacobi sweep over all channels: Laplace (`pm = None`, `c ≡ 1`) or Perona–Malik with
/// `Some(k)` (then exactly three channels, the components of `N`). `fixed[i] != 0` keeps
/// sample `i`.
pub fn sweep(
    dims: [usize; 3],
    src: &[&[f32]],
    fixed: &[u8],
    pm: Option<f32>,
    dst: &mut [&mut [f32]],
) {
    let [nx, ny, _] = dims;
    let m = src.len();
    assert!(
        pm.is_none() || m == 3,
        "Perona–Malik sweeps take three channels"
    );
    assert_eq!(m, dst.len(), "as many outputs as inputs");
    let outs: Vec<&mut [f32]> = dst.iter_mut().map(|d| &mut **d).collect();
    par_slabs_multi(outs, nx * ny, |z0, out| {
        let nzs = out[0].len() / (nx * ny);
        let mut east = vec![vec![0.0f32; nx]; m];
        let mut west = vec![vec![0.0f32; nx]; m];
        let mut coef = vec![vec![1.0f32; nx]; 6];
        for zl in 0..nzs {
            let z = z0 + zl;
            for y in 0..ny {
                let r = rows(dims, y, z);
                for ch in 0..m {
                    let c = &src[ch][r.o..r.o + nx];
                    east[ch][..nx - 1].copy_from_slice(&c[1..]);
                    east[ch][nx - 1] = c[nx - 1];
                    west[ch][1..].copy_from_slice(&c[..nx - 1]);
                    west[ch][0] = c[0];
                }
                if let Some(k) = pm {
                    let qk = 0.25 / k;
                    let c0 = &src[0][r.o..r.o + nx];
                    let c1 = &src[1][r.o..r.o + nx];
                    let c2 = &src[2][r.o..r.o + nx];
                    let row = |ch: usize, o: usize| &src[ch][o..o + nx];
                    let nbs: [[&[f32]; 3]; 6] = [
                        [&east[0][..nx], &east[1][..nx], &east[2][..nx]],
                        [&west[0][..nx], &west[1][..nx], &west[2][..nx]],
                        [row(0, r.u), row(1, r.u), row(2, r.u)],
                        [row(0, r.d), row(1, r.d), row(2, r.d)],
                        [row(0, r.n), row(1, r.n), row(2, r.n)],
                        [row(0, r.s), row(1, r.s), row(2, r.s)],
                    ];
                    for (cf, [b0, b1, b2]) in coef.iter_mut().zip(nbs) {
                        let cf = &mut cf[..nx];
                        for x in 0..nx {
                            let d0 = b0[x] - c0[x];
                            let d1 = b1[x] - c1[x];
                            let d2 = b2[x] - c2[x];
                            let q = (d0 * d0 + d1 * d1 + d2 * d2) * qk;
                            cf[x] = 1.0 / (1.0 + q * q);
                        }
                    }
                }
                let fx = &fixed[r.o..r.o + nx];
                let ol = zl * nx * ny + y * nx;
                for ch in 0..m {
                    let c = &src[ch][r.o..r.o + nx];
                    let e = &east[ch][..nx];
                    let w = &west[ch][..nx];
                    let u = &src[ch][r.u..r.u + nx];
                    let dn = &src[ch][r.d..r.d + nx];
                    let no = &src[ch][r.n..r.n + nx];
                    let so = &src[ch][r.s..r.s + nx];
                    let dst = &mut out[ch][ol..ol + nx];
                    if pm.is_some() {
                        let (ce, cw, cu) = (&coef[0][..nx], &coef[1][..nx], &coef[2][..nx]);
                        let (cd, cn, cs) = (&coef[3][..nx], &coef[4][..nx], &coef[5][..nx]);
                        for x in 0..nx {
                            let v = c[x];
                            let acc = ce[x] * (e[x] - v)
                                + cw[x] * (w[x] - v)
                                + cu[x] * (u[x] - v)
                                + cd[x] * (dn[x] - v)
                                + cn[x] * (no[x] - v)
                                + cs[x] * (so[x] - v);
                            let nv = v + acc * (1.0 / 6.0);
                            dst[x] = if fx[x] != 0 { v } else { nv };
                        }
                    } else {
                        for x in 0..nx {
                            let v = c[x];
                            let acc = (e[x] - v)
                                + (w[x] - v)
                                + (u[x] - v)
                                + (dn[x] - v)
                                + (no[x] - v)
                                + (so[x] - v);
                            let nv = v + acc * (1.0 / 6.0);
                            dst[x] = if fx[x] != 0 { v } else { nv };
                        }
                    }
                }
            }
        }
    });
}

/// `sweeps` Jacobi sweeps (see [`sweep`]) in place, ping-ponging through a scratch copy.
pub fn sweeps(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], pm: Option<f32>, n: u32) {
    let mut other: Vec<Vec<f32>> = chans.to_vec();
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

/// Fills the free samples (`fixed == 0`) of every channel with the harmonic interpolation of the
/// fixed ones by the cascadic multigrid of the module docs. Channels without any fixed sample
/// become 0.
pub fn harmonic_fill(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], p: &DiffuseParams) {
    cascade(dims, chans, fixed, p, 0);
    let zero = vec![0.0f32; fixed.len()];
    for c in chans.iter_mut() {
        for _ in 0..p.vcycles {
            vcycle(dims, c, &zero, fixed, p.coarsest_sweeps);
        }
    }
}

fn cascade(dims: [usize; 3], chans: &mut [Vec<f32>], fixed: &[u8], p: &DiffuseParams, level: u32) {
    let n = dims.iter().product::<usize>();
    let coarse = dims.map(|d| d.div_ceil(2));
    if n <= COARSEST || coarse.iter().any(|&d| d < 2) {
        // Coarsest level: start from the mean of the constraints.
        for c in chans.iter_mut() {
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
        sweeps(dims, chans, fixed, None, p.coarsest_sweeps);
        return;
    }
    // Restriction of the constraints.
    let [nx, ny, nz] = dims;
    let [cx, cy, cz] = coarse;
    let cn = cx * cy * cz;
    let mut cfixed = vec![0u8; cn];
    let mut count = vec![0u32; cn];
    let mut cchans: Vec<Vec<f32>> = (0..chans.len()).map(|_| vec![0.0; cn]).collect();
    for z in 0..nz {
        for y in 0..ny {
            for x in 0..nx {
                let i = x + nx * (y + ny * z);
                if fixed[i] != 0 {
                    let ci = x / 2 + cx * (y / 2 + cy * (z / 2));
                    cfixed[ci] = 1;
                    count[ci] += 1;
                    for (cc, c) in cchans.iter_mut().zip(chans.iter()) {
                        cc[ci] += c[i];
                    }
                }
            }
        }
    }
    for cc in cchans.iter_mut() {
        for (v, k) in cc.iter_mut().zip(&count) {
            if *k > 0 {
                *v /= *k as f32;
            }
        }
    }
    cascade(coarse, &mut cchans, &cfixed, p, level + 1);
    // Trilinear prolongation into the free fine samples.
    for (c, cc) in chans.iter_mut().zip(&cchans) {
        let fine = prolong(dims, coarse, cc);
        for ((v, f), fx) in c.iter_mut().zip(fine).zip(fixed) {
            if *fx == 0 {
                *v = f;
            }
        }
    }
    sweeps(dims, chans, fixed, None, p.fine_sweeps << level.min(6));
}

/// Normalises every non-zero vector of a three-channel field in place, except at the fixed
/// samples (which hold the constraints unchanged, bit for bit).
pub fn normalize_field(n: &mut [Vec<f32>], fixed: &[u8]) {
    let len = n[0].len();
    for i in 0..len {
        if fixed[i] != 0 {
            continue;
        }
        let l2 = n[0][i] * n[0][i] + n[1][i] * n[1][i] + n[2][i] * n[2][i];
        if l2 > 1e-24 {
            let inv = 1.0 / l2.sqrt();
            for c in n.iter_mut() {
                c[i] *= inv;
            }
        }
    }
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
    if warm {
        sweeps(dims, n, fixed, None, p.fine_sweeps);
    } else {
        harmonic_fill(dims, n, fixed, p);
    }
    normalize_field(n, fixed);
    sweeps(dims, n, fixed, Some(p.k), p.pm_sweeps);
    normalize_field(n, fixed);
}

/// `out = u + ⅙ (Σ_nb (u_nb − u) + b)` at free samples, `u` at fixed ones (one damped Jacobi
/// sweep for `Σ_nb (u − u_nb) = b`, Neumann borders). With `b = 0` it is [`sweep`] (Laplace).
fn smooth_rhs(dims: [usize; 3], u: &[f32], b: &[f32], fixed: &[u8], out: &mut [f32]) {
    let [nx, ny, _] = dims;
    super::grid::par_slabs(out, nx * ny, |z0, out| {
        let (mut east, mut west) = (vec![0.0f32; nx], vec![0.0f32; nx]);
        for zl in 0..out.len() / (nx * ny) {
            let z = z0 + zl;
            for y in 0..ny {
                let r = rows(dims, y, z);
                let c = &u[r.o..r.o + nx];
                east[..nx - 1].copy_from_slice(&c[1..]);
                east[nx - 1] = c[nx - 1];
                west[1..].copy_from_slice(&c[..nx - 1]);
                west[0] = c[0];
                let (e, w) = (&east[..nx], &west[..nx]);
                let (up, dn) = (&u[r.u..r.u + nx], &u[r.d..r.d + nx]);
                let (no, so) = (&u[r.n..r.n + nx], &u[r.s..r.s + nx]);
                let (bb, fx) = (&b[r.o..r.o + nx], &fixed[r.o..r.o + nx]);
                let dst = &mut out[zl * nx * ny + y * nx..zl * nx * ny + y * nx + nx];
                for x in 0..nx {
                    let v = c[x];
                    let acc = (e[x] - v)
                        + (w[x] - v)
                        + (up[x] - v)
                        + (dn[x] - v)
                        + (no[x] - v)
                        + (so[x] - v);
                    let nv = v + (acc + bb[x]) * (1.0 / 6.0);
                    dst[x] = if fx[x] != 0 { v } else { nv };
                }
            }
        }
    });
}

/// Residual `b − Σ_nb (u − u_nb)` at free samples, 0 at fixed ones.
fn residual(dims: [usize; 3], u: &[f32], b: &[f32], fixed: &[u8]) -> Vec<f32> {
    let [nx, ny, nz] = dims;
    let mut r = vec![0.0f32; u.len()];
    for z in 0..nz {
        for y in 0..ny {
            let rw = rows(dims, y, z);
            for x in 0..nx {
                let i = rw.o + x;
                if fixed[i] != 0 {
                    continue;
                }
                let v = u[i];
                let e = if x + 1 < nx { u[i + 1] } else { v };
                let w = if x > 0 { u[i - 1] } else { v };
                let lap = (e - v)
                    + (w - v)
                    + (u[rw.u + x] - v)
                    + (u[rw.d + x] - v)
                    + (u[rw.n + x] - v)
                    + (u[rw.s + x] - v);
                r[i] = b[i] + lap;
            }
        }
    }
    r
}

/// One multigrid V-cycle for `Σ_nb (u − u_nb) = b` at the free samples (cell-centred: mean
/// restriction of the residual, the operator rediscretised on the coarse grid — hence the
/// factor 4 — trilinear prolongation of the correction, two damped Jacobi sweeps before and
/// after). A coarse sample is fixed (zero correction) when any of its children is.
fn vcycle(dims: [usize; 3], u: &mut Vec<f32>, b: &[f32], fixed: &[u8], coarsest_sweeps: u32) {
    let n = u.len();
    let coarse = dims.map(|d| d.div_ceil(2));
    let mut tmp = vec![0.0f32; n];
    let mut smooth = |u: &mut Vec<f32>, k: u32| {
        for _ in 0..k {
            smooth_rhs(dims, u, b, fixed, &mut tmp);
            std::mem::swap(u, &mut tmp);
        }
    };
    if n <= COARSEST || coarse.iter().any(|&d| d < 2) {
        smooth(u, coarsest_sweeps);
        return;
    }
    smooth(u, 2);
    let r = residual(dims, u, b, fixed);
    let [nx, ny, nz] = dims;
    let [cx, cy, cz] = coarse;
    let cn = cx * cy * cz;
    let mut rc = vec![0.0f32; cn];
    let mut cnt = vec![0u8; cn];
    let mut cfixed = vec![0u8; cn];
    for z in 0..nz {
        for y in 0..ny {
            for x in 0..nx {
                let i = x + nx * (y + ny * z);
                let ci = x / 2 + cx * (y / 2 + cy * (z / 2));
                rc[ci] += r[i];
                cnt[ci] += 1;
                cfixed[ci] |= fixed[i];
            }
        }
    }
    for (v, c) in rc.iter_mut().zip(&cnt) {
        *v = 4.0 * *v / f32::from(*c);
    }
    let mut ec = vec![0.0f32; cn];
    vcycle(coarse, &mut ec, &rc, &cfixed, coarsest_sweeps);
    let corr = prolong(dims, coarse, &ec);
    for i in 0..n {
        if fixed[i] == 0 {
            u[i] += corr[i];
        }
    }
    smooth(u, 2);
}

/// Trilinear interpolation of a coarse grid (sample `X` at fine position `2X + ½`) onto `dims`.
fn prolong(dims: [usize; 3], coarse: [usize; 3], cc: &[f32]) -> Vec<f32> {
    let [nx, ny, nz] = dims;
    let [cx, cy, cz] = coarse;
    let axis = |nf: usize, nc: usize| -> Vec<(usize, usize, f32)> {
        (0..nf)
            .map(|i| {
                let f = (i as f32 * 0.5 - 0.25).clamp(0.0, (nc - 1) as f32);
                let i0 = (f.floor() as usize).min(nc - 1);
                let i1 = (i0 + 1).min(nc - 1);
                (i0, i1, f - i0 as f32)
            })
            .collect()
    };
    let (ax, ay, az) = (axis(nx, cx), axis(ny, cy), axis(nz, cz));
    let mut out = vec![0.0f32; nx * ny * nz];
    super::grid::par_slabs(&mut out, nx * ny, |zs, out| {
        for zl in 0..out.len() / (nx * ny) {
            let (z0, z1, wz) = az[zs + zl];
            for y in 0..ny {
                let (y0, y1, wy) = ay[y];
                let r00 = cx * (y0 + cy * z0);
                let r10 = cx * (y1 + cy * z0);
                let r01 = cx * (y0 + cy * z1);
                let r11 = cx * (y1 + cy * z1);
                let o = nx * (y + ny * zl);
                for x in 0..nx {
                    let (x0, x1, wx) = ax[x];
                    let lerp = |r: usize| cc[r + x0] + wx * (cc[r + x1] - cc[r + x0]);
                    let a = lerp(r00) + wy * (lerp(r10) - lerp(r00));
                    let b = lerp(r01) + wy * (lerp(r11) - lerp(r01));
                    out[o + x] = a + wz * (b - a);
                }
            }
        }
    });
    out
}
