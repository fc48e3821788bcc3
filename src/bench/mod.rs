//! `strata bench`: performance figures against the issues' targets.
//!
//! `strata bench tiles` (issue 2) synthesises LOD-0 tiles of the classic world (four biomes, a
//! 35-sample blur kernel, 8 warped octaves) on one core and on all cores, and runs the fBm part
//! against the `fastnoise-lite` crate's 8-octave Perlin fBm in the same process; then (issue 17)
//! `earth-1` tiles of the default world at LOD 0 against fastnoise-lite's time for 4 225
//! samples, and every coarse LOD (1 to 12) against LOD 0, cold (the process-wide caches emptied)
//! and warm (the same tiles again), beside the same ratios for the default world of stored
//! worlds before the coarse lattice. With `--json` each
//! figure is one JSON object per line, units in the key names.
//!
//! `strata bench serve` (issue 3) is in [`serve`]; `strata bench strata` (issue 6, the layered
//! subsurface) in [`strata`]; `strata bench realism` (issue 17, the world against real DEMs) in
//! [`realism`]; `strata bench abuse` (issue 18, the cost of requests at their limits) in
//! [`abuse`]; `strata bench scale` (issue 21, replicas behind a load balancer) in [`scale`];
//! `strata bench ptex` (issue 20, the Ptex bake) in [`ptex`], its level-of-detail update in
//! [`ptex_update`].

pub mod abuse;
mod args;
pub mod http;
pub mod poisson;
pub mod ptex;
pub mod ptex_update;
pub mod realism;
pub mod scale;
pub mod serve;
mod serve_edits;
pub mod strata;
pub mod volume;

use crate::terrain::fractal::fbm_batch;
use crate::terrain::{synthesize, TileKey, WorldParams, WorldPlan};
pub use args::BenchArgs;
use serde_json::json;
use std::hint::black_box;
use std::time::Instant;

/// Target of issue 2: milliseconds per LOD-0 tile per core.
pub const TARGET_MS_PER_TILE: f64 = 0.2;
/// Target of issue 2: our fBm throughput over fastnoise-lite's.
pub const TARGET_FBM_RATIO: f64 = 3.0;
/// Target of issue 17: an `earth-1` LOD-0 tile over fastnoise-lite's time for 4 225 samples of
/// 8-octave fBm, measured in the same run.
pub const TARGET_EARTH_RATIO: f64 = 1.5;

/// Milliseconds per tile of `keys`, one core, each tile timed alone.
fn ms_per_tile(plan: &WorldPlan, keys: &[TileKey]) -> f64 {
    for k in keys.iter().take(4) {
        black_box(synthesize(plan, *k));
    }
    let start = Instant::now();
    for k in keys {
        black_box(synthesize(plan, *k));
    }
    start.elapsed().as_secs_f64() * 1e3 / keys.len() as f64
}

/// Milliseconds per tile of `keys`, cold and warm: the first pass after emptying the
/// process-wide caches (the river network's blocks, the climate's node windows), then the same
/// keys again with what that pass cached (after four tiles to warm the code up).
fn cold_warm_ms(plan: &WorldPlan, keys: &[TileKey]) -> (f64, f64) {
    for k in keys.iter().take(4) {
        black_box(synthesize(plan, *k));
    }
    crate::terrain::earth::clear_caches();
    let pass = || {
        let start = Instant::now();
        for k in keys {
            black_box(synthesize(plan, *k));
        }
        start.elapsed().as_secs_f64() * 1e3 / keys.len() as f64
    };
    let cold = pass();
    (cold, pass())
}

/// The median of `v` (the upper one of an even count); NaN when `v` is empty.
pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// Runs a benchmark by name.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    match args.name.as_str() {
        "tiles" => tiles(args),
        "serve" => serve::run(args),
        "strata" => strata::run(args),
        "poisson" => poisson::run(args),
        "volume" => volume::run(args),
        "realism" => realism::run(args),
        "abuse" => abuse::run(args),
        "scale" => scale::run(args),
        "ptex" => ptex::run(args),
        other => anyhow::bail!(
            "unknown benchmark {other:?}; known: tiles, serve, strata, poisson, volume, realism, \
             abuse, scale, ptex"
        ),
    }
}

