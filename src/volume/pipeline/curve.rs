//! Feature curves (Becher §3.1): cubic B-splines with constraint points.
//!
//! A curve is `F(t) = (B(t), P(t), s)`: a clamped uniform cubic B-spline `B` over `t ∈ [0, 1]`
//! (it passes through its first and last control points), constraint points
//! `(b_l, b_r, α, β, m, t)` interpolated by `P`, and the seed flag `s` (a seed curve lies on the
//! surface; a guidance curve only steers the normals).
//!
//! Interpolation along the curve, as §3.1 prescribes: `α` and `β` linearly; the material id by
//! nearest neighbour in `t`; the bitangents through a rotation-minimising frame (RMF). The frame is
//! transported along the sampled curve with the double-reflection method of Wang, Jüttler, Zheng
//! and Liu (*Computation of rotation minimizing frames*, ACM TOG 27(1), 2008) — the paper's
//! "rotational transformation computed from known curve tangents". Each constraint bitangent is
//! expressed in that frame as an angle and a length; between two constraint points both are
//! interpolated linearly (the angle the short way round), and the bitangent is rebuilt in the
//! local frame. It is therefore perpendicular to the tangent by construction and rotates no
//! more between samples than the frame does plus the constraint's share of twist.
//!
//! Orientation convention (ours; the paper fixes none): `b_l` points to the left ribbon, `b_r` to
//! the right ribbon, and the ribbons' outward normals (pointing into the air, towards `S > 0`) are
//! `n_l = t̂ × b_l` and `n_r = b_r × t̂`. For a curve running along +x with `b_l = −z`,
//! `b_r = +z` both normals point up (+y). [`ConstraintPoint::facing`] builds bitangents for a
//! wanted normal. The bitangent's length is the ribbon's width in metres.

use super::grid::{add, cross, dot, length, normalize, scale, sub};
use super::PipelineError;
use serde::{Deserialize, Serialize};

/// Most control points of one curve.
pub const MAX_CONTROL_POINTS: usize = 4096;
/// Most samples one curve is discretised into.
pub const MAX_CURVE_SAMPLES: usize = 1 << 16;

/// A constraint point `(b_l, b_r, α, β, m, t)` attached to a feature curve.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConstraintPoint {
    /// Position on the curve in parameter space, `[0, 1]`.
    pub t: f32,
    /// Left-hand bitangent, metres (its length is the left ribbon's width).
    pub b_l: [f32; 3],
    /// Right-hand bitangent, metres.
    pub b_r: [f32; 3],
    /// Noise amplitude parameter `α` (metres of displacement at the mesher).
    pub alpha: f32,
    /// Noise roughness parameter `β` (dimensionless).
    pub beta: f32,
    /// Surface material id.
    pub material: u16,
}

impl ConstraintPoint {
    /// A constraint point at `t` of `curve` whose ribbons both face `normal` (tilted away from it
    /// by `droop` radians: 0 is a flat ribbon pair, positive values make a ridge), each `width`
    /// metres wide.
    #[allow(clippy::too_many_arguments)]
    pub fn facing(
        curve: &FeatureCurve,
        t: f32,
        normal: [f32; 3],
        width: f32,
        droop: f32,
        alpha: f32,
        beta: f32,
        material: u16,
    ) -> Self {
        let tan = normalize(curve.derivative(t));
        let n = normalize(sub(normal, scale(tan, dot(normal, tan))));
        // t × (n × t) = n and (t × n) × t = n for unit n ⊥ t.
        let left = normalize(cross(n, tan));
        let (c, s) = (droop.cos(), droop.sin());
        let b_l = scale(sub(scale(left, c), scale(n, s)), width);
        let b_r = scale(sub(scale(left, -c), scale(n, s)), width);
        Self {
            t,
            b_l,
            b_r,
            alpha,
            beta,
            material,
        }
    }
}

/// A feature curve (§3.1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FeatureCurve {
    /// Control vertices of the clamped uniform cubic B-spline, world metres (at least 4).
    pub control_points: Vec<[f32; 3]>,
    /// Constraint points sorted by strictly increasing `t`; the first at `t = 0`, the last at
    /// `t = 1` (§3.1: "a minimum of two constraint points attached to the curve's endpoints").
    pub constraints: Vec<ConstraintPoint>,
    /// Seed primitive (`true`: the surface passes through the curve) or guidance primitive.
    pub seed: bool,
}

/// One sample of a discretised feature curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveSample {
    /// Curve parameter.
    pub t: f32,
    /// Position `B(t)`, metres.
    pub position: [f32; 3],
    /// Unit tangent.
    pub tangent: [f32; 3],
    /// Interpolated left bitangent, metres (perpendicular to `tangent`).
    pub b_l: [f32; 3],
    /// Interpolated right bitangent, metres.
    pub b_r: [f32; 3],
    /// Interpolated `α`.
    pub alpha: f32,
    /// Interpolated `β`.
    pub beta: f32,
    /// Nearest constraint point's material.
    pub material: u16,
}

