//! Replicas sharing a PostgreSQL store (a throwaway cluster, `common::postgres`): an edit
//! committed through one `strata serve` reaches the stream sessions of another (LISTEN/NOTIFY),
//! and after the replicas' listening connections are cut, an edit made meanwhile still reaches
//! them (the catch-up by version when they listen again), as do the edits after it.

mod common;

use common::replica::{create_world, next_json, request, session, Ws};
use serde_json::{json, Value};

const ADMIN: &str = "st_replicas_admin";

fn serve(url: &str) -> (common::Server, tempfile::TempDir) {
    let dir = tempfile::tempdir().expect("tmp");
    let server = common::start(
        [
            "--data",
            dir.path().to_str().expect("utf-8 path"),
            "--admin-token",
            ADMIN,
            "--store",
            url,
        ],
        &[],
    );
    (server, dir)
}

/// An HTTP request to `addr` with the server's admin token: the status and the JSON body.
async fn call(
    addr: &str,
    method: &'static str,
    path: String,
    ctype: &'static str,
    body: Value,
) -> (u16, Value) {
    let bytes = serde_json::to_vec(&body).expect("json");
    let (status, body) = request(
        addr,
        ADMIN,
        method,
        path,
        vec![("content-type", ctype.into())],
        bytes,
    )
    .await;
    (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
}

/// Adds a region near the origin through `addr`; returns the version it made.
async fn edit(addr: &str, id: &str, region: &str) -> u64 {
    let patch = json!([{"op": "add", "path": "/regions/-", "value":
        {"id": region, "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    let (status, body) = call(
        addr,
        "POST",
        format!("/v1/worlds/{id}/edits"),
        "application/json-patch+json",
        patch,
    )
    .await;
    assert_eq!(status, 200, "{body}");
    body["version"].as_u64().expect("version")
}

/// Reads until an `invalidate` of `version` (or later): every tile the session holds near the
/// origin is touched by the edits these tests make.
async fn invalidated(ws: &mut Ws, version: u64) {
    loop {
        let m = next_json(ws).await;
        if m["type"] == "invalidate" && m["version"].as_u64() >= Some(version) {
            assert!(!m["tiles"].as_array().expect("tiles").is_empty(), "{m}");
            return;
        }
    }
}

/// A world created through `a`: its id and admin token.
async fn world(a: &str) -> (String, String) {
    create_world(a, ADMIN, 5).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_edit_on_one_replica_reaches_the_stream_sessions_of_another() {
    let url = common::postgres::database().await;
    let (a, _da) = serve(&url);
    let (b, _db) = serve(&url);
    let (id, token) = world(&a.addr).await;
    let mut on_b = session(&b.addr, &id, &token).await;
    let mut on_a = session(&a.addr, &id, &token).await;
    let v = edit(&a.addr, &id, "from-a").await;
    invalidated(&mut on_b, v).await;
    invalidated(&mut on_a, v).await;
    let v = edit(&b.addr, &id, "from-b").await;
    invalidated(&mut on_a, v).await;
    invalidated(&mut on_b, v).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_replica_whose_listening_connection_was_cut_misses_no_invalidation() {
    let url = common::postgres::database().await;
    let (a, _da) = serve(&url);
    let (b, _db) = serve(&url);
    let (id, token) = world(&a.addr).await;
    let mut on_b = session(&b.addr, &id, &token).await;
    // Cut every replica's listening connection, then edit at once: the notification is sent
    // while B is not listening (or, if B was quick, after it listens again); either way its
    // session must see the edit.
    let admin = common::postgres::connect("postgres").await;
    let db = url.rsplit('/').next().expect("database name");
    let cut = admin
        .execute(
            "SELECT pg_terminate_backend(pid) FROM pg_stat_activity
             WHERE application_name = 'strata-listen' AND datname = $1",
            &[&db],
        )
        .await
        .expect("terminate the listeners");
    assert_eq!(cut, 2, "both replicas were listening");
    let v = edit(&a.addr, &id, "while-cut").await;
    invalidated(&mut on_b, v).await;
    let v = edit(&a.addr, &id, "after").await;
    invalidated(&mut on_b, v).await;
}
