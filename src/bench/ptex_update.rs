//! `strata bench ptex`, second part (issue 20, Done-when 6): the level-of-detail update of Ptex
//! pages ([`crate::ptex::budget`]) over a scene of 349² = 121,801 LOD-0 height-tile faces (about
//! the paper's Table 2 scene, 121,696 primitives) with the paper's budget split (its 125 MB of
//! vista pages need 146 MB with our 12-byte texels and borders, so the vista level gets what it
//! needs and the detail levels 537 MB), in two scenarios as Table 2 has:
//!
//! - a scripted **fly-through** of views along a loop over the scene at 40 m: each update's
//!   distance step (frustum and distance of every face, timed alone), classification (the
//!   budget's update: distance again, sort, thresholds, slots) and the baking of the pages it
//!   asks for;
//! - an **editing session**: edits of 32 m boxes near the camera, each update selecting the
//!   faces whose reach meets the box (`stream::ptex::face_reach`, over every face) and baking
//!   their vista and detail pages again.
//!
//! Classification reads each face's bounding sphere at height 0 (the cost does not depend on the
//! heights); pages are baked from the default world's tiles (synthesised beforehand, outside the
//! timings, as a server's stage cache holds them) with [`crate::ptex::select::bake_faces`] on
//! all cores, as a stream session's batches are. Figures: average and maximum per update, beside
//! Table 2's GTX 1080 figures, and the largest single batch (what a session bakes between two
//! tile frames). The first view, which fills every level from empty (the paper's pipeline stage 6
//! does that before any update), is reported apart and left out of the averages.

use super::emit;
use crate::bench::BenchArgs;
use crate::ptex::budget::{
    distance_in_view, page_bytes, Bake, Budget, BudgetConfig, FaceBounds, View, LEVEL_RES,
};
use crate::ptex::face::{TileFaceKey, TileFacePlan};
use crate::ptex::select::bake_faces;
use crate::ptex::{FaceSet, MaterialSet, Pages};
use crate::scene::Rect;
use crate::stream::ptex::{face_reach, BATCH_TEXELS};
use crate::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan};
use serde_json::json;
use std::collections::{BTreeMap, HashMap};
use std::hint::black_box;
use std::time::Instant;

/// Target of the issue: the complete update's average, milliseconds.
pub const TARGET_UPDATE_MS: f64 = 11.0;
/// Faces per side of the scene.
const SIDE: usize = 349;
/// Views of the fly-through after the first.
const VIEWS: usize = 60;
/// Edits of the editing session.
const EDITS: usize = 30;

/// The scene's faces, their bounds and the tiles their pages are baked from.
struct Scene {
    plan: WorldPlan,
    mats: MaterialSet,
    keys: Vec<TileFaceKey>,
    bounds: Vec<FaceBounds>,
    tiles: HashMap<TileKey, Tile>,
    sets: HashMap<TileKey, FaceSet>,
}

impl Scene {
    fn new() -> anyhow::Result<Self> {
        let plan = WorldPlan::new(7, WorldParams::default())?;
        let mats = MaterialSet::default_ground(plan.seed);
        let keys = (0..SIDE * SIDE)
            .map(|i| TileFaceKey {
                lod: 0,
                fx: (i % SIDE) as i64,
                fz: (i / SIDE) as i64,
            })
            .collect();
        let bounds = (0..SIDE * SIDE)
            .map(|i| FaceBounds {
                centre: [
                    (i % SIDE) as f32 * 16.0 + 8.0,
                    0.0,
                    (i / SIDE) as f32 * 16.0 + 8.0,
                ],
                radius: 11.4,
            })
            .collect();
        Ok(Self {
            plan,
            mats,
            keys,
            bounds,
            tiles: HashMap::new(),
            sets: HashMap::new(),
        })
    }

    /// Synthesises the tiles and face sets `bakes` need (not timed).
    fn prepare(&mut self, bakes: &[Bake]) {
        for b in bakes {
            let key = self.keys[b.face as usize].tile();
            if self.sets.contains_key(&key) {
                continue;
            }
            let faces = TileFacePlan::new(key, [false; 4], self.plan.lods.len() as u32 - 1);
            for t in faces.tiles() {
                if !self.tiles.contains_key(&t) {
                    self.tiles.insert(t, synthesize(&self.plan, t));
                }
            }
            let set = faces.build(|t| self.tiles.get(&t), &self.mats);
            self.sets.insert(key, set);
        }
    }

