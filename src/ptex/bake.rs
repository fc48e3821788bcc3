//! The §4.7 bake of a face's texels (the CPU reference of `shaders/ptex.wgsl`).
//!
//! For texel `(i, j)` of a face at resolution `res` (centre `uv = ((i + ½)/res, (j + ½)/res)`):
//!
//! 1. **Interpolation.** Bilinear in the face's control grid: position `p`, normal `n`
//!    (normalised; `+Y` when it vanishes), noise amplitude `a`, and the weight of each material
//!    id among the four surrounding samples (equal ids merged, in corner order `00, 10, 01, 11`).
//!    Where the set has texel inputs ([`FaceSet::surface`]: height tiles of worlds with
//!    `texturing.ptex_blend: 2`) the materials come from the inputs instead: their bilinear mix
//!    (height above the sea and above the snow line, ground shares) and `n_y` go through the
//!    proto-texturing thresholds ([`texel_weights`]), and the texel keeps the materials of
//!    weight at least [`MIN_SURFACE_WEIGHT`], at most four, divided by their sum
//!    ([`surface_slots`]). So a material's border runs where the thresholds cross at the
//!    texel's own place (a contour of the snow line, a slope break) rather than along the
//!    vertex lattice, whose one-hot materials blend in steps a vertex spacing wide.
//! 2. **Octave cut.** A texel is `τ = size_m/res` metres; octaves of frequency above `1/(2τ)`
//!    are left out (the finest is `kmax = ⌊log2(1/(2τ))⌋`), so a coarse page is the filtered
//!    version of a fine one rather than its alias.
//! 3. **Displacement** `D(q) = a·fbm3(q) + Σₘ bₘ Σ_axis w_axis(n)·reliefₘ(q)`: the world-space
//!    noise of the [`MaterialSet`] plus the materials' relief, projected tri-planarly with the
//!    weights `w_axis = n_axis⁴ / Σ n⁴` of the interpolated normal.
//! 4. **Displaced normal.** With the tangent frame `t₁ = normalize(h × n)`, `t₂ = n × t₁` (`h` =
//!    `+Y`, or `+X` where `|n_y| ≥ 0.9`) and the step `δ = τ/2`: `n' = normalize(n − g₁t₁ −
//!    g₂t₂)`, `gₖ = (D(p + δtₖ) − D(p))/δ`.
//! 5. **Tri-planar blend** with the displaced normal's weights `w(n')`: albedo and roughness of
//!    each material's pattern on the three projection planes (X: `(y, z)`, Y: `(z, x)`, Z:
//!    `(x, y)`), weighted by `bₘ·w_axis(n')`. A material with a normal map tilts `n'` by the
//!    map's normal on each plane with the same weights (`normal_maps`: a whiteout blend per
//!    plane), so the written normal is `n''`; without normal maps `n'' = n'`.
//!    An image material ([`super::material::Texture`]) reads its albedo, and the `t` of its
//!    roughness and relief where it has those images, from its images tiled on the plane
//!    (coordinates times `2^−repeat_log2`, wrapped; bilinear at mip level `side_log2 −
//!    repeat_log2 − (kmax + 1)`, so an image pixel is no smaller than a texel).
//! 6. **Decals** ([`super::decal`]), top-down, in order, over the blended albedo and roughness.
//! 7. **Quantisation**: `⌊255·clamp(x, 0, 1) + ½⌋` for albedo and roughness, `⌊127·clamp(n, −1,
//!    1) + ½⌋` as a signed byte for the normal, the dominant material id (largest `bₘ`, the
//!    lower id on a tie), `D(p)` as `f32` metres.
//!
//! Every input is an `f32` function of the face; no state, no order dependence: the same face
//! gives the same bytes in any set, on any thread.
//!
//! The bake takes a row's texels (and the texels a border reads from a neighbour) [`LANES`] at
//! a time (`texels_lanes`): each lane goes through [`texel`]'s `f32` operations in the same
//! order (Rust neither contracts nor reorders them), so the grouping changes no bit, and the
//! compiler runs the lanes side by side in vector registers. A lattice cell every lane lies in
//! is hashed once (and kept per octave for the next lanes); a group holding an image material
//! takes its relief and blend texel by texel.

use super::border::fill_borders;
use super::decal::{apply as apply_decals, Spot};
use super::face::{Face, FaceSet};
use super::image::mip_level;
use super::material::{MaterialSet, Texture};
use super::noise::{
    exp2i, fbm2_in, fbm2_lanes, fbm3_in, fbm3_lanes, octave_count, Cell2, Cell3, Lanes, LANES,
    MAX_FREQ_LOG2, MAX_OCTAVES, MIN_FREQ_LOG2,
};
use super::pages::Pages;
use crate::terrain::texture::{texel_weights, TexelRule, SURFACE_INPUTS};
use crate::terrain::world::MATERIALS;
use rayon::prelude::*;

/// Bakes every face of `set` at `res` into `out` (interiors, then borders), keeping only the
/// set's output faces.
pub fn bake(set: &FaceSet, mats: &MaterialSet, res: u32, out: &mut Pages) {
    bake_interior(set, mats, res, out);
    fill_borders(set, out);
    out.truncate(set.output);
}

/// Bakes the interior texels of every face of `set` at `res` into `out` (reset to the set's
/// faces; borders left zero). The rows of all faces are shared among the cores (a set of one
/// large face still uses them all), each worker reading the noise through its own
/// [`NoiseCache`].
pub fn bake_interior(set: &FaceSet, mats: &MaterialSet, res: u32, out: &mut Pages) {
    out.reset(res, set.faces.len());
    let faces: Vec<usize> = (0..set.faces.len()).collect();
    bake_rows(set, mats, res, &faces, out);
}

/// Bakes the interior rows of faces `chosen` of `set` at `res` into `out` (face `k` of `out`
/// being `chosen[k]`; `out` already reset to `chosen.len()` faces), rows in parallel.
pub(crate) fn bake_rows(
    set: &FaceSet,
    mats: &MaterialSet,
    res: u32,
    chosen: &[usize],
    out: &mut Pages,
) {
    let side = out.side();
    let r = res as usize;
    let constants: Vec<(i32, f32)> = chosen
        .iter()
        .map(|&f| face_constants(&set.faces[f], res))
        .collect();
    out.albedo
        .par_chunks_mut(side)
        .zip(out.normal.par_chunks_mut(side))
        .zip(out.displacement.par_chunks_mut(side))
        .enumerate()
        .for_each_init(
            || NoiseCache::new(mats),
            |cache, (row, ((alb, nrm), disp))| {
                let (k, y) = (row / side, row % side);
                if y == 0 || y > r {
                    return;
                }
                let (f, j) = (chosen[k], (y - 1) as u32);
                // The row in runs of [`LANES`] texels, a short last run repeating its last
                // texel in the spare lanes.
                for i in (0..r).step_by(LANES) {
                    let ij = std::array::from_fn(|l| ((i + l).min(r - 1) as u32, j));
                    let texels = texels_lanes(set, mats, f, res, constants[k], ij, cache);
                    for (l, t) in texels.iter().enumerate().take(r - i) {
                        alb[i + l + 1] = t.albedo;
                        nrm[i + l + 1] = t.normal;
                        disp[i + l + 1] = t.displacement;
                    }
                }
            },
        );
}

