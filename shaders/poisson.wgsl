// WGSL twin of the multigrid kernels of `terrain::poisson::ops` (issue 4): red-black
// Gauss–Seidel half-sweeps, the residual, full-weighting restriction, bilinear prolongation, and
// zeroing a level's unknowns. The host driver is `gpu::poisson`.
//
// Storage follows the CPU's colour-split layout (`terrain::poisson::grid`): each per-sample field
// of a level is one array of 2·len values, colour c (0 red, 1 black) at offset c·len; row j of a
// colour holds `stride = (nx + 1) / 2` slots, slot k being column i = 2k + s with
// s = (c + j) mod 2. The arithmetic is the CPU's, in the same order, in f32 (the CPU stores f64):
//   smoother   h ← (((l + r) + u) + d − b) · 0.25 at free samples of one colour;
//   residual   r = b − ((((l + r) + u) + d) − 4 h) at free samples, 0 elsewhere;
//   restrict   b_c = (4 r_c + 2 ((r_w + r_e) + (r_n + r_s)) + ((o r_nw + o r_ne) + (o r_sw + o r_se)))
//              · 0.25 at free coarse samples, 0 elsewhere;
//   prolong    h += coarse value / mean of 2 / ((o a + o b) + (o c + o d)) · 0.25 at free fine samples;
// where o is 1, or 0 for a corner whose two connecting fine samples are both fixed.
// Coarse levels carry a Galerkin 9-point operator (`terrain::poisson::galerkin`): one default 3×3
// stencil and a list of samples with their own stencil. With
//   Σ = ((s_w w + s_e e) + (s_u u + s_d d)) + ((s_uw uw + s_ue ue) + (s_dw dw + s_de de))
// (u the row above), the 9-point smoother is h ← (b − Σ) · (1 / s_c) over one of four colours
// (colour array c, row parity p), and the 9-point residual r = b − (Σ + s_c h). A first dispatch
// applies the default stencil to every sample of the colour, a second one the special stencils
// (each reads only samples of other colours, so the order within the colour does not matter).
//
// `PoissonParams` is `gpu::poisson::GpuPoissonParams` on the CPU, field for field.

struct PoissonParams {
    // This level: samples per side, slots per colour row, values per colour array.
    nx: u32,
    nz: u32,
    stride: u32,
    len: u32,
    // The next coarser level (zeros for the coarsest level).
    cnx: u32,
    cnz: u32,
    cstride: u32,
    clen: u32,
}

const WORKGROUP: u32 = 64u;

@group(0) @binding(0) var<uniform> p: PoissonParams;
// This level: unknowns, right-hand side, free mask (1 free, 0 fixed or padding), residual.
@group(0) @binding(1) var<storage, read_write> h: array<f32>;
@group(0) @binding(2) var<storage, read_write> rhs: array<f32>;
@group(0) @binding(3) var<storage, read> free_mask: array<u32>;
@group(0) @binding(4) var<storage, read_write> res: array<f32>;
// The next coarser level: unknowns, right-hand side, free mask.
@group(0) @binding(5) var<storage, read_write> hc: array<f32>;
@group(0) @binding(6) var<storage, read_write> rhsc: array<f32>;
@group(0) @binding(7) var<storage, read> cfree: array<u32>;
// This level's 9-point operator (coarse levels; a dummy on the finest): words 0..9 the default
// stencil (f32 bits, entry (dx, dz) at (dz + 1) · 3 + dx + 1), word 9 its inverse centre; then 11
// words per special sample: its index into the two-colour arrays (c · len + j · stride + k), its
// stencil, its inverse centre.
@group(0) @binding(8) var<storage, read> stencils: array<u32>;

const SPECIAL_BASE: u32 = 10u;
const SPECIAL_WORDS: u32 = 11u;

// Index of this level's slot k of colour c in row j.
fn slot(c: u32, j: u32, k: u32) -> u32 {
    return c * p.len + j * p.stride + k;
}

// True if slot k of colour c in row j is an interior sample of this level.
fn interior(c: u32, j: u32, k: u32) -> bool {
    let s = (c + j) & 1u;
    return j > 0u && j + 1u < p.nz && k + s >= 1u && k < p.nx / 2u;
}

// Residual of this level at natural sample (i, j) (zero on the border).
fn res_at(i: u32, j: u32) -> f32 {
    return res[((i + j) & 1u) * p.len + j * p.stride + i / 2u];
}

// True if this level's natural sample (i, j) is free.
fn free_at(i: u32, j: u32) -> bool {
    return free_mask[((i + j) & 1u) * p.len + j * p.stride + i / 2u] != 0u;
}

// Weight factor of a corner between an odd-odd fine sample and a coarse counterpart: 1 if one
// of the two samples connecting them, (i1, j1) and (i2, j2), is free, else 0 (the corner lies
// across a constraint).
fn open(i1: u32, j1: u32, i2: u32, j2: u32) -> f32 {
    return select(0.0, 1.0, free_at(i1, j1) || free_at(i2, j2));
}

