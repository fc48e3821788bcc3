//! One WebSocket client: its view, the tiles it holds, a bounded frame queue.
//!
//! Three things happen concurrently, in one `select!` loop plus a writer task:
//! - client messages: a new view replaces the pending work (tiles no longer in view are never
//!   produced), an edit is applied and acknowledged;
//! - edit events: held tiles whose reach (footprint plus the margin their inputs are read from,
//!   `scene::tile_reach`) meets the dirty region are invalidated (one text
//!   message) and queued again, ahead of the rest, in view order;
//! - production: while work is pending and the queue has room, the next tile is synthesised and
//!   queued. A full queue stops production (backpressure); a client that does not take a frame
//!   within [`SEND_TIMEOUT`] is disconnected (the kernel's socket buffers take the first frames,
//!   so a client that never reads is closed [`SEND_TIMEOUT`] after they fill).
//!
//! **Memory per client** is bounded: the queue holds at most [`QUEUE_FRAMES`] frames and
//! [`QUEUE_BYTES`] bytes of them (production waits for room), the WebSocket's write buffer one
//! frame more plus its 128 KiB write buffer, and the view's bookkeeping at most
//! [`super::view::MAX_VIEW_TILES`] entries: [`CLIENT_MEMORY_BOUND`] in all. Frames are
//! reference-counted bytes the source shares between clients (the server's body cache holds
//! them), so clients of one area hold one copy of each frame, not one each.
//!
//! At shutdown the server cancels the session's token: production stops at once and the client
//! gets a close frame with code [`GOING_AWAY`].

#[cfg(doc)]
use super::protocol::TileFrame;
use super::protocol::{ClientMessage, ServerMessage};
use super::view::{select, ViewTile, MAX_VIEW_TILES};
use crate::encode::Format;
use crate::scene::Dirty;
use crate::terrain::{TileKey, WorldPlan};
use axum::extract::ws::{CloseFrame, Message, WebSocket};
use futures::{SinkExt, StreamExt};
use std::borrow::Cow;
use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::{broadcast, mpsc, OwnedSemaphorePermit, Semaphore};
use tokio_util::sync::CancellationToken;

/// Frames buffered per client.
pub const QUEUE_FRAMES: usize = 16;
/// Bytes of frames buffered per client: production waits while the queue holds more.
pub const QUEUE_BYTES: usize = 1 << 20;
/// Largest tile frame, bytes: a LOD-0 JSON tile with every optional layer (about 0.4 MiB),
/// rounded up.
pub const MAX_FRAME_BYTES: usize = 1 << 20;
/// Memory one client may hold, bytes: the queued frames, one frame in production and one in
/// the WebSocket's buffers with its 128 KiB write buffer, and the view's bookkeeping (a tile
/// key and its seams per view tile, two hash maps of them).
pub const CLIENT_MEMORY_BOUND: usize =
    QUEUE_BYTES + 2 * MAX_FRAME_BYTES + (128 << 10) + MAX_VIEW_TILES * 256;
/// A client that does not accept a frame for this long is disconnected.
pub const SEND_TIMEOUT: Duration = Duration::from_secs(10);
/// Largest client message, bytes.
pub const MAX_MESSAGE_BYTES: usize = 256 * 1024;
/// Close code after a client message over [`MAX_MESSAGE_BYTES`] (RFC 6455 "message too big").
pub const MESSAGE_TOO_BIG: u16 = 1009;
/// Close code sent to every client when the server shuts down (RFC 6455 "going away").
pub const GOING_AWAY: u16 = 1001;
/// At shutdown, the longest a client is given to take its last messages and the close frame.
pub const GOING_AWAY_TIMEOUT: Duration = Duration::from_secs(2);

/// Process-wide stream counters (for `/metrics` and tests).
#[derive(Debug, Default)]
pub struct Stats {
    /// Connected stream clients.
    pub sessions: std::sync::atomic::AtomicI64,
    /// Tile frames produced since start.
    pub frames: std::sync::atomic::AtomicU64,
    /// Clients disconnected for not keeping up.
    pub dropped_slow: std::sync::atomic::AtomicU64,
}

/// The counters.
pub static STATS: Stats = Stats {
    sessions: std::sync::atomic::AtomicI64::new(0),
    frames: std::sync::atomic::AtomicU64::new(0),
    dropped_slow: std::sync::atomic::AtomicU64::new(0),
};

/// Decrements the session gauge when a session ends, however it ends.
struct SessionGuard;

impl Drop for SessionGuard {
    fn drop(&mut self) {
        STATS
            .sessions
            .fetch_sub(1, std::sync::atomic::Ordering::Relaxed);
    }
}

