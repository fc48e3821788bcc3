//! One WebSocket client: its view, the products it holds, a bounded outbox.
//!
//! Three things happen concurrently, in one `select!` loop plus a writer task
//! ([`super::writer`]):
//! - client messages: a new view replaces the pending work (products no longer in view are never
//!   produced, their queued frames are withdrawn; a v2 view's cave chunks are chosen from the
//!   height tiles under the caves near the ground, which the reply waits for), an edit is
//!   applied and acknowledged, a v2 `credit` lets more frames go;
//! - edit events: held products whose reach (footprint plus the margin their inputs are read
//!   from, `scene::tile_reach`) meets the dirty region are invalidated (one text message; tiles
//!   and chunks by the edit's surface region, [`WorldEdit::surface`], which an edit of the
//!   Ptex elements alone leaves empty); their
//!   queued frames are withdrawn (superseded frames are coalesced) and they are queued again,
//!   ahead of the rest, in view order;
//! - production: while work is pending, the outbox has room and (v2) the client has credit, the
//!   next product is synthesised and queued. A full outbox or no credit stops production: the
//!   client is slowed, never dropped for it. A v2 client that opted in to Ptex pages
//!   ([`super::ptex`]) also gets batches of pages, at most one per
//!   [`super::ptex::PTEX_EVERY`] frames while tiles or chunks wait, each spending a credit;
//!   `idle` then waits for its pages too. A v2 client that holds no credit while frames wait
//!   and sends nothing for [`SEND_TIMEOUT`] is closed with [`POLICY_VIOLATION`] and a reason;
//!   a client whose socket takes no frame for [`SEND_TIMEOUT`] (it does not read) likewise.
//!
//! **Memory per client** is bounded: the outbox holds at most [`QUEUE_FRAMES`] items and
//! [`QUEUE_BYTES`] bytes of frames plus the one frame that crossed the byte bound (production
//! waits for room), the WebSocket's write buffer one frame more plus its 128 KiB write buffer,
//! and the view's bookkeeping at most [`super::view::MAX_VIEW_TILES`] tiles and
//! [`super::chunks::MAX_VIEW_CHUNKS`] chunks: [`CLIENT_MEMORY_BOUND`] in all. No frame over
//! [`MAX_FRAME_BYTES`] is queued (a larger chunk is refused with an `error`). Frames are
//! reference-counted bytes the source shares between clients (the server's body cache holds
//! them), so clients of one area hold one copy of each frame, not one each.
//!
//! At shutdown the server cancels the session's token: production stops at once and the client
//! gets a close frame with code [`GOING_AWAY`].

use super::cave_chunks::{cave_columns, column_chunks, column_tiles, ground_span};
use super::chunks::{
    chunk_view_of, select_chunks, sort_nearest, within_limits, Box3, Rings, MAX_VIEW_CHUNKS,
};
use super::outbox::{Outbox, Outgoing};
#[cfg(doc)]
use super::protocol::TileFrame;
use super::protocol::{
    chunk_address, ClientMessage, Protocol, ServerMessage, VolumeView, MAX_CREDITS,
};
use super::ptex::{
    chunk_frame_quads, face_reach, PtexBaked, PtexBatch, PtexGrant, PtexSession, PTEX_EVERY,
};
use super::view::{select, ViewTile, MAX_VIEW_TILES};
use super::work::{merge, Product, Work};
use crate::encode::{Format, TileVersion};
use crate::scene::{Dirty, Rect};
use crate::subsurface::openings::CaveSite;
use crate::terrain::{Tile, TileKey, WorldParams, WorldPlan};
use crate::volume::chunk::{tiles_needed, ChunkKey};
use axum::extract::ws::{CloseFrame, Message, WebSocket};
use futures::StreamExt;
use std::borrow::Cow;
use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::broadcast;
use tokio::time::Instant;
use tokio_util::sync::CancellationToken;