pub(crate) fn emit(args: &BenchArgs, value: serde_json::Value, line: String) {
    use std::io::Write;
    // A closed pipe (`| head`) ends the output, not the process with a panic.
    let mut out = std::io::stdout().lock();
    let _ = if args.json {
        writeln!(out, "{value}")
    } else {
        writeln!(out, "{line}")
    };
}

/// The tiles of the benchmark: a strip of LOD-0 tiles that crosses several biome cells, so border
/// tiles (blur and several generators) appear in their natural proportion.
fn bench_keys(n: usize) -> Vec<TileKey> {
    let side = (n as f64).sqrt().ceil() as i64;
    (0..n as i64)
        .map(|i| TileKey {
            lod: 0,
            x: (i % side) * 3 - 40,
            z: (i / side) * 3 + 20,
        })
        .collect()
}

/// The world of issue 2's benchmark: the classic biomes with a 35-sample blur kernel at LOD 0.
pub fn bench_world() -> WorldParams {
    let mut params = WorldParams::classic();
    params.layout.blur_radius_m = 17.0 * params.cell_m;
    params
}

fn tiles(args: &BenchArgs) -> anyhow::Result<()> {
    let plan = WorldPlan::new(7, bench_world())?;
    let kernel_taps = plan.lods[0].kernel.len();
    let octaves = plan.lods[0]
        .fractals
        .iter()
        .map(|f| f.octaves.len())
        .max()
        .unwrap_or(0);
    let cores = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1);
    emit(
        args,
        json!({"bench":"tiles","biomes":plan.biome_count(),"kernel_taps":kernel_taps,"octaves":octaves,"cores":cores}),
        format!("tiles: {} biomes, {kernel_taps}-tap blur kernel, {octaves} warped octaves, {cores} cores", plan.biome_count()),
    );

    // One core.
    let keys = bench_keys(args.tiles);
    for k in keys.iter().take(8) {
        black_box(synthesize(&plan, *k));
    }
    let mut border = 0usize;
    let mut border_s = 0.0f64;
    // Each tile is timed alone (wall and thread CPU time), so telling border tiles apart and
    // freeing the tile stay out of the figures.
    let mut one = 0.0f64;
    let mut cpu_ms = 0.0f64;
    for k in &keys {
        let c0 = crate::cpu_time::thread_ms();
        let t0 = Instant::now();
        let t = black_box(synthesize(&plan, *k));
        let dt = t0.elapsed().as_secs_f64();
        cpu_ms += crate::cpu_time::thread_ms() - c0;
        one += dt;
        if t.weights.iter().any(|w| *w > 0.0 && *w < 1.0) {
            border += 1;
            border_s += dt;
        }
    }
    let cpu_ms_per_tile = cpu_ms / keys.len() as f64;
    let ms_per_tile = one * 1e3 / keys.len() as f64;
    let interior_ms = (one - border_s) * 1e3 / (keys.len() - border).max(1) as f64;
    let border_ms = border_s * 1e3 / border.max(1) as f64;
    emit(
        args,
        json!({"bench":"tiles","figure":"one_core","tiles":keys.len(),"ms_per_tile":ms_per_tile,
               "target_ms_per_tile":TARGET_MS_PER_TILE,"meets_target":ms_per_tile <= TARGET_MS_PER_TILE,
               "border_tiles":border,"ms_per_border_tile":border_ms,"ms_per_interior_tile":interior_ms,
               "cpu_ms_per_tile":cpu_ms_per_tile}),
        format!(
            "  one core:  {ms_per_tile:.3} ms per LOD-0 tile (target ≤ {TARGET_MS_PER_TILE}; thread CPU time {cpu_ms_per_tile:.3} ms) — {border} of {} tiles blend biomes: {border_ms:.3} ms each, others {interior_ms:.3} ms",
            keys.len()
        ),
    );

    // All cores.
    let all_keys = bench_keys(args.tiles * cores);
    let start = Instant::now();
    std::thread::scope(|s| {
        for c in 0..cores {
            let plan = &plan;
            let keys = &all_keys;
            s.spawn(move || {
                for k in keys.iter().skip(c).step_by(cores) {
                    black_box(synthesize(plan, *k));
                }
            });
        }
    });
    let all = start.elapsed().as_secs_f64();
    let tiles_per_s = all_keys.len() as f64 / all;
    emit(
        args,
        json!({"bench":"tiles","figure":"all_cores","cores":cores,"tiles":all_keys.len(),"tiles_per_s":tiles_per_s,
               "ms_per_tile_per_core":all * 1e3 * cores as f64 / all_keys.len() as f64}),
        format!(
            "  {cores} cores: {tiles_per_s:.0} tiles/s ({:.3} ms per tile per core)",
            all * 1e3 * cores as f64 / all_keys.len() as f64
        ),
    );

    // fBm part against fastnoise-lite, one core, same sample positions and 8 octaves.
    let n = 1 << 20;
    let xs: Vec<f32> = (0..n).map(|i| (i % 1024) as f32 * 0.75 + 13.0).collect();
    let zs: Vec<f32> = (0..n).map(|i| (i / 1024) as f32 * 0.75 - 7.0).collect();
    let mut out = vec![0.0f32; n];
    let fractal = &plan.lods[0].fractals[2];
    fbm_batch(fractal, &xs[..4096], &zs[..4096], &mut out[..4096]);
    let start = Instant::now();
    fbm_batch(fractal, &xs, &zs, &mut out);
    let ours = n as f64 / start.elapsed().as_secs_f64();
    black_box(&out);

    let mut fnl = fastnoise_lite::FastNoiseLite::with_seed(7);
    fnl.set_noise_type(Some(fastnoise_lite::NoiseType::Perlin));
    fnl.set_fractal_type(Some(fastnoise_lite::FractalType::FBm));
    fnl.set_fractal_octaves(Some(8));
    fnl.set_frequency(Some(1.0 / 1200.0));
    let start = Instant::now();
    let mut acc = 0.0f32;
    for i in 0..n {
        acc += fnl.get_noise_2d(xs[i], zs[i]);
    }
    let theirs = n as f64 / start.elapsed().as_secs_f64();
    black_box(acc);
    let ratio = ours / theirs;
    earth_tiles(args)?;
    emit(
        args,
        json!({"bench":"tiles","figure":"fbm","octaves":fractal.octaves.len(),"warped":fractal.warp.is_some(),
               "samples_per_s":ours,"fastnoise_lite_samples_per_s":theirs,"ratio":ratio,
               "target_ratio":TARGET_FBM_RATIO,"meets_target":ratio >= TARGET_FBM_RATIO}),
        format!(
            "  fBm, one core: {:.1} M samples/s ({} warped octaves) vs fastnoise-lite {:.1} M samples/s (8-octave Perlin fBm): ratio {ratio:.2} (target ≥ {TARGET_FBM_RATIO})",
            ours / 1e6,
            fractal.octaves.len(),
            theirs / 1e6
        ),
    );
    Ok(())
}

