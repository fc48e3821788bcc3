//! Issue 18, item 4: export archives held on disk are bounded per world and per server, and old
//! archives expire. Queued and running jobs count at their bound (`max_bytes`), finished ones at
//! their size; a job that does not fit is 429 `export_quota_exceeded` naming the budget, with
//! `Retry-After`; an expired archive is deleted and answers 410 `job_expired`. The flags
//! (`--export-world-budget`, `--export-disk-budget`, `--export-max-age`) reach `/v1/info` of the
//! real binary. Two replicas sharing one store (SQLite, PostgreSQL) count each other's jobs
//! against the budgets, and either expires the other's archives, one whose replica stopped
//! included.

use axum::http::StatusCode;
use axum::Router;
use serde_json::{json, Value};
use std::sync::Arc;
use std::time::Duration;
use strata::compute::Compute;
use strata::export::{size::archive_bound, ExportSpec, Product, Shard};
use strata::server::jobs::{JobLimits, Ledger};
use strata::server::{app, AppState};
use strata::store::{PostgresStore, SceneStore, SqliteStore};
use strata::terrain::{WorldParams, WorldPlan};

mod common;

use common::oneshot::{
    get_as as get, post_json as post, private_world as world, wait_job_done as wait_done, Reply,
};

/// Two binary tiles at LOD 0.
fn body() -> Value {
    json!({"lod": 0, "region": [0, 0, 2, 1], "products": ["tiles"], "formats": ["bin"]})
}

/// The bound the server reserves for [`body`].
fn bound() -> u64 {
    let plan = WorldPlan::new(1, WorldParams::default()).expect("plan");
    let spec = ExportSpec {
        lod: 0,
        x0: 0,
        z0: 0,
        x1: 2,
        z1: 1,
        products: vec![Product::Tiles],
        formats: vec!["bin".into()],
        ptex_res: None,
    };
    archive_bound(&plan, &spec, Shard::WHOLE)
}

async fn export(app: &Router, id: &str, token: &str) -> Reply {
    post(
        app,
        &format!("/v1/worlds/{id}/exports"),
        Some(token),
        &body(),
    )
    .await
}

fn refused(r: &Reply, budget: &str) {
    r.error(
        StatusCode::TOO_MANY_REQUESTS,
        "export_quota_exceeded",
        Some(budget),
    );
    let secs: u64 = r
        .header("retry-after")
        .and_then(|v| v.parse().ok())
        .expect("a Retry-After of whole seconds");
    assert!(secs >= 1, "Retry-After: {secs}");
}

#[tokio::test]
async fn queued_running_and_stored_archives_count_against_the_world_and_disk_budgets() {
    let dir = tempfile::tempdir().expect("tmp");
    let b = bound();
    let limits = JobLimits {
        world_budget_bytes: 2 * b + b / 2,
        disk_budget_bytes: 3 * b + b / 2,
        ..JobLimits::default()
    };
    let app = app(AppState::new(Compute::cpu())
        .with_job_limits(limits)
        .with_jobs_dir(dir.path()));
    let (one, one_admin) = world(&app, 1).await;
    let (two, two_admin) = world(&app, 2).await;
    let first = export(&app, &one, &one_admin).await;
    assert_eq!(first.status_is(StatusCode::ACCEPTED).json()["max_bytes"], b);
    export(&app, &one, &one_admin)
        .await
        .status_is(StatusCode::ACCEPTED);
    // World one holds two bounds, queued, running or done: a third does not fit its budget.
    refused(&export(&app, &one, &one_admin).await, "export_world_budget");
    // Another world has a budget of its own, but the server's is shared.
    export(&app, &two, &two_admin)
        .await
        .status_is(StatusCode::ACCEPTED);
    refused(&export(&app, &two, &two_admin).await, "export_disk_budget");
    // Finished archives still count: they are on disk until they expire.
    let url = first.json()["status_url"].as_str().expect("url").to_owned();
    wait_done(&app, &url, &one_admin).await;
    refused(&export(&app, &one, &one_admin).await, "export_world_budget");
}

#[tokio::test]
async fn archives_expire_after_max_age_and_free_their_budget() {
    let dir = tempfile::tempdir().expect("tmp");
    let b = bound();
    let limits = JobLimits {
        world_budget_bytes: b + b / 2,
        max_age: Duration::from_secs(1),
        ..JobLimits::default()
    };
    let app = app(AppState::new(Compute::cpu())
        .with_job_limits(limits)
        .with_jobs_dir(dir.path()));
    let (id, admin) = world(&app, 3).await;
    let started = export(&app, &id, &admin)
        .await
        .status_is(StatusCode::ACCEPTED)
        .json();
    let (status_url, download_url) = (
        started["status_url"].as_str().expect("url"),
        started["download_url"].as_str().expect("url"),
    );
    wait_done(&app, status_url, &admin).await;
    get(&app, download_url, &admin)
        .await
        .status_is(StatusCode::OK);
    let archive = dir
        .path()
        .join(format!("{}.tar", started["job"].as_str().expect("job")));
    assert!(archive.exists(), "{} is written", archive.display());
    let r = export(&app, &id, &admin).await;
    refused(&r, "export_world_budget");
    let wait: u64 = r
        .header("retry-after")
        .and_then(|v| v.parse().ok())
        .expect("Retry-After");
    assert!(
        wait <= 2,
        "the archive expires within a second or two, not {wait} s"
    );
    tokio::time::sleep(Duration::from_millis(1200)).await;
    get(&app, download_url, &admin)
        .await
        .error(StatusCode::GONE, "job_expired", None);
    let v = get(&app, status_url, &admin)
        .await
        .status_is(StatusCode::OK)
        .json();
    assert_eq!(v["status"], "expired", "{v}");
    assert!(!archive.exists(), "the expired archive is deleted");
    export(&app, &id, &admin)
        .await
        .status_is(StatusCode::ACCEPTED);
}

