//! Export jobs over HTTP (`POST /v1/worlds/{id}/exports`, `/v1/jobs/{job}…`), driven through
//! `strata::server::app` with `tower::ServiceExt::oneshot`; archives go to a temporary directory.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::time::Duration;
use strata::compute::Compute;
use strata::export::{self, tar::read_members, ExportSpec, Product, Shard};
use strata::server::jobs::{JobLimits, Status};
use strata::server::{app, AppState};
use strata::terrain::{WorldParams, WorldPlan};

/// Longest wait for one export job of these tests.
const JOB_TIMEOUT: Duration = Duration::from_secs(300);

mod common;
use common::oneshot::Reply;

/// One request with an optional bearer token and JSON body; the whole exchange must end within
/// [`JOB_TIMEOUT`].
async fn send(
    app: &Router,
    method: Method,
    uri: &str,
    token: Option<&str>,
    body: Option<&[u8]>,
) -> Reply {
    let mut headers = Vec::new();
    if let Some(t) = token {
        headers.push(("authorization", format!("Bearer {t}")));
    }
    if body.is_some() {
        headers.push(("content-type", "application/json".to_string()));
    }
    tokio::time::timeout(
        JOB_TIMEOUT,
        common::oneshot::send(app, method, uri, &headers, body),
    )
    .await
    .expect("the reply ends in time")
}

async fn get(app: &Router, uri: &str, token: Option<&str>) -> Reply {
    send(app, Method::GET, uri, token, None).await
}

async fn post(app: &Router, uri: &str, token: Option<&str>, body: &Value) -> Reply {
    let bytes = serde_json::to_vec(body).expect("json");
    send(app, Method::POST, uri, token, Some(&bytes)).await
}

fn service(dir: &std::path::Path) -> Router {
    app(AppState::new(Compute::cpu()).with_jobs_dir(dir))
}

