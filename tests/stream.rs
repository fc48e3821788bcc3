//! WebSocket streaming with a real client (tokio-tungstenite) against the app on a real socket.

use futures::{SinkExt, StreamExt};
use std::sync::atomic::Ordering;
use std::time::Duration;
use strata::compute::Compute;
use strata::server::{app, AppState};
use strata::stream::protocol::TileFrame;
use strata::stream::session::STATS;
use strata::stream::view::select;
use strata::terrain::TileKey;
use tokio_tungstenite::tungstenite::Message;

/// The frame counter is process-wide: tests of this binary run one at a time.
static SERIAL: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

async fn serve() -> String {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    tokio::spawn(async move {
        axum::serve(listener, app(AppState::new(Compute::cpu())))
            .await
            .expect("serve");
    });
    format!("ws://{addr}")
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
