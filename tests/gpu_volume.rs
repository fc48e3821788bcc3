//! The WGSL twins of the volume pipeline's diffusion and surface propagation
//! (`shaders/volume_diffuse.wgsl`, `shaders/volume_propagate.wgsl`) against the CPU reference on
//! a software adapter (lavapipe). These tests REQUIRE an adapter: without one they fail with
//! instructions, they never skip. Grids are small because lavapipe is slow.

#![allow(clippy::needless_range_loop)]

mod common;

use std::mem::{offset_of, size_of};
use strata::gpu::volume::{
    diffuse_on_device, propagate_on_device, DiffuseInput, GpuDiffuseParams, GpuPropagateParams,
    PropagateInput, DIFFUSE_WGSL, PROPAGATE_WGSL,
};
use strata::volume::pipeline::diffuse::{sweeps, K_PERONA_MALIK};
use strata::volume::pipeline::propagate::propagate_surface;
use strata::volume::pipeline::{generate, scenes};

fn software_device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    common::device::software_device("gpu_volume")
}

fn field(n: usize, seed: u32, base: f32, amp: f32) -> Vec<f32> {
    (0..n)
        .map(|i| {
            let h = (i as u32 ^ seed)
                .wrapping_mul(0x9E37_79B9)
                .rotate_left(13)
                .wrapping_mul(0x85EB_CA6B);
            base + amp * ((h >> 8) as f32 / (1u32 << 24) as f32 * 2.0 - 1.0)
        })
        .collect()
}

/// `(member, offset)` of struct `Params` in a shader, and its size.
fn params_layout(source: &str) -> (Vec<(String, u32)>, u32) {
    let module = naga::front::wgsl::parse_str(source).expect("shader parses");
    for (_, ty) in module.types.iter() {
        if ty.name.as_deref() == Some("Params") {
            if let naga::TypeInner::Struct { members, span } = &ty.inner {
                return (
                    members
                        .iter()
                        .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                        .collect(),
                    *span,
                );
            }
        }
    }
    panic!("no struct Params");
}

#[test]
fn host_params_match_the_wgsl_structs() {
    let (m, size) = params_layout(DIFFUSE_WGSL);
    assert_eq!(size as usize, size_of::<GpuDiffuseParams>());
    let want = [
        ("nx", offset_of!(GpuDiffuseParams, nx)),
        ("ny", offset_of!(GpuDiffuseParams, ny)),
        ("nz", offset_of!(GpuDiffuseParams, nz)),
        ("mode", offset_of!(GpuDiffuseParams, mode)),
        ("qk", offset_of!(GpuDiffuseParams, qk)),
        ("_pad0", offset_of!(GpuDiffuseParams, _pad0)),
        ("_pad1", offset_of!(GpuDiffuseParams, _pad1)),
        ("_pad2", offset_of!(GpuDiffuseParams, _pad2)),
    ];
    assert_eq!(m.len(), want.len());
    for ((name, off), (wn, wo)) in m.iter().zip(want) {
        assert_eq!((name.as_str(), *off as usize), (wn, wo));
    }
    let (m, size) = params_layout(PROPAGATE_WGSL);
    assert_eq!(size as usize, size_of::<GpuPropagateParams>());
    let want = [
        ("nx", offset_of!(GpuPropagateParams, nx)),
        ("ny", offset_of!(GpuPropagateParams, ny)),
        ("nz", offset_of!(GpuPropagateParams, nz)),
        ("layer", offset_of!(GpuPropagateParams, layer)),
        ("spacing", offset_of!(GpuPropagateParams, spacing)),
        ("_pad0", offset_of!(GpuPropagateParams, _pad0)),
        ("_pad1", offset_of!(GpuPropagateParams, _pad1)),
        ("_pad2", offset_of!(GpuPropagateParams, _pad2)),
    ];
    assert_eq!(m.len(), want.len());
    for ((name, off), (wn, wo)) in m.iter().zip(want) {
        assert_eq!((name.as_str(), *off as usize), (wn, wo));
    }
}