// Coarse unknown at natural sample (i, j).
fn hc_at(i: u32, j: u32) -> f32 {
    return hc[((i + j) & 1u) * p.clen + j * p.cstride + i / 2u];
}

fn smooth_at(c: u32, k: u32, j: u32) {
    if (k >= p.stride || !interior(c, j, k)) {
        return;
    }
    let x = slot(c, j, k);
    if (free_mask[x] == 0u) {
        return;
    }
    let s = (c + j) & 1u;
    let y = (1u - c) * p.len + j * p.stride;
    let l = h[y + k + s - 1u];
    let r = h[y + k + s];
    let u = h[y - p.stride + k];
    let d = h[y + p.stride + k];
    h[x] = (l + r + u + d - rhs[x]) * 0.25;
}

// Half-sweep over the red samples: one invocation per slot (x) and row (y).
@compute @workgroup_size(64)
fn smooth_red(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_at(0u, id.x, id.y);
}

// Half-sweep over the black samples.
@compute @workgroup_size(64)
fn smooth_black(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_at(1u, id.x, id.y);
}

// Residual of both colours of slot (x) in row (y).
@compute @workgroup_size(64)
fn residual(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    let j = id.y;
    if (k >= p.stride || j >= p.nz) {
        return;
    }
    for (var c = 0u; c < 2u; c++) {
        let x = slot(c, j, k);
        var v = 0.0;
        if (interior(c, j, k) && free_mask[x] != 0u) {
            let s = (c + j) & 1u;
            let y = (1u - c) * p.len + j * p.stride;
            let l = h[y + k + s - 1u];
            let r = h[y + k + s];
            let u = h[y - p.stride + k];
            let d = h[y + p.stride + k];
            v = rhs[x] - (l + r + u + d - 4.0 * h[x]);
        }
        res[x] = v;
    }
}

// Full weighting of this level's residual into the coarse right-hand side: one invocation per
// coarse sample (x = column, y = row).
@compute @workgroup_size(64)
fn restrict_residual(@builtin(global_invocation_id) id: vec3<u32>) {
    let ic = id.x;
    let jc = id.y;
    if (ic >= p.cnx || jc >= p.cnz) {
        return;
    }
    let x = ((ic + jc) & 1u) * p.clen + jc * p.cstride + ic / 2u;
    if (cfree[x] == 0u) {
        rhsc[x] = 0.0;
        return;
    }
    // Free coarse samples are interior, so every fine index below is in range.
    let i = 2u * ic;
    let j = 2u * jc;
    let edges = (res_at(i - 1u, j) + res_at(i + 1u, j)) + (res_at(i, j - 1u) + res_at(i, j + 1u));
    let corners = (open(i - 1u, j, i, j - 1u) * res_at(i - 1u, j - 1u)
        + open(i + 1u, j, i, j - 1u) * res_at(i + 1u, j - 1u))
        + (open(i - 1u, j, i, j + 1u) * res_at(i - 1u, j + 1u)
        + open(i + 1u, j, i, j + 1u) * res_at(i + 1u, j + 1u));
    rhsc[x] = (4.0 * res_at(i, j) + 2.0 * edges + corners) * 0.25;
}

// Bilinear prolongation of the coarse unknowns, added to this level's free samples: one
// invocation per slot (x) and row (y), both colours.
@compute @workgroup_size(64)
fn prolong(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    let j = id.y;
    if (k >= p.stride || j >= p.nz) {
        return;
    }
    for (var c = 0u; c < 2u; c++) {
        let x = slot(c, j, k);
        if (!interior(c, j, k) || free_mask[x] == 0u) {
            continue;
        }
        let i = 2u * k + ((c + j) & 1u);
        let ic = i / 2u;
        let jc = j / 2u;
        var e: f32;
        if (j % 2u == 0u) {
            if (i % 2u == 0u) {
                e = hc_at(ic, jc);
            } else {
                e = (hc_at(ic, jc) + hc_at(ic + 1u, jc)) * 0.5;
            }
        } else {
            if (i % 2u == 0u) {
                e = (hc_at(ic, jc) + hc_at(ic, jc + 1u)) * 0.5;
            } else {
                e = ((open(i - 1u, j, i, j - 1u) * hc_at(ic, jc)
                    + open(i + 1u, j, i, j - 1u) * hc_at(ic + 1u, jc))
                    + (open(i - 1u, j, i, j + 1u) * hc_at(ic, jc + 1u)
                    + open(i + 1u, j, i, j + 1u) * hc_at(ic + 1u, jc + 1u))) * 0.25;
            }
        }
        h[x] = h[x] + e;
    }
}

