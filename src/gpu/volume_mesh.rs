//! WGSL twin of surface-nets meshing (`shaders/volume_mesh.wgsl`, Becher et al. §4.6).
//!
//! One dispatch, one invocation per cell, computes what [`crate::volume::mesh::surface_nets`]
//! computes per cell: the corner sign mask, the vertex offset, the normal and the quad flags of
//! the three grid edges leaving the cell's minimum corner. The host then compacts the cells in
//! index order, which is the CPU's emission order, into a [`QuadMesh`] (vertex positions from the
//! offsets, quads from the flags) and runs the same Ptex adjacency pass
//! ([`crate::volume::mesh::ptex`]). Per-sample attributes (materials, noise parameters) are not
//! uploaded: the twin covers the geometry, and its vertices carry material 0 and zero noise.
//!
//! # Tolerance
//!
//! The vertex and quad sets depend only on signs (`S < 0`) and are identical. Offsets and normals
//! use the same operations in the same order, but WGSL lets the compiler contract `a·b + c` into
//! a fused multiply-add and allows 2.5 ULP for `/` and `sqrt`, so `tests/gpu_volume_mesh.rs`
//! accepts 1e-5 cell units on offsets and 1e-5 on normal components (a few ULP of values of
//! magnitude ≤ 1, far below anything visible) and reports how many are bit-identical.

use super::kit::{
    bind_group, dispatch_linear, read_back, readback, storage, upload, Binding, Program,
};
use super::scopes::Scopes;
use crate::volume::mesh::{nets, MeshError, MeshOptions, QuadClass, QuadMesh, MAX_SAMPLES, NONE};
use anyhow::{bail, Context};
use bytemuck::{Pod, Zeroable};
use std::time::Duration;

/// `shaders/volume_mesh.wgsl`.
pub const VOLUME_MESH_WGSL: &str = include_str!("../../shaders/volume_mesh.wgsl");
/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// Largest per-cell output buffer (WebGPU's default storage binding limit).
pub const MAX_BUFFER_BYTES: u64 = 128 << 20;

/// `MeshParams` of the shader, field for field.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuMeshParams {
    /// Samples along x.
    pub nx: u32,
    /// Samples along y.
    pub ny: u32,
    /// Samples along z.
    pub nz: u32,
    /// Sample spacing, metres (unused by the kernel; offsets are in cell units).
    pub spacing_m: f32,
    /// Quad range minimum, x.
    pub qmin_x: u32,
    /// Quad range minimum, y.
    pub qmin_y: u32,
    /// Quad range minimum, z.
    pub qmin_z: u32,
    /// Padding.
    pub _pad0: u32,
    /// Quad range end (exclusive), x.
    pub qmax_x: u32,
    /// Quad range end, y.
    pub qmax_y: u32,
    /// Quad range end, z.
    pub qmax_z: u32,
    /// Padding.
    pub _pad1: u32,
}

/// The compiled meshing pipeline for one device.
#[derive(Debug)]
pub struct VolumeMeshKernel {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::ComputePipeline,
}

impl VolumeMeshKernel {
    /// Compiles `volume_mesh.wgsl`.
    ///
    /// # Errors
    /// If shader compilation or pipeline creation reports an error.
    pub fn new(device: &wgpu::Device) -> anyhow::Result<Self> {
        let scopes = Scopes::push(device);
        let (r, w) = (Binding::Read, Binding::ReadWrite);
        let program = Program::new(
            device,
            "strata volume_mesh.wgsl",
            VOLUME_MESH_WGSL,
            &[Binding::Uniform, r, w, w, w],
        );
        let pipeline = program.pipeline(device, "mesh_cells");
        scopes.pop().context("compiling shaders/volume_mesh.wgsl")?;
        let layout = program.layout;
        Ok(Self { layout, pipeline })
    }

