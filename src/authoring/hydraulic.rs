//! The hydraulic erosion brush (Guérin et al. 2022, §4.4 and Fig. 14: "an hydraulic-erosion
//! brush adapted from geomorphological simulation", applied in the elevation domain while
//! "retain[ing] previous Dirichlet constraints"). The region is solved up to the brush, the
//! brush erodes the resulting heights, and the gradients go back to the gradient domain.
//!
//! Extraction: rather than replacing the target gradient by the eroded heights' differences
//! (which, at the brush's rim, would keep a deposit's rise but not its fall and shift the
//! whole brush), the erosion's change of each edge's height difference is *added* to the
//! edge's target. The solution `h̃` before the brush satisfies the discrete Poisson equation
//! of the old target at every free sample, so the eroded heights `h̃ + e` satisfy that of the
//! new target exactly: the reconstruction reproduces the erosion (to the solver's tolerance),
//! material conservation included, and later tools edit it like any other relief.
//!
//! The simulation is the particle (droplet) model of Beyer, *Implementation of a method for
//! hydraulic erosion* (2015), which the paper does not fix: each droplet carries water `w`,
//! speed `v` and sediment `s`, moves one cell per step along its inertia-blended downhill
//! direction, and with the height change `Δh` (in cells: heights divided by the spacing, so the
//! model is scale-free) has the capacity `c = max(−Δh, s_min)·v·w·K`. Above capacity (or moving
//! uphill) it deposits, below it erodes `min((c − s)·rate, −Δh)`; then `v² ← max(v² − Δh·G, 0)`
//! and `w ← w·(1 − evaporation)`. Erosion and deposition act on the four samples around the
//! droplet with bilinear weights.
//!
//! Deviations and guarantees:
//! - Determinism: droplets run one after another in index order; droplet `k` starts at a point of
//!   the brush disc hashed from the world seed, the brush seed and `k`
//!   ([`crate::terrain::hash`]); a droplet on a flat spot takes a hashed direction. No global RNG.
//! - Dirichlet constraints: a fixed sample (and any sample outside the brush) is never changed.
//!   Erosion takes from each corner its bilinear share times the brush's C² falloff there;
//!   deposition spreads over the movable corners only.
//! - Conservation: every metre taken is carried as sediment, and a droplet that stops (end of
//!   its steps, leaving the brush or the grid) drops what it carries on the last movable cell it
//!   crossed, so the total height is conserved to rounding.

use super::raster::Canvas;
use crate::terrain::cancel::{Cancel, Cancelled};
use crate::terrain::hash::{hash2, stream, unit};

/// Hash purpose of the droplet seeds.
const DROPLET_PURPOSE: u32 = 0x4a_0003;
/// Inertia of a droplet's direction (share of the previous direction kept per step).
const INERTIA: f64 = 0.05;
/// Sediment capacity factor `K`.
const CAPACITY: f64 = 4.0;
/// Least slope used for the capacity, so droplets on flats still carry some.
const MIN_SLOPE: f64 = 0.01;
/// Share of the excess sediment deposited per step.
const DEPOSITION: f64 = 0.3;
/// Share of the water evaporating per step.
const EVAPORATION: f64 = 0.02;
/// Gravity in the speed update (cells per step squared per cell of drop).
const GRAVITY: f64 = 4.0;

/// The brush's droplet settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Droplets {
    /// How many droplets.
    pub count: u32,
    /// Most steps (cells) per droplet.
    pub steps: u32,
    /// Share of the missing capacity eroded per step, `0..=1`.
    pub erosion_rate: f64,
    /// Hash seed (already mixed with the world seed).
    pub seed: u32,
}

/// A height field being eroded: `n × n` heights in cells (metres over the spacing) and, per
/// sample, how much it may change (0: fixed or outside the brush, up to 1).
#[derive(Debug)]
pub struct Field<'a> {
    /// Samples per side.
    pub n: usize,
    /// Heights, in units of the grid spacing, row-major.
    pub heights: &'a mut [f64],
    /// Erodibility per sample, `0..=1`.
    pub weight: &'a [f64],
}

