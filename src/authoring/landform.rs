//! Landform tools (Guérin et al. 2022, §4.2 and Fig. 4) and the composite brushes of Fig. 8,
//! rasterised on a [`Canvas`] in the displacement formulation of [`super`].
//!
//! The paper's catalogue splits in two groups, and so does this module:
//!
//! - crests, cliffs and rivers rely on elevation constraints (hard, Dirichlet samples of `d`)
//!   plus a gradient constraint beside the curve: steep for crests and cliffs, a gentle upward
//!   one for river banks. Here that gradient constraint *replaces* the target gradient of the
//!   heights near the curve (the curve decides the slope there), blended back to the previous
//!   target over the last third of the tool's width.
//! - free crests, faults and ravines are pure gradient constraints with no elevation. They *add*
//!   to the target gradient, so crossing or overlapping curves superpose additively (§4.2: "the
//!   superposition of gradient constraints is additive, unlike for elevation constraints"). Each
//!   adds the gradient of a function of the distance to the curve, `∇φ(dist)`, so its field is
//!   curl-free and the reconstruction meets it (a fault's field is the exception at its two ends,
//!   where the throw dies out and the least-squares solve spreads the mismatch).
//!
//! The Fig. 8 composites: the mountain-range brush builds a main free crest along the stroke and
//! side spurs (smaller free crests) at regular intervals, alternating sides with a hashed angle
//! jitter; the mesa is a plateau (an elevation disc, hard) ringed by a cliff band. Deviation from
//! the paper: the mountain range adds no downslope-oriented tensor noise (compose a `noise` brush
//! and a `stroke_tensor` for that).
//!
//! Sides: "right" of a stroke is the side to the right looking along it on a map with x east
//! and z south (north up), i.e. where `t × (p − q) > 0` for the stroke tangent `t`.

use super::nearest::Nearest;
use super::raster::{dist, falloff, polyline_distance, Canvas};
use crate::terrain::hash::{hash2, stream, unit};

/// Hash purpose of the mountain-range spur jitter.
const SPUR_PURPOSE: u32 = 0x4a_0002;
/// `∫₀¹ (1 − u²)³ du`: the area under the C² falloff over a unit radius.
pub const FALLOFF_AREA: f64 = 16.0 / 35.0;
/// Most spurs a mountain-range brush generates.
pub const MAX_SPURS: usize = 256;

/// Where a point lies relative to a polyline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Distance to the polyline, metres.
    pub dist: f64,
    /// Unit vector from the closest point of the polyline to the point (zero on the curve).
    pub away: [f64; 2],
    /// `+1` right of the stroke, `−1` left (see the module docs).
    pub side: f64,
    /// True when the closest point is not one of the polyline's two ends.
    pub interior: bool,
}

/// The [`Frame`] of `p` relative to `pts`.
pub fn frame(pts: &[[f64; 2]], p: [f64; 2]) -> Frame {
    frame_at(pts, p, polyline_distance(pts, p))
}

/// The [`Frame`] of `p` relative to `pts` from its closest point `(distance, segment,
/// fraction)`, as [`polyline_distance`] or [`Nearest::get`] give it.
pub fn frame_at(pts: &[[f64; 2]], p: [f64; 2], (d, s, t): (f64, usize, f64)) -> Frame {
    let (a, b) = if pts.len() == 1 {
        (pts[0], pts[0])
    } else {
        (pts[s], pts[s + 1])
    };
    let q = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    let away = if d > 0.0 {
        [(p[0] - q[0]) / d, (p[1] - q[1]) / d]
    } else {
        [0.0, 0.0]
    };
    let tan = [b[0] - a[0], b[1] - a[1]];
    let cross = tan[0] * (p[1] - q[1]) - tan[1] * (p[0] - q[0]);
    let last = pts.len().saturating_sub(2);
    let interior = pts.len() > 1 && !(s == 0 && t <= 0.0) && !(s == last && t >= 1.0);
    Frame {
        dist: d,
        away,
        side: if cross >= 0.0 { 1.0 } else { -1.0 },
        interior,
    }
}

