//! Issue 18, item 5: the expensive routes are rate-limited per client address and per token
//! (`strata serve --rate-limit N`): a burst over the limit is 429 `rate_limited` naming
//! `rate_limit`, with `Retry-After`; another address, or another token, is unaffected; a token
//! is limited from every address; a cached tile is never charged. Driven over TCP against the
//! real binary, each client from its own loopback source address (127.0.0.x).

use serde_json::Value;
use std::net::SocketAddr;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

mod common;

/// Requests per minute of the server under test.
const LIMIT: usize = 3;

/// An answer: status, lower-case header lines, body.
struct Answer {
    status: u16,
    head: String,
    body: Vec<u8>,
}

impl Answer {
    fn header(&self, name: &str) -> Option<&str> {
        self.head.lines().find_map(|l| {
            let (k, v) = l.split_once(':')?;
            (k.trim() == name).then(|| v.trim())
        })
    }

    fn json(&self) -> Value {
        serde_json::from_slice(&self.body).expect("a JSON body")
    }
}

/// One request on a fresh connection from source address `from` (`127.0.0.x`).
async fn request(
    server: &str,
    from: &str,
    method: &str,
    path: &str,
    token: Option<&str>,
    body: &str,
) -> Answer {
    let socket = tokio::net::TcpSocket::new_v4().expect("socket");
    socket
        .bind(format!("{from}:0").parse::<SocketAddr>().expect("source"))
        .expect("bind the source address");
    let mut s = socket
        .connect(server.parse().expect("server address"))
        .await
        .expect("connect");
    let mut head = format!("{method} {path} HTTP/1.1\r\nHost: {server}\r\nConnection: close\r\n");
    if let Some(t) = token {
        head.push_str(&format!("Authorization: Bearer {t}\r\n"));
    }
    if method != "GET" {
        head.push_str(&format!(
            "Content-Type: application/json\r\nContent-Length: {}\r\n",
            body.len()
        ));
    }
    head.push_str("\r\n");
    s.write_all(head.as_bytes()).await.expect("write");
    s.write_all(body.as_bytes()).await.expect("write");
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).await.expect("read");
    let split = raw
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("header end");
    let head = String::from_utf8_lossy(&raw[..split]).to_ascii_lowercase();
    let status = head
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .expect("status");
    Answer {
        status,
        head,
        body: raw[split + 4..].to_vec(),
    }
}

async fn get(server: &str, from: &str, path: &str, token: Option<&str>) -> Answer {
    request(server, from, "GET", path, token, "").await
}

fn limited(a: &Answer) {
    assert_eq!(a.status, 429, "{}", String::from_utf8_lossy(&a.body));
    let e = &a.json()["error"];
    assert_eq!(e["code"], "rate_limited");
    assert_eq!(e["field"], "rate_limit");
    let message = e["message"].as_str().expect("message");
    assert!(
        message.contains(&format!("rate_limit of {LIMIT}")),
        "{message}"
    );
    let wait: u64 = a
        .header("retry-after")
        .and_then(|v| v.parse().ok())
        .expect("Retry-After");
    assert!((1..=60).contains(&wait), "Retry-After: {wait}");
}

/// A server with `--rate-limit` [`LIMIT`] and its data directory.
fn server() -> (common::Server, tempfile::TempDir) {
    let data = tempfile::tempdir().expect("tmp");
    let path = data.path().to_str().expect("utf-8").to_owned();
    let server = common::start(["--rate-limit", &LIMIT.to_string(), "--data", &path], &[]);
    (server, data)
}

