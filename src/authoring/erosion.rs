//! The erosion brush (Guérin et al. 2022, §4.4, "backward compatible tools"): a tool of the
//! elevation domain run inside the gradient framework. The region is solved up to the brush, the
//! brush erodes the resulting heights, and the eroded heights' gradients are extracted back into
//! the target gradient inside the brush. As in the paper, the Dirichlet constraints are kept: a
//! fixed sample never moves, so user-designated elevations hold through the erosion.
//!
//! This is the thermal companion of the paper's hydraulic brush (that one is
//! [`super::hydraulic`]): material slides downhill wherever the slope exceeds the talus angle,
//! scaled by the brush's C² falloff, a deterministic Jacobi-style update that removes peaks and
//! fills hollows.

use super::raster::{dist, falloff, Canvas};

/// Most erosion iterations of one brush.
pub const MAX_EROSION_ITERATIONS: u32 = 500;

impl Canvas {
    /// Erodes the heights `base + current` within `radius` of `center` for `iterations` thermal
    /// steps of talus angle `talus_deg` (rate 0.25 of the excess per neighbour and step), keeping
    /// fixed samples, then replaces the target gradient on the edges inside the brush by the
    /// eroded heights' differences.
    pub fn erode(
        &mut self,
        center: [f64; 2],
        radius: f64,
        talus_deg: f64,
        iterations: u32,
        current: &[f32],
    ) {
        let n = self.grid.n;
        let h = self.grid.spacing_m;
        let talus = talus_deg.to_radians().tan() * h;
        let weight: Vec<f64> = (0..n * n)
            .map(|v| {
                if self.fixed[v] {
                    0.0
                } else {
                    falloff(dist(self.grid.position(v % n, v / n), center), radius)
                }
            })
            .collect();
        let mut heights: Vec<f64> = (0..n * n)
            .map(|v| f64::from(self.base[v]) + f64::from(current[v]))
            .collect();
        let mut next = heights.clone();
        for _ in 0..iterations.min(MAX_EROSION_ITERATIONS) {
            next.copy_from_slice(&heights);
            for j in 0..n {
                for i in 0..n {
                    let v = j * n + i;
                    let neighbours = [
                        (i > 0).then(|| v - 1),
                        (i + 1 < n).then(|| v + 1),
                        (j > 0).then(|| v - n),
                        (j + 1 < n).then(|| v + n),
                    ];
                    for u in neighbours.into_iter().flatten() {
                        // Material leaves `v` toward a lower `u` by a quarter of the excess
                        // drop; both ends must be free to move, weighted by the lesser weight.
                        let excess = heights[v] - heights[u] - talus;
                        let w = weight[v].min(weight[u]);
                        if excess > 0.0 && w > 0.0 {
                            let moved = 0.25 * 0.5 * excess * w;
                            next[v] -= moved;
                            next[u] += moved;
                        }
                    }
                }
            }
            std::mem::swap(&mut heights, &mut next);
        }
        let inv = 1.0 / h;
        self.edges(|c, is_x, e, mid, (a, b)| {
            if falloff(dist(mid, center), radius) == 0.0 {
                return;
            }
            let target = (heights[b] - heights[a]) * inv;
            let proc = (f64::from(c.base[b]) - f64::from(c.base[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (target - proc) as f32;
        });
    }
}
