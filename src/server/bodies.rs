//! Encoded products by `(tile input hash, format)`: a hit answers a request with a reference-counted
//! body and a precomputed ETag, no synthesis, encoding or hashing. A [`Memo`] bounded by a byte
//! budget, least recently used evicted first (O(1), no scan); concurrent misses of one body
//! encode it once ([`BodyCache::get_or_encode`]).

use super::routes::CachedProduct;
use super::AppError;
use crate::cache::{Memo, Outcome};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// Default budget of encoded bodies, bytes.
pub const DEFAULT_BODY_BUDGET_BYTES: usize = 96 << 20;

/// Key: the tile's input hash and the format's extension.
pub type BodyKey = ([u8; 32], &'static str);

/// Bytes a product is counted for: the struct, the body's length (a body made from a `Vec`
/// may hold a little more capacity: approximate), the ETag and the extra headers.
pub fn product_bytes(p: &CachedProduct) -> usize {
    std::mem::size_of::<CachedProduct>()
        + p.body.len()
        + p.hash.capacity()
        + p.extra
            .iter()
            .map(|(name, value)| {
                std::mem::size_of::<(axum::http::HeaderName, String)>()
                    + name.as_str().len()
                    + value.capacity()
            })
            .sum::<usize>()
}

/// The cache; cheap to share behind an `Arc`.
#[derive(Debug)]
pub struct BodyCache {
    memo: Memo<BodyKey, Arc<CachedProduct>>,
    /// Requests answered from the cache.
    pub hits: AtomicU64,
    /// Requests that encoded a body.
    pub misses: AtomicU64,
}

impl Default for BodyCache {
    fn default() -> Self {
        Self::new(DEFAULT_BODY_BUDGET_BYTES)
    }
}

impl BodyCache {
    /// A cache of at most `budget` bytes of products ([`product_bytes`] each, plus
    /// [`crate::cache::ENTRY_OVERHEAD_BYTES`]).
    pub fn new(budget: usize) -> Self {
        Self {
            memo: Memo::new(budget, |_, p: &Arc<CachedProduct>| product_bytes(p)),
            hits: AtomicU64::new(0),
            misses: AtomicU64::new(0),
        }
    }

    /// The cached product, if any.
    pub fn get(&self, key: &BodyKey) -> Option<Arc<CachedProduct>> {
        let found = self.memo.get(key);
        let counter = if found.is_some() {
            &self.hits
        } else {
            &self.misses
        };
        counter.fetch_add(1, Ordering::Relaxed);
        found
    }

    /// The product under `key`, encoding it with the future `encode` returns on a miss;
    /// concurrent misses of one key await one encoding (counted as hits). A failed encoding is
    /// not kept.
    pub async fn get_or_encode<F, Fut>(
        &self,
        key: BodyKey,
        encode: F,
    ) -> Result<Arc<CachedProduct>, AppError>
    where
        F: FnOnce() -> Fut,
        Fut: std::future::Future<Output = Result<Arc<CachedProduct>, AppError>>,
    {
        let (product, outcome) = self.memo.try_get_or_compute_async(key, encode).await?;
        let counter = match outcome {
            Outcome::Computed => &self.misses,
            Outcome::Hit | Outcome::Joined => &self.hits,
        };
        counter.fetch_add(1, Ordering::Relaxed);
        Ok(product)
    }

    /// Whether `key` is cached (neither a hit nor a miss is counted).
    pub fn contains(&self, key: &BodyKey) -> bool {
        self.memo.contains(key)
    }

    /// Stores a product, evicting the least recently used ones beyond the budget.
    pub fn insert(&self, key: BodyKey, product: Arc<CachedProduct>) {
        self.memo.insert(key, product);
    }

    /// `(entries, bytes)`.
    pub fn size(&self) -> (usize, usize) {
        let s = self.memo.stats();
        (s.entries as usize, s.bytes as usize)
    }

    /// The byte budget.
    pub fn budget_bytes(&self) -> usize {
        self.memo.budget_bytes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn product(n: usize) -> Arc<CachedProduct> {
        Arc::new(CachedProduct::new(
            vec![7u8; n],
            "application/octet-stream",
            Vec::new(),
        ))
    }

    #[test]
    fn evicts_least_recently_used_within_budget() {
        let one = product_bytes(&product(1000)) + crate::cache::ENTRY_OVERHEAD_BYTES;
        let c = BodyCache::new(3 * one + one / 2);
        for i in 0..3u8 {
            c.insert(([i; 32], "bin"), product(1000));
        }
        c.memo.run_pending_tasks();
        assert!(c.get(&([0; 32], "bin")).is_some());
        c.memo.run_pending_tasks();
        c.insert(([9; 32], "bin"), product(1000));
        c.memo.run_pending_tasks();
        assert!(
            c.get(&([1; 32], "bin")).is_none(),
            "the least recently used went first"
        );
        assert!(c.get(&([0; 32], "bin")).is_some() && c.get(&([9; 32], "bin")).is_some());
        assert_eq!(c.size(), (3, 3 * one));
    }

    #[test]
    fn a_product_counts_its_headers() {
        let bare = product_bytes(&product(10));
        let p = CachedProduct::new(
            vec![7u8; 10],
            "application/octet-stream",
            vec![(
                axum::http::HeaderName::from_static("x-strata-lod"),
                "12345".to_owned(),
            )],
        );
        assert!(product_bytes(&p) >= bare + "x-strata-lod".len() + 5);
    }
}