impl Field<'_> {
    fn height_and_gradient(&self, x: f64, z: f64) -> (f64, [f64; 2]) {
        let n = self.n;
        let (i, j) = (x.floor() as usize, z.floor() as usize);
        let (u, v) = (x - i as f64, z - j as f64);
        let h = |a: usize, b: usize| self.heights[b * n + a];
        let (nw, ne, sw, se) = (h(i, j), h(i + 1, j), h(i, j + 1), h(i + 1, j + 1));
        let gx = (ne - nw) * (1.0 - v) + (se - sw) * v;
        let gz = (sw - nw) * (1.0 - u) + (se - ne) * u;
        let height =
            nw * (1.0 - u) * (1.0 - v) + ne * u * (1.0 - v) + sw * (1.0 - u) * v + se * u * v;
        (height, [gx, gz])
    }

    /// The four samples around `(x, z)` with their bilinear weights.
    fn corners(&self, x: f64, z: f64) -> [(usize, f64); 4] {
        let n = self.n;
        let (i, j) = (x.floor() as usize, z.floor() as usize);
        let (u, v) = (x - i as f64, z - j as f64);
        let c = j * n + i;
        [
            (c, (1.0 - u) * (1.0 - v)),
            (c + 1, u * (1.0 - v)),
            (c + n, (1.0 - u) * v),
            (c + n + 1, u * v),
        ]
    }

    fn movable(&self, x: f64, z: f64) -> bool {
        self.corners(x, z)
            .iter()
            .any(|(c, b)| *b > 0.0 && self.weight[*c] > 0.0)
    }

    /// Takes up to `amount` around `(x, z)`; returns what was taken.
    fn erode(&mut self, x: f64, z: f64, amount: f64) -> f64 {
        let mut taken = 0.0;
        for (c, b) in self.corners(x, z) {
            let t = amount * b * self.weight[c];
            self.heights[c] -= t;
            taken += t;
        }
        taken
    }

    /// Puts `amount` around `(x, z)` on the movable corners; returns what was put (0 when no
    /// corner may move).
    fn deposit(&mut self, x: f64, z: f64, amount: f64) -> f64 {
        let corners = self.corners(x, z);
        let total: f64 = corners
            .iter()
            .filter(|(c, _)| self.weight[*c] > 0.0)
            .map(|(_, b)| b)
            .sum();
        if total <= 0.0 {
            return 0.0;
        }
        let mut put = 0.0;
        for (c, b) in corners {
            if self.weight[c] > 0.0 {
                let p = amount * b / total;
                self.heights[c] += p;
                put += p;
            }
        }
        put
    }

    /// Inside the grid, with a cell to the east and south.
    fn inside(&self, x: f64, z: f64) -> bool {
        let last = (self.n - 1) as f64;
        x >= 0.0 && z >= 0.0 && x < last && z < last
    }
}

/// Droplets run between two polls of the cancellation flag: at most 64 × 512 steps, a few
/// milliseconds.
const DROPLETS_PER_CHECK: u32 = 64;

