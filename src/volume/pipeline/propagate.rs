//! Wavefront propagations: material with confidence (Becher §4.4) and the surface field `S`
//! (§4.5).
//!
//! Both grow outwards from a seed set one layer at a time: layer 0 is the seed set (`Ω_R`,
//! `Ω_S`), layer `L + 1` the unset samples with a neighbour in layer `L` — the paper's boundary
//! `∂Ω_S`, "set according to the following function and inserted into `Ω_S`". A sample of layer
//! `L` is computed only from its neighbours of layers `< L` and **set once**. [`layers`] is the
//! breadth-first search that orders the samples by layer. The propagations get the same layers
//! as the L1 distance to the seed set ([`l1_layers`]: on the full 6-connected grid the number of
//! breadth-first steps is the city-block distance, computed by separable passes). Since a value
//! depends only on the final values of its lower-layer neighbours, any visiting order in which
//! those come first yields the same bits; [`wavefront`] uses raster sweeps in the eight axis
//! directions, each setting the samples whose lower-layer neighbours are already final, then
//! finishes any rest in layer order. The sweeps stream through memory and need neither a
//! visiting order nor a neighbour-bit array (a layer-by-layer visit reads a thin shell across
//! the whole grid per layer); measured at 128 × 64 × 128 they cost about the same CPU time as
//! the counting-sorted layer order they replace (within 10 %), with less memory. On the GPU
//! (`shaders/volume_propagate.wgsl`) the same layers are produced by one dispatch per layer.
//!
//! **Surface propagation** (§4.5): with `NB` the six neighbours,
//!
//! `S_ijk = min_{x ∈ NB, layer(x) < layer(ijk)} ( S_x + ((i,j,k) − x) · (N_ijk + N_x)/2 )`
//!
//! positions in metres (the offset is ±`spacing` along one axis). `N` points out of the solid,
//! so `S` grows into the air and falls into the rock: `S < 0` inside.
//!
//! **Material propagation** (§4.4): a sample of layer `L` sums the confidence of its neighbours of
//! lower layers per material, takes the material with the largest sum (ties: the smaller id) and
//! that sum divided by the total as its confidence; seeds have confidence 1. Confidence is thus
//! in `(0, 1]`. Deviation: the paper re-averages confidences during every diffusion iteration; we
//! assign each sample once, in wavefront order, which is the same rule evaluated on the
//! neighbours that already hold a material, in O(n).

use super::grid::{par_slabs, Grid};
use super::voxelize::NO_MATERIAL;
use std::collections::VecDeque;

/// Layer of a sample no seed reaches (there are no seeds).
pub const UNREACHED: u32 = u32::MAX;

/// Breadth-first layers from the seed samples (`seeds[i] != 0`): the samples in visiting order
/// (non-decreasing layer) and each sample's layer.
pub fn layers(dims: [usize; 3], seeds: &[u8]) -> (Vec<u32>, Vec<u32>) {
    let [nx, ny, nz] = dims;
    let n = nx * ny * nz;
    let mut layer = vec![UNREACHED; n];
    let mut order = Vec::with_capacity(n);
    let mut queue = VecDeque::new();
    for (i, s) in seeds.iter().enumerate() {
        if *s != 0 {
            layer[i] = 0;
            queue.push_back(i as u32);
        }
    }
    while let Some(i) = queue.pop_front() {
        order.push(i);
        let i = i as usize;
        let l = layer[i] + 1;
        let (x, y, z) = (i % nx, (i / nx) % ny, i / (nx * ny));
        let mut visit = |j: usize| {
            if layer[j] == UNREACHED {
                layer[j] = l;
                queue.push_back(j as u32);
            }
        };
        if x + 1 < nx {
            visit(i + 1);
        }
        if x > 0 {
            visit(i - 1);
        }
        if y + 1 < ny {
            visit(i + nx);
        }
        if y > 0 {
            visit(i - nx);
        }
        if z + 1 < nz {
            visit(i + nx * ny);
        }
        if z > 0 {
            visit(i - nx * ny);
        }
    }
    (order, layer)
}

/// The six neighbours of sample `i` in the order E, W, U, D, N, S, each with its axis and the
/// sign of `(i − x)` along it; `None` outside the grid.
#[inline]
pub fn neighbours(dims: [usize; 3], i: usize) -> [Option<(usize, usize, f32)>; 6] {
    let [nx, ny, nz] = dims;
    let (x, y, z) = (i % nx, (i / nx) % ny, i / (nx * ny));
    [
        (x + 1 < nx).then(|| (i + 1, 0, -1.0)),
        (x > 0).then(|| (i - 1, 0, 1.0)),
        (y + 1 < ny).then(|| (i + nx, 1, -1.0)),
        (y > 0).then(|| (i - nx, 1, 1.0)),
        (z + 1 < nz).then(|| (i + nx * ny, 2, -1.0)),
        (z > 0).then(|| (i - nx * ny, 2, 1.0)),
    ]
}

