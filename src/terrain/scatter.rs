//! Deterministic scatter points (Choroś & Topolski §5: flora and fauna placed by biome weights).
//!
//! Candidates sit on a world-anchored lattice of `spacing_m` (at LOD 0): candidate `(a, b)` is at
//! `((a + u)·s, (b + v)·s)` with `u, v ∈ [0, 1)` hashed from `(seed, a, b)`. Each candidate has a
//! level `ℓ = min(trailing zeros of a hash / 2, 12)`, so a quarter of the candidates of one level
//! reach the next; a tile at LOD `l` keeps those with `ℓ ≥ l`, so the candidate positions of a
//! coarse tile are a subset of its fine tiles' (the biome, kind and height come from the tile's own
//! vertices, so they can differ across LODs near biome borders).
//! A candidate takes biome `b` with probability `w_b` (the vertex weights, bilinearly
//! interpolated), then becomes kind `k` of that biome with probability `density_k`, and is kept
//! only if the ground is dry and not steeper than the kind allows.

use super::hash::{hash2, mix32, purpose, stream, unit};
use super::plan::{WorldPlan, TILE_QUADS, TILE_VERTS};
use super::tile::Tile;
use serde::Serialize;

/// One placed object.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ScatterPoint {
    /// World X, metres.
    pub x: f64,
    /// Ground height, metres.
    pub y: f32,
    /// World Z, metres.
    pub z: f64,
    /// Biome name.
    pub biome: String,
    /// Object kind.
    pub kind: String,
    /// Lowest-detail LOD that still carries this object.
    pub level: u32,
}

/// Scatter of one tile; `tile` supplies heights, normals and weights.
pub fn scatter(plan: &WorldPlan, tile: &Tile) -> Vec<ScatterPoint> {
    let params = &plan.params;
    let s = params.scatter.spacing_m as f64;
    let span = (TILE_QUADS as f64) * tile.spacing_m as f64;
    let (x0, z0) = (tile.origin_x_m(), tile.origin_z_m());
    let seed_pos = stream(plan.seed, purpose::SCATTER, 0);
    let seed_level = stream(plan.seed, purpose::SCATTER, 1);
    let seed_pick = stream(plan.seed, purpose::SCATTER, 2);
    let a0 = (x0 / s).floor() as i64;
    let a1 = ((x0 + span) / s).ceil() as i64;
    let b0 = (z0 / s).floor() as i64;
    let b1 = ((z0 + span) / s).ceil() as i64;
    let k = tile.biome_count;
    let mut out = Vec::new();
    for b in b0..b1 {
        for a in a0..a1 {
            let (ai, bi) = (a as i32, b as i32);
            let level = (hash2(ai, bi, seed_level).trailing_zeros() / 2).min(12);
            if level < tile.key.lod {
                continue;
            }
            let h = hash2(ai, bi, seed_pos);
            let x = (a as f64 + unit(h) as f64) * s;
            let z = (b as f64 + unit(mix32(h ^ 0x5bd1_e995)) as f64) * s;
            // Half-open tile area, so a point belongs to exactly one tile of a LOD.
            if x < x0 || x >= x0 + span || z < z0 || z >= z0 + span {
                continue;
            }
            let fi = (x - x0) / tile.spacing_m as f64;
            let fj = (z - z0) / tile.spacing_m as f64;
            let (i, j) = (
                (fi as usize).min(TILE_VERTS - 2),
                (fj as usize).min(TILE_VERTS - 2),
            );
            let (ti, tj) = ((fi - i as f64) as f32, (fj - j as f64) as f32);
            let corners = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)];
            let cw = [
                (1.0 - ti) * (1.0 - tj),
                ti * (1.0 - tj),
                (1.0 - ti) * tj,
                ti * tj,
            ];
            let mut y = 0.0f32;
            let mut ny = 0.0f32;
            let mut weights = [0.0f32; super::world::MAX_BIOMES];
            for ((ci, cj), wgt) in corners.iter().zip(cw) {
                let v = cj * TILE_VERTS + ci;
                y += wgt * tile.heights[v];
                ny += wgt * tile.normals[v][1];
                for (c, w) in weights.iter_mut().take(k).enumerate() {
                    *w += wgt * tile.weights[v * k + c];
                }
            }
            let pick = hash2(ai, bi, seed_pick);
            let mut u = unit(pick);
            let mut biome = k - 1;
            for (c, w) in weights.iter().take(k).enumerate() {
                if u < *w {
                    biome = c;
                    break;
                }
                u -= w;
            }
            let mut v = unit(mix32(pick));
            for kind in &params.biomes[biome].scatter {
                if v < kind.density {
                    if y > params.sea_level_m && ny >= libm::cosf(kind.max_slope_deg.to_radians()) {
                        out.push(ScatterPoint {
                            x,
                            y,
                            z,
                            biome: params.biomes[biome].name.clone(),
                            kind: kind.kind.clone(),
                            level,
                        });
                    }
                    break;
                }
                v -= kind.density;
            }
        }
    }
    out
}
