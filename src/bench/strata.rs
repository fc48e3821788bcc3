//! `strata bench strata` (issue 6): for each of Santamaría-Ibirika et al.'s Table 2
//! configurations A0–B3, the time to generate a terrain of 5×5×5 chunks of 10³ voxels (one core)
//! beside the paper's Table 3 offline average (Intel i7 950), and the stored limits per voxel
//! (paper: 84,376 limits for 125,000 voxels).

use super::emit;
use crate::bench::BenchArgs;
use crate::subsurface::plan::ElementKind;
use crate::subsurface::{ChunkKey, SubsurfaceConfig, SubsurfacePlan, PRESETS};
use serde_json::json;
use std::hint::black_box;
use std::time::Instant;

/// Target of issue 6: milliseconds per 5×5×5-chunk terrain on the CPU path.
pub const TARGET_MS_PER_TERRAIN: f64 = 10.0;
/// Chunk side, voxels (the paper's 10×10×10).
pub const CHUNK: u32 = 10;
/// Table 3, offline average time (ms) of A0…B3 on an i7 950.
pub const PAPER_MS: [f64; 8] = [
    319.14, 347.01, 334.85, 348.46, 324.36, 354.25, 354.30, 346.67,
];
/// §5.1: average limits of the paper's terrains (for 125,000 voxels).
pub const PAPER_LIMITS: f64 = 84_376.42;
/// Terrains per configuration (the paper generates 100).
const TERRAINS: u64 = 100;

/// The 5×5×5 chunks of one terrain: y from −40 to 10 around the mean surface at 0.
fn keys(t: u64) -> Vec<ChunkKey> {
    let (ox, oz) = ((t % 10) as i32 * 5, (t / 10) as i32 * 5);
    let mut keys = Vec::with_capacity(125);
    for y in -4..=0 {
        for z in 0..5 {
            for x in 0..5 {
                keys.push(ChunkKey {
                    x: ox + x,
                    y,
                    z: oz + z,
                });
            }
        }
    }
    keys
}

/// Runs the benchmark.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    emit(
        args,
        json!({"bench":"strata","terrains_per_configuration":TERRAINS,"chunks_per_terrain":125,"voxels_per_chunk":CHUNK*CHUNK*CHUNK}),
        format!("strata: {TERRAINS} terrains per configuration (a fresh seed each) of 5×5×5 chunks of {CHUNK}³ voxels, one core"),
    );
    for (n, name) in PRESETS.iter().enumerate() {
        let config =
            SubsurfaceConfig::preset(name).ok_or_else(|| anyhow::anyhow!("no preset {name}"))?;
        // Warm-up: one untimed terrain (page faults, caches).
        let warm = SubsurfacePlan::new(u64::MAX, config.clone());
        for key in keys(0) {
            black_box(warm.chunk(key, CHUNK));
        }
        let mut total_s = 0.0f64;
        let mut max_ms = 0.0f64;
        let (mut limits, mut voxels, mut layers, mut elements) = (0usize, 0usize, 0usize, 0usize);
        for t in 0..TERRAINS {
            let start = Instant::now();
            let plan = SubsurfacePlan::new(t, config.clone());
            for key in keys(t) {
                let chunk = black_box(plan.chunk(key, CHUNK));
                limits += chunk.limits.len();
                voxels += chunk.voxel_count();
            }
            let s = start.elapsed().as_secs_f64();
            total_s += s;
            max_ms = max_ms.max(s * 1e3);
            layers += plan.layers.len();
            // Elements whose cell meets the terrain's 50×50 footprint.
            let (ox, oz) = ((t % 10) as f32 * 50.0, (t / 10) as f32 * 50.0);
            for kind in [ElementKind::Vein, ElementKind::Cave] {
                let side = plan.cell_side(kind);
                let (i0, i1) = (
                    (ox / side).floor() as i32,
                    ((ox + 49.0) / side).floor() as i32,
                );
                let (k0, k1) = (
                    (oz / side).floor() as i32,
                    ((oz + 49.0) / side).floor() as i32,
                );
                for k in k0..=k1 {
                    for i in i0..=i1 {
                        elements += usize::from(plan.element(kind, (i, k)).is_some());
                    }
                }
            }
        }
        let ms = total_s * 1e3 / TERRAINS as f64;
        let per_terrain = |v: usize| v as f64 / TERRAINS as f64;
        let ratio = limits as f64 / voxels as f64;
        let meets = ms <= TARGET_MS_PER_TERRAIN && limits < voxels;
        emit(
            args,
            json!({"bench":"strata","configuration":name,"ms_per_terrain":ms,"max_ms_per_terrain":max_ms,
                   "paper_ms_per_terrain":PAPER_MS[n],"speedup_over_paper":PAPER_MS[n] / ms,
                   "limits_per_terrain":per_terrain(limits),"voxels_per_terrain":per_terrain(voxels),
                   "limits_per_voxel":ratio,"paper_limits_per_voxel":PAPER_LIMITS / 125_000.0,
                   "layers_per_terrain":per_terrain(layers),"elements_per_terrain":per_terrain(elements),
                   "target_ms_per_terrain":TARGET_MS_PER_TERRAIN,"meets_target":meets}),
            format!(
                "  {name}: {ms:.3} ms per terrain (max {max_ms:.3}; paper {:.2} ms, ×{:.0}; target ≤ {TARGET_MS_PER_TERRAIN}) — {:.0} limits for {:.0} voxels ({ratio:.3}; paper {:.3}), {:.2} layers, {:.2} elements",
                PAPER_MS[n],
                PAPER_MS[n] / ms,
                per_terrain(limits),
                per_terrain(voxels),
                PAPER_LIMITS / 125_000.0,
                per_terrain(layers),
                per_terrain(elements),
            ),
        );
    }
    Ok(())
}
