//! WGSL twins of the volume pipeline's iterative stages (Becher §4.3–4.5):
//! `shaders/volume_diffuse.wgsl` ([`diffuse_on_device`], the twin of
//! [`crate::volume::pipeline::diffuse::sweeps`]) and `shaders/volume_propagate.wgsl`
//! ([`propagate_on_device`], the twin of
//! [`crate::volume::pipeline::propagate::propagate_surface`]).
//!
//! Both take the device and queue from the caller (tests inject lavapipe). The diffusion ping-
//! pongs between two buffers, one compute pass per sweep; the propagation runs one compute pass
//! per wavefront layer, `nx + ny + nz − 2` passes (an upper bound of the breadth-first distance;
//! passes after the last layer change nothing).
//!
//! # Tolerance
//!
//! The kernels perform the CPU's operations in the CPU's order, but WGSL allows a compiler to
//! contract `a·b + c` into a fused multiply-add and computes `1/(1 + q²)` to 2.5 ULP, so a
//! sweep may differ from the CPU by a few ULP per sample, and differences travel with the
//! diffusion. `tests/gpu_volume.rs` states the bounds it allows next to each comparison.
//!
//! # Limits
//!
//! Four channels per sample (`vec4`); the largest grid is the one whose `vec4` buffer fits the
//! device's `max_storage_buffer_binding_size` (128 MiB by default: 8 Mi samples, e.g.
//! 256 × 128 × 256); larger grids are an error, not a panic.

use super::kit::{read_back, readback, upload};
use super::scopes::Scopes;
use crate::volume::pipeline::grid::Grid;
use anyhow::{bail, Context};

const WORKGROUP: u32 = 64;
const MAX_GROUPS: u32 = 65_535;

/// `Params` of `shaders/volume_diffuse.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuDiffuseParams {
    /// Samples along x.
    pub nx: u32,
    /// Samples along y.
    pub ny: u32,
    /// Samples along z.
    pub nz: u32,
    /// 0: Laplace (`c ≡ 1`); 1: Perona–Malik on the xyz channels.
    pub mode: u32,
    /// `0.25 / k`.
    pub qk: f32,
    /// Padding to 32 bytes.
    pub _pad0: u32,
    /// Padding.
    pub _pad1: u32,
    /// Padding.
    pub _pad2: u32,
}

/// `Params` of `shaders/volume_propagate.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuPropagateParams {
    /// Samples along x.
    pub nx: u32,
    /// Samples along y.
    pub ny: u32,
    /// Samples along z.
    pub nz: u32,
    /// The wavefront layer this dispatch sets.
    pub layer: u32,
    /// Grid spacing, metres.
    pub spacing: f32,
    /// Padding to 32 bytes.
    pub _pad0: u32,
    /// Padding.
    pub _pad1: u32,
    /// Padding.
    pub _pad2: u32,
}

/// Input of [`diffuse_on_device`].
#[derive(Clone, Copy, Debug)]
pub struct DiffuseInput<'a> {
    /// Grid dimensions.
    pub dims: [usize; 3],
    /// One to four channels, each `dims` samples (Perona–Malik: exactly three, `N`).
    pub channels: &'a [Vec<f32>],
    /// Constrained samples (`!= 0`) keep their values.
    pub fixed: &'a [u8],
    /// `Some(k)`: Perona–Malik sweeps with parameter `k`; `None`: Laplace sweeps.
    pub pm: Option<f32>,
    /// Number of Jacobi sweeps.
    pub sweeps: u32,
}

/// Input of [`propagate_on_device`].
#[derive(Clone, Copy, Debug)]
pub struct PropagateInput<'a> {
    /// The grid (dimensions and spacing).
    pub grid: &'a Grid,
    /// Dense unit normals, three channels.
    pub normal: &'a [Vec<f32>],
    /// `Ω_S` membership.
    pub omega_s: &'a [u8],
    /// `S` with the seed values in `Ω_S`.
    pub surface: &'a [f32],
}

/// The shader source of `volume_diffuse.wgsl`.
pub const DIFFUSE_WGSL: &str = include_str!("../../shaders/volume_diffuse.wgsl");
/// The shader source of `volume_propagate.wgsl`.
pub const PROPAGATE_WGSL: &str = include_str!("../../shaders/volume_propagate.wgsl");

