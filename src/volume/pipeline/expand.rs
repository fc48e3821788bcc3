//! Feature-curve expansion (Becher §5.1), the pipeline's optional stage 2a: every feature curve is
//! extended from both ends by small steps along `N × B`, the cross product of the diffused normal
//! field and a smooth bitangent field; after each covered distance a control vertex is added; a
//! branch stops when it would leave the computational domain or come too close to another
//! curve. The voxelization and the normal diffusion are then run again on the expanded curves
//! ([`expand_scene`]; `region::generate` calls it when `PipelineParams::expand` is set), so `N`
//! matches them.
//!
//! Why one file of about 830 lines (200 of tests): the bitangent smoothing, the tracing of branches
//! and the rebuild of a curve are the stages of one §5.1 expansion over the shared `Guidance` and
//! `Branch` types.
//!
//! # The smooth bitangent field (§5.1)
//!
//! `B` is sign-free: `b` and `−b` describe the same ribbon direction, so diffusing it like `N`
//! (a neighbourhood mean) would cancel opposite-signed neighbours. As the paper does, each
//! sample's bitangent is approximated by successive pair-wise averaging over its local
//! neighbourhood with the sign-insensitive average
//!
//! `avg(a, b) = normalize(a + sign(a·b)·b)` (`avg(0, b) = b`),
//!
//! [`smooth_bitangents`]: first the samples outside `Ω_B` are filled in wavefront layers (each
//! sample from its six neighbours set in earlier layers), then a few Jacobi sweeps re-average
//! every sample outside `Ω_B` with its neighbours; `Ω_B` stays fixed. The neighbours are folded
//! in the fixed order −x, +x, −y, +y, −z, +z. **Order bias**, as the paper warns: `avg` is
//! neither commutative in sign nor associative, so the first non-zero neighbour decides the sign
//! the others are flipped to, and in the fold the last neighbour weighs ½, the one before ¼, and
//! so on — the field leans toward the +z, then −z, then +y … neighbours. The bias is
//! deterministic (a fixed order, no dependence on threads or hashing), and the sign does not
//! matter to the expansion, which orients `N × B` along its previous step.
//!
//! # Stepping
//!
//! A branch starts at a curve end `p₀` heading along the outward tangent. Each step: `N` is the
//! trilinear interpolation of the diffused normals at `p` (normalised), `B` the smooth bitangent
//! of the nearest sample, `d = normalize(N × B)` flipped if needed so that `d · d_prev ≥ 0`, and
//! `p ← p + step_m·d`. After every `round(spacing_m / step_m)` accepted steps the current point
//! becomes a new control vertex. A branch stops (the step is not taken and the distance covered
//! since the last vertex is dropped) when the next point would leave the grid's box, when
//! `|N × B| < 10⁻³` (no direction), when it would come closer than `min_distance_m` to another
//! curve, after `max_length_m` metres or [`MAX_EXPANSION_STEPS`] steps, or when the curve would
//! exceed [`MAX_CONTROL_POINTS`](super::curve::MAX_CONTROL_POINTS).
//!
//! Curves are expanded one after another in document order, each against the others' current
//! control polygons; a final pass trims every added vertex (and what follows it on its branch)
//! that a later expansion brought within `min_distance_m` of another curve. Trimming only
//! shortens polygons, so one pass suffices: afterwards every added control vertex is at least
//! `min_distance_m` from every other curve's control polygon (tested).
//!
//! # The expanded curve
//!
//! New vertices are appended (forward branch) or prepended (backward branch) to the control
//! points. The curve stays a clamped uniform cubic B-spline over `t ∈ [0, 1]`, so the original
//! constraint points are re-parametrised onto the original spans:
//! `t' = (b + t·(m − 3)) / (m + a + b − 3)` with `m` original control points, `b` prepended and
//! `a` appended. A branch that
//! added vertices gets a new end constraint point copying the old end's `α`, `β`, material and
//! bitangents, the bitangents re-expressed in the frame of the new end (tangent, the sampled `N`)
//! with the same components they had in the frame of the old end — so a ribbon's width and droop
//! relative to the surface carry over.
//!
//! # Deviations
//!
//! - "Too close to another feature curve" is measured to the other curves' control polygons, not
//!   to the splines: the polygon is what expansion appends to, and uniform re-parametrisation
//!   moves a spline slightly when vertices are added. A cubic B-spline lies in the convex hull of
//!   its control polygon.
//! - The added vertices sit on the traced path, and the spline through them smooths it; the
//!   original part of a curve moves slightly because its knots are re-spaced uniformly.
//! - The first guidance pass is a whole `generate` run without expansion (its surface
//!   propagation and filter are discarded): simple, about one extra pipeline run of cost. The
//!   stage times `generate` returns are those of the final run; the expansion is not in them.
//! - The smooth bitangent field has a WGSL twin, `shaders/volume_bitangent.wgsl`
//!   (`gpu::volume_bitangent`, bit-identical on lavapipe in `tests/gpu_volume_bitangent.rs`).
//!   The stepping has none: it follows one curve end at a time, a sequential walk of a few
//!   hundred steps whose every step depends on the previous one.

