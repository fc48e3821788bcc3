//! The WGSL twin of the Ptex bake (Becher §4.7): `shaders/ptex.wgsl` run by
//! [`bake_interior_on_device`], the twin of [`crate::ptex::bake_interior`]. One invocation per
//! interior texel, one dispatch, one submission; the borders are then copied on the CPU
//! ([`crate::ptex::border::fill_borders`]: a copy, no arithmetic). The device and queue come
//! from the caller, so tests inject lavapipe.
//!
//! # Tolerance
//!
//! The hashing and the lattice coordinates are exact on both sides (`ptex::noise`), but WGSL
//! lets a compiler contract `a·b + c` and computes `sqrt` and `/` to a few ULP, so a texel's
//! floats may differ from the CPU's by rounding, and a quantised byte may land one step away
//! when the value sits near a rounding boundary; the normal, a difference quotient over half a
//! texel, amplifies that. `tests/gpu_ptex.rs` states the bound it allows.
//!
//! # Limits
//!
//! The output (12 bytes per texel) must fit the device's `max_storage_buffer_binding_size`; a
//! larger bake is an error, not a panic.

use super::kit::{bind_group, dispatch_linear, read_back, readback, upload, Binding, Program};
use super::scopes::Scopes;
use crate::ptex::bake::face_constants;
use crate::ptex::{FaceSet, MaterialSet, Pages};
use anyhow::{bail, Context};
use std::time::Duration;

/// `shaders/ptex.wgsl`.
pub const PTEX_WGSL: &str = include_str!("../../shaders/ptex.wgsl");
/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// How long one job may wait for the device.
const JOB_TIMEOUT: Duration = Duration::from_secs(120);

/// `Params` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuPtexParams {
    /// Texels per face side.
    pub res: u32,
    /// Faces.
    pub faces: u32,
    /// Lowest displacement-noise octave exponent.
    pub noise_k0: i32,
    /// Displacement-noise octaves.
    pub noise_octaves: u32,
    /// Displacement-noise hash seed.
    pub noise_seed: u32,
    /// Materials in the set.
    pub materials: u32,
    /// Padding.
    pub pad: [u32; 2],
}

/// `Face` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuFace {
    /// Anchor, units of 256 m.
    pub anchor: [i32; 3],
    /// First sample.
    pub first: u32,
    /// Samples per side.
    pub n: u32,
    /// Finest octave exponent at this resolution.
    pub kmax: i32,
    /// Forward-difference step, metres.
    pub step: f32,
    /// Padding.
    pub pad: u32,
}

/// `Sample` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuSample {
    /// Position relative to the anchor, metres.
    pub position: [f32; 3],
    /// Material id.
    pub material: u32,
    /// Unit normal.
    pub normal: [f32; 3],
    /// Noise amplitude, metres.
    pub noise_m: f32,
}

/// `Mat` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    /// Albedo at pattern 0.
    pub base: [f32; 3],
    /// Relief, metres.
    pub relief_m: f32,
    /// Albedo at pattern 1.
    pub tint: [f32; 3],
    /// Roughness at pattern 0.
    pub rough0: f32,
    /// Roughness at pattern 1.
    pub rough1: f32,
    /// Lowest pattern octave exponent.
    pub freq_log2: i32,
    /// Pattern octaves.
    pub octaves: u32,
    /// Pattern hash seed.
    pub seed: u32,
    /// Padding.
    pub pad: [u32; 4],
}

