//! The stream endpoints: `/v1/seeds/{seed}/stream` and `/v1/worlds/{id}/stream` run a
//! [`crate::stream::session`] on a source backed by the server's state (plans, edits, the tile
//! products through the stage and body caches).

use super::edit_service::{StreamView, WorldEdit};
use super::route_table::RouteTable;
use super::routes::CachedProduct;
use super::{AppError, AppState};
use crate::encode::{Format, TileVersion};
use crate::stream::protocol::{ChunkFrame, Protocol, TileFrame};
use crate::stream::ptex::{PtexBaked, PtexBatch, PtexGrant};
use crate::stream::session::{run, StreamError, StreamSource, MAX_MESSAGE_BYTES};
use crate::terrain::TileKey;
use crate::volume::chunk::{tiles_needed, ChunkKey};
use axum::body::Bytes;
use axum::extract::ws::rejection::WebSocketUpgradeRejection;
use axum::extract::{Path, State, WebSocketUpgrade};
use axum::response::{IntoResponse, Response};
use std::sync::Arc;
use tokio::sync::broadcast;

/// Routes of this module, to merge into the app's router.
pub fn router() -> RouteTable {
    RouteTable::new()
        .get("/v1/seeds/{seed}/stream", seed_stream)
        .get("/v1/worlds/{id}/stream", world_stream)
}

impl From<AppError> for StreamError {
    fn from(e: AppError) -> Self {
        StreamError {
            code: e.code,
            message: e.message,
            field: e.field,
        }
    }
}

/// The frame of tile `key` of the world `view` in `format` of `version`: the tile's body
/// (through the body cache) behind a frame header, itself kept in the body cache under a key of
/// its own, so the clients streaming one area share one copy of each frame, the frames in their
/// queues included.
async fn tile_frame(
    state: &AppState,
    view: &StreamView,
    key: TileKey,
    seams: [bool; 4],
    format: Format,
    version: TileVersion,
) -> Result<Bytes, StreamError> {
    let tag = version.tag(format);
    let tile_hash = view.view.tile_hash(key, seams);
    // The frame names the world version, so its key does too; the domain string keeps frame
    // keys apart from the tile bodies' input hashes.
    let mut h = blake3::Hasher::new();
    h.update(b"strata.stream.v1 frame");
    h.update(&tile_hash);
    h.update(&view.version.to_le_bytes());
    h.update(tag.as_bytes());
    let frame_key = (*h.finalize().as_bytes(), tag);
    let frame = state
        .bodies
        .get_or_encode(frame_key, || async {
            // Boxed: the tile product's future nested in this one exceeds the compiler's
            // layout depth otherwise.
            let product =
                Box::pin(state.tile_product(&view.view, key, seams, format, version)).await?;
            let bytes = TileFrame::encode_parts(key, format, view.version, seams, &product.body);
            Ok(frame_product(bytes))
        })
        .await?;
    Ok(frame.body.clone())
}

/// The frame of volume chunk `key` of the world `view` in `format`: the chunk route's body
/// behind a frame header, kept in the body cache under a key made of the input hashes of the
/// tiles the chunk reads (which cover the volume regions and `strata` elements in their reach),
/// the chunk's address and the world version, so clients streaming one area share each frame.
async fn chunk_frame(
    state: &AppState,
    view: &StreamView,
    key: ChunkKey,
    format: Format,
) -> Result<Bytes, StreamError> {
    let tag = match format {
        Format::Json => "chunk.json",
        Format::Glb => "chunk.glb",
        _ => "chunk.bin",
    };
    let mut h = blake3::Hasher::new();
    h.update(b"strata.stream.v2 chunk frame");
    for (x, z) in tiles_needed(key) {
        let tile = TileKey { lod: key.lod, x, z };
        h.update(&view.view.tile_hash(tile, [false; 4]));
    }
    h.update(&key.lod.to_le_bytes());
    for c in [key.x, key.y, key.z] {
        h.update(&c.to_le_bytes());
    }
    h.update(&view.version.to_le_bytes());
    let frame_key = (*h.finalize().as_bytes(), tag);
    let frame = state
        .bodies
        .get_or_encode(frame_key, || async {
            let product = Box::pin(super::chunks::product(
                state,
                view.view.clone(),
                key,
                format,
            ))
            .await?;
            let bytes = ChunkFrame::encode_parts(key, format, view.version, &product.body);
            Ok(frame_product(bytes))
        })
        .await?;
    Ok(frame.body.clone())
}

