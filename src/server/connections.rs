//! The accept loop of [`super::serve`]: HTTP/1.1 connections through hyper with a header read
//! timeout, at most [`Limits::max_connections`] at once, and graceful shutdown.
//!
//! - A connection that has not sent a whole request header within
//!   [`Limits::header_read_timeout`] of opening (or of its previous answer) is closed by hyper.
//! - The request body's pauses are bounded by the router ([`Limits::body_read_timeout`],
//!   `tower_http::timeout::RequestBodyTimeoutLayer`).
//! - Each connection holds a slot of a semaphore of [`Limits::max_connections`]; a WebSocket
//!   upgraded from it keeps the slot until its session ends ([`ConnectionSlot`]). A connection
//!   beyond the limit is answered `503` with the JSON error `too_many_connections` and
//!   `Retry-After: 1`, and closed.
//! - Each request carries its peer address (`axum::extract::ConnectInfo<SocketAddr>`), which the
//!   rate limits key ([`super::rate_limit`]).
//! - When `stopping` is cancelled the listener closes, every connection finishes its request in
//!   flight and closes, and [`serve`] waits up to [`super::SESSION_DRAIN_TIMEOUT`] for them.

use super::error::code;
use super::Limits;
use axum::body::Body;
use hyper::body::Incoming;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::service::TowerToHyperService;
use std::sync::Arc;
use std::time::Duration;
use tokio::io::AsyncWriteExt;
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{OwnedSemaphorePermit, Semaphore};
use tokio_util::sync::CancellationToken;
use tokio_util::task::TaskTracker;
use tower::ServiceExt;

/// How long a refused connection is given to take its 503 answer.
const REFUSAL_WRITE_TIMEOUT: Duration = Duration::from_secs(1);

/// The slot of the connection a request came on (a request extension): a stream session keeps
/// it, so that upgraded connections count against the limit until they end.
#[derive(Clone, Debug)]
pub struct ConnectionSlot {
    _permit: Arc<OwnedSemaphorePermit>,
}

/// Serves `app` on `listener` until `stopping` is cancelled, then drains the connections.
pub async fn serve(
    listener: TcpListener,
    app: axum::Router,
    limits: Limits,
    stopping: CancellationToken,
) {
    let slots = Arc::new(Semaphore::new(limits.max_connections));
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(TokioTimer::new())
        .header_read_timeout(limits.header_read_timeout);
    let connections = TaskTracker::new();
    loop {
        let stream = tokio::select! {
            () = stopping.cancelled() => break,
            accepted = listener.accept() => match accepted {
                Ok(accepted) => accepted,
                Err(e) => {
                    // Out of file descriptors, for instance: wait instead of spinning.
                    tracing::warn!("accept failed: {e}");
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
        };
        let (stream, peer) = stream;
        let Ok(permit) = slots.clone().try_acquire_owned() else {
            connections.spawn(refuse(stream, limits.max_connections));
            continue;
        };
        let slot = ConnectionSlot {
            _permit: Arc::new(permit),
        };
        let service = app
            .clone()
            .map_request(move |mut req: hyper::Request<Incoming>| {
                req.extensions_mut().insert(slot.clone());
                req.extensions_mut()
                    .insert(axum::extract::ConnectInfo(peer));
                req.map(Body::new)
            });
        let conn = http
            .serve_connection(TokioIo::new(stream), TowerToHyperService::new(service))
            .with_upgrades();
        let stopping = stopping.clone();
        connections.spawn(async move {
            let mut conn = std::pin::pin!(conn);
            let result = tokio::select! {
                r = conn.as_mut() => r,
                () = stopping.cancelled() => {
                    conn.as_mut().graceful_shutdown();
                    conn.await
                }
            };
            if let Err(e) = result {
                tracing::debug!("connection ended: {e}");
            }
        });
    }
    drop(listener);
    connections.close();
    if tokio::time::timeout(super::SESSION_DRAIN_TIMEOUT, connections.wait())
        .await
        .is_err()
    {
        tracing::warn!("connections still open at shutdown; closing them");
    }
}

/// Answers a connection over the limit with 503 `too_many_connections` and closes it.
async fn refuse(mut stream: TcpStream, max: usize) {
    tracing::debug!("connection refused: {max} connections open");
    let body = serde_json::json!({"error": {
        "code": code::TOO_MANY_CONNECTIONS,
        "message": format!("the server holds its limit of {max} connections; retry later"),
        "field": null,
    }})
    .to_string();
    let head = format!(
        "HTTP/1.1 503 Service Unavailable\r\ncontent-type: application/json\r\n\
         cache-control: no-store\r\nretry-after: 1\r\nconnection: close\r\n\
         content-length: {}\r\n\r\n",
        body.len()
    );
    let answer = async {
        stream.write_all(head.as_bytes()).await?;
        stream.write_all(body.as_bytes()).await?;
        stream.shutdown().await
    };
    let _ = tokio::time::timeout(REFUSAL_WRITE_TIMEOUT, answer).await;
}