/// Why a request of a stream failed: the code, message and field of the API's one error shape
/// (the server's `AppError` converts into it), sent to the client as an `error` message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StreamError {
    /// Stable error code.
    pub code: &'static str,
    /// Human-readable explanation.
    pub message: String,
    /// The offending parameter or JSON pointer, if one is to blame.
    pub field: Option<Cow<'static, str>>,
}

/// The world at one version as a [`StreamSource`] serves it: the server's view of a world
/// version, which the session hands back when it asks for that version's tiles.
pub trait SourceView: Send + Sync + 'static {
    /// The version (a bare seed is version 1 forever).
    fn version(&self) -> u64;
    /// The version's plan.
    fn plan(&self) -> &Arc<WorldPlan>;
}

/// An edit of the stream's world, with the view of the version it made, so a session reads
/// nothing per edit.
#[derive(Clone, Debug)]
pub struct WorldEdit<V> {
    /// The view of the version the edit made.
    pub view: V,
    /// What it changed.
    pub dirty: Dirty,
}

/// What a stream shows: a bare seed or a stored world. The server implements it for both.
#[async_trait::async_trait]
pub trait StreamSource: Send + Sync + 'static {
    /// The world at one version.
    type View: SourceView + Clone;
    /// The current version's view.
    async fn current(&self) -> Result<Self::View, StreamError>;
    /// A new receiver of this world's edits, for a stream of a stored world; `None` for a bare
    /// seed.
    fn subscribe_edits(&self) -> Option<broadcast::Receiver<WorldEdit<Self::View>>>;
    /// Applies an edit sent on the socket; returns the new version.
    async fn edit(
        &self,
        patch: serde_json::Value,
        if_match: Option<u64>,
    ) -> Result<u64, StreamError>;
    /// The frame of tile `key` with `seams` of the world `view` in `format` (its bytes as
    /// [`TileFrame::encode`] writes them, with the view's version): reference-counted bytes a
    /// source shares between the clients that stream the same tile.
    async fn frame(
        &self,
        view: &Self::View,
        key: TileKey,
        seams: [bool; 4],
        format: Format,
    ) -> Result<axum::body::Bytes, StreamError>;
}

fn error_message(e: &StreamError, id: Option<String>) -> ServerMessage {
    ServerMessage::Error {
        code: e.code.to_string(),
        message: e.message.clone(),
        field: e.field.as_ref().map(|f| f.to_string()),
        id,
    }
}

fn refused(code: &'static str, field: &'static str, message: impl Into<String>) -> StreamError {
    StreamError {
        code,
        message: message.into(),
        field: Some(field.into()),
    }
}

/// The error sent before closing a stream whose client sent a message over [`MAX_MESSAGE_BYTES`].
fn too_large() -> StreamError {
    StreamError {
        code: "message_too_large",
        message: format!("messages are limited to {MAX_MESSAGE_BYTES} bytes; closing the stream"),
        field: None,
    }
}

/// Whether a read error is the WebSocket's message size limit (tungstenite's capacity error,
/// whose text starts with "Space limit exceeded"; axum does not expose its type).
fn is_too_large(e: &axum::Error) -> bool {
    e.to_string().contains("Space limit exceeded")
}

/// A queued message and, for a frame, its share of [`QUEUE_BYTES`], returned once it is sent.
type Queued = (Message, Option<OwnedSemaphorePermit>);

fn text(msg: &ServerMessage) -> Queued {
    (
        Message::Text(serde_json::to_string(msg).unwrap_or_default().into()),
        None,
    )
}

