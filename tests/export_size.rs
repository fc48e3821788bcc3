//! Issue 18, finding 3: an export's archive size is bounded before the job is admitted. The
//! bound the server reserves (`max_bytes` of the 202 answer,
//! `strata::export::size::archive_bound`) is never below the real archive, and an export whose
//! bound exceeds a disk budget is refused with 400 `export_too_large` naming `/region` and the
//! budget's bytes, before any tile is synthesised.

use axum::http::StatusCode;
use axum::Router;
use serde_json::{json, Value};
use strata::compute::Compute;
use strata::server::jobs::JobLimits;
use strata::server::{app, AppState};

mod common;

use common::oneshot::{
    get_as as get, post_json as post, private_world as world, wait_job_done as wait_done,
};

/// Runs an export to the end: the 202 answer and the archive.
async fn export(app: &Router, id: &str, token: &str, body: &Value) -> (Value, Vec<u8>) {
    let started = post(app, &format!("/v1/worlds/{id}/exports"), Some(token), body)
        .await
        .status_is(StatusCode::ACCEPTED)
        .json();
    let status_url = started["status_url"].as_str().expect("status url");
    wait_done(app, status_url, token).await;
    let url = started["download_url"].as_str().expect("download url");
    let archive = get(app, url, token)
        .await
        .status_is(StatusCode::OK)
        .body
        .clone();
    (started, archive)
}

#[tokio::test]
async fn the_reserved_bound_is_never_below_the_real_archive() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = app(AppState::new(Compute::cpu()).with_jobs_dir(dir.path()));
    let (id, admin) = world(&app, 42).await;
    for body in [
        json!({"lod": 2, "region": [-1, -1, 1, 1], "products": ["tiles", "scatter"],
               "formats": ["json", "bin", "png", "glb"]}),
        json!({"lod": 0, "region": [3, -2, 6, -1], "products": ["tiles"], "formats": ["bin"]}),
        json!({"lod": 5, "region": [0, 0, 3, 2], "products": ["scatter", "tiles"],
               "formats": ["png", "json"], "shard": "2/3"}),
    ] {
        let (started, archive) = export(&app, &id, &admin, &body).await;
        let bound = started["max_bytes"].as_u64().expect("max_bytes");
        let len = archive.len() as u64;
        assert!(
            len <= bound,
            "{body}: the archive has {len} bytes, above its bound {bound}"
        );
        assert!(
            bound <= 4 * len,
            "{body}: the bound {bound} is more than 4× the archive's {len} bytes"
        );
    }
}

#[tokio::test]
async fn an_export_larger_than_a_budget_is_refused_naming_the_region_and_the_limit() {
    let mib = 1u64 << 20;
    for (limits, budget, limit) in [
        (
            JobLimits {
                world_budget_bytes: mib,
                ..JobLimits::default()
            },
            "export_world_budget",
            mib,
        ),
        (
            JobLimits {
                disk_budget_bytes: 2 * mib,
                ..JobLimits::default()
            },
            "export_disk_budget",
            2 * mib,
        ),
    ] {
        let dir = tempfile::tempdir().expect("tmp");
        let app = app(AppState::new(Compute::cpu())
            .with_job_limits(limits)
            .with_jobs_dir(dir.path()));
        let (id, admin) = world(&app, 7).await;
        // 256 binary tiles take about 40 MB, whatever they hold.
        let body = json!({"lod": 0, "region": [0, 0, 16, 16], "products": ["tiles"],
                          "formats": ["bin"]});
        let r = post(
            &app,
            &format!("/v1/worlds/{id}/exports"),
            Some(&admin),
            &body,
        )
        .await;
        r.error(StatusCode::BAD_REQUEST, "export_too_large", Some("/region"));
        let message = r.json()["error"]["message"]
            .as_str()
            .expect("message")
            .to_owned();
        assert!(
            message.contains(budget) && message.contains(&limit.to_string()),
            "{message}"
        );
        // Refused before any work: no job, no file.
        assert_eq!(std::fs::read_dir(dir.path()).map_or(0, |d| d.count()), 0);
        // A smaller export of the same world fits.
        let small = json!({"lod": 0, "region": [0, 0, 2, 1], "products": ["tiles"],
                           "formats": ["bin"]});
        post(
            &app,
            &format!("/v1/worlds/{id}/exports"),
            Some(&admin),
            &small,
        )
        .await
        .status_is(StatusCode::ACCEPTED);
    }
}