/// Issue 17's cost figures: `earth-1` tiles at LOD 0 (the same strip of keys as issue 2's, plus
/// a strip in the mountains) against fastnoise-lite's time for one tile's worth of 8-octave fBm,
/// and coarse LODs against LOD 0.
fn earth_tiles(args: &BenchArgs) -> anyhow::Result<()> {
    let plan = WorldPlan::new(7, WorldParams::default())?;
    let n = args.tiles.max(16);
    let strip = |lod: u32, x0: i64, z0: i64| -> Vec<TileKey> {
        (0..n as i64)
            .map(|i| TileKey {
                lod,
                x: x0 + (i % 16) * 3,
                z: z0 + (i / 16) * 3,
            })
            .collect()
    };
    // The machine is shared and noisy: earth tiles and fastnoise-lite's 4 225 samples are timed
    // in alternation, five rounds, and the ratio is the median of the rounds' ratios.
    let (plains, peaks) = (strip(0, -40, 20), strip(0, 1700, -20));
    let mut fnl = fastnoise_lite::FastNoiseLite::with_seed(7);
    fnl.set_noise_type(Some(fastnoise_lite::NoiseType::Perlin));
    fnl.set_fractal_type(Some(fastnoise_lite::FractalType::FBm));
    fnl.set_fractal_octaves(Some(8));
    fnl.set_frequency(Some(1.0 / 1200.0));
    let fnl_ms = |rounds: usize| {
        let start = Instant::now();
        let mut acc = 0.0f32;
        for r in 0..rounds {
            for i in 0..4225 {
                acc += fnl.get_noise_2d((i % 65) as f32 * 0.75 + r as f32, (i / 65) as f32 * 0.75);
            }
        }
        black_box(acc);
        start.elapsed().as_secs_f64() * 1e3 / rounds as f64
    };
    let (mut ratios, mut lod0s, mut peak_ms, mut fnls) = (vec![], vec![], vec![], vec![]);
    for _ in 0..5 {
        let a = ms_per_tile(&plan, &plains);
        let b = ms_per_tile(&plan, &peaks);
        let f = fnl_ms(n);
        ratios.push(a.max(b) / f);
        lod0s.push(a);
        peak_ms.push(b);
        fnls.push(f);
    }
    let (lod0, mountains, fnl_tile_ms) = (median(lod0s), median(peak_ms), median(fnls));
    let ratio = median(ratios);
    emit(
        args,
        json!({"bench":"tiles","figure":"earth_lod0","ms_per_tile":lod0,"ms_per_mountain_tile":mountains,
               "fastnoise_lite_ms_per_4225_samples":fnl_tile_ms,"ratio":ratio,
               "target_ratio":TARGET_EARTH_RATIO,"meets_target":ratio <= TARGET_EARTH_RATIO}),
        format!(
            "  earth-1, one core: {lod0:.3} ms per LOD-0 tile, {mountains:.3} ms in the mountains; fastnoise-lite 4225 8-octave samples {fnl_tile_ms:.3} ms: ratio {ratio:.2}, median of 5 alternating rounds (target ≤ {TARGET_EARTH_RATIO})"
        ),
    );
    // Coarse LODs against LOD 0, each cold (the process-wide caches emptied first: every
    // tile builds the network blocks it reads, as the first tiles of a region do) and warm (the
    // same tiles again with those blocks cached, as a server streaming a region has them: tiles
    // of every LOD and their neighbours share the blocks). LOD 0 is the plains strip, timed the
    // same way in the same round; five rounds, the medians of the rounds' ratios. The peer is
    // the default world of stored worlds before the coarse lattice (`coarse_lattice_cells`
    // absent, every gully octave), its coarse tiles against its own LOD 0 in the same rounds.
    let mut stored = WorldParams::default();
    if let Some(e) = stored.earth.as_mut() {
        e.coarse_lattice_cells = None;
        e.gully_first = 0;
    }
    let peer = WorldPlan::new(7, stored)?;
    for lod in 1u32..=12 {
        let coarse = strip(lod, -8, -8);
        let (mut cold, mut warm, mut cold_ms, mut warm_ms) = (vec![], vec![], vec![], vec![]);
        let (mut peer_cold, mut peer_warm) = (vec![], vec![]);
        for _ in 0..5 {
            let (c0, w0) = cold_warm_ms(&plan, &plains);
            let (c, w) = cold_warm_ms(&plan, &coarse);
            cold.push(c / c0);
            warm.push(w / w0);
            cold_ms.push(c);
            warm_ms.push(w);
            let (c0, w0) = cold_warm_ms(&peer, &plains);
            let (c, w) = cold_warm_ms(&peer, &coarse);
            peer_cold.push(c / c0);
            peer_warm.push(w / w0);
        }
        let (cold, warm) = (median(cold), median(warm));
        let (cold_ms, warm_ms) = (median(cold_ms), median(warm_ms));
        let (peer_cold, peer_warm) = (median(peer_cold), median(peer_warm));
        emit(
            args,
            json!({"bench":"tiles","figure":"earth_lod","lod":lod,"ms_per_tile_cold":cold_ms,
                   "ms_per_tile_warm":warm_ms,"ratio_to_lod0_cold":cold,"ratio_to_lod0_warm":warm,
                   "stored_ratio_to_lod0_cold":peer_cold,"stored_ratio_to_lod0_warm":peer_warm,
                   "target_ratio":1.0,"meets_target":cold <= 1.0 && warm <= 1.0}),
            format!(
                "  earth-1 LOD {lod:>2}: {cold_ms:.3} ms per tile cold, {warm_ms:.3} warm; {cold:.2} × LOD 0 cold, {warm:.2} warm (stored worlds without the coarse lattice: {peer_cold:.2}, {peer_warm:.2}), medians of 5 alternating rounds (target ≤ 1)"
            ),
        );
    }
    Ok(())
}
