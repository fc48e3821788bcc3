//! A minimal HTTP/1.1 client over TCP for `strata bench serve` and the tests that talk to a
//! running server.

use anyhow::Context;

/// `GET path` on `addr` ([`http`]).
///
/// # Errors
/// As [`http`].
pub async fn http_get(addr: &str, path: &str) -> anyhow::Result<(u16, Vec<u8>)> {
    http(addr, "GET", path, &[], "").await
}

/// One HTTP/1.1 request to `addr` (`host:port`) on a fresh TCP connection with
/// `Connection: close`: the status code and the body bytes. Minimal on purpose (no chunked
/// decoding, no redirects), so that the serve benchmark measures the server and not a client
/// library; the stream tests use it for the same reason.
///
/// # Errors
/// If the connection or the exchange fails, or the answer has no status line or header end.
pub async fn http(
    addr: &str,
    method: &str,
    path: &str,
    headers: &[(&str, &str)],
    body: &str,
) -> anyhow::Result<(u16, Vec<u8>)> {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let mut s = tokio::net::TcpStream::connect(addr).await?;
    let mut req = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Length: {}\r\n",
        body.len()
    );
    for (k, v) in headers {
        req.push_str(&format!("{k}: {v}\r\n"));
    }
    req.push_str("\r\n");
    req.push_str(body);
    s.write_all(req.as_bytes()).await?;
    let mut raw = Vec::new();
    s.read_to_end(&mut raw).await?;
    let split = raw
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .context("no header end")?;
    let head = String::from_utf8_lossy(&raw[..split]);
    let status = head
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .context("no status")?;
    Ok((status, raw[split + 4..].to_vec()))
}
