//! Export jobs: a small bounded queue of background [`crate::export`] runs, their progress and
//! their archives on disk.
//!
//! A job is admitted as `queued`, waits for one of [`JobLimits::max_running`] run slots (first
//! come, first served), runs as `running` on the blocking pool (`export::write_archive` into
//! `<dir>/<job>.tar.part`, renamed to `<dir>/<job>.tar` once complete) and ends `done` or
//! `failed`. Progress is published on a [`watch`] channel at most every [`PROGRESS_INTERVAL`]
//! (plus the final count), so any number of followers see the latest state without buffering.
//!
//! Limits ([`JobLimits`]): at most [`MAX_RUNNING_JOBS`] jobs run at once; at most
//! [`MAX_QUEUED_JOBS`] wait, and a job beyond that is refused ([`SubmitError::TooMany`]); the
//! newest [`MAX_FINISHED_JOBS`] finished jobs are kept, and admitting a job forgets the oldest
//! finished ones beyond that and deletes their archives.
//!
//! Shared state ([`ledger`]): with a [`Ledger`] (what `strata serve` sets up), each job's state
//! is also kept in the scene store and its archive in the shared archive directory, so every
//! replica on the same store answers for it, and one whose replica died (or restarted) is redone
//! by another ([`Jobs::resume`]) with the same bytes. Without one (tests of the queue), jobs live
//! in memory only. [`Jobs::sweep`] deletes the archives and partial archives no job needs.
//!
//! Disk budgets ([`quota`]): a job is admitted only if the upper bound of its archive fits the
//! world's and the server's budgets beside the archives already queued, running and stored, and
//! archives are deleted [`JobLimits::max_age`] after they were finished ([`Jobs::expire`]). With
//! a ledger the budgets, the queue limit and the expiry are counted in the store over every
//! replica's jobs ([`Jobs::expire_shared`]), so they hold across replicas; the newest
//! [`MAX_FINISHED_JOBS`] finished jobs are still what each process keeps in memory.
//!
//! Dropping [`Jobs`] (the server shutting down, a test ending) cancels every job: queued ones
//! fail at once, running ones at their next archive write.

use crate::export::{self, ExportSpec, Shard};
use crate::terrain::WorldPlan;
use serde::Serialize;
use std::collections::HashMap;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};
use std::time::{Duration, Instant};
use tokio::sync::{watch, Semaphore};

pub mod ledger;
pub mod quota;
pub use ledger::Ledger;
pub use quota::Budget;

/// Export jobs running at once (each on `cores / MAX_RUNNING_JOBS` threads, at least one).
pub const MAX_RUNNING_JOBS: usize = 2;
/// Export jobs waiting for a run slot; one more is refused (HTTP 429 `too_many_jobs`).
pub const MAX_QUEUED_JOBS: usize = 16;
/// Finished jobs (and their archives) kept; older ones are forgotten as new jobs are admitted.
pub const MAX_FINISHED_JOBS: usize = 64;
/// Least time between two published progress updates of a job (the final one is always sent).
pub const PROGRESS_INTERVAL: Duration = Duration::from_millis(100);

/// Limits of a [`Jobs`] queue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JobLimits {
    /// Jobs running at once ([`MAX_RUNNING_JOBS`]).
    pub max_running: usize,
    /// Jobs waiting to run ([`MAX_QUEUED_JOBS`]).
    pub max_queued: usize,
    /// Finished jobs kept ([`MAX_FINISHED_JOBS`]).
    pub max_finished: usize,
    /// Archive bytes one world's jobs may hold, queued and running ones counted at their
    /// bound ([`quota::DEFAULT_WORLD_BUDGET_MB`] MiB).
    pub world_budget_bytes: u64,
    /// Archive bytes all jobs together may hold ([`quota::DEFAULT_DISK_BUDGET_MB`] MiB).
    pub disk_budget_bytes: u64,
    /// How long a finished archive is kept ([`quota::DEFAULT_MAX_AGE_S`] seconds).
    pub max_age: Duration,
}