use super::curve::{ConstraintPoint, FeatureCurve, MAX_CONTROL_POINTS};
use super::grid::{add, cross, dot, length, normalize, scale, sub, Grid};
use super::region::{PipelineParams, Scene};
use super::PipelineError;
use crate::terrain::cancel::Cancel;
use crate::volume::offload::{CpuOnly, VolumeOffload};
use serde::{Deserialize, Serialize};

/// Most steps of one branch (one curve end).
pub const MAX_EXPANSION_STEPS: usize = 4096;
/// Jacobi sweeps of [`smooth_bitangents`] after the wavefront fill.
pub const BITANGENT_SWEEPS: usize = 2;

/// Settings of the expansion (element field `expand_curves`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExpandParams {
    /// Length of one step along `N × B`, metres.
    #[serde(default = "default_step")]
    pub step_m: f32,
    /// Distance covered between two added control vertices, metres (rounded to whole steps).
    #[serde(default = "default_spacing")]
    pub spacing_m: f32,
    /// A branch stops before coming closer than this to another curve, metres.
    #[serde(default = "default_min_distance")]
    pub min_distance_m: f32,
    /// Longest branch, metres.
    #[serde(default = "default_max_length")]
    pub max_length_m: f32,
}

fn default_step() -> f32 {
    0.5
}

fn default_spacing() -> f32 {
    4.0
}

fn default_min_distance() -> f32 {
    4.0
}

fn default_max_length() -> f32 {
    64.0
}

impl Default for ExpandParams {
    fn default() -> Self {
        Self {
            step_m: default_step(),
            spacing_m: default_spacing(),
            min_distance_m: default_min_distance(),
            max_length_m: default_max_length(),
        }
    }
}

impl ExpandParams {
    /// Checks the settings.
    ///
    /// # Errors
    /// [`PipelineError::Invalid`] naming the field: `step_m` not in `[0.05, 16]` m, `spacing_m`
    /// below `step_m` or above 256 m, `min_distance_m` not in `[0, 256]` m, `max_length_m` not in
    /// `[0, 4096]` m.
    pub fn validate(&self) -> Result<(), PipelineError> {
        let within = |v: f32, lo: f32, hi: f32| v.is_finite() && (lo..=hi).contains(&v);
        if !within(self.step_m, 0.05, 16.0) {
            return Err(PipelineError::invalid(
                "step_m",
                "must be in [0.05, 16] metres",
            ));
        }
        if !within(self.spacing_m, self.step_m, 256.0) {
            return Err(PipelineError::invalid(
                "spacing_m",
                "must be in [step_m, 256] metres",
            ));
        }
        if !within(self.min_distance_m, 0.0, 256.0) {
            return Err(PipelineError::invalid(
                "min_distance_m",
                "must be in [0, 256] metres",
            ));
        }
        if !within(self.max_length_m, 0.0, 4096.0) {
            return Err(PipelineError::invalid(
                "max_length_m",
                "must be in [0, 4096] metres",
            ));
        }
        Ok(())
    }

    fn steps_per_vertex(&self) -> usize {
        ((self.spacing_m / self.step_m).round() as usize).max(1)
    }
}

/// The sign-insensitive pair-wise average `normalize(a + sign(a·b)·b)`; `b` when `a` is zero.
pub fn sign_free_average(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    if a == [0.0; 3] {
        return b;
    }
    if b == [0.0; 3] {
        return a;
    }
    let s = if dot(a, b) < 0.0 { -1.0 } else { 1.0 };
    let r = normalize(add(a, scale(b, s)));
    if r == [0.0; 3] {
        a
    } else {
        r
    }
}

