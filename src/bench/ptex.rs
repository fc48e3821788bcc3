//! `strata bench ptex` (issue 20, Done-when 6, first part): the Ptex bake's throughput on one
//! core ([`crate::ptex::bake_interior`] on a rayon pool of one thread) at 8², 64² and 256²
//! texels per face, over the 16 faces of LOD-0 height tiles of the default world, against a
//! peer measured in the same run: the `fastnoise-lite` crate doing the same number of noise
//! calls per texel as the bake does for a texel of two materials at full octaves (three 5-octave
//! 3D value fBm for the displacement and its two differences, and 24 4-octave 2D value fBm for
//! the two materials' relief at three points and their albedo, on three planes each). The
//! ratio is the peer's time over ours (above 1: the bake is faster than the same work with the
//! crate). No target is set for the bake alone. Each round also bakes the same faces as a world
//! stored before `texturing.ptex_blend: 2` does (the vertices' materials blended), and prints the
//! new bake's time over that one.
//!
//! Then the level-of-detail update over about the paper's Table 2 scene
//! ([`super::ptex_update`]).

use super::{emit, median};
use crate::bench::BenchArgs;
use crate::ptex::face::TileFacePlan;
use crate::ptex::{bake_interior, FaceSet, MaterialSet, Pages};
use crate::terrain::{synthesize, TileKey, WorldParams, WorldPlan};
use serde_json::json;
use std::hint::black_box;
use std::time::Instant;

/// The faces of `n` LOD-0 tiles of `plan`.
fn faces(plan: &WorldPlan, mats: &MaterialSet, n: i64) -> Vec<FaceSet> {
    (0..n)
        .map(|i| {
            let key = TileKey {
                lod: 0,
                x: 7 * i - 20,
                z: 3 - 5 * i,
            };
            let tile = synthesize(plan, key);
            let mut set = TileFacePlan::new(key, [false; 4], plan.lods.len() as u32 - 1).build(
                |t| (t == key).then_some(&tile),
                mats,
                plan,
            );
            set.output = set.faces.len();
            set
        })
        .collect()
}

/// The peer's work for `texels` texels, milliseconds.
fn peer_ms(texels: usize) -> f64 {
    use fastnoise_lite::{FastNoiseLite, FractalType, NoiseType};
    let make = |octaves: i32| {
        let mut n = FastNoiseLite::with_seed(7);
        n.set_noise_type(Some(NoiseType::Value));
        n.set_fractal_type(Some(FractalType::FBm));
        n.set_fractal_octaves(Some(octaves));
        n.set_frequency(Some(0.125));
        n
    };
    let (n3, n2) = (make(5), make(4));
    let start = Instant::now();
    let mut acc = 0.0f32;
    for t in 0..texels {
        let (x, z) = ((t % 256) as f32 * 0.0625, (t / 256) as f32 * 0.0625);
        for d in 0..3 {
            acc += n3.get_noise_3d(x + d as f32 * 0.01, 1.5, z);
        }
        for k in 0..24 {
            acc += n2.get_noise_2d(x + k as f32 * 0.37, z);
        }
    }
    black_box(acc);
    start.elapsed().as_secs_f64() * 1e3
}

/// Runs the bake benchmark.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let plan = WorldPlan::new(7, WorldParams::default())?;
    // The peer of the same run: the same faces baked as worlds stored before `ptex_blend: 2`
    // bake them (each texel blends its vertices' dominant materials).
    let mut stored = WorldParams::default();
    stored.texturing.ptex_blend = 1;
    let stored = WorldPlan::new(7, stored)?;
    let mats = MaterialSet::default_ground(plan.seed);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let bake_ms = |sets: &[FaceSet], res: u32, pages: &mut Pages| {
        let start = Instant::now();
        pool.install(|| {
            for s in sets {
                bake_interior(s, &mats, res, pages);
                black_box(&*pages);
            }
        });
        start.elapsed().as_secs_f64() * 1e3
    };
    for (res, tiles, reps) in [(8u32, 16i64, 7usize), (64, 2, 5), (256, 1, 3)] {
        let sets = faces(&plan, &mats, tiles);
        let stored_sets = faces(&stored, &mats, tiles);
        let face_count: usize = sets.iter().map(|s| s.faces.len()).sum();
        let texels = face_count * (res * res) as usize;
        let mut pages = Pages::default();
        let (mut ours, mut ratios, mut blend1, mut over) = (vec![], vec![], vec![], vec![]);
        for _ in 0..reps {
            let ms = bake_ms(&sets, res, &mut pages);
            let ms1 = bake_ms(&stored_sets, res, &mut pages);
            let peer = peer_ms(texels);
            ours.push(ms);
            ratios.push(peer / ms);
            blend1.push(ms1);
            over.push(ms / ms1);
        }
        let (ms, ratio) = (median(ours), median(ratios));
        let (ms1, over) = (median(blend1), median(over));
        let faces_per_s = face_count as f64 / ms * 1e3;
        let mtexels_per_s = texels as f64 / ms / 1e3;
        emit(
            args,
            json!({"bench":"ptex","figure":"bake","res":res,"faces":face_count,"texels":texels,
                   "ms_per_core":ms,"faces_per_s_per_core":faces_per_s,
                   "mtexels_per_s_per_core":mtexels_per_s,"fastnoise_lite_ratio":ratio,
                   "ms_per_core_ptex_blend_1":ms1,"ratio_to_ptex_blend_1":over}),
            format!(
                "bake {res}²: {face_count} faces in {ms:.1} ms on one core: {faces_per_s:.1} faces/s, {mtexels_per_s:.3} Mtexels/s; fastnoise-lite doing the same noise calls: ratio {ratio:.2}; stored worlds' blend (ptex_blend 1) {ms1:.1} ms: {over:.2} × that"
            ),
        );
    }
    super::ptex_update::run(args)
}
