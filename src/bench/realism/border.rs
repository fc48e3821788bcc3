//! The biome-border transect of `strata bench realism`: whether a biome border adds curvature
//! to the relief, at every LOD 0–8.
//!
//! A wall along a border is curvature where two biomes blend and nowhere else. With `w` the
//! weight of biome A and `h_A`, `h_B` the two generators' heights, the blend
//! `w·h_A + (1 − w)·h_B` has the Laplacian `w·∇²h_A + (1 − w)·∇²h_B` plus the terms
//! `2·∇w·∇(h_A − h_B) + (h_A − h_B)·∇²w`, which are the wall; they are largest where `w` changes
//! fastest, at the middle of the blend. So the figure compares up to three windows of
//! [`WINDOW_TILES`]² tiles at the same LOD: one centred at the middle of a border (its two
//! largest weights both at least [`MIDDLE_WEIGHT`]) and one in each of the two biomes alone
//! (largest weight at least [`PURE_WEIGHT`]): the mean `|∇²h|` of the middle window divided by
//! the mean of the two pure windows' means. Without the wall terms the middle's curvature is a
//! convex mix of the two sides', so the ratio is at most about 1; a wall raises it. Cells whose
//! Laplacian stencil holds lake or river water are left out of every window: a shore's
//! curvature belongs to wherever a lake happens to lie, not to the blend (in the default world
//! a lake that fills a hollow in LOD 4's middle window raised that LOD's ratio from 1.43 to
//! 1.51 with `lakes: 6`; without the water's cells it reads 1.31).
//!
//! Comparing windows across a border is what makes this fair at fine LODs: a window of 4 × 4
//! tiles is 256 m across at LOD 0, far narrower than the blend of a world whose weights change
//! over kilometres, so within one window there is border or no border, and pooling windows of
//! different areas would compare mountains with plains. Where the middle window does hold both
//! (a blend narrower than the window, as in the classic world), its border vertices are compared
//! with its other vertices instead ([`Method`]).
//!
//! Sites: on a grid of [`SEARCH_TILES`]² tiles centred on the origin, at the first of
//! [`SEARCH_LODS`] that holds one (a world whose blend is narrower than a coarse spacing shows
//! no middle there), the middle is the land vertex nearest the origin whose two largest weights
//! are both at least [`MIDDLE_WEIGHT`]; the pure sites are the land vertices nearest the middle
//! where each of those two biomes has a weight of at least [`PURE_WEIGHT`].

use super::metrics::land_border_curvature;
use super::sample::{first_tile, sample, Sampled};
use crate::terrain::{synthesize, TileKey, WorldPlan};
use rayon::prelude::*;

/// The LODs of the site search, coarse first (256, 16 and 1 m spacing with a 1 m cell).
pub const SEARCH_LODS: [u32; 3] = [8, 4, 0];
/// Tiles per side of the site search (131 km at LOD 8 with a 1 m cell).
pub const SEARCH_TILES: i64 = 8;
/// Both largest weights at the middle of a border are at least this.
pub const MIDDLE_WEIGHT: f32 = 0.4;
/// A biome is alone where its weight is at least this.
pub const PURE_WEIGHT: f32 = 0.99;
/// Tiles per side of each window.
pub const WINDOW_TILES: usize = 4;

/// Where a border is measured: world metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transect {
    /// The middle of the border.
    pub middle: (f64, f64),
    /// Biome A alone.
    pub a: (f64, f64),
    /// Biome B alone.
    pub b: (f64, f64),
    /// The indices of biomes A and B.
    pub biomes: (usize, usize),
}

/// A vertex of the site search.
struct Site {
    x: f64,
    z: f64,
    land: bool,
    weights: Vec<f32>,
}

/// Finds a border near the origin, or `None` when no search grid holds one with both sides.
pub fn find_transect(plan: &WorldPlan) -> Option<Transect> {
    SEARCH_LODS
        .iter()
        .find_map(|lod| find_transect_at(plan, *lod))
}