impl Default for JobLimits {
    fn default() -> Self {
        Self {
            max_running: MAX_RUNNING_JOBS,
            max_queued: MAX_QUEUED_JOBS,
            max_finished: MAX_FINISHED_JOBS,
            world_budget_bytes: quota::DEFAULT_WORLD_BUDGET_MB << 20,
            disk_budget_bytes: quota::DEFAULT_DISK_BUDGET_MB << 20,
            max_age: Duration::from_secs(quota::DEFAULT_MAX_AGE_S),
        }
    }
}

/// Where a job is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Waiting for a run slot.
    Queued,
    /// Writing its archive.
    Running,
    /// The archive is complete.
    Done,
    /// It stopped; see [`Progress::error`].
    Failed,
    /// It was done, and its archive was deleted [`JobLimits::max_age`] after.
    Expired,
}

impl Status {
    /// `queued`, `running`, `done` or `failed`.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Queued => "queued",
            Status::Running => "running",
            Status::Done => "done",
            Status::Failed => "failed",
            Status::Expired => "expired",
        }
    }

    /// Whether the job has ended.
    pub fn is_finished(self) -> bool {
        matches!(self, Status::Done | Status::Failed | Status::Expired)
    }
}

/// The published state of a job.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Progress {
    /// Where it is.
    pub status: Status,
    /// Tiles written.
    pub done: usize,
    /// Tiles of the job (its shard).
    pub total: usize,
    /// Why it failed.
    pub error: Option<String>,
}

/// One export job.
#[derive(Debug)]
pub struct Job {
    /// Random id (32 hex digits).
    pub id: String,
    /// The world exported.
    pub world: String,
    /// The world version exported.
    pub version: u64,
    /// What is exported.
    pub spec: ExportSpec,
    /// Which shard.
    pub shard: Shard,
    /// What every tile applies on top of the field: the solved authored regions and the
    /// `strata` elements of the world version.
    pub edits: crate::edits::TileEdits,
    /// Upper bound of the archive, bytes ([`crate::export::size::archive_bound`]).
    pub reserved: u64,
    /// The archive's size once done, bytes.
    stored: AtomicU64,
    /// When the job was done.
    finished: OnceLock<Instant>,
    /// When the job was done or failed, seconds since the Unix epoch.
    finished_unix: OnceLock<i64>,
    /// The status last written to the [`Ledger`].
    synced: Mutex<Option<Status>>,
    seq: u64,
    path: PathBuf,
    state: watch::Sender<Progress>,
    cancel: AtomicBool,
}

impl Job {
    /// A job of `spec`'s `shard` of world `world` at `version`, queued to run in this process,
    /// its archive at `path`; `synced` is the status the [`Ledger`] holds for it (`None`: it is
    /// this process's alone).
    #[allow(clippy::too_many_arguments)]
    fn queued(
        path: PathBuf,
        id: String,
        world: String,
        version: u64,
        (spec, shard): (ExportSpec, Shard),
        edits: crate::edits::TileEdits,
        reserved: u64,
        seq: u64,
        synced: Option<Status>,
    ) -> Self {
        let total = spec.keys(shard).len();
        Self {
            path,
            id,
            world,
            version,
            spec,
            shard,
            edits,
            reserved,
            stored: AtomicU64::new(0),
            finished: OnceLock::new(),
            finished_unix: OnceLock::new(),
            synced: Mutex::new(synced),
            seq,
            state: watch::Sender::new(Progress {
                status: Status::Queued,
                done: 0,
                total,
                error: None,
            }),
            cancel: AtomicBool::new(false),
        }
    }

    /// The current state.
    pub fn progress(&self) -> Progress {
        self.state.borrow().clone()
    }

    /// A receiver of state changes, the current state marked unseen.
    pub fn subscribe(&self) -> watch::Receiver<Progress> {
        let mut rx = self.state.subscribe();
        rx.mark_changed();
        rx
    }

    /// The finished archive, once the job is done.
    pub fn archive(&self) -> Option<&Path> {
        (self.state.borrow().status == Status::Done).then_some(self.path.as_path())
    }