    /// Bakes `bakes` in batches of one level of at most [`BATCH_TEXELS`] texels, one tile's
    /// faces at a time; returns the largest batch's milliseconds.
    fn bake(&self, bakes: &[Bake], pages: &mut Pages) -> f64 {
        let mut by_level: BTreeMap<u8, Vec<Bake>> = BTreeMap::new();
        for b in bakes {
            by_level.entry(b.level).or_default().push(*b);
        }
        let mut worst = 0.0f64;
        for (level, list) in by_level {
            let res = LEVEL_RES[level as usize];
            let per_batch = (BATCH_TEXELS / u64::from(res * res)).max(1) as usize;
            for batch in list.chunks(per_batch) {
                let start = Instant::now();
                let mut by_tile: BTreeMap<TileKey, Vec<usize>> = BTreeMap::new();
                for b in batch {
                    let f = self.keys[b.face as usize];
                    by_tile.entry(f.tile()).or_default().push(f.id() as usize);
                }
                for (tile, chosen) in by_tile {
                    if let Some(set) = self.sets.get(&tile) {
                        bake_faces(set, &self.mats, res, &chosen, pages);
                        black_box(&*pages);
                    }
                }
                worst = worst.max(start.elapsed().as_secs_f64() * 1e3);
            }
        }
        worst
    }
}

/// View `t` of the fly-through: a loop at 40 m over the scene, looking ahead and down.
fn view(t: usize) -> View {
    let side = SIDE as f32 * 16.0;
    let a = t as f32 * 0.02;
    let (dx, dz) = (-a.sin(), a.cos());
    let f = [dx * 0.94, -0.34, dz * 0.94];
    let l = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
    View {
        eye: [
            side * (0.5 + 0.3 * a.cos()),
            40.0,
            side * (0.5 + 0.3 * a.sin()),
        ],
        forward: f.map(|c| c / l),
        cos_half_angle: 0.8,
        far_m: 4000.0,
    }
}

/// Average and maximum.
fn stats(v: &[f64]) -> (f64, f64) {
    let avg = v.iter().sum::<f64>() / v.len().max(1) as f64;
    (avg, v.iter().copied().fold(0.0, f64::max))
}

