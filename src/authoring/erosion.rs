//! The erosion brush (Guérin et al. 2022, §4.4, "backward compatible tools"): a tool of the
//! elevation domain run inside the gradient framework. The region is solved up to the brush, the
//! brush erodes the resulting heights, and the change of the heights' gradients is added to the
//! target gradient inside the brush. As in the paper, the Dirichlet constraints are kept: a
//! fixed sample never moves, so user-designated elevations hold through the erosion.
//!
//! Adding the change (rather than replacing the target by the eroded heights' gradient) keeps
//! the brush local: the change `Δ` of the heights is zero outside the disc and at fixed samples,
//! and the target gains exactly `∇Δ`, so by linearity the reconstruction becomes the previous
//! one plus `Δ` and nothing outside the disc moves. Replacing would also pull in, inside the
//! disc, whatever mismatch the previous target had with the solved heights (its curl, or a
//! conflicting constraint), and that mismatch would spread beyond the rim.
//!
//! This is the thermal companion of the paper's hydraulic brush (that one is
//! [`super::hydraulic`]): material slides downhill wherever the slope exceeds the talus angle,
//! scaled by the brush's C² falloff, a deterministic Jacobi-style update that removes peaks and
//! fills hollows.

use super::raster::{dist, falloff, Canvas};
use crate::terrain::cancel::{Cancel, Cancelled};

/// Most erosion iterations of one brush.
pub const MAX_EROSION_ITERATIONS: u32 = 500;

impl Canvas {
    /// Erodes the heights `base + current` within `radius` of `center` for `iterations` thermal
    /// steps of talus angle `talus_deg` (rate 0.25 of the excess per neighbour and step), keeping
    /// fixed samples, then adds the change of the heights' differences to the target gradient on
    /// the edges inside the brush.
    ///
    /// # Errors
    /// [`Cancelled`] if `cancel` is set (polled before every sweep of the grid); the canvas is
    /// then unchanged.
    pub fn erode(
        &mut self,
        center: [f64; 2],
        radius: f64,
        talus_deg: f64,
        iterations: u32,
        current: &[f32],
        cancel: &Cancel,
    ) -> Result<(), Cancelled> {
        let n = self.grid.n;
        let h = self.grid.spacing_m;
        let talus = talus_deg.to_radians().tan() * h;
        let weight = self.brush_weights(center, radius);
        let mut heights: Vec<f64> = (0..n * n)
            .map(|v| f64::from(self.base[v]) + f64::from(current[v]))
            .collect();
        let start = heights.clone();
        let mut next = heights.clone();
        for _ in 0..iterations.min(MAX_EROSION_ITERATIONS) {
            cancel.check()?;
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
            let change = ((heights[b] - start[b]) - (heights[a] - start[a])) * inv;
            let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
            *g = (f64::from(*g) + change) as f32;
        });
        Ok(())
    }
}