impl CurveSample {
    /// Outward unit normal of the left ribbon, `t̂ × b_l`.
    pub fn normal_l(&self) -> [f32; 3] {
        normalize(cross(self.tangent, self.b_l))
    }

    /// Outward unit normal of the right ribbon, `b_r × t̂`.
    pub fn normal_r(&self) -> [f32; 3] {
        normalize(cross(self.b_r, self.tangent))
    }
}

fn knots(m: usize) -> Vec<f32> {
    let inner = m - 3;
    let mut u = vec![0.0; 4];
    u.extend((1..inner).map(|i| i as f32 / inner as f32));
    u.extend([1.0; 4]);
    u
}

/// de Boor's algorithm for degree `p` on knots `u` with control points `c` at `x`.
fn de_boor(u: &[f32], c: &[[f32; 3]], p: usize, x: f32) -> [f32; 3] {
    let m = c.len();
    // Span k with u[k] <= x < u[k+1], clamped to the last non-empty span.
    let mut k = p;
    while k + 1 < m && u[k + 1] <= x {
        k += 1;
    }
    let mut d: Vec<[f32; 3]> = (0..=p).map(|j| c[j + k - p]).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let lo = u[j + k - p];
            let hi = u[j + 1 + k - r];
            let a = if hi > lo { (x - lo) / (hi - lo) } else { 0.0 };
            d[j] = add(scale(d[j - 1], 1.0 - a), scale(d[j], a));
        }
    }
    d[p]
}

fn wrap_angle(a: f32) -> f32 {
    let tau = std::f32::consts::TAU;
    let mut a = a % tau;
    if a > std::f32::consts::PI {
        a -= tau;
    } else if a <= -std::f32::consts::PI {
        a += tau;
    }
    a
}

fn finite3(v: [f32; 3]) -> bool {
    v.iter().all(|c| c.is_finite())
}

impl FeatureCurve {
    /// Checks the curve.
    ///
    /// # Errors
    /// [`PipelineError::Invalid`] naming the field: fewer than 4 or more than
    /// [`MAX_CONTROL_POINTS`] control points, a non-finite value, fewer than two constraint
    /// points, constraint `t` not strictly increasing from 0 to 1, or a bitangent (nearly)
    /// parallel to the tangent.
    pub fn validate(&self) -> Result<(), PipelineError> {
        let m = self.control_points.len();
        if !(4..=MAX_CONTROL_POINTS).contains(&m) {
            return Err(PipelineError::invalid(
                "control_points",
                format!("a cubic B-spline needs 4..={MAX_CONTROL_POINTS} control points, got {m}"),
            ));
        }
        if let Some(i) = self.control_points.iter().position(|p| !finite3(*p)) {
            return Err(PipelineError::invalid(
                format!("control_points[{i}]"),
                "must be finite",
            ));
        }
        let c = &self.constraints;
        if c.len() < 2 {
            return Err(PipelineError::invalid(
                "constraints",
                "at least two constraint points (at t = 0 and t = 1) are required",
            ));
        }
        if c[0].t != 0.0 || c[c.len() - 1].t != 1.0 {
            return Err(PipelineError::invalid(
                "constraints",
                "the first constraint point must be at t = 0 and the last at t = 1",
            ));
        }
        for (i, p) in c.iter().enumerate() {
            let name = |f: &str| format!("constraints[{i}].{f}");
            if !(p.t.is_finite() && (0.0..=1.0).contains(&p.t)) {
                return Err(PipelineError::invalid(name("t"), "must be in [0, 1]"));
            }
            if i > 0 && p.t <= c[i - 1].t {
                return Err(PipelineError::invalid(
                    name("t"),
                    "constraint points must have strictly increasing t",
                ));
            }
            if !(p.alpha.is_finite() && p.beta.is_finite()) {
                return Err(PipelineError::invalid(
                    name("alpha"),
                    "alpha and beta must be finite",
                ));
            }
            let tan = normalize(self.derivative(p.t));
            for (field, b) in [("b_l", p.b_l), ("b_r", p.b_r)] {
                if !finite3(b) {
                    return Err(PipelineError::invalid(name(field), "must be finite"));
                }
                let perp = sub(b, scale(tan, dot(b, tan)));
                if length(perp) < 1e-3 * length(b).max(1e-6) || length(b) < 1e-6 {
                    return Err(PipelineError::invalid(
                        name(field),
                        "must be non-zero and not parallel to the curve's tangent",
                    ));
                }
            }
        }
        Ok(())
    }

    /// `B(t)`, metres.
    pub fn position(&self, t: f32) -> [f32; 3] {
        let u = knots(self.control_points.len());
        de_boor(&u, &self.control_points, 3, t.clamp(0.0, 1.0))
    }

    /// `dB/dt`, metres per unit of `t`.
    pub fn derivative(&self, t: f32) -> [f32; 3] {
        let p = &self.control_points;
        let u = knots(p.len());
        let q: Vec<[f32; 3]> = (0..p.len() - 1)
            .map(|i| {
                let du = u[i + 4] - u[i + 1];
                scale(sub(p[i + 1], p[i]), if du > 0.0 { 3.0 / du } else { 0.0 })
            })
            .collect();
        de_boor(&u[1..u.len() - 1], &q, 2, t.clamp(0.0, 1.0))
    }

