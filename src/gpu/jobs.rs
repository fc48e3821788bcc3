//! The device's stage jobs beside the field: one [`GpuHandle`] method per WGSL twin that
//! production runs (Poisson cycles, Perona–Malik diffusion, surface propagation, smooth
//! bitangents, surface nets), and the per-stage job counts `/metrics` reports.
//!
//! Each method checks its input against the kernel's limits before sending it (a refusal is
//! counted as `skipped` and leaves the device healthy), copies what the kernel reads into the
//! job (a job outlives no borrow: it runs on the device thread) and runs it with
//! [`GpuHandle::run`], so a failure marks the device lost and the caller computes on the CPU.

use super::device::GpuHandle;
use super::poisson::MAX_BUFFER_BYTES as POISSON_BUFFER_BYTES;
use super::tile::MAX_BUFFER_BYTES;
use super::volume::{diffuse_on_device, propagate_on_device, DiffuseInput, PropagateInput};
use super::volume_bitangent::smooth_bitangents_on_device;
use super::volume_mesh::MAX_BUFFER_BYTES as MESH_BUFFER_BYTES;
use crate::terrain::poisson::level::Level;
use crate::terrain::poisson::SolveOptions;
use crate::volume::mesh::{MeshOptions, QuadMesh, MAX_SAMPLES};
use crate::volume::pipeline::Grid;
use anyhow::anyhow;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// How long a stage job other than the field may run once started: the volume and Poisson
/// kernels take seconds on a software adapter for the largest grids the scene allows.
pub const STAGE_JOB_TIMEOUT: Duration = Duration::from_secs(120);

/// A stage that has a WGSL twin, as `/metrics` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeviceStage {
    /// Heights and weights of a lattice rectangle (`shaders/tile.wgsl`, `shaders/earth.wgsl`).
    Field,
    /// Finest-level multigrid cycles of an authored region's solve (`shaders/poisson.wgsl`).
    Poisson,
    /// Perona–Malik sweeps of a volume region's normals (`shaders/volume_diffuse.wgsl`).
    Diffusion,
    /// Surface propagation of a volume region (`shaders/volume_propagate.wgsl`).
    Propagation,
    /// The smooth bitangent field of a curve expansion (`shaders/volume_bitangent.wgsl`).
    Bitangents,
    /// Surface nets of a volume chunk or region (`shaders/volume_mesh.wgsl`).
    Meshing,
}

impl DeviceStage {
    /// Every stage, in `/metrics` order.
    pub const ALL: [DeviceStage; 6] = [
        DeviceStage::Field,
        DeviceStage::Poisson,
        DeviceStage::Diffusion,
        DeviceStage::Propagation,
        DeviceStage::Bitangents,
        DeviceStage::Meshing,
    ];

    /// The `stage` label.
    pub fn name(self) -> &'static str {
        match self {
            DeviceStage::Field => "field",
            DeviceStage::Poisson => "poisson",
            DeviceStage::Diffusion => "diffusion",
            DeviceStage::Propagation => "propagation",
            DeviceStage::Bitangents => "bitangents",
            DeviceStage::Meshing => "meshing",
        }
    }
}

/// What became of a job sent for the device.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JobResult {
    /// It ran on the device and its result was used.
    Device,
    /// It failed on the device (which is then lost); the CPU computed it.
    Failed,
    /// It was not sent: the device was lost already or the input exceeds the kernel's limits.
    Skipped,
}

impl JobResult {
    /// Every result, in `/metrics` order.
    pub const ALL: [JobResult; 3] = [JobResult::Device, JobResult::Failed, JobResult::Skipped];

    /// The `result` label.
    pub fn name(self) -> &'static str {
        match self {
            JobResult::Device => "device",
            JobResult::Failed => "failed",
            JobResult::Skipped => "skipped",
        }
    }
}

/// Job counts by stage and result since the device was opened.
#[derive(Debug, Default)]
pub struct JobCounts([[AtomicU64; 3]; 6]);

impl JobCounts {
    pub(super) fn count(&self, stage: DeviceStage, result: JobResult) {
        self.0[stage as usize][result as usize].fetch_add(1, Ordering::Relaxed);
    }

    /// The count of `stage` jobs that ended as `result`.
    pub fn get(&self, stage: DeviceStage, result: JobResult) -> u64 {
        self.0[stage as usize][result as usize].load(Ordering::Relaxed)
    }
}

/// Whether a volume grid of `dims` fits the `vec4` storage buffers the volume kernels bind.
fn volume_grid(dims: [usize; 3]) -> anyhow::Result<()> {
    let n = dims
        .iter()
        .try_fold(1usize, |a, &d| a.checked_mul(d))
        .unwrap_or(usize::MAX);
    if n == 0 || (n as u64).saturating_mul(16) > MAX_BUFFER_BYTES || n >= u32::MAX as usize {
        return Err(anyhow!(
            "a volume grid of {dims:?} exceeds the device's {MAX_BUFFER_BYTES}-byte buffers"
        ));
    }
    Ok(())
}

impl GpuHandle {
    /// Job counts by stage and result.
    pub fn job_counts(&self) -> &JobCounts {
        &self.jobs
    }

