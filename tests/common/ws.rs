//! A stream client for the WebSocket tests: the app on a real socket, connect, send and receive,
//! and a public world to stream.

use futures::{SinkExt, StreamExt};
use serde_json::{json, Value};
use std::time::Duration;
use strata::stream::ptex::PtexSettings;
use tokio_tungstenite::tungstenite::Message;

/// A client's WebSocket.
pub type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// The app (CPU backend) with Ptex `settings` on a real loopback socket; returns `host:port`.
pub async fn serve_ptex(settings: PtexSettings) -> String {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    tokio::spawn(async move {
        let state =
            strata::server::AppState::new(strata::compute::Compute::cpu()).with_ptex(settings);
        axum::serve(listener, strata::server::app(state))
            .await
            .expect("serve");
    });
    addr.to_string()
}

/// Opens the stream at `path` (with its query).
pub async fn connect(addr: &str, path: &str) -> Ws {
    tokio_tungstenite::connect_async(format!("ws://{addr}{path}"))
        .await
        .expect("connect")
        .0
}

/// The next message, within `limit`.
pub async fn next(ws: &mut Ws, limit: Duration) -> Message {
    tokio::time::timeout(limit, ws.next())
        .await
        .expect("a message in time")
        .expect("stream open")
        .expect("message")
}

/// Sends `msg` as a text message.
pub async fn send(ws: &mut Ws, msg: Value) {
    ws.send(Message::Text(msg.to_string().into()))
        .await
        .expect("send");
}

/// Creates a public world of `seed`, with `scene` if given (else the server's default scene);
/// its id and admin token.
pub async fn create_world(addr: &str, seed: u64, scene: Option<Value>) -> (String, String) {
    let mut body = json!({"seed": seed, "public": true});
    if let Some(scene) = scene {
        body["scene"] = scene;
    }
    let (status, text) = strata::bench::http::http(
        addr,
        "POST",
        "/v1/worlds",
        &[("Content-Type", "application/json")],
        &body.to_string(),
    )
    .await
    .expect("HTTP");
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&text));
    let doc: Value = serde_json::from_slice(&text).expect("JSON");
    (
        doc["id"].as_str().expect("id").to_string(),
        doc["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}