#[test]
fn the_flags_reach_v1_info() {
    let info = |args: &[&str]| {
        let server = common::start(args, &[]);
        let (status, body) = common::raw::get(&server.addr, "/v1/info");
        assert_eq!(status, 200);
        let v: Value = serde_json::from_slice(&body).expect("json");
        v["limits"].clone()
    };
    let data = tempfile::tempdir().expect("tmp");
    let data = data.path().to_str().expect("utf-8 path");
    let set = info(&[
        "--data",
        data,
        "--export-world-budget",
        "3",
        "--export-disk-budget",
        "5",
        "--export-max-age",
        "7",
    ]);
    assert_eq!(set["export_world_budget_bytes"], 3 << 20);
    assert_eq!(set["export_disk_budget_bytes"], 5 << 20);
    assert_eq!(set["export_max_age_s"], 7);
    let defaults = info(&["--data", data]);
    assert_eq!(defaults["export_world_budget_bytes"], 1024u64 << 20);
    assert_eq!(defaults["export_disk_budget_bytes"], 4096u64 << 20);
    assert_eq!(defaults["export_max_age_s"], 86_400);
    assert_eq!(defaults["max_export_tiles"], 65_536);
}

/// A replica: its own handle on the shared store, its own owner id and job queue, the shared
/// archive directory.
fn replica(store: Arc<dyn SceneStore>, dir: &std::path::Path, limits: JobLimits) -> AppState {
    let ledger = Ledger::new(store.clone(), Duration::from_secs(20)).expect("ledger");
    AppState::new(Compute::cpu())
        .with_worlds(store, None)
        .with_job_limits(limits)
        .with_jobs_dir(dir)
        .with_job_ledger(ledger)
}

/// Waits until the store holds job `id` as done.
async fn stored_done(store: &dyn SceneStore, id: &str) {
    let deadline = tokio::time::Instant::now() + Duration::from_secs(60);
    while store.job(id).await.expect("job").map(|r| r.status) != Some("done".into()) {
        assert!(
            tokio::time::Instant::now() < deadline,
            "job {id} not stored done"
        );
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

/// Two replicas on one store: the world's budget counts both replicas' jobs; once the first
/// replica has gone, the second expires its archive (deleted from the shared directory, the job
/// answered `expired` and its archive 410), and the budget is free again.
async fn replicas_share_the_budgets_and_the_expiry(a: Arc<dyn SceneStore>, b: Arc<dyn SceneStore>) {
    let dir = tempfile::tempdir().expect("tmp");
    let bd = bound();
    let limits = JobLimits {
        world_budget_bytes: 2 * bd + bd / 2,
        max_age: Duration::from_secs(1),
        ..JobLimits::default()
    };
    let (state_a, state_b) = (
        replica(a.clone(), dir.path(), limits),
        replica(b.clone(), dir.path(), limits),
    );
    let (app_a, app_b) = (app(state_a.clone()), app(state_b.clone()));
    let (id, admin) = world(&app_a, 4).await;
    let first = export(&app_a, &id, &admin)
        .await
        .status_is(StatusCode::ACCEPTED)
        .json();
    let first_job = first["job"].as_str().expect("job").to_owned();
    wait_done(&app_a, first["status_url"].as_str().expect("url"), &admin).await;
    stored_done(&*b, &first_job).await;
    // Replica B holds none of A's jobs, yet counts A's archive: one more fits, a third does not,
    // on either replica.
    export(&app_b, &id, &admin)
        .await
        .status_is(StatusCode::ACCEPTED);
    refused(&export(&app_b, &id, &admin).await, "export_world_budget");
    refused(&export(&app_a, &id, &admin).await, "export_world_budget");
    // Replica A goes; its archive is left in the shared directory until B expires it.
    drop(app_a);
    drop(state_a);
    let archive = dir.path().join(format!("{first_job}.tar"));
    assert!(archive.exists(), "{} is written", archive.display());
    let deadline = tokio::time::Instant::now() + Duration::from_secs(30);
    while archive.exists() {
        assert!(
            tokio::time::Instant::now() < deadline,
            "the archive of the replica that went never expired"
        );
        state_b.jobs.expire_shared().await;
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    assert_eq!(
        b.job(&first_job).await.expect("job").map(|r| r.status),
        Some("expired".into())
    );
    get(&app_b, &format!("/v1/jobs/{first_job}/archive"), &admin)
        .await
        .error(StatusCode::GONE, "job_expired", None);
    export(&app_b, &id, &admin)
        .await
        .status_is(StatusCode::ACCEPTED);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn replicas_share_the_budgets_and_the_expiry_on_sqlite() {
    let data = tempfile::tempdir().expect("tmp");
    let open =
        || Arc::new(SqliteStore::open_in_dir(data.path()).expect("open")) as Arc<dyn SceneStore>;
    replicas_share_the_budgets_and_the_expiry(open(), open()).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn replicas_share_the_budgets_and_the_expiry_on_postgres() {
    let url = common::postgres::database().await;
    let open = || async {
        Arc::new(PostgresStore::connect(&url).await.expect("connect")) as Arc<dyn SceneStore>
    };
    replicas_share_the_budgets_and_the_expiry(open().await, open().await).await;
}