    /// `cycles` finest-level cycles of [`super::poisson::PoissonKernels::solve`] from the state
    /// of `levels` (a loaded [`crate::terrain::poisson::Solver`]'s hierarchy): the finest
    /// unknowns as two colour arrays.
    ///
    /// # Errors
    /// As [`GpuHandle::run`]; skipped when a level exceeds the kernels' buffers.
    pub async fn poisson_cycles(
        &self,
        levels: Vec<Level>,
        cycles: usize,
        options: SolveOptions,
    ) -> anyhow::Result<[Vec<f32>; 2]> {
        let bytes = levels
            .first()
            .map_or(u64::MAX, |l| 8 * l.split.len() as u64);
        if bytes > POISSON_BUFFER_BYTES {
            return self.refuse(
                DeviceStage::Poisson,
                anyhow!("the Poisson hierarchy exceeds the device's buffers"),
            );
        }
        self.run(DeviceStage::Poisson, STAGE_JOB_TIMEOUT, move |ctx| {
            ctx.poisson()?
                .solve(&ctx.device, &ctx.queue, &levels, cycles, &options)
        })
        .await
    }

    /// `sweeps` Perona–Malik sweeps with parameter `k` of the three-channel field `chans`
    /// ([`diffuse_on_device`], the twin of [`crate::volume::pipeline::diffuse::sweeps`]).
    ///
    /// # Errors
    /// As [`GpuHandle::run`]; skipped when the grid exceeds the device's buffers.
    pub async fn pm_sweeps(
        &self,
        dims: [usize; 3],
        chans: Vec<Vec<f32>>,
        fixed: Vec<u8>,
        k: f32,
        sweeps: u32,
    ) -> anyhow::Result<Vec<Vec<f32>>> {
        if let Err(e) = volume_grid(dims) {
            return self.refuse(DeviceStage::Diffusion, e);
        }
        self.run(DeviceStage::Diffusion, STAGE_JOB_TIMEOUT, move |ctx| {
            let input = DiffuseInput {
                dims,
                channels: &chans,
                fixed: &fixed,
                pm: Some(k),
                sweeps,
            };
            diffuse_on_device(&ctx.device, &ctx.queue, &input)
        })
        .await
    }

    /// Surface propagation of the seeds `surface` in `omega_s` along `normal`
    /// ([`propagate_on_device`], the twin of
    /// [`crate::volume::pipeline::propagate::propagate_surface`]): `S` and its layers.
    ///
    /// # Errors
    /// As [`GpuHandle::run`]; skipped when the grid exceeds the device's buffers.
    pub async fn propagate_surface(
        &self,
        grid: Grid,
        normal: Vec<Vec<f32>>,
        omega_s: Vec<u8>,
        surface: Vec<f32>,
    ) -> anyhow::Result<(Vec<f32>, Vec<u32>)> {
        if let Err(e) = volume_grid(grid.dims) {
            return self.refuse(DeviceStage::Propagation, e);
        }
        self.run(DeviceStage::Propagation, STAGE_JOB_TIMEOUT, move |ctx| {
            let input = PropagateInput {
                grid: &grid,
                normal: &normal,
                omega_s: &omega_s,
                surface: &surface,
            };
            propagate_on_device(&ctx.device, &ctx.queue, &input)
        })
        .await
    }

    /// The smooth bitangent field of `sparse` after `sweeps` sweeps
    /// ([`smooth_bitangents_on_device`], the twin of
    /// [`crate::volume::pipeline::expand::smooth_bitangents`]).
    ///
    /// # Errors
    /// As [`GpuHandle::run`]; skipped when the grid exceeds the device's buffers.
    pub async fn smooth_bitangents(
        &self,
        dims: [usize; 3],
        sparse: [Vec<f32>; 3],
        sweeps: usize,
    ) -> anyhow::Result<[Vec<f32>; 3]> {
        if let Err(e) = volume_grid(dims) {
            return self.refuse(DeviceStage::Bitangents, e);
        }
        self.run(DeviceStage::Bitangents, STAGE_JOB_TIMEOUT, move |ctx| {
            smooth_bitangents_on_device(&ctx.device, &ctx.queue, dims, &sparse, sweeps)
        })
        .await
    }

    /// The surface-nets geometry of `sdf` ([`super::volume_mesh::VolumeMeshKernel::mesh`]):
    /// vertices carry material 0 and zero noise, which the caller fills in.
    ///
    /// # Errors
    /// As [`GpuHandle::run`]; skipped when the grid is not one the kernel takes.
    pub async fn surface_nets(&self, sdf: Vec<f32>, opts: MeshOptions) -> anyhow::Result<QuadMesh> {
        let [nx, ny, nz] = opts.dims;
        let cells = (nx.max(1) - 1) as u64 * (ny.max(1) - 1) as u64 * (nz.max(1) - 1) as u64;
        let samples = nx.saturating_mul(ny).saturating_mul(nz);
        if opts.dims.iter().any(|&d| d < 2)
            || samples > MAX_SAMPLES
            || sdf.len() != samples
            || cells.saturating_mul(16) > MESH_BUFFER_BYTES
        {
            return self.refuse(
                DeviceStage::Meshing,
                anyhow!(
                    "a mesh grid of {:?} is not one the device kernel takes",
                    opts.dims
                ),
            );
        }
        self.run(DeviceStage::Meshing, STAGE_JOB_TIMEOUT, move |ctx| {
            let mut out = QuadMesh::default();
            ctx.mesh()?.mesh(
                &ctx.device,
                &ctx.queue,
                &sdf,
                &opts,
                &mut out,
                Some(STAGE_JOB_TIMEOUT),
            )?;
            Ok(out)
        })
        .await
    }
}