    /// How many receivers of its state changes there are.
    pub fn followers(&self) -> usize {
        self.state.receiver_count()
    }

    /// Replaces the published state (a job another replica runs, as read from the store).
    pub(crate) fn publish(&self, progress: Progress) {
        self.state.send_if_modified(|p| {
            let changed = *p != progress;
            *p = progress;
            changed
        });
    }

    /// Asks the job to stop: a queued job fails before it runs, a running one at its next write.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    fn fail(&self, error: impl Into<String>) {
        let error = error.into();
        tracing::warn!(job = %self.id, world = %self.world, "export failed: {error}");
        let _ = self.finished_unix.set(unix_now());
        self.state.send_modify(|p| {
            p.status = Status::Failed;
            p.error = Some(error);
        });
    }
}

/// Why a job was not admitted.
#[derive(Debug, thiserror::Error)]
pub enum SubmitError {
    /// The queue is full.
    #[error("{queued} export jobs are already waiting (the limit is {limit}); retry later")]
    TooMany {
        /// Jobs waiting.
        queued: usize,
        /// The limit.
        limit: usize,
    },
    /// The archive's bound is larger than a budget: it can never be admitted.
    #[error(
        "the archive may take up to {estimate} bytes, more than the {} of {limit} bytes",
        budget.name()
    )]
    TooLarge {
        /// The budget.
        budget: Budget,
        /// The archive's bound, bytes.
        estimate: u64,
        /// The budget, bytes.
        limit: u64,
    },
    /// The budget holds too many archives now; older ones expire.
    #[error(
        "the {} of {limit} bytes holds {used} bytes of archives, and this one may take up to \
         {estimate} bytes; retry once older archives expire",
        budget.name()
    )]
    OverQuota {
        /// The budget.
        budget: Budget,
        /// Bytes already charged to it.
        used: u64,
        /// The archive's bound, bytes.
        estimate: u64,
        /// The budget, bytes.
        limit: u64,
        /// Seconds until the oldest archive in the budget expires (or a short wait while only
        /// running jobs fill it).
        retry_after_s: u64,
    },
    /// No job id could be drawn.
    #[error("the OS random source failed: {0}")]
    Random(String),
    /// The job could not be stored ([`Jobs::submit_shared`]).
    #[error("the export job cannot be stored: {0}")]
    Store(String),
}

/// The export jobs of a server.
pub struct Jobs {
    dir: PathBuf,
    limits: JobLimits,
    threads: usize,
    slots: Arc<Semaphore>,
    jobs: Mutex<HashMap<String, Arc<Job>>>,
    seq: AtomicU64,
    ledger: Option<Ledger>,
    /// Set when the queue is dropped (the server stopping): the jobs it cancels then are left
    /// unfinished in the store, for another replica (or this server, restarted) to take over.
    closing: Arc<AtomicBool>,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

/// Seconds since the Unix epoch.
fn unix_now() -> i64 {
    crate::store::now_ms() / 1000
}

impl std::fmt::Debug for Jobs {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Jobs")
            .field("dir", &self.dir)
            .field("limits", &self.limits)
            .field("threads", &self.threads)
            .finish_non_exhaustive()
    }
}

/// Whether `id` has the shape of a job id.
pub fn valid_job_id(id: &str) -> bool {
    id.len() == 32 && id.bytes().all(|b| matches!(b, b'0'..=b'9' | b'a'..=b'f'))
}

