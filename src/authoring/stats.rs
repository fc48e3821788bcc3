//! Readouts (issue 4, item 3; Guérin et al. 2022 §6.3 reports slopes and elevations of authored
//! terrain): elevation (min, mean, max) and slope (mean, steepest) of a solved region's heights
//! `h = h_proc + d` over a point, a polyline or a rectangle.
//!
//! Slopes use the paper's discrete gradient `g_ij = (h_{i+1,j} − h_{i−1,j}, h_{i,j+1} −
//! h_{i,j−1}) / 2δ` (one-sided at the grid's border), `slope = atan |g|`. Elevations at a point
//! or along a polyline are bilinear in the samples; a polyline is read every half spacing; a
//! rectangle reads every grid sample inside it (at least the one nearest its centre).

use super::region::Displacement;
use serde::{Deserialize, Serialize};

/// Most polyline readout points (half-spacing steps) before a readout is refused.
pub const MAX_READOUT_POINTS: usize = 1 << 20;

/// Where to read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum StatsShape {
    /// One point `[x, z]`, metres.
    Point([f64; 2]),
    /// A polyline of points `[x, z]`, metres.
    Polyline(Vec<[f64; 2]>),
    /// An axis-aligned rectangle, corners `[x, z]` in metres.
    Rect {
        /// West-north corner.
        min: [f64; 2],
        /// East-south corner.
        max: [f64; 2],
    },
}

/// A readout.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stats {
    /// Lowest elevation, metres.
    pub elevation_min_m: f64,
    /// Mean elevation, metres.
    pub elevation_mean_m: f64,
    /// Highest elevation, metres.
    pub elevation_max_m: f64,
    /// Mean slope, degrees.
    pub mean_slope_deg: f64,
    /// Steepest slope, degrees.
    pub steepest_slope_deg: f64,
    /// Readout points used.
    pub samples: usize,
}

/// A refused readout: the field and the reason.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct StatsError {
    /// The offending field (`point`, `polyline/2`, `rect`).
    pub field: String,
    /// Why.
    pub message: String,
}

fn refuse(field: impl Into<String>, message: impl Into<String>) -> StatsError {
    StatsError {
        field: field.into(),
        message: message.into(),
    }
}

/// Heights and slopes of a solved region.
struct Surface<'a> {
    r: &'a Displacement,
}

impl Surface<'_> {
    fn h(&self, i: usize, j: usize) -> f64 {
        let v = j * self.r.grid.n + i;
        f64::from(self.r.base[v]) + f64::from(self.r.d[v])
    }

    /// Slope at sample `(i, j)`, degrees.
    fn slope(&self, i: usize, j: usize) -> f64 {
        let n = self.r.grid.n;
        let diff = |lo: (usize, usize), hi: (usize, usize), steps: usize| {
            (self.h(hi.0, hi.1) - self.h(lo.0, lo.1)) / (steps as f64 * self.r.grid.spacing_m)
        };
        let (il, ih) = (i.saturating_sub(1), (i + 1).min(n - 1));
        let (jl, jh) = (j.saturating_sub(1), (j + 1).min(n - 1));
        let gx = diff((il, j), (ih, j), ih - il);
        let gz = diff((i, jl), (i, jh), jh - jl);
        gx.hypot(gz).atan().to_degrees()
    }

    /// Bilinear height and the slope at the nearest sample of a position inside the grid.
    fn at(&self, p: [f64; 2]) -> (f64, f64) {
        let g = &self.r.grid;
        let last = (g.n - 1) as f64;
        let (u, v) = g.grid_coords(p[0], p[1]);
        let (u, v) = (u.clamp(0.0, last), v.clamp(0.0, last));
        let (i, j) = (
            (u.floor() as usize).min(g.n - 2),
            (v.floor() as usize).min(g.n - 2),
        );
        let (fu, fv) = (u - i as f64, v - j as f64);
        let top = self.h(i, j) * (1.0 - fu) + self.h(i + 1, j) * fu;
        let bottom = self.h(i, j + 1) * (1.0 - fu) + self.h(i + 1, j + 1) * fu;
        let h = top * (1.0 - fv) + bottom * fv;
        (h, self.slope(u.round() as usize, v.round() as usize))
    }

    fn inside(&self, p: [f64; 2]) -> bool {
        let g = &self.r.grid;
        p.iter().all(|c| c.is_finite())
            && p[0] >= g.origin[0]
            && p[1] >= g.origin[1]
            && p[0] <= g.max[0]
            && p[1] <= g.max[1]
    }
}

/// Accumulates readout points.
#[derive(Default)]
struct Acc {
    min: f64,
    max: f64,
    sum_h: f64,
    sum_s: f64,
    steep: f64,
    count: usize,
}

impl Acc {
    fn add(&mut self, (h, s): (f64, f64)) {
        if self.count == 0 {
            self.min = h;
            self.max = h;
        }
        self.min = self.min.min(h);
        self.max = self.max.max(h);
        self.sum_h += h;
        self.sum_s += s;
        self.steep = self.steep.max(s);
        self.count += 1;
    }

    fn done(self) -> Stats {
        let n = self.count.max(1) as f64;
        Stats {
            elevation_min_m: self.min,
            elevation_mean_m: self.sum_h / n,
            elevation_max_m: self.max,
            mean_slope_deg: self.sum_s / n,
            steepest_slope_deg: self.steep,
            samples: self.count,
        }
    }
}