/// Runs both scenarios.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let mut scene = Scene::new()?;
    let vista = scene.keys.len() as u64 * page_bytes(LEVEL_RES[0]);
    let detail_bytes = 537_000_000u64;
    let config = BudgetConfig {
        bytes: vista + detail_bytes,
        thresholds_m: [3000.0, 1200.0, 500.0, 200.0, 80.0],
    };
    let mut budget = Budget::new(config, scene.keys.len())?;
    let mut pages = Pages::default();
    // The first view fills the detail levels from empty.
    let first = budget.update(&scene.bounds, &view(0));
    scene.prepare(&first.bake);
    let start = Instant::now();
    scene.bake(&first.bake, &mut pages);
    let first_ms = start.elapsed().as_secs_f64() * 1e3;
    let (mut dist, mut class, mut bake, mut full, mut count, mut batch) =
        (vec![], vec![], vec![], vec![], vec![], 0.0f64);
    for t in 1..=VIEWS {
        let v = view(t);
        let start = Instant::now();
        let visible = scene
            .bounds
            .iter()
            .filter_map(|b| distance_in_view(b, &v))
            .count();
        dist.push(start.elapsed().as_secs_f64() * 1e3);
        black_box(visible);
        let start = Instant::now();
        let changed = budget.update(&scene.bounds, &v);
        class.push(start.elapsed().as_secs_f64() * 1e3);
        scene.prepare(&changed.bake);
        let start = Instant::now();
        batch = batch.max(scene.bake(&changed.bake, &mut pages));
        bake.push(start.elapsed().as_secs_f64() * 1e3);
        full.push(class.last().copied().unwrap_or(0.0) + bake.last().copied().unwrap_or(0.0));
        count.push(changed.bake.len() as f64);
    }
    let ((d_avg, d_max), (c_avg, c_max), (b_avg, b_max), (u_avg, u_max), (p_avg, p_max)) = (
        stats(&dist),
        stats(&class),
        stats(&bake),
        stats(&full),
        stats(&count),
    );
    emit(
        args,
        json!({"bench":"ptex","figure":"update","scenario":"fly-through","faces":scene.keys.len(),
               "views":VIEWS,"vista_bytes":vista,"detail_bytes":detail_bytes,
               "capacity":budget.capacity(),"first_view_pages":first.bake.len(),
               "first_view_bake_ms":first_ms,
               "distance_ms_avg":d_avg,"distance_ms_max":d_max,
               "classification_ms_avg":c_avg,"classification_ms_max":c_max,
               "bake_ms_avg":b_avg,"bake_ms_max":b_max,"batch_ms_max":batch,
               "update_ms_avg":u_avg,"update_ms_max":u_max,
               "pages_per_update_avg":p_avg,"pages_per_update_max":p_max,
               "paper_distance_ms":6.36,"paper_classification_ms_avg":3.62,
               "paper_classification_ms_max":11.45,"paper_complete_ms_avg":11.02,
               "paper_complete_ms_max":19.94,"paper_pages_avg":508,"paper_pages_max":2232,
               "target_update_ms_avg":TARGET_UPDATE_MS,"meets_target":u_avg <= TARGET_UPDATE_MS}),
        format!(
            "update, fly-through over {} faces, {VIEWS} views (vista {:.0} MB, detail 537 MB, slots {:?}; the first view's {} pages baked in {first_ms:.0} ms, apart):\n  distance {d_avg:.2} ms avg, {d_max:.2} max (paper 6.36 ms)\n  classification (distance, sort, thresholds, slots) {c_avg:.2} ms avg, {c_max:.2} max (paper 3.62 / 11.45 ms)\n  baking {b_avg:.1} ms avg, {b_max:.1} max; largest batch {batch:.1} ms\n  complete update {u_avg:.1} ms avg, {u_max:.1} max (paper 11.02 / 19.94 ms; target ≤ {TARGET_UPDATE_MS} ms avg: {})\n  pages per update {p_avg:.0} avg, {p_max:.0} max (paper 508 / 2232)",
            scene.keys.len(),
            vista as f64 / 1e6,
            budget.capacity(),
            first.bake.len(),
            if u_avg <= TARGET_UPDATE_MS { "met" } else { "not met" }
        ),
    );
    // The editing session: edits of 32 m boxes ahead of the last view's eye.
    let params = WorldParams::default();
    let last = view(VIEWS);
    let (mut select, mut rebake, mut total, mut touched) = (vec![], vec![], vec![], vec![]);
    for e in 0..EDITS {
        let c = [
            f64::from(last.eye[0] + last.forward[0] * 60.0) + (e % 6) as f64 * 24.0,
            f64::from(last.eye[2] + last.forward[2] * 60.0) + (e / 6) as f64 * 24.0,
        ];
        let dirty = Rect {
            min: [c[0] - 16.0, c[1] - 16.0],
            max: [c[0] + 16.0, c[1] + 16.0],
        };
        let start = Instant::now();
        let hit: Vec<u32> = scene
            .keys
            .iter()
            .enumerate()
            .filter(|(_, f)| face_reach(&params, **f).intersects(&dirty))
            .map(|(i, _)| i as u32)
            .collect();
        let bakes = budget.invalidate(&hit);
        select.push(start.elapsed().as_secs_f64() * 1e3);
        scene.prepare(&bakes);
        let start = Instant::now();
        scene.bake(&bakes, &mut pages);
        rebake.push(start.elapsed().as_secs_f64() * 1e3);
        total.push(select.last().copied().unwrap_or(0.0) + rebake.last().copied().unwrap_or(0.0));
        touched.push(bakes.len() as f64);
    }
    let ((s_avg, s_max), (r_avg, r_max), (t_avg, t_max), (n_avg, n_max)) = (
        stats(&select),
        stats(&rebake),
        stats(&total),
        stats(&touched),
    );
    emit(
        args,
        json!({"bench":"ptex","figure":"update","scenario":"editing","faces":scene.keys.len(),
               "edits":EDITS,"select_ms_avg":s_avg,"select_ms_max":s_max,
               "bake_ms_avg":r_avg,"bake_ms_max":r_max,"update_ms_avg":t_avg,"update_ms_max":t_max,
               "pages_per_edit_avg":n_avg,"pages_per_edit_max":n_max,
               "paper_complete_ms_avg":11.02,"paper_complete_ms_max":19.94,
               "target_update_ms_avg":TARGET_UPDATE_MS,"meets_target":t_avg <= TARGET_UPDATE_MS}),
        format!(
            "update, editing session over {} faces, {EDITS} edits of 32 m boxes:\n  touched faces' selection {s_avg:.2} ms avg, {s_max:.2} max\n  baking {r_avg:.1} ms avg, {r_max:.1} max\n  complete update {t_avg:.1} ms avg, {t_max:.1} max (target ≤ {TARGET_UPDATE_MS} ms avg: {})\n  pages per edit {n_avg:.0} avg, {n_max:.0} max",
            scene.keys.len(),
            if t_avg <= TARGET_UPDATE_MS { "met" } else { "not met" }
        ),
    );
    Ok(())
}
