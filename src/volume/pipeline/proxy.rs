//! Proxy geometry (Becher §3.2–3.3): every modelling primitive becomes a triangle soup with
//! per-triangle attributes, the generalised input of the voxelization (§4.2).
//!
//! - A feature curve is discretised into line segments; each segment spans two (possibly
//!   distorted) rectangles along the interpolated left and right bitangents, two triangles each.
//!   A triangle carries the ribbon's outward normal (averaged over the segment's end points), its
//!   unit bitangent and which side it belongs to (needed by the bitangent averaging rule), the
//!   interpolated `α`, `β`, the material and the curve's seed flag.
//! - An input mesh is a triangle soup wound counter-clockwise seen from outside (the outward normal
//!   is `(v1 − v0) × (v2 − v0)`); `α`, `β` and the material are global per mesh (§4.2: imported
//!   meshes carry no noise parameters, so user-defined values are assigned). glTF parsing is not
//!   part of this module.
//! - A heightfield becomes two triangles per lattice cell, normals pointing up.
//!
//! Deviation: the paper keeps per-vertex attributes and interpolates them; a triangle here
//! carries one set (segments are at most half a voxel long, so the difference is below the
//! voxelization's own resolution).

use super::curve::FeatureCurve;
use super::grid::{add, cross, normalize, scale, sub};
use super::PipelineError;
use serde::{Deserialize, Serialize};

/// Most triangles of one input mesh or heightfield proxy.
pub const MAX_TRIANGLES: usize = 1 << 24;

/// Which ribbon of a feature curve a triangle belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Not a feature-curve triangle (no bitangent).
    None,
    /// The left ribbon (along `b_l`).
    Left,
    /// The right ribbon (along `b_r`).
    Right,
}

/// One proxy triangle with its constraint attributes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProxyTriangle {
    /// Vertices, world metres.
    pub v: [[f32; 3]; 3],
    /// Outward unit normal (into the air).
    pub normal: [f32; 3],
    /// Ribbon side, for the bitangent averaging rule.
    pub side: Side,
    /// Unit bitangent (zero when `side` is [`Side::None`]).
    pub bitangent: [f32; 3],
    /// Noise amplitude `α`.
    pub alpha: f32,
    /// Noise roughness `β`.
    pub beta: f32,
    /// Material id.
    pub material: u16,
    /// Whether the surface passes through the triangle (seed) or it only guides the normals.
    pub seed: bool,
}

/// An imported triangle mesh (§3.3).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct InputMesh {
    /// Triangles, world metres, counter-clockwise seen from outside.
    pub triangles: Vec<[[f32; 3]; 3]>,
    /// Noise amplitude assigned to the whole mesh.
    pub alpha: f32,
    /// Noise roughness assigned to the whole mesh.
    pub beta: f32,
    /// Material id of the whole mesh.
    pub material: u16,
}

/// A heightfield patch used as the lowest-priority input (§3.3): `heights[i + w·j]` is the
/// height at `(origin[0] + i·spacing, origin[1] + j·spacing)` in world (x, z).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Heightfield {
    /// World (x, z) of sample (0, 0), metres.
    pub origin: [f32; 2],
    /// Lattice spacing, metres.
    pub spacing: f32,
    /// Samples along x and z.
    pub dims: [usize; 2],
    /// Heights, metres, row-major in x.
    pub heights: Vec<f32>,
    /// Noise amplitude assigned to the heightfield.
    pub alpha: f32,
    /// Noise roughness assigned to the heightfield.
    pub beta: f32,
    /// Material id of the heightfield.
    pub material: u16,
}

/// Proxy triangles of a feature curve with segments about `step` metres long.
///
/// # Errors
/// As [`FeatureCurve::sample`].
pub fn curve_proxy(curve: &FeatureCurve, step: f32) -> Result<Vec<ProxyTriangle>, PipelineError> {
    let s = curve.sample(step)?;
    let mut out = Vec::with_capacity(4 * s.len());
    for w in s.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let alpha = 0.5 * (a.alpha + b.alpha);
        let beta = 0.5 * (a.beta + b.beta);
        for side in [Side::Left, Side::Right] {
            let (ba, bb, n) = match side {
                Side::Left => (a.b_l, b.b_l, add(a.normal_l(), b.normal_l())),
                _ => (a.b_r, b.b_r, add(a.normal_r(), b.normal_r())),
            };
            let normal = normalize(n);
            let bitangent = normalize(add(normalize(ba), normalize(bb)));
            let qa = add(a.position, ba);
            let qb = add(b.position, bb);
            for v in [[a.position, b.position, qb], [a.position, qb, qa]] {
                out.push(ProxyTriangle {
                    v,
                    normal,
                    side,
                    bitangent,
                    alpha,
                    beta,
                    material: a.material,
                    seed: curve.seed,
                });
            }
        }
    }
    Ok(out)
}