/// The breadth-first layers of [`layers`] without a queue: on the full 6-connected grid the
/// number of steps from the nearest seed is the L1 (city-block) distance to the seed set, which
/// is separable into forward and backward `d = min(d, d_prev + 1)` passes along x, y and z.
/// [`UNREACHED`] everywhere when there are no seeds.
pub fn l1_layers(dims: [usize; 3], seeds: &[u8]) -> Vec<u32> {
    let [nx, ny, nz] = dims;
    let slice = nx * ny;
    let mut d: Vec<u32> = seeds
        .iter()
        .map(|&s| if s != 0 { 0 } else { UNREACHED })
        .collect();
    // Along x and y inside every z-slice, slabs in parallel (integer minima: the result does not
    // depend on the split).
    par_slabs(&mut d, slice, |_, slab| {
        for sl in slab.chunks_exact_mut(slice) {
            // Column by column across all rows of the slice: the rows are independent, so
            // consecutive updates do not wait on each other as a scan along one row does.
            for x in 1..nx {
                for y in 0..ny {
                    let i = y * nx + x;
                    sl[i] = sl[i].min(sl[i - 1].saturating_add(1));
                }
            }
            for x in (0..nx - 1).rev() {
                for y in 0..ny {
                    let i = y * nx + x;
                    sl[i] = sl[i].min(sl[i + 1].saturating_add(1));
                }
            }
            for y in 1..ny {
                let (lo, hi) = sl.split_at_mut(y * nx);
                min_plus_one(&mut hi[..nx], &lo[(y - 1) * nx..]);
            }
            for y in (0..ny - 1).rev() {
                let (lo, hi) = sl.split_at_mut((y + 1) * nx);
                min_plus_one(&mut lo[y * nx..], hi);
            }
        }
    });
    // Along z, slice against slice.
    for z in 1..nz {
        let (lo, hi) = d.split_at_mut(z * slice);
        min_plus_one(&mut hi[..slice], &lo[(z - 1) * slice..]);
    }
    for z in (0..nz - 1).rev() {
        let (lo, hi) = d.split_at_mut((z + 1) * slice);
        min_plus_one(&mut lo[z * slice..], hi);
    }
    d
}

/// `a = min(a, b + 1)` element-wise over `a`'s length, saturating at [`UNREACHED`].
#[inline]
fn min_plus_one(a: &mut [u32], b: &[u32]) {
    let b = &b[..a.len()];
    for (a, b) in a.iter_mut().zip(b) {
        *a = (*a).min(b.saturating_add(1));
    }
}

/// Sweep orders of [`wavefront`]: the direction (`true`: increasing) along x, y and z of each
/// raster sweep. A sample's lower-layer ancestors all lie on monotone paths towards the seeds
/// (every step of a dependency chain lowers the L1 distance by one, so a chain never turns back
/// along an axis), hence a sample whose ancestors lie in one octant is resolved by that octant's
/// sweep; the first orders cover the largest parts of typical scenes (ground below, sky above).
const SWEEPS: [[bool; 3]; 8] = [
    [true, true, true],
    [false, false, false],
    [false, true, true],
    [true, false, false],
    [true, false, true],
    [false, true, false],
    [true, true, false],
    [false, false, true],
];

