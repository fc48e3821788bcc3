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
//! Times: `lease_until_ms` in milliseconds since the Unix epoch, given by the caller (so all
//! replicas compare against their own clocks; keep them in sync, as leases of seconds need);
//! `created_at` and `finished_at` in seconds since the Unix epoch.
//!
//! [`SceneStore::update_job`]: super::SceneStore::update_job
//! [`SceneStore::claim_job`]: super::SceneStore::claim_job

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
