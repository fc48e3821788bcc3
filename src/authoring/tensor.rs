//! Tensor-map transformations (Guérin et al. 2022, §4.3): the target gradient of the heights is
//! multiplied by a 2×2 tensor field, `g̃ = A(p)·g`.
//!
//! The directional tensor is `D = I + μ·M(θ)` with `M(θ) = [[cos 2θ, sin 2θ], [sin 2θ,
//! −cos 2θ]]`: `M` has eigenvalue `+1` along the direction `θ` and `−1` across it, so `D` scales
//! the slope along `θ` by `1 + μ` and across it by `1 − μ`, dragging gradients toward `θ`. Three
//! tools:
//!
//! - the constant directional tensor on a disc `Ω` (`A = D` inside, `I` outside);
//! - the skeleton tensor `A(p) = I + μ·α(d(p)/r)·M(θ)` for a point or polyline skeleton, `α` the
//!   C² falloff and `d` the distance to the skeleton (the paper's first skeleton variant: a
//!   constant tensor ignoring `u(p)`);
//! - the stroke-aligned brush (the paper's Fig. 7 variant): the same with `θ` taken, at each
//!   point, from the stroke's direction at the closest point.
//!
//! Angles are measured from +x toward +z (clockwise on a north-up map). Discretisation: the grid
//! stores one gradient component per edge; the other component at an edge's midpoint is the mean
//! of the four nearest edges of the other family (the staggered-grid interpolation).

use super::nearest::Nearest;
use super::raster::{dist, falloff, Canvas};

/// `M(θ)` for `θ` in radians.
pub fn orientation(theta: f64) -> [[f64; 2]; 2] {
    let (s, c) = (2.0 * theta).sin_cos();
    [[c, s], [s, -c]]
}

/// Direction of segment `s` of the polyline, radians from +x toward +z (0 for a single point).
fn stroke_angle(pts: &[[f64; 2]], s: usize) -> f64 {
    if pts.len() < 2 {
        return 0.0;
    }
    (pts[s + 1][1] - pts[s][1]).atan2(pts[s + 1][0] - pts[s][0])
}

impl Canvas {
    /// The current target gradient of the heights, `∇h_proc + g_d`, on both edge families.
    fn height_gradients(&self) -> (Vec<f64>, Vec<f64>) {
        let n = self.grid.n;
        let inv = 1.0 / self.grid.spacing_m;
        let b = |v: usize| f64::from(self.base[v]);
        let mut gx = Vec::with_capacity(self.gx.len());
        for j in 0..n {
            for i in 0..n - 1 {
                let v = j * n + i;
                gx.push((b(v + 1) - b(v)) * inv + f64::from(self.gx[j * (n - 1) + i]));
            }
        }
        let mut gz = Vec::with_capacity(self.gz.len());
        for j in 0..n - 1 {
            for i in 0..n {
                let v = j * n + i;
                gz.push((b(v + n) - b(v)) * inv + f64::from(self.gz[j * n + i]));
            }
        }
        (gx, gz)
    }

    /// Multiplies the target gradient of the heights by `I + t(p)` on every edge where `t`
    /// (evaluated at the edge's midpoint) is `Some`.
    fn apply_tensor(&mut self, mut t: impl FnMut([f64; 2]) -> Option<[[f64; 2]; 2]>) {
        let n = self.grid.n;
        let (hx, hz) = self.height_gradients();
        let mean = |vals: &mut dyn Iterator<Item = f64>| {
            let (s, k) = vals.fold((0.0, 0usize), |(s, k), v| (s + v, k + 1));
            s / k.max(1) as f64
        };
        self.edges(|c, is_x, e, mid, _| {
            let Some(m) = t(mid) else {
                return;
            };
            let g = if is_x {
                let (i, j) = (e % (n - 1), e / (n - 1));
                let rows = [j.checked_sub(1), (j + 1 < n).then_some(j)];
                let z = mean(
                    &mut rows
                        .into_iter()
                        .flatten()
                        .flat_map(|r| [hz[r * n + i], hz[r * n + i + 1]]),
                );
                [hx[e], z]
            } else {
                let (i, j) = (e % n, e / n);
                let cols = [i.checked_sub(1), (i + 1 < n).then_some(i)];
                let x = mean(
                    &mut cols
                        .into_iter()
                        .flatten()
                        .flat_map(|k| [hx[j * (n - 1) + k], hx[(j + 1) * (n - 1) + k]]),
                );
                [x, hz[e]]
            };
            let axis = usize::from(!is_x);
            let out = g[axis] + m[axis][0] * g[0] + m[axis][1] * g[1];
            let old = if is_x { hx[e] } else { hz[e] };
            let slot = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *slot = (f64::from(*slot) + out - old) as f32;
        });
    }

