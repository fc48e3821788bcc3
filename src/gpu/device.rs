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
use super::jobs::{DeviceStage, JobCounts, JobResult};
use super::poisson::PoissonKernels;
use super::tile::{TileKernels, DEFAULT_JOB_TIMEOUT, MAX_BUFFER_BYTES};
use super::volume_mesh::VolumeMeshKernel;
use crate::terrain::tile::{Field, FieldJob};
use crate::terrain::WorldPlan;
use anyhow::{anyhow, bail};
use clap::ValueEnum;
use serde::Serialize;
use std::cell::OnceCell;
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

/// A job's work on the device thread: it sends its own typed reply and returns the error that
/// marks the device lost, if any.
type Task = Box<dyn FnOnce(&DeviceContext) -> Result<(), String> + Send>;

enum Job {
    Run {
        task: Task,
        started: oneshot::Sender<()>,
    },
    Destroy,
}

/// What a job sees on the device thread: the device, its queue and the compiled kernels.
/// Kernels that only some worlds need are compiled on first use.
pub struct DeviceContext {
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    /// The classic field kernels.
    pub tile: TileKernels,
    /// The `earth-1` field kernels.
    pub earth: EarthKernels,
    poisson: OnceCell<PoissonKernels>,
    mesh: OnceCell<VolumeMeshKernel>,
}

impl fmt::Debug for DeviceContext {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("DeviceContext")
            .field("poisson_compiled", &self.poisson.get().is_some())
            .field("mesh_compiled", &self.mesh.get().is_some())
            .finish_non_exhaustive()
    }
}

impl DeviceContext {
    /// The multigrid Poisson kernels, compiled on first use.
    ///
    /// # Errors
    /// If they do not compile on this device.
    pub fn poisson(&self) -> anyhow::Result<&PoissonKernels> {
        if self.poisson.get().is_none() {
            let _ = self.poisson.set(PoissonKernels::new(&self.device)?);
        }
        Ok(self.poisson.get().expect("set above"))
    }

    /// The surface-nets kernel, compiled on first use.
    ///
    /// # Errors
    /// If it does not compile on this device.
    pub fn mesh(&self) -> anyhow::Result<&VolumeMeshKernel> {
        if self.mesh.get().is_none() {
            let _ = self.mesh.set(VolumeMeshKernel::new(&self.device)?);
        }
        Ok(self.mesh.get().expect("set above"))
    }
}

/// How long dropping the last handle waits for the device thread to release the device.
const SHUTDOWN_WAIT: Duration = Duration::from_secs(5);

/// The sending end of the device thread's queue, shared by every handle. When the last handle
/// goes, the queue closes and the drop waits (at most [`SHUTDOWN_WAIT`]) for the thread to drop
/// the device, so a process that exits next does not unload the driver under a live device
/// (lavapipe then crashes in its exit handlers).
struct Queue {
    tx: Option<mpsc::Sender<Job>>,
    released: std::sync::Mutex<std::sync::mpsc::Receiver<()>>,
}

impl Queue {
    fn sender(&self) -> &mpsc::Sender<Job> {
        self.tx
            .as_ref()
            .expect("the sender lives until the queue is dropped")
    }
}

impl Drop for Queue {
    fn drop(&mut self) {
        self.tx = None;
        if let Ok(released) = self.released.lock() {
            let _ = released.recv_timeout(SHUTDOWN_WAIT);
        }
    }
}

