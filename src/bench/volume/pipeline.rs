//! `strata bench volume`, pipeline part (issue 5): the volume-region pipeline of Becher et al.
//! (§4.1–4.5) on the arch scene ([`crate::volume::pipeline::scenes::arch`]) at the three grid
//! sizes of the paper's Table 1, per stage, beside the paper's GTX 1080 times; and one diffusion
//! sweep's effective bandwidth against a plain memory copy of the same bytes.
//!
//! Our "complete" time is the wall clock of proxies → voxelization → normal diffusion → noise
//! diffusion → material and surface propagation (concurrent, one thread each) → Gaussian filter,
//! i.e. everything up to `S`; each stage is also reported as CPU time of all threads, which is
//! what to compare when the machine is busy. The paper's
//! complete time also contains its reset (buffer clears), surface reconstruction and texture
//! baking; the reconstruction is measured by the mesh part of this benchmark, texture baking is
//! not part of strata. Target (CPU path): 128 × 64 × 128 complete in ≤ 132 ms; a sweep at ≥ 50 %
//! of copy bandwidth. The sweeps are measured at 128 × 64 × 128, whose data fit this machine's
//! last-level cache (the copy runs at cache speed and the Perona–Malik sweep, three exact
//! divisions per sample, is compute-bound), and at 256 × 128 × 256, whose data do not. Each
//! sweep and the copy of its bytes are timed back to back, 30 times, and each figure is the best
//! of its repetitions, so that both see the same machine conditions.

use crate::bench::emit;
use crate::bench::BenchArgs;
use crate::volume::pipeline::diffuse::{sweep, K_PERONA_MALIK};
use crate::volume::pipeline::grid::{par_slabs, threads};
use crate::volume::pipeline::{generate, scenes, RegionFields};
use serde_json::json;
use std::hint::black_box;
use std::time::Instant;

/// Target of issue 5: 128 × 64 × 128 complete on the CPU path, milliseconds.
pub const TARGET_MS_128: f64 = 132.0;
/// Target of issue 5: a diffusion sweep's bandwidth as a fraction of a memory copy's.
pub const TARGET_SWEEP_FRACTION: f64 = 0.5;

/// The paper's Table 1 (GTX 1080), milliseconds: reset, voxelization, guidance field diffusion,
/// noise field diffusion, surface propagation, surface reconstruction, texture baking, complete.
const TABLE1: [([usize; 3], [f64; 8]); 3] = [
    (
        [64, 32, 64],
        [0.03, 0.14, 3.47, 2.21, 3.21, 5.87, 2.06, 16.99],
    ),
    (
        [128, 64, 128],
        [0.71, 0.50, 54.81, 26.36, 36.74, 8.77, 3.85, 131.69],
    ),
    (
        [256, 128, 256],
        [5.04, 0.45, 570.04, 377.52, 473.07, 20.13, 34.57, 1480.82],
    ),
];

fn run_once(dims: [usize; 3]) -> anyhow::Result<RegionFields> {
    let (grid, scene, params) = scenes::arch(dims);
    Ok(generate(&grid, &scene, &params)?)
}

