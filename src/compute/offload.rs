//! [`Offload`]: the device behind the pure modules' offload hooks
//! ([`crate::terrain::offload::PoissonOffload`], [`crate::volume::offload::VolumeOffload`]).
//!
//! The pure solvers run on tokio's blocking pool (and their rayon workers), so an offload call
//! blocks its thread: it copies the kernel's input into a job for the device task, spawns the
//! job's future on the runtime and waits for it on a standard channel. Any refusal or failure
//! answers `None`, on which the caller runs the CPU reference; a failure also marks the device
//! lost ([`crate::gpu::GpuHandle::run`]), so later calls answer `None` at once.

use crate::gpu::GpuHandle;
use crate::terrain::offload::PoissonOffload;
use crate::terrain::poisson::level::Level;
use crate::terrain::poisson::SolveOptions;
use crate::volume::mesh::{MeshOptions, QuadMesh};
use crate::volume::offload::VolumeOffload;
use crate::volume::pipeline::Grid;
use std::future::Future;

/// The offload of a [`super::Compute`]: its device while that is healthy, else nothing (every
/// kernel on the CPU). Made by [`super::Compute::offload`]; cheap to clone.
#[derive(Clone, Debug, Default)]
pub struct Offload {
    device: Option<(GpuHandle, tokio::runtime::Handle)>,
}

impl Offload {
    /// The offload of `gpu`, whose jobs are driven by the runtime `rt`.
    pub(super) fn new(gpu: Option<GpuHandle>, rt: Option<tokio::runtime::Handle>) -> Self {
        Self {
            device: gpu.zip(rt),
        }
    }

    /// Whether calls may reach a device.
    pub fn has_device(&self) -> bool {
        self.device.as_ref().is_some_and(|(g, _)| !g.is_lost())
    }

    /// Runs the device call `job` to completion from a blocking thread; `None` without a
    /// healthy device or when the job fails (logged).
    fn block<T, F>(&self, what: &str, job: impl FnOnce(GpuHandle) -> F) -> Option<T>
    where
        T: Send + 'static,
        F: Future<Output = anyhow::Result<T>> + Send + 'static,
    {
        let (gpu, rt) = self.device.as_ref()?;
        if gpu.is_lost() {
            return None;
        }
        let fut = job(gpu.clone());
        let (tx, rx) = std::sync::mpsc::sync_channel(1);
        rt.spawn(async move {
            let _ = tx.send(fut.await);
        });
        match rx.recv() {
            Ok(Ok(v)) => Some(v),
            Ok(Err(e)) => {
                tracing::warn!("{what} on the GPU failed, computing it on the CPU: {e:#}");
                None
            }
            Err(_) => None,
        }
    }
}

impl PoissonOffload for Offload {
    fn has_device(&self) -> bool {
        Offload::has_device(self)
    }

    fn poisson_cycles(
        &self,
        levels: &[Level],
        cycles: usize,
        options: &SolveOptions,
    ) -> Option<[Vec<f32>; 2]> {
        let (levels, options) = (levels.to_vec(), *options);
        self.block("Poisson cycles", move |g| async move {
            g.poisson_cycles(levels, cycles, options).await
        })
    }
}

impl VolumeOffload for Offload {
    fn pm_sweeps(
        &self,
        dims: [usize; 3],
        chans: &[Vec<f32>],
        fixed: &[u8],
        k: f32,
        sweeps: u32,
    ) -> Option<Vec<Vec<f32>>> {
        let (chans, fixed) = (chans.to_vec(), fixed.to_vec());
        self.block("Perona–Malik diffusion", move |g| async move {
            g.pm_sweeps(dims, chans, fixed, k, sweeps).await
        })
    }

    fn propagate_surface(
        &self,
        grid: &Grid,
        normal: &[Vec<f32>; 3],
        omega_s: &[u8],
        surface: &[f32],
    ) -> Option<(Vec<f32>, Vec<u32>)> {
        let (grid, normal) = (*grid, normal.to_vec());
        let (omega_s, surface) = (omega_s.to_vec(), surface.to_vec());
        self.block("surface propagation", move |g| async move {
            g.propagate_surface(grid, normal, omega_s, surface).await
        })
    }

    fn smooth_bitangents(
        &self,
        dims: [usize; 3],
        sparse: &[Vec<f32>; 3],
        sweeps: usize,
    ) -> Option<[Vec<f32>; 3]> {
        let sparse = sparse.clone();
        self.block("smooth bitangents", move |g| async move {
            g.smooth_bitangents(dims, sparse, sweeps).await
        })
    }

    fn surface_nets(&self, sdf: &[f32], opts: &MeshOptions) -> Option<QuadMesh> {
        let (sdf, opts) = (sdf.to_vec(), *opts);
        self.block("surface nets", move |g| async move {
            g.surface_nets(sdf, opts).await
        })
    }
}
