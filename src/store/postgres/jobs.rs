//! The export jobs of the PostgreSQL store ([`super::super::jobs`]): the table of
//! `migrations/postgres/0002_export_jobs.sql`. A stale job is claimed with `SELECT … FOR UPDATE
//! SKIP LOCKED`, so replicas claiming at once each get a different job or none; admissions take
//! a transaction-scoped advisory lock ([`ADMISSION_LOCK`]), so they run one at a time.

use super::super::jobs::{refusal, Held, CHARGE_SQL};
use super::super::{Admission, JobQuota, JobRecord, JobUpdate, StoreError};
use super::{db, load_meta};
use deadpool_postgres::GenericClient;
use tokio_postgres::Row;

const JOB_COLUMNS: &str = "id, world_id, version, spec, status, done, total, error, reserved, \
                           bytes, owner, lease_until_ms, created_at, finished_at";

fn job_row(r: &Row) -> JobRecord {
    JobRecord {
        id: r.get(0),
        world: r.get(1),
        version: r.get::<_, i64>(2) as u64,
        spec: r.get(3),
        status: r.get(4),
        done: r.get::<_, i64>(5) as u64,
        total: r.get::<_, i64>(6) as u64,
        error: r.get(7),
        reserved: r.get::<_, i64>(8) as u64,
        bytes: r.get::<_, i64>(9) as u64,
        owner: r.get(10),
        lease_until_ms: r.get(11),
        created_at: r.get(12),
        finished_at: r.get(13),
    }
}

/// [`super::super::SceneStore::insert_job`].
pub(super) async fn insert(c: &impl GenericClient, job: &JobRecord) -> Result<(), StoreError> {
    load_meta(c, &job.world).await?;
    let inserted = c
        .execute(
            &format!(
                "INSERT INTO export_jobs ({JOB_COLUMNS}) VALUES
                 ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14)
                 ON CONFLICT (id) DO NOTHING"
            ),
            &[
                &job.id,
                &job.world,
                &(job.version as i64),
                &job.spec,
                &job.status,
                &(job.done as i64),
                &(job.total as i64),
                &job.error,
                &(job.reserved as i64),
                &(job.bytes as i64),
                &job.owner,
                &job.lease_until_ms,
                &job.created_at,
                &job.finished_at,
            ],
        )
        .await
        .map_err(db)?;
    if inserted == 0 {
        return Err(StoreError::Duplicate(job.id.clone()));
    }
    Ok(())
}

/// [`super::super::SceneStore::job`].
pub(super) async fn get(c: &impl GenericClient, id: &str) -> Result<Option<JobRecord>, StoreError> {
    Ok(c.query_opt(
        &format!("SELECT {JOB_COLUMNS} FROM export_jobs WHERE id = $1"),
        &[&id],
    )
    .await
    .map_err(db)?
    .map(|r| job_row(&r)))
}

/// [`super::super::SceneStore::update_job`].
pub(super) async fn update(
    c: &impl GenericClient,
    id: &str,
    owner: &str,
    u: &JobUpdate,
) -> Result<bool, StoreError> {
    let n = c
        .execute(
            "UPDATE export_jobs SET status = $3, done = $4, total = $5, error = $6, bytes = $7,
             lease_until_ms = $8, finished_at = $9 WHERE id = $1 AND owner = $2",
            &[
                &id,
                &owner,
                &u.status,
                &(u.done as i64),
                &(u.total as i64),
                &u.error,
                &(u.bytes as i64),
                &u.lease_until_ms,
                &u.finished_at,
            ],
        )
        .await
        .map_err(db)?;
    Ok(n == 1)
}

/// [`super::super::SceneStore::claim_job`]: one statement, so it needs no transaction of its own.
pub(super) async fn claim(
    c: &impl GenericClient,
    owner: &str,
    now_ms: i64,
    lease_until_ms: i64,
) -> Result<Option<JobRecord>, StoreError> {
    Ok(c.query_opt(
        &format!(
            "UPDATE export_jobs SET owner = $1, lease_until_ms = $3, status = 'queued', done = 0
                 WHERE id = (
                     SELECT id FROM export_jobs
                     WHERE status IN ('queued', 'running') AND lease_until_ms < $2
                     ORDER BY created_at, id LIMIT 1
                     FOR UPDATE SKIP LOCKED
                 ) RETURNING {JOB_COLUMNS}"
        ),
        &[&owner, &now_ms, &lease_until_ms],
    )
    .await
    .map_err(db)?
    .map(|r| job_row(&r)))
}

/// The advisory lock key admissions hold for their transaction ("strata export admission").
pub(super) const ADMISSION_LOCK: i64 = 0x5354_5241_5441_4558;

/// [`super::super::SceneStore::admit_job`], in the transaction `tx`.
pub(super) async fn admit(
    tx: &deadpool_postgres::Transaction<'_>,
    job: &JobRecord,
    quota: &JobQuota,
) -> Result<Admission, StoreError> {
    tx.execute("SELECT pg_advisory_xact_lock($1)", &[&ADMISSION_LOCK])
        .await
        .map_err(db)?;
    load_meta(tx, &job.world).await?;
    let sums = |filter: &'static str| async move {
        let r = tx
            .query_one(
                &format!(
                    "SELECT COALESCE(SUM({CHARGE_SQL}), 0)::BIGINT,
                     MIN(CASE WHEN status = 'done' THEN finished_at END)
                     FROM export_jobs WHERE {filter}"
                ),
                &[&job.world],
            )
            .await
            .map_err(db)?;
        Ok::<_, StoreError>((r.get::<_, i64>(0) as u64, r.get::<_, Option<i64>>(1)))
    };
    let held = Held {
        world: sums("world_id = $1").await?,
        all: sums("$1::TEXT IS NOT NULL").await?,
        queued: tx
            .query_one(
                "SELECT COUNT(*) FROM export_jobs WHERE status = 'queued'",
                &[],
            )
            .await
            .map_err(db)?
            .get::<_, i64>(0) as u64,
    };
    if let Some(refused) = refusal(job.reserved, quota, &held) {
        return Ok(refused);
    }
    insert(tx, job).await?;
    Ok(Admission::Admitted)
}

/// [`super::super::SceneStore::expire_jobs`]: one statement.
pub(super) async fn expire(
    c: &impl GenericClient,
    before_s: i64,
) -> Result<Vec<String>, StoreError> {
    Ok(c.query(
        "UPDATE export_jobs SET status = 'expired'
             WHERE status = 'done' AND finished_at <= $1 RETURNING id",
        &[&before_s],
    )
    .await
    .map_err(db)?
    .iter()
    .map(|r| r.get(0))
    .collect())
}