/// What a tool does to one edge's target gradient.
pub(super) enum Edit {
    /// The target gradient of the heights becomes `w·v + (1 − w)·previous` (`v` a vector; the
    /// edge takes its component along the edge's axis).
    Replace([f64; 2], f64),
    /// The target gradient of `d` gains the vector's component along the edge's axis.
    Add([f64; 2]),
}

/// Weight of a replacing gradient constraint of reach `width` at distance `d`: 1 out to two
/// thirds of the width, then linearly down to 0 at the width.
pub(super) fn band(d: f64, width: f64) -> f64 {
    ((width - d) / (width / 3.0)).clamp(0.0, 1.0)
}

impl Canvas {
    /// Applies `f` to every edge whose midpoint lies within `reach` metres of the polyline
    /// `pts`, by the midpoint's [`Frame`]; `f` must edit nothing farther (each tool's width).
    pub(super) fn by_frame(
        &mut self,
        pts: &[[f64; 2]],
        reach: f64,
        mut f: impl FnMut(&Frame) -> Option<Edit>,
    ) {
        let inv = 1.0 / self.grid.spacing_m;
        // A relative slack of 1e-9 keeps every edge `f` could edit despite rounding in its own
        // distance tests (such as `dist − half < width`).
        let index = Nearest::new(pts, reach + 1e-9 * reach.abs().max(1.0));
        self.edges(|c, is_x, e, mid, (a, b)| {
            let Some(near) = index.get(mid) else {
                return;
            };
            let Some(edit) = f(&frame_at(pts, mid, near)) else {
                return;
            };
            let axis = usize::from(!is_x);
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            match edit {
                Edit::Replace(v, w) => {
                    let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
                    *g = (f64::from(*g) * (1.0 - w) + (v[axis] - proc) * w) as f32;
                }
                Edit::Add(v) => *g = (f64::from(*g) + v[axis]) as f32,
            }
        });
    }

    /// Point gradient constraint: the heights' slope at `center` becomes `slope_deg` rising
    /// toward `direction_deg`. Soft and added: the target gradient gains the discrete gradient
    /// of the potential `φ = w(r)·(tan(slope)·(p − c)·u − (h₀(p) − h₀(c)))` (`w` the C² falloff
    /// over `radius`, `u` the direction, `h₀` the procedural heights), so the field stays
    /// curl-free and is reconstructed exactly where nothing else conflicts; at the centre
    /// (`w = 1`, `∇w = 0`) the heights' gradient is `tan(slope)·u`.
    pub fn slope_point(
        &mut self,
        center: [f64; 2],
        radius: f64,
        slope_deg: f64,
        direction_deg: f64,
    ) {
        let tan = slope_deg.to_radians().tan();
        let (sin, cos) = direction_deg.to_radians().sin_cos();
        let n = self.grid.n;
        let (fi, fj) = self.grid.grid_coords(center[0], center[1]);
        let near = |f: f64| (f.round().max(0.0) as usize).min(n - 1);
        let h_c = f64::from(self.base[near(fj) * n + near(fi)]);
        let phi: Vec<f64> = (0..n * n)
            .map(|v| {
                let p = self.grid.position(v % n, v / n);
                let w = falloff(dist(p, center), radius);
                if w == 0.0 {
                    return 0.0;
                }
                let plane = tan * ((p[0] - center[0]) * cos + (p[1] - center[1]) * sin);
                w * (plane - (f64::from(self.base[v]) - h_c))
            })
            .collect();
        self.add_potential(&phi);
    }