/// The six neighbours of sample `c` in the fixed fold order −x, +x, −y, +y, −z, +z.
fn neighbours(dims: [usize; 3], c: [usize; 3]) -> [Option<usize>; 6] {
    let idx = |x: usize, y: usize, z: usize| x + dims[0] * (y + dims[1] * z);
    let [x, y, z] = c;
    [
        (x > 0).then(|| idx(x - 1, y, z)),
        (x + 1 < dims[0]).then(|| idx(x + 1, y, z)),
        (y > 0).then(|| idx(x, y - 1, z)),
        (y + 1 < dims[1]).then(|| idx(x, y + 1, z)),
        (z > 0).then(|| idx(x, y, z - 1)),
        (z + 1 < dims[2]).then(|| idx(x, y, z + 1)),
    ]
}

fn get(f: &[Vec<f32>; 3], i: usize) -> [f32; 3] {
    [f[0][i], f[1][i], f[2][i]]
}

fn put(f: &mut [Vec<f32>; 3], i: usize, v: [f32; 3]) {
    for k in 0..3 {
        f[k][i] = v[k];
    }
}

/// The smooth, dense bitangent field of §5.1 from the voxelized sparse `B` (module docs):
/// samples with a non-zero `sparse` vector (`Ω_B`) keep it (normalised); the others are filled
/// by wavefront layers of sign-free pair-wise averages, then `sweeps` Jacobi sweeps. Samples no
/// wavefront reaches (only when `Ω_B` is empty) stay zero.
pub fn smooth_bitangents(dims: [usize; 3], sparse: &[Vec<f32>; 3], sweeps: usize) -> [Vec<f32>; 3] {
    let n = dims[0] * dims[1] * dims[2];
    let mut b: [Vec<f32>; 3] = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    // Layer of each sample: 0 = Ω_B, u32::MAX = not reached yet.
    let mut layer = vec![u32::MAX; n];
    let mut front = Vec::new();
    for i in 0..n {
        let v = normalize(get(sparse, i));
        if v != [0.0; 3] {
            put(&mut b, i, v);
            layer[i] = 0;
            front.push(i);
        }
    }
    let coords = |i: usize| {
        [
            i % dims[0],
            (i / dims[0]) % dims[1],
            i / (dims[0] * dims[1]),
        ]
    };
    let mut l = 0u32;
    while !front.is_empty() {
        l += 1;
        let mut next = Vec::new();
        for &i in &front {
            for j in neighbours(dims, coords(i)).into_iter().flatten() {
                if layer[j] == u32::MAX {
                    layer[j] = l;
                    next.push(j);
                }
            }
        }
        // Sorted so the result does not depend on discovery order (it already cannot: each
        // value reads only earlier layers; sorting keeps memory access regular).
        next.sort_unstable();
        for &i in &next {
            let mut acc = [0.0; 3];
            for j in neighbours(dims, coords(i)).into_iter().flatten() {
                if layer[j] < l {
                    acc = sign_free_average(acc, get(&b, j));
                }
            }
            put(&mut b, i, acc);
        }
        front = next;
    }
    for _ in 0..sweeps {
        let prev = b.clone();
        for i in 0..n {
            if layer[i] == 0 || layer[i] == u32::MAX {
                continue;
            }
            let mut acc = get(&prev, i);
            for j in neighbours(dims, coords(i)).into_iter().flatten() {
                acc = sign_free_average(acc, get(&prev, j));
            }
            put(&mut b, i, acc);
        }
    }
    b
}

/// Trilinear interpolation of a three-component field at grid coordinates `g` (clamped).
fn trilinear(grid: &Grid, f: [&[f32]; 3], g: [f32; 3]) -> [f32; 3] {
    let d = grid.dims;
    let c: [f32; 3] = std::array::from_fn(|k| g[k].clamp(0.0, (d[k] - 1) as f32));
    let i: [usize; 3] = std::array::from_fn(|k| (c[k] as usize).min(d[k] - 2));
    let t: [f32; 3] = std::array::from_fn(|k| c[k] - i[k] as f32);
    let mut out = [0.0; 3];
    for corner in 0..8 {
        let o = [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1];
        let w: f32 = (0..3)
            .map(|k| if o[k] == 1 { t[k] } else { 1.0 - t[k] })
            .product();
        let idx = grid.index(i[0] + o[0], i[1] + o[1], i[2] + o[2]);
        for k in 0..3 {
            out[k] += w * f[k][idx];
        }
    }
    out
}

