//! Rasterising tool operations on a region's grid, in the displacement formulation of
//! [`super`]: hard operations fix samples of `d`, soft ones edit the target gradient of `d`.
//!
//! Discretisation as in [`crate::terrain::poisson::Problem`]: `gx[j·(n−1) + i]` is the target
//! `∂d/∂x` on the edge between samples `(i, j)` and `(i+1, j)`, `gz[j·n + i]` the target `∂d/∂z`
//! between `(i, j)` and `(i, j+1)`. Brush falloffs are the C² kernel `(1 − (r/R)²)³`.

use super::grid::RegionGrid;
use super::nearest::{segment_distance, Nearest};
use crate::terrain::hash::stream;
use crate::terrain::noise::lattice;

/// Hash purpose of the noise brush's seed.
const NOISE_PURPOSE: u32 = 0x4a_0001;

/// The C² brush falloff: 1 at the centre, 0 with zero first and second derivatives at `radius`.
pub fn falloff(r: f64, radius: f64) -> f64 {
    if radius <= 0.0 || r >= radius {
        return 0.0;
    }
    let t = r / radius;
    let u = 1.0 - t * t;
    u * u * u
}

/// Perlin's smootherstep `6t⁵ − 15t⁴ + 10t³` of `t` clamped to `[0, 1]`: 0 and 1 at the ends
/// with zero first and second derivatives there, so a profile made of it is C².
pub fn smootherstep(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// Distance from `p` to the polyline and the arc-length parameter of the closest point
/// (`(distance, segment index, fraction along it)`).
pub fn polyline_distance(pts: &[[f64; 2]], p: [f64; 2]) -> (f64, usize, f64) {
    if pts.len() == 1 {
        return (dist(pts[0], p), 0, 0.0);
    }
    let mut best = (f64::INFINITY, 0, 0.0);
    for (s, w) in pts.windows(2).enumerate() {
        let (dd, t) = segment_distance(w[0], w[1], p);
        if dd < best.0 {
            best = (dd, s, t);
        }
    }
    best
}

/// Whether `p` lies inside the polygon `poly` (even-odd rule; closed implicitly).
pub fn inside_polygon(poly: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let mut j = poly.len().saturating_sub(1);
    for (i, a) in poly.iter().enumerate() {
        let b = poly[j];
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
        {
            inside = !inside;
        }
        j = i;
    }
    inside
}

pub(super) fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// The problem being built: the fixed samples of `d` with their values and the target gradient
/// of `d`, plus the procedural heights they are relative to.
#[derive(Clone, Debug)]
pub struct Canvas {
    /// The grid.
    pub grid: RegionGrid,
    /// Procedural heights at the samples, metres.
    pub base: Vec<f32>,
    /// True where `d` is fixed (outside the bbox, the border, and hard constraints).
    pub fixed: Vec<bool>,
    /// Samples a freeze brush protects from later hard constraints.
    pub frozen: Vec<bool>,
    /// `d` at the fixed samples, metres.
    pub d: Vec<f32>,
    /// Target `∂d/∂x` on the x-edges.
    pub gx: Vec<f32>,
    /// Target `∂d/∂z` on the z-edges.
    pub gz: Vec<f32>,
}

impl Canvas {
    /// An unedited region: `d = 0` fixed outside the bbox and on the border, zero target gradient.
    pub fn new(grid: RegionGrid, base: Vec<f32>) -> Self {
        let n = grid.n;
        let fixed = (0..n * n)
            .map(|v| !grid.is_interior(v % n, v / n))
            .collect();
        Self {
            grid,
            base,
            fixed,
            frozen: vec![false; n * n],
            d: vec![0.0; n * n],
            gx: vec![0.0; (n - 1) * n],
            gz: vec![0.0; n * (n - 1)],
        }
    }

    /// The weight of an elevation brush centred on `center` (world `[x, z]`, metres) with radius
    /// `radius` (metres) at every sample, in sample order: the C² [`falloff`] of the sample's
    /// distance to the centre, and 0 at fixed samples, which a brush never moves.
    pub(super) fn brush_weights(&self, center: [f64; 2], radius: f64) -> Vec<f64> {
        let n = self.grid.n;
        (0..n * n)
            .map(|v| {
                if self.fixed[v] {
                    0.0
                } else {
                    falloff(dist(self.grid.position(v % n, v / n), center), radius)
                }
            })
            .collect()
    }

    /// For tests: an unedited canvas ([`Canvas::new`]) of `n × n` samples 1 m apart from the world
    /// origin, over the procedural heights `base(x, z)` (metres) at each sample's world `x` and
    /// `z` (metres).
    #[cfg(test)]
    pub(super) fn unit_grid(n: usize, base: impl Fn(f64, f64) -> f32) -> Self {
        let grid = RegionGrid {
            origin: [0.0, 0.0],
            spacing_m: 1.0,
            n,
            max: [(n - 1) as f64, (n - 1) as f64],
        };
        let base = (0..n * n)
            .map(|v| base((v % n) as f64, (v / n) as f64))
            .collect();
        Self::new(grid, base)
    }

    pub(super) fn fix(&mut self, v: usize, height_m: f64) {
        if self.frozen[v] || !self.grid.is_interior(v % self.grid.n, v / self.grid.n) {
            return;
        }
        self.fixed[v] = true;
        self.d[v] = (height_m - f64::from(self.base[v])) as f32;
    }

    /// Samples within `radius` of the polyline (at least the nearest one), with the parameter of
    /// their closest point: `(sample, distance, segment, fraction)`, in sample order.
    ///
    /// Each segment visits only the samples of its bounding box grown by `radius`, so the cost
    /// follows the polyline's length, not the grid's area; the closest segment of a sample is
    /// the first of the least distance, as [`polyline_distance`] picks it.
    pub(super) fn near_polyline(
        &self,
        pts: &[[f64; 2]],
        radius: f64,
    ) -> Vec<(usize, f64, usize, f64)> {
        let n = self.grid.n;
        let last = (n - 1) as f64;
        let segments: Vec<([f64; 2], [f64; 2])> = if pts.len() == 1 {
            vec![(pts[0], pts[0])]
        } else {
            pts.windows(2).map(|w| (w[0], w[1])).collect()
        };
        let mut best: std::collections::BTreeMap<usize, (f64, usize, f64)> = Default::default();
        for (s, (a, b)) in segments.iter().enumerate() {
            let lo = self
                .grid
                .grid_coords(a[0].min(b[0]) - radius, a[1].min(b[1]) - radius);
            let hi = self
                .grid
                .grid_coords(a[0].max(b[0]) + radius, a[1].max(b[1]) + radius);
            if hi.0 < 0.0 || hi.1 < 0.0 || lo.0 > last || lo.1 > last {
                continue;
            }
            // One sample of slack against rounding at the box's edges (the distance decides).
            let (i0, j0) = (
                (lo.0 - 1.0).max(0.0).ceil() as usize,
                (lo.1 - 1.0).max(0.0).ceil() as usize,
            );
            let (i1, j1) = (
                (hi.0 + 1.0).min(last).floor() as usize,
                (hi.1 + 1.0).min(last).floor() as usize,
            );
            for j in j0..=j1 {
                for i in i0..=i1 {
                    let p = self.grid.position(i, j);
                    let (d, _, t) = polyline_distance(&[*a, *b], p);
                    if d > radius {
                        continue;
                    }
                    let v = j * n + i;
                    let entry = best.entry(v).or_insert((f64::INFINITY, s, t));
                    if d < entry.0 {
                        *entry = (d, s, t);
                    }
                }
            }
        }
        if best.is_empty() {
            // Nothing within the radius: the nearest sample, by a full scan.
            let mut nearest = (f64::INFINITY, 0, 0, 0.0);
            for v in 0..n * n {
                let (d, s, t) = polyline_distance(pts, self.grid.position(v % n, v / n));
                if d < nearest.0 {
                    nearest = (d, v, s, t);
                }
            }
            return vec![(nearest.1, nearest.0, nearest.2, nearest.3)];
        }
        best.into_iter()
            .map(|(v, (d, s, t))| (v, d, s, t))
            .collect()
    }

    /// Hard elevation constraint along a polyline (one point is a polyline of one point), the
    /// elevation interpolated linearly between the points' elevations.
    pub fn elevation(&mut self, pts: &[[f64; 2]], elevations: &[f64], radius: f64) {
        for (v, _, s, t) in self.near_polyline(pts, radius) {
            let e = if elevations.len() == 1 {
                elevations[0]
            } else {
                elevations[s] * (1.0 - t) + elevations[s + 1] * t
            };
            self.fix(v, e);
        }
    }

    /// The C² ring of a hard elevation constraint: a sample at distance `r` from the polyline
    /// with `radius < r < radius + ring` (metres) takes `h = h_p + (e − h_p)·S((radius + ring −
    /// r)/ring)`, `h_p` its procedural height, `e` the elevation of its closest point and `S`
    /// [`smootherstep`]; the samples beyond, up to two spacings past the ring, keep `h_p`
    /// (`d = 0`), so the solve sees the ring's outer edge as it is. Samples inside `skip` (the
    /// painted region's polygon) are left to the constraint.
    pub fn elevation_ring(
        &mut self,
        pts: &[[f64; 2]],
        elevations: &[f64],
        radius: f64,
        ring: f64,
        skip: Option<&[[f64; 2]]>,
    ) {
        let reach = radius + ring + 2.0 * self.grid.spacing_m;
        for (v, r, s, t) in self.near_polyline(pts, reach) {
            let n = self.grid.n;
            if r <= radius || r > reach {
                continue;
            }
            if skip.is_some_and(|poly| inside_polygon(poly, self.grid.position(v % n, v / n))) {
                continue;
            }
            let e = if elevations.len() == 1 {
                elevations[0]
            } else {
                elevations[s] * (1.0 - t) + elevations[s + 1] * t
            };
            let base = f64::from(self.base[v]);
            self.fix(
                v,
                base + (e - base) * smootherstep((radius + ring - r) / ring),
            );
        }
    }

    /// Hard elevation constraint over a painted region: every sample inside the polygon `poly`
    /// (even-odd rule) or within `radius` of its outline takes `elevation`.
    pub fn elevation_region(&mut self, poly: &[[f64; 2]], elevation: f64, radius: f64) {
        let n = self.grid.n;
        for v in 0..n * n {
            if inside_polygon(poly, self.grid.position(v % n, v / n)) {
                self.fix(v, elevation);
            }
        }
        let mut ring = poly.to_vec();
        ring.push(poly[0]);
        self.elevation(&ring, &[elevation], radius);
    }

    /// Freeze brush: fixes the samples within `radius` of `center` at the displacement `current`
    /// (the solution of the operations so far) and protects them from later hard constraints.
    pub fn freeze(&mut self, center: [f64; 2], radius: f64, current: &[f32]) {
        for (v, ..) in self.near_polyline(&[center], radius) {
            if self.grid.is_interior(v % self.grid.n, v / self.grid.n) {
                self.fixed[v] = true;
                self.d[v] = current[v];
                self.frozen[v] = true;
            }
        }
    }

    /// Visits every edge with its midpoint: `f(is_x_edge, edge index, midpoint, (a, b))` where
    /// `a`, `b` are the sample indices at its ends.
    pub(super) fn edges(
        &mut self,
        mut f: impl FnMut(&mut Self, bool, usize, [f64; 2], (usize, usize)),
    ) {
        let n = self.grid.n;
        let h = self.grid.spacing_m;
        for j in 0..n {
            for i in 0..n - 1 {
                let p = self.grid.position(i, j);
                f(
                    self,
                    true,
                    j * (n - 1) + i,
                    [p[0] + 0.5 * h, p[1]],
                    (j * n + i, j * n + i + 1),
                );
            }
        }
        for j in 0..n - 1 {
            for i in 0..n {
                let p = self.grid.position(i, j);
                f(
                    self,
                    false,
                    j * n + i,
                    [p[0], p[1] + 0.5 * h],
                    (j * n + i, (j + 1) * n + i),
                );
            }
        }
    }

    /// Gradient amplify/suppress brush: the target gradient of the heights, `∇h_proc + g_d`,
    /// is scaled by `1 + (factor − 1)·f(r)`.
    pub fn amplify(&mut self, center: [f64; 2], radius: f64, factor: f64) {
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, mid, (a, b)| {
            let w = falloff(dist(mid, center), radius);
            if w == 0.0 {
                return;
            }
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            let total = proc + f64::from(*g);
            *g = (f64::from(*g) + (factor - 1.0) * w * total) as f32;
        });
    }

    /// Noise brush: `g += f(r)·A·∇n` with `n = amplitude · lattice(x/λ, z/λ)` and the tensor
    /// `A = I + modulation` (§4.3 applied to the noise, as in Fig. 11 where the noise is
    /// oriented by tensors; `modulation = μ·M(θ)` stretches the noise's slopes along `θ` by
    /// `1 + μ` and across it by `1 − μ`; zero for plain noise). The component along an edge is
    /// the noise's difference across the edge; the other, for the tensor, its central
    /// difference at the edge's midpoint.
    #[allow(clippy::too_many_arguments)]
    pub fn noise(
        &mut self,
        world_seed: u64,
        center: [f64; 2],
        radius: f64,
        amplitude: f64,
        wavelength: f64,
        seed: u32,
        modulation: [[f64; 2]; 2],
    ) {
        let s = stream(world_seed, NOISE_PURPOSE, seed);
        let n_at = |p: [f64; 2]| {
            amplitude
                * f64::from(lattice(
                    (p[0] / wavelength) as f32,
                    (p[1] / wavelength) as f32,
                    s,
                ))
        };
        let modulated = modulation.iter().flatten().any(|m| *m != 0.0);
        let h = self.grid.spacing_m;
        let inv = 1.0 / h;
        self.edges(|c, is_x, e, mid, (a, b)| {
            let w = falloff(dist(mid, center), radius);
            if w == 0.0 {
                return;
            }
            let n = c.grid.n;
            let pa = c.grid.position(a % n, a / n);
            let pb = c.grid.position(b % n, b / n);
            let along = (n_at(pb) - n_at(pa)) * inv;
            let dn = if modulated {
                let off = if is_x { [0.0, 0.5 * h] } else { [0.5 * h, 0.0] };
                let across = (n_at([mid[0] + off[0], mid[1] + off[1]])
                    - n_at([mid[0] - off[0], mid[1] - off[1]]))
                    * inv;
                let g = if is_x {
                    [along, across]
                } else {
                    [across, along]
                };
                let axis = usize::from(!is_x);
                along + modulation[axis][0] * g[0] + modulation[axis][1] * g[1]
            } else {
                along
            };
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (f64::from(*g) + w * dn) as f32;
        });
    }

    /// Crest (Fig. 4): the ridge line fixed at `elevation` (hard), and on both flanks, out to
    /// `width`, a target slope of `slope_deg` falling away from the line (soft; it replaces the
    /// target gradient there, blended out over the last third of the width).
    pub fn crest(&mut self, pts: &[[f64; 2]], elevation: f64, slope_deg: f64, width: f64) {
        let half = 0.5 * self.grid.spacing_m;
        self.elevation(pts, &[elevation], half);
        let tan = slope_deg.to_radians().tan();
        let inv = 1.0 / self.grid.spacing_m;
        let index = Nearest::new(pts, width);
        self.edges(|c, is_x, e, mid, (a, b)| {
            let Some((d, s, t)) = index.get(mid) else {
                return;
            };
            if d == 0.0 {
                return;
            }
            let w = ((width - d) / (width / 3.0)).min(1.0);
            let (p0, p1) = if pts.len() == 1 {
                (pts[0], pts[0])
            } else {
                (pts[s], pts[s + 1])
            };
            let q = [p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])];
            let away = [(mid[0] - q[0]) / d, (mid[1] - q[1]) / d];
            let target = -tan * if is_x { away[0] } else { away[1] };
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (f64::from(*g) * (1.0 - w) + (target - proc) * w) as f32;
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_polyline_finds_what_a_full_scan_finds() {
        let n = 33;
        let grid = RegionGrid {
            origin: [10.0, 20.0],
            spacing_m: 0.75,
            n,
            max: [34.0, 44.0],
        };
        let c = Canvas::new(grid, vec![0.0; n * n]);
        let line = [
            [12.3, 21.1],
            [30.2, 25.7],
            [18.0, 40.9],
            [18.0, 40.9],
            [29.5, 43.0],
        ];
        for radius in [0.0, 0.3, 0.75, 2.6] {
            let fast = c.near_polyline(&line, radius);
            let full: Vec<_> = (0..n * n)
                .filter_map(|v| {
                    let (d, s, t) = polyline_distance(&line, grid.position(v % n, v / n));
                    (d <= radius).then_some((v, d, s, t))
                })
                .collect();
            if full.is_empty() {
                assert_eq!(
                    fast.len(),
                    1,
                    "the nearest sample when none is within {radius}"
                );
            } else {
                assert_eq!(fast, full, "radius {radius}");
            }
        }
        // A point far outside the grid still gets its nearest sample.
        assert_eq!(c.near_polyline(&[[-100.0, 20.0]], 1.0)[0].0, 0);
    }
}
