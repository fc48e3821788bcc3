//! Volume-chunk routes (issue 5).

use super::AppState;
use axum::Router;

/// The volume-chunk routes.
pub fn routes() -> Router<AppState> {
    Router::new()
}
