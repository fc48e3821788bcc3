//! A client's outgoing queue: control messages and frames waiting for the socket, bounded in
//! items and bytes, whose frames can be withdrawn while they wait.
//!
//! The session pushes, the writer task pops. Frames carry the product they show, so an edit
//! that makes a queued frame stale withdraws it ([`Outbox::withdraw`]) and the fresh frame
//! takes its place instead of following it: superseded frames are coalesced.

use super::work::Product;
use axum::body::Bytes;
use axum::extract::ws::CloseFrame;
use std::collections::{HashSet, VecDeque};
use std::sync::Mutex;
use tokio::sync::Notify;

/// One thing to write to the socket.
#[derive(Debug)]
pub enum Outgoing {
    /// A JSON control message.
    Text(String),
    /// A binary frame of `product`.
    Frame {
        /// What the frame shows.
        product: Product,
        /// The frame's bytes (shared with other clients and the body cache).
        bytes: Bytes,
    },
    /// A close frame; the writer stops after it.
    Close(CloseFrame),
}

#[derive(Debug, Default)]
struct Inner {
    items: VecDeque<Outgoing>,
    bytes: usize,
    closed: bool,
}

/// The bounded queue between a session and its writer.
#[derive(Debug)]
pub struct Outbox {
    inner: Mutex<Inner>,
    max_items: usize,
    max_bytes: usize,
    /// Woken when an item is pushed or the outbox is closed.
    pushed: Notify,
    /// Woken when an item leaves (popped or withdrawn).
    room: Notify,
}

impl Outbox {
    /// An empty outbox holding at most `max_items` items; frames are pushed only while the
    /// queued frames' bytes are under `max_bytes` (so they stay under `max_bytes` plus one
    /// frame).
    pub fn new(max_items: usize, max_bytes: usize) -> Self {
        Self {
            inner: Mutex::new(Inner::default()),
            max_items,
            max_bytes,
            pushed: Notify::new(),
            room: Notify::new(),
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn has_room(&self, frame: bool) -> bool {
        let inner = self.lock();
        inner.items.len() < self.max_items && (!frame || inner.bytes < self.max_bytes)
    }

    /// Waits until a frame may be pushed (fewer than the item bound queued, bytes under the
    /// byte bound). Cancel-safe.
    pub async fn frame_room(&self) {
        self.wait_room(true).await;
    }

    async fn wait_room(&self, frame: bool) {
        loop {
            let notified = self.room.notified();
            tokio::pin!(notified);
            notified.as_mut().enable();
            if self.has_room(frame) {
                return;
            }
            notified.await;
        }
    }

    /// Queues `item` once there is room for it (a control message waits for the item bound
    /// only); false when the outbox is closed.
    pub async fn push(&self, item: Outgoing) -> bool {
        let frame = matches!(item, Outgoing::Frame { .. });
        self.wait_room(frame).await;
        self.push_now(item)
    }

    /// Queues `item` without waiting (a frame produced after [`Outbox::frame_room`], or a close
    /// frame); false when the outbox is closed.
    pub fn push_now(&self, item: Outgoing) -> bool {
        let mut inner = self.lock();
        if inner.closed {
            return false;
        }
        if let Outgoing::Frame { bytes, .. } = &item {
            inner.bytes += bytes.len();
        }
        inner.items.push_back(item);
        drop(inner);
        self.pushed.notify_one();
        true
    }

    /// Removes the queued frames of `stale` products; returns how many were removed.
    pub fn withdraw(&self, stale: &HashSet<Product>) -> usize {
        self.withdraw_where(|p| stale.contains(p))
    }

    /// Removes the queued frames of products not in `keep`, Ptex pages excepted (a session's
    /// pages are not products of a view); returns how many were removed.
    pub fn withdraw_unless(&self, keep: &HashSet<Product>) -> usize {
        self.withdraw_where(|p| !matches!(p, Product::Ptex(_)) && !keep.contains(p))
    }

    fn withdraw_where(&self, stale: impl Fn(&Product) -> bool) -> usize {
        let mut inner = self.lock();
        let before = inner.items.len();
        let mut freed = 0;
        inner.items.retain(|item| match item {
            Outgoing::Frame { product, bytes } if stale(product) => {
                freed += bytes.len();
                false
            }
            _ => true,
        });
        inner.bytes -= freed;
        let removed = before - inner.items.len();
        drop(inner);
        if removed > 0 {
            self.room.notify_waiters();
        }
        removed
    }

    /// The next item, waiting for one; `None` once the outbox is closed and empty.
    pub async fn pop(&self) -> Option<Outgoing> {
        loop {
            let notified = self.pushed.notified();
            tokio::pin!(notified);
            notified.as_mut().enable();
            {
                let mut inner = self.lock();
                if let Some(item) = inner.items.pop_front() {
                    if let Outgoing::Frame { bytes, .. } = &item {
                        inner.bytes -= bytes.len();
                    }
                    drop(inner);
                    self.room.notify_waiters();
                    return Some(item);
                }
                if inner.closed {
                    return None;
                }
            }
            notified.await;
        }
    }

    /// Takes every queued item at once (for the going-away path).
    pub fn drain(&self) -> Vec<Outgoing> {
        let mut inner = self.lock();
        inner.bytes = 0;
        let items = inner.items.drain(..).collect();
        drop(inner);
        self.room.notify_waiters();
        items
    }

    /// Refuses further pushes; the writer takes what is queued, then [`Outbox::pop`] ends.
    /// Waiting pushers are woken (their push fails).
    pub fn close(&self) {
        self.lock().closed = true;
        self.pushed.notify_waiters();
        self.pushed.notify_one();
        self.room.notify_waiters();
    }

    /// Whether the outbox was closed.
    pub fn is_closed(&self) -> bool {
        self.lock().closed
    }

    /// Frames and bytes queued now (for tests and metrics).
    pub fn queued(&self) -> (usize, usize) {
        let inner = self.lock();
        (inner.items.len(), inner.bytes)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::TileKey;

    fn frame(x: i64, len: usize) -> Outgoing {
        Outgoing::Frame {
            product: Product::Tile(TileKey { lod: 0, x, z: 0 }),
            bytes: Bytes::from(vec![0u8; len]),
        }
    }

    #[tokio::test]
    async fn withdrawn_frames_free_their_room_and_others_keep_their_order() {
        let out = Outbox::new(3, 1 << 20);
        assert!(out.push(frame(1, 10)).await);
        assert!(out.push(Outgoing::Text("t".into())).await);
        assert!(out.push(frame(2, 20)).await);
        assert!(!out.has_room(false), "three items fill it");
        let stale = HashSet::from([Product::Tile(TileKey { lod: 0, x: 1, z: 0 })]);
        assert_eq!(out.withdraw(&stale), 1);
        assert_eq!(out.queued(), (2, 20));
        assert!(matches!(out.pop().await, Some(Outgoing::Text(_))));
        assert!(matches!(
            out.pop().await,
            Some(Outgoing::Frame { product: Product::Tile(k), .. }) if k.x == 2
        ));
        out.close();
        assert!(out.pop().await.is_none());
        assert!(!out.push(frame(3, 1)).await, "closed");
    }

    #[tokio::test]
    async fn frames_wait_for_the_byte_bound() {
        let out = Outbox::new(8, 100);
        assert!(
            out.push(frame(1, 150)).await,
            "an empty outbox takes one large frame"
        );
        assert!(!out.has_room(true), "over the byte bound: no frame");
        assert!(out.has_room(false), "control messages still fit");
        out.pop().await;
        assert!(out.has_room(true));
    }
}