/// The wavefront from the seeds: calls `set(i, t, bits, &state)` once for every reached non-seed
/// sample, when all its lower-layer neighbours are final, and returns the layers
/// ([`l1_layers`]). `state[j] = 2·layer(j) + pending(j)` and `t = 2·layer(i)`, so neighbour `j`
/// is of a lower layer iff `state[j] < t`; `bits` holds the neighbour-existence bits (bit `k`
/// set when neighbour `k` of [`neighbours`]' order E, W, U, D, N, S lies inside the grid).
///
/// Each value depends only on the final values of its lower-layer neighbours, so any order in
/// which those are final first gives the same bits as the breadth-first order of [`layers`]
/// (the paper's "set once" rule). The order used: the eight raster sweeps of [`SWEEPS`], which
/// stream through memory (rows without pending samples are skipped), then, for whatever is left
/// (nothing in the reference scenes), a pass over the remaining samples sorted by layer. Results
/// do not depend on the thread count (the pass is sequential).
fn wavefront(
    dims: [usize; 3],
    seeds: &[u8],
    mut set: impl FnMut(usize, u32, u8, &[u32]),
) -> Vec<u32> {
    let [nx, ny, nz] = dims;
    let mut state = l1_layers(dims, seeds);
    if state.first().is_none_or(|&l| l == UNREACHED) {
        // No seeds: nothing is reached.
        return state;
    }
    // Every sample is reached (the grid is connected): pending samples get an odd state.
    // Pending samples as one bit per sample, `words` 64-bit words per x-row: a sweep visits only
    // pending samples (no unpredictable branch per final one) and skips final rows.
    let words = nx.div_ceil(64);
    let mut pending = vec![0u64; ny * nz * words];
    for (row, p) in state
        .chunks_exact_mut(nx)
        .zip(pending.chunks_exact_mut(words))
    {
        for (chunk, word) in row.chunks_mut(64).zip(p.iter_mut()) {
            let mut bits = 0u64;
            for (b, l) in chunk.iter_mut().enumerate() {
                let bit = u32::from(*l > 0);
                *l = 2 * *l + bit;
                bits |= u64::from(bit) << b;
            }
            *word = bits;
        }
    }
    let dir = |k: usize, m: usize, up: bool| if up { k } else { m - 1 - k };
    for order in SWEEPS {
        for zk in 0..nz {
            let z = dir(zk, nz, order[2]);
            for yk in 0..ny {
                let y = dir(yk, ny, order[1]);
                let r = y + ny * z;
                let row_pending = &mut pending[r * words..(r + 1) * words];
                if row_pending.iter().all(|&w| w == 0) {
                    continue;
                }
                let row_bits = u8::from(y + 1 < ny) << 2
                    | u8::from(y > 0) << 3
                    | u8::from(z + 1 < nz) << 4
                    | u8::from(z > 0) << 5;
                // Offsets of the row's neighbours; an absent neighbour is the sample itself,
                // whose pending state never equals a lower layer's.
                let up = if y + 1 < ny { nx } else { 0 };
                let down = if y > 0 { nx } else { 0 };
                let north = if z + 1 < nz { nx * ny } else { 0 };
                let south = if z > 0 { nx * ny } else { 0 };
                let o = nx * r;
                for wk in 0..words {
                    let w = dir(wk, words, order[0]);
                    let mut m = row_pending[w];
                    let mut done = 0u64;
                    while m != 0 {
                        // The next pending sample in the sweep's x direction.
                        let b = if order[0] {
                            m.trailing_zeros()
                        } else {
                            63 - m.leading_zeros()
                        };
                        m &= !(1u64 << b);
                        let x = 64 * w + b as usize;
                        let i = o + x;
                        // A lower-layer neighbour is of layer `layer(i) − 1`: state `t − 2`
                        // when final, `t − 1` while pending.
                        let t = state[i] - 1;
                        let east = usize::from(x + 1 < nx);
                        let west = usize::from(x > 0);
                        let waiting = (state[i + east] == t - 1)
                            | (state[i - west] == t - 1)
                            | (state[i + up] == t - 1)
                            | (state[i - down] == t - 1)
                            | (state[i + north] == t - 1)
                            | (state[i - south] == t - 1);
                        if waiting {
                            continue;
                        }
                        let bits = row_bits | u8::from(x + 1 < nx) | u8::from(x > 0) << 1;
                        set(i, t, bits, &state);
                        state[i] = t;
                        done |= 1u64 << b;
                    }
                    row_pending[w] &= !done;
                }
            }
        }
    }
    // Whatever the sweeps left, in order of layer: every lower layer is final by then.
    let mut rest: Vec<(u32, u32)> = Vec::new();
    for (r, p) in pending.chunks_exact(words).enumerate() {
        for (w, &bits) in p.iter().enumerate() {
            let mut m = bits;
            while m != 0 {
                let b = m.trailing_zeros() as usize;
                m &= m - 1;
                let i = r * nx + 64 * w + b;
                rest.push((state[i], i as u32));
            }
        }
    }
    rest.sort_unstable();
    for (s, i) in rest {
        let i = i as usize;
        let c = grid_coords(dims, i);
        let bits = u8::from(c[0] + 1 < nx)
            | u8::from(c[0] > 0) << 1
            | u8::from(c[1] + 1 < ny) << 2
            | u8::from(c[1] > 0) << 3
            | u8::from(c[2] + 1 < nz) << 4
            | u8::from(c[2] > 0) << 5;
        set(i, s - 1, bits, &state);
        state[i] = s - 1;
    }
    for s in &mut state {
        *s >>= 1;
    }
    state
}