/// Handle to the device task; cheap to clone. The task ends when the last handle is dropped.
#[derive(Clone)]
pub struct GpuHandle {
    queue: Arc<Queue>,
    lost: Arc<AtomicBool>,
    info: Arc<AdapterInfo>,
    timeout: Duration,
    pub(super) jobs: Arc<JobCounts>,
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
        if let Err(e) = check_job(&plan, job) {
            return self.refuse(DeviceStage::Field, e);
        }
        let timeout = self.timeout;
        self.run(DeviceStage::Field, timeout, move |ctx| {
            if plan.earth.is_some() {
                ctx.earth
                    .field(&ctx.device, &ctx.queue, &plan, job, Some(timeout))
            } else {
                ctx.tile
                    .field(&ctx.device, &ctx.queue, &plan, job, Some(timeout))
            }
        })
        .await
    }

    /// Runs `work` on the device thread and returns its result, counting it under `stage`.
    ///
    /// The caller checks that the input is within the kernel's limits first: any error `work`
    /// returns, a panic in it, or a reply later than `timeout` after the job started marks the
    /// device lost. Time in the queue does not count against `timeout`.
    ///
    /// # Errors
    /// At once if the device is lost; otherwise `work`'s error, a panic, or the time-out.
    pub async fn run<T: Send + 'static>(
        &self,
        stage: DeviceStage,
        timeout: Duration,
        work: impl FnOnce(&DeviceContext) -> anyhow::Result<T> + Send + 'static,
    ) -> anyhow::Result<T> {
        if self.is_lost() {
            self.jobs.count(stage, JobResult::Skipped);
            bail!("GPU device lost");
        }
        let result = self.send(timeout, work).await;
        self.jobs.count(
            stage,
            if result.is_ok() {
                JobResult::Device
            } else {
                JobResult::Failed
            },
        );
        result
    }

    /// Counts a job of `stage` that is not sent because its input exceeds the kernel's limits,
    /// and returns `refusal` as the error.
    pub(super) fn refuse<T>(
        &self,
        stage: DeviceStage,
        refusal: anyhow::Error,
    ) -> anyhow::Result<T> {
        self.jobs.count(stage, JobResult::Skipped);
        Err(refusal)
    }

    async fn send<T: Send + 'static>(
        &self,
        timeout: Duration,
        work: impl FnOnce(&DeviceContext) -> anyhow::Result<T> + Send + 'static,
    ) -> anyhow::Result<T> {
        let (started_tx, mut started_rx) = oneshot::channel();
        let (reply_tx, reply_rx) = oneshot::channel();
        let task: Task = Box::new(move |ctx| {
            let result = work(ctx);
            let failure = result.as_ref().err().map(|e| format!("{e:#}"));
            let _ = reply_tx.send(result);
            failure.map_or(Ok(()), Err)
        });
        let job = Job::Run {
            task,
            started: started_tx,
        };
        if self.queue.sender().send(job).await.is_err() {
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
        match tokio::time::timeout(timeout, reply_rx).await {
            Ok(Ok(result)) => result,
            Ok(Err(_)) => {
                self.mark_lost();
                bail!("GPU device task dropped the job")
            }
            Err(_) => {
                self.mark_lost();
                bail!("GPU job timed out after {timeout:?}")
            }
        }
    }

    /// Test hook: destroys the device (`Device::destroy`) inside the device task, after the jobs
    /// already queued. The lost flag is not set here: the next job runs on the destroyed device,
    /// fails for real (its result cannot be mapped), and that failure sets the flag. If the queue
    /// is full the flag is set directly.
    pub fn simulate_device_loss(&self) {
        if self.queue.sender().try_send(Job::Destroy).is_err() {
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
    let (released_tx, released_rx) = std::sync::mpsc::channel();
    std::thread::Builder::new()
        .name("strata-gpu".into())
        .spawn(move || {
            device_thread(choice, ready_tx, rx, thread_lost);
            let _ = released_tx.send(());
        })?;
    match ready_rx.await {
        Ok(Ok(Some(info))) => Ok(Some(GpuHandle {
            queue: Arc::new(Queue {
                tx: Some(tx),
                released: std::sync::Mutex::new(released_rx),
            }),
            lost,
            info: Arc::new(info),
            timeout,
            jobs: Arc::default(),
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
    ready: oneshot::Sender<anyhow::Result<Option<AdapterInfo>>>,
    mut rx: mpsc::Receiver<Job>,
    lost: Arc<AtomicBool>,
) {
    let opened = pollster::block_on(request_device(choice)).and_then(|opened| {
        opened
            .map(|(adapter, device, queue)| {
                let ctx = DeviceContext {
                    tile: TileKernels::new(&device)?,
                    earth: EarthKernels::new(&device)?,
                    poisson: OnceCell::new(),
                    mesh: OnceCell::new(),
                    device,
                    queue,
                };
                Ok((adapter_info_of(&adapter.get_info()), ctx))
            })
            .transpose()
    });
    let (info, ctx) = match opened {
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
    ctx.device.set_device_lost_callback(move |reason, message| {
        // `Destroyed` only follows our own `destroy()` (the test hook), whose effect the next job
        // must detect by failing; every other reason is a real loss.
        if reason != wgpu::DeviceLostReason::Destroyed {
            tracing::error!("GPU device lost ({reason:?}): {message}");
            flag.store(true, Ordering::Release);
        }
    });
    let flag = lost.clone();
    ctx.device.on_uncaptured_error(Arc::new(move |e| {
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
            Job::Run { task, started } => {
                let _ = started.send(());
                if lost.load(Ordering::Acquire) {
                    // Dropping the task drops its reply sender: the caller sees the job dropped.
                    continue;
                }
                let failure = match catch_unwind(AssertUnwindSafe(|| task(&ctx))) {
                    Ok(result) => result.err(),
                    Err(panic) => Some(format!(
                        "panic in the GPU job: {}",
                        panic
                            .downcast_ref::<String>()
                            .map(String::as_str)
                            .or_else(|| panic.downcast_ref::<&str>().copied())
                            .unwrap_or("unknown panic")
                    )),
                };
                if let Some(e) = failure {
                    tracing::error!("GPU job failed, marking the device lost: {e}");
                    lost.store(true, Ordering::Release);
                }
            }
            Job::Destroy => {
                tracing::warn!("destroying the GPU device (simulated device loss)");
                ctx.device.destroy();
            }
        }
    }
}
