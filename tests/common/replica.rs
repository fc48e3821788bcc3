//! Requests and stream sessions against running replicas (`tests/replicas.rs`,
//! `tests/balancer.rs`): the server admin token in every request, a stream session that has
//! received its view, a world created through a given address.

use futures::{SinkExt, StreamExt};
use serde_json::{json, Value};
use std::time::Duration;
use tokio_tungstenite::tungstenite::Message;

/// A client WebSocket.
pub type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// `method path` to `addr` with `Authorization: Bearer admin` and `headers`, on the blocking
/// pool: the status and the body.
pub async fn request(
    addr: &str,
    admin: &'static str,
    method: &'static str,
    path: String,
    headers: Vec<(&'static str, String)>,
    body: Vec<u8>,
) -> (u16, Vec<u8>) {
    let addr = addr.to_string();
    tokio::task::spawn_blocking(move || {
        let bearer = format!("Bearer {admin}");
        let mut h: Vec<(&str, &str)> = vec![("authorization", &bearer)];
        h.extend(headers.iter().map(|(k, v)| (*k, v.as_str())));
        super::raw::request(&addr, method, &path, &h, &body)
            .unwrap_or_else(|e| panic!("{method} {path}: {e}"))
    })
    .await
    .expect("request task")
}

/// Creates a public world of `seed` through `addr`: its id and admin token.
pub async fn create_world(addr: &str, admin: &'static str, seed: u64) -> (String, String) {
    let (status, body) = request(
        addr,
        admin,
        "POST",
        "/v1/worlds".into(),
        vec![("content-type", "application/json".into())],
        serde_json::to_vec(&json!({ "seed": seed })).expect("json"),
    )
    .await;
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&body));
    let w: Value = serde_json::from_slice(&body).expect("json");
    (
        w["id"].as_str().expect("id").to_string(),
        w["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}

/// The next text message of `ws` as JSON (within 60 s).
pub async fn next_json(ws: &mut Ws) -> Value {
    loop {
        let m = tokio::time::timeout(Duration::from_secs(60), ws.next())
            .await
            .expect("a message within 60 s")
            .expect("stream open")
            .expect("message");
        if let Message::Text(t) = m {
            return serde_json::from_str(&t).expect("JSON");
        }
    }
}

/// A stream session on `addr` of world `id`, with its view sent and every tile received.
pub async fn session(addr: &str, id: &str, token: &str) -> Ws {
    let (mut ws, _) = tokio_tungstenite::connect_async(format!(
        "ws://{addr}/v1/worlds/{id}/stream?token={token}"
    ))
    .await
    .expect("connect");
    assert_eq!(next_json(&mut ws).await["type"], "hello");
    ws.send(Message::Text(
        json!({"type": "view", "x": 16, "z": 16, "rings": [1]})
            .to_string()
            .into(),
    ))
    .await
    .expect("send");
    while next_json(&mut ws).await["type"] != "idle" {}
    ws
}