    /// Meshes `sdf` on the device into `out` (same contract as
    /// [`crate::volume::mesh::surface_nets`] without attributes).
    ///
    /// # Errors
    /// Bad grids as the CPU reports them, grids whose per-cell outputs exceed
    /// [`MAX_BUFFER_BYTES`], and device errors, time-outs or failed mappings.
    pub fn mesh(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        sdf: &[f32],
        opts: &MeshOptions,
        out: &mut QuadMesh,
        timeout: Option<Duration>,
    ) -> anyhow::Result<()> {
        let [nx, ny, nz] = opts.dims;
        if opts.dims.iter().any(|&d| d < 2) || nx * ny * nz > MAX_SAMPLES {
            return Err(MeshError::BadDims(opts.dims).into());
        }
        if sdf.len() != nx * ny * nz {
            return Err(MeshError::Length {
                field: "sdf",
                got: sdf.len(),
                want: nx * ny * nz,
            }
            .into());
        }
        let cells = (nx - 1) * (ny - 1) * (nz - 1);
        if cells as u64 * 16 > MAX_BUFFER_BYTES {
            bail!("{cells} cells need more than {MAX_BUFFER_BYTES} bytes of output");
        }
        let params = GpuMeshParams {
            nx: nx as u32,
            ny: ny as u32,
            nz: nz as u32,
            spacing_m: opts.spacing_m,
            qmin_x: opts.quad_min[0],
            qmin_y: opts.quad_min[1],
            qmin_z: opts.quad_min[2],
            _pad0: 0,
            qmax_x: opts.quad_max[0],
            qmax_y: opts.quad_max[1],
            qmax_z: opts.quad_max[2],
            _pad1: 0,
        };
        let scopes = Scopes::push(device);
        let params_buf = upload(
            device,
            queue,
            "mesh params",
            bytemuck::bytes_of(&params),
            wgpu::BufferUsages::UNIFORM,
        );
        let sdf_buf = upload(
            device,
            queue,
            "sdf",
            bytemuck::cast_slice(sdf),
            wgpu::BufferUsages::STORAGE,
        );
        let output =
            |label: &str, bytes: u64| storage(device, label, bytes, wgpu::BufferUsages::COPY_SRC);
        let n = cells as u64;
        let vbuf = output("vertex_out", 16 * n);
        let nbuf = output("normal_out", 16 * n);
        let fbuf = output("flags_out", 4 * n);
        let readback = readback(device, "mesh readback", 36 * n);
        let bind = bind_group(
            device,
            &self.layout,
            "strata volume mesh job",
            &[&params_buf, &sdf_buf, &vbuf, &nbuf, &fbuf],
        );
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("strata volume mesh"),
        });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: None,
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind, &[]);
            dispatch_linear(&mut pass, cells as u32, WORKGROUP);
        }
        encoder.copy_buffer_to_buffer(&vbuf, 0, &readback, 0, 16 * n);
        encoder.copy_buffer_to_buffer(&nbuf, 0, &readback, 16 * n, 16 * n);
        encoder.copy_buffer_to_buffer(&fbuf, 0, &readback, 32 * n, 4 * n);
        let submission = queue.submit([encoder.finish()]);
        let data: Vec<u32> = read_back(device, &readback, submission, timeout, scopes)?;
        let (verts, rest) = data.split_at(4 * cells);
        let (normals, flags) = rest.split_at(4 * cells);
        compact(opts, verts, normals, flags, out);
        Ok(())
    }
}

/// Builds the mesh from the per-cell outputs in cell order (the CPU's emission order).
fn compact(opts: &MeshOptions, verts: &[u32], normals: &[u32], flags: &[u32], out: &mut QuadMesh) {
    let [nx, ny, _] = opts.dims;
    let (cnx, cny) = (nx - 1, ny - 1);
    let spacing = opts.spacing_m as f64;
    out.clear();
    let mut vertex_of = vec![NONE; flags.len()];
    for (c, &fl) in flags.iter().enumerate() {
        let mask = fl & 0xff;
        if mask == 0 || mask == 0xff {
            continue;
        }
        let cell = [c % cnx, (c / cnx) % cny, c / (cnx * cny)];
        let f: [f32; 3] = std::array::from_fn(|k| f32::from_bits(verts[4 * c + k]));
        let nrm: [f32; 3] = std::array::from_fn(|k| f32::from_bits(normals[4 * c + k]));
        vertex_of[c] = out.positions.len() as u32;
        out.cells.push(cell.map(|v| v as u32));
        out.offsets.push(f);
        out.positions.push(std::array::from_fn(|k| {
            ((cell[k] as f64 + f[k] as f64) * spacing) as f32
        }));
        out.normals.push(nrm);
        out.materials.push(0);
        out.noise.push([0.0; 4]);
        out.slots.push([NONE; 12]);
        out.masks.push(mask as u8);
        let at = |x: usize, y: usize, z: usize| vertex_of[x + cnx * (y + cny * z)];
        let [cx, cy, cz] = cell;
        let p = [cx as u32, cy as u32, cz as u32];
        let vi = vertex_of[c];
        for axis in 0..3 {
            let bits = (fl >> (8 + 2 * axis)) & 3;
            if bits & 1 == 0 {
                continue;
            }
            let quad = match axis {
                0 => [
                    at(cx, cy - 1, cz - 1),
                    at(cx, cy, cz - 1),
                    vi,
                    at(cx, cy - 1, cz),
                ],
                1 => [
                    at(cx - 1, cy, cz - 1),
                    at(cx - 1, cy, cz),
                    vi,
                    at(cx, cy, cz - 1),
                ],
                _ => [
                    at(cx - 1, cy - 1, cz),
                    at(cx, cy - 1, cz),
                    vi,
                    at(cx - 1, cy, cz),
                ],
            };
            nets::push_quad(out, axis, bits & 2 != 0, quad, p);
        }
    }
    crate::volume::mesh::ptex::adjacency(out);
    debug_assert!(out.classes.iter().all(|c| QuadClass::ALL.contains(c)));
}
