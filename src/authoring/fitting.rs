//! Global fitting tools (Guérin et al. 2022, §5.1, Figs. 10 and 11) and the two-pass
//! regularisation (§3), rasterised on a [`Canvas`] in the displacement formulation of [`super`].
//!
//! - Contours: "a simple and direct correspondence between input contour lines and elevation
//!   constraints". Each line fixes the samples within half a spacing of it at its elevation
//!   (so every grid edge the line crosses has a fixed end: a closed line is a closed barrier of
//!   the 5-point stencil). The relief between the lines is the prior target gradient of the
//!   heights scaled by `detail`: 0 is the paper's "null-Laplacian" (bare diffusion), whose
//!   discrete maximum principle keeps the surface between two nested contours within their
//!   elevations; larger values keep that share of the prior relief as detail (the paper layers
//!   noise into the gradient map, Fig. 10).
//! - Ridge/river networks: each edge is a polyline from node to node, an elevation constraint
//!   whose elevation is linear in arc length between the nodes' elevations, so edges meeting at
//!   a node agree there and a river whose end node is not higher (validated) never rises along
//!   its course. Beside each edge, out to `width_m`, the flanks of a ridge fall and the banks of
//!   a river rise at `slope_deg` (soft, replacing, as the landform tools do). Deviation: the
//!   paper's anisotropic variant (tensors across ridges, noise moderated by distance, Fig. 11
//!   right) is left to composing the `stroke_tensor` and `noise` tools.
//! - Two-pass regularisation (§3): "first, a reconstruction g̃ ↦ h̃, followed by an extraction
//!   h̃ ↦ g̃′ … the Dirichlet conditions can subsequently be dropped as they become implicitly
//!   incorporated". The extraction is the staggered one of the solver's discretisation (forward
//!   differences on the edges), so `g̃′` is exactly a gradient field (zero discrete curl) whose
//!   reconstruction with the border alone reproduces `h̃`. Frozen samples stay fixed (the freeze
//!   brush's promise outlives the regularisation).

use super::landform::{band, Edit};
use super::raster::{dist, Canvas};
use super::spec_tools::{Contour, EdgeKind, NetworkEdge, NetworkNode};

impl Canvas {
    /// Scales the target gradient of the heights, `∇h_proc + g_d`, by `detail` on every edge.
    pub fn keep_detail(&mut self, detail: f64) {
        if detail == 1.0 {
            return;
        }
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, _, (a, b)| {
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (detail * (proc + f64::from(*g)) - proc) as f32;
        });
    }

    /// Fitting to contours: the prior relief scaled by `detail`, then each line fixed at its
    /// elevation.
    pub fn contours(&mut self, lines: &[Contour], detail: f64) {
        self.keep_detail(detail);
        let half = 0.5 * self.grid.spacing_m;
        for line in lines {
            self.elevation(&line.points, &[line.elevation_m], half);
        }
    }

    /// Fitting to a ridge/river network: the prior relief scaled by `detail`, every edge's
    /// flanks or banks (soft), then every edge's line at its interpolated elevations (hard).
    /// `elevations` are the nodes' ([`super::spec_tools::resolve_elevations`]).
    pub fn network(
        &mut self,
        nodes: &[NetworkNode],
        elevations: &[f64],
        edges: &[NetworkEdge],
        detail: f64,
    ) {
        self.keep_detail(detail);
        let half = 0.5 * self.grid.spacing_m;
        let lines: Vec<(Vec<[f64; 2]>, Vec<f64>)> = edges
            .iter()
            .map(|e| edge_line(nodes, elevations, e))
            .collect();
        for (e, (pts, _)) in edges.iter().zip(&lines) {
            if e.width_m <= 0.0 {
                continue;
            }
            // Ridge flanks fall away from the line, river banks rise away from it.
            let sign = match e.kind {
                EdgeKind::Ridge => -1.0,
                EdgeKind::River => 1.0,
            };
            let k = sign * e.slope_deg.to_radians().tan();
            let width = e.width_m;
            self.by_frame(pts, half + width, |f| {
                let d = f.dist - half;
                (d > 0.0 && d < width)
                    .then(|| Edit::Replace([k * f.away[0], k * f.away[1]], band(d, width)))
            });
        }
        for (pts, es) in &lines {
            self.elevation(pts, es, half);
        }
    }

    /// Two-pass regularisation: the target gradient of `d` becomes the forward differences of
    /// the reconstruction `current` (with the fixed samples at their imposed values), and the
    /// interior constraints that are not frozen are dropped.
    pub fn regularize(&mut self, current: &[f32]) {
        let n = self.grid.n;
        let solved: Vec<f64> = (0..n * n)
            .map(|v| f64::from(if self.fixed[v] { self.d[v] } else { current[v] }))
            .collect();
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, _, (a, b)| {
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = ((solved[b] - solved[a]) * inv) as f32;
        });
        for v in 0..n * n {
            if self.fixed[v] && !self.frozen[v] && self.grid.is_interior(v % n, v / n) {
                self.fixed[v] = false;
                self.d[v] = 0.0;
            }
        }
    }

    /// The discrete curl of the target gradient of `d` around each cell, `∂gz/∂x − ∂gx/∂z`
    /// (per metre), row-major `(n − 1) × (n − 1)`.
    pub fn curl(&self) -> Vec<f64> {
        let n = self.grid.n;
        let inv = 1.0 / self.grid.spacing_m;
        let mut out = Vec::with_capacity((n - 1) * (n - 1));
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                let gx = |i: usize, j: usize| f64::from(self.gx[j * (n - 1) + i]);
                let gz = |i: usize, j: usize| f64::from(self.gz[j * n + i]);
                out.push((gz(i + 1, j) - gz(i, j) - gx(i, j + 1) + gx(i, j)) * inv);
            }
        }
        out
    }
}

