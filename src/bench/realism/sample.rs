//! Grids of a world: tiles synthesised in parallel and stitched, and the LOD-consistency check.
//!
//! A grid of `nx × nz` tiles at one LOD takes from each tile its vertices `0..64` along both axes
//! (the 65th row and column repeat the next tile's first), so it has `64·nx × 64·nz` vertices and
//! vertex `(I, J)` of the grid is global lattice vertex `(64·tx0 + I, 64·tz0 + J)` of that LOD, at
//! world `((64·tx0 + I)·δ, (64·tz0 + J)·δ)`, `δ = cell_m · 2^lod`. A vertex is on a biome border
//! when its largest biome weight is below [`BORDER_WEIGHT`].
//!
//! **LOD-consistency ratio** ([`lod_consistency`]): a vertex of LOD `k` at global lattice index
//! `(I, J)` is the LOD-0 vertex `(I·2^k, J·2^k)`. For a grid at LOD `k ≥ 1`, LOD-0 tiles are
//! synthesised at `n × n` evenly spread grid positions (not whole LOD-0 areas; `n` chosen for a
//! wanted number of compared vertices), every grid vertex
//! that falls on one of them is compared, and the figure is the 99th percentile (nearest rank) of
//! `|h_k − h_0|` over those vertices divided by [`WorldPlan::lod_error_bound_m`]`(k)` (a
//! dimensionless ratio; ≤ 1 means the bound holds for 99 % of vertices).

use super::metrics::{percentile, Grid};
use crate::terrain::earth::rivers;
use crate::terrain::{synthesize, TileKey, WorldPlan};
use rayon::prelude::*;
use std::collections::BTreeMap;

/// A vertex whose largest biome weight is below this is on a biome border.
pub const BORDER_WEIGHT: f32 = 0.99;

/// Quads per tile side.
const Q: usize = 64;

/// A stitched grid of tiles.
#[derive(Clone, Debug)]
pub struct Sampled {
    /// Heights.
    pub grid: Grid,
    /// Biome-border vertices, same layout.
    pub border: Vec<bool>,
    /// Lake or river water surface over each vertex, metres (NaN: none), same layout.
    pub water: Vec<f32>,
    /// The tiles' LOD.
    pub lod: u32,
    /// First tile column.
    pub tx0: i64,
    /// First tile row.
    pub tz0: i64,
}

impl Sampled {
    /// The surface a DEM would record: the lake or river surface where there is one, else the
    /// ground.
    pub fn surface(&self) -> Grid {
        let heights = self
            .grid
            .heights
            .iter()
            .zip(&self.water)
            .map(|(h, w)| if w.is_nan() { *h } else { w.max(*h) })
            .collect();
        Grid::new(self.grid.w, self.grid.h, self.grid.spacing_m, heights)
    }
}

/// The first tile coordinate of `n` tiles at `lod` centred on world coordinate `centre_m`.
pub fn first_tile(plan: &WorldPlan, lod: u32, centre_m: f64, n: usize) -> i64 {
    let span = Q as f64 * plan.lods[lod as usize].spacing_m as f64;
    (centre_m / span).round() as i64 - (n / 2) as i64
}