/// Bindings: 0 uniform params (dynamic offset if `dynamic`), 1 read-only storage, 2 storage
/// (read-only if `b2_read_only`), 3 read-write storage.
fn layout(
    device: &wgpu::Device,
    label: &str,
    dynamic: bool,
    b2_read_only: bool,
) -> wgpu::BindGroupLayout {
    let storage = |binding: u32, read_only: bool| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: dynamic,
                    min_binding_size: None,
                },
                count: None,
            },
            storage(1, true),
            storage(2, b2_read_only),
            storage(3, false),
        ],
    })
}

fn pipeline(
    device: &wgpu::Device,
    source: &str,
    entry: &str,
    layout: &wgpu::BindGroupLayout,
) -> wgpu::ComputePipeline {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(entry),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pl = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(entry),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: Some(&pl),
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    })
}

fn groups(n: u32) -> (u32, u32) {
    let g = n.div_ceil(WORKGROUP);
    let x = g.clamp(1, MAX_GROUPS);
    (x, g.div_ceil(x))
}

fn check_grid(device: &wgpu::Device, dims: [usize; 3], chans: &[Vec<f32>]) -> anyhow::Result<u32> {
    let n = dims.iter().product::<usize>();
    let limit = device.limits().max_storage_buffer_binding_size;
    if (n as u64) * 16 > limit || n >= u32::MAX as usize {
        bail!(
            "grid {dims:?} needs a {}-byte buffer; the device allows {limit}",
            n * 16
        );
    }
    if chans.iter().any(|c| c.len() != n) {
        bail!("every channel must have {n} samples");
    }
    Ok(n as u32)
}

/// Runs `input.sweeps` Jacobi sweeps of `shaders/volume_diffuse.wgsl` and returns the channels.
///
/// # Errors
/// Bad input (channel count or lengths, a grid too large for the device), or a device error.
pub fn diffuse_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    input: &DiffuseInput,
) -> anyhow::Result<Vec<Vec<f32>>> {
    let m = input.channels.len();
    if !(1..=4).contains(&m) || (input.pm.is_some() && m != 3) {
        bail!("diffusion takes 1 to 4 channels (exactly 3 for Perona–Malik), got {m}");
    }
    let n = check_grid(device, input.dims, input.channels)?;
    if input.fixed.len() != n as usize {
        bail!("fixed must have {n} samples");
    }
    let scopes = Scopes::push(device);
    let bgl = layout(device, "volume diffuse", false, true);
    let pipe = pipeline(device, DIFFUSE_WGSL, "sweep", &bgl);
    let params = GpuDiffuseParams {
        nx: input.dims[0] as u32,
        ny: input.dims[1] as u32,
        nz: input.dims[2] as u32,
        mode: u32::from(input.pm.is_some()),
        qk: input.pm.map_or(0.0, |k| 0.25 / k),
        _pad0: 0,
        _pad1: 0,
        _pad2: 0,
    };
    let mut packed = vec![0.0f32; 4 * n as usize];
    for (c, ch) in input.channels.iter().enumerate() {
        for (i, v) in ch.iter().enumerate() {
            packed[4 * i + c] = *v;
        }
    }
    let fixed: Vec<u32> = input.fixed.iter().map(|&f| u32::from(f != 0)).collect();
    let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC;
    let ubuf = upload(
        device,
        queue,
        "diffuse params",
        bytemuck::bytes_of(&params),
        wgpu::BufferUsages::UNIFORM,
    );
    let a = upload(
        device,
        queue,
        "diffuse a",
        bytemuck::cast_slice(&packed),
        storage,
    );
    let b = upload(
        device,
        queue,
        "diffuse b",
        bytemuck::cast_slice(&packed),
        storage,
    );
    let fbuf = upload(
        device,
        queue,
        "fixed",
        bytemuck::cast_slice(&fixed),
        wgpu::BufferUsages::STORAGE,
    );
    let group = |src: &wgpu::Buffer, dst: &wgpu::Buffer| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("volume diffuse"),
            layout: &bgl,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: ubuf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: src.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: fbuf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: dst.as_entire_binding(),
                },
            ],
        })
    };
    let (ab, ba) = (group(&a, &b), group(&b, &a));
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("volume diffuse"),
    });
    let (gx, gy) = groups(n);
    for s in 0..input.sweeps {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: None,
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipe);
        pass.set_bind_group(0, if s.is_multiple_of(2) { &ab } else { &ba }, &[]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
    let result = if input.sweeps.is_multiple_of(2) {
        &a
    } else {
        &b
    };
    let out = readback(device, "volume diffuse readback", u64::from(n) * 16);
    encoder.copy_buffer_to_buffer(result, 0, &out, 0, u64::from(n) * 16);
    let submission = queue.submit([encoder.finish()]);
    let data: Vec<f32> = read_back(device, &out, submission, None, scopes)
        .context("running shaders/volume_diffuse.wgsl")?;
    Ok((0..m)
        .map(|c| (0..n as usize).map(|i| data[4 * i + c]).collect())
        .collect())
}