/// `(x, y, z)` of index `i` in a grid of `dims`.
#[inline]
fn grid_coords(dims: [usize; 3], i: usize) -> [usize; 3] {
    [
        i % dims[0],
        (i / dims[0]) % dims[1],
        i / (dims[0] * dims[1]),
    ]
}

/// Surface propagation (§4.5) in place: `s` holds the seed values in `Ω_S` (`omega_s != 0`);
/// every other reachable sample is set once by the min rule, in one breadth-first pass. Returns
/// the layers (for tests and the GPU twin). Samples no seed reaches keep their value.
pub fn propagate_surface(
    grid: &Grid,
    normal: &[Vec<f32>],
    omega_s: &[u8],
    s: &mut [f32],
) -> Vec<u32> {
    let dims = grid.dims;
    let [nx, ny, _] = dims;
    let h = grid.spacing;
    let (n0, n1, n2) = (&normal[0], &normal[1], &normal[2]);
    wavefront(dims, omega_s, |i, t, b, state| {
        let mut best = f32::INFINITY;
        // E, W, U, D, N, S with the sign of (i − x) along the axis, as `neighbours`.
        let mut take = |j: usize, nc: &[f32], sign: f32| {
            if state[j] < t {
                let v = s[j] + (sign * h) * ((nc[i] + nc[j]) * 0.5);
                best = best.min(v);
            }
        };
        if b & 1 != 0 {
            take(i + 1, n0, -1.0);
        }
        if b & 2 != 0 {
            take(i - 1, n0, 1.0);
        }
        if b & 4 != 0 {
            take(i + nx, n1, -1.0);
        }
        if b & 8 != 0 {
            take(i - nx, n1, 1.0);
        }
        if b & 16 != 0 {
            take(i + nx * ny, n2, -1.0);
        }
        if b & 32 != 0 {
            take(i - nx * ny, n2, 1.0);
        }
        s[i] = best;
    })
}

/// Material propagation with confidence (§4.4) in place: `material` holds the seeds' materials
/// in `Ω_R` (`omega_r != 0`); returns the confidence of every sample (1 in `Ω_R`, 0 where no
/// material arrives). One breadth-first pass.
pub fn propagate_material(dims: [usize; 3], omega_r: &[u8], material: &mut [u16]) -> Vec<f32> {
    let mut conf: Vec<f32> = omega_r
        .iter()
        .map(|&o| if o != 0 { 1.0 } else { 0.0 })
        .collect();
    let [nx, ny, _] = dims;
    let offsets = [
        1isize,
        -1,
        nx as isize,
        -(nx as isize),
        (nx * ny) as isize,
        -((nx * ny) as isize),
    ];
    wavefront(dims, omega_r, |i, t, bits, state| {
        // The lower-layer neighbours that hold a material, in the order E, W, U, D, N, S; an
        // absent one votes weight 0 for no material, which changes no sum below.
        let mut m = [NO_MATERIAL; 6];
        let mut c = [0.0f32; 6];
        for (k, off) in offsets.iter().enumerate() {
            if bits & (1 << k) != 0 {
                let j = i.wrapping_add_signed(*off);
                if state[j] < t && material[j] != NO_MATERIAL {
                    m[k] = material[j];
                    c[k] = conf[j];
                }
            }
        }
        let total = ((((c[0] + c[1]) + c[2]) + c[3]) + c[4]) + c[5];
        if total > 0.0 {
            let first = m.iter().copied().find(|&k| k != NO_MATERIAL);
            let first = first.unwrap_or(NO_MATERIAL);
            if m.iter().all(|&k| k == NO_MATERIAL || k == first) {
                // One material (the common case): its sum, accumulated as below, wins.
                let mut w = 0.0f32;
                for q in 0..6 {
                    if m[q] == first {
                        w += c[q];
                    }
                }
                material[i] = first;
                conf[i] = (w / total).clamp(0.0, 1.0);
                return;
            }
            // Each material's summed confidence (in neighbour order), the largest sum winning
            // and ties going to the smaller id.
            let mut best = (NO_MATERIAL, -1.0f32);
            for k in 0..6 {
                if m[k] != NO_MATERIAL {
                    let mut w = 0.0f32;
                    for q in 0..6 {
                        if m[q] == m[k] {
                            w += c[q];
                        }
                    }
                    if w > best.1 || (w == best.1 && m[k] < best.0) {
                        best = (m[k], w);
                    }
                }
            }
            material[i] = best.0;
            conf[i] = (best.1 / total).clamp(0.0, 1.0);
        }
    });
    conf
}