/// An edge's polyline (start node, its vertices, end node) and the elevation at each vertex,
/// linear in arc length between the nodes' `elevations`.
pub fn edge_line(
    nodes: &[NetworkNode],
    elevations: &[f64],
    e: &NetworkEdge,
) -> (Vec<[f64; 2]>, Vec<f64>) {
    let (a, b) = (&nodes[e.from], &nodes[e.to]);
    let (ea, eb) = (elevations[e.from], elevations[e.to]);
    let pts: Vec<[f64; 2]> = std::iter::once(a.at)
        .chain(e.points.iter().copied())
        .chain(std::iter::once(b.at))
        .collect();
    let mut walked = vec![0.0; pts.len()];
    for k in 1..pts.len() {
        walked[k] = walked[k - 1] + dist(pts[k - 1], pts[k]);
    }
    let total = walked[pts.len() - 1];
    let es = walked
        .iter()
        .map(|w| {
            let t = if total > 0.0 { w / total } else { 0.0 };
            ea + t * (eb - ea)
        })
        .collect();
    (pts, es)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::authoring::spec_tools::resolve_elevations;

    /// A canvas over a bumpy field, 33 × 33 at 1 m.
    fn canvas() -> Canvas {
        Canvas::unit_grid(33, |x, z| (3.0 * (0.3 * x).sin() * (0.2 * z).cos()) as f32)
    }

    #[test]
    fn regularisation_leaves_a_curl_free_field_and_drops_the_constraints() {
        let mut c = canvas();
        let n = c.grid.n;
        c.elevation(&[[16.0, 16.0]], &[9.0], 1.5);
        c.freeze([8.0, 8.0], 1.0, &vec![0.5; n * n]);
        // A varying amplification is not a gradient: it has curl.
        c.amplify([16.0, 16.0], 10.0, 3.0);
        let before = c.curl().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let current: Vec<f32> = (0..n * n)
            .map(|v| ((v % n) as f32 * 0.1).sin() * (v / n) as f32 * 0.05)
            .collect();
        c.regularize(&current);
        let after = c.curl().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        println!("regularisation: largest |curl| {before:.3e} → {after:.3e} per metre");
        assert!(before > 0.01, "the amplified field has curl: {before}");
        // Single-precision differences of values below 2 m: rounding only.
        assert!(after < 1e-6, "curl after {after}");
        let v = 16 * n + 16;
        assert!(!c.fixed[v], "the elevation constraint is dropped");
        assert!(
            c.fixed[8 * n + 8] && c.d[8 * n + 8] == 0.5,
            "frozen samples stay"
        );
        assert!(c.fixed[0] && c.fixed[n * n - 1], "the border stays");
        // The edge targets are the differences of `current` (fixed samples at their values).
        let e = 5 * (n - 1) + 20;
        let want = current[5 * n + 21] - current[5 * n + 20];
        assert!((c.gx[e] - want).abs() < 1e-6);
    }

    #[test]
    fn keep_detail_scales_the_height_gradient() {
        let mut c = canvas();
        let n = c.grid.n;
        c.keep_detail(0.0);
        // The target of the heights is flat: g_d = −∇h_proc.
        let e = 7 * (n - 1) + 3;
        let proc = c.base[7 * n + 4] - c.base[7 * n + 3];
        assert!((c.gx[e] + proc).abs() < 1e-6);
    }

    #[test]
    fn network_edges_interpolate_their_node_elevations_by_arc_length() {
        let nodes = [
            NetworkNode {
                at: [0.0, 0.0],
                elevation_m: Some(10.0),
            },
            NetworkNode {
                at: [30.0, 40.0],
                elevation_m: None,
            },
        ];
        let e = NetworkEdge {
            from: 0,
            to: 1,
            kind: EdgeKind::River,
            points: vec![[30.0, 0.0]],
            width_m: 0.0,
            slope_deg: 0.0,
            grade_deg: Some(-(1.0f64 / 7.0).atan().to_degrees()),
        };
        // The end node's elevation comes from the grade: 70 m at 1 in 7 drops 10 m.
        let elevations = resolve_elevations(&nodes, std::slice::from_ref(&e)).expect("resolved");
        assert!((elevations[1] - 0.0).abs() < 1e-9, "{elevations:?}");
        let (pts, es) = edge_line(&nodes, &[10.0, 0.0], &e);
        assert_eq!(pts.len(), 3);
        assert_eq!(es, vec![10.0, 10.0 - 10.0 * 30.0 / 70.0, 0.0]);
        // Without the grade the end node has no elevation.
        let bare = NetworkEdge {
            grade_deg: None,
            ..e
        };
        assert_eq!(resolve_elevations(&nodes, &[bare]), Err(1));
    }
}