fn new_job_id() -> Result<String, SubmitError> {
    let mut bytes = [0u8; 16];
    getrandom::fill(&mut bytes).map_err(|e| SubmitError::Random(e.to_string()))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

impl Jobs {
    /// Jobs writing their archives to `dir` (created on first use).
    pub fn new(dir: impl Into<PathBuf>, limits: JobLimits) -> Self {
        let limits = JobLimits {
            max_running: limits.max_running.max(1),
            ..limits
        };
        let cores = std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1);
        Self {
            dir: dir.into(),
            limits,
            threads: (cores / limits.max_running).max(1),
            slots: Arc::new(Semaphore::new(limits.max_running)),
            jobs: Mutex::new(HashMap::new()),
            seq: AtomicU64::new(0),
            ledger: None,
            closing: Arc::new(AtomicBool::new(false)),
        }
    }

    /// Keeps the jobs' state in `ledger`'s store too (see [`ledger`]). Call it before the first
    /// job, then [`Jobs::start_renewing`] once the queue is in its `Arc`.
    pub fn with_ledger(mut self, ledger: Ledger) -> Self {
        self.ledger = Some(ledger);
        self
    }

    /// Starts renewing the leases of this queue's jobs ([`ledger::renew`]) until it is dropped.
    /// Needs a tokio runtime; does nothing without a ledger.
    pub fn start_renewing(self: &Arc<Self>) {
        if self.ledger.is_some() {
            tokio::spawn(ledger::renew(Arc::downgrade(self)));
        }
    }

    /// The ledger, if the jobs' state is kept in the store.
    pub fn ledger(&self) -> Option<&Ledger> {
        self.ledger.as_ref()
    }

    /// Forgets job `id` (its archive stays).
    fn forget(&self, id: &str) {
        self.jobs().remove(id);
    }

    /// The archive directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The limits in force.
    pub fn limits(&self) -> JobLimits {
        self.limits
    }

    fn jobs(&self) -> MutexGuard<'_, HashMap<String, Arc<Job>>> {
        lock(&self.jobs)
    }

    /// The job `id`, if it is known (expiring old archives first).
    pub fn get(&self, id: &str) -> Option<Arc<Job>> {
        self.expire();
        self.jobs().get(id).cloned()
    }

    /// Deletes the archives finished more than [`JobLimits::max_age`] ago and marks their jobs
    /// `expired`; how many. Blocking file I/O (one unlink per archive).
    pub fn expire(&self) -> usize {
        let now = Instant::now();
        let stale: Vec<Arc<Job>> = self
            .jobs()
            .values()
            .filter(|j| j.is_stale(self.limits.max_age, now))
            .cloned()
            .collect();
        for job in &stale {
            job.state.send_modify(|p| p.status = Status::Expired);
            if let Err(e) = std::fs::remove_file(&job.path) {
                if e.kind() != io::ErrorKind::NotFound {
                    tracing::warn!("cannot delete {}: {e}", job.path.display());
                }
            }
            tracing::info!(job = %job.id, world = %job.world, "export archive expired");
        }
        stale.len()
    }

    /// Bytes charged to the budgets now: `(world's, all jobs')`.
    pub fn charged(&self, world: &str) -> (u64, u64) {
        self.expire();
        let jobs = self.jobs();
        let all = jobs.values().map(|j| j.charge()).sum();
        let own = jobs
            .values()
            .filter(|j| j.world == world)
            .map(|j| j.charge())
            .sum();
        (own, all)
    }

    /// `(queued, running, finished)` job counts.
    pub fn counts(&self) -> (usize, usize, usize) {
        let mut c = (0, 0, 0);
        for j in self.jobs().values() {
            match j.state.borrow().status {
                Status::Queued => c.0 += 1,
                Status::Running => c.1 += 1,
                Status::Done | Status::Failed | Status::Expired => c.2 += 1,
            }
        }
        c
    }

    /// Deletes the archives (`<32 hex>.tar`) and partial archives (`<32 hex>.<owner>.part`) in
    /// the directory that no job needs: those of no job of this process and, with a ledger, of
    /// no job the store has done (archives) or unfinished (partial archives). Run at start, it
    /// deletes what a previous process left behind and keeps what other replicas share.
    pub async fn sweep(&self) -> io::Result<usize> {
        let entries = match std::fs::read_dir(&self.dir) {
            Ok(e) => e,
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(0),
            Err(e) => return Err(e),
        };
        let mut removed = 0;
        for entry in entries {
            let entry = entry?;
            let name = entry.file_name();
            let Some(name) = name.to_str() else { continue };
            let (stem, part) = match (name.strip_suffix(".tar"), name.strip_suffix(".part")) {
                (Some(stem), _) => (stem, false),
                (None, Some(rest)) => (rest.split('.').next().unwrap_or(""), true),
                (None, None) => continue,
            };
            if !valid_job_id(stem) || self.get(stem).is_some() {
                continue;
            }
            if let Some(ledger) = &self.ledger {
                let status = match ledger.store.job(stem).await {
                    Ok(r) => r.map(|r| ledger::parse_status(&r.status)),
                    // Unknown: keep it rather than delete another replica's archive.
                    Err(_) => continue,
                };
                let needed = match status {
                    Some(Status::Done) => !part,
                    Some(Status::Queued | Status::Running) => part,
                    _ => false,
                };
                if needed {
                    continue;
                }
            }
            std::fs::remove_file(entry.path())?;
            removed += 1;
        }
        Ok(removed)
    }

    /// Admits an export of `spec` (already validated against `plan`) of world `world` at
    /// `version` and starts it in the background. Needs a tokio runtime.
    pub fn submit(
        &self,
        world: &str,
        version: u64,
        plan: Arc<WorldPlan>,
        spec: ExportSpec,
        shard: Shard,
    ) -> Result<Arc<Job>, SubmitError> {
        self.submit_with(world, version, plan, Default::default(), spec, shard)
    }

    /// [`Jobs::submit`] for a world with edits (authored regions already solved, strata).
    pub fn submit_with(
        &self,
        world: &str,
        version: u64,
        plan: Arc<WorldPlan>,
        edits: crate::edits::TileEdits,
        spec: ExportSpec,
        shard: Shard,
    ) -> Result<Arc<Job>, SubmitError> {
        let job = self.admit(world, version, &plan, edits, spec, shard)?;
        self.start(job.clone(), plan);
        Ok(job)
    }

    /// [`Jobs::submit_with`] that, with a ledger, stores the job before it starts, so that every
    /// replica knows it once this returns.
    ///
    /// # Errors
    /// What [`Jobs::submit_with`] refuses, or the store's failure (the job is then forgotten).
    pub async fn submit_shared(
        &self,
        world: &str,
        version: u64,
        plan: Arc<WorldPlan>,
        edits: crate::edits::TileEdits,
        spec: ExportSpec,
        shard: Shard,
    ) -> Result<Arc<Job>, SubmitError> {
        let job = match &self.ledger {
            Some(ledger) => {
                self.admit_shared(ledger, world, version, &plan, edits, spec, shard)
                    .await?
            }
            None => self.admit(world, version, &plan, edits, spec, shard)?,
        };
        self.start(job.clone(), plan);
        Ok(job)
    }

    /// Admits a job, without starting it, in the store of `ledger`: the budgets and the queue
    /// limit are counted over every job the store holds, every replica's
    /// ([`crate::store::SceneStore::admit_job`]). The oldest finished jobs beyond
    /// [`JobLimits::max_finished`] are forgotten here, their archives left to the store's expiry.
    #[allow(clippy::too_many_arguments)]
    async fn admit_shared(
        &self,
        ledger: &Ledger,
        world: &str,
        version: u64,
        plan: &WorldPlan,
        edits: crate::edits::TileEdits,
        spec: ExportSpec,
        shard: Shard,
    ) -> Result<Arc<Job>, SubmitError> {
        let reserved = export::size::archive_bound(plan, &spec, shard);
        quota::too_large(reserved, &self.limits)?;
        let id = new_job_id()?;
        let job = Arc::new(Job::queued(
            self.dir.join(format!("{id}.tar")),
            id.clone(),
            world.to_string(),
            version,
            (spec, shard),
            edits,
            reserved,
            self.seq.fetch_add(1, Ordering::Relaxed),
            Some(Status::Queued),
        ));
        let quota = crate::store::JobQuota {
            world_bytes: self.limits.world_budget_bytes,
            disk_bytes: self.limits.disk_budget_bytes,
            max_queued: self.limits.max_queued as u64,
        };
        let admission = ledger
            .store
            .admit_job(&ledger.record(&job), &quota)
            .await
            .map_err(|e| SubmitError::Store(e.to_string()))?;
        match admission {
            crate::store::Admission::Admitted => {}
            crate::store::Admission::TooMany { queued } => {
                return Err(SubmitError::TooMany {
                    queued: queued as usize,
                    limit: self.limits.max_queued,
                })
            }
            crate::store::Admission::OverQuota {
                world,
                used,
                oldest_done_s,
            } => {
                return Err(quota::over_quota_in_store(
                    world,
                    used,
                    oldest_done_s,
                    reserved,
                    &self.limits,
                ))
            }
        }
        {
            let mut jobs = self.jobs();
            // Forgotten here only: whether their archives are kept is the store's to say.
            evict(&mut jobs, self.limits.max_finished);
            jobs.insert(id, job.clone());
        }
        tracing::info!(
            job = %job.id, world, version, tiles = job.progress().total,
            shard = format!("{}/{}", shard.index + 1, shard.count), "export job queued"
        );
        Ok(job)
    }

    /// With a ledger, expires in the store every job done more than [`JobLimits::max_age`]
    /// ago, whichever replica ran it (one that died included), and deletes their archives from
    /// the shared directory; how many. Without one, [`Jobs::expire`].
    pub async fn expire_shared(&self) -> usize {
        let Some(ledger) = &self.ledger else {
            return self.expire();
        };
        let max_age = i64::try_from(self.limits.max_age.as_secs()).unwrap_or(i64::MAX);
        let before = unix_now().saturating_sub(max_age);
        let ids = match ledger.store.expire_jobs(before).await {
            Ok(ids) => ids,
            Err(e) => {
                tracing::warn!("cannot expire export jobs in the store: {e}");
                return self.expire();
            }
        };
        for id in &ids {
            if let Some(job) = self.jobs().get(id) {
                job.state.send_modify(|p| p.status = Status::Expired);
                *lock(&job.synced) = Some(Status::Expired);
            }
            let path = self.dir.join(format!("{id}.tar"));
            if let Err(e) = std::fs::remove_file(&path) {
                if e.kind() != io::ErrorKind::NotFound {
                    tracing::warn!("cannot delete {}: {e}", path.display());
                }
            }
            tracing::info!(job = %id, "export archive expired");
        }
        ids.len() + self.expire()
    }

    /// Runs again, under this process's ownership, the job `record` another process owned
    /// (already claimed in the store): queued like a new job, but past the budgets, which the
    /// job was admitted under. A job of the same id in this process is replaced.
    pub fn resume(
        &self,
        record: &crate::store::JobRecord,
        plan: Arc<WorldPlan>,
        edits: crate::edits::TileEdits,
        spec: ExportSpec,
        shard: Shard,
    ) -> Arc<Job> {
        let job = Arc::new(Job::queued(
            self.dir.join(format!("{}.tar", record.id)),
            record.id.clone(),
            record.world.clone(),
            record.version,
            (spec, shard),
            edits,
            record.reserved,
            self.seq.fetch_add(1, Ordering::Relaxed),
            Some(Status::Queued),
        ));
        if let Some(old) = self.jobs().insert(job.id.clone(), job.clone()) {
            old.cancel();
        }
        tracing::info!(job = %job.id, world = %job.world, "export job taken over");
        self.start(job.clone(), plan);
        job
    }

    /// A job of another replica, as the store has it ([`ledger::progress_of`]): not run here,
    /// its archive read from the shared directory once done. `None` if its spec is unreadable.
    pub fn remote(&self, record: &crate::store::JobRecord) -> Option<Arc<Job>> {
        let stored = ledger::StoredSpec::parse(&record.spec).ok()?;
        Some(Arc::new(Job {
            path: self.dir.join(format!("{}.tar", record.id)),
            id: record.id.clone(),
            world: record.world.clone(),
            version: record.version,
            spec: stored.spec,
            shard: stored.shard,
            edits: Default::default(),
            reserved: record.reserved,
            stored: AtomicU64::new(record.bytes),
            finished: OnceLock::new(),
            finished_unix: OnceLock::new(),
            synced: Mutex::new(None),
            seq: 0,
            state: watch::Sender::new(ledger::progress_of(record)),
            cancel: AtomicBool::new(false),
        }))
    }

    /// Admits a job without starting it.
    fn admit(
        &self,
        world: &str,
        version: u64,
        plan: &WorldPlan,
        edits: crate::edits::TileEdits,
        spec: ExportSpec,
        shard: Shard,
    ) -> Result<Arc<Job>, SubmitError> {
        let reserved = export::size::archive_bound(plan, &spec, shard);
        self.expire();
        let evicted = {
            let mut jobs = self.jobs();
            quota::admit(&jobs, world, reserved, &self.limits)?;
            let queued = jobs
                .values()
                .filter(|j| j.state.borrow().status == Status::Queued)
                .count();
            if queued >= self.limits.max_queued {
                return Err(SubmitError::TooMany {
                    queued,
                    limit: self.limits.max_queued,
                });
            }
            let id = loop {
                let id = new_job_id()?;
                if !jobs.contains_key(&id) {
                    break id;
                }
            };
            let job = Arc::new(Job::queued(
                self.dir.join(format!("{id}.tar")),
                id.clone(),
                world.to_string(),
                version,
                (spec, shard),
                edits,
                reserved,
                self.seq.fetch_add(1, Ordering::Relaxed),
                None,
            ));
            let evicted = evict(&mut jobs, self.limits.max_finished);
            jobs.insert(id, job.clone());
            (job, evicted)
        };
        let (job, evicted) = evicted;
        if !evicted.is_empty() {
            tokio::task::spawn_blocking(move || {
                for path in evicted {
                    if let Err(e) = std::fs::remove_file(&path) {
                        if e.kind() != io::ErrorKind::NotFound {
                            tracing::warn!("cannot delete {}: {e}", path.display());
                        }
                    }
                }
            });
        }
        tracing::info!(
            job = %job.id, world, version, tiles = job.progress().total,
            shard = format!("{}/{}", shard.index + 1, shard.count), "export job queued"
        );
        Ok(job)
    }

    /// Starts an admitted job in the background. Needs a tokio runtime.
    fn start(&self, job: Arc<Job>, plan: Arc<WorldPlan>) {
        let owner = self.ledger.as_ref().map(|l| l.owner.clone());
        tokio::spawn(run(
            job,
            plan,
            self.slots.clone(),
            self.dir.clone(),
            self.threads,
            self.ledger.clone().map(|l| (l, self.closing.clone())),
            owner.unwrap_or_else(|| "local".into()),
        ));
    }
}