/// What a session streams: a bare seed (version 1 forever, no edits) or a stored world (the
/// latest version, its edit events, edits by callers with the edit role).
enum Of {
    Seed(StreamView),
    World {
        id: String,
        caller: crate::server::access::Caller,
    },
}

/// The server's [`StreamSource`]: products through the state's caches, whichever world.
struct Source {
    state: AppState,
    of: Of,
}

impl Source {
    async fn meta(&self, id: &str) -> Result<crate::store::WorldMeta, AppError> {
        self.state.worlds.store.meta(id).await.map_err(|e| {
            tracing::warn!(world = %id, "stream: world lookup failed: {e}");
            AppError::new(
                axum::http::StatusCode::NOT_FOUND,
                crate::server::error::code::WORLD_NOT_FOUND,
                "world not found",
            )
            .with_field("id")
        })
    }
}

#[async_trait::async_trait]
impl StreamSource for Source {
    type View = StreamView;

    async fn current(&self) -> Result<StreamView, StreamError> {
        match &self.of {
            Of::Seed(view) => Ok(view.clone()),
            Of::World { id, .. } => {
                let meta = self.meta(id).await?;
                let view = self.state.worlds.view(&meta, meta.version).await?;
                Ok(StreamView {
                    version: meta.version,
                    view,
                })
            }
        }
    }

    fn subscribe_edits(&self) -> Option<broadcast::Receiver<WorldEdit>> {
        match &self.of {
            Of::Seed(_) => None,
            Of::World { id, .. } => Some(self.state.worlds.subscribe_world(id)),
        }
    }

    async fn frame(
        &self,
        view: &StreamView,
        key: TileKey,
        seams: [bool; 4],
        format: Format,
        version: TileVersion,
    ) -> Result<Bytes, StreamError> {
        tile_frame(&self.state, view, key, seams, format, version).await
    }

    async fn ground_tile(&self, view: &StreamView, key: TileKey) -> Arc<crate::terrain::Tile> {
        self.state.tile(&view.view, key, [false; 4]).await
    }

    async fn chunk_frame(
        &self,
        view: &StreamView,
        key: ChunkKey,
        format: Format,
    ) -> Result<Bytes, StreamError> {
        chunk_frame(&self.state, view, key, format).await
    }

    fn ptex_grant(&self) -> Option<(PtexGrant, [f32; 5])> {
        let grant = self.state.ptex.grant()?;
        Some((grant, self.state.ptex.settings().thresholds_m))
    }

    async fn ptex_frame(
        &self,
        view: &StreamView,
        batch: &PtexBatch,
    ) -> Result<PtexBaked, StreamError> {
        super::stream_ptex::frame(&self.state, view, batch).await
    }

    async fn edit(
        &self,
        patch: serde_json::Value,
        if_match: Option<u64>,
    ) -> Result<u64, StreamError> {
        let Of::World { id, caller } = &self.of else {
            return Err(AppError::new(
                axum::http::StatusCode::FORBIDDEN,
                "read_only",
                "a bare seed has no scene to edit; create a world (POST /v1/worlds) and stream it",
            )
            .into());
        };
        let meta = self.meta(id).await?;
        caller.require(&meta, crate::store::Role::Edit)?;
        let patch: json_patch::Patch = serde_json::from_value(patch).map_err(|e| {
            AppError::bad_request(
                crate::server::error::code::BAD_BODY,
                "patch",
                format!("not a JSON Patch: {e}"),
            )
        })?;
        Ok(
            crate::server::edit_service::commit_edit(&self.state, id, patch, if_match)
                .await?
                .version,
        )
    }
}

/// The upgrade's answer: the session of `source` runs on the socket, holding the connection's
/// slot, tracked by the state's sessions (so shutdown closes it).
fn upgrade(
    ws: WebSocketUpgrade,
    source: Source,
    slot: Option<axum::Extension<super::connections::ConnectionSlot>>,
    protocol: Protocol,
) -> Response {
    let sessions = source.state.sessions.clone();
    let source = Arc::new(source);
    ws.max_message_size(MAX_MESSAGE_BYTES)
        .on_upgrade(move |socket| async move {
            // The connection's slot stays taken while the session runs.
            let _slot = slot;
            sessions
                .track(|closing| run(socket, source, closing, protocol))
                .await;
        })
}