/// The field vector of the sample nearest to grid coordinates `g` (clamped).
fn nearest(grid: &Grid, f: [&[f32]; 3], g: [f32; 3]) -> [f32; 3] {
    let d = grid.dims;
    let i: [usize; 3] = std::array::from_fn(|k| (g[k].round().max(0.0) as usize).min(d[k] - 1));
    let idx = grid.index(i[0], i[1], i[2]);
    [f[0][idx], f[1][idx], f[2][idx]]
}

/// The guidance the expansion steps along: diffused normals and the smooth bitangent field.
#[derive(Clone, Copy, Debug)]
pub struct Guidance<'a> {
    /// The grid both fields live on.
    pub grid: &'a Grid,
    /// Dense unit normals `N`.
    pub normal: [&'a [f32]; 3],
    /// Dense smooth bitangents ([`smooth_bitangents`]).
    pub bitangent: [&'a [f32]; 3],
}

impl Guidance<'_> {
    /// The normalised `N` at world point `p`.
    pub fn normal_at(&self, p: [f32; 3]) -> [f32; 3] {
        normalize(trilinear(self.grid, self.normal, self.grid.to_grid(p)))
    }

    /// `N(p) × B(p)` at world point `p` (not normalised; sign arbitrary).
    pub fn direction_at(&self, p: [f32; 3]) -> [f32; 3] {
        let b = nearest(self.grid, self.bitangent, self.grid.to_grid(p));
        cross(self.normal_at(p), b)
    }

    fn inside(&self, p: [f32; 3]) -> bool {
        let g = self.grid.to_grid(p);
        (0..3).all(|k| g[k] >= 0.0 && g[k] <= (self.grid.dims[k] - 1) as f32)
    }
}

/// One expanded end of a curve.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Branch {
    /// The accepted step points, starting with the curve's end point.
    pub trace: Vec<[f32; 3]>,
    /// The added control vertices in order away from the curve (each a point of `trace`).
    pub vertices: Vec<[f32; 3]>,
}

/// The result of [`expand_curves`].
#[derive(Clone, Debug, PartialEq)]
pub struct Expansion {
    /// The expanded curves, in input order.
    pub curves: Vec<FeatureCurve>,
    /// Per curve: the backward branch (from `t = 0`) and the forward branch (from `t = 1`).
    pub branches: Vec<[Branch; 2]>,
}

