//! How the Ptex bake weighs a height tile's ground materials (`texturing.ptex_blend`,
//! `strata::ptex::bake` step 1, `strata::terrain::texture::texel_weights`):
//!
//! - with `ptex_blend: 2` (new worlds) a texel is snow wherever the ground under it lies clearly
//!   above its snow line on a gentle slope, and never where it lies clearly below, the ground
//!   being interpolated from the tile's vertices at the texel's own place (this file's own
//!   reading of the face layout of `api/ptex_pages_v1.md`: `u` south, `v` east); with
//!   `ptex_blend: 1` (worlds stored before it) the texels follow their vertices' dominant
//!   materials and hundreds of them break that rule along the steps of the vertex lattice, so
//!   the check can fail;
//! - a stored world's document without `ptex_blend` reads as 1, and a new world writes 2.
//!
//! The WGSL twin's bake of such a tile is compared with the CPU's in `tests/gpu_ptex.rs`.

mod common;

use strata::ptex::face::TileFacePlan;
use strata::ptex::{bake_interior, FaceSet, MaterialSet, Pages, TILE_FACES, TILE_FACE_CELLS};
use strata::terrain::earth::{snow_shift, tile_sea_snow_lines};
use strata::terrain::tile::{synthesize, Tile, TileKey};
use strata::terrain::world::{material, WorldParams};
use strata::terrain::{WorldPlan, TILE_VERTS};

const SEED: u64 = 42;
const RES: u32 = 64;
/// Margin of the snow-line test beyond the transition's width, metres (the bake interpolates
/// the same inputs in another order: rounding is far below this).
const MARGIN_M: f32 = 0.5;

fn plan(blend: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    params.texturing.ptex_blend = blend;
    WorldPlan::new(SEED, params).expect("default world")
}

/// [`plan`] on the relief of new worlds before `gully_first: 1` and `valleys: 7` (every gully
/// octave, a valley for every stream): there the snow line crosses the steps of the vertices'
/// lattice in many places, and the blend of `ptex_blend: 1` contradicts it (on today's relief,
/// whose slopes the streams no longer carve into bowls, in a few dozen texels only).
fn plan_of_before(blend: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    params.texturing.ptex_blend = blend;
    let earth = params.earth.as_mut().expect("earth-1");
    earth.gully_first = 0;
    earth.rivers.as_mut().expect("rivers").valleys = 6;
    WorldPlan::new(SEED, params).expect("the world of before")
}

fn face_set(plan: &WorldPlan, tile: &Tile, mats: &MaterialSet) -> FaceSet {
    let faces = TileFacePlan::new(tile.key, [false; 4], plan.lods.len() as u32 - 1);
    let mut set = faces.build(|t| (t == tile.key).then_some(tile), mats, plan);
    set.output = set.faces.len();
    set
}

/// Per texel of the tile's 16 faces at `RES`: whether the ground there is clearly above its
/// snow line (`Some(true)`), clearly below (`Some(false)`) or neither or not judged (steep, near
/// the sea or with ice in its biomes: `None`).
fn snow_truth(plan: &WorldPlan, tile: &Tile) -> Vec<Option<bool>> {
    let earth = plan.earth.as_ref().expect("an earth world");
    let shift = snow_shift(earth, tile.key, tile.spacing_m, &tile.normals);
    // New worlds read the sea-level climate's snow line (`snow_lines: 2`) instead of the
    // biome-weighted one.
    let sea = tile_sea_snow_lines(earth, tile.key, tile.spacing_m);
    let rule = plan.texture.texel_rule();
    let blend = rule.blend_m;
    let k = tile.biome_count;
    let lines: Vec<f32> = plan.params.biomes.iter().map(|b| b.snow_line_m).collect();
    let ice: Vec<bool> = plan
        .params
        .biomes
        .iter()
        .map(|b| b.ground == "snow")
        .collect();
    // At each vertex: height above the sea, height above the snow line, ice share, normal.
    let at = |v: usize| -> ([f32; 3], [f32; 3]) {
        let w = &tile.weights[v * k..(v + 1) * k];
        let own = match sea.get(v) {
            Some(&line) => line,
            None => w.iter().zip(&lines).map(|(w, l)| w * l).sum::<f32>(),
        };
        let line = own + shift[v];
        let ice: f32 = w
            .iter()
            .zip(&ice)
            .filter(|(_, i)| **i)
            .map(|(w, _)| w)
            .sum();
        let h = tile.heights[v];
        (
            [h - plan.params.sea_level_m, h - line, ice],
            tile.normals[v],
        )
    };
    let c = TILE_FACE_CELLS as f32;
    let mut out = Vec::new();
    for f in 0..TILE_FACES * TILE_FACES {
        let (fi, fj) = ((f % TILE_FACES) as f32, (f / TILE_FACES) as f32);
        for j in 0..RES {
            for i in 0..RES {
                // Texel (i, j) at uv = ((i + ½)/R, (j + ½)/R); u runs south, v east.
                let u = (i as f32 + 0.5) / RES as f32;
                let v = (j as f32 + 0.5) / RES as f32;
                let (x, z) = (fi * c + v * c, fj * c + u * c);
                let (x0, z0) = (x.floor().min(63.0), z.floor().min(63.0));
                let (fx, fz) = (x - x0, z - z0);
                let (x0, z0) = (x0 as usize, z0 as usize);
                let corners = [
                    (z0 * TILE_VERTS + x0, (1.0 - fx) * (1.0 - fz)),
                    (z0 * TILE_VERTS + x0 + 1, fx * (1.0 - fz)),
                    ((z0 + 1) * TILE_VERTS + x0, (1.0 - fx) * fz),
                    ((z0 + 1) * TILE_VERTS + x0 + 1, fx * fz),
                ];
                let (mut s, mut n) = ([0.0f32; 3], [0.0f32; 3]);
                for (vtx, w) in corners {
                    let (sv, nv) = at(vtx);
                    for c in 0..3 {
                        s[c] += w * sv[c];
                        n[c] += w * nv[c];
                    }
                }
                let ny = n[1] / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                let judged = s[0] > rule.beach_height_m + 2.0 * blend
                    && ny > rule.rock_cos.0 + 0.01
                    && s[2] == 0.0;
                out.push(if !judged {
                    None
                } else if s[1] > blend + MARGIN_M {
                    Some(true)
                } else if s[1] < -blend - MARGIN_M {
                    Some(false)
                } else {
                    None
                });
            }
        }
    }
    out
}

