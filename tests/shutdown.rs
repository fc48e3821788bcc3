//! Shutdown of the real `strata serve` process with open streams (issue 18, finding 6): SIGTERM
//! closes every stream with a close frame of code 1001, and nothing panics on the way out (a
//! cancelled blocking task is not a panic).

mod common;

use futures::{SinkExt, StreamExt};
use std::time::{Duration, Instant};
use tokio_tungstenite::tungstenite::Message;

/// Streams open when the signal comes: half of a bare seed, half of a stored world.
const STREAMS: usize = 50;

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// Reads until the server closes; the close frame's code, or `None` when the connection ended
/// without one.
async fn close_code(mut ws: Ws) -> Option<u16> {
    let deadline = Instant::now() + Duration::from_secs(30);
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        match tokio::time::timeout(left, ws.next()).await {
            Ok(Some(Ok(Message::Close(frame)))) => return frame.map(|f| u16::from(f.code)),
            Ok(Some(Ok(_))) => continue,
            Ok(Some(Err(_)) | None) | Err(_) => return None,
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn sigterm_closes_every_stream_with_going_away_and_nothing_panics() {
    let data = tempfile::tempdir().expect("temp dir");
    let (mut server, log) = common::start_logged(["--data".as_ref(), data.path().as_os_str()], &[]);
    let addr = server.addr.clone();
    let (status, body) = strata::bench::http::http(
        &addr,
        "POST",
        "/v1/worlds",
        &[("Content-Type", "application/json")],
        r#"{"seed":5,"public":true}"#,
    )
    .await
    .expect("create a world");
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&body));
    let world: serde_json::Value = serde_json::from_slice(&body).expect("JSON");
    let id = world["id"].as_str().expect("world id");

    let mut clients = Vec::new();
    for i in 0..STREAMS {
        let url = if i % 2 == 0 {
            format!("ws://{addr}/v1/seeds/42/stream")
        } else {
            format!("ws://{addr}/v1/worlds/{id}/stream")
        };
        let (mut ws, _) = tokio_tungstenite::connect_async(url)
            .await
            .expect("connect");
        let hello = tokio::time::timeout(Duration::from_secs(30), ws.next())
            .await
            .expect("hello within 30 s")
            .expect("stream open")
            .expect("hello");
        assert!(
            matches!(&hello, Message::Text(t) if t.contains("\"hello\"")),
            "{hello:?}"
        );
        // Views far apart, so that syntheses are running and queued when the signal comes.
        let view = format!(
            r#"{{"type":"view","x":{},"z":0,"rings":[3,3,3]}}"#,
            i as f64 * 20_000.0
        );
        ws.send(Message::Text(view.into()))
            .await
            .expect("send view");
        clients.push(ws);
    }
    tokio::time::sleep(Duration::from_millis(500)).await;

    let pid = i32::try_from(server.child.id()).expect("pid");
    // SAFETY: kill only sends a signal to the server process this test started.
    assert_eq!(unsafe { libc::kill(pid, libc::SIGTERM) }, 0, "send SIGTERM");
    let codes = futures::future::join_all(clients.into_iter().map(close_code)).await;
    let going_away = codes.iter().filter(|c| **c == Some(1001)).count();

    let deadline = Instant::now() + Duration::from_secs(60);
    let exit = loop {
        if let Some(status) = server.child.try_wait().expect("wait") {
            break status;
        }
        assert!(
            Instant::now() < deadline,
            "the server did not exit within 60 s of SIGTERM:\n{}",
            log.now()
        );
        tokio::time::sleep(Duration::from_millis(50)).await;
    };
    let log = log.finish();
    assert_eq!(
        going_away, STREAMS,
        "close codes seen by the clients (None: no close frame): {codes:?}\n{log}"
    );
    assert!(!log.contains("panicked"), "the server panicked:\n{log}");
    assert!(exit.success(), "exit status {exit}:\n{log}");
}
