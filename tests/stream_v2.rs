//! Stream protocol v2 (`api/stream_protocol_v2.md`) with a real client (tokio-tungstenite)
//! against the app on a real socket: flow control by credits (a slow but live client is slowed,
//! never dropped, and never gets more frames than it granted; a client that grants nothing is
//! closed with 1008 and a reason), volume chunks of a world's volume region (the same bytes as
//! the HTTP chunk route, re-sent after an edit) and of a cave that opens to the ground (the
//! tiles marking the vertices where it does), and v1 still served by default.

use serde_json::{json, Value};
use std::time::Duration;
use strata::edits::{synthesize, TileEdits};
use strata::stream::protocol::{ChunkFrame, TileFrame};
use strata::stream::session::SEND_TIMEOUT;
use strata::stream::view::select;
use strata::terrain::{TileKey, WorldParams, WorldPlan};
use strata::volume::chunk::ChunkKey;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;
use tokio_tungstenite::tungstenite::Message;

mod common;

use common::ws::{connect, create_world, next, send, Ws};

/// The app on a real socket; returns `host:port`.
async fn serve() -> String {
    common::oneshot::serve_cpu().await
}

fn json_text(m: &Message) -> Option<Value> {
    match m {
        Message::Text(t) => Some(serde_json::from_str(t).expect("JSON")),
        _ => None,
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn v1_is_the_default_and_v2_is_asked_for_by_query() {
    let addr = serve().await;
    let mut v1 = connect(&addr, "/v1/seeds/3/stream").await;
    let hello = json_text(&next(&mut v1, Duration::from_secs(30)).await).expect("hello");
    assert_eq!(hello["protocol"], "strata.stream.v1");
    assert!(hello.get("credits").is_none(), "v1's hello is unchanged");
    assert!(hello.get("biomes").is_none(), "v1's hello is unchanged");
    // A v1 session refuses v2 messages, naming the field.
    send(&mut v1, json!({"type": "credit", "frames": 1})).await;
    let m = json_text(&next(&mut v1, Duration::from_secs(30)).await).expect("error");
    assert_eq!(
        (m["code"].as_str(), m["field"].as_str()),
        (Some("bad_message"), Some("type"))
    );
    let mut v2 = connect(&addr, "/v1/seeds/3/stream?protocol=2").await;
    let hello = json_text(&next(&mut v2, Duration::from_secs(30)).await).expect("hello");
    assert_eq!(hello["protocol"], "strata.stream.v2");
    assert_eq!(hello["credits"], 0);
    // The biomes the tiles' weights mean: a bare seed is the default world, earth-1's six.
    let params = strata::terrain::WorldParams::default();
    let names: Vec<&str> = params.biomes.iter().map(|b| b.name.as_str()).collect();
    assert_eq!(hello["generator"], "earth-1");
    assert_eq!(hello["biomes"], json!(names));
    assert_eq!(names.len(), 6, "earth-1's default biome set");
    // A bad protocol is a 400 naming the field, before the upgrade.
    let (status, body) =
        strata::bench::http::http(&addr, "GET", "/v1/seeds/3/stream?protocol=9", &[], "")
            .await
            .expect("HTTP");
    let body: Value = serde_json::from_slice(&body).expect("JSON error");
    assert_eq!(status, 400);
    assert_eq!(body["error"]["field"], "protocol");
}

/// Done-when item 3 of issue 19: a client that takes one frame every 2 s, granting one credit
/// at a time, stays connected for 60 s (six times the timeout) and gets every frame of its view,
/// never more than it granted.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_slow_client_granting_one_credit_at_a_time_is_slowed_not_dropped() {
    let addr = serve().await;
    let mut ws = connect(&addr, "/v1/seeds/11/stream?protocol=2").await;
    next(&mut ws, Duration::from_secs(30)).await;
    let rings = [3u32];
    send(
        &mut ws,
        json!({"type": "view", "x": 0, "z": 0, "rings": rings}),
    )
    .await;
    let want: Vec<TileKey> = select(0.0, 0.0, &rings, 1.0)
        .iter()
        .map(|t| t.key)
        .collect();
    const SLOW: usize = 30;
    assert!(want.len() > SLOW);
    let (mut granted, mut got) = (0usize, Vec::new());
    send(&mut ws, json!({"type": "credit", "frames": 1})).await;
    granted += 1;
    loop {
        match next(&mut ws, Duration::from_secs(60)).await {
            Message::Binary(b) => {
                got.push(TileFrame::decode(&b).expect("a tile frame").key);
                assert!(
                    got.len() <= granted,
                    "{} frames arrived with {granted} granted",
                    got.len()
                );
                if got.len() < SLOW {
                    tokio::time::sleep(Duration::from_secs(2)).await;
                    send(&mut ws, json!({"type": "credit", "frames": 1})).await;
                    granted += 1;
                } else if got.len() == SLOW {
                    // The rest at once.
                    let rest = want.len() - SLOW;
                    send(&mut ws, json!({"type": "credit", "frames": rest})).await;
                    granted += rest;
                }
            }
            Message::Text(t) => {
                let m: Value = serde_json::from_str(&t).expect("JSON");
                assert_ne!(m["type"], "error", "{m}");
                if m["type"] == "idle" {
                    break;
                }
            }
            Message::Close(c) => panic!("a slow but live client was closed: {c:?}"),
            _ => {}
        }
    }
    assert_eq!(got, want, "every frame of the view, nearest first");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_grants_nothing_is_closed_with_1008_and_a_reason() {
    let addr = serve().await;
    let mut ws = connect(&addr, "/v1/seeds/12/stream?protocol=2").await;
    next(&mut ws, Duration::from_secs(30)).await;
    send(
        &mut ws,
        json!({"type": "view", "x": 0, "z": 0, "rings": [1]}),
    )
    .await;
    loop {
        match next(&mut ws, SEND_TIMEOUT * 3).await {
            Message::Binary(_) => panic!("a frame without credit"),
            Message::Close(Some(c)) => {
                assert_eq!(c.code, CloseCode::Policy, "{c:?}");
                assert!(c.reason.contains("no credit"), "{c:?}");
                break;
            }
            Message::Close(None) => panic!("closed without a code"),
            _ => {}
        }
    }
}

const SEED: u64 = 7;

fn ground_at(x: i64, z: i64) -> f32 {
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let t = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[(z * 65 + x) as usize]
}

/// Reads frames until `idle`: the chunk frames, the tile frames and the control messages.
async fn until_idle(ws: &mut Ws) -> (Vec<ChunkFrame>, Vec<TileFrame>, Vec<Value>) {
    let (mut chunks, mut tiles, mut msgs) = (Vec::new(), Vec::new(), Vec::new());
    loop {
        match next(ws, Duration::from_secs(300)).await {
            Message::Binary(b) => match ChunkFrame::decode(&b) {
                Some(c) => chunks.push(c),
                None => tiles.push(TileFrame::decode(&b).expect("a tile or chunk frame")),
            },
            m => {
                if let Some(v) = json_text(&m) {
                    assert_ne!(v["type"], "error", "{v}");
                    let idle = v["type"] == "idle";
                    msgs.push(v);
                    if idle {
                        return (chunks, tiles, msgs);
                    }
                }
            }
        }
    }
}

async fn http_chunk(addr: &str, id: &str, key: ChunkKey, v: u64) -> Vec<u8> {
    let path = format!(
        "/v1/worlds/{id}/chunks/{}/{}/{}/{}.bin?v={v}",
        key.lod, key.x, key.y, key.z
    );
    let (status, body) = strata::bench::http::http(addr, "GET", &path, &[], "")
        .await
        .expect("HTTP");
    assert_eq!(status, 200, "{path}: {}", String::from_utf8_lossy(&body));
    body
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_volume_region_streams_its_chunks_and_an_edit_resends_them() {
    let addr = serve().await;
    let ground = ground_at(32, 24);
    let arch = common::arch::arch_element(ground);
    let (id, token) = create_world(&addr, SEED, Some(json!({"volumes": [arch]}))).await;

    let mut ws = connect(
        &addr,
        &format!("/v1/worlds/{id}/stream?protocol=2&token={token}"),
    )
    .await;
    next(&mut ws, Duration::from_secs(30)).await;
    send(&mut ws, json!({"type": "credit", "frames": 1024})).await;
    let y = f64::from(ground) + 10.0;
    send(
        &mut ws,
        json!({"type": "view", "x": 32, "z": 24, "y": y, "rings": [1], "chunk_rings": [2]}),
    )
    .await;
    let (chunks, tiles, msgs) = until_idle(&mut ws).await;
    let view = msgs
        .iter()
        .find(|m| m["type"] == "view")
        .expect("view reply");
    let listed = view["chunks"]
        .as_array()
        .expect("the view lists its chunks")
        .len();
    assert_eq!(tiles.len(), select(32.0, 24.0, &[1], 1.0).len());
    assert!(!chunks.is_empty(), "the arch's chunks arrive");
    assert_eq!(chunks.len(), listed, "every listed chunk arrives");
    // Only chunks meeting the region's box: x in [0, 64), z in [0, 48), y in y_m.
    let (lo, hi) = (f64::from(ground) - 12.0, f64::from(ground) + 36.0);
    for c in &chunks {
        let k = c.key;
        assert_eq!(k.lod, 0, "two rings of LOD 0 cover the region");
        assert!((0..2).contains(&k.x) && (0..2).contains(&k.z), "{k:?}");
        let (y0, y1) = (k.y as f64 * 32.0, (k.y + 1) as f64 * 32.0);
        assert!(y0 < hi && y1 > lo, "{k:?} misses the region's heights");
        assert_eq!(c.version, 1);
        assert_eq!(
            c.payload,
            http_chunk(&addr, &id, k, 1).await,
            "{k:?}: the chunk route's bytes"
        );
    }
    assert!(
        chunks.iter().any(|c| c.payload.len() > 96),
        "some chunk has a surface"
    );

    // An edit in the region's reach: an authored region inside the box.
    let patch = json!([{"op": "add", "path": "/regions/-",
                        "value": {"id": "r1", "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    send(
        &mut ws,
        json!({"type": "edit", "id": "e1", "patch": patch, "if_match": 1}),
    )
    .await;
    let (fresh, _, msgs) = until_idle(&mut ws).await;
    let inv = msgs
        .iter()
        .find(|m| m["type"] == "invalidate")
        .expect("invalidate");
    let stale: Vec<ChunkKey> = inv["chunks"]
        .as_array()
        .expect("chunks")
        .iter()
        .map(|a| ChunkKey {
            lod: a[0].as_u64().expect("lod") as u32,
            x: a[1].as_i64().expect("x"),
            y: a[2].as_i64().expect("y"),
            z: a[3].as_i64().expect("z"),
        })
        .collect();
    assert!(!stale.is_empty(), "{inv}");
    let resent: Vec<ChunkKey> = fresh.iter().map(|c| c.key).collect();
    assert_eq!(
        resent, stale,
        "each invalidated chunk comes again, nearest first"
    );
    for c in &fresh {
        assert_eq!(c.version, 2);
        assert_eq!(c.payload, http_chunk(&addr, &id, c.key, 2).await);
    }
}

/// The world columns `(x, z)` whose vertices a JSON tile frame marks `volume_override`, with
/// the marked vertices' heights.
fn marked(t: &TileFrame) -> Vec<((i64, i64), f64)> {
    let doc: Value = serde_json::from_slice(&t.payload).expect("a JSON tile");
    let Some(marks) = doc.get("volume_override") else {
        return Vec::new();
    };
    let heights = doc["heights"].as_array().expect("heights");
    let s = 1i64 << t.key.lod;
    marks
        .as_array()
        .expect("indices")
        .iter()
        .map(|v| {
            let v = v.as_u64().expect("index") as usize;
            let (i, j) = ((v % 65) as i64, (v / 65) as i64);
            let h = heights[v].as_f64().expect("height");
            (((t.key.x * 64 + i) * s, (t.key.z * 64 + j) * s), h)
        })
        .collect()
}

fn chunk_keys(list: &Value) -> Vec<ChunkKey> {
    list.as_array()
        .expect("chunk addresses")
        .iter()
        .map(|a| ChunkKey {
            lod: a[0].as_u64().expect("lod") as u32,
            x: a[1].as_i64().expect("x"),
            y: a[2].as_i64().expect("y"),
            z: a[3].as_i64().expect("z"),
        })
        .collect()
}

/// Issue 19, Done-when 1 over the WebSocket: a `strata` element whose cave opens to the ground
/// streams the chunks where it does without being asked, the tiles mark exactly the vertices
/// where it breaches, and removing the element drops the chunks and re-sends the tiles unmarked.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_cave_opening_to_the_ground_streams_its_chunks_and_tiles_mark_the_opening() {
    let addr = serve().await;
    let cave = common::cave::cave(SEED);
    let (id, token) =
        create_world(&addr, SEED, Some(json!({"strata": [cave.element.clone()]}))).await;
    let (cx, cz) = (
        (cave.min[0] + cave.max[0]) / 2.0,
        (cave.min[1] + cave.max[1]) / 2.0,
    );
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let (tx, tz) = ((cx / 64.0).floor() as i64, (cz / 64.0).floor() as i64);
    let plain = synthesize(
        &plan,
        TileKey {
            lod: 0,
            x: tx,
            z: tz,
        },
        &TileEdits::default(),
    );
    let at = |x: f64, z: f64| ((z as i64 - tz * 64) * 65 + (x as i64 - tx * 64)) as usize;
    let ground = f64::from(plain.heights[at(cx, cz)]);

    let mut ws = connect(
        &addr,
        &format!("/v1/worlds/{id}/stream?protocol=2&token={token}"),
    )
    .await;
    next(&mut ws, Duration::from_secs(30)).await;
    send(&mut ws, json!({"type": "credit", "frames": 1024})).await;
    let y = ground + 20.0;
    send(
        &mut ws,
        json!({"type": "view", "x": cx, "z": cz, "y": y, "rings": [1], "format": "json",
               "chunk_rings": [3]}),
    )
    .await;
    let (chunks, tiles, msgs) = until_idle(&mut ws).await;
    let view = msgs
        .iter()
        .find(|m| m["type"] == "view")
        .expect("view reply");
    let listed = chunk_keys(&view["chunks"]);
    println!(
        "cave {:?}..{:?}: {} breached columns, {} chunk frames, {} tiles",
        cave.min,
        cave.max,
        cave.breached.len(),
        chunks.len(),
        tiles.len()
    );
    assert!(!chunks.is_empty(), "the cave's chunks arrive unasked");
    let got: Vec<ChunkKey> = chunks.iter().map(|c| c.key).collect();
    assert_eq!(got, listed, "every listed chunk arrives, nearest first");
    // The chunks lie over the cave's square and hold its floor where it opens.
    for c in &chunks {
        let k = c.key;
        let (x0, z0) = (k.x as f64 * 32.0, k.z as f64 * 32.0);
        assert!(
            x0 < cave.max[0]
                && x0 + 32.0 > cave.min[0]
                && z0 < cave.max[1]
                && z0 + 32.0 > cave.min[1],
            "{k:?} is away from the cave"
        );
        assert_eq!(c.payload, http_chunk(&addr, &id, k, 1).await, "{k:?}");
    }
    // Tiles mark exactly the columns where the cave breaches; a marked vertex lies on the
    // cave's floor, inside a streamed chunk.
    assert_eq!(tiles.len(), select(cx, cz, &[1], 1.0).len());
    let mut marks: Vec<((i64, i64), f64)> = tiles.iter().flat_map(marked).collect();
    marks.sort_by_key(|m| m.0);
    marks.dedup_by_key(|m| m.0);
    let columns: Vec<(i64, i64)> = marks.iter().map(|m| m.0).collect();
    let mut breached = cave.breached.clone();
    breached.sort();
    assert_eq!(
        columns, breached,
        "marked vertices are the breached columns"
    );
    let cube_y = |y: f64| ((y / 32.0).floor() as i64 - 3, (y / 32.0).floor() as i64 + 3);
    let (ylo, yhi) = cube_y(y);
    let mut inside = 0;
    for &((x, z), h) in &marks {
        let key = ChunkKey {
            lod: 0,
            x: x.div_euclid(32),
            y: (h / 32.0).floor() as i64,
            z: z.div_euclid(32),
        };
        if key.y < ylo
            || key.y > yhi
            || (x - (cx.floor() as i64)).abs() > 96
            || (z - (cz.floor() as i64)).abs() > 96
        {
            continue;
        }
        inside += 1;
        assert!(
            got.contains(&key),
            "the opening at ({x}, {h}, {z}) is in no chunk: {key:?}"
        );
    }
    assert!(
        inside * 2 > marks.len(),
        "{inside} of {} openings in the rings",
        marks.len()
    );

    // Removing the element drops the chunks and re-sends the tiles it marked, unmarked.
    let patch = json!([{"op": "remove", "path": "/strata/0"}]);
    send(
        &mut ws,
        json!({"type": "edit", "id": "e1", "patch": patch, "if_match": 1}),
    )
    .await;
    let (fresh, retiled, msgs) = until_idle(&mut ws).await;
    let inv = msgs
        .iter()
        .find(|m| m["type"] == "invalidate")
        .expect("invalidate");
    let mut dropped = chunk_keys(&inv["dropped"]);
    dropped.sort_by_key(|k| (k.lod, k.x, k.y, k.z));
    let mut held = got.clone();
    held.sort_by_key(|k| (k.lod, k.x, k.y, k.z));
    assert_eq!(dropped, held, "every cave chunk leaves the view");
    assert!(
        fresh.is_empty(),
        "no chunk is sent for a world without caves"
    );
    assert!(!retiled.is_empty(), "the opened tiles come again");
    assert!(retiled
        .iter()
        .all(|t| t.version == 2 && marked(t).is_empty()));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_edit_of_the_biomes_sends_their_new_names_before_the_fresh_tiles() {
    let addr = serve().await;
    let (id, token) = create_world(&addr, SEED, None).await;
    let mut ws = connect(
        &addr,
        &format!("/v1/worlds/{id}/stream?protocol=2&token={token}"),
    )
    .await;
    let hello = json_text(&next(&mut ws, Duration::from_secs(30)).await).expect("hello");
    let mut names: Vec<String> = serde_json::from_value(hello["biomes"].clone()).expect("names");
    send(&mut ws, json!({"type": "credit", "frames": 1024})).await;
    send(
        &mut ws,
        json!({"type": "view", "x": 0, "z": 0, "y": 300, "rings": [1]}),
    )
    .await;
    until_idle(&mut ws).await;

    // An edit elsewhere in the scene sends no `world` message.
    let region = json!([{"op": "add", "path": "/regions/-",
                         "value": {"id": "r1", "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    send(
        &mut ws,
        json!({"type": "edit", "id": "e1", "patch": region}),
    )
    .await;
    let (_, _, msgs) = until_idle(&mut ws).await;
    assert!(msgs.iter().any(|m| m["type"] == "ack"), "{msgs:?}");
    assert!(!msgs.iter().any(|m| m["type"] == "world"), "{msgs:?}");

    // A renamed biome: the new names come before the invalidation and the fresh tiles.
    names[0] = "glacier".into();
    let rename = json!([{"op": "replace", "path": "/world/biomes/0/name", "value": "glacier"}]);
    send(
        &mut ws,
        json!({"type": "edit", "id": "e2", "patch": rename}),
    )
    .await;
    let (_, tiles, msgs) = until_idle(&mut ws).await;
    assert!(
        msgs.iter().any(|m| m["type"] == "ack" && m["version"] == 3),
        "{msgs:?}"
    );
    let world = msgs
        .iter()
        .position(|m| m["type"] == "world")
        .expect("a world message");
    assert_eq!(msgs[world]["version"], 3);
    assert_eq!(msgs[world]["generator"], "earth-1");
    assert_eq!(msgs[world]["biomes"], json!(names));
    let invalidate = msgs
        .iter()
        .position(|m| m["type"] == "invalidate")
        .expect("every held tile is stale");
    assert!(world < invalidate, "{msgs:?}");
    assert_eq!(tiles.len(), select(0.0, 0.0, &[1], 1.0).len());
}

/// A v2 view with `tile_format: 2` gets tile frames whose payloads are the version 2 tiles
/// (each vertex's water surface and kind) that `GET …/tiles/…bin?format=2` serves, so a client
/// tells lake water from a river's without guessing; `tile_format` is checked like `format`.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tile_format_2_streams_the_tiles_with_their_water_kinds() {
    let addr = serve().await;
    let mut ws = connect(&addr, "/v1/seeds/42/stream?protocol=2").await;
    let hello = json_text(&next(&mut ws, Duration::from_secs(30)).await).expect("hello");
    assert_eq!(hello["protocol"], "strata.stream.v2");
    for (bad, field) in [
        (json!({"tile_format": 3}), "tile_format"),
        (json!({"tile_format": 2, "format": "png"}), "tile_format"),
    ] {
        let mut view = json!({"type": "view", "x": 60000, "z": -18000, "rings": [1]});
        for (k, v) in bad.as_object().expect("fields") {
            view[k] = v.clone();
        }
        send(&mut ws, view).await;
        let m = json_text(&next(&mut ws, Duration::from_secs(30)).await).expect("error");
        assert_eq!(
            (m["code"].as_str(), m["field"].as_str()),
            (Some("unknown_format"), Some(field)),
            "{m}"
        );
    }
    // One LOD-6 tile and its ring around a lake that a river crosses (seed 42).
    send(&mut ws, json!({"type": "credit", "frames": 64})).await;
    send(
        &mut ws,
        json!({"type": "view", "x": 60000, "z": -18000, "rings": [0, 0, 0, 0, 0, 0, 1], "tile_format": 2}),
    )
    .await;
    let (_, tiles, _) = until_idle(&mut ws).await;
    assert!(
        tiles.len() >= 9,
        "a ring of LOD-6 tiles at least: {}",
        tiles.len()
    );
    let mut kinds = [0usize; 4];
    for t in &tiles {
        let s = |b: bool| u8::from(b).to_string();
        let path = format!(
            "/v1/seeds/42/tiles/{}/{}/{}.bin?format=2&seams={}",
            t.key.lod,
            t.key.x,
            t.key.z,
            t.seams.map(s).join(",")
        );
        let (status, body) = strata::bench::http::http(&addr, "GET", &path, &[], "")
            .await
            .expect("HTTP");
        assert_eq!(status, 200, "{path}");
        assert_eq!(t.payload, body, "the frame of {path} carries its bytes");
        // The header's version (offset 4) and water kind section (offset 112), little-endian.
        let p = &t.payload;
        assert_eq!(u16::from_le_bytes([p[4], p[5]]), 2, "a version 2 tile");
        let at = u32::from_le_bytes([p[112], p[113], p[114], p[115]]) as usize;
        for &k in &p[at..at + 65 * 65] {
            kinds[k as usize] += 1;
        }
    }
    assert!(
        kinds[2] > 0 && kinds[3] > 0,
        "the view holds lake and river water: {kinds:?}"
    );
}