/// Frames buffered per client.
pub const QUEUE_FRAMES: usize = 16;
/// Bytes of frames buffered per client: production waits while the queue holds more.
pub const QUEUE_BYTES: usize = 1 << 20;
/// Largest frame, bytes: a LOD-0 JSON tile with every optional layer (about 0.4 MiB), rounded
/// up. A chunk frame over it is not sent (the client gets an `error` naming the chunk).
pub const MAX_FRAME_BYTES: usize = 1 << 20;
/// Memory one client may hold, bytes: the queued frames, the one frame that crossed the byte
/// bound and one in the WebSocket's buffers with its 128 KiB write buffer, and the view's
/// bookkeeping (a product's address and its seams per view tile and chunk, in a few lists and
/// hash maps).
pub const CLIENT_MEMORY_BOUND: usize = QUEUE_BYTES
    + 2 * MAX_FRAME_BYTES
    + (128 << 10)
    + (MAX_VIEW_TILES + super::chunks::MAX_VIEW_CHUNKS + super::chunks::MAX_ASKED_CHUNKS) * 256;
/// A client whose socket takes no frame for this long, or (v2) that holds no credit while
/// frames wait and sends nothing for this long, is disconnected with [`POLICY_VIOLATION`].
pub const SEND_TIMEOUT: Duration = Duration::from_secs(10);
/// Close code of a client that neither reads nor grants credit for [`SEND_TIMEOUT`] (RFC 6455
/// "policy violation").
pub const POLICY_VIOLATION: u16 = 1008;
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
    /// The boxes where the world's surface is not a heightfield (its volume regions), metres:
    /// the chunk rings of a v2 view stream the chunks meeting them.
    fn volume_boxes(&self) -> Vec<Box3>;
    /// The caves of the world's `strata` elements that breach the ground or may come near it
    /// and whose bounding square meets the ground area `[x0, z0, x1, z1]` (metres), searched
    /// nearest `centre` first within a bounded budget ([`crate::subsurface::openings`]).
    fn cave_sites(&self, area: [f64; 4], centre: [f64; 2]) -> Vec<CaveSite>;
}

/// The names of `plan`'s biomes, in the order of its tiles' biome weights.
fn biome_names(plan: &WorldPlan) -> Vec<String> {
    plan.params.biomes.iter().map(|b| b.name.clone()).collect()
}