/// The lattice cells a worker's texels read last, per octave: of the displacement noise and of
/// each material's pattern on each plane, apart for each of a texel's three points `p`,
/// `p + δt₁`, `p + δt₂` (so each point's walk along a row keeps its cells). Any texel of any
/// face may go through any cache: it only spares hashes (see [`Cell3`]), the bits are those
/// of the noise without it.
#[derive(Clone, Debug)]
pub struct NoiseCache {
    d3: [[Cell3; MAX_OCTAVES]; 3],
    /// Octaves kept per material, plane and point.
    stride: usize,
    /// `[point][material][plane][octave]`.
    d2: Vec<Cell2>,
    materials: usize,
    /// The patterns of the lanes of [`texels_lanes`], `[material][point][plane]`.
    lanes: Vec<[[Lanes; 3]; 3]>,
}

impl NoiseCache {
    /// An empty cache for the materials of `mats`, keeping as many octaves of each pattern as
    /// the material with the most has.
    pub fn new(mats: &MaterialSet) -> Self {
        let stride = mats
            .materials
            .iter()
            .map(|m| m.octaves as usize)
            .max()
            .unwrap_or(0)
            .min(MAX_OCTAVES);
        let materials = mats.materials.len();
        Self {
            d3: [[Cell3::EMPTY; MAX_OCTAVES]; 3],
            stride,
            d2: vec![Cell2::EMPTY; 3 * materials * 3 * stride],
            materials,
            lanes: vec![[[[0.0; LANES]; 3]; 3]; materials],
        }
    }

    /// The cells of material `m`'s pattern on plane `axis` at point `point` (empty past the
    /// materials the cache was made for).
    fn pattern(&mut self, point: usize, m: usize, axis: usize) -> &mut [Cell2] {
        if m >= self.materials {
            return &mut [];
        }
        let at = ((point * self.materials + m) * 3 + axis) * self.stride;
        &mut self.d2[at..at + self.stride]
    }
}

/// One baked texel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texel {
    /// Albedo and roughness bytes.
    pub albedo: [u8; 4],
    /// Normal bytes and dominant material.
    pub normal: [u8; 4],
    /// Displacement, metres.
    pub displacement: f32,
}

/// The finest octave exponent for a texel of `texel_m` metres: the largest `k` with
/// `2^k·texel_m ≤ ½` (at most [`MAX_FREQ_LOG2`], at least `MIN_FREQ_LOG2 − 1`).
pub fn finest_octave(texel_m: f32) -> i32 {
    let mut k = MAX_FREQ_LOG2;
    while k >= MIN_FREQ_LOG2 && exp2i(k) * texel_m > 0.5 {
        k -= 1;
    }
    k
}

/// The per-face constants of a bake at `res`: `(kmax, δ)`.
pub fn face_constants(face: &Face, res: u32) -> (i32, f32) {
    let texel_m = face.size_m / res as f32;
    (finest_octave(texel_m), texel_m * 0.5)
}

fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v/|v|`, or `fallback` when `|v|²` is below `1e-20`.
fn normalize_or(v: [f32; 3], fallback: [f32; 3]) -> [f32; 3] {
    let l2 = dot(v, v);
    if l2 < 1e-20 {
        return fallback;
    }
    let inv = 1.0 / l2.sqrt();
    v.map(|c| c * inv)
}

/// Tri-planar weights `n_a⁴ / Σ n⁴`.
fn triplanar(n: [f32; 3]) -> [f32; 3] {
    let a = n.map(|c| {
        let c2 = c * c;
        c2 * c2
    });
    let s = a[0] + a[1] + a[2];
    let inv = 1.0 / s;
    a.map(|c| c * inv)
}

/// The projection plane `axis` of a point: `(y, z)`, `(z, x)`, `(x, y)`.
fn plane<T: Copy>(v: [T; 3], axis: usize) -> [T; 2] {
    [v[(axis + 1) % 3], v[(axis + 2) % 3]]
}

/// The image sample of material `m`'s image `img` at `q` on plane `axis`: the plane's
/// coordinates times `2^−repeat_log2`, wrapped to `[0, 1)`, at the mip level for `kmax`.
fn image_sample(
    mats: &MaterialSet,
    img: u32,
    repeat_log2: i32,
    q: [f32; 3],
    axis: usize,
    kmax: i32,
) -> [f32; 4] {
    let image = &mats.images[img as usize];
    let scale = exp2i(-repeat_log2);
    let [a, b] = plane(q, axis).map(|c| {
        let x = c * scale;
        x - x.floor()
    });
    let level = mip_level(image.side_log2() - repeat_log2, kmax, image.levels.len());
    image.sample(level, a, b, true)
}

/// The relief `t ∈ [0, 1]` of material `m` at `q` on plane `axis`: its height image's R channel,
/// or its pattern.
fn relief_t(
    mats: &MaterialSet,
    m: usize,
    anchor: [i32; 3],
    q: [f32; 3],
    axis: usize,
    kmax: i32,
    cells: &mut [Cell2],
) -> f32 {
    match mats.materials[m].texture {
        Some(Texture {
            height: Some(h),
            repeat_log2,
            ..
        }) => image_sample(mats, h, repeat_log2, q, axis, kmax)[0],
        _ => pattern(mats, m, anchor, q, axis, kmax, cells),
    }
}

/// The pattern `t ∈ [0, 1]` of material `m` at `q` on plane `axis`, its octaves through
/// `cells`.
fn pattern(
    mats: &MaterialSet,
    m: usize,
    anchor: [i32; 3],
    q: [f32; 3],
    axis: usize,
    kmax: i32,
    cells: &mut [Cell2],
) -> f32 {
    let mat = &mats.materials[m];
    let count = octave_count(mat.freq_log2, mat.octaves, kmax);
    let seed = mats.seeds[m].wrapping_add(256 * axis as u32);
    let v = fbm2_in(
        cells,
        plane(anchor, axis),
        plane(q, axis),
        mat.freq_log2,
        count,
        seed,
    );
    (0.5 + 0.5 * v).clamp(0.0, 1.0)
}

/// Step 1 at texel `(i, j)` of face `f` at resolution `res`: the materials the texel blends, as
/// indices into `mats` with their weights (merged, at most four, in the order the later steps
/// sum them).
pub fn texel_materials(
    set: &FaceSet,
    mats: &MaterialSet,
    f: usize,
    res: u32,
    i: u32,
    j: u32,
) -> Vec<(usize, f32)> {
    let r = res as f32;
    let pt = interpolate(
        set,
        mats,
        &set.faces[f],
        (i as f32 + 0.5) / r,
        (j as f32 + 0.5) / r,
    );
    (0..pt.count).map(|k| (pt.ids[k], pt.weights[k])).collect()
}

/// The interpolated inputs of a texel.
struct Point {
    p: [f32; 3],
    n: [f32; 3],
    amp: f32,
    /// Merged material indices and weights, `count` of them.
    ids: [usize; 4],
    weights: [f32; 4],
    count: usize,
}

fn interpolate(set: &FaceSet, mats: &MaterialSet, face: &Face, u: f32, v: f32) -> Point {
    let n = face.n;
    let last = (n - 2) as f32;
    let gu = u * (n - 1) as f32;
    let gv = v * (n - 1) as f32;
    let cu = gu.floor().min(last);
    let cv = gv.floor().min(last);
    let (fu, fv) = (gu - cu, gv - cv);
    let base = face.first as usize + cv as usize * n as usize + cu as usize;
    let s = [
        set.samples[base],
        set.samples[base + 1],
        set.samples[base + n as usize],
        set.samples[base + n as usize + 1],
    ];
    let w = [
        (1.0 - fu) * (1.0 - fv),
        fu * (1.0 - fv),
        (1.0 - fu) * fv,
        fu * fv,
    ];
    let mix3 = |get: &dyn Fn(usize) -> [f32; 3]| -> [f32; 3] {
        std::array::from_fn(|c| {
            w[0] * get(0)[c] + w[1] * get(1)[c] + w[2] * get(2)[c] + w[3] * get(3)[c]
        })
    };
    let p = mix3(&|k| s[k].position);
    let nn = mix3(&|k| s[k].normal);
    let amp = w[0] * s[0].noise_m + w[1] * s[1].noise_m + w[2] * s[2].noise_m + w[3] * s[3].noise_m;
    let mut out = Point {
        p,
        n: normalize_or(nn, [0.0, 1.0, 0.0]),
        amp,
        ids: [0; 4],
        weights: [0.0; 4],
        count: 0,
    };
    if let Some(rule) = set.texel_rule() {
        let at = [base, base + 1, base + n as usize, base + n as usize + 1];
        let inputs: [f32; SURFACE_INPUTS] = std::array::from_fn(|c| {
            let g = |k: usize| set.surface[at[k]][c];
            w[0] * g(0) + w[1] * g(1) + w[2] * g(2) + w[3] * g(3)
        });
        let (ids, weights, count) = surface_slots(rule, &inputs, out.n[1], mats);
        if count > 0 {
            (out.ids, out.weights, out.count) = (ids, weights, count);
            return out;
        }
    }
    for k in 0..4 {
        let id = mats.index(s[k].material);
        match out.ids[..out.count].iter().position(|&x| x == id) {
            Some(at) => out.weights[at] += w[k],
            None => {
                out.ids[out.count] = id;
                out.weights[out.count] = w[k];
                out.count += 1;
            }
        }
    }
    out
}

/// Lightest weight of a material [`surface_slots`] keeps: below half a step of the 8-bit albedo,
/// so leaving it out changes no colour by more than rounding, and the texel saves its pattern.
pub const MIN_SURFACE_WEIGHT: f32 = 1.0 / 512.0;

/// Step 1 with texel inputs ([`FaceSet::surface`]): the materials of a texel whose interpolated
/// inputs are `inputs` and whose interpolated unit normal has the y component `normal_y`, from
/// [`texel_weights`]: those of weight at least [`MIN_SURFACE_WEIGHT`] in id order, at most four
/// (where more have weight, the lightest are left out, the higher id first on a tie), their
/// weights divided by their sum, as set indices (ids one set index holds merged); a count of 0
/// where none has weight.
fn surface_slots(
    rule: &TexelRule,
    inputs: &[f32; SURFACE_INPUTS],
    normal_y: f32,
    mats: &MaterialSet,
) -> ([usize; 4], [f32; 4], usize) {
    let weights = texel_weights(rule, inputs, normal_y);
    let mut kept = [(0usize, 0.0f32); MATERIALS.len()];
    let mut count = 0;
    for (id, &w) in weights.iter().enumerate() {
        if w >= MIN_SURFACE_WEIGHT {
            kept[count] = (id, w);
            count += 1;
        }
    }
    while count > 4 {
        let mut lightest = 0;
        for k in 1..count {
            if kept[k].1 <= kept[lightest].1 {
                lightest = k;
            }
        }
        kept.copy_within(lightest + 1..count, lightest);
        count -= 1;
    }
    let mut total = 0.0f32;
    for &(_, w) in &kept[..count] {
        total += w;
    }
    let (mut ids, mut out, mut slots) = ([0usize; 4], [0.0f32; 4], 0);
    for &(id, w) in &kept[..count] {
        let w = w / total;
        let index = mats.index(id as u32);
        match ids[..slots].iter().position(|&x| x == index) {
            Some(at) => out[at] += w,
            None => {
                ids[slots] = index;
                out[slots] = w;
                slots += 1;
            }
        }
    }
    (ids, out, slots)
}

/// `D(q)` with the geometric tri-planar weights `wg`, the noise of point `point` (0: `p`, 1 and
/// 2: the displaced points) through `cache`. At `p`, the patterns the relief reads are kept in
/// `patterns` (`[material slot][plane]`) for the albedo, which reads them at `p` too.
#[allow(clippy::too_many_arguments)]
fn displacement(
    mats: &MaterialSet,
    pt: &Point,
    anchor: [i32; 3],
    q: [f32; 3],
    wg: [f32; 3],
    kmax: i32,
    point: usize,
    cache: &mut NoiseCache,
    patterns: &mut [[Option<f32>; 3]; 4],
) -> f32 {
    let count = octave_count(mats.noise_freq_log2, mats.noise_octaves, kmax);
    let noise = fbm3_in(
        &mut cache.d3[point],
        anchor,
        q,
        mats.noise_freq_log2,
        count,
        mats.noise_seed,
    );
    relief_sum(mats, pt, noise, wg, |m, id, axis| {
        let t = relief_t(
            mats,
            id,
            anchor,
            q,
            axis,
            kmax,
            cache.pattern(point, id, axis),
        );
        if point == 0 && relief_from_pattern(mats, id) {
            patterns[m][axis] = Some(t);
        }
        t
    })
}

/// Whether material `id`'s relief is its pattern (not a height image).
fn relief_from_pattern(mats: &MaterialSet, id: usize) -> bool {
    !matches!(
        mats.materials[id].texture,
        Some(Texture {
            height: Some(_),
            ..
        })
    )
}

/// `D = a·noise + Σₘ bₘ·(reliefₘ·Σ_axis w_axis·(t − ½))` with `relief(m, id, axis)` the relief
/// `t` of material slot `m` (material `id`) on plane `axis`.
fn relief_sum(
    mats: &MaterialSet,
    pt: &Point,
    noise: f32,
    wg: [f32; 3],
    mut relief: impl FnMut(usize, usize, usize) -> f32,
) -> f32 {
    let mut d = pt.amp * noise;
    for m in 0..pt.count {
        let id = pt.ids[m];
        let relief_m = mats.materials[id].relief_m;
        let mut r = 0.0f32;
        for (axis, w) in wg.iter().enumerate() {
            let t = relief(m, id, axis);
            r += w * (t - 0.5);
        }
        d += pt.weights[m] * (relief_m * r);
    }
    d
}

fn unorm8(x: f32) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8
}

fn snorm8(x: f32) -> u8 {
    ((x.clamp(-1.0, 1.0) * 127.0 + 0.5).floor() as i32 as i8) as u8
}

/// Bakes texel `(i, j)` of face `f` of `set` at `res`.
pub fn texel(set: &FaceSet, mats: &MaterialSet, f: usize, res: u32, i: u32, j: u32) -> Texel {
    let constants = face_constants(&set.faces[f], res);
    texel_in(
        set,
        mats,
        f,
        res,
        constants,
        i,
        j,
        &mut NoiseCache::new(mats),
    )
}

/// A texel's interpolated inputs, tangent frame, geometric tri-planar weights and the points
/// `p`, `p + δt₁`, `p + δt₂` its displacement is read at.
struct Frame {
    pt: Point,
    t1: [f32; 3],
    t2: [f32; 3],
    wg: [f32; 3],
    q: [[f32; 3]; 3],
}

/// The [`Frame`] of texel `(i, j)` of `face` at `res` with the step `step`.
fn frame(
    set: &FaceSet,
    mats: &MaterialSet,
    face: &Face,
    res: u32,
    step: f32,
    (i, j): (u32, u32),
) -> Frame {
    let r = res as f32;
    let (u, v) = ((i as f32 + 0.5) / r, (j as f32 + 0.5) / r);
    let pt = interpolate(set, mats, face, u, v);
    let n = pt.n;
    let helper = if n[1].abs() < 0.9 {
        [0.0, 1.0, 0.0]
    } else {
        [1.0, 0.0, 0.0]
    };
    let t1 = normalize_or(cross(helper, n), [1.0, 0.0, 0.0]);
    let t2 = cross(n, t1);
    let wg = triplanar(n);
    let at = |t: [f32; 3]| -> [f32; 3] { std::array::from_fn(|c| pt.p[c] + step * t[c]) };
    let q = [pt.p, at(t1), at(t2)];
    Frame { pt, t1, t2, wg, q }
}

/// Steps 4 to 7 of a texel: the displaced normal from the displacements `d` at the frame's
/// three points, the tri-planar blend (`at_p(m, id, axis)`: the pattern `t` of material slot `m`,
/// material `id`, on plane `axis` at `p`), the decals and the quantisation.
fn finish(
    mats: &MaterialSet,
    a: [i32; 3],
    (kmax, step): (i32, f32),
    fr: &Frame,
    [d0, d1, d2]: [f32; 3],
    mut at_p: impl FnMut(usize, usize, usize) -> f32,
) -> Texel {
    let pt = &fr.pt;
    let (n, t1, t2) = (pt.n, fr.t1, fr.t2);
    let inv = 1.0 / step;
    let (g1, g2) = ((d1 - d0) * inv, (d2 - d0) * inv);
    let nd = normalize_or(std::array::from_fn(|c| n[c] - g1 * t1[c] - g2 * t2[c]), n);
    let wd = triplanar(nd);
    let mut albedo = [0.0f32; 3];
    let mut rough = 0.0f32;
    let mut dominant = 0usize;
    for m in 0..pt.count {
        let id = pt.ids[m];
        let mat = &mats.materials[id];
        for (axis, w) in wd.iter().enumerate() {
            let k = pt.weights[m] * w;
            let Some(tex) = mat.texture else {
                let t = at_p(m, id, axis);
                for (c, a) in albedo.iter_mut().enumerate() {
                    *a += k * (mat.base[c] + (mat.tint[c] - mat.base[c]) * t);
                }
                rough += k * (mat.roughness[0] + (mat.roughness[1] - mat.roughness[0]) * t);
                continue;
            };
            let rgb = image_sample(mats, tex.albedo, tex.repeat_log2, pt.p, axis, kmax);
            for (c, a) in albedo.iter_mut().enumerate() {
                *a += k * rgb[c];
            }
            let t = match tex.roughness {
                Some(r) => image_sample(mats, r, tex.repeat_log2, pt.p, axis, kmax)[0],
                None => at_p(m, id, axis),
            };
            rough += k * (mat.roughness[0] + (mat.roughness[1] - mat.roughness[0]) * t);
        }
        let best = pt.weights[dominant];
        if pt.weights[m] > best || (pt.weights[m] == best && id < pt.ids[dominant]) {
            dominant = m;
        }
    }
    let spot = Spot {
        anchor: a,
        p: pt.p,
        normal_y: nd[1],
        kmax,
    };
    apply_decals(&mats.decals, &mats.images, spot, &mut albedo, &mut rough);
    let nd = normal_maps(mats, kmax, pt, nd, wd);
    Texel {
        albedo: [
            unorm8(albedo[0]),
            unorm8(albedo[1]),
            unorm8(albedo[2]),
            unorm8(rough),
        ],
        normal: [
            snorm8(nd[0]),
            snorm8(nd[1]),
            snorm8(nd[2]),
            pt.ids[dominant] as u8,
        ],
        displacement: d0,
    }
}

/// Step 5's normal maps: each material of the texel with a normal map
/// ([`Texture::normal`]) tilts the displaced normal `nd` on each projection plane, weighted by
/// its weight times the plane's (`wd`, the blend's weights). On plane `axis` (coordinates `u`,
/// `v` the world components `axis + 1`, `axis + 2`, mod 3) the map's unit normal `t = 2·s − 1`
/// (`s` the sample, [`image_sample`]) and `nd` give the whiteout blend `(t_x + nd_u, t_y + nd_v,
/// |t_z|·nd_axis)`, normalised: the map's relief as seen along the plane's normal, on either
/// side of it. The result is `normalize(nd + Σ k·(blend − nd))`. Without a normal map among the
/// texel's materials `nd` is returned as it is, so every other bake keeps its bytes.
fn normal_maps(mats: &MaterialSet, kmax: i32, pt: &Point, nd: [f32; 3], wd: [f32; 3]) -> [f32; 3] {
    let mut tilt = [0.0f32; 3];
    let mut mapped = false;
    for m in 0..pt.count {
        let Some(Texture {
            normal: Some(img),
            repeat_log2,
            ..
        }) = mats.materials[pt.ids[m]].texture
        else {
            continue;
        };
        mapped = true;
        for (axis, w) in wd.iter().enumerate() {
            let k = pt.weights[m] * w;
            let s = image_sample(mats, img, repeat_log2, pt.p, axis, kmax);
            let (a1, a2) = ((axis + 1) % 3, (axis + 2) % 3);
            let mut v = [0.0f32; 3];
            v[a1] = (2.0 * s[0] - 1.0) + nd[a1];
            v[a2] = (2.0 * s[1] - 1.0) + nd[a2];
            v[axis] = (2.0 * s[2] - 1.0).abs() * nd[axis];
            let v = normalize_or(v, nd);
            for c in 0..3 {
                tilt[c] += k * (v[c] - nd[c]);
            }
        }
    }
    if !mapped {
        return nd;
    }
    normalize_or(std::array::from_fn(|c| nd[c] + tilt[c]), nd)
}

/// [`texel`] with the face's [`face_constants`] given and the noise through `cache`: the same
/// bytes.
#[allow(clippy::too_many_arguments)]
pub fn texel_in(
    set: &FaceSet,
    mats: &MaterialSet,
    f: usize,
    res: u32,
    constants: (i32, f32),
    i: u32,
    j: u32,
    cache: &mut NoiseCache,
) -> Texel {
    let (kmax, step) = constants;
    let face = &set.faces[f];
    let fr = frame(set, mats, face, res, step, (i, j));
    let a = face.anchor;
    let mut patterns = [[None; 3]; 4];
    let mut unused = [[None; 3]; 4];
    let (pt, wg) = (&fr.pt, fr.wg);
    let d0 = displacement(mats, pt, a, fr.q[0], wg, kmax, 0, cache, &mut patterns);
    let d1 = displacement(mats, pt, a, fr.q[1], wg, kmax, 1, cache, &mut unused);
    let d2 = displacement(mats, pt, a, fr.q[2], wg, kmax, 2, cache, &mut unused);
    finish(
        mats,
        a,
        constants,
        &fr,
        [d0, d1, d2],
        |m, id, axis| match patterns[m][axis] {
            Some(t) => t,
            None => pattern(mats, id, a, pt.p, axis, kmax, cache.pattern(0, id, axis)),
        },
    )
}

/// One lane quantity per axis, `[axis][lane]`.
type Lanes3 = [Lanes; 3];

/// [`Frame`] at [`LANES`] texels, `[…][lane]`.
struct FrameLanes {
    p: Lanes3,
    n: Lanes3,
    amp: Lanes,
    /// Merged material indices and weights by slot, `count` of them in each lane (the others
    /// 0).
    ids: [[usize; LANES]; 4],
    weights: [Lanes; 4],
    count: [usize; LANES],
    t1: Lanes3,
    t2: Lanes3,
    wg: Lanes3,
    q: [Lanes3; 3],
}

/// `v` in every lane.
fn splat3(v: [f32; 3]) -> Lanes3 {
    v.map(|c| [c; LANES])
}

#[inline(always)]
fn cross_lanes(a: &Lanes3, b: &Lanes3) -> Lanes3 {
    let mut out = [[0.0; LANES]; 3];
    for l in 0..LANES {
        out[0][l] = a[1][l] * b[2][l] - a[2][l] * b[1][l];
        out[1][l] = a[2][l] * b[0][l] - a[0][l] * b[2][l];
        out[2][l] = a[0][l] * b[1][l] - a[1][l] * b[0][l];
    }
    out
}

/// [`normalize_or`] in every lane.
#[inline(always)]
fn normalize_or_lanes(v: &Lanes3, fallback: &Lanes3) -> Lanes3 {
    let mut l2 = [0.0f32; LANES];
    let mut inv = [0.0f32; LANES];
    for l in 0..LANES {
        l2[l] = v[0][l] * v[0][l] + v[1][l] * v[1][l] + v[2][l] * v[2][l];
        inv[l] = 1.0 / l2[l].sqrt();
    }
    let mut out = [[0.0; LANES]; 3];
    for c in 0..3 {
        for l in 0..LANES {
            out[c][l] = if l2[l] < 1e-20 {
                fallback[c][l]
            } else {
                v[c][l] * inv[l]
            };
        }
    }
    out
}

/// [`triplanar`] in every lane.
#[inline(always)]
fn triplanar_lanes(n: &Lanes3) -> Lanes3 {
    let mut a = [[0.0f32; LANES]; 3];
    for c in 0..3 {
        for l in 0..LANES {
            let c2 = n[c][l] * n[c][l];
            a[c][l] = c2 * c2;
        }
    }
    let mut inv = [0.0f32; LANES];
    for l in 0..LANES {
        let s = a[0][l] + a[1][l] + a[2][l];
        inv[l] = 1.0 / s;
    }
    for a in &mut a {
        for l in 0..LANES {
            a[l] *= inv[l];
        }
    }
    a
}

/// [`frame`] at texels `ij` of `face`, lane by lane the same operations.
fn frame_lanes(
    set: &FaceSet,
    mats: &MaterialSet,
    face: &Face,
    res: u32,
    step: f32,
    ij: &[(u32, u32); LANES],
) -> FrameLanes {
    let n = face.n as usize;
    let (last, span, r) = ((n - 2) as f32, (n - 1) as f32, res as f32);
    let mut w = [[0.0f32; LANES]; 4];
    let mut base = [0usize; LANES];
    for l in 0..LANES {
        let (i, j) = ij[l];
        let (u, v) = ((i as f32 + 0.5) / r, (j as f32 + 0.5) / r);
        let (gu, gv) = (u * span, v * span);
        let cu = gu.floor().min(last);
        let cv = gv.floor().min(last);
        let (fu, fv) = (gu - cu, gv - cv);
        base[l] = face.first as usize + cv as usize * n + cu as usize;
        w[0][l] = (1.0 - fu) * (1.0 - fv);
        w[1][l] = fu * (1.0 - fv);
        w[2][l] = (1.0 - fu) * fv;
        w[3][l] = fu * fv;
    }
    // The four samples of each lane, `[sample][component][lane]` (4: the noise amplitude).
    let mut sp = [[[0.0f32; LANES]; 3]; 4];
    let mut sn = [[[0.0f32; LANES]; 3]; 4];
    let mut sa = [[0.0f32; LANES]; 4];
    let mut ids = [[0usize; LANES]; 4];
    let mut weights = [[0.0f32; LANES]; 4];
    let mut count = [0usize; LANES];
    for l in 0..LANES {
        for (k, off) in [0, 1, n, n + 1].into_iter().enumerate() {
            let s = &set.samples[base[l] + off];
            for c in 0..3 {
                sp[k][c][l] = s.position[c];
                sn[k][c][l] = s.normal[c];
            }
            sa[k][l] = s.noise_m;
            let id = mats.index(s.material);
            match (0..count[l]).find(|&at| ids[at][l] == id) {
                Some(at) => weights[at][l] += w[k][l],
                None => {
                    ids[count[l]][l] = id;
                    weights[count[l]][l] = w[k][l];
                    count[l] += 1;
                }
            }
        }
    }
    let mix = |s: [&Lanes; 4], out: &mut Lanes| {
        for l in 0..LANES {
            out[l] = w[0][l] * s[0][l] + w[1][l] * s[1][l] + w[2][l] * s[2][l] + w[3][l] * s[3][l];
        }
    };
    let mut p = [[0.0f32; LANES]; 3];
    let mut nn = [[0.0f32; LANES]; 3];
    let mut amp = [0.0f32; LANES];
    for c in 0..3 {
        mix([&sp[0][c], &sp[1][c], &sp[2][c], &sp[3][c]], &mut p[c]);
        mix([&sn[0][c], &sn[1][c], &sn[2][c], &sn[3][c]], &mut nn[c]);
    }
    mix([&sa[0], &sa[1], &sa[2], &sa[3]], &mut amp);
    let nrm = normalize_or_lanes(&nn, &splat3([0.0, 1.0, 0.0]));
    if let Some(rule) = set.texel_rule() {
        for l in 0..LANES {
            let at = [base[l], base[l] + 1, base[l] + n, base[l] + n + 1];
            let inputs: [f32; SURFACE_INPUTS] = std::array::from_fn(|c| {
                let g = |k: usize| set.surface[at[k]][c];
                w[0][l] * g(0) + w[1][l] * g(1) + w[2][l] * g(2) + w[3][l] * g(3)
            });
            let (lane_ids, lane_weights, lane_count) =
                surface_slots(rule, &inputs, nrm[1][l], mats);
            if lane_count > 0 {
                for k in 0..4 {
                    ids[k][l] = lane_ids[k];
                    weights[k][l] = lane_weights[k];
                }
                count[l] = lane_count;
            }
        }
    }
    let mut helper = [[0.0f32; LANES]; 3];
    for l in 0..LANES {
        let up = nrm[1][l].abs() < 0.9;
        helper[0][l] = if up { 0.0 } else { 1.0 };
        helper[1][l] = if up { 1.0 } else { 0.0 };
    }
    let t1 = normalize_or_lanes(&cross_lanes(&helper, &nrm), &splat3([1.0, 0.0, 0.0]));
    let t2 = cross_lanes(&nrm, &t1);
    let wg = triplanar_lanes(&nrm);
    let mut q = [p; 3];
    for (q, t) in q[1..].iter_mut().zip([&t1, &t2]) {
        for c in 0..3 {
            for l in 0..LANES {
                q[c][l] = p[c][l] + step * t[c][l];
            }
        }
    }
    FrameLanes {
        p,
        n: nrm,
        amp,
        ids,
        weights,
        count,
        t1,
        t2,
        wg,
        q,
    }
}

/// [`texel_in`] at [`LANES`] texels `ij` of face `f` side by side: the same bytes, texel by
/// texel, each lane going through the same operations in the same order. The noise sums (the
/// displacement noise at the three points of every lane, and the pattern of each material any
/// lane holds, on each plane, at the points that read it) are taken for all lanes at once with
/// [`fbm3_lanes`] and [`fbm2_lanes`]; where the lanes hold only procedural materials the
/// interpolation, relief, displaced normal, blend and quantisation go lane by lane too, else
/// (image materials) each texel's relief and blend are [`texel_in`]'s own code.
pub(crate) fn texels_lanes(
    set: &FaceSet,
    mats: &MaterialSet,
    f: usize,
    res: u32,
    constants: (i32, f32),
    ij: [(u32, u32); LANES],
    cache: &mut NoiseCache,
) -> [Texel; LANES] {
    let (kmax, step) = constants;
    let face = &set.faces[f];
    let a = face.anchor;
    let fr = frame_lanes(set, mats, face, res, step, &ij);
    // The materials the lanes hold, as bits (a set past 64 materials goes one texel at a time).
    let mut present = 0u64;
    let mut slots = 0;
    for l in 0..LANES {
        for m in 0..fr.count[l] {
            let id = fr.ids[m][l];
            if id >= 64 {
                return ij.map(|(i, j)| texel_in(set, mats, f, res, constants, i, j, cache));
            }
            present |= 1u64 << id;
        }
        slots = slots.max(fr.count[l]);
    }
    let count = octave_count(mats.noise_freq_log2, mats.noise_octaves, kmax);
    let noise: [Lanes; 3] = std::array::from_fn(|point| {
        fbm3_lanes(
            &mut cache.d3[point],
            a,
            &fr.q[point],
            mats.noise_freq_log2,
            count,
            mats.noise_seed,
        )
    });
    if cache.lanes.len() < mats.materials.len() {
        cache
            .lanes
            .resize(mats.materials.len(), [[[0.0; LANES]; 3]; 3]);
    }
    let mut textured = false;
    let mut bits = present;
    while bits != 0 {
        let id = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        textured |= mats.materials[id].texture.is_some();
        let from_pattern = relief_from_pattern(mats, id);
        let albedo_pattern = mats.materials[id]
            .texture
            .is_none_or(|t| t.roughness.is_none());
        let points = if from_pattern {
            3
        } else {
            usize::from(albedo_pattern)
        };
        for (point, q) in fr.q.iter().enumerate().take(points) {
            for axis in 0..3 {
                let t = pattern_lanes(mats, id, a, q, axis, kmax, cache.pattern(point, id, axis));
                cache.lanes[id][point][axis] = t;
            }
        }
    }
    let kept = &cache.lanes;
    if textured {
        return std::array::from_fn(|l| {
            let fr = frame(set, mats, face, res, step, ij[l]);
            let d: [f32; 3] = std::array::from_fn(|point| {
                relief_sum(mats, &fr.pt, noise[point][l], fr.wg, |_, id, axis| {
                    if relief_from_pattern(mats, id) {
                        kept[id][point][axis][l]
                    } else {
                        relief_t(mats, id, a, fr.q[point], axis, kmax, &mut [])
                    }
                })
            });
            finish(mats, a, constants, &fr, d, |_, id, axis| {
                kept[id][0][axis][l]
            })
        });
    }
    // Each slot's patterns, `[slot][point][plane]` (a slot past a lane's count holds another
    // material's or stale values, which the lane leaves out).
    let mut t = [[[[0.0f32; LANES]; 3]; 3]; 4];
    for (m, t) in t.iter_mut().enumerate().take(slots) {
        let ids = &fr.ids[m];
        if ids.iter().all(|&id| id == ids[0]) {
            *t = kept[ids[0]];
        } else {
            for (l, &id) in ids.iter().enumerate() {
                for (point, t) in t.iter_mut().enumerate() {
                    for (axis, t) in t.iter_mut().enumerate() {
                        t[l] = kept[id][point][axis][l];
                    }
                }
            }
        }
    }
    let material = |m: usize, l: usize| &mats.materials[fr.ids[m][l]];
    // The relief: [`relief_sum`], lane by lane.
    let mut d = noise;
    for (d, noise) in d.iter_mut().zip(&noise) {
        for l in 0..LANES {
            d[l] = fr.amp[l] * noise[l];
        }
    }
    for (m, t) in t.iter().enumerate().take(slots) {
        let relief: Lanes = std::array::from_fn(|l| material(m, l).relief_m);
        for (d, t) in d.iter_mut().zip(t) {
            for l in 0..LANES {
                let mut r = 0.0f32;
                for (w, t) in fr.wg.iter().zip(t) {
                    r += w[l] * (t[l] - 0.5);
                }
                d[l] = if m < fr.count[l] {
                    d[l] + fr.weights[m][l] * (relief[l] * r)
                } else {
                    d[l]
                };
            }
        }
    }
    // The displaced normal and the blend: [`finish`], lane by lane.
    let inv = 1.0 / step;
    let mut raw = [[0.0f32; LANES]; 3];
    for l in 0..LANES {
        let (g1, g2) = ((d[1][l] - d[0][l]) * inv, (d[2][l] - d[0][l]) * inv);
        for (c, raw) in raw.iter_mut().enumerate() {
            raw[l] = fr.n[c][l] - g1 * fr.t1[c][l] - g2 * fr.t2[c][l];
        }
    }
    let nd = normalize_or_lanes(&raw, &fr.n);
    let wd = triplanar_lanes(&nd);
    let mut albedo = [[0.0f32; LANES]; 3];
    let mut rough = [0.0f32; LANES];
    for (m, t) in t.iter().enumerate().take(slots) {
        let base: Lanes3 = std::array::from_fn(|c| std::array::from_fn(|l| material(m, l).base[c]));
        let tint: Lanes3 = std::array::from_fn(|c| std::array::from_fn(|l| material(m, l).tint[c]));
        let r0: Lanes = std::array::from_fn(|l| material(m, l).roughness[0]);
        let r1: Lanes = std::array::from_fn(|l| material(m, l).roughness[1]);
        for axis in 0..3 {
            let t = &t[0][axis];
            for l in 0..LANES {
                let k = fr.weights[m][l] * wd[axis][l];
                let on = m < fr.count[l];
                for c in 0..3 {
                    let x = albedo[c][l] + k * (base[c][l] + (tint[c][l] - base[c][l]) * t[l]);
                    albedo[c][l] = if on { x } else { albedo[c][l] };
                }
                let x = rough[l] + k * (r0[l] + (r1[l] - r0[l]) * t[l]);
                rough[l] = if on { x } else { rough[l] };
            }
        }
    }
    if !mats.decals.is_empty() {
        for l in 0..LANES {
            let mut alb = [albedo[0][l], albedo[1][l], albedo[2][l]];
            let p = [fr.p[0][l], fr.p[1][l], fr.p[2][l]];
            let spot = Spot {
                anchor: a,
                p,
                normal_y: nd[1][l],
                kmax,
            };
            apply_decals(&mats.decals, &mats.images, spot, &mut alb, &mut rough[l]);
            for (c, x) in alb.into_iter().enumerate() {
                albedo[c][l] = x;
            }
        }
    }
    // The quantisation, lane by lane.
    let mut bytes = [[0u8; LANES]; 7];
    for (b, x) in bytes.iter_mut().zip(albedo.iter().chain([&rough])) {
        for l in 0..LANES {
            b[l] = unorm8(x[l]);
        }
    }
    for (b, x) in bytes[4..].iter_mut().zip(&nd) {
        for l in 0..LANES {
            b[l] = snorm8(x[l]);
        }
    }
    std::array::from_fn(|l| {
        let mut dominant = 0usize;
        for m in 0..fr.count[l] {
            let (w, best) = (fr.weights[m][l], fr.weights[dominant][l]);
            if w > best || (w == best && fr.ids[m][l] < fr.ids[dominant][l]) {
                dominant = m;
            }
        }
        Texel {
            albedo: [bytes[0][l], bytes[1][l], bytes[2][l], bytes[3][l]],
            normal: [
                bytes[4][l],
                bytes[5][l],
                bytes[6][l],
                fr.ids[dominant][l] as u8,
            ],
            displacement: d[0][l],
        }
    })
}

/// [`pattern`] at [`LANES`] points `q` (`[axis][lane]`).
fn pattern_lanes(
    mats: &MaterialSet,
    m: usize,
    anchor: [i32; 3],
    q: &[Lanes; 3],
    axis: usize,
    kmax: i32,
    cells: &mut [Cell2],
) -> Lanes {
    let mat = &mats.materials[m];
    let count = octave_count(mat.freq_log2, mat.octaves, kmax);
    let seed = mats.seeds[m].wrapping_add(256 * axis as u32);
    let [u, v] = plane([&q[0], &q[1], &q[2]], axis);
    let v = fbm2_lanes(
        cells,
        plane(anchor, axis),
        [u, v],
        mat.freq_log2,
        count,
        seed,
    );
    v.map(|v| (0.5 + 0.5 * v).clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ptex::select::bake_faces;
    use crate::terrain::{TileKey, WorldParams, WorldPlan};

    /// Material 2 of the default set with a uniform normal map whose texels are `rgb`, and a
    /// texel of that material alone on ground whose displaced normal is `nd`.
    fn mapped(rgb: [u8; 3], nd: [f32; 3]) -> [f32; 3] {
        use crate::ptex::image::Image;
        let mut mats = MaterialSet::default_ground(7);
        mats.images.push(std::sync::Arc::new(Image::new(
            4,
            4,
            vec![[rgb[0], rgb[1], rgb[2], 255]; 16],
        )));
        mats.materials[2].texture = Some(Texture {
            albedo: 0,
            roughness: None,
            height: None,
            normal: Some(0),
            repeat_log2: 0,
        });
        let pt = Point {
            p: [3.2, 10.0, -7.9],
            n: nd,
            amp: 0.0,
            ids: [2, 0, 0, 0],
            weights: [1.0, 0.0, 0.0, 0.0],
            count: 1,
        };
        normal_maps(&mats, 6, &pt, nd, triplanar(nd))
    }

    #[test]
    fn a_normal_map_tilts_the_normal_the_way_its_relief_leans() {
        let up = [0.0, 1.0, 0.0];
        // A flat map (128, 128, 255) is the normal itself, to a byte.
        let flat = mapped([128, 128, 255], up);
        assert!(
            flat.iter().zip(up).all(|(a, b)| (a - b).abs() < 0.01),
            "{flat:?}"
        );
        // On ground facing up the plane is Y, whose coordinates are (z, x): the map's x leans
        // the normal along world z, its y along world x, by the map's own angle.
        let along_u = mapped([218, 128, 218], up);
        assert!(along_u[2] > 0.6 && along_u[0].abs() < 0.01, "{along_u:?}");
        let along_v = mapped([128, 38, 218], up);
        assert!(along_v[0] < -0.6 && along_v[2].abs() < 0.01, "{along_v:?}");
        // On a wall facing −X (plane X, coordinates (y, z)) the map's x leans it along world y.
        let wall = mapped([218, 128, 218], [-1.0, 0.0, 0.0]);
        assert!(
            wall[1] > 0.6 && wall[0] < -0.6 && wall[2].abs() < 0.01,
            "{wall:?}"
        );
        // Every result is a unit vector.
        for n in [flat, along_u, along_v, wall] {
            let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((l - 1.0).abs() < 1e-5, "|{n:?}| = {l}");
        }
    }

    /// The blake3 digest of the three planes of `pages`.
    fn digest(pages: &Pages) -> String {
        let mut h = blake3::Hasher::new();
        for t in &pages.albedo {
            h.update(t);
        }
        for t in &pages.normal {
            h.update(t);
        }
        for d in &pages.displacement {
            h.update(&d.to_bits().to_le_bytes());
        }
        h.finalize().to_hex()[..16].to_string()
    }

    #[test]
    fn the_bake_keeps_the_bytes_of_the_build_before_its_speed_ups() {
        // Digests of the bake before the cached lattice cells, the shared pattern values and the
        // row-parallel interiors (main at d29b3c9), whole tiles and chosen faces, 8² to 256²,
        // over the default world of then as far as these tiles see it (`valleys: 3`; new worlds
        // carve later valleys, which move these tiles' heights, the bake's input; no coarse
        // lattice, which moves them too; the first snow lines; no alpine zone; the second
        // gullies with every octave; and `ptex_blend: 1`, as every world stored before `2`
        // bakes).
        let mut params = WorldParams::default();
        if let Some(e) = params.earth.as_mut() {
            (e.coarse_lattice_cells, e.snow_lines, e.gullies) = (None, 1, 2);
            e.gully_first = 0;
        }
        if let Some(rivers) = params.earth.as_mut().and_then(|e| e.rivers.as_mut()) {
            rivers.valleys = 3;
        }
        params.texturing.ptex_blend = 1;
        params.texturing.alpine_fraction = 0.0;
        let plan = WorldPlan::new(7, params).expect("plan");
        let mats = MaterialSet::default_ground(plan.seed);
        let mut got = Vec::new();
        for (key, res) in [
            (
                TileKey {
                    lod: 0,
                    x: -20,
                    z: 3,
                },
                8u32,
            ),
            (
                TileKey {
                    lod: 0,
                    x: -13,
                    z: -2,
                },
                64,
            ),
            (
                TileKey {
                    lod: 2,
                    x: 3,
                    z: -2,
                },
                16,
            ),
            (TileKey { lod: 0, x: 5, z: 9 }, 256),
        ] {
            let set = crate::ptex::face::test_face_set(&plan, key, &mats);
            let mut pages = Pages::default();
            if res < 256 {
                bake(&set, &mats, res, &mut pages);
                got.push(format!("{res} whole {}", digest(&pages)));
            }
            bake_faces(&set, &mats, res, &[5, 0, 15], &mut pages);
            got.push(format!("{res} chosen {}", digest(&pages)));
        }
        let want = [
            "8 whole 442c91b79915bd9a",
            "8 chosen 3d5f98aaca8ab6b6",
            "64 whole e809b05ba0a77ca8",
            "64 chosen 1f28e1ac513a7997",
            "16 whole 78e49d6517b64973",
            "16 chosen e4d4407d852c17fd",
            "256 chosen ccbe524274f279a3",
        ];
        assert_eq!(got, want);
    }

    #[test]
    fn lanes_give_each_texel_the_bytes_of_texel() {
        // Image materials (albedo only; albedo and height; every image) and a decal beside the
        // procedural ones, lanes along rows, down columns and scattered over the face.
        use crate::ptex::decal::Decal;
        use crate::ptex::image::Image;
        use std::sync::Arc;
        let plan = WorldPlan::new(7, WorldParams::default()).expect("plan");
        let mut mats = MaterialSet::default_ground(plan.seed);
        let image = |seed: u32| {
            let texels = (0..64u32)
                .map(|i| {
                    let h = crate::terrain::hash::mix32(i ^ seed);
                    h.to_le_bytes()
                })
                .collect();
            Arc::new(Image::new(8, 8, texels))
        };
        mats.images = (0..4).map(image).collect();
        let texture = |albedo, roughness, height, normal| {
            Some(Texture {
                albedo,
                roughness,
                height,
                normal,
                repeat_log2: 1,
            })
        };
        let procedural = mats.clone();
        for (id, tex) in [
            (1, texture(0, None, None, None)),
            (2, texture(1, None, Some(2), Some(0))),
            (4, texture(3, Some(0), Some(1), None)),
        ] {
            mats.materials[id].texture = tex;
        }
        // The first tile of a walk with a face of two materials or more, and its faces of most
        // materials.
        let materials = |set: &FaceSet, f: usize| {
            let face = &set.faces[f];
            let n = (face.n * face.n) as usize;
            let first = face.first as usize;
            let ids: std::collections::BTreeSet<u32> = set.samples[first..first + n]
                .iter()
                .map(|s| s.material)
                .collect();
            ids.len()
        };
        let (set, faces) = (0..64)
            .find_map(|k: i64| {
                let key = TileKey {
                    lod: (k % 3) as u32,
                    x: 5 * k - 40,
                    z: 3 * k - 20,
                };
                let set = crate::ptex::face::test_face_set(&plan, key, &mats);
                let mut faces: Vec<usize> = (0..set.faces.len()).collect();
                faces.sort_by_key(|&f| std::cmp::Reverse(materials(&set, f)));
                faces.truncate(4);
                (materials(&set, faces[0]) >= 2).then_some((set, faces))
            })
            .expect("a tile of two materials");
        let centre = set.samples[set.faces[faces[0]].first as usize].position;
        let a = set.faces[faces[0]].anchor;
        let decal = Decal {
            anchor: [a[0], a[2]],
            offset: [centre[0], centre[2]],
            inv_size: [1.0 / 30.0, 1.0 / 20.0],
            cos: 0.8,
            sin: 0.6,
            opacity: 0.7,
            roughness: Some(0.2),
            image: 2,
            mask: None,
            density_log2: 0,
            mask_density_log2: 0,
            facing: false,
        };
        // And one that fades with the facing, turned the other way.
        let facing = Decal {
            sin: -0.6,
            opacity: 0.9,
            facing: true,
            ..decal
        };
        let mut decaled = procedural;
        decaled.decals.extend([decal, facing]);
        mats.decals.extend([decal, facing]);
        for mats in [mats, decaled] {
            lanes_match(&set, &faces, &mats);
        }
    }

    /// Asserts that [`texels_lanes`] gives [`texel`]'s bytes over faces `faces` of `set`.
    fn lanes_match(set: &FaceSet, faces: &[usize], mats: &MaterialSet) {
        let mut cache = NoiseCache::new(mats);
        let mut dominant = std::collections::BTreeSet::new();
        for res in [8u32, 16, 64] {
            for &f in faces {
                let constants = face_constants(&set.faces[f], res);
                let r = res as usize;
                let groups: Vec<[(u32, u32); LANES]> = (0..r * r / LANES)
                    .flat_map(|g| {
                        let row = std::array::from_fn(|l| ((g * LANES + l) % r, g * LANES / r));
                        let column = row.map(|(i, j)| (j, i));
                        let scattered = row.map(|(i, j)| ((i * 5 + j) % r, (j * 3 + i * 7) % r));
                        [row, column, scattered]
                    })
                    .map(|g| g.map(|(i, j)| (i as u32, j as u32)))
                    .collect();
                for ij in groups {
                    let got = texels_lanes(set, mats, f, res, constants, ij, &mut cache);
                    for (l, &(i, j)) in ij.iter().enumerate() {
                        let want = texel(set, mats, f, res, i, j);
                        dominant.insert(want.normal[3]);
                        assert_eq!(got[l].albedo, want.albedo, "{res} face {f} ({i}, {j})");
                        assert_eq!(got[l].normal, want.normal, "{res} face {f} ({i}, {j})");
                        assert_eq!(
                            got[l].displacement.to_bits(),
                            want.displacement.to_bits(),
                            "{res} face {f} ({i}, {j})"
                        );
                    }
                }
            }
        }
        assert!(dominant.len() >= 2, "materials {dominant:?}");
    }
}
