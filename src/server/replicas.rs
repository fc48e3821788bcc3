//! Replicas sharing a PostgreSQL store: the edits the other replicas commit
//! ([`crate::store::PostgresStore::follow_edits`]) are announced to this process's stream
//! sessions as its own are ([`super::edit_service::EditChannels::announce`]). Notifications sent
//! while the listening connection was down are lost, so each time it listens (again) every world
//! streamed here is compared with the store: one that moved past the version last announced is
//! announced at the store's version with everything stale (sessions then refresh every tile they
//! hold), so no invalidation is missed. A world whose sessions have been announced nothing since
//! they joined counts as version 0 there, and is refreshed whole.

use super::worlds::Worlds;
use crate::scene::Dirty;
use crate::store::FeedEvent;
use std::sync::Arc;
use tokio::sync::mpsc;

/// Announces what `feed` reports to the sessions of `worlds`, until the feed ends.
pub(super) async fn follow(mut feed: mpsc::Receiver<FeedEvent>, worlds: Arc<Worlds>) {
    while let Some(event) = feed.recv().await {
        match event {
            FeedEvent::Edit(e) => {
                worlds
                    .edits
                    .announce(&worlds, &e.world, e.version, &e.dirty)
                    .await;
            }
            FeedEvent::Listening => catch_up(&worlds).await,
        }
    }
}

/// Announces, with everything stale, each streamed world whose stored version is past the one
/// last announced here.
async fn catch_up(worlds: &Worlds) {
    for (id, known) in worlds.edits.streamed_worlds() {
        match worlds.store.meta(&id).await {
            Ok(meta) if meta.version > known => {
                tracing::info!(world = %id, from = known, to = meta.version, "stream sessions catch up");
                worlds
                    .edits
                    .announce(worlds, &id, meta.version, &Dirty::Everything)
                    .await;
            }
            Ok(_) => {}
            Err(e) => tracing::warn!(world = %id, "cannot catch up stream sessions: {e}"),
        }
    }
}