/// Squared distance from `p` to the segment `[a, b]`.
fn dist2_segment(p: [f32; 3], a: [f32; 3], b: [f32; 3]) -> f32 {
    let ab = sub(b, a);
    let l2 = dot(ab, ab);
    let t = if l2 > 0.0 {
        (dot(sub(p, a), ab) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = add(a, scale(ab, t));
    let d = sub(p, q);
    dot(d, d)
}

/// Distance from `p` to a polyline (a single point counts as a polyline).
pub fn polygon_distance(p: [f32; 3], poly: &[[f32; 3]]) -> f32 {
    match poly {
        [] => f32::INFINITY,
        [a] => length(sub(p, *a)),
        _ => poly
            .windows(2)
            .map(|w| dist2_segment(p, w[0], w[1]))
            .fold(f32::INFINITY, f32::min)
            .sqrt(),
    }
}

/// The current control polygon of curve `c`: its control points with the branches' vertices.
fn polygon(curve: &FeatureCurve, b: &[Branch; 2]) -> Vec<[f32; 3]> {
    let mut out: Vec<[f32; 3]> = b[0].vertices.iter().rev().copied().collect();
    out.extend_from_slice(&curve.control_points);
    out.extend_from_slice(&b[1].vertices);
    out
}

/// Traces one branch from `start` heading along `heading`.
fn trace(
    g: &Guidance<'_>,
    start: [f32; 3],
    heading: [f32; 3],
    p: &ExpandParams,
    budget: usize,
    too_close: &dyn Fn([f32; 3]) -> bool,
) -> Branch {
    let mut b = Branch {
        trace: vec![start],
        vertices: Vec::new(),
    };
    let per = p.steps_per_vertex();
    let max_steps = ((p.max_length_m / p.step_m).floor() as usize).min(MAX_EXPANSION_STEPS);
    let (mut pos, mut prev) = (start, normalize(heading));
    if prev == [0.0; 3] {
        return b;
    }
    for step in 1..=max_steps {
        if b.vertices.len() >= budget {
            break;
        }
        let raw = g.direction_at(pos);
        if length(raw) < 1e-3 {
            break;
        }
        let mut d = normalize(raw);
        if dot(d, prev) < 0.0 {
            d = scale(d, -1.0);
        }
        let next = add(pos, scale(d, p.step_m));
        if !g.inside(next) || too_close(next) {
            break;
        }
        b.trace.push(next);
        pos = next;
        prev = d;
        if step % per == 0 {
            b.vertices.push(next);
        }
    }
    // Step points past the last vertex are not part of the curve.
    b.trace.truncate(1 + per * b.vertices.len());
    b
}

/// Bitangent `b` (⊥ `tan`) as components along `(tan × n, n)` of the frame with normal `n`.
fn frame_coords(b: [f32; 3], tan: [f32; 3], n: [f32; 3]) -> Option<[f32; 2]> {
    let n = normalize(sub(n, scale(tan, dot(n, tan))));
    if n == [0.0; 3] {
        return None;
    }
    let s = cross(tan, n);
    Some([dot(b, s), dot(b, n)])
}

fn from_frame(c: [f32; 2], tan: [f32; 3], n: [f32; 3]) -> Option<[f32; 3]> {
    let n = normalize(sub(n, scale(tan, dot(n, tan))));
    if n == [0.0; 3] {
        return None;
    }
    let s = cross(tan, n);
    Some(add(scale(s, c[0]), scale(n, c[1])))
}

/// The curve with the branches' vertices added and its constraints re-parametrised (module
/// docs), or the curve unchanged if the result would not be a valid curve.
fn rebuild(g: &Guidance<'_>, curve: &FeatureCurve, br: &[Branch; 2]) -> FeatureCurve {
    let (b, a) = (br[0].vertices.len(), br[1].vertices.len());
    if a == 0 && b == 0 {
        return curve.clone();
    }
    let m = curve.control_points.len();
    let mut out = FeatureCurve {
        control_points: polygon(curve, br),
        constraints: Vec::new(),
        seed: curve.seed,
    };
    let spans = (m + a + b - 3) as f32;
    let remap = |t: f32| (b as f32 + t * (m - 3) as f32) / spans;
    // A constraint carried to a new end, its bitangents in the new end's frame.
    let carried = |old: &ConstraintPoint, t_old: f32, t_new: f32, out: &FeatureCurve| {
        let (p_old, p_new) = (curve.position(t_old), out.position(t_new));
        let (tan_old, tan_new) = (
            normalize(curve.derivative(t_old)),
            normalize(out.derivative(t_new)),
        );
        let (n_old, n_new) = (g.normal_at(p_old), g.normal_at(p_new));
        let move_b = |v: [f32; 3]| {
            let c = frame_coords(v, tan_old, n_old)?;
            from_frame(c, tan_new, n_new)
        };
        Some(ConstraintPoint {
            t: t_new,
            b_l: move_b(old.b_l)?,
            b_r: move_b(old.b_r)?,
            ..*old
        })
    };
    let first = curve.constraints[0];
    let last = curve.constraints[curve.constraints.len() - 1];
    let mut cs = Vec::with_capacity(curve.constraints.len() + 2);
    let mut shape = out.clone();
    shape.constraints = Vec::new();
    if b > 0 {
        match carried(&first, 0.0, 0.0, &shape) {
            Some(c) => cs.push(c),
            None => return curve.clone(),
        }
    }
    cs.extend(curve.constraints.iter().map(|c| ConstraintPoint {
        t: remap(c.t),
        ..*c
    }));
    if a > 0 {
        match carried(&last, 1.0, 1.0, &shape) {
            Some(c) => cs.push(c),
            None => return curve.clone(),
        }
    }
    // Rounding of the re-parametrisation must keep the ends exact.
    if b == 0 {
        cs[0].t = 0.0;
    }
    if a == 0 {
        let k = cs.len() - 1;
        cs[k].t = 1.0;
    }
    out.constraints = cs;
    if out.validate().is_err() {
        return curve.clone();
    }
    out
}

/// Expands `curves` along the guidance fields (module docs).
///
/// # Errors
/// [`PipelineError::Invalid`] for invalid `params` or an invalid curve (`curves[i]…`).
pub fn expand_curves(
    g: &Guidance<'_>,
    curves: &[FeatureCurve],
    params: &ExpandParams,
) -> Result<Expansion, PipelineError> {
    params.validate()?;
    for (i, c) in curves.iter().enumerate() {
        c.validate()
            .map_err(|e| e.within(&format!("curves[{i}]")))?;
    }
    let mut branches: Vec<[Branch; 2]> = vec![Default::default(); curves.len()];
    let md = params.min_distance_m;
    for i in 0..curves.len() {
        let others: Vec<Vec<[f32; 3]>> = (0..curves.len())
            .filter(|&j| j != i)
            .map(|j| polygon(&curves[j], &branches[j]))
            .collect();
        let too_close = |p: [f32; 3]| others.iter().any(|poly| polygon_distance(p, poly) < md);
        let c = &curves[i];
        let budget = MAX_CONTROL_POINTS.saturating_sub(c.control_points.len());
        let back = trace(
            g,
            c.position(0.0),
            scale(c.derivative(0.0), -1.0),
            params,
            budget,
            &too_close,
        );
        let fwd = trace(
            g,
            c.position(1.0),
            c.derivative(1.0),
            params,
            budget.saturating_sub(back.vertices.len()),
            &too_close,
        );
        branches[i] = [back, fwd];
    }
    // Trim vertices a later expansion brought too close (module docs).
    let per = params.steps_per_vertex();
    for i in 0..curves.len() {
        for end in 0..2 {
            let others: Vec<Vec<[f32; 3]>> = (0..curves.len())
                .filter(|&j| j != i)
                .map(|j| polygon(&curves[j], &branches[j]))
                .collect();
            let br = &mut branches[i][end];
            if let Some(k) = br
                .vertices
                .iter()
                .position(|v| others.iter().any(|poly| polygon_distance(*v, poly) < md))
            {
                br.vertices.truncate(k);
                br.trace.truncate(1 + per * k);
            }
        }
    }
    let curves = curves
        .iter()
        .zip(&branches)
        .map(|(c, b)| rebuild(g, c, b))
        .collect();
    Ok(Expansion { curves, branches })
}

/// The scene with its curves expanded: one pipeline run without expansion gives `N` and the
/// voxelized `B`, [`smooth_bitangents`] densifies `B`, and [`expand_curves`] traces the curves.
///
/// # Errors
/// As [`super::generate`] and [`expand_curves`].
pub fn expand_scene(
    grid: &Grid,
    scene: &Scene,
    params: &PipelineParams,
    expand: &ExpandParams,
) -> Result<Scene, PipelineError> {
    expand_scene_on(grid, scene, params, expand, &CpuOnly, &Cancel::never())
}

/// [`expand_scene`] with the guidance pass's twinned stages and the smooth bitangents offered
/// to `dev` ([`crate::volume::offload`]), polling `cancel` in the guidance pass
/// ([`super::generate_on`]) and after it.
///
/// # Errors
/// As [`expand_scene`], and [`PipelineError::Cancelled`] once `cancel` is set.
pub fn expand_scene_on(
    grid: &Grid,
    scene: &Scene,
    params: &PipelineParams,
    expand: &ExpandParams,
    dev: &dyn VolumeOffload,
    cancel: &Cancel,
) -> Result<Scene, PipelineError> {
    expand.validate().map_err(|e| e.within("expand_curves"))?;
    if scene.curves.is_empty() {
        return Ok(scene.clone());
    }
    let first = super::region::generate_on(
        grid,
        scene,
        &PipelineParams {
            expand: None,
            ..*params
        },
        dev,
        cancel,
    )?;
    cancel.check().map_err(|_| PipelineError::Cancelled)?;
    let b = dev
        .smooth_bitangents(grid.dims, &first.bitangent, BITANGENT_SWEEPS)
        .filter(|b| b.iter().all(|c| c.len() == grid.len()))
        .unwrap_or_else(|| smooth_bitangents(grid.dims, &first.bitangent, BITANGENT_SWEEPS));
    let g = Guidance {
        grid,
        normal: [&first.normal[0], &first.normal[1], &first.normal[2]],
        bitangent: [&b[0], &b[1], &b[2]],
    };
    let e = expand_curves(&g, &scene.curves, expand)?;
    Ok(Scene {
        curves: e.curves,
        ..scene.clone()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::volume::pipeline::generate;

    #[test]
    fn sign_free_average_ignores_signs() {
        let x = [1.0, 0.0, 0.0];
        let mx = [-1.0, 0.0, 0.0];
        assert_eq!(sign_free_average(x, mx), x);
        assert_eq!(sign_free_average([0.0; 3], mx), mx);
        let y = [0.0, 1.0, 0.0];
        let a = sign_free_average(x, y);
        let b = sign_free_average(x, scale(y, -1.0));
        assert!((dot(a, x) - dot(b, x)).abs() < 1e-6);
    }

    #[test]
    fn smooth_field_is_dense_fixed_on_omega_b_and_sign_smooth() {
        let dims = [9, 5, 7];
        let n = 9 * 5 * 7;
        let mut sparse: [Vec<f32>; 3] = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        // Two constraints of opposite sign along z: a mean would cancel them.
        let i0 = 1 + 9 * (2 + 5 * 3);
        let i1 = 7 + 9 * (2 + 5 * 3);
        sparse[2][i0] = 1.0;
        sparse[2][i1] = -1.0;
        let b = smooth_bitangents(dims, &sparse, BITANGENT_SWEEPS);
        assert_eq!(get(&b, i0), [0.0, 0.0, 1.0]);
        assert_eq!(get(&b, i1), [0.0, 0.0, -1.0]);
        for i in 0..n {
            let v = get(&b, i);
            assert!((length(v) - 1.0).abs() < 1e-4, "sample {i} is unit");
            assert!(v[2].abs() > 0.999, "sample {i} is ±z: {v:?}");
        }
        assert_eq!(b, smooth_bitangents(dims, &sparse, BITANGENT_SWEEPS));
    }

    /// Flat ground at y = 6 m in a 48 × 24 × 32 m box; curve A a ridge along x (14 → 24 m) at
    /// y = 12 m, z = 16 m, ribbons 3 m wide; curve B along z (4 → 28 m) at x = 30 m, y = 12 m,
    /// ribbons 1 m wide; both facing up.
    fn scene() -> (Grid, Scene, PipelineParams) {
        let grid = Grid::new([49, 25, 33], [0.0; 3], 1.0).expect("grid");
        let a = super::super::scenes::facing_curve(
            &[
                [14.0, 12.0, 16.0],
                [17.0, 12.0, 16.0],
                [21.0, 12.0, 16.0],
                [24.0, 12.0, 16.0],
            ],
            [0.0, 1.0, 0.0],
            3.0,
            1,
        );
        let b = super::super::scenes::facing_curve(
            &[
                [30.0, 12.0, 4.0],
                [30.0, 12.0, 12.0],
                [30.0, 12.0, 20.0],
                [30.0, 12.0, 28.0],
            ],
            [0.0, 1.0, 0.0],
            1.0,
            2,
        );
        let scene = Scene {
            curves: vec![a, b],
            meshes: Vec::new(),
            heightfield: Some(super::super::scenes::flat_ground(
                6.0, -4.0, 52.0, -4.0, 36.0,
            )),
        };
        (grid, scene, PipelineParams::default())
    }

    fn guidance_fields(
        grid: &Grid,
        scene: &Scene,
        params: &PipelineParams,
    ) -> (super::super::RegionFields, [Vec<f32>; 3]) {
        let first = generate(grid, scene, params).expect("first pass");
        let b = smooth_bitangents(grid.dims, &first.bitangent, BITANGENT_SWEEPS);
        (first, b)
    }

    #[test]
    fn expansion_follows_n_cross_b_keeps_its_distance_and_stays_inside() {
        let (grid, scene, params) = scene();
        let (first, b) = guidance_fields(&grid, &scene, &params);
        let g = Guidance {
            grid: &grid,
            normal: [&first.normal[0], &first.normal[1], &first.normal[2]],
            bitangent: [&b[0], &b[1], &b[2]],
        };
        let p = ExpandParams {
            step_m: 0.5,
            spacing_m: 2.0,
            min_distance_m: 4.0,
            max_length_m: 64.0,
        };
        let e = expand_curves(&g, &scene.curves, &p).expect("expanded");
        let per = p.steps_per_vertex();
        assert_eq!(per, 4);
        let mut added = 0;
        for (ci, br) in e.branches.iter().enumerate() {
            for branch in br {
                // Every step is step_m along ±normalize(N × B) at its start point.
                for w in branch.trace.windows(2) {
                    let d = scale(sub(w[1], w[0]), 1.0 / p.step_m);
                    let want = normalize(g.direction_at(w[0]));
                    let err = length(sub(d, want)).min(length(add(d, want)));
                    assert!(err < 1e-4, "curve {ci}: step {d:?} vs ±{want:?}");
                    assert!(g.inside(w[1]), "curve {ci}: {:?} left the domain", w[1]);
                }
                // Vertices sit on the trace after every `per` steps.
                for (k, v) in branch.vertices.iter().enumerate() {
                    assert_eq!(*v, branch.trace[(k + 1) * per], "curve {ci} vertex {k}");
                }
                added += branch.vertices.len();
            }
        }
        // No added vertex comes closer than min_distance to another curve's final polygon.
        for (i, br) in e.branches.iter().enumerate() {
            for v in br.iter().flat_map(|b| &b.vertices) {
                for (j, c) in e.curves.iter().enumerate() {
                    if i != j {
                        let d = polygon_distance(*v, &c.control_points);
                        assert!(
                            d >= p.min_distance_m,
                            "curve {i} vertex {v:?} is {d} m from curve {j}"
                        );
                    }
                }
            }
        }
        // Curve A grew both ways: to the border (x = 0) and toward B (x = 30), stopping where
        // the next step would come within 4 m of it.
        let fwd = &e.branches[0][1].vertices;
        let back = &e.branches[0][0].vertices;
        assert!(
            !fwd.is_empty() && back.len() >= 4,
            "fwd {fwd:?} back {back:?}"
        );
        let last = fwd[fwd.len() - 1];
        eprintln!(
            "A: {} vertices back to {:?}, {} forward to {last:?}; B: {} and {} added",
            back.len(),
            back[back.len() - 1],
            fwd.len(),
            e.branches[1][0].vertices.len(),
            e.branches[1][1].vertices.len()
        );
        assert!(
            last[0] <= 26.0 + 1e-3 && last[0] > 25.0,
            "A stops before B: {last:?}"
        );
        assert!(
            back[back.len() - 1][0] < 4.0,
            "A reaches the border: {back:?}"
        );
        assert!(added > 0);
        for c in &e.curves {
            c.validate().expect("expanded curves are valid");
        }
        assert_eq!(e.curves[0].control_points.len(), 4 + fwd.len() + back.len());
        // Deterministic.
        assert_eq!(e, expand_curves(&g, &scene.curves, &p).expect("again"));
    }

    #[test]
    fn the_pipeline_stage_updates_n_for_the_expanded_curves() {
        let (grid, scene, params) = scene();
        let plain = generate(&grid, &scene, &params).expect("plain");
        let with = PipelineParams {
            expand: Some(ExpandParams::default()),
            ..params
        };
        let expanded =
            expand_scene(&grid, &scene, &params, &ExpandParams::default()).expect("expand");
        assert_eq!(
            expanded,
            expand_scene(&grid, &scene, &params, &ExpandParams::default()).expect("again")
        );
        assert!(expanded.curves[0].control_points.len() > scene.curves[0].control_points.len());
        let fields = generate(&grid, &scene, &with).expect("expanded run");
        let count = |f: &super::super::RegionFields| {
            f.voxelized.omega_n.iter().filter(|&&o| o != 0).count()
        };
        assert!(
            count(&fields) > count(&plain),
            "the expanded curves constrain more samples: {} vs {}",
            count(&fields),
            count(&plain)
        );
        let direct = generate(&grid, &expanded, &params).expect("direct");
        assert_eq!(
            fields.surface, direct.surface,
            "the stage is expand then solve"
        );
    }
}