/// Forgets the oldest finished jobs so that at most `keep - 1` remain; their archive paths.
fn evict(jobs: &mut HashMap<String, Arc<Job>>, keep: usize) -> Vec<PathBuf> {
    let mut finished: Vec<(u64, String)> = jobs
        .values()
        .filter(|j| j.state.borrow().status.is_finished())
        .map(|j| (j.seq, j.id.clone()))
        .collect();
    if finished.len() < keep.max(1) {
        return Vec::new();
    }
    finished.sort_unstable();
    let excess = finished.len() + 1 - keep.max(1);
    finished[..excess]
        .iter()
        .filter_map(|(_, id)| jobs.remove(id))
        .map(|j| j.path.clone())
        .collect()
}

impl Drop for Jobs {
    fn drop(&mut self) {
        self.closing.store(true, Ordering::SeqCst);
        self.slots.close();
        for job in self.jobs().values() {
            job.cancel();
        }
    }
}

/// Waits for a run slot, then writes the archive on the blocking pool; with a ledger, writes
/// the final state to the store at once, unless the queue is closing (then the job stays
/// unfinished there, to be taken over).
async fn run(
    job: Arc<Job>,
    plan: Arc<WorldPlan>,
    slots: Arc<Semaphore>,
    dir: PathBuf,
    threads: usize,
    ledger: Option<(Ledger, Arc<AtomicBool>)>,
    owner: String,
) {
    execute(&job, plan, slots, dir, threads, owner).await;
    if let Some((ledger, closing)) = ledger {
        if closing.load(Ordering::SeqCst) {
            return;
        }
        if let Err(e) = ledger.push(&job).await {
            tracing::warn!(job = %job.id, "cannot store the end of the export job: {e}");
        }
    }
}