#[test]
fn diffusion_sweeps_match_the_cpu() {
    let (_a, device, queue) = software_device();
    let dims = [20, 12, 16];
    let n = 20 * 12 * 16;
    let fixed: Vec<u8> = (0..n).map(|i| u8::from(i % 11 == 0)).collect();
    // Perona–Malik on near-unit normals (|ΔN|² around 4k, where the coefficients vary most).
    let normals: Vec<Vec<f32>> = (0..3)
        .map(|c| field(n, c, [0.3, 0.9, 0.3][c as usize], 0.06))
        .collect();
    // Laplace on two unrelated channels.
    let noise: Vec<Vec<f32>> = (0..2).map(|c| field(n, 10 + c, 0.0, 1.0)).collect();
    for (chans, pm) in [(&normals, Some(K_PERONA_MALIK)), (&noise, None)] {
        let steps = 12;
        let mut cpu = chans.clone();
        sweeps(dims, &mut cpu, &fixed, pm, steps);
        let gpu = diffuse_on_device(
            &device,
            &queue,
            &DiffuseInput {
                dims,
                channels: chans,
                fixed: &fixed,
                pm,
                sweeps: steps,
            },
        )
        .expect("gpu diffusion");
        let (mut worst, mut same) = (0.0f32, 0usize);
        for (c, g) in cpu.iter().zip(&gpu) {
            for (a, b) in c.iter().zip(g) {
                worst = worst.max((a - b).abs());
                same += usize::from(a.to_bits() == b.to_bits());
            }
        }
        println!(
            "{}: max |Δ| = {worst:e} after {steps} sweeps, {same} of {} values bit-identical",
            if pm.is_some() {
                "Perona–Malik"
            } else {
                "Laplace"
            },
            chans.len() * n
        );
        // Tolerance: values are O(1); each sweep may differ by a few ULP (fused multiply-adds,
        // `1/(1+q²)` to 2.5 ULP) and a sweep averages, not amplifies, earlier differences, so
        // 12 sweeps stay within 12 × 8 ULP of 1.0 ≈ 1.2·10⁻⁵.
        assert!(worst <= 1.2e-5, "CPU and GPU differ by {worst}");
        for i in 0..n {
            if fixed[i] != 0 {
                for (g, c) in gpu.iter().zip(chans.iter()) {
                    assert_eq!(g[i], c[i], "constrained sample {i} moved on the GPU");
                }
            }
        }
    }
}

#[test]
fn surface_propagation_matches_the_cpu() {
    let (_a, device, queue) = software_device();
    let (grid, scene, params) = scenes::arch([32, 16, 24]);
    let f = generate(&grid, &scene, &params).expect("arch");
    let v = &f.voxelized;
    let mut cpu = v.surface.clone();
    let cpu_layer = propagate_surface(&grid, &f.normal, &v.omega_s, &mut cpu);
    let (gpu, gpu_layer) = propagate_on_device(
        &device,
        &queue,
        &PropagateInput {
            grid: &grid,
            normal: &f.normal,
            omega_s: &v.omega_s,
            surface: &v.surface,
        },
    )
    .expect("gpu propagation");
    assert_eq!(cpu_layer, gpu_layer, "the same wavefront layers");
    let (mut worst, mut same) = (0.0f32, 0usize);
    for i in 0..grid.len() {
        let d = (cpu[i] - gpu[i]).abs();
        same += usize::from(cpu[i].to_bits() == gpu[i].to_bits());
        // Tolerance: each layer adds one term `±h·(n_a + n_b)/2` (one possibly fused multiply-add,
        // ≤ 1 ULP of the running value); the min rule does not amplify differences, so after L
        // layers |ΔS| ≤ L ULP of |S| ≤ 64 m, i.e. (L + 1) · 8·10⁻⁶ m.
        let tol = (cpu_layer[i] as f32 + 1.0) * 8e-6;
        assert!(
            d <= tol,
            "sample {i}: CPU {} GPU {} (layer {})",
            cpu[i],
            gpu[i],
            cpu_layer[i]
        );
        worst = worst.max(d);
    }
    println!(
        "propagation: max |ΔS| = {worst:e} m, {same} of {} bit-identical",
        grid.len()
    );
}