// Sets this level's unknowns (both colours, fixed samples included) to zero: the start of a
// correction cycle.
@compute @workgroup_size(64)
fn zero_h(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    let j = id.y;
    if (k >= p.stride || j >= p.nz) {
        return;
    }
    h[slot(0u, j, k)] = 0.0;
    h[slot(1u, j, k)] = 0.0;
}

// Stencil entry e of the stencil starting at word `base`.
fn st(base: u32, e: u32) -> f32 {
    return bitcast<f32>(stencils[base + e]);
}

// Σ of the off-centre terms of the stencil at word `base`, for slot k of colour c in row j.
fn nine_sum(base: u32, c: u32, j: u32, k: u32) -> f32 {
    let s = (c + j) & 1u;
    let y = (1u - c) * p.len + j * p.stride;
    let xu = c * p.len + (j - 1u) * p.stride;
    let xd = c * p.len + (j + 1u) * p.stride;
    let w = h[y + k + s - 1u];
    let e = h[y + k + s];
    let u = h[y - p.stride + k];
    let d = h[y + p.stride + k];
    let uw = h[xu + k + s - 1u];
    let ue = h[xu + k + s];
    let dw = h[xd + k + s - 1u];
    let de = h[xd + k + s];
    return ((st(base, 3u) * w + st(base, 5u) * e) + (st(base, 1u) * u + st(base, 7u) * d))
        + ((st(base, 0u) * uw + st(base, 2u) * ue) + (st(base, 6u) * dw + st(base, 8u) * de));
}

// Default-stencil update of slot k of colour c in row j = 2m + parity.
fn smooth_nine_at(c: u32, parity: u32, k: u32, m: u32) {
    let j = 2u * m + parity;
    if (k >= p.stride || j >= p.nz || !interior(c, j, k)) {
        return;
    }
    let x = slot(c, j, k);
    if (free_mask[x] == 0u) {
        return;
    }
    h[x] = (rhs[x] - nine_sum(0u, c, j, k)) * st(0u, 9u);
}

// Special-stencil update of special sample `n` if it has colour c and row parity `parity`.
fn smooth_special_at(c: u32, parity: u32, n: u32) {
    let base = SPECIAL_BASE + n * SPECIAL_WORDS;
    if (base + SPECIAL_WORDS > arrayLength(&stencils)) {
        return;
    }
    let x = stencils[base];
    let cc = x / p.len;
    let j = (x % p.len) / p.stride;
    if (cc != c || (j & 1u) != parity) {
        return;
    }
    let k = (x % p.len) % p.stride;
    h[x] = (rhs[x] - nine_sum(base + 1u, c, j, k)) * st(base + 1u, 9u);
}

// The four colours of the 9-point smoother: one invocation per slot (x) and row pair (y).
@compute @workgroup_size(64)
fn smooth_nine_00(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_nine_at(0u, 0u, id.x, id.y);
}

@compute @workgroup_size(64)
fn smooth_nine_01(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_nine_at(0u, 1u, id.x, id.y);
}

@compute @workgroup_size(64)
fn smooth_nine_10(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_nine_at(1u, 0u, id.x, id.y);
}

@compute @workgroup_size(64)
fn smooth_nine_11(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_nine_at(1u, 1u, id.x, id.y);
}

// The special samples of each colour: one invocation per special sample (x).
@compute @workgroup_size(64)
fn smooth_special_00(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_special_at(0u, 0u, id.x);
}

@compute @workgroup_size(64)
fn smooth_special_01(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_special_at(0u, 1u, id.x);
}

@compute @workgroup_size(64)
fn smooth_special_10(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_special_at(1u, 0u, id.x);
}

@compute @workgroup_size(64)
fn smooth_special_11(@builtin(global_invocation_id) id: vec3<u32>) {
    smooth_special_at(1u, 1u, id.x);
}

// 9-point residual of both colours of slot (x) in row (y), default stencil.
@compute @workgroup_size(64)
fn residual_nine(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    let j = id.y;
    if (k >= p.stride || j >= p.nz) {
        return;
    }
    for (var c = 0u; c < 2u; c++) {
        let x = slot(c, j, k);
        var v = 0.0;
        if (interior(c, j, k) && free_mask[x] != 0u) {
            v = rhs[x] - (nine_sum(0u, c, j, k) + st(0u, 4u) * h[x]);
        }
        res[x] = v;
    }
}

// 9-point residual of special sample (x), overwriting the default one.
@compute @workgroup_size(64)
fn residual_special(@builtin(global_invocation_id) id: vec3<u32>) {
    let base = SPECIAL_BASE + id.x * SPECIAL_WORDS;
    if (base + SPECIAL_WORDS > arrayLength(&stencils)) {
        return;
    }
    let x = stencils[base];
    let c = x / p.len;
    let j = (x % p.len) / p.stride;
    let k = (x % p.len) % p.stride;
    res[x] = rhs[x] - (nine_sum(base + 1u, c, j, k) + st(base + 1u, 4u) * h[x]);
}
