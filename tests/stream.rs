//! WebSocket streaming with a real client (tokio-tungstenite) against the app on a real socket.

use futures::{SinkExt, StreamExt};
use std::sync::atomic::Ordering;
use std::time::Duration;
use strata::stream::protocol::TileFrame;
use strata::stream::session::STATS;
use strata::stream::view::select;
use strata::terrain::TileKey;
use tokio_tungstenite::tungstenite::Message;

mod common;

/// The frame counter is process-wide: tests of this binary run one at a time.
static SERIAL: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

/// The app on a real socket; returns `ws://host:port`.
async fn serve() -> String {
    format!("ws://{}", common::oneshot::serve_cpu().await)
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn next(ws: &mut Ws) -> Message {
    tokio::time::timeout(Duration::from_secs(30), ws.next())
        .await
        .expect("a message within 30 s")
        .expect("stream open")
        .expect("message")
}

async fn next_json(ws: &mut Ws) -> serde_json::Value {
    loop {
        match next(ws).await {
            Message::Text(t) => return serde_json::from_str(&t).expect("JSON"),
            Message::Binary(_) => continue,
            _ => continue,
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tiles_arrive_nearest_first_then_idle() {
    let _serial = SERIAL.lock().await;
    let base = serve().await;
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("{base}/v1/seeds/42/stream"))
        .await
        .expect("connect");
    let hello = next_json(&mut ws).await;
    assert_eq!(hello["type"], "hello");
    assert_eq!(hello["protocol"], "strata.stream.v1");
    let (x, z, rings) = (100.0, -30.0, vec![1u32, 1, 1]);
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":x,"z":z,"rings":rings})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let view = next_json(&mut ws).await;
    assert_eq!(view["type"], "view");
    let want = select(x, z, &rings, 1.0);
    assert_eq!(view["tiles"], want.len());
    let mut got: Vec<TileFrame> = Vec::new();
    loop {
        match next(&mut ws).await {
            Message::Binary(b) => got.push(TileFrame::decode(&b).expect("a tile frame")),
            Message::Text(t) => {
                let m: serde_json::Value = serde_json::from_str(&t).expect("JSON");
                assert_eq!(m["type"], "idle", "{m}");
                break;
            }
            _ => {}
        }
    }
    let keys: Vec<TileKey> = got.iter().map(|f| f.key).collect();
    let want_keys: Vec<TileKey> = want.iter().map(|t| t.key).collect();
    assert_eq!(
        keys, want_keys,
        "tiles arrive in the view's nearest-first order"
    );
    for (f, t) in got.iter().zip(&want) {
        assert_eq!(f.seams, t.seams);
        assert_eq!(f.version, 1);
        assert_eq!(&f.payload[..4], b"STRT", "bin payload");
    }
    // Moving within the same tiles sends nothing new.
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":x + 1.0,"z":z,"rings":rings})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let again = next_json(&mut ws).await;
    assert_eq!(again["sending"], 0, "{again}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_new_view_cancels_the_old_one() {
    let _serial = SERIAL.lock().await;
    let base = serve().await;
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("{base}/v1/seeds/7/stream"))
        .await
        .expect("connect");
    next_json(&mut ws).await;
    let far = 500_000.0;
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":0,"z":0,"rings":[4,4,4]})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":far,"z":far,"rings":[1]})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let second: Vec<TileKey> = select(far, far, &[1], 1.0).iter().map(|t| t.key).collect();
    let first: Vec<TileKey> = select(0.0, 0.0, &[4, 4, 4], 1.0)
        .iter()
        .map(|t| t.key)
        .collect();
    let mut views = 0;
    let mut after_second = Vec::new();
    let mut before = 0;
    loop {
        match next(&mut ws).await {
            Message::Text(t) => {
                let m: serde_json::Value = serde_json::from_str(&t).expect("JSON");
                match m["type"].as_str() {
                    Some("view") => views += 1,
                    Some("idle") if views == 2 => break,
                    _ => {}
                }
            }
            Message::Binary(b) => {
                let f = TileFrame::decode(&b).expect("frame");
                if views == 2 {
                    after_second.push(f.key);
                } else {
                    before += 1;
                }
            }
            _ => {}
        }
    }
    // At most a queue's worth of the first view was produced before the second arrived; after
    // it, only the second view's tiles come, all of them.
    assert!(
        before < first.len(),
        "{before} of {} first-view tiles",
        first.len()
    );
    let tail: Vec<TileKey> = after_second
        .iter()
        .filter(|k| !first.contains(k) || second.contains(k))
        .copied()
        .collect();
    assert_eq!(tail, second);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_reads_nothing_stalls_production() {
    let _serial = SERIAL.lock().await;
    let base = serve().await;
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("{base}/v1/seeds/9/stream"))
        .await
        .expect("connect");
    next_json(&mut ws).await;
    let rings = [6u32, 6, 6, 6];
    let total = select(0.0, 0.0, &rings, 1.0).len();
    let start = STATS.frames.load(Ordering::Relaxed);
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":0,"z":0,"rings":rings,"format":"json"})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    // Read nothing; let the server fill its queue and the socket buffers.
    tokio::time::sleep(Duration::from_secs(3)).await;
    let a = STATS.frames.load(Ordering::Relaxed) - start;
    tokio::time::sleep(Duration::from_secs(1)).await;
    let b = STATS.frames.load(Ordering::Relaxed) - start;
    println!("{a} then {b} frames produced of {total} for a client that reads nothing");
    assert!(b < total as u64, "production must stall: {b} of {total}");
    assert_eq!(a, b, "production stopped growing");
    // Reading resumes it.
    let mut frames = 0;
    while frames < 10 {
        if let Message::Binary(_) = next(&mut ws).await {
            frames += 1;
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_messages_get_errors_naming_the_field() {
    let _serial = SERIAL.lock().await;
    let base = serve().await;
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("{base}/v1/seeds/1/stream"))
        .await
        .expect("connect");
    next_json(&mut ws).await;
    for (msg, code, field) in [
        (
            r#"{"type":"view","x":0,"z":0,"rings":[]}"#,
            "bad_rings",
            "rings",
        ),
        (
            r#"{"type":"view","x":1e12,"z":0,"rings":[1]}"#,
            "coordinate_out_of_range",
            "x",
        ),
        (
            r#"{"type":"view","x":0,"z":0,"rings":[1],"format":"tiff"}"#,
            "unknown_format",
            "format",
        ),
        (r#"{"type":"fly"}"#, "bad_message", "type"),
        ("not json", "bad_message", "type"),
    ] {
        ws.send(Message::Text(msg.into())).await.expect("send");
        let m = next_json(&mut ws).await;
        assert_eq!(m["type"], "error", "{msg}: {m}");
        assert_eq!(m["code"], code, "{msg}: {m}");
        assert_eq!(m["field"], field, "{msg}: {m}");
    }
    ws.send(Message::Text(
        r#"{"type":"edit","id":"e1","patch":[]}"#.into(),
    ))
    .await
    .expect("send");
    let m = next_json(&mut ws).await;
    assert_eq!(
        (m["code"].as_str(), m["id"].as_str()),
        (Some("read_only"), Some("e1"))
    );
}

/// Creates a world over HTTP; returns `(id, admin token)`.
async fn create_world(base: &str, public: bool) -> (String, String) {
    let http = base.replacen("ws://", "", 1);
    let body = serde_json::json!({"seed": 5, "public": public}).to_string();
    let (status, text) = raw_http(
        &http,
        "POST",
        "/v1/worlds",
        &[("Content-Type", "application/json")],
        &body,
    )
    .await;
    assert_eq!(status, 201, "{text}");
    let v: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    (
        v["id"].as_str().expect("id").to_string(),
        v["tokens"]["admin"]
            .as_str()
            .expect("admin token")
            .to_string(),
    )
}

/// A minimal HTTP/1.1 request over TCP ([`strata::bench::http::http`]): status and body text.
async fn raw_http(
    addr: &str,
    method: &str,
    path: &str,
    headers: &[(&str, &str)],
    body: &str,
) -> (u16, String) {
    let (status, body) = strata::bench::http::http(addr, method, path, headers, body)
        .await
        .expect("HTTP exchange");
    (status, String::from_utf8_lossy(&body).into_owned())
}

/// Reads until `idle`, returning the frames and control messages seen.
async fn until_idle(ws: &mut Ws) -> (Vec<TileFrame>, Vec<serde_json::Value>) {
    let (mut frames, mut msgs) = (Vec::new(), Vec::new());
    loop {
        match next(ws).await {
            Message::Binary(b) => frames.push(TileFrame::decode(&b).expect("frame")),
            Message::Text(t) => {
                let m: serde_json::Value = serde_json::from_str(&t).expect("JSON");
                let idle = m["type"] == "idle";
                msgs.push(m);
                if idle {
                    return (frames, msgs);
                }
            }
            _ => {}
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn edits_invalidate_the_tiles_they_touch_and_fresh_tiles_follow() {
    let _serial = SERIAL.lock().await;
    let base = serve().await;
    let (id, token) = create_world(&base, false).await;
    // A private world refuses a stream without a token.
    let refused = tokio_tungstenite::connect_async(format!("{base}/v1/worlds/{id}/stream")).await;
    assert!(refused.is_err(), "a private world needs a read token");
    let (mut ws, _) =
        tokio_tungstenite::connect_async(format!("{base}/v1/worlds/{id}/stream?token={token}"))
            .await
            .expect("connect");
    let hello = next_json(&mut ws).await;
    assert_eq!(hello["version"], 1);
    let rings = [1u32, 1];
    ws.send(Message::Text(
        serde_json::json!({"type":"view","x":32,"z":32,"rings":rings})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let (frames, _) = until_idle(&mut ws).await;
    let view = select(32.0, 32.0, &rings, 1.0);
    assert_eq!(frames.len(), view.len());

    // An edit on the socket: a region inside LOD-0 tile (0, 0).
    let patch = serde_json::json!([{"op":"add","path":"/regions/-","value":{"id":"r1","bbox":{"min":[10.0,10.0],"max":[20.0,20.0]}}}]);
    ws.send(Message::Text(
        serde_json::json!({"type":"edit","id":"e1","patch":patch,"if_match":1})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let (fresh, msgs) = until_idle(&mut ws).await;
    let ack = msgs.iter().find(|m| m["type"] == "ack").expect("ack");
    assert_eq!(
        (ack["id"].as_str(), ack["version"].as_u64()),
        (Some("e1"), Some(2))
    );
    let inv = msgs
        .iter()
        .find(|m| m["type"] == "invalidate")
        .expect("invalidate");
    assert_eq!(inv["version"], 2);
    let touched: Vec<TileKey> = inv["tiles"]
        .as_array()
        .expect("tiles")
        .iter()
        .map(|t| TileKey {
            lod: t[0].as_u64().expect("lod") as u32,
            x: t[1].as_i64().expect("x"),
            z: t[2].as_i64().expect("z"),
        })
        .collect();
    // The tiles whose inputs the region is in reach of (footprint plus margin), in view order.
    let region = strata::scene::Rect {
        min: [10.0, 10.0],
        max: [20.0, 20.0],
    };
    let world = strata::terrain::WorldParams::default();
    let expected: Vec<TileKey> = view
        .iter()
        .map(|t| t.key)
        .filter(|k| strata::scene::tile_reach(&world, *k).intersects(&region))
        .collect();
    assert!(expected.contains(&TileKey { lod: 0, x: 0, z: 0 }) && expected.len() < view.len());
    assert_eq!(touched, expected, "only the tiles in reach of the region");
    assert_eq!(
        fresh.iter().map(|f| (f.key, f.version)).collect::<Vec<_>>(),
        expected.iter().map(|k| (*k, 2)).collect::<Vec<_>>()
    );

    // An edit by another editor over HTTP reaches this socket too; a conflicting one is refused.
    let http = base.replacen("ws://", "", 1);
    let auth = format!("Bearer {token}");
    let patch = r#"[{"op":"add","path":"/regions/-","value":{"id":"r2","bbox":{"min":[-100.0,-100.0],"max":[-90.0,-90.0]}}}]"#;
    let (status, text) = raw_http(
        &http,
        "POST",
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("Content-Type", "application/json-patch+json"),
            ("Authorization", &auth),
            ("If-Match", "2"),
        ],
        patch,
    )
    .await;
    assert_eq!(status, 200, "{text}");
    let (fresh, msgs) = until_idle(&mut ws).await;
    let inv = msgs
        .iter()
        .find(|m| m["type"] == "invalidate")
        .expect("invalidate");
    assert_eq!(inv["version"], 3);
    assert!(
        inv["tiles"]
            .as_array()
            .is_some_and(|t| t.iter().all(|k| k[1].as_i64() < Some(0))),
        "{inv}"
    );
    assert!(fresh
        .iter()
        .all(|f| f.version == 3 && f.key.x < 0 && f.key.z < 0));
    ws.send(Message::Text(
        serde_json::json!({"type":"edit","id":"e2","patch":[],"if_match":1})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    let m = next_json(&mut ws).await;
    assert_eq!(
        (m["code"].as_str(), m["id"].as_str()),
        (Some("version_conflict"), Some("e2")),
        "{m}"
    );
}
