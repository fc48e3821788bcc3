//! A small least-recently-used cache of world plans, one per seed.

use super::AppError;
use crate::terrain::{WorldParams, WorldPlan};
use std::sync::{Arc, Mutex};

/// Plans of recently requested seeds.
#[derive(Debug)]
pub(crate) struct PlanCache {
    capacity: usize,
    /// `(seed, plan, last use)`.
    entries: Mutex<Vec<(u64, Arc<WorldPlan>, u64)>>,
    clock: std::sync::atomic::AtomicU64,
    hits: std::sync::atomic::AtomicU64,
    misses: std::sync::atomic::AtomicU64,
}

impl PlanCache {
    pub(crate) fn new(capacity: usize) -> Self {
        Self {
            capacity: capacity.max(1),
            entries: Mutex::new(Vec::new()),
            clock: Default::default(),
            hits: Default::default(),
            misses: Default::default(),
        }
    }

    /// `(hits, misses)` so far.
    pub(crate) fn stats(&self) -> (u64, u64) {
        use std::sync::atomic::Ordering::Relaxed;
        (self.hits.load(Relaxed), self.misses.load(Relaxed))
    }

    fn tick(&self) -> u64 {
        self.clock
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed)
    }

    fn lookup(&self, seed: u64) -> Option<Arc<WorldPlan>> {
        let now = self.tick();
        let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        let e = entries.iter_mut().find(|e| e.0 == seed)?;
        e.2 = now;
        Some(e.1.clone())
    }

    fn insert(&self, seed: u64, plan: Arc<WorldPlan>) -> Arc<WorldPlan> {
        let now = self.tick();
        let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(e) = entries.iter_mut().find(|e| e.0 == seed) {
            // Built concurrently by another request: keep one.
            e.2 = now;
            return e.1.clone();
        }
        if entries.len() >= self.capacity {
            if let Some(oldest) = entries
                .iter()
                .enumerate()
                .min_by_key(|(_, e)| e.2)
                .map(|(i, _)| i)
            {
                entries.swap_remove(oldest);
            }
        }
        entries.push((seed, plan.clone(), now));
        plan
    }

    /// The plan of `seed`'s default world.
    pub(crate) async fn get_or_build(&self, seed: u64) -> Result<Arc<WorldPlan>, AppError> {
        use std::sync::atomic::Ordering::Relaxed;
        if let Some(p) = self.lookup(seed) {
            self.hits.fetch_add(1, Relaxed);
            return Ok(p);
        }
        self.misses.fetch_add(1, Relaxed);
        let built =
            tokio::task::spawn_blocking(move || WorldPlan::new(seed, WorldParams::default()))
                .await
                .map_err(|e| AppError::internal(format!("building the world plan failed: {e}")))?
                .map_err(|e| AppError::internal(format!("invalid world settings: {e}")))?;
        Ok(self.insert(seed, Arc::new(built)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn bounded_and_lru() {
        let c = PlanCache::new(2);
        let a = c.get_or_build(1).await.expect("plan");
        c.get_or_build(2).await.expect("plan");
        assert!(
            Arc::ptr_eq(&a, &c.get_or_build(1).await.expect("plan")),
            "hit"
        );
        c.get_or_build(3).await.expect("plan"); // evicts 2, the least recently used
        let seeds: Vec<u64> = c
            .entries
            .lock()
            .expect("lock")
            .iter()
            .map(|e| e.0)
            .collect();
        assert_eq!(seeds.len(), 2);
        assert!(seeds.contains(&1) && seeds.contains(&3));
    }
}
