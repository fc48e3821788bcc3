//! Solutions by `(seed, element digest)`: each element of each world version is solved once, on
//! the blocking pool, however many requests ask for it at once (the [`Memo`]'s single flight);
//! the least recently used go first beyond the cache's byte budget. Authored regions
//! ([`super::regions`]) and volume regions ([`super::volumes`]) keep theirs here.

use crate::cache::Memo;
use std::sync::Arc;

/// What a solution holds, bytes (its arrays' capacities; approximate where a type says so).
pub trait Weigh {
    /// Bytes held, the value itself included.
    fn weight(&self) -> usize;
}

/// Solutions of type `T` by `(seed, digest)`, within a byte budget. A refusal (`None`) is kept
/// too.
#[derive(Debug)]
pub struct SolvedCache<T> {
    memo: Memo<(u64, [u8; 32]), Option<Arc<T>>>,
}

impl<T: Weigh + Send + Sync + 'static> SolvedCache<T> {
    /// An empty cache of at most `budget_bytes` of solutions ([`Weigh::weight`] each, plus
    /// [`crate::cache::ENTRY_OVERHEAD_BYTES`]).
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            memo: Memo::new(budget_bytes, |_, v: &Option<Arc<T>>| {
                v.as_ref().map_or(0, |v| v.weight())
            }),
        }
    }

    /// `(entries, bytes, budget bytes)`.
    pub fn size(&self) -> (u64, u64, u64) {
        let s = self.memo.stats();
        (s.entries, s.bytes, s.budget_bytes)
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
        self.memo
            .get_or_compute_async(key, move || async move {
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
            .0
    }
}
