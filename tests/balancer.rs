//! Three `strata serve` replicas on one PostgreSQL database (a throwaway cluster,
//! `common::postgres`) behind Debian's nginx as the load balancer, all on loopback: stream
//! sessions opened through the balancer (nginx's round robin puts them on different replicas)
//! all see an edit made through it; two editors racing through it with the same `If-Match` get
//! one 200 and one 409; every replica serves the same bytes for the same URL. A replica
//! SIGKILLed while four editors edit over their streams loses no acknowledged edit, and every
//! stream, resumed through the balancer or not, is told of the last version. Without nginx
//! (`apt-get install nginx-light`; `.ci/run` installs it) this fails, never skips.

mod common;

use common::replica::{create_world, next_json, request, session, Ws};
use futures::{SinkExt, StreamExt};
use serde_json::{json, Value};
use std::path::Path;
use std::time::{Duration, Instant};
use strata::harness::nginx::Nginx;
use tokio_tungstenite::tungstenite::Message;

const ADMIN: &str = "st_balancer_admin";

/// nginx on a free loopback port, proxying HTTP and WebSockets round robin to `upstreams`.
fn nginx(dir: &Path, upstreams: &[&str]) -> Nginx {
    strata::harness::nginx::balancer(dir, upstreams)
        .unwrap_or_else(|e| panic!("the balancer tests: {e:#}"))
}