async fn execute(
    job: &Arc<Job>,
    plan: Arc<WorldPlan>,
    slots: Arc<Semaphore>,
    dir: PathBuf,
    threads: usize,
    owner: String,
) {
    let Ok(_permit) = slots.acquire_owned().await else {
        job.fail("the server is shutting down");
        return;
    };
    if job.cancelled() {
        job.fail("cancelled");
        return;
    }
    job.state.send_modify(|p| p.status = Status::Running);
    let started = Instant::now();
    let j = job.clone();
    let result = tokio::task::spawn_blocking(move || write(&j, &plan, &dir, threads, &owner)).await;
    match result {
        Ok(Ok(bytes)) => {
            tracing::info!(
                job = %job.id, bytes, ms = started.elapsed().as_millis() as u64,
                "export job done"
            );
            job.stored.store(bytes, Ordering::Relaxed);
            let _ = job.finished.set(Instant::now());
            let _ = job.finished_unix.set(unix_now());
            job.state.send_modify(|p| {
                p.status = Status::Done;
                p.done = p.total;
            });
        }
        Ok(Err(e)) => job.fail(format!("{e:#}")),
        Err(e) if e.is_panic() => job.fail(format!("the export panicked: {e}")),
        Err(_) => job.fail("cancelled: the server is shutting down"),
    }
}

