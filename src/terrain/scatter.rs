//! Deterministic scatter points (Choroś & Topolski §5: flora and fauna placed by biome weights).
//!
//! Every candidate has a level `ℓ ≤` [`MAX_LEVEL`]; a tile at LOD `l` keeps those with `ℓ ≥ l`,
//! so the candidate positions of a coarse tile are a subset of its fine tiles' (the biome, kind
//! and height come from the tile's own vertices, so they can differ across LODs near biome
//! borders). A world's [`ScatterLattice`] says where candidates sit and how they get their
//! level, with `s = spacing_m`:
//!
//! - **`scan`** (worlds stored before `levels`): candidate `(a, b)` of one world-anchored
//!   lattice of `s` is at `((a + u)·s, (b + v)·s)` with `u, v ∈ [0, 1)` hashed from
//!   `(seed, a, b)`, and `ℓ = min(trailing zeros of a hash / 2, 12)`, so a quarter of the
//!   candidates of one level reach the next. A tile visits every candidate of its area: a tile
//!   one LOD coarser visits 4 times as many ([`candidates`]).
//! - **`levels`** (the default): level `L` has its own lattice of `s·2^L`, candidate `(a, b)` of
//!   it is at `((a + u)·s·2^L, (b + v)·s·2^L)` with `u, v` hashed from `(seed, L, a, b)` and has
//!   level `L`; a tile at LOD `l` visits the lattices `L = l ..= 12`, about `(64·δ/s)²·4/3`
//!   candidates (`δ` its spacing) whatever the LOD. The density of level `≥ L` falls by 4 per
//!   level, as with `scan`.
//!
//! A candidate takes biome `b` with probability `w_b` (the vertex weights, bilinearly
//! interpolated), then becomes kind `k` of that biome with probability `density_k`, and is kept
//! only if the ground is dry and not steeper than the kind allows.

use super::hash::{hash2, mix32, purpose, stream, unit};
use super::plan::{WorldPlan, TILE_QUADS, TILE_VERTS};
use super::tile::Tile;
use super::world::ScatterLattice;
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

/// The highest level a candidate can have: [`super::MAX_LOD`], so the coarsest tiles keep some.
pub const MAX_LEVEL: u32 = 12;

/// The candidates a tile at `lod` visits (with [`ScatterLattice::Scan`] it grows 4× per LOD),
/// known before any work, so a request can be refused by its cost.
pub fn candidates(plan: &WorldPlan, lod: u32) -> u64 {
    let s = plan.params.scatter.spacing_m as f64;
    let span = TILE_QUADS as f64 * plan.lods[lod as usize].spacing_m as f64;
    // A tile's area meets at most ⌈span / s⌉ + 1 lattice columns of spacing `s`.
    let side = |s: f64| (span / s).ceil() as u64 + 1;
    match plan.params.scatter.lattice {
        ScatterLattice::Scan => side(s).pow(2),
        ScatterLattice::Levels => (lod..=MAX_LEVEL)
            .map(|l| side(s * f64::from(1u32 << l)).pow(2))
            .sum(),
    }
}

/// Most candidates one scatter tile may visit (about 10 ms of one core): a `levels` world's
/// tiles visit a few hundred at every LOD; a `scan` world reaches it past LOD 6.
pub const MAX_CANDIDATES: u64 = 1 << 22;

/// Why scatter at `lod` costs too much for this world, if it does: the message names the limit
/// and the coarsest LOD served.
pub fn cost_error(plan: &WorldPlan, lod: u32) -> Option<String> {
    let n = candidates(plan, lod);
    (n > MAX_CANDIDATES).then(|| {
        let served = (0..lod)
            .take_while(|l| candidates(plan, *l) <= MAX_CANDIDATES)
            .last()
            .unwrap_or(0);
        format!(
            "scatter at LOD {lod} would visit {n} candidates, more than the limit of \
             {MAX_CANDIDATES}; this world's scatter lattice (scan) is served up to LOD {served}"
        )
    })
}

/// Scatter of one tile; `tile` supplies heights, normals and weights.
pub fn scatter(plan: &WorldPlan, tile: &Tile) -> Vec<ScatterPoint> {
    let s = plan.params.scatter.spacing_m as f64;
    let mut out = Vec::new();
    match plan.params.scatter.lattice {
        ScatterLattice::Scan => {
            let seed_pick = stream(plan.seed, purpose::SCATTER, 2);
            let seed_pos = stream(plan.seed, purpose::SCATTER, 0);
            let seed_level = stream(plan.seed, purpose::SCATTER, 1);
            for_each_cell(tile, s, |a, b| {
                let level = (hash2(a, b, seed_level).trailing_zeros() / 2).min(MAX_LEVEL);
                if level >= tile.key.lod {
                    let at = jittered(a, b, seed_pos, s);
                    place(plan, tile, at, hash2(a, b, seed_pick), level, &mut out);
                }
            });
        }
        ScatterLattice::Levels => {
            for level in tile.key.lod..=MAX_LEVEL {
                let sl = s * f64::from(1u32 << level);
                let seed_pos = stream(plan.seed, purpose::SCATTER, 16 + level);
                let seed_pick = stream(plan.seed, purpose::SCATTER, 32 + level);
                for_each_cell(tile, sl, |a, b| {
                    let at = jittered(a, b, seed_pos, sl);
                    place(plan, tile, at, hash2(a, b, seed_pick), level, &mut out);
                });
            }
        }
    }
    out
}

/// The position of candidate `(a, b)` of the lattice of spacing `s`: its cell's corner plus a
/// hashed offset in `[0, s)` on each axis, world metres.
fn jittered(a: i32, b: i32, seed: u32, s: f64) -> (f64, f64) {
    let h = hash2(a, b, seed);
    let x = (a as f64 + unit(h) as f64) * s;
    let z = (b as f64 + unit(mix32(h ^ 0x5bd1_e995)) as f64) * s;
    (x, z)
}

/// Calls `f(a, b)` for every cell of the lattice of spacing `s` that meets the tile's area.
fn for_each_cell(tile: &Tile, s: f64, mut f: impl FnMut(i32, i32)) {
    let span = (TILE_QUADS as f64) * tile.spacing_m as f64;
    let (x0, z0) = (tile.origin_x_m(), tile.origin_z_m());
    let a0 = (x0 / s).floor() as i64;
    let a1 = ((x0 + span) / s).ceil() as i64;
    let b0 = (z0 / s).floor() as i64;
    let b1 = ((z0 + span) / s).ceil() as i64;
    for b in b0..b1 {
        for a in a0..a1 {
            f(a as i32, b as i32);
        }
    }
}

/// Places the candidate at world `(x, z)` with pick hash `pick` and level `level`, if it lies
/// in the tile's half-open area (so a point belongs to exactly one tile of a LOD), draws a biome
/// and a kind that accepts the ground there.
fn place(
    plan: &WorldPlan,
    tile: &Tile,
    (x, z): (f64, f64),
    pick: u32,
    level: u32,
    out: &mut Vec<ScatterPoint>,
) {
    let params = &plan.params;
    let span = (TILE_QUADS as f64) * tile.spacing_m as f64;
    let (x0, z0) = (tile.origin_x_m(), tile.origin_z_m());
    let k = tile.biome_count;
    if x < x0 || x >= x0 + span || z < z0 || z >= z0 + span {
        return;
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