/// Texels clearly above the snow line, clearly below, and those of either whose dominant
/// material contradicts it.
fn snow_check(plan: &WorldPlan, tile: &Tile) -> (usize, usize, usize) {
    let mats = MaterialSet::default_ground(plan.seed);
    let set = face_set(plan, tile, &mats);
    let mut pages = Pages::default();
    bake_interior(&set, &mats, RES, &mut pages);
    let truth = snow_truth(plan, tile);
    let (mut above, mut below, mut wrong) = (0, 0, 0);
    let per = (RES * RES) as usize;
    for (t, want) in truth.iter().enumerate() {
        let Some(snow) = want else { continue };
        let (f, j, i) = (t / per, (t % per) / RES as usize, t % RES as usize);
        let dominant = pages.normal[pages.at(f, i as i32, j as i32)][3];
        if *snow {
            above += 1;
        } else {
            below += 1;
        }
        wrong += usize::from((dominant == material::SNOW) != *snow);
    }
    (above, below, wrong)
}

/// A tile of the default world where the snow line crosses gentle ground (a mountain block
/// 131 km east and south of the origin), the first of a fixed search with enough texels on
/// both sides of it.
fn snow_line_tile(plan: &WorldPlan) -> Tile {
    for lod in [5u32, 4] {
        for (x, z) in [(63, 64), (64, 64), (63, 65), (64, 63), (62, 64)] {
            let key = TileKey {
                lod,
                x: x << (5 - lod),
                z: z << (5 - lod),
            };
            let tile = synthesize(plan, key);
            let truth = snow_truth(plan, &tile);
            let above = truth.iter().filter(|t| **t == Some(true)).count();
            let below = truth.iter().filter(|t| **t == Some(false)).count();
            if above > 2000 && below > 2000 {
                println!("tile {key:?}: {above} texels above the snow line, {below} below");
                return tile;
            }
        }
    }
    panic!("no tile where the snow line crosses gentle ground");
}

#[test]
fn texels_are_snow_above_the_snow_line_and_not_below_it_with_blend_2_only() {
    let new = plan(2);
    let tile = snow_line_tile(&new);
    let (above, below, wrong) = snow_check(&new, &tile);
    println!("ptex_blend 2: {above} above, {below} below, {wrong} contradict");
    assert!(above > 2000 && below > 2000);
    assert_eq!(wrong, 0, "texels whose snow contradicts their snow line");
    // On the relief of before, both blends of one tile (the same heights: `ptex_blend` is the
    // bake's alone).
    let before = plan_of_before(2);
    let tile = snow_line_tile(&before);
    let (_, _, wrong) = snow_check(&before, &tile);
    assert_eq!(
        wrong, 0,
        "texels whose snow contradicts their snow line, relief of before"
    );
    let old = plan_of_before(1);
    let tile_old = synthesize(&old, tile.key);
    assert_eq!(tile_old.heights, tile.heights);
    let (_, _, wrong_old) = snow_check(&old, &tile_old);
    println!("ptex_blend 1: {wrong_old} contradict");
    assert!(
        wrong_old > 200,
        "the vertices' blend breaks the rule along the lattice's steps: {wrong_old}"
    );
}

#[test]
fn stored_worlds_read_blend_1_and_new_worlds_write_blend_2() {
    let new = serde_json::to_value(WorldParams::default()).expect("json");
    assert_eq!(new["texturing"]["ptex_blend"], 2);
    let mut stored = new.clone();
    stored["texturing"]
        .as_object_mut()
        .expect("texturing")
        .remove("ptex_blend");
    let read: WorldParams = serde_json::from_value(stored).expect("a stored document");
    assert_eq!(read.texturing.ptex_blend, 1);
    assert_eq!(
        serde_json::to_value(&read).expect("json")["texturing"].get("ptex_blend"),
        None,
        "a stored world writes its document as it was"
    );
    let mut bad = WorldParams::default();
    bad.texturing.ptex_blend = 3;
    let e = bad.validate().expect_err("ptex_blend 3");
    assert_eq!(e.field, "texturing.ptex_blend");
}
