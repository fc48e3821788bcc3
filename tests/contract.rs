//! Every error is the JSON error shape (issue 18, finding 8): a path segment longer than a file
//! name, a path that is not UTF-8, a chunked body over the limit and a stream route without an
//! upgrade, which used to answer empty or `text/plain` bodies; the documented maximum of the edit
//! log's `limit`; stream errors that name the bad field; and a stream message over the limit,
//! which closes the stream with a close frame after a `message_too_large` error.

use axum::body::Body;
use axum::http::{Method, Request, StatusCode};
use futures::{SinkExt, StreamExt};
use http_body_util::BodyExt;
use serde_json::Value;
use std::time::Duration;
use strata::compute::Compute;
use strata::server::{app, AppState, MAX_BODY_BYTES};
use strata::stream::session::MAX_MESSAGE_BYTES;
use tokio_tungstenite::tungstenite::Message;
use tower::ServiceExt;

mod common;
use common::oneshot::{send, Reply};

/// Asserts the JSON error shape with this status, code and field.
fn json_error(r: &Reply, status: StatusCode, code: &str, field: Option<&str>) {
    assert_eq!(
        r.header("content-type"),
        Some("application/json"),
        "{status} {code}: {}",
        String::from_utf8_lossy(&r.body)
    );
    r.error(status, code, field);
    assert_eq!(r.json()["error"]["field"].as_str(), field);
}

async fn get(app: &axum::Router, uri: &str, headers: &[(&str, &str)]) -> Reply {
    send(app, Method::GET, uri, headers, None).await
}

