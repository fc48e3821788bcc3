//! Issue 18's probe, replayed against the real binary: the findings about cost (1, 2 and 4) get
//! their bounded answers, and the server's resident set stays within its memory budget.
//!
//! The other findings are replayed where their fix is tested:
//! 2 (scatter burning CPU) also `tests/rate_limit.rs` (the expensive routes' rate limits);
//! 3 (anonymous exports, disk fill) `tests/exports.rs::exports_need_an_edit_token_and_following_them_needs_read`,
//! `tests/export_size.rs` (an archive's size bound, checked before a job is accepted) and
//! `tests/export_quota.rs` (per-world and per-server disk budgets, expiry);
//! 5 (read timeouts, the connection cap) `tests/connections.rs`;
//! 6 (SIGTERM with open streams) `tests/shutdown.rs`;
//! 7 (integer overflow) `tests/numeric_params.rs`;
//! 8 (the contract) `tests/contract.rs`;
//! 9 (cross-origin) `tests/cors.rs`;
//! 10 (the CLI) `tests/cli_export.rs`;
//! 11 (memory per stream client) `tests/stream_memory.rs`.

mod common;

use common::raw::{get, request};
use serde_json::{json, Value};

/// Resident set of process `pid`, MiB.
fn rss_mib(pid: u32) -> u64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).expect("status");
    let kib: u64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .expect("VmRSS");
    kib >> 10
}

/// Asserts a 4xx JSON error whose field starts with `field`; returns the message.
fn refused(status: u16, body: &[u8], field: &str) -> String {
    let e: Value = serde_json::from_slice(body).expect("a JSON error");
    assert!(
        (400..500).contains(&status),
        "expected a 4xx, got {status}: {e}"
    );
    let got = e["error"]["field"].as_str().unwrap_or_default();
    assert!(
        got.starts_with(field),
        "field {got:?}, expected {field:?}: {e}"
    );
    e["error"]["message"]
        .as_str()
        .unwrap_or_default()
        .to_string()
}

fn post_world(addr: &str, scene: Value) -> (u16, Vec<u8>) {
    let body = json!({"seed": 42, "public": true, "scene": scene}).to_string();
    request(
        addr,
        "POST",
        "/v1/worlds",
        &[("content-type", "application/json")],
        body.as_bytes(),
    )
    .expect("POST /v1/worlds")
}

#[test]
fn the_cost_findings_get_bounded_answers_and_memory_stays_within_the_budget() {
    let data = tempfile::tempdir().expect("tempdir");
    let server = common::start(["--data", data.path().to_str().expect("utf-8 path")], &[]);
    let addr = server.addr.as_str();
    let budget_mib = 512;

    // Finding 1: a region of ±1e9 m is refused when the scene is written, naming the field and
    // the limit, on creation and as an edit.
    for extent in [1e9, 1e8, 1e7] {
        let region = json!({"id": "huge", "bbox": {"min": [-extent, -extent], "max": [extent, extent]},
                            "samples": 33, "ops": []});
        let (status, body) = post_world(addr, json!({"regions": [region]}));
        let message = refused(status, &body, "/regions/0");
        assert!(
            message.chars().any(|c| c.is_ascii_digit()),
            "the message states the limit: {message}"
        );
    }
    let (status, body) = post_world(addr, json!({}));
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&body));
    let world: Value = serde_json::from_slice(&body).expect("world");
    let id = world["id"].as_str().expect("id");
    let auth = format!(
        "Bearer {}",
        world["tokens"]["admin"].as_str().expect("admin token")
    );
    let patch = json!([{"op": "add", "path": "/regions/-", "value":
        {"id": "huge", "bbox": {"min": [-1e9, -1e9], "max": [1e9, 1e9]}, "samples": 2049, "ops": []}}]);
    let (status, body) = request(
        addr,
        "POST",
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("content-type", "application/json-patch+json"),
            ("authorization", &auth),
        ],
        patch.to_string().as_bytes(),
    )
    .expect("edit");
    refused(status, &body, "/regions/0");
    // The world still serves its tiles, and nothing grew.
    for x in -2..2 {
        let (status, _) = get(addr, &format!("/v1/worlds/{id}/tiles/0/{x}/0.bin"));
        assert_eq!(status, 200);
    }
    let rss = rss_mib(server.child.id());
    assert!(
        rss <= budget_mib,
        "resident set {rss} MiB after finding 1's requests; the budget is {budget_mib} MiB"
    );

    // Finding 2: scatter at the coarsest LOD visits a bounded number of candidates (the cost
    // model refuses what would visit more than its limit, naming `lod`), so it is answered.
    for lod in [10, 11, 12] {
        let (status, body) = get(addr, &format!("/v1/seeds/42/scatter/{lod}/0/0.json"));
        if status != 200 {
            refused(status, &body, "lod");
        }
    }

    // Finding 4: hydraulic erosion over a region's budget (droplets × steps) is refused naming
    // the operation's field and the limit.
    let heavy = json!({"id": "heavy", "bbox": {"min": [0.0, 0.0], "max": [8192.0, 8192.0]}, "samples": 2049,
        "ops": [{"op": "hydraulic_erosion", "center": [4096.0, 4096.0], "radius_m": 4000.0,
                 "droplets": 200000, "steps": 512}]});
    let (status, body) = post_world(addr, json!({"regions": [heavy]}));
    let message = refused(status, &body, "/regions/0/ops/0");
    assert!(
        message.contains(&strata::authoring::spec_tools::MAX_REGION_CELL_STEPS.to_string()),
        "the message names the limit: {message}"
    );

    let rss = rss_mib(server.child.id());
    assert!(
        rss <= budget_mib,
        "resident set {rss} MiB after the findings' requests; the budget is {budget_mib} MiB"
    );
}