    /// Curve gradient constraint with a slope profile on each side: out to `width` the heights
    /// fall away from the polyline at `left_deg` on its left and `right_deg` on its right,
    /// keeping the procedural heights along the curve itself. Soft and added, as
    /// [`Canvas::slope_point`]: the target gradient gains the discrete gradient of the potential
    /// `φ = W(dist)·(−tan(slope_side)·dist − (h₀(p) − h₀(q)))` (`q` the closest point of the
    /// curve, `W` 1 out to two thirds of the width, then a smoothstep down to 0), which is
    /// curl-free, so inside the band the heights are `h₀(q) − tan·dist`.
    pub fn slope_curve(&mut self, pts: &[[f64; 2]], left_deg: f64, right_deg: f64, width: f64) {
        let (tl, tr) = (left_deg.to_radians().tan(), right_deg.to_radians().tan());
        let n = self.grid.n;
        let index = Nearest::new(pts, width);
        let phi: Vec<f64> = (0..n * n)
            .map(|v| {
                let p = self.grid.position(v % n, v / n);
                let Some(near) = index.get(p) else {
                    return 0.0;
                };
                let f = frame_at(pts, p, near);
                let x = ((f.dist - 2.0 * width / 3.0) / (width / 3.0)).clamp(0.0, 1.0);
                let w = 1.0 - x * x * (3.0 - 2.0 * x);
                let tan = if f.side > 0.0 { tr } else { tl };
                let q = [p[0] - f.dist * f.away[0], p[1] - f.dist * f.away[1]];
                w * (-tan * f.dist - (f64::from(self.base[v]) - self.base_at(q)))
            })
            .collect();
        self.add_potential(&phi);
    }