/// A world made from a bare seed (private): its id and admin token.
async fn world(app: &Router, seed: u64) -> (String, String) {
    let r = post(app, "/v1/worlds", None, &json!({ "seed": seed })).await;
    let v = r.status_is(StatusCode::CREATED).json();
    (
        v["id"].as_str().expect("id").to_string(),
        v["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}

/// Starts an export; the 202 answer.
async fn start(app: &Router, id: &str, token: Option<&str>, body: &Value) -> Value {
    let r = post(app, &format!("/v1/worlds/{id}/exports"), token, body).await;
    let v = r.status_is(StatusCode::ACCEPTED).json();
    let job = v["job"].as_str().expect("job id");
    assert_eq!(v["status_url"], format!("/v1/jobs/{job}"));
    assert_eq!(v["events_url"], format!("/v1/jobs/{job}/events"));
    assert_eq!(v["download_url"], format!("/v1/jobs/{job}/archive"));
    assert_eq!(r.header("location"), v["status_url"].as_str());
    v
}

/// Polls a job's status until it has finished.
async fn wait(app: &Router, status_url: &str, token: Option<&str>) -> Value {
    let deadline = tokio::time::Instant::now() + JOB_TIMEOUT;
    loop {
        let v = get(app, status_url, token)
            .await
            .status_is(StatusCode::OK)
            .json();
        if v["status"] == "done" || v["status"] == "failed" {
            return v;
        }
        assert!(tokio::time::Instant::now() < deadline, "job stuck: {v}");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

/// The `(event, data)` pairs of a `text/event-stream` body.
fn sse(body: &[u8]) -> Vec<(String, Value)> {
    let text = std::str::from_utf8(body).expect("utf-8");
    text.split("\n\n")
        .filter_map(|block| {
            let mut name = None;
            let mut data = String::new();
            for line in block.lines() {
                if let Some(n) = line.strip_prefix("event:") {
                    name = Some(n.trim().to_string());
                } else if let Some(d) = line.strip_prefix("data:") {
                    data.push_str(d.trim_start());
                }
            }
            let data = serde_json::from_str(&data).ok()?;
            Some((name?, data))
        })
        .collect()
}

/// The member names of an export in canonical order: rows, columns, products, formats.
fn expected_names(lod: u32, [x0, z0, x1, z1]: [i64; 4], formats: &[&str]) -> Vec<String> {
    let mut names = Vec::new();
    for z in z0..z1 {
        for x in x0..x1 {
            for f in formats {
                names.push(format!("tiles/{lod}/{x}/{z}.{f}"));
            }
            names.push(format!("scatter/{lod}/{x}/{z}.json"));
        }
    }
    names.push("manifest.json".into());
    names
}

#[tokio::test]
async fn export_job_follows_over_sse_and_matches_the_http_api() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let (id, admin) = world(&app, 42).await;
    let tok = Some(admin.as_str());
    // Version 2 has other world settings and an authored region, so the export must pick the
    // version asked for and carry the region's edit as the tile routes do.
    let patch = json!([{"op": "replace", "path": "/world/sea_level_m", "value": 20},
        {"op": "add", "path": "/regions/-", "value": {"id": "peak",
         "bbox": {"min": [0.0, 0.0], "max": [200.0, 200.0]}, "samples": 65,
         "ops": [{"op": "elevation", "shape": {"point": [100.0, 100.0]}, "elevation_m": 500.0, "radius_m": 8.0}]}}]);
    common::oneshot::send(
        &app,
        Method::POST,
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("authorization", format!("Bearer {admin}")),
            ("content-type", "application/json-patch+json".to_string()),
        ],
        Some(patch.to_string().as_bytes()),
    )
    .await
    .ok();

    let region = [-1i64, 0, 2, 2];
    let started = start(
        &app,
        &id,
        tok,
        &json!({"lod": 2, "region": region, "products": ["tiles", "scatter"],
                "formats": ["bin", "png"], "v": 2}),
    )
    .await;
    assert_eq!(
        (&started["version"], &started["total"]),
        (&json!(2), &json!(6))
    );

    // Follow the job over SSE to the end.
    let events_url = started["events_url"].as_str().expect("url");
    let r = get(&app, events_url, tok).await;
    r.status_is(StatusCode::OK);
    assert!(r
        .header("content-type")
        .is_some_and(|t| t.starts_with("text/event-stream")));
    let events = sse(&r.body);
    let (last, rest) = events.split_last().expect("events");
    assert_eq!(last.0, "done", "{events:?}");
    assert_eq!(last.1["download_url"], started["download_url"]);
    assert_eq!((&last.1["done"], &last.1["total"]), (&json!(6), &json!(6)));
    assert!(!rest.is_empty() && rest.iter().all(|(name, _)| name == "progress"));
    let done: Vec<u64> = rest
        .iter()
        .map(|(_, d)| d["done"].as_u64().expect("done"))
        .collect();
    assert!(done.windows(2).all(|w| w[0] <= w[1]), "{done:?}");
    assert_eq!(done.last(), Some(&6), "the final count is always sent");
    assert!(rest.iter().all(|(_, d)| d["total"] == 6));

    // A late client gets the current state first, then the end.
    let late = sse(&get(&app, events_url, tok)
        .await
        .status_is(StatusCode::OK)
        .body);
    let names: Vec<&str> = late.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["progress", "done"], "{late:?}");
    assert_eq!(late[0].1, json!({"status": "done", "done": 6, "total": 6}));

    let status_url = started["status_url"].as_str().expect("url");
    let v = get(&app, status_url, tok)
        .await
        .status_is(StatusCode::OK)
        .json();
    assert_eq!(
        v,
        json!({"id": started["job"], "world": id, "version": 2, "shard": "1/1",
               "status": "done", "done": 6, "total": 6,
               "download_url": started["download_url"]})
    );

    let r = get(&app, started["download_url"].as_str().expect("url"), tok).await;
    r.status_is(StatusCode::OK);
    assert_eq!(r.header("content-type"), Some("application/x-tar"));
    assert!(r
        .header("content-disposition")
        .is_some_and(|d| d.starts_with("attachment; filename=")));
    assert_eq!(
        r.header("content-length"),
        Some(r.body.len().to_string().as_str())
    );
    let members = read_members(&r.body).expect("tar");
    let names: Vec<String> = members.iter().map(|(n, _)| n.clone()).collect();
    assert_eq!(names, expected_names(2, region, &["bin", "png"]));
    assert_eq!(members.len(), 6 * 3 + 1);

    // Every member is the bytes the HTTP API serves for the same key and version.
    let mut differs_from_v1 = false;
    for (name, bytes) in &members[..members.len() - 1] {
        let url = format!("/v1/worlds/{id}/{name}?v=2");
        let served = get(&app, &url, tok).await;
        served.status_is(StatusCode::OK);
        assert!(served.body == *bytes, "{name} differs from GET {url}");
        let v1 = get(&app, &format!("/v1/worlds/{id}/{name}?v=1"), tok).await;
        differs_from_v1 |= v1.status_is(StatusCode::OK).body != *bytes;
    }
    assert!(
        differs_from_v1,
        "version 2 changed the products, and the export is of v2"
    );
    let manifest: Value = serde_json::from_slice(&members[members.len() - 1].1).expect("json");
    assert_eq!(manifest["format"], "strata.export.v1");
    assert_eq!(manifest["seed"], "42");
    assert_eq!(manifest["members"].as_array().map(Vec::len), Some(18));
    assert_eq!(manifest["shard"], json!({"index": 0, "count": 1}));
}

#[tokio::test]
async fn three_shard_jobs_equal_the_whole_job_and_the_cli() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let (id, admin) = world(&app, 7).await;
    let tok = Some(admin.as_str());
    let body = |shard: Option<&str>| {
        let mut b = json!({"lod": 1, "region": [-2, -1, 2, 2], "products": ["tiles", "scatter"],
                           "formats": ["bin", "png"]});
        if let Some(s) = shard {
            b["shard"] = json!(s);
        }
        b
    };
    // All four jobs are queued at once (two run at a time).
    let mut jobs = vec![start(&app, &id, tok, &body(None)).await];
    for s in ["1/3", "2/3", "3/3"] {
        let v = start(&app, &id, tok, &body(Some(s))).await;
        assert_eq!(v["shard"], s);
        jobs.push(v);
    }
    let mut archives = Vec::new();
    for j in &jobs {
        let v = wait(&app, j["status_url"].as_str().expect("url"), tok).await;
        assert_eq!(v["status"], "done", "{v}");
        let r = get(&app, j["download_url"].as_str().expect("url"), tok).await;
        archives.push(r.status_is(StatusCode::OK).body.clone());
    }
    let whole = read_members(&archives[0]).expect("tar");
    assert_eq!(whole.len(), 12 * 3 + 1);
    let mut joined = Vec::new();
    for (i, a) in archives[1..].iter().enumerate() {
        let mut m = read_members(a).expect("tar");
        let (name, manifest) = m.pop().expect("manifest");
        assert_eq!(name, "manifest.json");
        let manifest: Value = serde_json::from_slice(&manifest).expect("json");
        assert_eq!(manifest["shard"], json!({"index": i, "count": 3}));
        joined.extend(m);
    }
    assert!(
        joined == whole[..whole.len() - 1],
        "shards concatenate to the whole"
    );

    // The archive is the one `strata export` writes for the same seed and arguments.
    let plan = WorldPlan::new(7, WorldParams::default()).expect("plan");
    let spec = ExportSpec {
        lod: 1,
        x0: -2,
        z0: -1,
        x1: 2,
        z1: 2,
        products: vec![Product::Tiles, Product::Scatter],
        formats: vec!["bin".into(), "png".into()],
        ptex_res: None,
    };
    let mut local = Vec::new();
    export::write_archive(
        &plan,
        &Default::default(),
        &spec,
        Shard::WHOLE,
        2,
        &mut local,
        |_, _| {},
    )
    .expect("export");
    assert!(
        local == archives[0],
        "the job's archive equals the CLI's, byte for byte"
    );
}

#[tokio::test]
async fn bad_exports_name_the_field_and_unknown_jobs_are_404() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let (id, admin) = world(&app, 1).await;
    let tok = Some(admin.as_str());
    let url = format!("/v1/worlds/{id}/exports");
    let good = json!({"lod": 2, "region": [0, 0, 2, 2], "products": ["tiles"], "formats": ["bin"]});
    let with = |k: &str, v: Value| {
        let mut b = good.clone();
        b[k] = v;
        b
    };
    let cases = [
        (with("lod", json!(13)), "invalid_export", "/lod"),
        (with("lod", json!(-1)), "bad_body", "/lod"),
        (
            with("region", json!([0, 0, 0, 2])),
            "invalid_export",
            "/region/2",
        ),
        (
            with("region", json!([0, 3, 2, 2])),
            "invalid_export",
            "/region/3",
        ),
        (
            with("region", json!([0, 0, 1000, 1000])),
            "invalid_export",
            "/region/2",
        ),
        (with("region", json!([0, 0, 2])), "bad_body", "/region"),
        (
            with("formats", json!(["tiff"])),
            "invalid_export",
            "/formats",
        ),
        (
            with("formats", json!(["bin", "bin"])),
            "invalid_export",
            "/formats",
        ),
        (with("formats", json!([])), "invalid_export", "/formats"),
        (with("products", json!([])), "invalid_export", "/products"),
        (
            with("products", json!(["meshes"])),
            "bad_body",
            "/products/0",
        ),
        (with("shard", json!("4/3")), "invalid_export", "/shard"),
        (with("v", json!(0)), "bad_version", "/v"),
        (with("colour", json!(true)), "bad_body", "/colour"),
    ];
    for (body, code, field) in cases {
        let r = post(&app, &url, tok, &body).await;
        r.error(StatusCode::BAD_REQUEST, code, Some(field));
    }
    let r = post(&app, &url, tok, &with("v", json!(9))).await;
    r.error(StatusCode::NOT_FOUND, "version_not_found", Some("/v"));
    let r = send(&app, Method::POST, &url, tok, Some(b"{")).await;
    r.error(StatusCode::BAD_REQUEST, "bad_body", Some("body"));
    let r = post(&app, "/v1/worlds/nope/exports", tok, &good).await;
    r.error(StatusCode::NOT_FOUND, "world_not_found", Some("id"));

    for job in ["0123456789abcdef0123456789abcdef", "nope", "..%2F..%2Fetc"] {
        for tail in ["", "/events", "/archive"] {
            let r = get(&app, &format!("/v1/jobs/{job}{tail}"), tok).await;
            r.error(StatusCode::NOT_FOUND, "job_not_found", Some("id"));
        }
    }
}

