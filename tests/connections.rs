//! Connections of the real `strata serve` over raw TCP (issue 18, finding 5): a connection that
//! sends nothing, a partial header or a partial body is closed after the read timeout instead of
//! staying open, and connections beyond the cap (stream connections included) are refused with
//! a JSON 503 while the held ones keep working.

mod common;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

/// The read timeout the server runs with in these tests.
const TIMEOUT_MS: u64 = 400;

/// Reads until the server closes the connection (or `within` passes): what it sent, and when
/// it closed (`None`: still open after `within`).
fn until_closed(stream: &mut TcpStream, within: Duration) -> (Vec<u8>, Option<Duration>) {
    let start = Instant::now();
    stream
        .set_read_timeout(Some(Duration::from_millis(100)))
        .expect("read timeout");
    let (mut got, mut buf) = (Vec::new(), [0u8; 4096]);
    while start.elapsed() < within {
        match stream.read(&mut buf) {
            Ok(0) => return (got, Some(start.elapsed())),
            Ok(n) => got.extend_from_slice(&buf[..n]),
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) => {}
            Err(_) => return (got, Some(start.elapsed())),
        }
    }
    (got, None)
}

#[test]
fn slow_clients_are_closed_after_the_read_timeout() {
    let data = tempfile::tempdir().expect("tmp");
    let timeout = TIMEOUT_MS.to_string();
    let server = common::start(
        [
            "--data".as_ref(),
            data.path().as_os_str(),
            "--read-timeout-ms".as_ref(),
            timeout.as_ref(),
        ],
        &[],
    );
    let within = Duration::from_millis(TIMEOUT_MS * 10);
    let cases: [(&str, &[u8]); 3] = [
        ("nothing", b""),
        ("a partial header", b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Slow: "),
        (
            "a partial body",
            b"POST /v1/worlds HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 1000\r\n\r\n{\"seed\":",
        ),
    ];
    for (what, sent) in cases {
        let mut s = TcpStream::connect(&server.addr).expect("connect");
        s.write_all(sent).expect("send");
        let started = Instant::now();
        let (answer, closed) = until_closed(&mut s, within);
        let closed = closed.unwrap_or_else(|| {
            panic!("{what}: the connection is still open {within:?} after it went quiet")
        });
        assert!(
            started.elapsed() >= Duration::from_millis(TIMEOUT_MS / 2),
            "{what}: closed after {closed:?}, before the timeout"
        );
        let answer = String::from_utf8_lossy(&answer);
        if let Some((_, body)) = answer.split_once("\r\n\r\n") {
            let v: serde_json::Value = serde_json::from_str(body)
                .unwrap_or_else(|e| panic!("{what}: the answer is not JSON ({e}): {answer}"));
            assert!(v["error"]["code"].is_string(), "{what}: {answer}");
        }
    }
    // A prompt client is served as before.
    let mut s = TcpStream::connect(&server.addr).expect("connect");
    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        .expect("send");
    let (answer, closed) = until_closed(&mut s, within);
    assert!(closed.is_some());
    assert!(
        String::from_utf8_lossy(&answer).starts_with("HTTP/1.1 200"),
        "{}",
        String::from_utf8_lossy(&answer)
    );
}

#[test]
fn connections_beyond_the_cap_get_a_json_503() {
    let data = tempfile::tempdir().expect("tmp");
    let server = common::start(
        [
            "--data".as_ref(),
            data.path().as_os_str(),
            "--max-connections".as_ref(),
            "3".as_ref(),
        ],
        &[],
    );
    // A stream keeps its connection's slot after the upgrade.
    let mut stream = TcpStream::connect(&server.addr).expect("connect");
    stream
        .write_all(
            b"GET /v1/seeds/1/stream HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\n\
              Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\
              Sec-WebSocket-Version: 13\r\n\r\n",
        )
        .expect("send");
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .expect("read timeout");
    let mut head = [0u8; 12];
    stream.read_exact(&mut head).expect("handshake answer");
    assert_eq!(&head, b"HTTP/1.1 101", "{}", String::from_utf8_lossy(&head));
    let held: Vec<TcpStream> = (0..2)
        .map(|_| TcpStream::connect(&server.addr).expect("connect"))
        .collect();
    // The held connections are accepted before the next one is.
    std::thread::sleep(Duration::from_millis(300));
    let mut extra = TcpStream::connect(&server.addr).expect("connect");
    let (answer, closed) = until_closed(&mut extra, Duration::from_secs(5));
    assert!(closed.is_some(), "the refused connection is closed");
    let answer = String::from_utf8_lossy(&answer).into_owned();
    assert!(answer.starts_with("HTTP/1.1 503"), "{answer}");
    assert!(
        answer.to_ascii_lowercase().contains("retry-after: 1"),
        "{answer}"
    );
    let (_, body) = answer.split_once("\r\n\r\n").expect("a body");
    let v: serde_json::Value = serde_json::from_str(body).expect("JSON");
    assert_eq!(v["error"]["code"], "too_many_connections", "{v}");
    assert!(
        v["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("limit of 3")),
        "{v}"
    );

    // A held connection still works, and a closed one frees its slot.
    let mut first = held.into_iter();
    let mut s = first.next().expect("held");
    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        .expect("send");
    let (answer, _) = until_closed(&mut s, Duration::from_secs(5));
    assert!(String::from_utf8_lossy(&answer).starts_with("HTTP/1.1 200"));
    drop(s);
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        let mut s = TcpStream::connect(&server.addr).expect("connect");
        s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            .expect("send");
        let (answer, _) = until_closed(&mut s, Duration::from_secs(5));
        if String::from_utf8_lossy(&answer).starts_with("HTTP/1.1 200") {
            break;
        }
        assert!(Instant::now() < deadline, "the freed slot is never reused");
        std::thread::sleep(Duration::from_millis(50));
    }
}