    /// The curve discretised into samples at most about `step` metres apart (plus one sample at
    /// every constraint point), with attributes interpolated as the module docs describe.
    ///
    /// # Errors
    /// As [`Self::validate`]; and `step` not positive.
    pub fn sample(&self, step: f32) -> Result<Vec<CurveSample>, PipelineError> {
        self.validate()?;
        if !(step.is_finite() && step > 0.0) {
            return Err(PipelineError::invalid("step", "must be positive"));
        }
        // Length estimate from a 64-segment polyline.
        let mut len = 0.0;
        let mut prev = self.position(0.0);
        for i in 1..=64 {
            let p = self.position(i as f32 / 64.0);
            len += length(sub(p, prev));
            prev = p;
        }
        let n = ((len / step).ceil() as usize).clamp(1, MAX_CURVE_SAMPLES - self.constraints.len());
        let mut ts: Vec<f32> = (0..=n).map(|i| i as f32 / n as f32).collect();
        ts.extend(self.constraints.iter().map(|c| c.t));
        ts.sort_by(f32::total_cmp);
        ts.dedup();

        let pos: Vec<[f32; 3]> = ts.iter().map(|&t| self.position(t)).collect();
        let tan: Vec<[f32; 3]> = ts
            .iter()
            .enumerate()
            .map(|(i, &t)| {
                let d = normalize(self.derivative(t));
                if length(d) > 0.5 {
                    d
                } else {
                    let (a, b) = if i + 1 < pos.len() {
                        (i, i + 1)
                    } else {
                        (i - 1, i)
                    };
                    normalize(sub(pos[b], pos[a]))
                }
            })
            .collect();
        // Rotation-minimising frame by double reflection, starting from the first constraint's
        // left bitangent.
        let b0 = self.constraints[0].b_l;
        let mut r = vec![normalize(sub(b0, scale(tan[0], dot(b0, tan[0]))))];
        for i in 0..ts.len() - 1 {
            let v1 = sub(pos[i + 1], pos[i]);
            let c1 = dot(v1, v1);
            let (rl, tl) = if c1 > 1e-20 {
                (
                    sub(r[i], scale(v1, 2.0 / c1 * dot(v1, r[i]))),
                    sub(tan[i], scale(v1, 2.0 / c1 * dot(v1, tan[i]))),
                )
            } else {
                (r[i], tan[i])
            };
            let v2 = sub(tan[i + 1], tl);
            let c2 = dot(v2, v2);
            let rn = if c2 > 1e-20 {
                sub(rl, scale(v2, 2.0 / c2 * dot(v2, rl)))
            } else {
                rl
            };
            // Re-orthogonalise against rounding drift.
            let t1 = tan[i + 1];
            r.push(normalize(sub(rn, scale(t1, dot(rn, t1)))));
        }
        // Constraint bitangents as (angle, length) in the frame at their sample.
        let polar = |b: [f32; 3], j: usize| {
            let s = cross(tan[j], r[j]);
            let x = dot(b, r[j]);
            let y = dot(b, s);
            (y.atan2(x), (x * x + y * y).sqrt())
        };
        let at: Vec<usize> = self
            .constraints
            .iter()
            .map(|c| {
                ts.iter()
                    .position(|&t| t == c.t)
                    .expect("every constraint t is among the sample parameters")
            })
            .collect();
        let pl: Vec<(f32, f32)> = self
            .constraints
            .iter()
            .zip(&at)
            .map(|(c, &j)| polar(c.b_l, j))
            .collect();
        let pr: Vec<(f32, f32)> = self
            .constraints
            .iter()
            .zip(&at)
            .map(|(c, &j)| polar(c.b_r, j))
            .collect();
        let mut out = Vec::with_capacity(ts.len());
        let mut seg = 0;
        for (i, &t) in ts.iter().enumerate() {
            while seg + 2 < self.constraints.len() && t > self.constraints[seg + 1].t {
                seg += 1;
            }
            let (a, b) = (&self.constraints[seg], &self.constraints[seg + 1]);
            let w = ((t - a.t) / (b.t - a.t)).clamp(0.0, 1.0);
            let s = cross(tan[i], r[i]);
            let rebuild = |pa: (f32, f32), pb: (f32, f32)| {
                let ang = pa.0 + w * wrap_angle(pb.0 - pa.0);
                let len = pa.1 + w * (pb.1 - pa.1);
                add(scale(r[i], len * ang.cos()), scale(s, len * ang.sin()))
            };
            out.push(CurveSample {
                t,
                position: pos[i],
                tangent: tan[i],
                b_l: rebuild(pl[seg], pl[seg + 1]),
                b_r: rebuild(pr[seg], pr[seg + 1]),
                alpha: a.alpha + w * (b.alpha - a.alpha),
                beta: a.beta + w * (b.beta - a.beta),
                material: if w <= 0.5 { a.material } else { b.material },
            });
        }
        Ok(out)
    }
}