#[tokio::test]
async fn archive_before_done_is_409_and_the_queue_is_bounded() {
    let dir = tempfile::tempdir().expect("tmp");
    let limits = JobLimits {
        max_running: 1,
        max_queued: 1,
        max_finished: 8,
        // The long job below (65536 tiles, about 8 GB) exceeds the default disk budgets, which
        // tests/export_size.rs checks; this test is about the queue.
        world_budget_bytes: 1 << 40,
        disk_budget_bytes: 1 << 40,
        ..JobLimits::default()
    };
    let state = AppState::new(Compute::cpu())
        .with_jobs_dir(dir.path())
        .with_job_limits(limits);
    let app = app(state.clone());
    let (id, admin) = world(&app, 3).await;
    let tok = Some(admin.as_str());
    // A large job holds the only run slot …
    let big =
        json!({"lod": 0, "region": [0, 0, 256, 256], "products": ["tiles"], "formats": ["bin"]});
    let a = start(&app, &id, tok, &big).await;
    let deadline = tokio::time::Instant::now() + JOB_TIMEOUT;
    loop {
        let v = get(&app, a["status_url"].as_str().expect("url"), tok)
            .await
            .json();
        if v["status"] == "running" {
            break;
        }
        assert_eq!(v["status"], "queued");
        assert!(tokio::time::Instant::now() < deadline);
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    // … so the next one waits, and its archive is not ready.
    let small = json!({"lod": 0, "region": [0, 0, 1, 1], "products": ["scatter"]});
    let b = start(&app, &id, tok, &small).await;
    assert_eq!(b["status"], "queued");
    let v = get(&app, b["status_url"].as_str().expect("url"), tok)
        .await
        .json();
    assert_eq!(
        (&v["status"], &v["done"], &v["total"]),
        (&json!("queued"), &json!(0), &json!(1))
    );
    assert!(v.get("download_url").is_none());
    for job in [&a, &b] {
        let r = get(&app, job["download_url"].as_str().expect("url"), tok).await;
        r.error(StatusCode::CONFLICT, "job_not_done", None);
    }
    // The queue holds one waiting job: a third is refused.
    let r = post(&app, &format!("/v1/worlds/{id}/exports"), tok, &small).await;
    r.error(StatusCode::TOO_MANY_REQUESTS, "too_many_jobs", None);
    assert!(r.header("retry-after").is_some());

    // Dropping the server cancels its jobs: the running one stops at its next write.
    let job_a = state
        .jobs
        .get(a["job"].as_str().expect("id"))
        .expect("job a");
    drop((app, state));
    let mut rx = job_a.subscribe();
    let p = tokio::time::timeout(
        Duration::from_secs(60),
        rx.wait_for(|p| p.status.is_finished()),
    )
    .await
    .expect("cancelled in time")
    .expect("sender alive")
    .clone();
    assert_eq!(p.status, Status::Failed, "{p:?}");
    assert!(p.done < p.total, "{p:?}");
}

#[tokio::test]
async fn exports_need_an_edit_token_and_following_them_needs_read() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let (id, admin) = world(&app, 5).await;
    let (_other, other_admin) = world(&app, 6).await;
    let r = post(
        &app,
        &format!("/v1/worlds/{id}/tokens"),
        Some(&admin),
        &json!({"role": "read"}),
    )
    .await;
    let reader = r.status_is(StatusCode::CREATED).json()["token"]
        .as_str()
        .expect("token")
        .to_string();
    let r = post(
        &app,
        &format!("/v1/worlds/{id}/tokens"),
        Some(&admin),
        &json!({"role": "edit"}),
    )
    .await;
    let editor = r.status_is(StatusCode::CREATED).json()["token"]
        .as_str()
        .expect("token")
        .to_string();
    let url = format!("/v1/worlds/{id}/exports");
    let body =
        json!({"lod": 3, "region": [0, 0, 1, 1], "products": ["tiles"], "formats": ["json"]});
    post(&app, &url, None, &body)
        .await
        .error(StatusCode::UNAUTHORIZED, "unauthenticated", None);
    post(&app, &url, Some(&other_admin), &body).await.error(
        StatusCode::FORBIDDEN,
        "forbidden",
        None,
    );
    post(&app, &url, Some("st_not-a-token"), &body).await.error(
        StatusCode::UNAUTHORIZED,
        "unauthenticated",
        None,
    );
    // Reading is not enough: an export writes archives to the server's disk.
    post(&app, &url, Some(&reader), &body)
        .await
        .error(StatusCode::FORBIDDEN, "forbidden", None);
    let job = start(&app, &id, Some(&editor), &body).await;
    let status_url = job["status_url"].as_str().expect("url");
    let v = wait(&app, status_url, Some(&reader)).await;
    assert_eq!(v["status"], "done");
    for url in [
        status_url,
        job["events_url"].as_str().expect("url"),
        job["download_url"].as_str().expect("url"),
    ] {
        get(&app, url, None)
            .await
            .error(StatusCode::UNAUTHORIZED, "unauthenticated", None);
        get(&app, url, Some(&other_admin))
            .await
            .error(StatusCode::FORBIDDEN, "forbidden", None);
        get(&app, url, Some(&reader))
            .await
            .status_is(StatusCode::OK);
    }
    // Once the world is public, anyone may follow and download its jobs.
    post(
        &app,
        &format!("/v1/worlds/{id}/access"),
        Some(&admin),
        &json!({"public": true}),
    )
    .await
    .status_is(StatusCode::OK);
    let r = get(&app, job["download_url"].as_str().expect("url"), None).await;
    assert_eq!(
        read_members(&r.status_is(StatusCode::OK).body)
            .expect("tar")
            .len(),
        2
    );
    // Issue 18, finding 3: a public world's exports still need the edit role.
    post(&app, &url, None, &body)
        .await
        .error(StatusCode::UNAUTHORIZED, "unauthenticated", None);
    post(&app, &url, Some(&reader), &body)
        .await
        .error(StatusCode::FORBIDDEN, "forbidden", None);
}