fn face_normal(v: &[[f32; 3]; 3]) -> [f32; 3] {
    normalize(cross(sub(v[1], v[0]), sub(v[2], v[0])))
}

/// Proxy triangles of an input mesh (degenerate triangles are dropped).
///
/// # Errors
/// [`PipelineError::Invalid`] naming `triangles` (too many, or a non-finite vertex) or `alpha`.
pub fn mesh_proxy(mesh: &InputMesh) -> Result<Vec<ProxyTriangle>, PipelineError> {
    if mesh.triangles.len() > MAX_TRIANGLES {
        return Err(PipelineError::invalid(
            "triangles",
            format!("at most {MAX_TRIANGLES} triangles per mesh"),
        ));
    }
    if !(mesh.alpha.is_finite() && mesh.beta.is_finite()) {
        return Err(PipelineError::invalid(
            "alpha",
            "alpha and beta must be finite",
        ));
    }
    let mut out = Vec::with_capacity(mesh.triangles.len());
    for (i, v) in mesh.triangles.iter().enumerate() {
        if v.iter().flatten().any(|c| !c.is_finite()) {
            return Err(PipelineError::invalid(
                format!("triangles[{i}]"),
                "vertices must be finite",
            ));
        }
        let normal = face_normal(v);
        if normal == [0.0; 3] {
            continue;
        }
        out.push(ProxyTriangle {
            v: *v,
            normal,
            side: Side::None,
            bitangent: [0.0; 3],
            alpha: mesh.alpha,
            beta: mesh.beta,
            material: mesh.material,
            seed: true,
        });
    }
    Ok(out)
}

/// Proxy triangles of the heightfield cells whose footprint overlaps the world (x, z) box
/// `[lo, hi]` (the region's footprint).
///
/// # Errors
/// [`PipelineError::Invalid`] naming `dims`, `heights`, `spacing`, `origin` or `alpha`.
pub fn heightfield_proxy(
    hf: &Heightfield,
    lo: [f32; 2],
    hi: [f32; 2],
) -> Result<Vec<ProxyTriangle>, PipelineError> {
    let [w, h] = hf.dims;
    if w < 2 || h < 2 || w.saturating_mul(h) > MAX_TRIANGLES / 2 {
        return Err(PipelineError::invalid(
            "dims",
            "heightfield needs at least 2×2 samples and at most 2^23",
        ));
    }
    if hf.heights.len() != w * h {
        return Err(PipelineError::invalid(
            "heights",
            format!("expected {} heights, got {}", w * h, hf.heights.len()),
        ));
    }
    if let Some(i) = hf.heights.iter().position(|v| !v.is_finite()) {
        return Err(PipelineError::invalid(
            format!("heights[{i}]"),
            "must be finite",
        ));
    }
    if !(hf.spacing.is_finite() && hf.spacing > 0.0) {
        return Err(PipelineError::invalid("spacing", "must be positive"));
    }
    if !(hf.origin[0].is_finite() && hf.origin[1].is_finite()) {
        return Err(PipelineError::invalid("origin", "must be finite"));
    }
    if !(hf.alpha.is_finite() && hf.beta.is_finite()) {
        return Err(PipelineError::invalid(
            "alpha",
            "alpha and beta must be finite",
        ));
    }
    let inv = 1.0 / hf.spacing;
    let range = |l: f32, u: f32, o: f32, n: usize| {
        let a = (((l - o) * inv).floor() as i64 - 1).clamp(0, n as i64 - 2) as usize;
        let b = (((u - o) * inv).ceil() as i64 + 1).clamp(0, n as i64 - 1) as usize;
        (a, b.max(a + 1))
    };
    let (i0, i1) = range(lo[0], hi[0], hf.origin[0], w);
    let (j0, j1) = range(lo[1], hi[1], hf.origin[1], h);
    let at = |i: usize, j: usize| {
        [
            hf.origin[0] + hf.spacing * i as f32,
            hf.heights[i + w * j],
            hf.origin[1] + hf.spacing * j as f32,
        ]
    };
    let mut out = Vec::with_capacity(2 * (i1 - i0) * (j1 - j0));
    for j in j0..j1 {
        for i in i0..i1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
            for v in [[a, c, b], [b, c, d]] {
                let normal = face_normal(&v);
                if normal == [0.0; 3] {
                    continue;
                }
                out.push(ProxyTriangle {
                    v,
                    normal,
                    side: Side::None,
                    bitangent: [0.0; 3],
                    alpha: hf.alpha,
                    beta: hf.beta,
                    material: hf.material,
                    seed: true,
                });
            }
        }
    }
    Ok(out)
}

/// The centroid of a triangle (for tests and diagnostics).
pub fn centroid(t: &ProxyTriangle) -> [f32; 3] {
    scale(add(add(t.v[0], t.v[1]), t.v[2]), 1.0 / 3.0)
}