/// Runs the surface propagation of `shaders/volume_propagate.wgsl`: returns `S` and the layer in
/// which each sample was set (`u32::MAX` where no seed reaches).
///
/// # Errors
/// Bad input lengths, a grid too large for the device, or a device error.
pub fn propagate_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    input: &PropagateInput,
) -> anyhow::Result<(Vec<f32>, Vec<u32>)> {
    let dims = input.grid.dims;
    if input.normal.len() != 3 {
        bail!("normal must have three channels");
    }
    let n = check_grid(device, dims, input.normal)?;
    if input.omega_s.len() != n as usize || input.surface.len() != n as usize {
        bail!("omega_s and surface must have {n} samples");
    }
    let scopes = Scopes::push(device);
    let bgl = layout(device, "volume propagate", true, false);
    let pipe = pipeline(device, PROPAGATE_WGSL, "propagate", &bgl);
    let passes = (dims[0] + dims[1] + dims[2] - 2) as u32;
    let align = u64::from(device.limits().min_uniform_buffer_offset_alignment).max(32);
    let mut uniforms = vec![0u8; (align * u64::from(passes)) as usize];
    for l in 1..=passes {
        let p = GpuPropagateParams {
            nx: dims[0] as u32,
            ny: dims[1] as u32,
            nz: dims[2] as u32,
            layer: l,
            spacing: input.grid.spacing,
            _pad0: 0,
            _pad1: 0,
            _pad2: 0,
        };
        let o = (align * u64::from(l - 1)) as usize;
        uniforms[o..o + 32].copy_from_slice(bytemuck::bytes_of(&p));
    }
    let mut packed = vec![0.0f32; 4 * n as usize];
    for (c, ch) in input.normal.iter().enumerate() {
        for (i, v) in ch.iter().enumerate() {
            packed[4 * i + c] = *v;
        }
    }
    let layers: Vec<u32> = input
        .omega_s
        .iter()
        .map(|&o| if o != 0 { 0 } else { u32::MAX })
        .collect();
    let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC;
    let ubuf = upload(
        device,
        queue,
        "propagate params",
        &uniforms,
        wgpu::BufferUsages::UNIFORM,
    );
    let nbuf = upload(
        device,
        queue,
        "normal",
        bytemuck::cast_slice(&packed),
        wgpu::BufferUsages::STORAGE,
    );
    let lbuf = upload(
        device,
        queue,
        "layer",
        bytemuck::cast_slice(&layers),
        storage,
    );
    let sbuf = upload(
        device,
        queue,
        "surface",
        bytemuck::cast_slice(input.surface),
        storage,
    );
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("volume propagate"),
        layout: &bgl,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &ubuf,
                    offset: 0,
                    size: wgpu::BufferSize::new(32),
                }),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: nbuf.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: lbuf.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: sbuf.as_entire_binding(),
            },
        ],
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("volume propagate"),
    });
    let (gx, gy) = groups(n);
    for l in 0..passes {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: None,
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipe);
        pass.set_bind_group(0, &bind, &[(align * u64::from(l)) as u32]);
        pass.dispatch_workgroups(gx, gy, 1);
    }
    // Both results in one readback: layers, then S.
    let both = readback(device, "volume propagate readback", u64::from(n) * 8);
    encoder.copy_buffer_to_buffer(&lbuf, 0, &both, 0, u64::from(n) * 4);
    encoder.copy_buffer_to_buffer(&sbuf, 0, &both, u64::from(n) * 4, u64::from(n) * 4);
    let submission = queue.submit([encoder.finish()]);
    let words: Vec<u32> = read_back(device, &both, submission, None, scopes)
        .context("running shaders/volume_propagate.wgsl")?;
    let (l, s) = words.split_at(n as usize);
    Ok((s.iter().map(|&b| f32::from_bits(b)).collect(), l.to_vec()))
}
