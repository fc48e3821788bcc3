//! Meshing part of `strata bench volume` (issue 5, Done-when 6): throughput of
//! [`crate::volume::mesh::surface_nets`] (vertices, normals, quads, quad classes and Ptex
//! adjacency) against the `fast-surface-nets` crate 0.2 (vertices, normals, triangle indices) on
//! the same signed distance grids in the same run. Target: ours ≥ 1.0× theirs in cells per second.
//!
//! Grids: a noisy sphere and a terrain-like heightfield SDF with an overhang term, at 64³ and
//! 128³ samples. After a warm-up, the two meshers run alternately, one run of each per
//! repetition, with the output buffers reused (both libraries keep their allocations between
//! calls). The times are medians; the ratio is the median of the per-repetition ratios.

use super::super::{emit, median};
use crate::bench::BenchArgs;
use crate::volume::mesh::{surface_nets, MeshOptions, QuadMesh, SampleAttributes};
use fast_surface_nets::ndshape::RuntimeShape;
use fast_surface_nets::SurfaceNetsBuffer;
use serde_json::json;
use std::time::Instant;

/// Ours must be at least this fast relative to `fast-surface-nets`.
pub const TARGET_RATIO: f64 = 1.0;

/// A noisy sphere filling most of an `n³` grid.
pub fn noisy_sphere(n: usize) -> Vec<f32> {
    let c = (n as f32 - 1.0) / 2.0;
    let r = 0.35 * n as f32;
    sample(n, |x, y, z| {
        let (dx, dy, dz) = (x - c, y - c, z - c);
        let d = (dx * dx + dy * dy + dz * dz).sqrt() - r;
        d + 0.06 * n as f32 * (0.31 * x).sin() * (0.27 * y).sin() * (0.23 * z).sin()
    })
}

/// A terrain-like field: height `0.4·n` plus ridges, with a sine term that makes overhangs.
pub fn terrain(n: usize) -> Vec<f32> {
    let s = n as f32;
    sample(n, |x, y, z| {
        let h = 0.4 * s
            + 0.1 * s * (0.11 * x).sin() * (0.07 * z).cos()
            + 0.04 * s * (0.29 * (x + z)).sin();
        y - h + 2.0 * (0.5 * y + 0.2 * x).sin()
    })
}

fn sample(n: usize, f: impl Fn(f32, f32, f32) -> f32) -> Vec<f32> {
    let mut out = Vec::with_capacity(n * n * n);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                out.push(f(x as f32, y as f32, z as f32));
            }
        }
    }
    out
}

/// Times `ours` and `theirs` in alternating order, one run of each per repetition, after one
/// warm-up run of each. Returns the median times in milliseconds and the median of the
/// per-repetition ratios `theirs ÷ ours`: the machine's speed changes from moment to moment, and
/// a ratio of two runs taken back to back is steadier than a ratio of two separate medians.
fn paired_ms(runs: usize, mut ours: impl FnMut(), mut theirs: impl FnMut()) -> (f64, f64, f64) {
    let time = |f: &mut dyn FnMut()| {
        let s = Instant::now();
        f();
        s.elapsed().as_secs_f64() * 1e3
    };
    ours();
    theirs();
    let mut a = Vec::with_capacity(runs);
    let mut b = Vec::with_capacity(runs);
    let mut r = Vec::with_capacity(runs);
    for rep in 0..runs {
        let (o, t) = if rep % 2 == 0 {
            let o = time(&mut ours);
            (o, time(&mut theirs))
        } else {
            let t = time(&mut theirs);
            (time(&mut ours), t)
        };
        a.push(o);
        b.push(t);
        r.push(t / o);
    }
    (median(a), median(b), median(r))
}

/// Runs the meshing benchmark.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    for (name, field) in [
        ("noisy_sphere", noisy_sphere as fn(usize) -> Vec<f32>),
        ("terrain", terrain),
    ] {
        for n in [64usize, 128] {
            let sdf = field(n);
            let dims = [n; 3];
            let opts = MeshOptions::new(dims, 1.0);
            let mut ours = QuadMesh::default();
            let runs = if n <= 64 { 61 } else { 21 };
            let shape = RuntimeShape::<u32, 3>::new([n as u32; 3]);
            let mut buf = SurfaceNetsBuffer::default();
            let max = [n as u32 - 1; 3];
            let (ours_ms, theirs_ms, ratio) = paired_ms(
                runs,
                || {
                    if let Err(e) =
                        surface_nets(&sdf, SampleAttributes::default(), &opts, &mut ours)
                    {
                        panic!("benchmark grid is valid: {e}");
                    }
                },
                || fast_surface_nets::surface_nets(&sdf, &shape, [0; 3], max, &mut buf),
            );
            // Quads differ only at the grid border, where `fast-surface-nets` emits fewer.
            anyhow::ensure!(
                buf.positions.len() == ours.vertex_count(),
                "meshes differ: {} vs {} vertices",
                ours.vertex_count(),
                buf.positions.len()
            );
            let cells = ((n - 1) * (n - 1) * (n - 1)) as f64;
            emit(
                args,
                json!({"bench":"volume","figure":"mesh","sdf":name,"grid":[n,n,n],
                       "vertices":ours.vertex_count(),"quads":ours.quad_count(),
                       "fast_surface_nets_quads":buf.indices.len() / 6,
                       "ms_per_grid":ours_ms,"mcells_per_s":cells / ours_ms / 1e3,
                       "fast_surface_nets_ms_per_grid":theirs_ms,
                       "fast_surface_nets_mcells_per_s":cells / theirs_ms / 1e3,
                       "ratio":ratio,"target_ratio":TARGET_RATIO,"meets_target":ratio >= TARGET_RATIO}),
                format!(
                    "mesh {name} {n}³: {} vertices, {} quads\n  strata (classes + Ptex adjacency): {ours_ms:.2} ms ({:.1} Mcells/s)\n  fast-surface-nets:                 {theirs_ms:.2} ms ({:.1} Mcells/s)\n  ratio {ratio:.2} (target ≥ {TARGET_RATIO})",
                    ours.vertex_count(),
                    ours.quad_count(),
                    cells / ours_ms / 1e3,
                    cells / theirs_ms / 1e3
                ),
            );
        }
    }
    Ok(())
}
