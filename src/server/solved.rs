//! Solutions by `(seed, element digest)`: each element of each world version is solved once, on
//! the blocking pool, however many requests ask for it at once; the least recently used go first.
//! Authored regions ([`super::regions`]) and volume regions ([`super::volumes`]) keep theirs here.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use tokio::sync::OnceCell;

type Slot<T> = Arc<OnceCell<Option<Arc<T>>>>;
/// `(seed, digest)` → the slot and its last use.
type Entries<T> = HashMap<(u64, [u8; 32]), (Slot<T>, u64)>;

/// Solutions of type `T` by `(seed, digest)`, at most `capacity` of them.
#[derive(Debug)]
pub struct SolvedCache<T> {
    entries: Mutex<Entries<T>>,
    clock: AtomicU64,
    capacity: usize,
}

impl<T: Send + Sync + 'static> SolvedCache<T> {
    /// An empty cache keeping at most `capacity` solutions.
    pub fn new(capacity: usize) -> Self {
        Self {
            entries: Mutex::default(),
            clock: AtomicU64::new(0),
            capacity: capacity.max(1),
        }
    }

    /// The solution under `key`, running `solve` on the blocking pool if there is none yet.
    /// `None` if `solve` refused (logged with `what`; the products then show the world without
    /// the element).
    pub async fn get_or_solve<E: std::fmt::Display + Send + 'static>(
        &self,
        key: (u64, [u8; 32]),
        what: &'static str,
        solve: impl FnOnce() -> Result<T, E> + Send + 'static,
    ) -> Option<Arc<T>> {
        let now = self.clock.fetch_add(1, Ordering::Relaxed);
        let slot = {
            let mut map = self
                .entries
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            if !map.contains_key(&key) && map.len() >= self.capacity {
                if let Some(oldest) = map.iter().min_by_key(|(_, (_, t))| *t).map(|(k, _)| *k) {
                    map.remove(&oldest);
                }
            }
            let entry = map.entry(key).or_insert_with(|| (Slot::default(), now));
            entry.1 = now;
            entry.0.clone()
        };
        slot.get_or_init(|| async move {
            // Not `None` on cancellation: a tile made without this region would be cached.
            match crate::compute::joined(tokio::task::spawn_blocking(solve)).await {
                Ok(v) => Some(Arc::new(v)),
                Err(e) => {
                    tracing::warn!("{what} not solved: {e}");
                    None
                }
            }
        })
        .await
        .clone()
    }
}