/// Runs this part of the benchmark.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let cores = threads();
    emit(
        args,
        json!({"bench":"volume","part":"pipeline","scene":"arch","threads":cores}),
        format!("volume pipeline: arch scene (4 feature curves + heightfield), CPU path, {cores} threads; paper: GTX 1080"),
    );
    for (dims, paper) in TABLE1 {
        let reps = if dims[0] >= 256 { 2 } else { 5 };
        let mut best: Option<RegionFields> = None;
        for _ in 0..reps {
            let f = run_once(dims)?;
            if best
                .as_ref()
                .is_none_or(|b| f.times.total_ms < b.times.total_ms)
            {
                best = Some(f);
            }
        }
        let f = best.expect("at least one repetition");
        let (t, c) = (f.times, f.cpu_times);
        let samples = dims.iter().product::<usize>();
        let is_target = dims == [128, 64, 128];
        let mut value = json!({
            "bench":"volume","figure":"pipeline","dims":dims,"samples":samples,"repetitions":reps,
            "threads":cores,
            "proxy_ms":t.proxy_ms,"voxelize_ms":t.voxelize_ms,"normal_diffusion_ms":t.normal_diffusion_ms,
            "noise_diffusion_ms":t.noise_diffusion_ms,"material_ms":t.material_ms,
            "surface_propagation_ms":t.surface_propagation_ms,
            "filter_ms":t.filter_ms,"total_ms":t.total_ms,
            "cpu_proxy_ms":c.proxy_ms,"cpu_voxelize_ms":c.voxelize_ms,
            "cpu_normal_diffusion_ms":c.normal_diffusion_ms,"cpu_noise_diffusion_ms":c.noise_diffusion_ms,
            "cpu_material_ms":c.material_ms,"cpu_surface_propagation_ms":c.surface_propagation_ms,
            "cpu_filter_ms":c.filter_ms,"cpu_total_ms":c.total_ms,
            "paper_voxelize_ms":paper[1],"paper_normal_diffusion_ms":paper[2],
            "paper_noise_diffusion_ms":paper[3],"paper_surface_propagation_ms":paper[4],
            "paper_total_ms":paper[7],
            "paper_total_without_reconstruction_and_baking_ms":paper[0] + paper[1] + paper[2] + paper[3] + paper[4],
        });
        if is_target {
            value["target_total_ms"] = json!(TARGET_MS_128);
            value["meets_target"] = json!(t.total_ms <= TARGET_MS_128);
        }
        let line = format!(
            "  {:>3}×{:>3}×{:>3}: total {:8.2} ms (paper {:8.2} ms{}) | voxelize {:6.2} ({:5.2}) | normal diffusion {:7.2} ({:7.2}) | noise diffusion {:7.2} + material {:6.2} ({:7.2}) | surface propagation {:6.2} + filter {:6.2} ({:7.2}) | proxies {:5.2}{}\n      CPU time, all threads: total {:8.2} ms | voxelize {:6.2} | normal diffusion {:7.2} | noise diffusion {:7.2} | material {:6.2} (one worker, beside the normal diffusion) | surface propagation {:6.2} | filter {:6.2}",
            dims[0], dims[1], dims[2], t.total_ms, paper[7],
            ", incl. reconstruction and baking",
            t.voxelize_ms, paper[1], t.normal_diffusion_ms, paper[2], t.noise_diffusion_ms, t.material_ms, paper[3],
            t.surface_propagation_ms, t.filter_ms, paper[4], t.proxy_ms,
            if is_target { format!(" — target ≤ {TARGET_MS_128} ms: {}", if t.total_ms <= TARGET_MS_128 { "met" } else { "MISSED" }) } else { String::new() },
            c.total_ms, c.voxelize_ms, c.normal_diffusion_ms, c.noise_diffusion_ms, c.material_ms,
            c.surface_propagation_ms, c.filter_ms,
        );
        emit(args, value, line);
        black_box(&f.surface);
    }
    // The target grid, whose 25 MB of sweep data sit in this machine's last-level cache (the
    // copy then runs at cache speed), and the paper's largest, whose 200 MB do not.
    sweep_bandwidth(args, [128, 64, 128]);
    sweep_bandwidth(args, [256, 128, 256]);
    Ok(())
}