/// Runs the droplets over `field`, starting in the disc of `radius` (cells) around `center`
/// (grid coordinates). Returns how many droplet steps visited each sample (the nearest sample
/// to each position): the flow.
///
/// # Errors
/// [`Cancelled`] if `cancel` is set (polled every [`DROPLETS_PER_CHECK`] droplets); `field` is
/// then partly eroded.
pub fn run_droplets(
    field: &mut Field<'_>,
    center: [f64; 2],
    radius: f64,
    p: &Droplets,
    cancel: &Cancel,
) -> Result<Vec<u32>, Cancelled> {
    let n = field.n;
    let mut flow = vec![0u32; n * n];
    for k in 0..p.count {
        if k % DROPLETS_PER_CHECK == 0 {
            cancel.check()?;
        }
        let key = k as i32;
        let r = radius * f64::from(unit(hash2(key, 0, p.seed))).sqrt();
        let a = std::f64::consts::TAU * f64::from(unit(hash2(key, 1, p.seed)));
        let (mut x, mut z) = (center[0] + r * a.cos(), center[1] + r * a.sin());
        if !field.inside(x, z) || !field.movable(x, z) {
            continue;
        }
        let (mut dir, mut speed2, mut water, mut sediment) = ([0.0f64; 2], 1.0f64, 1.0f64, 0.0f64);
        let mut last_movable = (x, z);
        for step in 0..p.steps {
            flow[(z.round() as usize) * n + x.round() as usize] += 1;
            let (h, g) = field.height_and_gradient(x, z);
            dir = [
                dir[0] * INERTIA - g[0] * (1.0 - INERTIA),
                dir[1] * INERTIA - g[1] * (1.0 - INERTIA),
            ];
            let len = dir[0].hypot(dir[1]);
            if len < 1e-12 {
                let t =
                    std::f64::consts::TAU * f64::from(unit(hash2(key, 2 + step as i32, p.seed)));
                dir = [t.cos(), t.sin()];
            } else {
                dir = [dir[0] / len, dir[1] / len];
            }
            let (nx, nz) = (x + dir[0], z + dir[1]);
            if !field.inside(nx, nz) || !field.movable(nx, nz) {
                break;
            }
            let dh = field.height_and_gradient(nx, nz).0 - h;
            let capacity = (-dh).max(MIN_SLOPE) * speed2.sqrt() * water * CAPACITY;
            if sediment > capacity || dh > 0.0 {
                let amount = if dh > 0.0 {
                    dh.min(sediment)
                } else {
                    (sediment - capacity) * DEPOSITION
                };
                sediment -= field.deposit(x, z, amount);
            } else {
                let amount = ((capacity - sediment) * p.erosion_rate).min(-dh);
                sediment += field.erode(x, z, amount);
            }
            speed2 = (speed2 - dh * GRAVITY).max(0.0);
            water *= 1.0 - EVAPORATION;
            last_movable = (x, z);
            (x, z) = (nx, nz);
        }
        if sediment > 0.0 {
            // Drop what is left where the droplet stopped, or on the last cell it could change.
            let left = sediment - field.deposit(x, z, sediment);
            if left > 0.0 {
                field.deposit(last_movable.0, last_movable.1, left);
            }
        }
    }
    Ok(flow)
}

impl Canvas {
    /// Hydraulic erosion of the heights `base + current` within `radius` of `center` (see the
    /// module docs), keeping fixed samples; the erosion's change of every edge's height
    /// difference is then added to the edge's target gradient. Returns the eroded heights
    /// (metres) and the flow per sample.
    ///
    /// # Errors
    /// [`Cancelled`] if `cancel` is set while the droplets run; the canvas is then unchanged.
    pub fn hydraulic_erode(
        &mut self,
        center: [f64; 2],
        radius: f64,
        droplets: &Droplets,
        current: &[f32],
        cancel: &Cancel,
    ) -> Result<(Vec<f64>, Vec<u32>), Cancelled> {
        let n = self.grid.n;
        let h = self.grid.spacing_m;
        let weight = self.brush_weights(center, radius);
        let before: Vec<f64> = (0..n * n)
            .map(|v| (f64::from(self.base[v]) + f64::from(current[v])) / h)
            .collect();
        let mut cells = before.clone();
        let (u, v) = self.grid.grid_coords(center[0], center[1]);
        let flow = run_droplets(
            &mut Field {
                n,
                heights: &mut cells,
                weight: &weight,
            },
            [u, v],
            radius / h,
            droplets,
            cancel,
        )?;
        // The change, exactly 0 where the droplets did not touch (fixed samples included).
        let change: Vec<f64> = cells
            .iter()
            .zip(&before)
            .map(|(a, b)| (a - b) * h)
            .collect();
        self.edges(|c, is_x, e, _, (a, b)| {
            let dd = change[b] - change[a];
            if dd != 0.0 {
                let g = if is_x { &mut c.gx[e] } else { &mut c.gz[e] };
                *g = (f64::from(*g) + dd / h) as f32;
            }
        });
        let heights = (0..n * n)
            .map(|v| f64::from(self.base[v]) + f64::from(current[v]) + change[v])
            .collect();
        Ok((heights, flow))
    }
}

