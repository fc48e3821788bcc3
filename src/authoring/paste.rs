//! Copy-paste of gradients (Guérin et al. 2022, §4.1): a rectangle of the procedural world is
//! copied, rotated and scaled, and its gradients replace the target gradient of the heights over
//! the pasted footprint. The reconstruction blends the paste seamlessly into its surroundings,
//! as in Poisson image editing: elevations are matched across the footprint's boundary, only the
//! gradients are carried over.
//!
//! Mapping: a point `p` of the footprint reads the source at `c_s + R(−θ)(p − c_t)/s` for the
//! source centre `c_s`, the target centre `c_t`, the rotation `θ` (from +x toward +z: clockwise
//! on a north-up map) and the scale `s`. Heights are copied, not scaled, so the pasted gradient is
//! `R(θ)·∇h_src / s`. The source is the procedural world of the same world (before any edit).

use super::grid::{Procedural, RegionGrid};
use super::raster::Canvas;
use crate::terrain::WorldPlan;

/// Most samples per side of a paste's source grid; a larger source is sampled more coarsely.
pub const MAX_SOURCE_SAMPLES: usize = 2049;

/// The procedural heights of a paste's source rectangle.
#[derive(Clone, Debug, PartialEq)]
pub struct PasteSource {
    /// The source grid (square, from the rectangle's west-north corner).
    pub grid: RegionGrid,
    /// Heights at the grid's samples, metres, row-major.
    pub heights: Vec<f32>,
    /// The source rectangle's centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Half the source rectangle's width and depth, metres.
    pub half: [f64; 2],
}

impl PasteSource {
    /// Samples the world's procedural heights over `min..max` every `spacing_m` (coarser if
    /// that needs more than [`MAX_SOURCE_SAMPLES`] per side).
    pub fn sample(plan: &WorldPlan, min: [f64; 2], max: [f64; 2], spacing_m: f64) -> Self {
        let extent = (max[0] - min[0]).max(max[1] - min[1]);
        let wanted = (extent / spacing_m).ceil() as usize + 2;
        let n = wanted.clamp(2, MAX_SOURCE_SAMPLES);
        let spacing_m = if wanted > MAX_SOURCE_SAMPLES {
            extent / (n - 2) as f64
        } else {
            spacing_m
        };
        let grid = RegionGrid {
            origin: min,
            spacing_m,
            n,
            max,
        };
        Self {
            grid,
            heights: Procedural::sample(plan, &grid).heights,
            center: [0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1])],
            half: [0.5 * (max[0] - min[0]), 0.5 * (max[1] - min[1])],
        }
    }

    /// Bilinear source height at a world position (clamped to the grid), metres.
    pub fn height(&self, p: [f64; 2]) -> f64 {
        let g = &self.grid;
        let last = (g.n - 1) as f64;
        let (u, v) = g.grid_coords(p[0], p[1]);
        let (u, v) = (u.clamp(0.0, last), v.clamp(0.0, last));
        let (i, j) = (
            (u.floor() as usize).min(g.n - 2),
            (v.floor() as usize).min(g.n - 2),
        );
        let (fu, fv) = (u - i as f64, v - j as f64);
        let h = |i: usize, j: usize| f64::from(self.heights[j * g.n + i]);
        let top = h(i, j) * (1.0 - fu) + h(i + 1, j) * fu;
        let bottom = h(i, j + 1) * (1.0 - fu) + h(i + 1, j + 1) * fu;
        top * (1.0 - fv) + bottom * fv
    }
}

/// Where the pasted copy lies: target centre, rotation and scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Centre of the pasted copy `[x, z]`, metres.
    pub target: [f64; 2],
    /// Rotation, degrees (from +x toward +z).
    pub rotation_deg: f64,
    /// Horizontal scale of the copy.
    pub scale: f64,
}

impl Placement {
    /// The source position a target point reads, and whether it lies in the source rectangle.
    pub fn source_of(&self, src: &PasteSource, p: [f64; 2]) -> ([f64; 2], bool) {
        let (s, c) = self.rotation_deg.to_radians().sin_cos();
        let l = [p[0] - self.target[0], p[1] - self.target[1]];
        let local = [
            (c * l[0] + s * l[1]) / self.scale,
            (-s * l[0] + c * l[1]) / self.scale,
        ];
        let inside = local[0].abs() <= src.half[0] && local[1].abs() <= src.half[1];
        ([src.center[0] + local[0], src.center[1] + local[1]], inside)
    }
}

impl Canvas {
    /// Copy-paste: on every edge whose two ends fall in the pasted footprint, the target
    /// gradient of the heights becomes the source's height difference along the mapped edge
    /// over the edge's length (soft, replacing).
    pub fn paste(&mut self, src: &PasteSource, at: &Placement) {
        let inv = 1.0 / self.grid.spacing_m;
        self.edges(|c, is_x, e, _, (a, b)| {
            let n = c.grid.n;
            let (sa, ina) = at.source_of(src, c.grid.position(a % n, a / n));
            let (sb, inb) = at.source_of(src, c.grid.position(b % n, b / n));
            if !(ina && inb) {
                return;
            }
            let target = (src.height(sb) - src.height(sa)) * inv;
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (target - proc) as f32;
        });
    }
}