/// An HTTP request to `addr` with the server's admin token: the status and the body.
async fn call(
    addr: &str,
    method: &'static str,
    path: String,
    headers: Vec<(&'static str, String)>,
    body: Vec<u8>,
) -> (u16, Vec<u8>) {
    request(addr, ADMIN, method, path, headers, body).await
}

async fn edit(addr: &str, id: &str, if_match: u64, region: &str) -> (u16, Value) {
    let patch = json!([{"op": "add", "path": "/regions/-", "value":
        {"id": region, "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    let (status, body) = call(
        addr,
        "POST",
        format!("/v1/worlds/{id}/edits"),
        vec![
            ("content-type", "application/json-patch+json".into()),
            ("if-match", if_match.to_string()),
        ],
        serde_json::to_vec(&patch).expect("json"),
    )
    .await;
    (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
}

/// Three `strata serve` processes on the database `url`, with data directories `dirs[0..3]`.
fn three_replicas(url: &str, dirs: &[tempfile::TempDir]) -> Vec<common::Server> {
    dirs[..3]
        .iter()
        .map(|d| {
            common::start(
                [
                    "--data",
                    d.path().to_str().expect("utf-8"),
                    "--admin-token",
                    ADMIN,
                    "--store",
                    url,
                ],
                &[],
            )
        })
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn three_replicas_behind_nginx_share_edits_streams_and_bytes() {
    let url = common::postgres::database().await;
    let dirs: Vec<tempfile::TempDir> = (0..4).map(|_| tempfile::tempdir().expect("tmp")).collect();
    let replicas = three_replicas(&url, &dirs);
    let addrs: Vec<&str> = replicas.iter().map(|r| r.addr.as_str()).collect();
    let lb = nginx(dirs[3].path(), &addrs);

    let (id, token) = create_world(&lb.addr, ADMIN, 11).await;

    // Three sessions through the balancer: round robin spreads them over the replicas.
    let mut sessions = Vec::new();
    for _ in 0..3 {
        sessions.push(session(&lb.addr, &id, &token).await);
    }

    // Two editors through the balancer, both expecting version 1: one wins.
    let (lb_a, lb_b, id_a, id_b) = (lb.addr.clone(), lb.addr.clone(), id.clone(), id.clone());
    let a = tokio::spawn(async move { edit(&lb_a, &id_a, 1, "a").await });
    let b = tokio::spawn(async move { edit(&lb_b, &id_b, 1, "b").await });
    let mut statuses = [a.await.expect("a").0, b.await.expect("b").0];
    statuses.sort_unstable();
    assert_eq!(statuses, [200, 409]);

    for ws in &mut sessions {
        loop {
            let m = next_json(ws).await;
            if m["type"] == "invalidate" {
                assert_eq!(m["version"], 2, "{m}");
                break;
            }
        }
    }

    // The same URL gives the same bytes on every replica and through the balancer.
    let path = format!("/v1/worlds/{id}/tiles/0/0/0.bin?v=2");
    let mut bodies = Vec::new();
    for addr in addrs.iter().copied().chain([lb.addr.as_str()]) {
        let (status, body) = call(addr, "GET", path.clone(), Vec::new(), Vec::new()).await;
        assert_eq!(status, 200, "{addr}: {}", String::from_utf8_lossy(&body));
        bodies.push(body);
    }
    assert!(bodies[0].len() > 1000);
    assert!(
        bodies.iter().all(|b| *b == bodies[0]),
        "every replica serves the same bytes"
    );
}

/// One editor's stream through the balancer: its socket, the edits the server acknowledged (and
/// the newest version among them) and the newest version it has been told of (a `hello`, an
/// `invalidate` or an `idle`).
struct Editor {
    ws: Ws,
    acked: Vec<String>,
    acked_version: u64,
    seen: u64,
    reconnects: u32,
}

impl Editor {
    /// A session through `lb` with its view sent (retrying while the balancer has no live
    /// upstream for it); its `hello` must not be older than `seen`, what the editor was told or
    /// acknowledged before.
    async fn connect(lb: &str, id: &str, token: &str, seen: u64) -> (Ws, u64) {
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            let url = format!("ws://{lb}/v1/worlds/{id}/stream?token={token}");
            if let Ok((mut ws, _)) = tokio_tungstenite::connect_async(url).await {
                let hello = next_json(&mut ws).await;
                let version = hello["version"].as_u64().expect("hello version");
                assert!(version >= seen, "resumed at {version}, older than {seen}");
                let view = json!({"type": "view", "x": 16, "z": 16, "rings": [1]});
                if ws
                    .send(Message::Text(view.to_string().into()))
                    .await
                    .is_ok()
                {
                    return (ws, version);
                }
            }
            assert!(Instant::now() < deadline, "no replica takes the stream");
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    }

    /// The next text message, or `None` when the socket is gone.
    async fn next(&mut self) -> Option<Value> {
        loop {
            let m = tokio::time::timeout(Duration::from_secs(60), self.ws.next())
                .await
                .unwrap_or_else(|_| {
                    panic!(
                        "no message within 60 s (told of {}, {} edits acknowledged, {} reconnects)",
                        self.seen,
                        self.acked.len(),
                        self.reconnects
                    )
                });
            match m {
                Some(Ok(Message::Text(t))) => {
                    let v: Value = serde_json::from_str(&t).expect("JSON");
                    // `idle` reports the version every tile of the view was sent at: tiles an
                    // edit touched before they were held get no `invalidate`.
                    if ["invalidate", "hello", "idle"].contains(&v["type"].as_str().unwrap_or("")) {
                        self.seen = self.seen.max(v["version"].as_u64().expect("version"));
                    }
                    return Some(v);
                }
                Some(Ok(_)) => continue,
                Some(Err(_)) | None => return None,
            }
        }
    }
}

/// Edits `n` times on its stream, reconnecting through `lb` whenever the socket dies; counts
/// each acknowledgement in `acks`.
async fn edit_stream(
    lb: String,
    id: String,
    token: String,
    k: usize,
    n: usize,
    acks: std::sync::Arc<std::sync::atomic::AtomicUsize>,
) -> Editor {
    let (ws, seen) = Editor::connect(&lb, &id, &token, 0).await;
    let mut e = Editor {
        ws,
        acked: Vec::new(),
        acked_version: 0,
        seen,
        reconnects: 0,
    };
    for i in 0..n {
        let name = format!("c{k}-{i}");
        let patch = json!([{"op": "add", "path": "/regions/-", "value":
            {"id": name, "bbox": {"min": [10.0 + k as f64, 10.0], "max": [20.0, 20.0]}}}]);
        let msg = json!({"type": "edit", "id": name, "patch": patch});
        let mut alive =
            e.ws.send(Message::Text(msg.to_string().into()))
                .await
                .is_ok();
        while alive {
            match e.next().await {
                Some(m) if m["type"] == "ack" && m["id"] == name.as_str() => {
                    let v = m["version"].as_u64().expect("version");
                    e.acked_version = e.acked_version.max(v);
                    e.acked.push(name.clone());
                    acks.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                    break;
                }
                Some(m) => assert_ne!(m["type"], "error", "{m}"),
                None => alive = false,
            }
        }
        if !alive {
            // The replica died: this edit's fate is unknown; resume through the balancer.
            let floor = e.seen.max(e.acked_version);
            let (ws, _) = Editor::connect(&lb, &id, &token, floor).await;
            e.ws = ws;
            e.reconnects += 1;
        }
    }
    e
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_replica_killed_during_four_edit_streams_loses_no_acknowledged_edit() {
    let url = common::postgres::database().await;
    // Three repetitions, each with fresh replicas and balancer, killing a different replica.
    for victim in 0..3 {
        kill_during_edit_streams(&url, victim).await;
    }
}

/// Three replicas of `url` behind nginx, four editors on one world through it, and replica
/// `victim` SIGKILLed once eight edits are acknowledged.
async fn kill_during_edit_streams(url: &str, victim: usize) {
    let dirs: Vec<tempfile::TempDir> = (0..4).map(|_| tempfile::tempdir().expect("tmp")).collect();
    let mut replicas = three_replicas(url, &dirs);
    let addrs: Vec<String> = replicas.iter().map(|r| r.addr.clone()).collect();
    let addr_refs: Vec<&str> = addrs.iter().map(String::as_str).collect();
    let lb = nginx(dirs[3].path(), &addr_refs);
    let (id, token) = create_world(&lb.addr, ADMIN, 12).await;

    let acks = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let per_editor = 10;
    let editors: Vec<_> = (0..4)
        .map(|k| {
            tokio::spawn(edit_stream(
                lb.addr.clone(),
                id.clone(),
                token.clone(),
                k,
                per_editor,
                acks.clone(),
            ))
        })
        .collect();
    while acks.load(std::sync::atomic::Ordering::SeqCst) < 8 {
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    // SIGKILL: no shutdown, no close frames.
    replicas[victim].child.kill().expect("SIGKILL a replica");
    let mut done = Vec::new();
    for e in editors {
        done.push(e.await.expect("editor"));
    }
    let reconnects: u32 = done.iter().map(|e| e.reconnects).sum();
    assert!(reconnects >= 1, "some stream was on the killed replica");

    let (status, body) = call(
        &lb.addr,
        "GET",
        format!("/v1/worlds/{id}"),
        Vec::new(),
        Vec::new(),
    )
    .await;
    assert_eq!(status, 200);
    let world: Value = serde_json::from_slice(&body).expect("json");
    let stored: std::collections::BTreeSet<String> = world["scene"]["regions"]
        .as_array()
        .expect("regions")
        .iter()
        .map(|r| r["id"].as_str().expect("id").to_string())
        .collect();
    let version = world["version"].as_u64().expect("version");
    assert_eq!(version, 1 + stored.len() as u64);
    for e in &done {
        for name in &e.acked {
            assert!(stored.contains(name), "acknowledged edit {name} was lost");
        }
    }
    // Every stream, resumed or not, is told of the last version: none missed an invalidation.
    for e in &mut done {
        while e.seen < version {
            assert!(e.next().await.is_some(), "a stream died after the kill");
        }
        assert_eq!(e.seen, version);
    }
}