    /// Adds the discrete gradient of the per-sample potential `phi` to the target gradient.
    fn add_potential(&mut self, phi: &[f64]) {
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, _, (a, b)| {
            let step = (phi[b] - phi[a]) * inv;
            if step != 0.0 {
                let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
                *g = (f64::from(*g) + step) as f32;
            }
        });
    }

    /// The procedural height at world point `q`, bilinear between samples (clamped to the grid).
    fn base_at(&self, q: [f64; 2]) -> f64 {
        let n = self.grid.n;
        let (fi, fj) = self.grid.grid_coords(q[0], q[1]);
        crate::terrain::lattice::bilinear_clamped(&self.base, n, n, fi, fj)
    }

    /// Cliff (Fig. 4): the top edge fixed at `top` along the polyline (hard), and on the right
    /// of the stroke (the downhill side), out to `width`, a target slope of `slope_deg` falling
    /// away from the top edge (soft, replacing). The foot lies near `top − width·tan(slope)`.
    pub fn cliff(&mut self, pts: &[[f64; 2]], top: f64, slope_deg: f64, width: f64) {
        self.elevation(pts, &[top], 0.5 * self.grid.spacing_m);
        let tan = slope_deg.to_radians().tan();
        self.by_frame(pts, width, |f| {
            (f.side > 0.0 && f.dist > 0.0 && f.dist < width)
                .then(|| Edit::Replace([-tan * f.away[0], -tan * f.away[1]], band(f.dist, width)))
        });
    }

    /// River (Fig. 4): the bed fixed at `bed` within `bed_width / 2` of the polyline (at least
    /// the nearest sample; hard), and banks rising gently at `bank_slope_deg` away from the bed
    /// out to `bank_width` beyond it (soft, replacing).
    pub fn river(
        &mut self,
        pts: &[[f64; 2]],
        bed: f64,
        bed_width: f64,
        bank_slope_deg: f64,
        bank_width: f64,
    ) {
        let half = 0.5 * bed_width.max(self.grid.spacing_m);
        self.elevation(pts, &[bed], half);
        let tan = bank_slope_deg.to_radians().tan();
        self.by_frame(pts, half + bank_width, |f| {
            let d = f.dist - half;
            (d > 0.0 && d < bank_width)
                .then(|| Edit::Replace([tan * f.away[0], tan * f.away[1]], band(d, bank_width)))
        });
    }

    /// Free crest (`sign = 1`) or ravine (`sign = −1`) (Fig. 4): adds a slope of `slope_deg`
    /// falling away from (rising away from) the polyline with the C² falloff over `width`, with
    /// no elevation constraint. The line ends up about `tan(slope)·width·16/35` above (below)
    /// its surroundings.
    pub fn free_crest(&mut self, pts: &[[f64; 2]], sign: f64, slope_deg: f64, width: f64) {
        let tan = slope_deg.to_radians().tan();
        self.by_frame(pts, width, |f| {
            let w = falloff(f.dist, width);
            (w > 0.0 && f.dist > 0.0)
                .then(|| Edit::Add([-sign * tan * w * f.away[0], -sign * tan * w * f.away[1]]))
        });
    }

    /// Fault (Fig. 4): a step of `throw` metres across the polyline, the right of the stroke
    /// dropping (a negative throw raises it), spread over a band of `width` by the gradient of a
    /// C² smooth step (pure gradient constraint, added). The step dies out beyond the ends.
    pub fn fault(&mut self, pts: &[[f64; 2]], throw: f64, width: f64) {
        let r = 0.5 * width;
        let scale = throw / (2.0 * r * FALLOFF_AREA);
        self.by_frame(pts, r, |f| {
            let w = falloff(f.dist, r);
            (w > 0.0 && f.dist > 0.0 && f.interior).then(|| {
                // The height is `−throw·S(s)` for the signed distance `s` (positive on the right)
                // and a smooth step `S`, so the gradient is `−throw·S′(s)·side·away`.
                let k = -scale * w * f.side;
                Edit::Add([k * f.away[0], k * f.away[1]])
            })
        });
    }

    /// Mountain-range brush (Fig. 8, left): a free crest along the stroke rising `height` over
    /// `width` on each side, and side spurs every `width` along the stroke, alternating sides,
    /// each a free crest of 0.8·`width` length at a hashed angle (±30° off the normal), half the
    /// width and 60 % of the height.
    pub fn mountain_range(
        &mut self,
        pts: &[[f64; 2]],
        height: f64,
        width: f64,
        world: u64,
        seed: u32,
    ) {
        let slope = |h: f64, w: f64| (h / (w * FALLOFF_AREA)).atan().to_degrees();
        self.free_crest(pts, 1.0, slope(height, width), width);
        let s = stream(world, SPUR_PURPOSE, seed);
        let mut next = 0.5 * width;
        let mut walked = 0.0;
        let mut k = 0u32;
        for w in pts.windows(2) {
            let len = dist(w[0], w[1]);
            if len <= 0.0 {
                continue;
            }
            let t = [(w[1][0] - w[0][0]) / len, (w[1][1] - w[0][1]) / len];
            while next <= walked + len && (k as usize) < MAX_SPURS {
                let u = (next - walked) / len;
                let root = [
                    w[0][0] + u * (w[1][0] - w[0][0]),
                    w[0][1] + u * (w[1][1] - w[0][1]),
                ];
                let jitter = (f64::from(unit(hash2(k as i32, 0, s))) - 0.5) * 60f64.to_radians();
                let side = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
                // The right-hand normal of the tangent, rotated by the jitter.
                let (c, sn) = (jitter.cos(), jitter.sin());
                let nrm = [-t[1] * side, t[0] * side];
                let dir = [c * nrm[0] - sn * nrm[1], sn * nrm[0] + c * nrm[1]];
                let tip = [
                    root[0] + 0.8 * width * dir[0],
                    root[1] + 0.8 * width * dir[1],
                ];
                self.free_crest(
                    &[root, tip],
                    1.0,
                    slope(0.6 * height, 0.5 * width),
                    0.5 * width,
                );
                next += width;
                k += 1;
            }
            walked += len;
        }
    }

    /// Mesa (Fig. 8, right): a plateau fixed at `elevation` within `radius` of `center` (hard)
    /// and a cliff ring around it falling at `slope_deg` over `cliff_width` (soft, replacing).
    pub fn mesa(
        &mut self,
        center: [f64; 2],
        radius: f64,
        elevation: f64,
        slope_deg: f64,
        cliff_width: f64,
    ) {
        self.elevation(&[center], &[elevation], radius);
        let tan = slope_deg.to_radians().tan();
        self.by_frame(&[center], radius + cliff_width, |f| {
            let d = f.dist - radius;
            (d > 0.0 && d < cliff_width)
                .then(|| Edit::Replace([-tan * f.away[0], -tan * f.away[1]], band(d, cliff_width)))
        });
    }
}