/// One Perona–Malik sweep (three channels) and one Laplace sweep (two channels) on a `dims`
/// grid against a two-thread memory copy of the same number of bytes.
///
/// Each repetition times the sweep and then the copy of its bytes, back to back, and each figure
/// is the best of its repetitions: on a shared machine the speed available changes from second
/// to second, and interleaving lets the sweep and its copy see the same conditions.
fn sweep_bandwidth(args: &BenchArgs, dims: [usize; 3]) {
    let n = dims.iter().product::<usize>();
    let fixed: Vec<u8> = (0..n).map(|i| u8::from(i % 97 == 0)).collect();
    let src: Vec<Vec<f32>> = (0..3)
        .map(|c| {
            (0..n)
                .map(|i| ((i * (c + 3)) % 101) as f32 / 101.0)
                .collect()
        })
        .collect();
    let mut dst: Vec<Vec<f32>> = (0..3).map(|_| vec![0.0f32; n]).collect();
    let reps = 30;
    // Bytes per sample: m channels read and written, one constraint byte read; neighbours come
    // from cache.
    let bytes = |m: usize| (n * (4 * m + 1), n * 4 * m);
    // A plain copy moving the same bytes: read `b` bytes and write `b` bytes.
    let (read3, written3) = bytes(3);
    let copy_bytes = (read3 + written3) / 2;
    let from = vec![1u8; copy_bytes];
    let mut to = vec![0u8; copy_bytes];
    let mut copy = |len: usize| {
        let per = len.div_ceil(64).next_multiple_of(64);
        let t0 = Instant::now();
        par_slabs(&mut to[..len], per, |k, out| {
            let o = k * per;
            out.copy_from_slice(&from[o..o + out.len()]);
        });
        t0.elapsed().as_secs_f64()
    };
    let mut time_sweep = |pm: Option<f32>, m: usize| {
        let s: Vec<&[f32]> = src[..m].iter().map(|c| c.as_slice()).collect();
        let mut d: Vec<&mut [f32]> = dst[..m].iter_mut().map(|c| c.as_mut_slice()).collect();
        let t0 = Instant::now();
        sweep(dims, &s, &fixed, pm, &mut d);
        t0.elapsed().as_secs_f64()
    };
    // Best seconds of: Perona–Malik, its copy, Laplace, its copy.
    let mut best = [f64::INFINITY; 4];
    for _ in 0..reps {
        for (k, (pm, m)) in [(Some(K_PERONA_MALIK), 3usize), (None, 2)]
            .into_iter()
            .enumerate()
        {
            best[2 * k] = best[2 * k].min(time_sweep(pm, m));
            let (read, written) = bytes(m);
            best[2 * k + 1] = best[2 * k + 1].min(copy((read + written) / 2));
        }
    }
    black_box((&dst, &to));
    let copy_gbs = |m: usize, secs: f64| {
        let (read, written) = bytes(m);
        2.0 * ((read + written) / 2) as f64 / secs / 1e9
    };
    let (pm_s, lap_s) = (best[0], best[2]);
    let copies = [copy_gbs(3, best[1]), copy_gbs(2, best[3])];
    for (k, (name, secs, m)) in [("perona_malik", pm_s, 3usize), ("laplace", lap_s, 2)]
        .into_iter()
        .enumerate()
    {
        let (read, written) = bytes(m);
        let gbs = (read + written) as f64 / secs / 1e9;
        let copy = copies[k];
        let fraction = gbs / copy;
        emit(
            args,
            json!({"bench":"volume","figure":"sweep_bandwidth","sweep":name,"dims":dims,"channels":m,
                   "ms_per_sweep":secs * 1e3,"bytes_per_sweep":read + written,"gb_per_s":gbs,
                   "copy_gb_per_s":copy,"fraction_of_copy":fraction,
                   "target_fraction_of_copy":TARGET_SWEEP_FRACTION,"meets_target":fraction >= TARGET_SWEEP_FRACTION}),
            format!(
                "  one {name} sweep at {}×{}×{} ({m} channels): {:.2} ms, {:.2} GB/s vs copy of the same bytes {:.2} GB/s = {:.0} % (target ≥ {:.0} %)",
                dims[0], dims[1], dims[2], secs * 1e3, gbs, copy, fraction * 100.0, TARGET_SWEEP_FRACTION * 100.0
            ),
        );
    }
}