/// Deletes the partial archives of job `id` that replicas which ran it before left behind.
fn remove_parts(dir: &Path, id: &str) {
    let prefix = format!("{id}.");
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if name.starts_with(&prefix) && name.ends_with(".part") {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// A writer that fails once its job is cancelled, which stops `write_archive`.
struct Cancellable<'a, W> {
    inner: W,
    job: &'a Job,
}

impl<W: Write> Write for Cancellable<'_, W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.job.cancelled() {
            return Err(io::Error::other("cancelled"));
        }
        self.inner.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}

/// Writes the job's archive to `<id>.<owner>.part`, then renames it `<id>.tar`; its size in
/// bytes. Replicas redoing a job each write their own partial archive, and the same bytes.
fn write(
    job: &Job,
    plan: &WorldPlan,
    dir: &Path,
    threads: usize,
    owner: &str,
) -> anyhow::Result<u64> {
    use anyhow::Context;
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let part = dir.join(format!("{}.{owner}.part", job.id));
    let attempt = || -> anyhow::Result<u64> {
        let file =
            std::fs::File::create(&part).with_context(|| format!("creating {}", part.display()))?;
        let mut out = BufWriter::new(Cancellable { inner: file, job });
        let mut last: Option<Instant> = None;
        export::write_archive(
            plan,
            &job.edits,
            &job.spec,
            job.shard,
            threads,
            &mut out,
            |done, total| {
                let now = Instant::now();
                if done == total || last.is_none_or(|t| now - t >= PROGRESS_INTERVAL) {
                    last = Some(now);
                    job.state.send_modify(|p| {
                        p.done = done;
                        p.total = total;
                    });
                }
            },
        )?;
        let file = out
            .into_inner()
            .map_err(|e| e.into_error())
            .context("writing the archive")?
            .inner;
        file.sync_all().context("syncing the archive")?;
        let bytes = file.metadata()?.len();
        std::fs::rename(&part, &job.path)
            .with_context(|| format!("renaming {}", part.display()))?;
        remove_parts(dir, &job.id);
        Ok(bytes)
    };
    let result = attempt();
    if result.is_err() {
        let _ = std::fs::remove_file(&part);
    }
    result
}

#[cfg(test)]
mod tests;
