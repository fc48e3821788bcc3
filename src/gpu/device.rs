//! The device task: one dedicated thread owns the wgpu `Device` and `Queue`.
//!
//! A thread rather than a tokio task because wgpu's error scopes are per thread and `Device::poll`
//! blocks. [`GpuHandle`]s (cheap clones) send jobs over a bounded `tokio::sync::mpsc` channel and
//! await the reply on a `oneshot`, so async callers never block the reactor.
//!
//! Loss detection: the device-lost callback, an error caught by a job's error scopes, an
//! uncaptured error, a failed mapping, a panic inside wgpu, a submission that does not finish
//! within the job timeout, or a reply that does not arrive within it all set the shared lost flag.
//! From then on [`GpuHandle::field`] returns `Err` at once, and `compute::Compute` computes
//! on the CPU.

use super::earth::EarthKernels;
use super::tile::{TileKernels, DEFAULT_JOB_TIMEOUT, MAX_BUFFER_BYTES};
use crate::terrain::tile::{Field, FieldJob};
use crate::terrain::WorldPlan;
use anyhow::{anyhow, bail};
use clap::ValueEnum;
use serde::Serialize;
use std::fmt;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::{mpsc, oneshot};

/// Which compute backend to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BackendChoice {
    /// A hardware GPU if there is one, else the CPU path.
    Auto,
    /// The CPU reference path only.
    Cpu,
    /// A wgpu device, software adapters (lavapipe, llvmpipe) included; fails without one.
    Gpu,
}

/// The wgpu adapter in use.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AdapterInfo {
    /// Adapter name, e.g. `"llvmpipe (LLVM 15.0.6, 256 bits)"`.
    pub name: String,
    /// Graphics API, e.g. `"Vulkan"`.
    pub backend: String,
    /// `"DiscreteGpu"`, `"IntegratedGpu"`, `"VirtualGpu"`, `"Cpu"` or `"Other"`.
    pub device_type: String,
}

/// Jobs that may wait in the channel before senders wait for room.
const QUEUE_DEPTH: usize = 32;
/// How often a job waiting in the queue checks whether the device was declared lost meanwhile.
const QUEUE_POLL: Duration = Duration::from_millis(50);

/// Storage buffers one kernel binds (`shaders/tile.wgsl`, bindings 1–8).
const STORAGE_BUFFERS: u32 = 8;

enum Job {
    Field {
        plan: Arc<WorldPlan>,
        job: FieldJob,
        started: oneshot::Sender<()>,
        reply: oneshot::Sender<anyhow::Result<Field>>,
    },
    Destroy,
}

/// Handle to the device task; cheap to clone. The task ends when the last handle is dropped.
#[derive(Clone)]
pub struct GpuHandle {
    tx: mpsc::Sender<Job>,
    lost: Arc<AtomicBool>,
    info: Arc<AdapterInfo>,
    timeout: Duration,
}

impl fmt::Debug for GpuHandle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("GpuHandle")
            .field("adapter", &*self.info)
            .field("lost", &self.is_lost())
            .field("timeout", &self.timeout)
            .finish()
    }
}

impl GpuHandle {
    /// Opens the device task for a backend choice: [`open`].
    ///
    /// # Errors
    /// As [`open`].
    pub async fn open(choice: BackendChoice) -> anyhow::Result<Option<GpuHandle>> {
        open(choice).await
    }

    /// Whether the device was lost (work then falls back to the CPU).
    pub fn is_lost(&self) -> bool {
        self.lost.load(Ordering::Acquire)
    }

    fn mark_lost(&self) {
        self.lost.store(true, Ordering::Release);
    }

    /// The adapter in use.
    pub fn adapter_info(&self) -> AdapterInfo {
        (*self.info).clone()
    }

    /// The per-job timeout.
    pub fn job_timeout(&self) -> Duration {
        self.timeout
    }

    /// Computes a field on the device: [`EarthKernels::field`] for an `earth-1` world,
    /// [`TileKernels::field`] for a classic one.
    ///
    /// # Errors
    /// At once if the device is lost or the job is out of range (see
    /// [`super::earth::earth_params`] and [`super::tile::field_params`]; this does not mark the
    /// device lost); otherwise if the job fails on the device or takes longer than the job
    /// timeout once started, which marks the device lost.
    pub async fn field(&self, plan: Arc<WorldPlan>, job: FieldJob) -> anyhow::Result<Field> {
        if self.is_lost() {
            bail!("GPU device lost");
        }
        check_job(&plan, job)?;
        let (started_tx, mut started_rx) = oneshot::channel();
        let (reply_tx, reply_rx) = oneshot::channel();
        let job = Job::Field {
            plan,
            job,
            started: started_tx,
            reply: reply_tx,
        };
        if self.tx.send(job).await.is_err() {
            self.mark_lost();
            bail!("GPU device task has stopped");
        }
        // Queue time does not count against the timeout; a stuck device is caught by the job that
        // is running on it, which marks the device lost and releases every waiter here.
        loop {
            tokio::select! {
                started = &mut started_rx => {
                    if started.is_err() {
                        self.mark_lost();
                        bail!("GPU device task dropped the job");
                    }
                    break;
                }
                _ = tokio::time::sleep(QUEUE_POLL) => {
                    if self.is_lost() {
                        bail!("GPU device lost while the job was queued");
                    }
                }
            }
        }
        match tokio::time::timeout(self.timeout, reply_rx).await {
            Ok(Ok(result)) => result,
            Ok(Err(_)) => {
                self.mark_lost();
                bail!("GPU device task dropped the job")
            }
            Err(_) => {
                self.mark_lost();
                bail!("GPU job timed out after {:?}", self.timeout)
            }
        }
    }