/// An edit of the stream's world, with the view of the version it made, so a session reads
/// nothing per edit.
#[derive(Clone, Debug)]
pub struct WorldEdit<V> {
    /// The view of the version the edit made.
    pub view: V,
    /// What it changed: where its Ptex pages may differ.
    pub dirty: Dirty,
    /// Where its tiles and volume chunks may differ: [`Dirty::Nothing`] for an edit of
    /// `materials` or `decals` only ([`crate::scene::PTEX_KINDS`]), else `dirty`.
    pub surface: Dirty,
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
    /// The frame of tile `key` with `seams` of the world `view` in `format` of `version` (its
    /// bytes as [`TileFrame::encode`] writes them, with the view's version): reference-counted
    /// bytes a source shares between the clients that stream the same tile.
    async fn frame(
        &self,
        view: &Self::View,
        key: TileKey,
        seams: [bool; 4],
        format: Format,
        version: TileVersion,
    ) -> Result<axum::body::Bytes, StreamError>;
    /// Height tile `key` of the world `view` without seams: the tile a volume chunk reads its
    /// columns from (the cave selection reads its ground, [`super::cave_chunks`]).
    async fn ground_tile(&self, view: &Self::View, key: TileKey) -> Arc<Tile>;
    /// The frame of volume chunk `key` of the world `view` in `format` (its bytes as
    /// [`super::protocol::ChunkFrame::encode_parts`] writes them, with the view's version),
    /// shared between clients like tile frames.
    async fn chunk_frame(
        &self,
        view: &Self::View,
        key: ChunkKey,
        format: Format,
    ) -> Result<axum::body::Bytes, StreamError>;
    /// Protocol v2 Ptex pages: a session's share of the server's page budget and the detail
    /// levels' distance thresholds, or `None` when the server's budget has no room.
    fn ptex_grant(&self) -> Option<(PtexGrant, [f32; 5])>;
    /// The frame of kind 3 of a batch of Ptex pages of the world `view`, with the bounds of
    /// each page's face ([`super::ptex`]).
    async fn ptex_frame(
        &self,
        view: &Self::View,
        batch: &PtexBatch,
    ) -> Result<PtexBaked, StreamError>;
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

fn text(msg: &ServerMessage) -> Outgoing {
    Outgoing::Text(serde_json::to_string(msg).unwrap_or_default())
}

/// The ground rectangle whose edits may change chunk `key`: the union of the reaches of the
/// height tiles it reads its columns from (their reaches hold the chunk's volume regions and
/// `strata` elements too).
fn chunk_reach(params: &WorldParams, key: ChunkKey) -> Rect {
    let mut reach: Option<Rect> = None;
    for (x, z) in tiles_needed(key) {
        let r = crate::scene::tile_reach(params, TileKey { lod: key.lod, x, z });
        reach = Some(match reach {
            None => r,
            Some(a) => Rect {
                min: [a.min[0].min(r.min[0]), a.min[1].min(r.min[1])],
                max: [a.max[0].max(r.max[0]), a.max[1].max(r.max[1])],
            },
        });
    }
    reach.unwrap_or(Rect {
        min: [0.0; 2],
        max: [0.0; 2],
    })
}

/// What a client's current view asks for.
#[derive(Default)]
struct ViewState {
    /// Camera `[x, y, z]`, metres.
    camera: [f64; 3],
    /// Tiles of the view, nearest first.
    tiles: Vec<ViewTile>,
    /// v2: chunk rings, asked chunks and the chunk format.
    rings: Vec<u32>,
    asked: Vec<ChunkKey>,
    chunk_format: Option<Format>,
    /// Chunks of the view (rings meeting volume regions, and asked), nearest first.
    chunks: Vec<ChunkKey>,
}

impl ViewState {
    /// The chunks of this view in the world `view` of `source`: the rings' chunks meeting its
    /// volume regions or its caves near the ground (at most [`MAX_VIEW_CHUNKS`], the nearest),
    /// and the asked ones, nearest first.
    async fn chunks_in<S: StreamSource>(&self, source: &S, view: &S::View) -> Vec<ChunkKey> {
        if self.chunk_format.is_none() {
            return Vec::new();
        }
        let plan = view.plan();
        let cell_m = f64::from(plan.params.cell_m);
        let valid = |k: ChunkKey| within_limits(plan, k);
        let mut chunks = select_chunks(
            self.camera,
            &self.rings,
            cell_m,
            &view.volume_boxes(),
            valid,
        );
        let rings = Rings::new(self.camera, &self.rings, cell_m);
        let sites = match rings.area() {
            Some(area) => view.cave_sites(area, [self.camera[0], self.camera[2]]),
            None => Vec::new(),
        };
        // The tiles of the level being visited (neighbouring columns share them).
        let mut tiles: HashMap<TileKey, Arc<Tile>> = HashMap::new();
        for c in cave_columns(&rings, cell_m, &sites) {
            tiles.retain(|k, _| k.lod == c.lod);
            let mut held = Vec::new();
            for (x, z) in column_tiles(&c) {
                let key = TileKey { lod: c.lod, x, z };
                let tile = match tiles.get(&key) {
                    Some(t) => t.clone(),
                    None => {
                        let t = source.ground_tile(view, key).await;
                        tiles.insert(key, t.clone());
                        t
                    }
                };
                held.push(((x, z), tile));
            }
            let held: Vec<((i64, i64), &Tile)> =
                held.iter().map(|(xz, t)| (*xz, t.as_ref())).collect();
            if let Some(ground) = ground_span(&c, &held) {
                for k in column_chunks(&rings, cell_m, &c, ground, valid) {
                    if !chunks.contains(&k) {
                        chunks.push(k);
                    }
                }
            }
        }
        sort_nearest(&mut chunks, self.camera, cell_m);
        chunks.truncate(MAX_VIEW_CHUNKS);
        for k in &self.asked {
            if !chunks.contains(k) {
                chunks.push(*k);
            }
        }
        sort_nearest(&mut chunks, self.camera, cell_m);
        chunks
    }