/// The droplet seed of a brush: the brush's `seed` hashed with the world seed.
pub fn droplet_seed(world_seed: u64, seed: u32) -> u32 {
    stream(world_seed, DROPLET_PURPOSE, seed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::authoring::raster::falloff;

    /// A valley: a plane tilted toward +z with a shallow V across x and hashed roughness, in
    /// cells, 65 × 65.
    fn valley() -> Vec<f64> {
        let n = 65;
        (0..n * n)
            .map(|v| {
                let (i, j) = ((v % n) as f64, (v / n) as f64);
                let rough = f64::from(unit(hash2(i as i32, j as i32, 7))) * 0.3;
                40.0 - 0.3 * j + 0.15 * (i - 32.0).abs() + rough
            })
            .collect()
    }

    fn run(fixed: &[usize]) -> (Vec<f64>, Vec<f64>, Vec<u32>) {
        let n = 65;
        let before = valley();
        let mut heights = before.clone();
        let weight: Vec<f64> = (0..n * n)
            .map(|v| {
                let (i, j) = ((v % n) as f64, (v / n) as f64);
                if fixed.contains(&v) {
                    0.0
                } else {
                    falloff((i - 32.0).hypot(j - 32.0), 30.0)
                }
            })
            .collect();
        let p = Droplets {
            count: 3000,
            steps: 80,
            erosion_rate: 0.3,
            seed: droplet_seed(1, 2),
        };
        let flow = run_droplets(
            &mut Field {
                n,
                heights: &mut heights,
                weight: &weight,
            },
            [32.0, 32.0],
            30.0,
            &p,
            &Cancel::never(),
        )
        .expect("never cancelled");
        (before, heights, flow)
    }

    #[test]
    fn droplets_conserve_material_and_keep_fixed_samples() {
        let n = 65;
        let fixed: Vec<usize> = (20..45).map(|i| 32 * n + i).collect();
        let (before, after, _) = run(&fixed);
        for v in &fixed {
            assert_eq!(before[*v].to_bits(), after[*v].to_bits(), "fixed {v} moved");
        }
        let moved: f64 = before.iter().zip(&after).map(|(a, b)| (a - b).abs()).sum();
        let net: f64 = before.iter().zip(&after).map(|(a, b)| b - a).sum();
        println!("hydraulic: material moved {moved:.3} cells·samples, net change {net:.2e}");
        assert!(moved > 10.0, "the droplets move material: {moved}");
        // Only rounding: about 10⁶ additions to heights of ~40 cells, each off by ≤ 7·10⁻¹⁵.
        assert!(net.abs() < 1e-7, "net change {net}");
        // Outside the brush nothing changes.
        assert_eq!(before[0].to_bits(), after[0].to_bits());
        // The same seed gives the same result, bit for bit.
        let (_, again, _) = run(&fixed);
        assert!(after
            .iter()
            .zip(&again)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
    }

    #[test]
    fn channels_deepen_along_the_flow_lines() {
        let n = 65;
        let (before, after, flow) = run(&[]);
        // Samples well inside the brush, sorted by flow: the busiest tenth against the rest.
        let mut inner: Vec<usize> = (0..n * n)
            .filter(|v| {
                let (i, j) = ((v % n) as f64, (v / n) as f64);
                (i - 32.0).hypot(j - 32.0) < 20.0
            })
            .collect();
        inner.sort_by_key(|v| std::cmp::Reverse(flow[*v]));
        let change =
            |vs: &[usize]| vs.iter().map(|v| after[*v] - before[*v]).sum::<f64>() / vs.len() as f64;
        let busy = &inner[..inner.len() / 10];
        let (busy_change, rest_change) = (change(busy), change(&inner[inner.len() / 10..]));
        println!(
            "hydraulic: busiest tenth (flow ≥ {}) changes {busy_change:.4} cells, the rest \
             {rest_change:.4}",
            flow[busy[busy.len() - 1]]
        );
        assert!(busy_change < 0.0, "flow lines are cut down: {busy_change}");
        assert!(busy_change < rest_change, "{busy_change} vs {rest_change}");
        // The flow gathers in the valley's axis (i = 32): more there than on the flanks.
        let along = |i: usize| (10..55).map(|j| flow[j * n + i]).sum::<u32>();
        assert!(along(32) > along(14) && along(32) > along(50));
    }
}
