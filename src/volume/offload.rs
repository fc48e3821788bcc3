//! The volume pipeline's offload hook (see [`crate::terrain::offload`] for the pattern): the
//! stages with a WGSL twin that production runs ask a [`VolumeOffload`] first and run the CPU
//! reference when it answers `None`.
//!
//! | Method | CPU reference | Twin |
//! |---|---|---|
//! | [`VolumeOffload::pm_sweeps`] | [`super::pipeline::diffuse::sweeps`] with Perona–Malik | `shaders/volume_diffuse.wgsl` |
//! | [`VolumeOffload::propagate_surface`] | [`super::pipeline::propagate::propagate_surface`] | `shaders/volume_propagate.wgsl` |
//! | [`VolumeOffload::smooth_bitangents`] | [`super::pipeline::expand::smooth_bitangents`] | `shaders/volume_bitangent.wgsl` |
//! | [`VolumeOffload::surface_nets`] | [`super::mesh::surface_nets`] (geometry) | `shaders/volume_mesh.wgsl` |
//!
//! The harmonic fills (cascadic multigrid) and the material wavefront have no twin and always
//! run on the CPU.

use super::mesh::{MeshOptions, QuadMesh};
use super::pipeline::Grid;
pub use crate::terrain::offload::CpuOnly;

/// Where the volume pipeline's twinned kernels may run; every method's default is `None` (the
/// CPU reference runs).
pub trait VolumeOffload: Sync {
    /// `sweeps` Perona–Malik sweeps with parameter `k` of the three channels `chans` over a
    /// `dims` grid, `fixed` samples kept: the swept channels.
    fn pm_sweeps(
        &self,
        dims: [usize; 3],
        chans: &[Vec<f32>],
        fixed: &[u8],
        k: f32,
        sweeps: u32,
    ) -> Option<Vec<Vec<f32>>> {
        let _ = (dims, chans, fixed, k, sweeps);
        None
    }

    /// Surface propagation along `normal` from the seeds `surface` in `omega_s`: `S` and the
    /// layer each sample was set in.
    fn propagate_surface(
        &self,
        grid: &Grid,
        normal: &[Vec<f32>; 3],
        omega_s: &[u8],
        surface: &[f32],
    ) -> Option<(Vec<f32>, Vec<u32>)> {
        let _ = (grid, normal, omega_s, surface);
        None
    }

    /// The smooth bitangent field of the sparse bitangents `sparse` after `sweeps` sweeps.
    fn smooth_bitangents(
        &self,
        dims: [usize; 3],
        sparse: &[Vec<f32>; 3],
        sweeps: usize,
    ) -> Option<[Vec<f32>; 3]> {
        let _ = (dims, sparse, sweeps);
        None
    }

    /// The surface-nets geometry of `sdf` (vertices, normals, quads, Ptex adjacency) for a grid
    /// [`super::mesh::surface_nets`] accepts; the caller fills in the vertex attributes.
    fn surface_nets(&self, sdf: &[f32], opts: &MeshOptions) -> Option<QuadMesh> {
        let _ = (sdf, opts);
        None
    }
}

impl VolumeOffload for CpuOnly {}
