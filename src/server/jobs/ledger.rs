//! Export jobs kept in the scene store ([`crate::store::jobs`]), so that every replica sharing
//! the store and the archive directory answers for any job, and a job whose replica died is
//! redone by another.
//!
//! - **Owner.** Each process is one owner (16 random hex digits). It writes a job's row when it
//!   admits the job, renews the lease of each of its queued and running jobs every third of
//!   [`Ledger::lease`] with their progress ([`renew`]), and writes the final state when a job
//!   ends or its archive expires.
//! - **Lost lease.** A renewal the store refuses means another replica claimed the job (this
//!   one stalled for longer than a lease): the local run is cancelled and forgotten, and the
//!   job is answered from the store.
//! - **Stopping.** A server that stops (its queue dropped) cancels its jobs without writing
//!   their end: they stay queued or running in the store and are taken over once their leases
//!   lapse, by another replica or by the server itself, restarted.
//! - **Takeover** (`src/server/takeover.rs`): every half lease, a replica claims the stale jobs
//!   ([`crate::store::SceneStore::claim_job`]) and redoes them from the start: the archive is a
//!   pure function of world, version and spec, so it is the same bytes as the first owner's.
//!   Each owner writes its own `<id>.<owner>.part` and renames it to `<id>.tar` when complete.

use super::{Job, Progress, Status};
use crate::export::{ExportSpec, Shard};
use crate::store::{now_ms, JobRecord, JobUpdate, SceneStore, StoreError};
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use std::time::Duration;

/// Default of `--export-lease`, seconds: how long a job's owner may go silent before another
/// replica takes the job over.
pub const DEFAULT_LEASE_S: u64 = 20;

/// Where a process keeps its jobs' state.
#[derive(Clone, Debug)]
pub struct Ledger {
    /// The shared store.
    pub store: Arc<dyn SceneStore>,
    /// This process's owner id.
    pub owner: String,
    /// How long a job stays this process's without a renewal.
    pub lease: Duration,
}

/// What a job's row keeps of its request, as JSON text (`spec` of [`JobRecord`]).
#[derive(Debug, Serialize, Deserialize)]
pub struct StoredSpec {
    /// What is exported.
    pub spec: ExportSpec,
    /// Which shard.
    pub shard: Shard,
}

impl StoredSpec {
    /// Parses a row's `spec`.
    ///
    /// # Errors
    /// The text is not a stored spec.
    pub fn parse(text: &str) -> Result<Self, String> {
        serde_json::from_str(text).map_err(|e| format!("stored export spec: {e}"))
    }
}

/// The status named `s` ([`crate::store::jobs::JOB_STATUSES`]); unknown names read as failed.
pub fn parse_status(s: &str) -> Status {
    match s {
        "queued" => Status::Queued,
        "running" => Status::Running,
        "done" => Status::Done,
        "expired" => Status::Expired,
        _ => Status::Failed,
    }
}

/// The published state of a stored job.
pub fn progress_of(r: &JobRecord) -> Progress {
    Progress {
        status: parse_status(&r.status),
        done: r.done as usize,
        total: r.total as usize,
        error: r.error.clone(),
    }
}

impl Ledger {
    /// A ledger in `store` with a new owner id and a lease of `lease`.
    ///
    /// # Errors
    /// The OS random source failed.
    pub fn new(store: Arc<dyn SceneStore>, lease: Duration) -> Result<Self, StoreError> {
        Ok(Self {
            store,
            owner: crate::store::random_hex(8)?,
            lease: lease.max(Duration::from_secs(1)),
        })
    }

    fn lease_end(&self) -> i64 {
        now_ms().saturating_add(self.lease.as_millis() as i64)
    }

    /// The row of a job this process just admitted.
    pub fn record(&self, job: &Job) -> JobRecord {
        let p = job.progress();
        let spec = StoredSpec {
            spec: job.spec.clone(),
            shard: job.shard,
        };
        JobRecord {
            id: job.id.clone(),
            world: job.world.clone(),
            version: job.version,
            spec: serde_json::to_string(&spec).unwrap_or_default(),
            status: p.status.as_str().to_string(),
            done: p.done as u64,
            total: p.total as u64,
            error: p.error,
            reserved: job.reserved,
            bytes: 0,
            owner: self.owner.clone(),
            lease_until_ms: self.lease_end(),
            created_at: crate::store::now_ms() / 1000,
            finished_at: None,
        }
    }

    /// Writes `job`'s state and renews its lease; whether this process still owns it.
    pub async fn push(&self, job: &Job) -> Result<bool, StoreError> {
        let p = job.progress();
        let update = JobUpdate {
            status: p.status.as_str().to_string(),
            done: p.done as u64,
            total: p.total as u64,
            error: p.error,
            bytes: job.stored.load(std::sync::atomic::Ordering::Relaxed),
            lease_until_ms: self.lease_end(),
            finished_at: job.finished_unix.get().copied(),
        };
        let owned = self.store.update_job(&job.id, &self.owner, &update).await?;
        if owned {
            *super::lock(&job.synced) = Some(p.status);
        }
        Ok(owned)
    }
}

/// Renews the leases of `jobs`' unfinished jobs and writes the states not yet written, every
/// third of the lease, while `jobs` lives. A job another replica claimed is cancelled and
/// forgotten here.
pub async fn renew(jobs: std::sync::Weak<super::Jobs>) {
    loop {
        let Some(j) = jobs.upgrade() else { return };
        let Some(ledger) = j.ledger.clone() else {
            return;
        };
        let every = ledger.lease / 3;
        let pending: Vec<Arc<Job>> = j
            .jobs()
            .values()
            .filter(|job| {
                let status = job.progress().status;
                !status.is_finished() || *super::lock(&job.synced) != Some(status)
            })
            .cloned()
            .collect();
        for job in pending {
            match ledger.push(&job).await {
                Ok(true) => {}
                Ok(false) => {
                    tracing::warn!(job = %job.id, "export job taken over by another replica");
                    job.cancel();
                    j.forget(&job.id);
                }
                Err(e) => tracing::warn!(job = %job.id, "cannot renew the export job: {e}"),
            }
        }
        drop(j);
        tokio::time::sleep(every).await;
    }
}