/// Runs a session until the client leaves or is dropped, or until `closing` is cancelled (the
/// server is shutting down): then the client gets the text messages already queued (acks, errors)
/// and a close frame with code 1001 (going away), within [`GOING_AWAY_TIMEOUT`].
pub async fn run<S: StreamSource>(socket: WebSocket, source: Arc<S>, closing: CancellationToken) {
    STATS
        .sessions
        .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let _guard = SessionGuard;
    let (mut sink, mut incoming) = socket.split();
    let (tx, mut rx) = mpsc::channel::<Queued>(QUEUE_FRAMES);
    let queued_bytes = Arc::new(Semaphore::new(QUEUE_BYTES));
    let writer_closing = closing.clone();
    let writer = tokio::spawn(async move {
        loop {
            let msg = tokio::select! {
                biased;
                () = writer_closing.cancelled() => break,
                msg = rx.recv() => msg,
            };
            let Some((msg, _bytes)) = msg else {
                let _ = sink.close().await;
                return;
            };
            match tokio::time::timeout(SEND_TIMEOUT, sink.send(msg)).await {
                Ok(Ok(())) => {}
                Ok(Err(_)) => return,
                Err(_) => {
                    tracing::info!("stream client too slow; disconnecting");
                    STATS
                        .dropped_slow
                        .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let close = CloseFrame {
                        code: 1008,
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
        rx.close();
        let going_away = async {
            while let Some((msg, _bytes)) = rx.recv().await {
                if matches!(msg, Message::Text(_)) {
                    sink.send(msg).await?;
                }
            }
            let close = CloseFrame {
                code: GOING_AWAY,
                reason: "server shutting down".into(),
            };
            sink.send(Message::Close(Some(close))).await
        };
        let _ = tokio::time::timeout(GOING_AWAY_TIMEOUT, going_away).await;
    });
    let mut edits = source.subscribe_edits();
    let mut current = match source.current().await {
        Ok(v) => v,
        Err(e) => {
            let _ = tx.send(text(&error_message(&e, None))).await;
            drop(tx);
            let _ = writer.await;
            return;
        }
    };
    let mut version = current.version();
    let cell_m = current.plan().params.cell_m as f64;
    let hello = ServerMessage::Hello {
        protocol: "strata.stream.v1",
        version,
        queue_frames: QUEUE_FRAMES,
    };
    if tx.send(text(&hello)).await.is_err() {
        return;
    }
    let mut format = Format::Bin;
    let mut view: Vec<ViewTile> = Vec::new();
    let mut held: HashMap<TileKey, u64> = HashMap::new();
    let mut pending: VecDeque<ViewTile> = VecDeque::new();
    let mut idle_sent = true;
    loop {
        if writer.is_finished() {
            break;
        }
        let edit_event = async {
            match edits.as_mut() {
                Some(rx) => rx.recv().await,
                None => std::future::pending().await,
            }
        };
        tokio::select! {
            () = closing.cancelled() => break,
            msg = incoming.next() => {
                let msg = match msg {
                    None => break,
                    Some(Ok(msg)) => msg,
                    Some(Err(e)) => {
                        if is_too_large(&e) {
                            let e = too_large();
                            let _ = tx.send(text(&error_message(&e, None))).await;
                            let close = CloseFrame { code: MESSAGE_TOO_BIG, reason: "message too large".into() };
                            let _ = tx.send((Message::Close(Some(close)), None)).await;
                        }
                        break;
                    }
                };
                let text_msg = match msg {
                    Message::Text(t) => t,
                    Message::Close(_) => break,
                    Message::Binary(_) => {
                        let e = refused("bad_message", "type", "send JSON text messages");
                        let _ = tx.send(text(&error_message(&e, None))).await;
                        continue;
                    }
                    _ => continue,
                };
                match ClientMessage::parse(&text_msg) {
                    Err(bad) => {
                        let e = StreamError {
                            code: "bad_message",
                            message: format!("not a strata.stream.v1 message: {}", bad.message),
                            field: Some(bad.field.into()),
                        };
                        let _ = tx.send(text(&error_message(&e, None))).await;
                    }
                    Ok(ClientMessage::View { x, z, rings, format: f }) => {
                        let reply = match view_of(x, z, &rings, f.as_deref(), cell_m) {
                            Err(e) => error_message(&e, None),
                            Ok((tiles, fmt)) => {
                                if fmt != format {
                                    held.clear();
                                    format = fmt;
                                }
                                let keys: HashSet<TileKey> = tiles.iter().map(|t| t.key).collect();
                                held.retain(|k, _| keys.contains(k));
                                pending = tiles.iter().filter(|t| held.get(&t.key) != Some(&version)).copied().collect();
                                view = tiles;
                                idle_sent = false;
                                ServerMessage::View { tiles: view.len(), sending: pending.len() }
                            }
                        };
                        if tx.send(text(&reply)).await.is_err() {
                            break;
                        }
                    }
                    Ok(ClientMessage::Edit { id, patch, if_match }) => {
                        let reply = match source.edit(patch, if_match).await {
                            Ok(v) => ServerMessage::Ack { id, version: v },
                            Err(e) => error_message(&e, Some(id)),
                        };
                        if tx.send(text(&reply)).await.is_err() {
                            break;
                        }
                    }
                }
            }
            ev = edit_event => {
                let (next, dirty) = match ev {
                    Ok(ev) => (ev.view, ev.dirty),
                    // Missed edits: the store's current version, everything stale.
                    Err(broadcast::error::RecvError::Lagged(_)) => match source.current().await {
                        Ok(v) => (v, Dirty::Everything),
                        Err(_) => continue,
                    },
                    Err(broadcast::error::RecvError::Closed) => { edits = None; continue; }
                };
                // Edits of one world may arrive out of order (their views are built
                // concurrently): an older one still invalidates what it touched, and tiles are
                // produced from the newest version seen, which includes it.
                if next.version() > version {
                    current = next;
                    version = current.version();
                }
                let params = &current.plan().params;
                let stale: Vec<ViewTile> = view.iter().filter(|t| held.contains_key(&t.key) && dirty.touches(&crate::scene::tile_reach(params, t.key))).copied().collect();
                // Tiles not held stay pending; held tiles the edit does not touch are current.
                for v in held.values_mut() {
                    *v = version;
                }
                if !stale.is_empty() {
                    let tiles = stale.iter().map(|t| [t.key.lod as i64, t.key.x, t.key.z]).collect();
                    if tx.send(text(&ServerMessage::Invalidate { version, tiles })).await.is_err() {
                        break;
                    }
                    let again: HashSet<TileKey> = stale.iter().map(|t| t.key).collect();
                    pending.retain(|t| !again.contains(&t.key));
                    for t in stale.iter().rev() {
                        held.remove(&t.key);
                        pending.push_front(*t);
                    }
                    idle_sent = false;
                }
            }
            permit = tx.reserve(), if !pending.is_empty() => {
                let Ok(permit) = permit else { break };
                let Some(t) = pending.pop_front() else { continue };
                let produced = tokio::select! {
                    r = source.frame(&current, t.key, t.seams, format) => r,
                    () = closing.cancelled() => break,
                };
                match produced {
                    Ok(frame) => {
                        // Room in the byte budget: the writer returns a frame's share once it is
                        // sent, or drops them all when it gives up on the client.
                        let share = u32::try_from(frame.len().min(QUEUE_BYTES)).unwrap_or(u32::MAX);
                        let bytes = tokio::select! {
                            b = queued_bytes.clone().acquire_many_owned(share) => b,
                            () = closing.cancelled() => break,
                        };
                        let Ok(bytes) = bytes else { break };
                        permit.send((Message::Binary(frame), Some(bytes)));
                        held.insert(t.key, version);
                        STATS.frames.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    }
                    Err(e) => permit.send(text(&error_message(&e, None))),
                }
            }
            _ = tokio::time::sleep(Duration::from_millis(250)), if pending.is_empty() && !idle_sent => {}
        }
        if pending.is_empty() && !idle_sent {
            idle_sent = true;
            if tx
                .send(text(&ServerMessage::Idle { version }))
                .await
                .is_err()
            {
                break;
            }
        }
    }
    drop(tx);
    let _ = writer.await;
}

/// Validates a view message: its position within the world, its rings and format; returns the
/// tiles it selects and the format. Public for the fuzz target `stream_message`.
pub fn view_of(
    x: f64,
    z: f64,
    rings: &[u32],
    format: Option<&str>,
    cell_m: f64,
) -> Result<(Vec<ViewTile>, Format), StreamError> {
    let limit = crate::terrain::plan::WORLD_LIMIT_CELLS * cell_m;
    for (name, v) in [("x", x), ("z", z)] {
        if !v.is_finite() || v.abs() > limit {
            return Err(refused(
                "coordinate_out_of_range",
                name,
                format!("{name} must be within ±{limit} m"),
            ));
        }
    }
    if rings.is_empty()
        || rings.len() > super::view::MAX_LEVELS
        || rings.iter().any(|r| *r > super::view::MAX_RINGS_PER_LEVEL)
    {
        return Err(refused(
            "bad_rings",
            "rings",
            format!(
                "rings: 1 to {} levels of 0 to {} rings",
                super::view::MAX_LEVELS,
                super::view::MAX_RINGS_PER_LEVEL
            ),
        ));
    }
    let format = match format {
        None => Format::Bin,
        Some(f) => Format::from_extension(f)
            .ok_or_else(|| refused("unknown_format", "format", format!("unknown format {f:?}")))?,
    };
    let tiles: Vec<ViewTile> = select(x, z, rings, cell_m)
        .into_iter()
        .filter(|t| {
            let lim = crate::terrain::plan::WORLD_LIMIT_CELLS / (64.0 * (1u64 << t.key.lod) as f64);
            (t.key.x.abs() as f64) < lim && (t.key.z.abs() as f64) < lim
        })
        .collect();
    if tiles.len() > MAX_VIEW_TILES {
        return Err(refused(
            "bad_rings",
            "rings",
            format!(
                "the view has {} tiles; at most {MAX_VIEW_TILES}",
                tiles.len()
            ),
        ));
    }
    Ok((tiles, format))
}