#[tokio::test]
async fn a_burst_of_scatter_is_refused_per_address_and_per_token() {
    let (srv, _data) = server();
    let addr = srv.addr.as_str();
    let scatter = "/v1/seeds/42/scatter/8/0/0.json";
    for _ in 0..LIMIT {
        assert_eq!(get(addr, "127.0.0.2", scatter, None).await.status, 200);
    }
    limited(&get(addr, "127.0.0.2", scatter, None).await);
    // Another address is unaffected.
    assert_eq!(get(addr, "127.0.0.3", scatter, None).await.status, 200);
    // Volume chunks are meshed on every request, so they are charged too.
    let chunk = "/v1/seeds/42/chunks/2/0/0/0.bin";
    for _ in 0..LIMIT {
        assert_eq!(get(addr, "127.0.0.5", chunk, None).await.status, 200);
    }
    limited(&get(addr, "127.0.0.5", chunk, None).await);
    // A world and two of its tokens (world creation is not rate-limited).
    let created = request(
        addr,
        "127.0.0.4",
        "POST",
        "/v1/worlds",
        None,
        r#"{"seed":42}"#,
    )
    .await;
    assert_eq!(created.status, 201);
    let world = created.json();
    let (id, t1) = (
        world["id"].as_str().expect("id").to_owned(),
        world["tokens"]["admin"].as_str().expect("token").to_owned(),
    );
    let minted = request(
        addr,
        "127.0.0.4",
        "POST",
        &format!("/v1/worlds/{id}/tokens"),
        Some(&t1),
        r#"{"role":"read"}"#,
    )
    .await;
    assert_eq!(
        minted.status,
        201,
        "{}",
        String::from_utf8_lossy(&minted.body)
    );
    let t2 = minted.json()["token"].as_str().expect("token").to_owned();
    let scatter = format!("/v1/worlds/{id}/scatter/8/0/0.json");
    for i in 0..LIMIT {
        // Each request from its own address: only the token runs out.
        let from = format!("127.0.1.{}", i + 1);
        assert_eq!(get(addr, &from, &scatter, Some(&t1)).await.status, 200);
    }
    let refused = get(addr, "127.0.2.1", &scatter, Some(&t1)).await;
    limited(&refused);
    assert!(refused.json()["error"]["message"]
        .as_str()
        .is_some_and(|m| m.contains("token")));
    // Another token from that address is unaffected.
    assert_eq!(
        get(addr, "127.0.2.1", &scatter, Some(&t2)).await.status,
        200
    );
}

#[tokio::test]
async fn cached_tiles_are_never_charged() {
    let (srv, _data) = server();
    let addr = srv.addr.as_str();
    let from = "127.0.3.1";
    let tile = |x: i64| format!("/v1/seeds/42/tiles/3/{x}/0.bin");
    assert_eq!(get(addr, from, &tile(0), None).await.status, 200);
    for _ in 0..4 * LIMIT {
        assert_eq!(
            get(addr, from, &tile(0), None).await.status,
            200,
            "a cached tile"
        );
    }
    for x in 1..LIMIT as i64 {
        assert_eq!(get(addr, from, &tile(x), None).await.status, 200);
    }
    limited(&get(addr, from, &tile(LIMIT as i64), None).await);
    assert_eq!(
        get(addr, from, &tile(1), None).await.status,
        200,
        "cached after the limit"
    );
}

#[tokio::test]
async fn export_creation_is_charged_and_the_limit_is_in_v1_info() {
    let (srv, _data) = server();
    let addr = srv.addr.as_str();
    let info = get(addr, "127.0.4.1", "/v1/info", None).await.json();
    assert_eq!(info["limits"]["rate_limit_per_minute"], LIMIT);
    let from = "127.0.4.2";
    let created = request(addr, from, "POST", "/v1/worlds", None, r#"{"seed":5}"#).await;
    let world = created.json();
    let (id, token) = (
        world["id"].as_str().expect("id"),
        world["tokens"]["admin"].as_str().expect("token"),
    );
    let path = format!("/v1/worlds/{id}/exports");
    let body = r#"{"lod":4,"region":[0,0,1,1],"products":["tiles"],"formats":["bin"]}"#;
    for _ in 0..LIMIT {
        let a = request(addr, from, "POST", &path, Some(token), body).await;
        assert_eq!(a.status, 202, "{}", String::from_utf8_lossy(&a.body));
    }
    limited(&request(addr, from, "POST", &path, Some(token), body).await);
}
