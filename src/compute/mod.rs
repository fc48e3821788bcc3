//! The compute front door: stages ask here for fields and tiles, and get them from the GPU device
//! task when one is configured and healthy, or from the CPU reference otherwise.
//!
//! CPU work runs on tokio's blocking pool so request handlers never stall the reactor. A GPU job
//! that fails (device lost, validation error, timeout) is recomputed on the CPU and the device is
//! marked lost, so requests never fail because of the device.
//!
//! A tile runs the jobs of [`crate::edits::tile_jobs`] here (device or CPU) and then
//! [`crate::edits::assemble`], the same synthesis as the CPU's [`crate::edits::synthesize`].
//! [`Compute::tile_cached`] puts the [`crate::cache::StageCache`] in front: a tile whose input
//! hash is cached runs no stage; otherwise each stage run is counted there.
//!
//! The other stages with a WGSL twin (the Poisson cycles of authored regions, the volume
//! pipeline's diffusion, propagation and bitangents, surface nets) run inside the pure solvers,
//! which ask the [`Offload`] of [`Compute::offload`] before computing on the CPU.
//!
//! Blocking work runs as a [`work::Work`], counted when it outlives the requests waiting for it.

mod offload;
pub mod work;

pub use offload::Offload;

use crate::cache::{InputHash, Stage, StageCache};
use crate::edits::TileEdits;
pub use crate::gpu::AdapterInfo;
use crate::terrain::tile::Field;
use crate::terrain::{FieldJob, Tile, TileKey, WorldPlan};
use serde::Serialize;
use std::sync::Arc;

/// What `GET /v1/info` reports about the compute backend.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct BackendInfo {
    /// `"cpu"` or `"gpu"`.
    pub backend: String,
    /// Adapter, when a GPU device is in use.
    pub adapter: Option<AdapterInfo>,
    /// Whether the GPU device was lost and work fell back to the CPU.
    pub device_lost: bool,
}

/// Handle to the compute backends; cheap to clone.
#[derive(Clone, Debug, Default)]
pub struct Compute {
    gpu: Option<crate::gpu::GpuHandle>,
}

impl Compute {
    /// CPU only.
    pub fn cpu() -> Self {
        Self { gpu: None }
    }

    /// With a GPU device task.
    pub fn with_gpu(gpu: crate::gpu::GpuHandle) -> Self {
        Self { gpu: Some(gpu) }
    }

    /// Backend report.
    pub fn info(&self) -> BackendInfo {
        match &self.gpu {
            None => BackendInfo {
                backend: "cpu".into(),
                adapter: None,
                device_lost: false,
            },
            Some(g) => BackendInfo {
                backend: if g.is_lost() {
                    "cpu".into()
                } else {
                    "gpu".into()
                },
                adapter: Some(g.adapter_info()),
                device_lost: g.is_lost(),
            },
        }
    }

    /// The offload the pure solvers take: this backend's device while it is healthy, jobs driven
    /// by the current tokio runtime (none outside one: then everything runs on the CPU).
    pub fn offload(&self) -> Offload {
        Offload::new(
            self.gpu.clone().filter(|g| !g.is_lost()),
            tokio::runtime::Handle::try_current().ok(),
        )
    }

    /// The device's job counts by stage and result, when there is a device.
    pub fn device_jobs(&self) -> Option<&crate::gpu::jobs::JobCounts> {
        self.gpu.as_ref().map(|g| g.job_counts())
    }

    /// Heights and weights of a lattice rectangle.
    pub async fn field(&self, plan: Arc<WorldPlan>, job: FieldJob) -> Field {
        if let Some(g) = &self.gpu {
            if !g.is_lost() {
                match g.field(plan.clone(), job).await {
                    Ok(f) => return f,
                    Err(e) => tracing::warn!("GPU job failed, falling back to the CPU: {e}"),
                }
            }
        }
        work::run_to_end(move || crate::terrain::tile::field(&plan, job)).await
    }

    /// A finished tile, with edges snapped to coarser neighbours where `coarser` says so.
    pub async fn tile(&self, plan: Arc<WorldPlan>, key: TileKey, coarser: [bool; 4]) -> Tile {
        self.run_stages(plan, key, coarser, None, TileEdits::default())
            .await
    }

    /// The tile whose input hash is `inputs` ([`crate::scene::SceneInputs::tile`] of the same
    /// plan, key and seams): from `cache` when it holds it (memory, then disk), else computed as
    /// [`Compute::tile`] does, with each stage run counted in `cache`, and kept there.
    /// `edits` yields what the tile applies on top of the field (solved authored regions, cave
    /// breaches); it is awaited only on a miss.
    pub async fn tile_cached<F>(
        &self,
        cache: &StageCache,
        inputs: InputHash,
        plan: Arc<WorldPlan>,
        key: TileKey,
        seams: [bool; 4],
        edits: F,
    ) -> Arc<Tile>
    where
        F: std::future::Future<Output = TileEdits>,
    {
        cache
            .get_or_compute(inputs, || async move {
                let edits = edits.await;
                self.run_stages(plan, key, seams, Some(cache), edits).await
            })
            .await
    }

    async fn run_stages(
        &self,
        plan: Arc<WorldPlan>,
        key: TileKey,
        coarser: [bool; 4],
        counts: Option<&StageCache>,
        edits: TileEdits,
    ) -> Tile {
        let count = |stage, since: std::time::Instant| {
            if let Some(c) = counts {
                c.record_run(stage, since.elapsed());
            }
        };
        let mut fields = Vec::new();
        for (edge, job) in crate::edits::tile_jobs(&plan, key, coarser) {
            let started = std::time::Instant::now();
            let mut f = self.field(plan.clone(), job).await;
            crate::edits::edit_field(&plan, job, &edits, &mut f);
            fields.push((edge, f));
            count(
                if edge.is_none() {
                    Stage::Field
                } else {
                    Stage::Snap
                },
                started,
            );
        }
        let started = std::time::Instant::now();
        let t = work::run_to_end(move || crate::edits::assemble(&plan, key, &fields, &edits)).await;
        count(Stage::Finish, started);
        t
    }
}

/// The result of a blocking task whose result the caller cannot do without.
///
/// A panic in the task goes on unwinding in the caller. A cancelled task is not a panic: tokio
/// cancels blocking tasks only while its runtime shuts down (nothing here aborts their handles),
/// and the runtime then drops every task, the caller included, so the caller waits for that
/// instead of inventing a result.
pub async fn joined<T>(task: tokio::task::JoinHandle<T>) -> T {
    match task.await {
        Ok(t) => t,
        Err(e) if e.is_panic() => std::panic::resume_unwind(e.into_panic()),
        Err(_) => {
            tracing::debug!("blocking task cancelled: the runtime is shutting down");
            std::future::pending().await
        }
    }
}
