//! Export jobs as the store keeps them, so that every replica sharing the store answers for any
//! job and a job whose replica died is taken over by another (`src/server/jobs/ledger.rs`).
//!
//! A job row is owned by one replica (`owner`, random per process) until `lease_until_ms`; the
//! owner renews the lease while the job is queued or running, and writes its progress with it
//! ([`SceneStore::update_job`], refused once another replica has claimed the row). A queued or
//! running job whose lease has passed is claimed by exactly one caller of
//! [`SceneStore::claim_job`] (PostgreSQL: `SELECT … FOR UPDATE SKIP LOCKED`; SQLite: its one
//! writer), which redoes it from the start: the archive is a pure function of the job's world,
//! version and spec, so it is the same bytes.
//!
//! Quotas ([`SceneStore::admit_job`]) are counted over every job the store holds, so they hold
//! across replicas: a new job is stored only if it fits the per-world and whole-store byte
//! budgets beside the jobs already stored (queued and running ones at their `reserved` bound,
//! done ones at their archive's `bytes`, failed and expired ones at nothing) and if fewer than
//! the limit of jobs are queued; admissions are serialised (PostgreSQL: a transaction-scoped
//! advisory lock; SQLite: its one writer), so two replicas admitting at once cannot both take
//! the last room. Expiry ([`SceneStore::expire_jobs`]) is the store's too: whichever replica
//! asks marks the old done jobs `expired` and deletes their archives, those of a replica that
//! died included.
//!
//! Times: `lease_until_ms` in milliseconds since the Unix epoch, given by the caller (so all
//! replicas compare against their own clocks; keep them in sync, as leases of seconds need);
//! `created_at` and `finished_at` in seconds since the Unix epoch.
//!
//! [`SceneStore::update_job`]: super::SceneStore::update_job
//! [`SceneStore::claim_job`]: super::SceneStore::claim_job
//! [`SceneStore::admit_job`]: super::SceneStore::admit_job
//! [`SceneStore::expire_jobs`]: super::SceneStore::expire_jobs

/// Where a job is, as stored: `queued`, `running`, `done`, `failed` or `expired`.
pub const JOB_STATUSES: [&str; 5] = ["queued", "running", "done", "failed", "expired"];

/// One export job.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JobRecord {
    /// Job id (32 hex digits).
    pub id: String,
    /// The world exported.
    pub world: String,
    /// The world version exported.
    pub version: u64,
    /// What is exported: the server's JSON of the export spec and shard, kept as text.
    pub spec: String,
    /// One of [`JOB_STATUSES`].
    pub status: String,
    /// Tiles written.
    pub done: u64,
    /// Tiles of the job.
    pub total: u64,
    /// Why it failed.
    pub error: Option<String>,
    /// Upper bound of the archive, bytes.
    pub reserved: u64,
    /// The archive's size once done, bytes (0 before).
    pub bytes: u64,
    /// The replica that runs it.
    pub owner: String,
    /// Until when the owner holds it, milliseconds since the Unix epoch.
    pub lease_until_ms: i64,
    /// When it was admitted, seconds since the Unix epoch.
    pub created_at: i64,
    /// When it was done or failed, seconds since the Unix epoch.
    pub finished_at: Option<i64>,
}

/// What the owner of a job writes ([`super::SceneStore::update_job`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JobUpdate {
    /// One of [`JOB_STATUSES`].
    pub status: String,
    /// Tiles written.
    pub done: u64,
    /// Tiles of the job.
    pub total: u64,
    /// Why it failed.
    pub error: Option<String>,
    /// The archive's size, bytes.
    pub bytes: u64,
    /// The renewed lease, milliseconds since the Unix epoch.
    pub lease_until_ms: i64,
    /// When it was done or failed, seconds since the Unix epoch.
    pub finished_at: Option<i64>,
}

/// Milliseconds since the Unix epoch (0 if the clock is before it).
pub fn now_ms() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_millis() as i64)
        .unwrap_or(0)
}

/// The limits a new job is admitted under ([`super::SceneStore::admit_job`]), over every job
/// the store holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JobQuota {
    /// Bytes the jobs of one world may hold.
    pub world_bytes: u64,
    /// Bytes all jobs together may hold.
    pub disk_bytes: u64,
    /// Jobs that may be queued; one more is refused.
    pub max_queued: u64,
}

/// What [`super::SceneStore::admit_job`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Admission {
    /// The job is stored.
    Admitted,
    /// `queued` jobs are queued already.
    TooMany {
        /// Jobs queued.
        queued: u64,
    },
    /// The job does not fit a budget beside `used` bytes.
    OverQuota {
        /// Whether the world's budget refused it (else the whole store's).
        world: bool,
        /// Bytes charged to that budget.
        used: u64,
        /// When the oldest done job charged to it finished, seconds since the Unix epoch.
        oldest_done_s: Option<i64>,
    },
}

/// What a job row holds against the budgets, as SQL over `export_jobs`.
pub(crate) const CHARGE_SQL: &str = "CASE WHEN status IN ('queued', 'running') THEN reserved \
                                     WHEN status = 'done' THEN bytes ELSE 0 END";

/// What the stored jobs hold: `(bytes, oldest done finished_at)` of the job's world and of all
/// jobs, and how many are queued.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Held {
    pub world: (u64, Option<i64>),
    pub all: (u64, Option<i64>),
    pub queued: u64,
}

/// The refusal of a job bounded by `reserved` bytes under `quota` beside `held`, if any: the
/// world's budget first, then the store's, then the queue.
pub(crate) fn refusal(reserved: u64, quota: &JobQuota, held: &Held) -> Option<Admission> {
    for (world, limit, (used, oldest)) in [
        (true, quota.world_bytes, held.world),
        (false, quota.disk_bytes, held.all),
    ] {
        if used.saturating_add(reserved) > limit {
            return Some(Admission::OverQuota {
                world,
                used,
                oldest_done_s: oldest,
            });
        }
    }
    (held.queued >= quota.max_queued).then_some(Admission::TooMany {
        queued: held.queued,
    })
}
