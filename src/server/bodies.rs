//! Encoded products by `(tile input hash, format)`: a hit answers a request with a reference-counted
//! body and a precomputed ETag, no synthesis, encoding or hashing. Bounded by a byte budget,
//! least recently used evicted first.

use super::routes::CachedProduct;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

/// Default budget of encoded bodies, bytes.
pub const DEFAULT_BODY_BUDGET_BYTES: usize = 128 << 20;

/// Key: the tile's input hash and the format's extension.
pub type BodyKey = ([u8; 32], &'static str);

#[derive(Debug, Default)]
struct Inner {
    map: HashMap<BodyKey, (Arc<CachedProduct>, u64)>,
    bytes: usize,
    tick: u64,
}

/// The cache; cheap to share behind an `Arc`.
#[derive(Debug)]
pub struct BodyCache {
    budget: usize,
    inner: Mutex<Inner>,
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
    /// A cache of at most `budget` bytes of bodies.
    pub fn new(budget: usize) -> Self {
        Self {
            budget,
            inner: Mutex::default(),
            hits: AtomicU64::new(0),
            misses: AtomicU64::new(0),
        }
    }

    /// The cached product, if any.
    pub fn get(&self, key: &BodyKey) -> Option<Arc<CachedProduct>> {
        let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        g.tick += 1;
        let tick = g.tick;
        match g.map.get_mut(key) {
            Some(entry) => {
                entry.1 = tick;
                self.hits.fetch_add(1, Ordering::Relaxed);
                Some(entry.0.clone())
            }
            None => {
                self.misses.fetch_add(1, Ordering::Relaxed);
                None
            }
        }
    }

    /// Stores a product, evicting the least recently used ones beyond the budget.
    pub fn insert(&self, key: BodyKey, product: Arc<CachedProduct>) {
        let size = product.body.len() + 256;
        if size > self.budget {
            return;
        }
        let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        g.tick += 1;
        let tick = g.tick;
        if let Some((old, _)) = g.map.insert(key, (product, tick)) {
            g.bytes -= old.body.len() + 256;
        }
        g.bytes += size;
        while g.bytes > self.budget {
            let Some(oldest) = g.map.iter().min_by_key(|(_, (_, t))| *t).map(|(k, _)| *k) else {
                break;
            };
            if let Some((p, _)) = g.map.remove(&oldest) {
                g.bytes -= p.body.len() + 256;
            }
        }
    }

    /// `(entries, bytes)`.
    pub fn size(&self) -> (usize, usize) {
        let g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        (g.map.len(), g.bytes)
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
        let c = BodyCache::new(3 * (1000 + 256));
        for i in 0..3u8 {
            c.insert(([i; 32], "bin"), product(1000));
        }
        assert!(c.get(&([0; 32], "bin")).is_some());
        c.insert(([9; 32], "bin"), product(1000));
        assert!(
            c.get(&([1; 32], "bin")).is_none(),
            "the least recently used went first"
        );
        assert!(c.get(&([0; 32], "bin")).is_some() && c.get(&([9; 32], "bin")).is_some());
        assert!(c.size().1 <= 3 * 1256);
    }
}
