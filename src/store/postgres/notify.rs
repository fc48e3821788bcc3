//! Edit fan-out between replicas sharing a PostgreSQL database: each committed edit sends a
//! `NOTIFY` on [`CHANNEL`] in its own transaction (so it is delivered at commit, in commit
//! order, and never for an edit that did not commit), and [`follow`] `LISTEN`s on a connection of
//! its own and hands other replicas' edits to the server. After the listening connection is lost
//! and made again, it reports [`FeedEvent::Listening`] so the server can catch up by version on
//! what it may have missed meanwhile.

use super::super::StoreError;
use crate::scene::Dirty;
use futures::StreamExt;
use serde::{Deserialize, Serialize};
use std::time::Duration;
use tokio::sync::mpsc;
use tokio_postgres::{AsyncMessage, NoTls};

/// The notification channel of committed edits.
pub const CHANNEL: &str = "strata_edits";
/// Largest payload sent with its dirty region; PostgreSQL's limit is 8000 bytes, and a larger
/// region is sent as everything.
const MAX_PAYLOAD: usize = 7000;
/// Pause before listening again after the connection was lost.
const RECONNECT_PAUSE: Duration = Duration::from_millis(250);

/// The payload of one edit's notification.
#[derive(Debug, Serialize, Deserialize)]
pub(super) struct Payload {
    /// The store (process) that committed it.
    pub origin: String,
    /// World id.
    pub world: String,
    /// The version it made.
    pub version: u64,
    /// What it changed; `None` when too large to send (then everything is stale).
    pub dirty: Option<Dirty>,
}

impl Payload {
    /// The notification text: with the dirty region when it fits, else without.
    pub(super) fn text(&self) -> Result<String, StoreError> {
        let text = serde_json::to_string(self).map_err(super::super::shared::backend)?;
        if text.len() <= MAX_PAYLOAD || self.dirty.is_none() {
            return Ok(text);
        }
        serde_json::to_string(&Payload {
            origin: self.origin.clone(),
            world: self.world.clone(),
            version: self.version,
            dirty: None,
        })
        .map_err(super::super::shared::backend)
    }
}

/// An edit another replica committed.
#[derive(Clone, Debug, PartialEq)]
pub struct RemoteEdit {
    /// World id.
    pub world: String,
    /// The version it made.
    pub version: u64,
    /// What it changed ([`Dirty::Everything`] when the notification could not carry it).
    pub dirty: Dirty,
}

/// What [`follow`] reports.
#[derive(Clone, Debug, PartialEq)]
pub enum FeedEvent {
    /// Listening (again): notifications sent while it was not are lost, so whoever follows
    /// compares the versions it knows with the store's.
    Listening,
    /// An edit committed by another replica.
    Edit(RemoteEdit),
}

/// Listens for other replicas' edits on the database of `config` until `tx` is closed,
/// reconnecting after a lost connection; `origin` is this store's own id, whose notifications
/// are skipped (the server announced those edits when it committed them).
pub(super) async fn follow(
    config: tokio_postgres::Config,
    origin: String,
    tx: mpsc::Sender<FeedEvent>,
) {
    loop {
        match listen_once(&config, &origin, &tx).await {
            Ok(()) => return,
            Err(e) => tracing::warn!("edit notifications from other replicas lost: {e}"),
        }
        if tx.is_closed() {
            return;
        }
        tokio::time::sleep(RECONNECT_PAUSE).await;
    }
}

/// One listening connection: `Ok` when `tx` closed, `Err` when the connection was lost.
async fn listen_once(
    config: &tokio_postgres::Config,
    origin: &str,
    tx: &mpsc::Sender<FeedEvent>,
) -> Result<(), String> {
    let mut config = config.clone();
    config.application_name("strata-listen");
    let (client, mut connection) = config.connect(NoTls).await.map_err(|e| e.to_string())?;
    let (ntx, mut nrx) = mpsc::unbounded_channel();
    let driver = tokio::spawn(async move {
        let mut messages = futures::stream::poll_fn(move |cx| connection.poll_message(cx));
        while let Some(m) = messages.next().await {
            match m {
                Ok(AsyncMessage::Notification(n)) => {
                    if ntx.send(n.payload().to_string()).is_err() {
                        return;
                    }
                }
                Ok(_) => {}
                Err(_) => return,
            }
        }
    });
    let listening = client.batch_execute(&format!("LISTEN {CHANNEL}")).await;
    if let Err(e) = listening {
        driver.abort();
        return Err(e.to_string());
    }
    if tx.send(FeedEvent::Listening).await.is_err() {
        driver.abort();
        return Ok(());
    }
    // The driver ends (and drops its sender) when the connection is lost.
    while let Some(text) = nrx.recv().await {
        let p: Payload = match serde_json::from_str(&text) {
            Ok(p) => p,
            Err(e) => {
                tracing::warn!("an edit notification is not understood: {e}");
                continue;
            }
        };
        if p.origin == origin {
            continue;
        }
        let edit = RemoteEdit {
            world: p.world,
            version: p.version,
            dirty: p.dirty.unwrap_or(Dirty::Everything),
        };
        if tx.send(FeedEvent::Edit(edit)).await.is_err() {
            driver.abort();
            return Ok(());
        }
    }
    drop(client);
    Err("the listening connection closed".into())
}
