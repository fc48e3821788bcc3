//! Issue 18, Done-when 1: a synthesis whose request timed out stops, frees its slot and caches
//! nothing partial. One test in its own binary, so the process's CPU clock measures the server
//! alone.

mod common;

use axum::http::StatusCode;
use common::oneshot::{post_json, send};
use serde_json::json;
use std::time::{Duration, Instant};
use strata::compute::Compute;
use strata::server::{app, AppState, Limits};

/// A region whose solve takes seconds in a test build: 513² samples and thermal erosion.
fn heavy_scene() -> serde_json::Value {
    json!({"regions": [{"id": "heavy", "bbox": {"min": [0.0, 0.0], "max": [4096.0, 4096.0]},
        "samples": 513, "ops": [
            {"op": "amplify", "center": [2048.0, 2048.0], "radius_m": 1500.0, "factor": 1.5},
            {"op": "erosion", "center": [2048.0, 2048.0], "radius_m": 2000.0, "iterations": 100}]}]})
}

/// Creates a public world of seed 42 with [`heavy_scene`] on `router`; its id.
async fn heavy_world(router: &axum::Router) -> String {
    let created = post_json(
        router,
        "/v1/worlds",
        None,
        &json!({"seed": 42, "public": true, "scene": heavy_scene()}),
    )
    .await;
    created.status_is(StatusCode::CREATED);
    created.json()["id"].as_str().expect("id").to_string()
}

fn metric(text: &str, name: &str) -> f64 {
    text.lines()
        .find_map(|l| l.strip_prefix(name)?.trim().parse().ok())
        .unwrap_or_else(|| panic!("{name} missing from /metrics"))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_timed_out_synthesis_stops_frees_its_slot_and_caches_nothing() {
    let limits = Limits {
        synthesis_timeout: Duration::from_millis(300),
        max_concurrent_syntheses: 1,
        ..Limits::default()
    };
    let st = AppState::with_limits(Compute::cpu(), limits);
    let router = app(st.clone());
    let id = heavy_world(&router).await;
    let tile = format!("/v1/worlds/{id}/tiles/0/16/16.bin");

    let reply = send::<&str>(&router, axum::http::Method::GET, &tile, &[], None).await;
    reply.error(StatusCode::SERVICE_UNAVAILABLE, "synthesis_timeout", None);

    // The job is cancelled at once and the region's solve stops at its next check.
    let deadline = Instant::now() + Duration::from_secs(5);
    while st.regions.running() > 0 {
        assert!(
            Instant::now() < deadline,
            "the region solve is still running"
        );
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let metrics = send::<&str>(&router, axum::http::Method::GET, "/metrics", &[], None).await;
    let metrics = String::from_utf8_lossy(&metrics.body).to_string();
    assert_eq!(metric(&metrics, "strata_synthesis_cancelled_total"), 1.0);
    assert_eq!(metric(&metrics, "strata_synthesis_after_timeout"), 0.0);
    assert_eq!(st.regions.size().0, 0, "a cancelled solve is not kept");
    // Nothing runs any more: the process spends next to no CPU.
    let cpu = strata::cpu_time::process_ms();
    tokio::time::sleep(Duration::from_millis(500)).await;
    let spent = strata::cpu_time::process_ms() - cpu;
    assert!(spent < 100.0, "{spent} ms of CPU after the cancellation");
    // The one slot is free: a cheap tile is answered within the limit.
    send::<&str>(
        &router,
        axum::http::Method::GET,
        "/v1/seeds/42/tiles/12/0/0.bin",
        &[],
        None,
    )
    .await
    .ok();

    // The same caches under the default limits give the full product, the bytes of a server
    // that never cancelled.
    let mut patient = AppState::new(Compute::cpu());
    patient.worlds = st.worlds.clone();
    patient.cache = st.cache.clone();
    patient.bodies = st.bodies.clone();
    patient.regions = st.regions.clone();
    let after = send::<&str>(&app(patient), axum::http::Method::GET, &tile, &[], None).await;
    after.ok();
    let fresh = AppState::new(Compute::cpu());
    let fresh_router = app(fresh);
    let fresh_id = heavy_world(&fresh_router).await;
    let reference = send::<&str>(
        &fresh_router,
        axum::http::Method::GET,
        &format!("/v1/worlds/{fresh_id}/tiles/0/16/16.bin"),
        &[],
        None,
    )
    .await;
    reference.ok();
    assert_eq!(after.body, reference.body);
}
