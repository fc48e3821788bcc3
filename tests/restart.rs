//! The same URL gives the same bytes across requests, server restarts and thread counts: the real
//! `strata` binary is started twice (one worker thread, then three) and asked for the same
//! products over real TCP.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

struct Server {
    child: Child,
    addr: String,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn start(worker_threads: usize, data: &std::path::Path) -> Server {
    let mut child = Command::new(env!("CARGO_BIN_EXE_strata"))
        .args([
            "serve",
            "--addr",
            "127.0.0.1:0",
            "--backend",
            "cpu",
            "--data",
        ])
        .arg(data)
        .env("TOKIO_WORKER_THREADS", worker_threads.to_string())
        .env("NO_COLOR", "1")
        .env("RUST_LOG", "strata=info")
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .expect("start strata serve");
    let stdout = child.stdout.take().expect("piped stdout");
    let mut lines = BufReader::new(stdout).lines();
    let addr = loop {
        let line = lines
            .next()
            .expect("server exited before listening")
            .expect("read server output");
        if let Some(rest) = line.split("listening on http://").nth(1) {
            break rest
                .split(|c: char| c.is_whitespace() || c == '\u{1b}')
                .next()
                .unwrap_or_default()
                .to_string();
        }
    };
    // Keep draining the log so the server never blocks on a full pipe.
    std::thread::spawn(move || for _ in lines.by_ref() {});
    Server { child, addr }
}

/// A minimal HTTP/1.1 GET: status code and body.
fn get(addr: &str, path: &str) -> (u16, Vec<u8>) {
    let mut s = TcpStream::connect(addr).expect("connect");
    s.set_read_timeout(Some(Duration::from_secs(60)))
        .expect("timeout");
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .expect("send");
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).expect("read");
    let split = raw
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("header end");
    let head = String::from_utf8_lossy(&raw[..split]).to_string();
    let status: u16 = head
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .expect("status");
    assert!(
        !head
            .to_ascii_lowercase()
            .contains("transfer-encoding: chunked"),
        "unexpected chunked body"
    );
    (status, raw[split + 4..].to_vec())
}

#[test]
fn bytes_are_identical_across_restarts_and_thread_counts() {
    let paths = [
        "/v1/seeds/42/tiles/0/0/0.bin",
        "/v1/seeds/42/tiles/0/-3/5.json",
        "/v1/seeds/7/tiles/2/-1/-1.glb",
        "/v1/seeds/7/tiles/4/3/-2.png",
        "/v1/seeds/7/tiles/1/2/2.bin?seams=1,1,0,0",
        "/v1/seeds/99/scatter/0/1/1.json",
    ];
    let data = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("restart-{}", std::process::id()));
    let mut runs = Vec::new();
    for threads in [1, 3] {
        let server = start(threads, &data);
        let bodies: Vec<Vec<u8>> = paths
            .iter()
            .map(|p| {
                let (status, body) = get(&server.addr, p);
                assert_eq!(status, 200, "{p}");
                assert!(!body.is_empty(), "{p}");
                // Twice within one run too.
                assert_eq!(get(&server.addr, p).1, body, "{p} changed between requests");
                body
            })
            .collect();
        runs.push(bodies);
    }
    for (i, p) in paths.iter().enumerate() {
        assert_eq!(
            runs[0][i], runs[1][i],
            "{p} differs after a restart with another thread count"
        );
    }
}
