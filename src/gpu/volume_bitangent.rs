//! The WGSL twin of the §5.1 smooth bitangent field (Becher et al., feature-curve expansion):
//! `shaders/volume_bitangent.wgsl` run by [`smooth_bitangents_on_device`], the twin of
//! [`crate::volume::pipeline::expand::smooth_bitangents`].
//!
//! One `seed` dispatch, one `fill` dispatch per wavefront layer (`nx + ny + nz − 2` of them, an
//! upper bound of the breadth-first distance in a box; passes after the last layer change
//! nothing), then `sweeps` Jacobi dispatches ping-ponging between two buffers; all in one
//! submission. The device and queue come from the caller, so tests inject lavapipe.
//!
//! # Tolerance
//!
//! The shader performs the CPU's operations in its order, but WGSL lets a compiler contract
//! `a·b + c` into a fused multiply-add and computes `sqrt` and `1/x` to a few ULP, so a sample
//! may differ from the CPU by a few ULP, and the sign test `a·b < 0` of the average can come out
//! the other way when `a·b` is within rounding of zero. `tests/gpu_volume_bitangent.rs` states
//! the bound it allows.
//!
//! # Limits
//!
//! The grid's `vec4` buffer must fit the device's `max_storage_buffer_binding_size` (128 MiB by
//! default: 8 Mi samples); a larger grid is an error, not a panic.

use super::kit::{
    bind_group, dispatch_linear, read_back, readback, storage, upload, Binding, Program,
};
use super::scopes::Scopes;
use anyhow::{bail, Context};
use std::time::Duration;

/// `shaders/volume_bitangent.wgsl`.
pub const VOLUME_BITANGENT_WGSL: &str = include_str!("../../shaders/volume_bitangent.wgsl");
/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// How long one job may wait for the device.
const JOB_TIMEOUT: Duration = Duration::from_secs(120);

/// `Params` of `shaders/volume_bitangent.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuBitangentParams {
    /// Samples along x.
    pub nx: u32,
    /// Samples along y.
    pub ny: u32,
    /// Samples along z.
    pub nz: u32,
    /// The wavefront layer a `fill` dispatch sets (unused by `seed` and `sweep`).
    pub layer: u32,
}

/// The smooth bitangent field of the voxelized sparse bitangents `sparse` (three channels over
/// the `dims` grid, zero outside `Ω_B`) after `sweeps` Jacobi sweeps, computed on `device`.
///
/// # Errors
/// Channels of the wrong length, a grid too large for the device, or a device error.
pub fn smooth_bitangents_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    dims: [usize; 3],
    sparse: &[Vec<f32>; 3],
    sweeps: usize,
) -> anyhow::Result<[Vec<f32>; 3]> {
    let n = dims.iter().product::<usize>();
    let limit = device.limits().max_storage_buffer_binding_size;
    if n == 0 || (n as u64) * 16 > limit || n >= u32::MAX as usize {
        bail!(
            "grid {dims:?} needs a {}-byte buffer; the device allows {limit}",
            n * 16
        );
    }
    if sparse.iter().any(|c| c.len() != n) {
        bail!("every channel must have {n} samples");
    }
    let scopes = Scopes::push(device);
    let (w, u) = (Binding::ReadWrite, Binding::Uniform);
    let program = Program::new(
        device,
        "strata volume_bitangent.wgsl",
        VOLUME_BITANGENT_WGSL,
        &[u, w, w, w],
    );
    let [seed, fill, sweep] = ["seed", "fill", "sweep"].map(|e| program.pipeline(device, e));
    let mut packed = vec![0.0f32; 4 * n];
    for (c, ch) in sparse.iter().enumerate() {
        for (i, v) in ch.iter().enumerate() {
            packed[4 * i + c] = *v;
        }
    }
    let copy = wgpu::BufferUsages::COPY_SRC;
    let layers = storage(device, "bitangent layers", 4 * n as u64, copy);
    let a = upload(
        device,
        queue,
        "bitangent a",
        bytemuck::cast_slice(&packed),
        wgpu::BufferUsages::STORAGE | copy,
    );
    let b = storage(device, "bitangent b", 16 * n as u64, copy);
    let passes = (dims[0] + dims[1] + dims[2] - 2) as u32;
    let params = |layer: u32| GpuBitangentParams {
        nx: dims[0] as u32,
        ny: dims[1] as u32,
        nz: dims[2] as u32,
        layer,
    };
    // One uniform buffer and bind group per layer (`layer` 0 serves `seed` and the sweeps),
    // and the sweeps' second bind group with the buffers swapped.
    let uniforms: Vec<wgpu::Buffer> = (0..=passes)
        .map(|l| {
            upload(
                device,
                queue,
                "bitangent params",
                bytemuck::bytes_of(&params(l)),
                wgpu::BufferUsages::UNIFORM,
            )
        })
        .collect();
    let groups: Vec<wgpu::BindGroup> = uniforms
        .iter()
        .map(|ub| {
            bind_group(
                device,
                &program.layout,
                "bitangent layer",
                &[ub, &layers, &a, &b],
            )
        })
        .collect();
    let swapped = bind_group(
        device,
        &program.layout,
        "bitangent swapped",
        &[&uniforms[0], &layers, &b, &a],
    );
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("strata volume bitangent"),
    });
    {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("strata volume bitangent"),
            timestamp_writes: None,
        });
        // Each dispatch sees the storage writes of the previous one (WebGPU orders dispatches
        // within a pass as separate usage scopes).
        pass.set_pipeline(&seed);
        pass.set_bind_group(0, &groups[0], &[]);
        dispatch_linear(&mut pass, n as u32, WORKGROUP);
        pass.set_pipeline(&fill);
        for g in &groups[1..] {
            pass.set_bind_group(0, g, &[]);
            dispatch_linear(&mut pass, n as u32, WORKGROUP);
        }
        pass.set_pipeline(&sweep);
        for s in 0..sweeps {
            pass.set_bind_group(
                0,
                if s.is_multiple_of(2) {
                    &groups[0]
                } else {
                    &swapped
                },
                &[],
            );
            dispatch_linear(&mut pass, n as u32, WORKGROUP);
        }
    }
    let result = if sweeps.is_multiple_of(2) { &a } else { &b };
    let out = readback(device, "bitangent readback", 16 * n as u64);
    encoder.copy_buffer_to_buffer(result, 0, &out, 0, 16 * n as u64);
    let submission = queue.submit([encoder.finish()]);
    let words: Vec<f32> = read_back(device, &out, submission, Some(JOB_TIMEOUT), scopes)
        .context("running shaders/volume_bitangent.wgsl")?;
    let channel = |c: usize| words.iter().skip(c).step_by(4).copied().collect();
    Ok([channel(0), channel(1), channel(2)])
}
