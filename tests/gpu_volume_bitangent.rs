//! The WGSL twin of the §5.1 smooth bitangent field (`shaders/volume_bitangent.wgsl`,
//! `strata::gpu::volume_bitangent`) against the CPU reference
//! (`strata::volume::pipeline::expand::smooth_bitangents`) on a software adapter (lavapipe).
//! REQUIRES an adapter: without one the test fails with instructions, it never skips.
//!
//! Tolerance (reason in `src/gpu/volume_bitangent.rs`): every sample the CPU fills is filled on
//! the GPU and the other way round (which samples a wavefront reaches is integer logic), and the
//! two vectors are the same line — `|cpu · gpu| ≥ 1 − 1e-5`, the room WGSL leaves for fused
//! multiply-adds and few-ULP `sqrt` and `/` over a handful of folds — and the same direction
//! (`cpu · gpu > 0`) except where a sign test `a·b < 0` met an `a·b` within rounding of zero;
//! those flips may be at most 0.1 % of the samples. The test prints how many samples are
//! bit-identical.

mod common;

use strata::gpu::volume_bitangent::smooth_bitangents_on_device;
use strata::volume::pipeline::expand::{smooth_bitangents, BITANGENT_SWEEPS};
use strata::volume::pipeline::{generate, scenes};

const LINE_TOL: f32 = 1e-5;
const MAX_FLIPPED_FRACTION: f64 = 1e-3;

fn device() -> (wgpu::Device, wgpu::Queue) {
    common::device::device("gpu_volume_bitangent")
}

fn compare(dims: [usize; 3], sparse: &[Vec<f32>; 3], sweeps: usize) {
    let (device, queue) = device();
    let cpu = smooth_bitangents(dims, sparse, sweeps);
    let gpu =
        smooth_bitangents_on_device(&device, &queue, dims, sparse, sweeps).expect("the GPU field");
    let n = dims.iter().product::<usize>();
    let at = |f: &[Vec<f32>; 3], i: usize| [f[0][i], f[1][i], f[2][i]];
    let (mut identical, mut flipped, mut filled) = (0usize, 0usize, 0usize);
    for i in 0..n {
        let (c, g) = (at(&cpu, i), at(&gpu, i));
        if c == g {
            identical += 1;
        }
        let zero = |v: [f32; 3]| v == [0.0; 3];
        assert_eq!(
            zero(c),
            zero(g),
            "sample {i}: filled on one side only ({c:?} vs {g:?})"
        );
        if zero(c) {
            continue;
        }
        filled += 1;
        let d = c[0] * g[0] + c[1] * g[1] + c[2] * g[2];
        assert!(d.abs() >= 1.0 - LINE_TOL, "sample {i}: {c:?} vs {g:?}");
        if d < 0.0 {
            flipped += 1;
        }
    }
    println!(
        "{dims:?}, {sweeps} sweeps: {filled} filled samples, {identical} of {n} bit-identical, \
         {flipped} flipped"
    );
    assert!(filled > 0, "the field is not empty");
    assert!(
        flipped as f64 <= MAX_FLIPPED_FRACTION * n as f64,
        "{flipped} of {n} samples flipped"
    );
}

/// The arch scene's voxelized bitangents: ribbons of four curves in a 48 × 24 × 40 box.
#[test]
fn the_smooth_bitangent_field_matches_the_cpu_on_the_arch_scene() {
    let (grid, scene, params) = scenes::arch([48, 24, 40]);
    let fields = generate(&grid, &scene, &params).expect("the arch region");
    let sparse = &fields.bitangent;
    assert!(sparse[0]
        .iter()
        .chain(&sparse[1])
        .chain(&sparse[2])
        .any(|&v| v != 0.0));
    for sweeps in [0, 1, BITANGENT_SWEEPS] {
        compare(grid.dims, sparse, sweeps);
    }
}

/// Two opposite constraints, the case a plain mean cancels, and an empty `Ω_B` (nothing filled).
#[test]
fn opposite_constraints_and_an_empty_field_match_the_cpu() {
    let dims = [9, 5, 7];
    let n = 9 * 5 * 7;
    let mut sparse: [Vec<f32>; 3] = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    sparse[2][1 + 9 * (2 + 5 * 3)] = 2.0;
    sparse[2][7 + 9 * (2 + 5 * 3)] = -1.0;
    sparse[0][4 + 9 * (4 + 5 * 6)] = 0.5;
    compare(dims, &sparse, BITANGENT_SWEEPS);
    let (device, queue) = device();
    let empty: [Vec<f32>; 3] = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    let gpu = smooth_bitangents_on_device(&device, &queue, dims, &empty, 2).expect("empty");
    assert!(gpu.iter().all(|c| c.iter().all(|&v| v == 0.0)));
    assert!(
        smooth_bitangents_on_device(&device, &queue, dims, &[vec![0.0; 3], vec![], vec![]], 1)
            .is_err()
    );
}