    /// Test hook: destroys the device (`Device::destroy`) inside the device task, after the jobs
    /// already queued. The lost flag is not set here: the next job runs on the destroyed device,
    /// fails for real (its result cannot be mapped), and that failure sets the flag. If the queue
    /// is full the flag is set directly.
    pub fn simulate_device_loss(&self) {
        if self.tx.try_send(Job::Destroy).is_err() {
            self.mark_lost();
        }
    }
}

/// Whether the kernels of `plan`'s generator can run `job` ([`super::earth::earth_params`] or
/// [`super::tile::field_params`]).
fn check_job(plan: &WorldPlan, job: FieldJob) -> anyhow::Result<()> {
    if plan.earth.is_some() {
        super::earth::earth_params(plan, job).map(|_| ())
    } else {
        super::tile::field_params(plan, job).map(|_| ())
    }
}

/// Opens the compute device for a backend choice, with the default job timeout.
///
/// - with [`BackendChoice::Cpu`], `Ok(None)`;
/// - with [`BackendChoice::Auto`], a hardware adapter (discrete, integrated or virtual GPU), or
///   `Ok(None)` when there is none, so the server uses the CPU path;
/// - with [`BackendChoice::Gpu`], the best adapter of any kind, software rasterisers (lavapipe,
///   llvmpipe) included; `Err` if there is none.
///
/// # Errors
/// With [`BackendChoice::Gpu`] and no usable adapter, or when the chosen adapter fails to create
/// a device or compile the kernels.
pub async fn open(choice: BackendChoice) -> anyhow::Result<Option<GpuHandle>> {
    open_with_timeout(choice, DEFAULT_JOB_TIMEOUT).await
}

/// [`open`] with a per-job timeout.
///
/// # Errors
/// As [`open`].
pub async fn open_with_timeout(
    choice: BackendChoice,
    timeout: Duration,
) -> anyhow::Result<Option<GpuHandle>> {
    if choice == BackendChoice::Cpu {
        return Ok(None);
    }
    let (ready_tx, ready_rx) = oneshot::channel();
    let (tx, rx) = mpsc::channel(QUEUE_DEPTH);
    let lost = Arc::new(AtomicBool::new(false));
    let thread_lost = lost.clone();
    std::thread::Builder::new()
        .name("strata-gpu".into())
        .spawn(move || device_thread(choice, timeout, ready_tx, rx, thread_lost))?;
    match ready_rx.await {
        Ok(Ok(Some(info))) => Ok(Some(GpuHandle {
            tx,
            lost,
            info: Arc::new(info),
            timeout,
        })),
        Ok(Ok(None)) => Ok(None),
        Ok(Err(e)) => Err(e),
        Err(_) => bail!("GPU device thread died while opening the device"),
    }
}

/// The adapter's description in the form `GET /v1/info` reports.
pub fn adapter_info_of(info: &wgpu::AdapterInfo) -> AdapterInfo {
    AdapterInfo {
        name: info.name.clone(),
        backend: format!("{:?}", info.backend),
        device_type: format!("{:?}", info.device_type),
    }
}

/// Rank of an adapter for a backend choice, lower is better; `None` if the choice excludes it.
///
/// Hardware comes first (discrete, integrated, virtual), then software (`Cpu`, e.g. lavapipe),
/// then `Other`; within a kind a native API comes before GL. `Auto` takes hardware only.
pub fn adapter_rank(
    choice: BackendChoice,
    device_type: wgpu::DeviceType,
    backend: wgpu::Backend,
) -> Option<u32> {
    use wgpu::DeviceType as T;
    let kind = match device_type {
        T::DiscreteGpu => 0,
        T::IntegratedGpu => 1,
        T::VirtualGpu => 2,
        T::Cpu => 3,
        T::Other => 4,
    };
    let allowed = match choice {
        BackendChoice::Cpu => false,
        BackendChoice::Auto => kind <= 2,
        BackendChoice::Gpu => true,
    };
    let api = u32::from(backend == wgpu::Backend::Gl);
    allowed.then_some(kind * 2 + api)
}