    /// Constant directional tensor `D = I + μ·M(θ)` on the disc of `radius` around `center`.
    pub fn directional_tensor(&mut self, center: [f64; 2], radius: f64, angle_deg: f64, mu: f64) {
        let m = orientation(angle_deg.to_radians());
        self.apply_tensor(|p| (dist(p, center) < radius).then(|| scaled(m, mu)));
    }

    /// Skeleton tensor `I + μ·α(d/r)·M(θ)` around a point or polyline skeleton.
    pub fn skeleton_tensor(&mut self, pts: &[[f64; 2]], radius: f64, angle_deg: f64, mu: f64) {
        let m = orientation(angle_deg.to_radians());
        let index = Nearest::new(pts, radius);
        self.apply_tensor(|p| {
            let w = falloff(index.get(p)?.0, radius);
            (w > 0.0).then(|| scaled(m, mu * w))
        });
    }

    /// Stroke-aligned tensor brush (Fig. 7): `I + μ·α(d/r)·M(θ(p))`, `θ(p)` the stroke's
    /// direction at the closest point.
    pub fn stroke_tensor(&mut self, pts: &[[f64; 2]], radius: f64, mu: f64) {
        let index = Nearest::new(pts, radius);
        self.apply_tensor(|p| {
            let (d, s, _) = index.get(p)?;
            let w = falloff(d, radius);
            (w > 0.0).then(|| scaled(orientation(stroke_angle(pts, s)), mu * w))
        });
    }
}

fn scaled(m: [[f64; 2]; 2], k: f64) -> [[f64; 2]; 2] {
    [[k * m[0][0], k * m[0][1]], [k * m[1][0], k * m[1][1]]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A canvas over the tilted plane `h = 0.2·x + 0.1·z`.
    fn plane_canvas() -> Canvas {
        Canvas::unit_grid(33, |x, z| (0.2 * x + 0.1 * z) as f32)
    }

    /// The target gradient of the heights at the edges next to sample (16, 16).
    fn gradient_at_centre(c: &Canvas) -> [f64; 2] {
        let (hx, hz) = c.height_gradients();
        let n = c.grid.n;
        [hx[16 * (n - 1) + 16], hz[16 * n + 16]]
    }

    #[test]
    fn a_directional_tensor_scales_slopes_along_its_direction_and_across_it() {
        for (east, mu) in [(true, 0.5), (false, 0.9), (true, 0.0)] {
            let angle = if east { 0.0 } else { 90.0 };
            let mut c = plane_canvas();
            c.directional_tensor([16.0, 16.0], 8.0, angle, mu);
            let g = gradient_at_centre(&c);
            // θ = 0: x is along, z across; θ = 90°: the reverse.
            let (along, across) = if east { (0.2, 0.1) } else { (0.1, 0.2) };
            let (ga, gc) = if east { (g[0], g[1]) } else { (g[1], g[0]) };
            assert!(
                (ga - along * (1.0 + mu)).abs() < 1e-5,
                "along {ga} (θ {angle}, μ {mu})"
            );
            assert!(
                (gc - across * (1.0 - mu)).abs() < 1e-5,
                "across {gc} (θ {angle}, μ {mu})"
            );
        }
        // Outside the disc nothing changes.
        let mut c = plane_canvas();
        c.directional_tensor([16.0, 16.0], 4.0, 30.0, 0.7);
        assert!(c.gx[2 * 32 + 2] == 0.0 && c.gz[2 * 33 + 2] == 0.0);
    }

    #[test]
    fn skeleton_and_stroke_tensors_fade_with_distance_and_follow_the_stroke() {
        // A skeleton segment along z = 16: full strength on it, none beyond the radius.
        let mut c = plane_canvas();
        c.skeleton_tensor(&[[4.0, 16.0], [28.0, 16.0]], 6.0, 0.0, 0.5);
        let g = gradient_at_centre(&c);
        // The x-edge's midpoint lies on the segment: α = 1. The z-edge's is 0.5 m off it.
        assert!((g[0] - 0.2 * 1.5).abs() < 1e-5, "{g:?}");
        let w = falloff(0.5, 6.0);
        assert!((g[1] - 0.1 * (1.0 - 0.5 * w)).abs() < 1e-5, "{g:?}");
        let n = c.grid.n;
        assert_eq!(c.gx[4 * (n - 1) + 16], 0.0, "10 m off the skeleton");
        // A stroke heading south (θ = 90°) scales the z slope, like a directional tensor of 90°.
        let mut s = plane_canvas();
        s.stroke_tensor(&[[16.0, 2.0], [16.0, 30.0]], 6.0, 0.5);
        let g = gradient_at_centre(&s);
        assert!((g[1] - 0.1 * 1.5).abs() < 1e-5, "{g:?}");
        assert!(g[0] < 0.2 && g[0] > 0.2 * 0.5 - 1e-6, "{g:?}");
    }
}