/// Synthesises `nx × nz` tiles at `lod` from tile `(tx0, tz0)` and stitches them.
pub fn sample(plan: &WorldPlan, lod: u32, tx0: i64, tz0: i64, nx: usize, nz: usize) -> Sampled {
    let keys: Vec<TileKey> = (0..nz as i64)
        .flat_map(|b| {
            (0..nx as i64).map(move |a| TileKey {
                lod,
                x: tx0 + a,
                z: tz0 + b,
            })
        })
        .collect();
    let parts: Vec<(Vec<f32>, Vec<bool>, Vec<f32>)> = keys
        .par_iter()
        .map(|key| {
            let t = synthesize(plan, *key);
            let k = t.biome_count.max(1);
            let mut h = Vec::with_capacity(Q * Q);
            let mut b = Vec::with_capacity(Q * Q);
            let mut wt = Vec::with_capacity(Q * Q);
            for j in 0..Q {
                for i in 0..Q {
                    let v = j * (Q + 1) + i;
                    h.push(t.heights[v]);
                    let inland = t
                        .water_kind
                        .get(v)
                        .is_some_and(|k| *k == rivers::kind::LAKE || *k == rivers::kind::RIVER);
                    wt.push(if inland {
                        t.heights[v] + t.water_depth[v]
                    } else {
                        f32::NAN
                    });
                    let max = t.weights[v * k..(v + 1) * k]
                        .iter()
                        .fold(0.0f32, |m, w| m.max(*w));
                    b.push(t.biome_count > 1 && max < BORDER_WEIGHT);
                }
            }
            (h, b, wt)
        })
        .collect();
    let (w, h) = (nx * Q, nz * Q);
    let mut heights = vec![0.0f32; w * h];
    let mut border = vec![false; w * h];
    let mut water = vec![f32::NAN; w * h];
    for (n, (th, tb, tw)) in parts.iter().enumerate() {
        let (a, b) = (n % nx, n / nx);
        for j in 0..Q {
            let row = (b * Q + j) * w + a * Q;
            heights[row..row + Q].copy_from_slice(&th[j * Q..(j + 1) * Q]);
            border[row..row + Q].copy_from_slice(&tb[j * Q..(j + 1) * Q]);
            water[row..row + Q].copy_from_slice(&tw[j * Q..(j + 1) * Q]);
        }
    }
    Sampled {
        grid: Grid::new(w, h, plan.lods[lod as usize].spacing_m as f64, heights),
        border,
        water,
        lod,
        tx0,
        tz0,
    }
}

/// LOD-consistency figures of one grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodCheck {
    /// 99th percentile of `|h_k − h_0|` over the bound (see the module docs).
    pub p99_ratio: f64,
    /// 99th percentile of `|h_k − h_0|`, metres.
    pub p99_diff_m: f64,
    /// Largest `|h_k − h_0|`, metres.
    pub max_diff_m: f64,
    /// `plan.lod_error_bound_m(k)`, metres.
    pub bound_m: f64,
    /// Vertices compared.
    pub vertices: usize,
    /// LOD-0 tiles synthesised.
    pub tiles: usize,
}

