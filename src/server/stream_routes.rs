//! The stream endpoints: `/v1/seeds/{seed}/stream` and `/v1/worlds/{id}/stream` run a
//! [`crate::stream::session`] on a source backed by the server's state (plans, edits, the tile
//! products through the stage and body caches).

use super::{AppError, AppState};
use crate::encode::{Format, TileVersion};
use crate::stream::session::{run, EditEvent, StreamError, StreamSource, MAX_MESSAGE_BYTES};
use crate::terrain::{TileKey, WorldPlan};
use axum::extract::ws::rejection::WebSocketUpgradeRejection;
use axum::extract::{Path, State, WebSocketUpgrade};
use axum::response::{IntoResponse, Response};
use std::sync::Arc;

/// Routes of this module, to merge into the app's router.
pub fn router() -> axum::Router<AppState> {
    axum::Router::new()
        .route("/v1/seeds/{seed}/stream", axum::routing::get(seed_stream))
        .route("/v1/worlds/{id}/stream", axum::routing::get(world_stream))
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

/// The payload of a tile frame: tile `key` of `world` at a version (or of the bare seed when
/// `None`), through the body cache, so clients streaming the same area share encodings.
async fn tile_payload(
    state: &AppState,
    world: Option<(&str, u64)>,
    plan: Arc<WorldPlan>,
    key: TileKey,
    seams: [bool; 4],
    format: Format,
) -> Result<Vec<u8>, StreamError> {
    let inputs = state.inputs_for(world, &plan).await?;
    let product = state
        .tile_product(&inputs, plan, key, seams, format, TileVersion::V1)
        .await?;
    Ok(product.body.to_vec())
}

/// A stored world: the latest version, its edit events, edits by callers with the edit role.
struct WorldSource {
    state: AppState,
    id: String,
    caller: crate::server::access::Caller,
}

impl WorldSource {
    async fn meta(&self) -> Result<crate::store::WorldMeta, AppError> {
        self.state.worlds.store.meta(&self.id).await.map_err(|e| {
            tracing::warn!(world = %self.id, "stream: world lookup failed: {e}");
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
impl StreamSource for WorldSource {
    async fn current(&self) -> Result<(u64, Arc<WorldPlan>), StreamError> {
        let meta = self.meta().await?;
        let plan = self.state.worlds.plan(&meta, meta.version).await?;
        Ok((meta.version, plan))
    }

    async fn plan_at(&self, version: u64) -> Result<Arc<WorldPlan>, StreamError> {
        let meta = self.meta().await?;
        Ok(self.state.worlds.plan(&meta, version).await?)
    }

    fn world(&self) -> Option<&str> {
        Some(&self.id)
    }

    fn subscribe_edits(&self) -> Option<tokio::sync::broadcast::Receiver<EditEvent>> {
        Some(self.state.subscribe_edits())
    }

    async fn tile(
        &self,
        version: u64,
        plan: Arc<WorldPlan>,
        key: TileKey,
        seams: [bool; 4],
        format: Format,
    ) -> Result<Vec<u8>, StreamError> {
        let world = Some((self.id.as_str(), version));
        tile_payload(&self.state, world, plan, key, seams, format).await
    }

    async fn edit(
        &self,
        patch: serde_json::Value,
        if_match: Option<u64>,
    ) -> Result<u64, StreamError> {
        let meta = self.meta().await?;
        self.caller.require(&meta, crate::store::Role::Edit)?;
        let patch: json_patch::Patch = serde_json::from_value(patch).map_err(|e| {
            AppError::bad_request(
                crate::server::error::code::BAD_BODY,
                "patch",
                format!("not a JSON Patch: {e}"),
            )
        })?;
        Ok(
            crate::server::worlds::commit_edit(&self.state, &self.id, patch, if_match)
                .await?
                .version,
        )
    }
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

/// `?token=` for browsers, which cannot set headers on a WebSocket.
#[derive(serde::Deserialize)]
struct TokenQuery {
    token: Option<String>,
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
        crate::server::worlds::authorize(&state, &headers, &id, crate::store::Role::Read).await?;
    let ws = match ws {
        Ok(ws) => ws,
        Err(e) => return Ok(upgrade_required(&e)),
    };
    let sessions = state.sessions.clone();
    let source: Arc<dyn StreamSource> = Arc::new(WorldSource { state, id, caller });
    Ok(ws
        .max_message_size(MAX_MESSAGE_BYTES)
        .on_upgrade(move |socket| async move {
            // The connection's slot stays taken while the session runs.
            let _slot = slot;
            sessions.track(|closing| run(socket, source, closing)).await;
        }))
}

/// A bare seed: version 1 forever, no edits.
struct SeedSource {
    state: AppState,
    plan: Arc<WorldPlan>,
}

#[async_trait::async_trait]
impl StreamSource for SeedSource {
    async fn current(&self) -> Result<(u64, Arc<WorldPlan>), StreamError> {
        Ok((1, self.plan.clone()))
    }

    async fn plan_at(&self, _version: u64) -> Result<Arc<WorldPlan>, StreamError> {
        Ok(self.plan.clone())
    }

    fn world(&self) -> Option<&str> {
        None
    }

    fn subscribe_edits(&self) -> Option<tokio::sync::broadcast::Receiver<EditEvent>> {
        None
    }

    async fn tile(
        &self,
        _version: u64,
        plan: Arc<WorldPlan>,
        key: TileKey,
        seams: [bool; 4],
        format: Format,
    ) -> Result<Vec<u8>, StreamError> {
        tile_payload(&self.state, None, plan, key, seams, format).await
    }

    async fn edit(
        &self,
        _patch: serde_json::Value,
        _if_match: Option<u64>,
    ) -> Result<u64, StreamError> {
        Err(AppError::new(
            axum::http::StatusCode::FORBIDDEN,
            "read_only",
            "a bare seed has no scene to edit; create a world (POST /v1/worlds) and stream it",
        )
        .into())
    }
}

async fn seed_stream(
    State(state): State<AppState>,
    Path(seed): Path<String>,
    slot: Option<axum::Extension<super::connections::ConnectionSlot>>,
    ws: Result<WebSocketUpgrade, WebSocketUpgradeRejection>,
) -> Result<Response, AppError> {
    let seed = crate::server::params::parse_seed(&seed)?;
    let ws = match ws {
        Ok(ws) => ws,
        Err(e) => return Ok(upgrade_required(&e)),
    };
    let plan = state.plan(seed).await?;
    let sessions = state.sessions.clone();
    let source: Arc<dyn StreamSource> = Arc::new(SeedSource { state, plan });
    Ok(ws
        .max_message_size(MAX_MESSAGE_BYTES)
        .on_upgrade(move |socket| async move {
            // The connection's slot stays taken while the session runs.
            let _slot = slot;
            sessions.track(|closing| run(socket, source, closing)).await;
        }))
}