#[tokio::test]
async fn every_error_is_the_json_shape() {
    let web = tempfile::tempdir().expect("tmp");
    std::fs::write(web.path().join("index.html"), "<!doctype html>").expect("write");
    let app = app(AppState::new(Compute::cpu()).with_web(web.path()));
    let none: &[(&str, &str)] = &[];

    // The viewer directory still serves its files.
    let r = get(&app, "/index.html", none).await;
    r.ok();
    assert_eq!(r.body, b"<!doctype html>");

    // Segments longer than a file name can be, plain or percent-encoded: 404, not 500.
    let long = "a".repeat(256);
    let encoded = "%61".repeat(300);
    for uri in [
        format!("/{long}"),
        format!("/assets/{long}.js"),
        format!("/{encoded}"),
        format!("/v1/{long}"),
    ] {
        let r = get(&app, &uri, none).await;
        json_error(&r, StatusCode::NOT_FOUND, "not_found", None);
    }

    // Percent-encoding that is not UTF-8, on any route.
    for uri in [
        "/v1/worlds/%ff",
        "/v1/worlds/%ff/tiles/0/0/0.json",
        "/v1/seeds/%ff/tiles/0/0/0.json",
        "/v1/jobs/%c3%28",
        "/%ff",
    ] {
        let r = get(&app, uri, none).await;
        json_error(&r, StatusCode::BAD_REQUEST, "bad_path", None);
    }

    // A chunked body (no Content-Length) over the limit.
    let chunk = vec![b' '; 64 * 1024];
    let chunks = (MAX_BODY_BYTES / chunk.len()) + 2;
    let stream = futures::stream::iter(
        (0..chunks).map(move |_| Ok::<_, std::io::Error>(axum::body::Bytes::from(chunk.clone()))),
    );
    let req = Request::builder()
        .method(Method::POST)
        .uri("/v1/worlds")
        .header("content-type", "application/json")
        .body(Body::from_stream(stream))
        .expect("request");
    let res = app.clone().oneshot(req).await.expect("infallible");
    let r = Reply {
        status: res.status(),
        headers: res.headers().clone(),
        body: res
            .into_body()
            .collect()
            .await
            .expect("body")
            .to_bytes()
            .to_vec(),
    };
    json_error(
        &r,
        StatusCode::PAYLOAD_TOO_LARGE,
        "payload_too_large",
        Some("body"),
    );
    assert!(
        r.json()["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains(&MAX_BODY_BYTES.to_string())),
        "the message states the limit: {}",
        r.json()
    );

    // A stream route without a WebSocket upgrade.
    let r = send(
        &app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "application/json")],
        Some(br#"{"seed":3,"public":true}"#),
    )
    .await;
    let id = r.json()["id"].as_str().expect("id").to_string();
    for uri in [
        "/v1/seeds/1/stream".to_string(),
        format!("/v1/worlds/{id}/stream"),
    ] {
        let r = get(&app, &uri, none).await;
        json_error(
            &r,
            StatusCode::UPGRADE_REQUIRED,
            "upgrade_required",
            Some("Upgrade"),
        );
        assert_eq!(r.header("upgrade"), Some("websocket"));
        let r = get(&app, &uri, &[("connection", "upgrade"), ("upgrade", "h2c")]).await;
        json_error(
            &r,
            StatusCode::UPGRADE_REQUIRED,
            "upgrade_required",
            Some("Upgrade"),
        );
    }
    // The stream route's own checks come first.
    let r = get(&app, "/v1/seeds/x/stream", none).await;
    json_error(&r, StatusCode::BAD_REQUEST, "bad_seed", Some("seed"));

    // The limits are listed where the route lists limits.
    let info = get(&app, "/v1/info", none).await.json();
    assert_eq!(info["limits"]["max_log_entries"], 1000);
    assert_eq!(
        info["limits"]["max_stream_message_bytes"],
        MAX_MESSAGE_BYTES
    );
    assert_eq!(
        info["limits"]["max_region_samples"],
        strata::authoring::spec_tools::MAX_ACCEPTED_SAMPLES
    );
    assert_eq!(
        info["limits"]["max_region_cell_steps"],
        strata::authoring::spec_tools::MAX_REGION_CELL_STEPS
    );

    // The edit log's documented maximum.
    let r = get(&app, &format!("/v1/worlds/{id}/edits?limit=1001"), none).await;
    json_error(&r, StatusCode::BAD_REQUEST, "bad_parameter", Some("limit"));

    // A method the route does not have.
    let r = send(&app, Method::DELETE, "/v1/info", none, None).await;
    json_error(
        &r,
        StatusCode::METHOD_NOT_ALLOWED,
        "method_not_allowed",
        None,
    );
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn next(ws: &mut Ws) -> Option<Message> {
    tokio::time::timeout(Duration::from_secs(30), ws.next())
        .await
        .expect("a message within 30 s")
        .and_then(Result::ok)
}

async fn next_text(ws: &mut Ws) -> Value {
    loop {
        match next(ws).await.expect("stream open") {
            Message::Text(t) => return serde_json::from_str(&t).expect("JSON"),
            Message::Close(c) => panic!("closed: {c:?}"),
            _ => continue,
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn stream_errors_name_the_field_and_oversized_messages_close_the_stream() {
    let addr = common::oneshot::serve_cpu().await;
    let (mut ws, _) = tokio_tungstenite::connect_async(format!("ws://{addr}/v1/seeds/1/stream"))
        .await
        .expect("connect");
    assert_eq!(next_text(&mut ws).await["type"], "hello");
    for (msg, field) in [
        (r#"{"type":"view","x":"east","z":0,"rings":[1]}"#, "x"),
        (r#"{"type":"view","x":0,"z":null,"rings":[1]}"#, "z"),
        (r#"{"type":"view","x":0,"z":0,"rings":"all"}"#, "rings"),
        (r#"{"type":"view","x":0,"z":0,"rings":[-1]}"#, "rings"),
        (r#"{"type":"view","z":0,"rings":[1]}"#, "x"),
        (r#"{"type":"view","x":0,"z":0}"#, "rings"),
        (
            r#"{"type":"view","x":0,"z":0,"rings":[1],"zoom":2}"#,
            "zoom",
        ),
        (
            r#"{"type":"view","x":0,"z":0,"rings":[1],"format":7}"#,
            "format",
        ),
        (r#"{"type":"edit","id":5,"patch":[]}"#, "id"),
        (
            r#"{"type":"edit","id":"e","patch":[],"if_match":-3}"#,
            "if_match",
        ),
        (r#"{"type":"edit","id":"e"}"#, "patch"),
        (r#"{"type":"fly"}"#, "type"),
        (r#"{"type":3}"#, "type"),
        (r#"{"x":0}"#, "type"),
        ("[1,2]", "type"),
        ("not json", "type"),
    ] {
        ws.send(Message::Text(msg.into())).await.expect("send");
        let m = next_text(&mut ws).await;
        assert_eq!(
            (m["type"].as_str(), m["code"].as_str(), m["field"].as_str()),
            (Some("error"), Some("bad_message"), Some(field)),
            "{msg}: {m}"
        );
    }
    // Still usable after the refusals.
    ws.send(Message::Text(
        r#"{"type":"view","x":0,"z":0,"rings":[0]}"#.into(),
    ))
    .await
    .expect("send");
    assert_eq!(next_text(&mut ws).await["type"], "view");

    let big = format!(
        r#"{{"type":"view","x":0,"z":0,"rings":[1],"format":"{}"}}"#,
        "b".repeat(MAX_MESSAGE_BYTES)
    );
    ws.send(Message::Text(big.into())).await.expect("send");
    let (mut too_large, mut close) = (None, None);
    while let Some(m) = next(&mut ws).await {
        match m {
            Message::Text(t) => {
                let v: Value = serde_json::from_str(&t).expect("JSON");
                if v["code"] == "message_too_large" {
                    too_large = Some(v);
                }
            }
            Message::Close(frame) => {
                close = Some(frame.map(|f| u16::from(f.code)));
                break;
            }
            _ => {}
        }
    }
    let too_large = too_large.expect("a message_too_large error before the close");
    assert!(
        too_large["message"]
            .as_str()
            .is_some_and(|m| m.contains(&MAX_MESSAGE_BYTES.to_string())),
        "{too_large}"
    );
    assert_eq!(
        close,
        Some(Some(1009)),
        "closed with 1009 (message too big)"
    );
}