fn find_transect_at(plan: &WorldPlan, lod: u32) -> Option<Transect> {
    let spacing = plan.lods[lod as usize].spacing_m as f64;
    let t0 = first_tile(plan, lod, 0.0, SEARCH_TILES as usize);
    let keys: Vec<TileKey> = (0..SEARCH_TILES)
        .flat_map(|b| {
            (0..SEARCH_TILES).map(move |a| TileKey {
                lod,
                x: t0 + a,
                z: t0 + b,
            })
        })
        .collect();
    let sea = plan.params.sea_level_m as f64;
    let sites: Vec<Site> = keys
        .par_iter()
        .flat_map_iter(|key| {
            let t = synthesize(plan, *key);
            let k = t.biome_count;
            (0..64 * 64).map(move |n| {
                let (i, j) = (n % 64, n / 64);
                let v = j * 65 + i;
                Site {
                    x: (key.x * 64 + i as i64) as f64 * spacing,
                    z: (key.z * 64 + j as i64) as f64 * spacing,
                    land: t.heights[v] as f64 > sea,
                    weights: t.weights[v * k..(v + 1) * k].to_vec(),
                }
            })
        })
        .collect();
    let top2 = |w: &[f32]| {
        let mut idx: Vec<usize> = (0..w.len()).collect();
        idx.sort_by(|p, q| w[*q].total_cmp(&w[*p]).then(p.cmp(q)));
        (idx[0], idx.get(1).copied().unwrap_or(idx[0]))
    };
    let d2 = |s: &Site, (x, z): (f64, f64)| (s.x - x).powi(2) + (s.z - z).powi(2);
    let nearest = |to: (f64, f64), keep: &dyn Fn(&Site) -> bool| {
        sites
            .iter()
            .filter(|s| s.land && keep(s))
            .min_by(|p, q| d2(p, to).total_cmp(&d2(q, to)))
    };
    let middle = nearest((0.0, 0.0), &|s| {
        let (a, b) = top2(&s.weights);
        a != b && s.weights[a] >= MIDDLE_WEIGHT && s.weights[b] >= MIDDLE_WEIGHT
    })?;
    let (ia, ib) = top2(&middle.weights);
    let at = (middle.x, middle.z);
    let a = nearest(at, &|s| s.weights[ia] >= PURE_WEIGHT)?;
    let b = nearest(at, &|s| s.weights[ib] >= PURE_WEIGHT)?;
    Some(Transect {
        middle: at,
        a: (a.x, a.z),
        b: (b.x, b.z),
        biomes: (ia, ib),
    })
}

/// How a LOD's border ratio was measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The middle window holds both border and other vertices (at least [`MIN_SHARE`] each):
    /// the mean `|∇²h|` on its border vertices over that on its other vertices, the same terrain
    /// on both sides of the comparison.
    Within,
    /// The middle window is (almost) all border or all other: its mean `|∇²h|` over the mean of
    /// the two pure windows' means.
    Across,
}

/// Each side of a [`Method::Within`] comparison holds at least this share of the window.
pub const MIN_SHARE: f64 = 0.1;

/// The curvature of the windows at one LOD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BorderCheck {
    /// How the ratio was measured.
    pub method: Method,
    /// Mean `|∇²h|` on the border: the middle window's border vertices ([`Method::Within`]) or
    /// the whole middle window ([`Method::Across`]), 1/m.
    pub border_per_m: f64,
    /// Mean `|∇²h|` off the border: the middle window's other vertices ([`Method::Within`]) or
    /// the mean of the two pure windows' means ([`Method::Across`]), 1/m.
    pub other_per_m: f64,
}

impl BorderCheck {
    /// The border's curvature over the other's.
    pub fn ratio(&self) -> f64 {
        self.border_per_m / self.other_per_m
    }
}

/// Mean `|∇²h|` over a window's interior, 1/m, where the stencil holds no lake or river water.
pub fn mean_abs_laplacian(s: &Sampled) -> f64 {
    let c = land_border_curvature(&s.grid, &vec![false; s.grid.heights.len()], &s.water);
    c.other_sum / c.other_cells.max(1) as f64
}

/// Measures the windows of `t` at `lod`.
pub fn check(plan: &WorldPlan, lod: u32, t: &Transect) -> BorderCheck {
    let n = WINDOW_TILES;
    let window = |(x, z): (f64, f64)| {
        sample(
            plan,
            lod,
            first_tile(plan, lod, x, n),
            first_tile(plan, lod, z, n),
            n,
            n,
        )
    };
    let middle = window(t.middle);
    let c = land_border_curvature(&middle.grid, &middle.border, &middle.water);
    let cells = (c.border_cells + c.other_cells).max(1) as f64;
    if (c.border_cells.min(c.other_cells) as f64) >= MIN_SHARE * cells {
        return BorderCheck {
            method: Method::Within,
            border_per_m: c.border_sum / c.border_cells as f64,
            other_per_m: c.other_sum / c.other_cells as f64,
        };
    }
    let (a, b) = (
        mean_abs_laplacian(&window(t.a)),
        mean_abs_laplacian(&window(t.b)),
    );
    BorderCheck {
        method: Method::Across,
        border_per_m: mean_abs_laplacian(&middle),
        other_per_m: 0.5 * (a + b),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::WorldParams;

    #[test]
    fn the_border_ratio_sees_the_classic_walls_and_not_the_default_blend() {
        // The classic world blends biomes over 64 m, so from 16 m spacing its borders are steps:
        // the walls the issue saw at 8 m and coarser.
        let classic = WorldPlan::new(42, WorldParams::classic()).expect("classic plan");
        let t = find_transect(&classic).expect("a classic border near the origin");
        let walls = check(&classic, 5, &t);
        assert_eq!(walls.method, Method::Within);
        assert!(walls.ratio() > 3.0, "classic walls at LOD 5: {walls:?}");
        // The default world's weights change over kilometres: no extra curvature.
        let default = WorldPlan::new(42, WorldParams::default()).expect("default plan");
        let t = find_transect(&default).expect("a default border near the origin");
        assert_ne!(t.biomes.0, t.biomes.1);
        let blend = check(&default, 3, &t);
        assert!(blend.ratio() <= 1.5, "default blend at LOD 3: {blend:?}");
    }
}