/// Elevation and slope statistics of the solved region `r` over `shape`.
///
/// # Errors
/// [`StatsError`] naming the field when the shape is empty, not finite or leaves the region's
/// bbox, or a polyline needs more than [`MAX_READOUT_POINTS`] readout points.
pub fn stats(r: &Displacement, shape: &StatsShape) -> Result<Stats, StatsError> {
    let s = Surface { r };
    let outside = "must lie inside the region's bbox";
    let mut acc = Acc::default();
    match shape {
        StatsShape::Point(p) => {
            if !s.inside(*p) {
                return Err(refuse("point", outside));
            }
            acc.add(s.at(*p));
        }
        StatsShape::Polyline(pts) => {
            if pts.is_empty() {
                return Err(refuse("polyline", "needs at least one point"));
            }
            for (k, p) in pts.iter().enumerate() {
                if !s.inside(*p) {
                    return Err(refuse(format!("polyline/{k}"), outside));
                }
            }
            let step = 0.5 * r.grid.spacing_m;
            let length: f64 = pts
                .windows(2)
                .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
                .sum();
            if length / step > MAX_READOUT_POINTS as f64 {
                return Err(refuse(
                    "polyline",
                    format!("too long: at most {MAX_READOUT_POINTS} half-spacing steps"),
                ));
            }
            acc.add(s.at(pts[0]));
            for w in pts.windows(2) {
                let len = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
                let steps = (len / step).ceil().max(1.0) as usize;
                for k in 1..=steps {
                    let t = k as f64 / steps as f64;
                    acc.add(s.at([
                        w[0][0] + t * (w[1][0] - w[0][0]),
                        w[0][1] + t * (w[1][1] - w[0][1]),
                    ]));
                }
            }
        }
        StatsShape::Rect { min, max } => {
            if !s.inside(*min) || !s.inside(*max) {
                return Err(refuse("rect", outside));
            }
            if max[0] < min[0] || max[1] < min[1] {
                return Err(refuse("rect", "max must not be west or north of min"));
            }
            let g = &r.grid;
            for j in 0..g.n {
                for i in 0..g.n {
                    let p = g.position(i, j);
                    if (min[0]..=max[0]).contains(&p[0]) && (min[1]..=max[1]).contains(&p[1]) {
                        acc.add((s.h(i, j), s.slope(i, j)));
                    }
                }
            }
            if acc.count == 0 {
                acc.add(s.at([0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1])]));
            }
        }
    }
    Ok(acc.done())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::authoring::RegionGrid;

    /// A tilted plane `h = 0.3·(x − 100) + 10` (slope atan 0.3 ≈ 16.70°), half procedural and
    /// half displacement.
    fn plane() -> Displacement {
        let n = 33;
        let grid = RegionGrid {
            origin: [100.0, 200.0],
            spacing_m: 2.0,
            n,
            max: [164.0, 264.0],
        };
        let mut base = Vec::new();
        let mut d = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let h = 0.3 * (grid.position(i, j)[0] - 100.0) + 10.0;
                base.push((0.5 * h) as f32);
                d.push((0.5 * h) as f32);
            }
        }
        Displacement {
            id: "p".into(),
            grid,
            d,
            base,
            fixed: vec![false; n * n],
            cycles: 0,
        }
    }

    #[test]
    fn readouts_of_a_plane_match_the_analytic_values() {
        let r = plane();
        let slope = 0.3f64.atan().to_degrees();
        let rect = stats(
            &r,
            &StatsShape::Rect {
                min: [110.0, 210.0],
                max: [130.0, 250.0],
            },
        )
        .expect("inside");
        assert!((rect.elevation_min_m - 13.0).abs() < 1e-4, "{rect:?}");
        assert!((rect.elevation_max_m - 19.0).abs() < 1e-4, "{rect:?}");
        assert!((rect.elevation_mean_m - 16.0).abs() < 1e-4, "{rect:?}");
        assert!((rect.mean_slope_deg - slope).abs() < 1e-3, "{rect:?}");
        assert!((rect.steepest_slope_deg - slope).abs() < 1e-3, "{rect:?}");
        assert_eq!(rect.samples, 11 * 21);

        let point = stats(&r, &StatsShape::Point([123.0, 231.5])).expect("inside");
        assert!((point.elevation_mean_m - (0.3 * 23.0 + 10.0)).abs() < 1e-4);
        assert!((point.steepest_slope_deg - slope).abs() < 1e-3);

        // Along the contour x = 140 the elevation is constant; across it, it rises linearly.
        let along = stats(
            &r,
            &StatsShape::Polyline(vec![[140.0, 205.0], [140.0, 255.0]]),
        )
        .expect("inside");
        assert!((along.elevation_max_m - along.elevation_min_m).abs() < 1e-4);
        let across = stats(
            &r,
            &StatsShape::Polyline(vec![[105.0, 230.0], [155.0, 230.0]]),
        )
        .expect("inside");
        assert!((across.elevation_min_m - 11.5).abs() < 1e-4, "{across:?}");
        assert!((across.elevation_max_m - 26.5).abs() < 1e-4, "{across:?}");
        assert!((across.elevation_mean_m - 19.0).abs() < 1e-4, "{across:?}");
    }

    #[test]
    fn readouts_outside_the_region_are_refused_naming_the_field() {
        let r = plane();
        let e = stats(&r, &StatsShape::Point([0.0, 0.0])).expect_err("outside");
        assert_eq!(e.field, "point");
        let e = stats(
            &r,
            &StatsShape::Polyline(vec![[110.0, 210.0], [500.0, 210.0]]),
        )
        .expect_err("outside");
        assert_eq!(e.field, "polyline/1");
        let e = stats(&r, &StatsShape::Polyline(vec![])).expect_err("empty");
        assert_eq!(e.field, "polyline");
    }
}
