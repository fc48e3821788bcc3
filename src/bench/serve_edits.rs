//! `strata bench serve`, edits: the time from an edit's acknowledgement (the HTTP 200) to its
//! invalidation reaching each of [`SUBSCRIBERS`] subscribed WebSocket clients, for tiles and for
//! volume chunks (issue 19, Done-when 6); the target of both is p99 ≤
//! [`TARGET_INVALIDATION_P99_MS`].
//!
//! - Tiles: a world of seed 42; each client streams protocol v1 with a view of the one LOD-0 tile
//!   under the edits.
//! - Chunks: a world of seed 42 with the arch volume element standing on the ground
//!   (`volume::pipeline::scenes::arch_element`); each client streams protocol v2
//!   (`api/stream_protocol_v2.md`), grants a credit for every frame it takes, and views the
//!   arch's LOD-0 chunks (one chunk ring). A latency is counted from an `invalidate` that lists
//!   chunks. Each edit adds an authored region inside the arch's box, so it reaches the arch's
//!   chunks; the next edit waits until every client has its fresh frames (`idle` at the new
//!   version), so the region's solve for one edit never delays the next one's invalidation.
//!
//! Both run against the server of `bench serve` in the same process, over loopback.

use super::http::http;
use crate::edits::{synthesize, TileEdits};
use crate::terrain::{TileKey, WorldParams, WorldPlan};
use anyhow::Context;
use futures::{SinkExt, StreamExt};
use serde_json::{json, Value};
use std::time::{Duration, Instant};
use tokio::sync::mpsc::{unbounded_channel, UnboundedSender};
use tokio_tungstenite::tungstenite::Message;

/// Target: p99 edit-to-invalidation latency, milliseconds.
pub const TARGET_INVALIDATION_P99_MS: f64 = 50.0;
/// Subscribed clients of the invalidation tests.
pub const SUBSCRIBERS: usize = 100;
/// The seed of both worlds.
const SEED: u64 = 42;

/// What a subscriber reports: an `invalidate` (with chunks, for the chunk test) at a version,
/// with the index of the server it is connected to and when it arrived, or an `idle` at a
/// version.
enum Event {
    Invalidated(usize, u64, Instant),
    Idle(u64),
}

/// Creates a public world of [`SEED`] with `scene`; its id and admin token.
async fn create_world(addr: &str, scene: Value) -> anyhow::Result<(String, String)> {
    let body = json!({"seed": SEED, "public": true, "scene": scene}).to_string();
    let (status, body) = http(
        addr,
        "POST",
        "/v1/worlds",
        &[("Content-Type", "application/json")],
        &body,
    )
    .await?;
    anyhow::ensure!(
        status == 201,
        "creating the world answered {status}: {}",
        String::from_utf8_lossy(&body)
    );
    let created: Value = serde_json::from_slice(&body)?;
    let id = created["id"].as_str().context("world id")?.to_string();
    let token = created["tokens"]["admin"].as_str().context("admin token")?;
    Ok((id, token.to_string()))
}

/// Adds the authored region `id` inside the arch's box (x and z from 10 to 20 m); the new version
/// and when the edit was acknowledged.
async fn edit(addr: &str, world: &str, token: &str, id: &str) -> anyhow::Result<(u64, Instant)> {
    let patch = json!([{"op":"add","path":"/regions/-","value":{"id":id,"bbox":{"min":[10.0,10.0],"max":[20.0,20.0]}}}]).to_string();
    let auth = format!("Bearer {token}");
    let (status, body) = http(
        addr,
        "POST",
        &format!("/v1/worlds/{world}/edits"),
        &[
            ("Content-Type", "application/json-patch+json"),
            ("Authorization", &auth),
        ],
        &patch,
    )
    .await?;
    let acked = Instant::now();
    anyhow::ensure!(
        status == 200,
        "edit answered {status}: {}",
        String::from_utf8_lossy(&body)
    );
    let version = serde_json::from_slice::<Value>(&body)?["version"]
        .as_u64()
        .context("version")?;
    Ok((version, acked))
}

/// Connects a subscriber to `path` on `addr` (server `server` of the run), sends `hello`
/// (credits, for v2) and `view`, and reports its invalidations (those listing chunks when
/// `chunks`) and idles to `tx`; resolves once it is first idle. A v2 subscriber grants a credit
/// back for every binary frame.
async fn subscribe(
    (server, addr): (usize, &str),
    path: &str,
    hello: Option<Value>,
    view: Value,
    chunks: bool,
    tx: UnboundedSender<Event>,
) -> anyhow::Result<tokio::sync::oneshot::Receiver<()>> {
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("ws://{addr}{path}")).await?;
    let credits = hello.is_some();
    if let Some(h) = hello {
        ws.send(Message::Text(h.to_string().into())).await?;
    }
    ws.send(Message::Text(view.to_string().into())).await?;
    let (ready_tx, ready_rx) = tokio::sync::oneshot::channel::<()>();
    tokio::spawn(async move {
        let mut ready_tx = Some(ready_tx);
        let credit = Message::Text(json!({"type":"credit","frames":1}).to_string().into());
        while let Some(Ok(msg)) = ws.next().await {
            let text = match msg {
                Message::Binary(_) if credits => {
                    if ws.send(credit.clone()).await.is_err() {
                        return;
                    }
                    continue;
                }
                Message::Text(t) => t,
                _ => continue,
            };
            let Ok(m) = serde_json::from_str::<Value>(&text) else {
                continue;
            };
            let version = m["version"].as_u64().unwrap_or(0);
            let event = match m["type"].as_str() {
                Some("idle") => {
                    if let Some(r) = ready_tx.take() {
                        let _ = r.send(());
                    }
                    Event::Idle(version)
                }
                Some("invalidate")
                    if !chunks || m["chunks"].as_array().is_some_and(|c| !c.is_empty()) =>
                {
                    Event::Invalidated(server, version, Instant::now())
                }
                _ => continue,
            };
            let _ = tx.send(event);
        }
    });
    Ok(ready_rx)
}