/// Bakes the interior texels of every face of `set` at `res` on `device` into `out` (reset to
/// the set's faces; borders left zero), like [`crate::ptex::bake_interior`].
///
/// # Errors
/// An empty or invalid input, an output too large for the device, or a device error.
pub fn bake_interior_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    set: &FaceSet,
    mats: &MaterialSet,
    res: u32,
    out: &mut Pages,
) -> anyhow::Result<()> {
    if !crate::ptex::valid_res(res) {
        bail!("res {res} is not a power of two in 8..=256");
    }
    if let Err(e) = mats.validate() {
        bail!("materials: {e}");
    }
    let texels = set.faces.len() as u64 * u64::from(res) * u64::from(res);
    let bytes = 12 * texels;
    let limit = device.limits().max_storage_buffer_binding_size;
    if texels == 0 || bytes > limit || texels >= u64::from(u32::MAX) {
        bail!("{texels} texels need a {bytes}-byte buffer; the device allows {limit}");
    }
    let faces: Vec<GpuFace> = set
        .faces
        .iter()
        .map(|f| {
            let (kmax, step) = face_constants(f, res);
            GpuFace {
                anchor: f.anchor,
                first: f.first,
                n: f.n,
                kmax,
                step,
                pad: 0,
            }
        })
        .collect();
    let samples: Vec<GpuSample> = set
        .samples
        .iter()
        .map(|s| GpuSample {
            position: s.position,
            material: s.material,
            normal: s.normal,
            noise_m: s.noise_m,
        })
        .collect();
    let materials: Vec<GpuMaterial> = mats
        .materials
        .iter()
        .zip(&mats.seeds)
        .map(|(m, &seed)| GpuMaterial {
            base: m.base,
            relief_m: m.relief_m,
            tint: m.tint,
            rough0: m.roughness[0],
            rough1: m.roughness[1],
            freq_log2: m.freq_log2,
            octaves: m.octaves,
            seed,
            pad: [0; 4],
        })
        .collect();
    let params = GpuPtexParams {
        res,
        faces: set.faces.len() as u32,
        noise_k0: mats.noise_freq_log2,
        noise_octaves: mats.noise_octaves,
        noise_seed: mats.noise_seed,
        materials: materials.len() as u32,
        pad: [0; 2],
    };
    let scopes = Scopes::push(device);
    let (u, r, w) = (Binding::Uniform, Binding::Read, Binding::ReadWrite);
    let program = Program::new(device, "strata ptex.wgsl", PTEX_WGSL, &[u, r, r, r, w]);
    let pipeline = program.pipeline(device, "bake");
    let storage = wgpu::BufferUsages::STORAGE;
    let ub = upload(
        device,
        queue,
        "ptex params",
        bytemuck::bytes_of(&params),
        wgpu::BufferUsages::UNIFORM,
    );
    let fb = upload(
        device,
        queue,
        "ptex faces",
        bytemuck::cast_slice(&faces),
        storage,
    );
    let sb = upload(
        device,
        queue,
        "ptex samples",
        bytemuck::cast_slice(&samples),
        storage,
    );
    let mb = upload(
        device,
        queue,
        "ptex materials",
        bytemuck::cast_slice(&materials),
        storage,
    );
    let ob = super::kit::storage(device, "ptex texels", bytes, wgpu::BufferUsages::COPY_SRC);
    let group = bind_group(device, &program.layout, "ptex", &[&ub, &fb, &sb, &mb, &ob]);
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("strata ptex bake"),
    });
    {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("strata ptex bake"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        dispatch_linear(&mut pass, texels as u32, WORKGROUP);
    }
    let rb = readback(device, "ptex readback", bytes);
    encoder.copy_buffer_to_buffer(&ob, 0, &rb, 0, bytes);
    let submission = queue.submit([encoder.finish()]);
    let words: Vec<u32> = read_back(device, &rb, submission, Some(JOB_TIMEOUT), scopes)
        .context("running shaders/ptex.wgsl")?;
    out.reset(res, set.faces.len());
    let rr = res as usize;
    for f in 0..set.faces.len() {
        for j in 0..rr {
            for i in 0..rr {
                let src = 3 * ((f * rr + j) * rr + i);
                let dst = out.at(f, i as i32, j as i32);
                out.albedo[dst] = words[src].to_le_bytes();
                out.normal[dst] = words[src + 1].to_le_bytes();
                out.displacement[dst] = f32::from_bits(words[src + 2]);
            }
        }
    }
    Ok(())
}
