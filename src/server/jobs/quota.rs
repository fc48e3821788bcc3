//! The disk budgets of export jobs: what one world and the whole server may hold in archives.
//!
//! Every job is charged, from the moment it is admitted, the upper bound of its archive
//! ([`crate::export::size::archive_bound`]) while it is queued or running, and its archive's real
//! size once it is done; a failed or expired job is charged nothing. A job is admitted only if
//! its bound fits both budgets beside what is already charged:
//!
//! - a bound larger than a budget can never fit: [`SubmitError::TooLarge`] (HTTP 400
//!   `export_too_large`);
//! - a bound that fits once older archives expire: [`SubmitError::OverQuota`] (HTTP 429
//!   `export_quota_exceeded`, `Retry-After` the seconds until the oldest archive in the budget
//!   expires).
//!
//! Archives expire [`JobLimits::max_age`] after they were finished: the file is deleted and the
//! job answers `expired` (HTTP 410 `job_expired` for its archive) until it is forgotten.
//!
//! With a [`super::Ledger`] (what `strata serve` runs) both the charges and the expiry are the
//! store's ([`crate::store::SceneStore::admit_job`], [`crate::store::SceneStore::expire_jobs`]):
//! they count every replica's jobs, and the archives of a replica that died expire too. Without
//! one they count this process's jobs.

use super::{Job, JobLimits, Status, SubmitError};
use std::collections::HashMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Default of `--export-world-budget`, MiB.
pub const DEFAULT_WORLD_BUDGET_MB: u64 = 1024;
/// Default of `--export-disk-budget`, MiB.
pub const DEFAULT_DISK_BUDGET_MB: u64 = 4096;
/// Default of `--export-max-age`, seconds (one day).
pub const DEFAULT_MAX_AGE_S: u64 = 86_400;
/// `Retry-After` of a refusal while only queued or running jobs fill the budget, seconds.
const RETRY_WHILE_RUNNING_S: u64 = 5;

/// A budget that can refuse a job.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Budget {
    /// The archives of one world (`--export-world-budget`).
    World,
    /// The archives of the whole server (`--export-disk-budget`).
    Disk,
}

impl Budget {
    /// The budget's name in errors and in `/v1/info`: `export_world_budget` or
    /// `export_disk_budget`.
    pub fn name(self) -> &'static str {
        match self {
            Budget::World => "export_world_budget",
            Budget::Disk => "export_disk_budget",
        }
    }
}

impl Job {
    /// Bytes this job holds against the budgets now.
    pub fn charge(&self) -> u64 {
        match self.state.borrow().status {
            Status::Queued | Status::Running => self.reserved,
            Status::Done => self.stored.load(std::sync::atomic::Ordering::Relaxed),
            Status::Failed | Status::Expired => 0,
        }
    }

    /// Whether the job's archive is older than `max_age` at `now`.
    pub(super) fn is_stale(&self, max_age: Duration, now: Instant) -> bool {
        self.state.borrow().status == Status::Done
            && self
                .finished
                .get()
                .is_some_and(|t| now.saturating_duration_since(*t) >= max_age)
    }
}

/// Refuses a job bounded by `estimate` bytes that is larger than a budget of `limits`: it
/// could never be admitted.
pub(super) fn too_large(estimate: u64, limits: &JobLimits) -> Result<(), SubmitError> {
    for (budget, limit) in [
        (Budget::World, limits.world_budget_bytes),
        (Budget::Disk, limits.disk_budget_bytes),
    ] {
        if estimate > limit {
            return Err(SubmitError::TooLarge {
                budget,
                estimate,
                limit,
            });
        }
    }
    Ok(())
}

/// The refusal of a job bounded by `estimate` bytes that the store found over a budget
/// ([`crate::store::Admission::OverQuota`]): `Retry-After` is the seconds until the oldest done
/// archive charged to it expires, or a short wait while only queued and running jobs fill it.
pub(super) fn over_quota_in_store(
    world: bool,
    used: u64,
    oldest_done_s: Option<i64>,
    estimate: u64,
    limits: &JobLimits,
) -> SubmitError {
    let (budget, limit) = if world {
        (Budget::World, limits.world_budget_bytes)
    } else {
        (Budget::Disk, limits.disk_budget_bytes)
    };
    let now_s = crate::store::now_ms() / 1000;
    let max_age = i64::try_from(limits.max_age.as_secs()).unwrap_or(i64::MAX);
    let retry_after_s = oldest_done_s.map_or(RETRY_WHILE_RUNNING_S, |t| {
        t.saturating_add(max_age).saturating_sub(now_s).max(0) as u64 + 1
    });
    SubmitError::OverQuota {
        budget,
        used,
        estimate,
        limit,
        retry_after_s,
    }
}

/// Checks that a job of `world` bounded by `estimate` bytes fits both budgets of `limits`
/// beside the `jobs` already admitted (a server without a ledger: this process's jobs).
pub(super) fn admit(
    jobs: &HashMap<String, Arc<Job>>,
    world: &str,
    estimate: u64,
    limits: &JobLimits,
) -> Result<(), SubmitError> {
    for (budget, limit) in [
        (Budget::World, limits.world_budget_bytes),
        (Budget::Disk, limits.disk_budget_bytes),
    ] {
        if estimate > limit {
            return Err(SubmitError::TooLarge {
                budget,
                estimate,
                limit,
            });
        }
        let in_scope = |j: &&Arc<Job>| budget == Budget::Disk || j.world == world;
        let used: u64 = jobs.values().filter(in_scope).map(|j| j.charge()).sum();
        if used.saturating_add(estimate) > limit {
            let now = Instant::now();
            let retry_after_s = jobs
                .values()
                .filter(in_scope)
                .filter(|j| j.state.borrow().status == Status::Done)
                .filter_map(|j| j.finished.get())
                .map(|t| (*t + limits.max_age).saturating_duration_since(now))
                .min()
                .map_or(RETRY_WHILE_RUNNING_S, |d| d.as_secs() + 1);
            return Err(SubmitError::OverQuota {
                budget,
                used,
                estimate,
                limit,
                retry_after_s,
            });
        }
    }
    Ok(())
}