/// Runs `edits` edits on `world` through `addr` with every subscriber of `rx` connected:
/// `(server, latency in ms)` from each edit's acknowledgement to each subscriber's invalidation,
/// sorted by latency; with `settle`, each edit waits until every subscriber is idle at its
/// version before the next.
async fn measure(
    addr: &str,
    world: &str,
    token: &str,
    edits: usize,
    settle: bool,
    rx: &mut tokio::sync::mpsc::UnboundedReceiver<Event>,
) -> anyhow::Result<Vec<(usize, f64)>> {
    let mut out = Vec::with_capacity(edits * SUBSCRIBERS);
    for e in 0..edits {
        let (version, acked) = edit(addr, world, token, &format!("bench{e}")).await?;
        let (mut invalidated, mut idle) = (0, 0);
        while invalidated < SUBSCRIBERS || (settle && idle < SUBSCRIBERS) {
            let event = tokio::time::timeout(Duration::from_secs(300), rx.recv())
                .await
                .context("invalidation or fresh frames timed out")?
                .context("subscribers gone")?;
            match event {
                Event::Invalidated(server, v, at) if v == version => {
                    out.push((
                        server,
                        at.saturating_duration_since(acked).as_secs_f64() * 1e3,
                    ));
                    invalidated += 1;
                }
                Event::Idle(v) if v == version => idle += 1,
                _ => {}
            }
        }
        // Let the fresh tiles go out before the next edit.
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    out.sort_by(|a, b| a.1.total_cmp(&b.1));
    Ok(out)
}

/// Waits until every subscriber has been idle once.
async fn all_ready(ready: Vec<tokio::sync::oneshot::Receiver<()>>) -> anyhow::Result<()> {
    for r in ready {
        tokio::time::timeout(Duration::from_secs(300), r)
            .await
            .context("a subscriber never became idle")??;
    }
    Ok(())
}

/// Tiles: latencies (ms, sorted) from each edit's acknowledgement to each subscriber's
/// `invalidate`.
pub async fn tile_latency(addr: String, edits: usize) -> anyhow::Result<Vec<f64>> {
    let lat = tile_latency_across(addr.clone(), std::slice::from_ref(&addr), edits).await?;
    Ok(lat.into_iter().map(|(_, ms)| ms).collect())
}

/// Tiles, with the edits made through `addr` and the subscribers spread round robin over the
/// servers `subscribe_at` (replicas sharing `addr`'s store, or `addr` itself): `(index in
/// subscribe_at, latency in ms)` per delivery, sorted by latency.
pub async fn tile_latency_across(
    addr: String,
    subscribe_at: &[String],
    edits: usize,
) -> anyhow::Result<Vec<(usize, f64)>> {
    anyhow::ensure!(!subscribe_at.is_empty(), "no server to subscribe at");
    let (world, token) = create_world(&addr, json!({})).await?;
    let (tx, mut rx) = unbounded_channel();
    let mut ready = Vec::new();
    for i in 0..SUBSCRIBERS {
        let server = i % subscribe_at.len();
        let view = json!({"type":"view","x":32,"z":32,"rings":[0]});
        let path = format!("/v1/worlds/{world}/stream");
        let at = (server, subscribe_at[server].as_str());
        ready.push(subscribe(at, &path, None, view, false, tx.clone()).await?);
    }
    all_ready(ready).await?;
    measure(&addr, &world, &token, edits, false, &mut rx).await
}

/// Chunks: latencies (ms, sorted) from each edit's acknowledgement to each subscriber's
/// `invalidate` listing the arch's chunks.
pub async fn chunk_latency(addr: String, edits: usize) -> anyhow::Result<Vec<f64>> {
    let plan = WorldPlan::new(SEED, WorldParams::default())?;
    let key = TileKey { lod: 0, x: 0, z: 0 };
    let ground = synthesize(&plan, key, &TileEdits::default()).heights[24 * 65 + 32];
    let arch = crate::volume::pipeline::scenes::arch_element(ground);
    let (world, token) = create_world(&addr, json!({"volumes": [arch]})).await?;
    let (tx, mut rx) = unbounded_channel();
    let mut ready = Vec::new();
    for _ in 0..SUBSCRIBERS {
        let hello = json!({"type":"credit","frames":64});
        let view = json!({"type":"view","x":32,"z":24,"y":f64::from(ground) + 10.0,
                          "rings":[0],"chunk_rings":[1]});
        let path = format!("/v1/worlds/{world}/stream?protocol=2");
        ready.push(subscribe((0, &addr), &path, Some(hello), view, true, tx.clone()).await?);
    }
    all_ready(ready).await?;
    let lat = measure(&addr, &world, &token, edits, true, &mut rx).await?;
    Ok(lat.into_iter().map(|(_, ms)| ms).collect())
}

/// The 50th and 99th percentiles and the maximum of sorted `lat`.
pub fn percentiles(lat: &[f64]) -> (f64, f64, f64) {
    let pct = |p: f64| lat[((lat.len() as f64 - 1.0) * p).round() as usize];
    (pct(0.5), pct(0.99), lat[lat.len() - 1])
}