/// Creates a device and queue on the best adapter for `choice` (see [`adapter_rank`]), with the
/// limits the tile kernels need. Also what the tests use to get a device.
///
/// # Errors
/// With [`BackendChoice::Gpu`] and no usable adapter, or if the device cannot be created.
pub async fn request_device(
    choice: BackendChoice,
) -> anyhow::Result<Option<(wgpu::Adapter, wgpu::Device, wgpu::Queue)>> {
    if choice == BackendChoice::Cpu {
        return Ok(None);
    }
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapters = instance.enumerate_adapters(wgpu::Backends::all()).await;
    let mut seen = Vec::new();
    let mut best: Option<(u32, wgpu::Adapter)> = None;
    for adapter in adapters {
        let info = adapter.get_info();
        seen.push(format!(
            "{} ({:?}, {:?})",
            info.name, info.backend, info.device_type
        ));
        let compute = adapter
            .get_downlevel_capabilities()
            .flags
            .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS);
        let limits = adapter.limits();
        if !compute
            || limits.max_storage_buffers_per_shader_stage < STORAGE_BUFFERS
            || limits.max_storage_buffer_binding_size < MAX_BUFFER_BYTES
        {
            continue;
        }
        if let Some(rank) = adapter_rank(choice, info.device_type, info.backend) {
            if best.as_ref().is_none_or(|(r, _)| rank < *r) {
                best = Some((rank, adapter));
            }
        }
    }
    let Some((_, adapter)) = best else {
        return match choice {
            BackendChoice::Gpu => Err(anyhow!(
                "--backend gpu: no wgpu adapter with compute shaders (found: {})",
                if seen.is_empty() {
                    "none".to_string()
                } else {
                    seen.join(", ")
                }
            )),
            _ => Ok(None),
        };
    };
    let required_limits = wgpu::Limits {
        max_storage_buffers_per_shader_stage: STORAGE_BUFFERS,
        max_storage_buffer_binding_size: MAX_BUFFER_BYTES,
        ..wgpu::Limits::downlevel_defaults()
    };
    let (device, queue) = adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("strata compute"),
            required_limits,
            ..Default::default()
        })
        .await
        .map_err(|e| anyhow!("creating a device on {}: {e}", adapter.get_info().name))?;
    Ok(Some((adapter, device, queue)))
}

fn device_thread(
    choice: BackendChoice,
    timeout: Duration,
    ready: oneshot::Sender<anyhow::Result<Option<AdapterInfo>>>,
    mut rx: mpsc::Receiver<Job>,
    lost: Arc<AtomicBool>,
) {
    let opened = pollster::block_on(request_device(choice)).and_then(|opened| {
        opened
            .map(|(adapter, device, queue)| {
                let kernels = (TileKernels::new(&device)?, EarthKernels::new(&device)?);
                Ok((adapter_info_of(&adapter.get_info()), device, queue, kernels))
            })
            .transpose()
    });
    let (info, device, queue, (kernels, earth_kernels)) = match opened {
        Ok(Some(opened)) => opened,
        Ok(None) => {
            let _ = ready.send(Ok(None));
            return;
        }
        Err(e) => {
            let _ = ready.send(Err(e));
            return;
        }
    };
    let flag = lost.clone();
    device.set_device_lost_callback(move |reason, message| {
        // `Destroyed` only follows our own `destroy()` (the test hook), whose effect the next job
        // must detect by failing; every other reason is a real loss.
        if reason != wgpu::DeviceLostReason::Destroyed {
            tracing::error!("GPU device lost ({reason:?}): {message}");
            flag.store(true, Ordering::Release);
        }
    });
    let flag = lost.clone();
    device.on_uncaptured_error(Arc::new(move |e| {
        tracing::error!("uncaptured wgpu error, marking the device lost: {e}");
        flag.store(true, Ordering::Release);
    }));
    tracing::info!(
        "GPU device: {} ({}, {})",
        info.name,
        info.backend,
        info.device_type
    );
    if ready.send(Ok(Some(info))).is_err() {
        return;
    }
    while let Some(job) = rx.blocking_recv() {
        match job {
            Job::Field {
                plan,
                job,
                started,
                reply,
            } => {
                let _ = started.send(());
                if lost.load(Ordering::Acquire) {
                    let _ = reply.send(Err(anyhow!("GPU device lost")));
                    continue;
                }
                let run = catch_unwind(AssertUnwindSafe(|| {
                    if plan.earth.is_some() {
                        earth_kernels.field(&device, &queue, &plan, job, Some(timeout))
                    } else {
                        kernels.field(&device, &queue, &plan, job, Some(timeout))
                    }
                }));
                let result = match run {
                    Ok(result) => result,
                    Err(panic) => {
                        let msg = panic
                            .downcast_ref::<String>()
                            .map(String::as_str)
                            .or_else(|| panic.downcast_ref::<&str>().copied())
                            .unwrap_or("unknown panic");
                        Err(anyhow!("panic in the GPU job: {msg}"))
                    }
                };
                if let Err(e) = &result {
                    tracing::error!("GPU job failed, marking the device lost: {e:#}");
                    lost.store(true, Ordering::Release);
                }
                let _ = reply.send(result);
            }
            Job::Destroy => {
                tracing::warn!("destroying the GPU device (simulated device loss)");
                device.destroy();
            }
        }
    }
}
