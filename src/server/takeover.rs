//! Taking over the export jobs of replicas that died ([`super::jobs::ledger`]): every half
//! lease, this replica claims the queued or running jobs whose owner has not renewed its lease
//! ([`crate::store::SceneStore::claim_job`]), while its own queue has room, and redoes each from
//! the start. The job's world version is read from the store and its edits solved here as
//! `POST /v1/worlds/{id}/exports` did, so the archive has the same bytes.

use super::jobs::ledger::StoredSpec;
use super::jobs::Status;
use super::AppState;
use crate::store::{now_ms, JobRecord, JobUpdate};

/// Claims and resumes stale jobs until the process ends; returns at once without a ledger.
pub async fn run(st: AppState) {
    let Some(ledger) = st.jobs.ledger().cloned() else {
        return;
    };
    let every = ledger.lease / 2;
    loop {
        tokio::time::sleep(every).await;
        while st.jobs.counts().0 < st.jobs.limits().max_queued {
            let lease_end = now_ms().saturating_add(ledger.lease.as_millis() as i64);
            let record = match ledger
                .store
                .claim_job(&ledger.owner, now_ms(), lease_end)
                .await
            {
                Ok(Some(r)) => r,
                Ok(None) => break,
                Err(e) => {
                    tracing::warn!("cannot claim stale export jobs: {e}");
                    break;
                }
            };
            if let Err(e) = resume(&st, &record).await {
                tracing::warn!(job = %record.id, "cannot take over the export job: {e}");
                let failed = JobUpdate {
                    status: Status::Failed.as_str().into(),
                    done: 0,
                    total: record.total,
                    error: Some(e),
                    bytes: 0,
                    lease_until_ms: lease_end,
                    finished_at: Some(now_ms() / 1000),
                };
                if let Err(e) = ledger
                    .store
                    .update_job(&record.id, &ledger.owner, &failed)
                    .await
                {
                    tracing::warn!(job = %record.id, "cannot store the failure: {e}");
                }
            }
        }
    }
}

/// Rebuilds the claimed job `record` (plan and edits of its world version) and queues it here.
async fn resume(st: &AppState, record: &JobRecord) -> Result<(), String> {
    let StoredSpec { spec, shard } = StoredSpec::parse(&record.spec)?;
    let view = st
        .worlds
        .view_of(&record.world, record.version)
        .await
        .map_err(|e| e.to_string())?;
    let edits = view.edits_over(st, &spec.keys(shard)).await;
    st.jobs
        .resume(record, view.plan.clone(), edits, spec, shard);
    Ok(())
}
