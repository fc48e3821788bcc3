//! Tests of the export job queue.

use super::*;
use crate::export::Product;
use crate::terrain::WorldParams;

fn spec(x1: i64) -> ExportSpec {
    ExportSpec {
        lod: 3,
        x0: 0,
        z0: 0,
        x1,
        z1: 1,
        products: vec![Product::Tiles],
        formats: vec!["bin".into()],
        ptex_res: None,
    }
}

async fn finished(job: &Job) -> Progress {
    let mut rx = job.subscribe();
    let p = rx
        .wait_for(|p| p.status.is_finished())
        .await
        .expect("sender alive");
    p.clone()
}

async fn started(job: &Job) {
    job.subscribe()
        .wait_for(|p| p.status != Status::Queued)
        .await
        .expect("sender alive");
}

#[tokio::test]
async fn jobs_queue_run_finish_and_are_evicted() {
    let dir = tempfile::tempdir().expect("tempdir");
    let plan = Arc::new(WorldPlan::new(3, WorldParams::default()).expect("plan"));
    let limits = JobLimits {
        max_running: 1,
        max_queued: 1,
        max_finished: 2,
        ..JobLimits::default()
    };
    let jobs = Jobs::new(dir.path().join("exports"), limits);
    // A long job holds the only run slot, the next one waits, a third is refused.
    let long = jobs
        .submit("w", 1, plan.clone(), spec(400), Shard::WHOLE)
        .expect("long");
    started(&long).await;
    let waiting = jobs
        .submit("w", 1, plan.clone(), spec(2), Shard::WHOLE)
        .expect("queued");
    assert_eq!(waiting.progress().status, Status::Queued);
    assert_eq!(waiting.progress().total, 2);
    assert!(waiting.archive().is_none());
    assert!(matches!(
        jobs.submit("w", 1, plan.clone(), spec(1), Shard::WHOLE),
        Err(SubmitError::TooMany {
            queued: 1,
            limit: 1
        })
    ));
    long.cancel();
    let p = finished(&long).await;
    assert_eq!(p.status, Status::Failed);
    assert!(
        p.error.as_deref().is_some_and(|e| e.contains("cancelled")),
        "{p:?}"
    );
    assert!(!long.path.with_extension("tar.part").exists());
    let p = finished(&waiting).await;
    assert_eq!((p.status, p.done, p.total), (Status::Done, 2, 2), "{p:?}");
    let path = waiting.archive().expect("archive").to_path_buf();
    let members = export::tar::read_members(&std::fs::read(&path).expect("read")).expect("members");
    assert_eq!(members.len(), 3);
    assert_eq!(jobs.counts(), (0, 0, 2));
    // Admitting a job keeps at most `max_finished` finished ones: the oldest (`long`) goes,
    // and with the next admission `waiting` and its archive go too.
    let third = jobs
        .submit("w", 1, plan.clone(), spec(1), Shard::WHOLE)
        .expect("third");
    assert!(jobs.get(&long.id).is_none() && jobs.get(&waiting.id).is_some());
    finished(&third).await;
    let fourth = jobs
        .submit("w", 1, plan.clone(), spec(1), Shard::WHOLE)
        .expect("fourth");
    assert!(jobs.get(&waiting.id).is_none());
    finished(&fourth).await;
    for _ in 0..100 {
        if !path.exists() {
            break;
        }
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
    assert!(!path.exists(), "the evicted archive is deleted");
    // A stray archive of a previous process is swept; the jobs' own are kept.
    let stray = jobs.dir().join(format!("{}.tar", "ab".repeat(16)));
    std::fs::write(&stray, b"x").expect("write");
    assert_eq!(jobs.sweep().await.expect("sweep"), 1);
    assert!(!stray.exists() && fourth.archive().expect("done").exists());
}

#[tokio::test]
async fn dropping_the_queue_cancels_its_jobs() {
    let dir = tempfile::tempdir().expect("tempdir");
    let plan = Arc::new(WorldPlan::new(3, WorldParams::default()).expect("plan"));
    let limits = JobLimits {
        max_running: 1,
        ..JobLimits::default()
    };
    let jobs = Jobs::new(dir.path(), limits);
    let running = jobs
        .submit("w", 1, plan.clone(), spec(400), Shard::WHOLE)
        .expect("running");
    started(&running).await;
    let queued = jobs
        .submit("w", 1, plan, spec(400), Shard::WHOLE)
        .expect("queued");
    drop(jobs);
    for job in [&running, &queued] {
        let p = tokio::time::timeout(Duration::from_secs(60), finished(job))
            .await
            .expect("the job stops");
        assert_eq!(p.status, Status::Failed, "{p:?}");
    }
}

#[test]
fn job_ids() {
    let id = new_job_id().expect("id");
    assert!(valid_job_id(&id), "{id}");
    assert_ne!(id, new_job_id().expect("id"));
    for bad in [
        "",
        "AB".repeat(16).as_str(),
        "../etc/passwd",
        &"a".repeat(33),
    ] {
        assert!(!valid_job_id(bad), "{bad}");
    }
}
