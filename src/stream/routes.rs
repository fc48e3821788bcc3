//! The stream endpoints.

use super::session::{run, StreamSource};
use crate::server::{AppError, AppState};
use crate::terrain::WorldPlan;
use axum::extract::{Path, State, WebSocketUpgrade};
use axum::response::Response;
use std::sync::Arc;

/// Routes of this module, to merge into the app's router.
pub fn router() -> axum::Router<AppState> {
    axum::Router::new().route("/v1/seeds/{seed}/stream", axum::routing::get(seed_stream))
}

/// A bare seed: version 1 forever, no edits.
struct SeedSource {
    plan: Arc<WorldPlan>,
}

#[async_trait::async_trait]
impl StreamSource for SeedSource {
    async fn current(&self) -> Result<(u64, Arc<WorldPlan>), AppError> {
        Ok((1, self.plan.clone()))
    }

    async fn plan_at(&self, _version: u64) -> Result<Arc<WorldPlan>, AppError> {
        Ok(self.plan.clone())
    }

    fn world(&self) -> Option<&str> {
        None
    }

    async fn edit(
        &self,
        _patch: serde_json::Value,
        _if_match: Option<u64>,
    ) -> Result<u64, AppError> {
        Err(AppError::new(
            axum::http::StatusCode::FORBIDDEN,
            "read_only",
            "a bare seed has no scene to edit; create a world (POST /v1/worlds) and stream it",
        ))
    }
}

async fn seed_stream(
    State(state): State<AppState>,
    Path(seed): Path<String>,
    ws: WebSocketUpgrade,
) -> Result<Response, AppError> {
    let seed: u64 = seed.parse().map_err(|_| {
        AppError::bad_request(
            crate::server::error::code::BAD_SEED,
            "seed",
            "seed must be a decimal u64",
        )
    })?;
    let plan = state.plan(seed).await?;
    let source: Arc<dyn StreamSource> = Arc::new(SeedSource { plan });
    Ok(ws
        .max_message_size(super::session::MAX_MESSAGE_BYTES)
        .on_upgrade(move |socket| run(socket, state, source)))
}