    /// Every product of the view, nearest first.
    fn work(&self, cell_m: f64) -> Vec<Work> {
        merge(
            self.tiles.iter().copied(),
            self.chunks.iter().copied(),
            self.camera,
            cell_m,
        )
    }
}

/// Runs a session of `protocol` until the client leaves or is dropped, or until `closing` is
/// cancelled (the server is shutting down): then the client gets the text messages already
/// queued (acks, errors) and a close frame with code 1001 (going away), within
/// [`GOING_AWAY_TIMEOUT`].
pub async fn run<S: StreamSource>(
    socket: WebSocket,
    source: Arc<S>,
    closing: CancellationToken,
    protocol: Protocol,
) {
    STATS
        .sessions
        .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let _guard = SessionGuard;
    let (sink, mut incoming) = socket.split();
    let outbox = Arc::new(Outbox::new(QUEUE_FRAMES, QUEUE_BYTES));
    let writer = tokio::spawn(super::writer::write(sink, outbox.clone(), closing.clone()));
    let mut edits = source.subscribe_edits();
    let mut current = match source.current().await {
        Ok(v) => v,
        Err(e) => {
            outbox.push(text(&error_message(&e, None))).await;
            outbox.close();
            let _ = writer.await;
            return;
        }
    };
    let mut version = current.version();
    let cell_m = current.plan().params.cell_m as f64;
    let v2 = protocol == Protocol::V2;
    // v1 has no flow control: unlimited credit, never spent.
    let mut credits: u32 = if v2 { 0 } else { u32::MAX };
    let hello = ServerMessage::Hello {
        protocol: protocol.name(),
        version,
        queue_frames: QUEUE_FRAMES,
        credits: v2.then_some(0),
        generator: v2.then_some(current.plan().params.generator),
        biomes: v2.then(|| biome_names(current.plan())),
    };
    if !outbox.push(text(&hello)).await {
        return;
    }
    // The tile frames' format and its version (`tile_format`, v2 views only).
    let mut format = (Format::Bin, TileVersion::V1);
    let mut view = ViewState::default();
    let mut held: HashMap<Product, u64> = HashMap::new();
    let mut pending: VecDeque<Work> = VecDeque::new();
    let mut idle_sent = true;
    // v2: the Ptex pages of a client that opted in; frames since the last Ptex batch.
    let mut ptex: Option<PtexSession> = None;
    let mut since_ptex: u32 = 0;
    let mut ptex_serial: u64 = 0;
    // Since when frames have waited for a credit the client does not grant (v2).
    let mut starved_since: Option<Instant> = None;
    loop {
        if writer.is_finished() || outbox.is_closed() {
            break;
        }
        let ptex_work = ptex.as_ref().is_some_and(PtexSession::has_work);
        if credits == 0 && (!pending.is_empty() || ptex_work) {
            starved_since.get_or_insert_with(Instant::now);
        } else {
            starved_since = None;
        }
        let starved_until = starved_since.map(|t| t + SEND_TIMEOUT);
        let edit_event = async {
            match edits.as_mut() {
                Some(rx) => rx.recv().await,
                None => std::future::pending().await,
            }
        };
        tokio::select! {
            () = closing.cancelled() => break,
            msg = incoming.next() => {
                starved_since = None;
                let msg = match msg {
                    None => break,
                    Some(Ok(msg)) => msg,
                    Some(Err(e)) => {
                        if is_too_large(&e) {
                            let e = too_large();
                            outbox.push(text(&error_message(&e, None))).await;
                            let close = CloseFrame { code: MESSAGE_TOO_BIG, reason: "message too large".into() };
                            outbox.push_now(Outgoing::Close(close));
                        }
                        break;
                    }
                };
                let text_msg = match msg {
                    Message::Text(t) => t,
                    Message::Close(_) => break,
                    Message::Binary(_) => {
                        let e = refused("bad_message", "type", "send JSON text messages");
                        outbox.push(text(&error_message(&e, None))).await;
                        continue;
                    }
                    _ => continue,
                };
                match ClientMessage::parse(&text_msg, protocol) {
                    Err(bad) => {
                        let e = StreamError {
                            code: "bad_message",
                            message: format!("not a {} message: {}", protocol.name(), bad.message),
                            field: Some(bad.field.into()),
                        };
                        outbox.push(text(&error_message(&e, None))).await;
                    }
                    Ok(ClientMessage::Credit { frames }) => {
                        credits = credits.saturating_add(frames).min(MAX_CREDITS);
                    }
                    Ok(ClientMessage::View { x, z, rings, format: f, volume }) => {
                        let accepted = view_of(x, z, &rings, f.as_deref(), cell_m).and_then(|(tiles, fmt)| {
                            let fmt = (fmt, tile_version_of(volume.as_ref().and_then(|v| v.tile_format), fmt)?);
                            let chunks = match &volume {
                                Some(vol) => Some(chunk_view_of(vol, current.plan())?),
                                None => None,
                            };
                            Ok((tiles, fmt, chunks))
                        }).and_then(|(tiles, fmt, chunks)| {
                            let eye = [x, volume.as_ref().map_or(0.0, |v| v.y), z];
                            let pv = match volume.as_ref().and_then(|v| v.ptex.as_ref()) {
                                Some(p) => Some((p.view(eye).map_err(|(field, m)| StreamError {
                                    code: "bad_ptex",
                                    message: m,
                                    field: Some(format!("ptex.{field}").into()),
                                })?, p.chunks)),
                                None => None,
                            };
                            Ok((tiles, fmt, chunks, pv))
                        });
                        let reply = match accepted {
                            Err(e) => error_message(&e, None),
                            Ok((tiles, fmt, chunks, pv)) => {
                                match pv {
                                    None => ptex = None,
                                    Some((pv, chunk_pages)) => {
                                        if ptex.is_none() {
                                            match source.ptex_grant() {
                                                Some((grant, thresholds)) => {
                                                    let mut p = PtexSession::new(grant, thresholds);
                                                    outbox.push_now(Outgoing::Text(serde_json::to_string(&p.hello()).unwrap_or_default()));
                                                    ptex = Some(p);
                                                }
                                                None => {
                                                    let e = refused("ptex_unavailable", "ptex", "the server's Ptex page budget is taken by other sessions; try again later");
                                                    outbox.push_now(text(&error_message(&e, None)));
                                                }
                                            }
                                        }
                                        if let Some(p) = ptex.as_mut() {
                                            p.set_view(pv, chunk_pages);
                                        }
                                    }
                                }
                                if fmt != format {
                                    held.retain(|p, _| matches!(p, Product::Chunk(_)));
                                    format = fmt;
                                }
                                let vol = volume.unwrap_or_default();
                                if let Some((_, cf)) = &chunks {
                                    if view.chunk_format != Some(*cf) {
                                        held.retain(|p, _| matches!(p, Product::Tile(_)));
                                    }
                                }
                                let VolumeView { y, chunk_rings, .. } = vol;
                                let (asked, chunk_format) = match chunks {
                                    Some((asked, cf)) => (asked, Some(cf)),
                                    None => (Vec::new(), None),
                                };
                                view = ViewState { camera: [x, y, z], tiles, rings: chunk_rings, asked, chunk_format, chunks: Vec::new() };
                                view.chunks = view.chunks_in(source.as_ref(), &current).await;
                                let work = view.work(cell_m);
                                let in_view: HashSet<Product> = work.iter().map(Work::product).collect();
                                held.retain(|p, _| in_view.contains(p));
                                if let Some(p) = ptex.as_mut() {
                                    p.retain_products(|k| in_view.contains(&Product::Tile(k)), |k| in_view.contains(&Product::Chunk(k)));
                                }
                                let gone = outbox.withdraw_unless(&in_view);
                                if v2 {
                                    credits = credits.saturating_add(gone as u32).min(MAX_CREDITS);
                                }
                                pending = work.into_iter().filter(|w| held.get(&w.product()) != Some(&version)).collect();
                                idle_sent = false;
                                ServerMessage::View {
                                    tiles: view.tiles.len(),
                                    sending: pending.len(),
                                    chunks: v2.then(|| view.chunks.iter().map(|k| chunk_address(*k)).collect()),
                                }
                            }
                        };
                        if !outbox.push(text(&reply)).await {
                            break;
                        }
                    }
                    Ok(ClientMessage::Edit { id, patch, if_match }) => {
                        let reply = match source.edit(patch, if_match).await {
                            Ok(v) => ServerMessage::Ack { id, version: v },
                            Err(e) => error_message(&e, Some(id)),
                        };
                        if !outbox.push(text(&reply)).await {
                            break;
                        }
                    }
                }
            }
            ev = edit_event => {
                let (next, dirty, surface) = match ev {
                    Ok(ev) => (ev.view, ev.dirty, ev.surface),
                    // Missed edits: the store's current version, everything stale.
                    Err(broadcast::error::RecvError::Lagged(_)) => match source.current().await {
                        Ok(v) => (v, Dirty::Everything, Dirty::Everything),
                        Err(_) => continue,
                    },
                    Err(broadcast::error::RecvError::Closed) => { edits = None; continue; }
                };
                // Edits of one world may arrive out of order (their views are built
                // concurrently): an older one still invalidates what it touched, and products
                // are produced from the newest version seen, which includes it.
                if next.version() > version {
                    let (generator, biomes) = (next.plan().params.generator, biome_names(next.plan()));
                    let changed = generator != current.plan().params.generator
                        || biomes != biome_names(current.plan());
                    current = next;
                    version = current.version();
                    if v2 && changed {
                        let msg = ServerMessage::World { version, generator, biomes };
                        if !outbox.push(text(&msg)).await {
                            break;
                        }
                    }
                }
                let params = &current.plan().params;
                // The edit may add or remove volume regions or caves: the view's chunks follow.
                let old_chunks = std::mem::take(&mut view.chunks);
                view.chunks = view.chunks_in(source.as_ref(), &current).await;
                let now_in: HashSet<ChunkKey> = view.chunks.iter().copied().collect();
                let dropped: Vec<ChunkKey> = old_chunks.into_iter().filter(|k| !now_in.contains(k) && held.remove(&Product::Chunk(*k)).is_some()).collect();
                let work = view.work(cell_m);
                let stale: Vec<Work> = work.iter().filter(|w| held.contains_key(&w.product()) && match w {
                    Work::Tile(t) => surface.touches(&crate::scene::tile_reach(params, t.key)),
                    Work::Chunk(c) => surface.touches(&chunk_reach(params, *c)),
                }).copied().collect();
                // Products not held stay pending; held products the edit does not touch are
                // current.
                for v in held.values_mut() {
                    *v = version;
                }
                let stale_set: HashSet<Product> = stale.iter().map(Work::product).collect();
                if let Some(p) = ptex.as_mut() {
                    if p.invalidate(|f| dirty.touches(&face_reach(params, f))) > 0 {
                        idle_sent = false;
                    }
                    // The chunks that left the view release their faces; the stale ones queue
                    // their pages again when their fresh frames are sent.
                    let in_view: HashSet<Product> = work.iter().map(Work::product).collect();
                    p.retain_products(|_| true, |k| in_view.contains(&Product::Chunk(k)));
                }
                if !stale.is_empty() || !dropped.is_empty() {
                    let tiles = stale.iter().filter_map(|w| match w {
                        Work::Tile(t) => Some([t.key.lod as i64, t.key.x, t.key.z]),
                        Work::Chunk(_) => None,
                    }).collect();
                    let chunks = stale.iter().filter_map(|w| match w {
                        Work::Chunk(c) => Some(chunk_address(*c)),
                        Work::Tile(_) => None,
                    }).collect();
                    let msg = ServerMessage::Invalidate {
                        version,
                        tiles,
                        chunks: v2.then_some(chunks),
                        dropped: v2.then(|| dropped.iter().map(|k| chunk_address(*k)).collect()),
                    };
                    // Queued frames of stale products are superseded: withdrawn, and their
                    // credit returned, so the fresh frame replaces them.
                    let gone = outbox.withdraw(&stale_set);
                    if v2 {
                        credits = credits.saturating_add(gone as u32).min(MAX_CREDITS);
                    }
                    if !outbox.push(text(&msg)).await {
                        break;
                    }
                    for p in &stale_set {
                        held.remove(p);
                    }
                }
                let fresh = work.iter().filter(|w| stale_set.contains(&w.product()));
                let rest = work.iter().filter(|w| !stale_set.contains(&w.product()) && !held.contains_key(&w.product()));
                let next_pending: VecDeque<Work> = fresh.chain(rest).copied().collect();
                if next_pending != pending {
                    idle_sent = idle_sent && next_pending.is_empty();
                }
                pending = next_pending;
            }
            () = outbox.frame_room(), if (!pending.is_empty() || ptex_work) && credits > 0 => {
                let ptex_turn = ptex_work && (pending.is_empty() || since_ptex + 1 >= PTEX_EVERY);
                if let (true, Some(p)) = (ptex_turn, ptex.as_mut()) {
                    since_ptex = 0;
                    let (message, batch) = p.next_batch();
                    if let Some(m) = message {
                        outbox.push_now(Outgoing::Text(serde_json::to_string(&m).unwrap_or_default()));
                    }
                    let Some(batch) = batch else { continue };
                    let baked = tokio::select! {
                        r = source.ptex_frame(&current, &batch) => r,
                        () = closing.cancelled() => break,
                    };
                    match baked {
                        Ok(b) => {
                            p.baked(&batch, &b.bounds);
                            ptex_serial += 1;
                            outbox.push_now(Outgoing::Frame { product: Product::Ptex(ptex_serial), bytes: b.bytes });
                            credits -= 1;
                            STATS.frames.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        }
                        Err(e) => {
                            outbox.push_now(text(&error_message(&e, None)));
                        }
                    }
                    continue;
                }
                since_ptex = since_ptex.saturating_add(1);
                let Some(w) = pending.pop_front() else { continue };
                let produced = tokio::select! {
                    r = async {
                        match w {
                            Work::Tile(t) => {
                                let (f, v) = format;
                                source.frame(&current, t.key, t.seams, f, v).await
                            }
                            Work::Chunk(c) => source.chunk_frame(&current, c, view.chunk_format.unwrap_or(Format::Bin)).await,
                        }
                    } => r,
                    () = closing.cancelled() => break,
                };
                match produced {
                    Ok(frame) if frame.len() > MAX_FRAME_BYTES => {
                        let e = StreamError {
                            code: "frame_too_large",
                            message: format!("the frame of {:?} has {} bytes; frames are limited to {MAX_FRAME_BYTES}", w.product(), frame.len()),
                            field: Some(match w { Work::Tile(_) => "rings", Work::Chunk(_) => "chunks" }.into()),
                        };
                        outbox.push_now(text(&error_message(&e, None)));
                    }
                    Ok(frame) => {
                        // A chunk's faces, for a client that asked for their Ptex pages.
                        let quads = match (&ptex, w) {
                            (Some(p), Work::Chunk(_)) if p.chunk_pages() => chunk_frame_quads(&frame),
                            _ => None,
                        };
                        outbox.push_now(Outgoing::Frame { product: w.product(), bytes: frame });
                        held.insert(w.product(), version);
                        let fits = match (ptex.as_mut(), w) {
                            (Some(p), Work::Tile(t)) => p.hold_tile(t.key, t.seams),
                            (Some(p), Work::Chunk(c)) => quads.is_none_or(|q| p.hold_chunk(c, q)),
                            _ => true,
                        };
                        if !fits {
                            let e = refused("ptex_budget_exceeded", "rings", "the vista pages of the view's faces exceed the session's Ptex budget; faces beyond it get no pages");
                            outbox.push_now(text(&error_message(&e, None)));
                        }
                        if v2 {
                            credits -= 1;
                        }
                        STATS.frames.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    }
                    Err(e) => {
                        outbox.push_now(text(&error_message(&e, None)));
                    }
                }
            }
            () = async {
                match starved_until {
                    Some(t) => tokio::time::sleep_until(t).await,
                    None => std::future::pending().await,
                }
            } => {
                tracing::info!("stream client granted no credit for {SEND_TIMEOUT:?}; disconnecting");
                STATS.dropped_slow.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let close = CloseFrame {
                    code: POLICY_VIOLATION,
                    reason: format!("no credit granted for {} s while frames were waiting", SEND_TIMEOUT.as_secs()).into(),
                };
                outbox.push_now(Outgoing::Close(close));
                break;
            }
            _ = tokio::time::sleep(Duration::from_millis(250)), if pending.is_empty() && !idle_sent => {}
        }
        if pending.is_empty() && !ptex.as_ref().is_some_and(PtexSession::has_work) && !idle_sent {
            idle_sent = true;
            if !outbox.push(text(&ServerMessage::Idle { version })).await {
                break;
            }
        }
    }
    outbox.close();
    let _ = writer.await;
}

/// The tile encoding's version a v2 view asks for with `tile_format` (`1` when not given); `2`
/// exists for `bin` and `json` only (`api/tile_format_v2.md`).
fn tile_version_of(tile_format: Option<u32>, format: Format) -> Result<TileVersion, StreamError> {
    let version = match tile_format {
        None | Some(1) => TileVersion::V1,
        Some(2) => TileVersion::V2,
        Some(n) => {
            return Err(refused(
                "unknown_format",
                "tile_format",
                format!("tile_format must be 1 or 2, got {n}"),
            ))
        }
    };
    if !version.has(format) {
        return Err(refused(
            "unknown_format",
            "tile_format",
            format!(
                "tile_format 2 exists for the bin and json tiles, not {}",
                format.extension()
            ),
        ));
    }
    Ok(version)
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
