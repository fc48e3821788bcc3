//! The task that writes a session's [`Outbox`] to its socket.
//!
//! It takes items in order and sends each within [`SEND_TIMEOUT`]; a client whose socket takes
//! nothing for that long (it does not read) is sent close code [`POLICY_VIOLATION`] with the
//! reason and dropped. When the server shuts down it sends the control messages still queued
//! and close code [`GOING_AWAY`], within [`GOING_AWAY_TIMEOUT`].

use super::outbox::{Outbox, Outgoing};
use super::session::{GOING_AWAY, GOING_AWAY_TIMEOUT, POLICY_VIOLATION, SEND_TIMEOUT, STATS};
use axum::extract::ws::{CloseFrame, Message, WebSocket};
use futures::stream::SplitSink;
use futures::SinkExt;
use std::sync::atomic::Ordering;
use std::sync::Arc;
use std::time::Duration;
use tokio_util::sync::CancellationToken;

/// Writes `outbox` to `sink` until the outbox is closed and empty, the client stops taking
/// frames, the socket fails or `closing` is cancelled. Closes the outbox when it ends, so a
/// session waiting for room learns that the client is gone.
pub async fn write(
    mut sink: SplitSink<WebSocket, Message>,
    outbox: Arc<Outbox>,
    closing: CancellationToken,
) {
    loop {
        let item = tokio::select! {
            biased;
            () = closing.cancelled() => break,
            item = outbox.pop() => item,
        };
        let (msg, last) = match item {
            None => {
                let _ = sink.close().await;
                return;
            }
            Some(Outgoing::Text(t)) => (Message::Text(t.into()), false),
            Some(Outgoing::Frame { bytes, .. }) => (Message::Binary(bytes), false),
            Some(Outgoing::Close(c)) => (Message::Close(Some(c)), true),
        };
        match tokio::time::timeout(SEND_TIMEOUT, sink.send(msg)).await {
            Ok(Ok(())) if !last => {}
            Ok(_) => {
                outbox.close();
                return;
            }
            Err(_) => {
                tracing::info!("stream client took no frame for {SEND_TIMEOUT:?}; disconnecting");
                STATS.dropped_slow.fetch_add(1, Ordering::Relaxed);
                outbox.close();
                // The reason v1 documents.
                let close = CloseFrame {
                    code: POLICY_VIOLATION,
                    reason: "client too slow".into(),
                };
                let _ = tokio::time::timeout(
                    Duration::from_secs(1),
                    sink.send(Message::Close(Some(close))),
                )
                .await;
                return;
            }
        }
    }
    outbox.close();
    let going_away = async {
        for item in outbox.drain() {
            if let Outgoing::Text(t) = item {
                sink.send(Message::Text(t.into())).await?;
            }
        }
        let close = CloseFrame {
            code: GOING_AWAY,
            reason: "server shutting down".into(),
        };
        sink.send(Message::Close(Some(close))).await
    };
    let _ = tokio::time::timeout(GOING_AWAY_TIMEOUT, going_away).await;
}