/// 426 `upgrade_required` (field `Upgrade`, with `Upgrade: websocket`) in the JSON error shape,
/// for a stream request that is not a WebSocket handshake.
fn upgrade_required(e: &WebSocketUpgradeRejection) -> Response {
    let mut res = AppError::new(
        axum::http::StatusCode::UPGRADE_REQUIRED,
        crate::server::error::code::UPGRADE_REQUIRED,
        format!("this route is a WebSocket (strata.stream.v1): {e}"),
    )
    .with_field("Upgrade")
    .into_response();
    res.headers_mut().insert(
        axum::http::header::UPGRADE,
        axum::http::HeaderValue::from_static("websocket"),
    );
    res
}

/// `?token=` for browsers, which cannot set headers on a WebSocket, and `?protocol=`.
#[derive(serde::Deserialize)]
struct TokenQuery {
    token: Option<String>,
    protocol: Option<String>,
}

/// `?protocol=`: the stream protocol version the client speaks, `1` (the default) or `2`.
#[derive(serde::Deserialize)]
struct ProtocolQuery {
    protocol: Option<String>,
}

/// The protocol `?protocol=` names: absent or `1` is v1, `2` is v2; anything else is a 400
/// naming the field.
fn protocol_of(q: Option<&str>) -> Result<Protocol, AppError> {
    match q {
        None | Some("1") => Ok(Protocol::V1),
        Some("2") => Ok(Protocol::V2),
        Some(other) => Err(AppError::bad_request(
            crate::server::error::code::BAD_PARAMETER,
            "protocol",
            format!(
                "protocol must be 1 or 2 (strata.stream.v1 or v2), got {:?}",
                other.chars().take(40).collect::<String>()
            ),
        )),
    }
}

async fn world_stream(
    State(state): State<AppState>,
    Path(id): Path<String>,
    axum::extract::Query(q): axum::extract::Query<TokenQuery>,
    headers: axum::http::HeaderMap,
    slot: Option<axum::Extension<super::connections::ConnectionSlot>>,
    ws: Result<WebSocketUpgrade, WebSocketUpgradeRejection>,
) -> Result<Response, AppError> {
    state.cors.check_upgrade(&headers)?;
    let protocol = protocol_of(q.protocol.as_deref())?;
    let mut headers = headers;
    if let Some(token) = q
        .token
        .filter(|_| !headers.contains_key(axum::http::header::AUTHORIZATION))
    {
        let value =
            axum::http::HeaderValue::from_str(&format!("Bearer {token}")).map_err(|_| {
                AppError::bad_request(
                    crate::server::error::code::BAD_BODY,
                    "token",
                    "token has characters a header cannot carry",
                )
            })?;
        headers.insert(axum::http::header::AUTHORIZATION, value);
    }
    let (_, caller) =
        crate::server::http::authorize(&state, &headers, &id, crate::store::Role::Read).await?;
    let ws = match ws {
        Ok(ws) => ws,
        Err(e) => return Ok(upgrade_required(&e)),
    };
    let source = Source {
        state,
        of: Of::World { id, caller },
    };
    Ok(upgrade(ws, source, slot, protocol))
}

async fn seed_stream(
    State(state): State<AppState>,
    Path(seed): Path<String>,
    axum::extract::Query(q): axum::extract::Query<ProtocolQuery>,
    slot: Option<axum::Extension<super::connections::ConnectionSlot>>,
    ws: Result<WebSocketUpgrade, WebSocketUpgradeRejection>,
) -> Result<Response, AppError> {
    let seed = crate::server::params::parse_seed(&seed)?;
    let protocol = protocol_of(q.protocol.as_deref())?;
    let ws = match ws {
        Ok(ws) => ws,
        Err(e) => return Ok(upgrade_required(&e)),
    };
    let view = StreamView {
        version: 1,
        view: state.bare_view(seed).await?,
    };
    let source = Source {
        state,
        of: Of::Seed(view),
    };
    Ok(upgrade(ws, source, slot, protocol))
}

/// A stream frame as the body cache keeps it.
fn frame_product(bytes: Vec<u8>) -> Arc<CachedProduct> {
    Arc::new(CachedProduct {
        body: bytes.into(),
        hash: String::new(),
        content_type: "application/octet-stream",
        extra: Vec::new(),
    })
}