/// The LOD-consistency check of `s` with `n × n` LOD-0 sample tiles, `n` the smallest that
/// compares about `min_vertices` vertices (a LOD-0 tile holds `(64 / 2^k)²` vertices of LOD
/// `k`, at least one); `None` at LOD 0.
pub fn lod_consistency(plan: &WorldPlan, s: &Sampled, min_vertices: usize) -> Option<LodCheck> {
    if s.lod == 0 {
        return None;
    }
    let per_tile = (Q >> s.lod.min(6)).pow(2);
    let n = (min_vertices as f64 / per_tile as f64)
        .sqrt()
        .ceil()
        .clamp(2.0, s.grid.w.min(s.grid.h) as f64) as usize;
    let step = 1i64 << s.lod;
    let (gi0, gj0) = (s.tx0 * Q as i64, s.tz0 * Q as i64);
    let (w, h) = (s.grid.w as i64, s.grid.h as i64);
    let mut tiles: Vec<(i64, i64)> = (0..n as i64)
        .flat_map(|b| (0..n as i64).map(move |a| (a, b)))
        .map(|(a, b)| {
            let i = (2 * a + 1) * w / (2 * n as i64);
            let j = (2 * b + 1) * h / (2 * n as i64);
            (
                ((gi0 + i) * step).div_euclid(Q as i64),
                ((gj0 + j) * step).div_euclid(Q as i64),
            )
        })
        .collect();
    tiles.sort_unstable();
    tiles.dedup();
    let diffs: BTreeMap<(i64, i64), f64> = tiles
        .par_iter()
        .map(|&(tx, tz)| {
            let t = synthesize(
                plan,
                TileKey {
                    lod: 0,
                    x: tx,
                    z: tz,
                },
            );
            // Grid vertices I with (gi0 + I)·step in [64·tx, 64·tx + 64].
            let range = |t0: i64, g0: i64, len: i64| {
                let lo = (t0 * Q as i64 + step - 1).div_euclid(step) - g0;
                let hi = (t0 * Q as i64 + Q as i64).div_euclid(step) - g0;
                lo.max(0)..=hi.min(len - 1)
            };
            let mut out = Vec::new();
            for jj in range(tz, gj0, h) {
                for ii in range(tx, gi0, w) {
                    let i0 = ((gi0 + ii) * step - tx * Q as i64) as usize;
                    let j0 = ((gj0 + jj) * step - tz * Q as i64) as usize;
                    let fine = t.heights[j0 * (Q + 1) + i0] as f64;
                    let coarse = s.grid.heights[(jj * w + ii) as usize] as f64;
                    out.push(((ii, jj), (coarse - fine).abs()));
                }
            }
            out
        })
        .flatten()
        .collect();
    let mut d: Vec<f64> = diffs.into_values().collect();
    let bound_m = plan.lod_error_bound_m(s.lod) as f64;
    let p99 = percentile(&mut d, 0.99);
    let max = d.last().copied().unwrap_or(f64::NAN);
    let p99_ratio = if bound_m > 0.0 {
        p99 / bound_m
    } else if p99 <= 1e-4 {
        0.0
    } else {
        f64::INFINITY
    };
    Some(LodCheck {
        p99_ratio,
        p99_diff_m: p99,
        max_diff_m: max,
        bound_m,
        vertices: d.len(),
        tiles: tiles.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::WorldParams;

    #[test]
    fn stitched_grid_drops_the_shared_edge() {
        let plan = WorldPlan::new(3, WorldParams::default()).expect("plan");
        let s = sample(&plan, 2, -1, 0, 2, 1);
        assert_eq!((s.grid.w, s.grid.h), (128, 64));
        let right = synthesize(&plan, TileKey { lod: 2, x: 0, z: 0 });
        let left = synthesize(
            &plan,
            TileKey {
                lod: 2,
                x: -1,
                z: 0,
            },
        );
        assert_eq!(s.grid.heights[64], right.heights[0]);
        assert_eq!(s.grid.heights[3 * 128 + 5], left.heights[3 * 65 + 5]);
        assert_eq!(s.grid.spacing_m, 4.0);
    }

    #[test]
    fn lod_check_compares_the_lod0_vertex_at_twice_the_index() {
        // A "LOD 1" grid made of LOD-0 heights at even indices agrees with LOD 0 exactly; one
        // with the heights at odd indices does not.
        let plan = WorldPlan::new(3, WorldParams::default()).expect("plan");
        let lod0: Vec<_> = (-2..0)
            .map(|x| synthesize(&plan, TileKey { lod: 0, x, z: -2 }))
            .collect();
        let h0 = |gi: i64, gj: i64| {
            let t = &lod0[(gi.div_euclid(64) + 2) as usize];
            t.heights[((gj + 128) * 65 + gi.rem_euclid(64)) as usize]
        };
        for offset in [0, 1] {
            let heights = (0..64 * 32)
                .map(|k| h0(-128 + 2 * (k % 64) + offset, -128 + 2 * (k / 64)))
                .collect();
            let s = Sampled {
                grid: Grid::new(64, 32, 2.0, heights),
                border: vec![false; 64 * 32],
                water: vec![f32::NAN; 64 * 32],
                lod: 1,
                tx0: -1,
                tz0: -1,
            };
            let c = lod_consistency(&plan, &s, 16 * 32 * 32).expect("LOD 1");
            assert!(c.vertices > 100, "{c:?}");
            if offset == 0 {
                assert_eq!(c.max_diff_m, 0.0, "{c:?}");
            } else {
                assert!(c.max_diff_m > 0.0, "{c:?}");
            }
        }
    }
}
