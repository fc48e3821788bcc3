//! World plans of bare seeds, one per seed: a [`Memo`] within a byte budget, least recently used
//! evicted first; concurrent misses of one seed build its plan once.

use super::AppError;
use crate::cache::Memo;
use crate::terrain::{WorldParams, WorldPlan};
use std::sync::Arc;

/// Bytes a world plan is counted for: an estimate (its octave tables and per-LOD constants are
/// not walked), the same for every plan.
pub(crate) const PLAN_BYTES_ESTIMATE: usize = 128 << 10;

/// Plans of recently requested seeds.
#[derive(Debug)]
pub(crate) struct PlanCache {
    memo: Memo<u64, Arc<WorldPlan>>,
}

impl PlanCache {
    /// At most `capacity` plans, and at most `budget_bytes` of them
    /// ([`PLAN_BYTES_ESTIMATE`] each).
    pub(crate) fn new(capacity: usize, budget_bytes: usize) -> Self {
        let one = PLAN_BYTES_ESTIMATE + crate::cache::ENTRY_OVERHEAD_BYTES;
        Self {
            memo: Memo::new(budget_bytes.min(capacity.max(1) * one), |_, _| {
                PLAN_BYTES_ESTIMATE
            }),
        }
    }

    /// `(hits, misses)` so far.
    pub(crate) fn stats(&self) -> (u64, u64) {
        let s = self.memo.stats();
        (s.hits + s.joined, s.misses)
    }

    /// `(entries, bytes, budget bytes)`.
    pub(crate) fn size(&self) -> (u64, u64, u64) {
        let s = self.memo.stats();
        (s.entries, s.bytes, s.budget_bytes)
    }

    /// The plan of `seed`'s default world.
    pub(crate) async fn get_or_build(&self, seed: u64) -> Result<Arc<WorldPlan>, AppError> {
        let (plan, _) = self
            .memo
            .try_get_or_compute_async(seed, || async move {
                let built = tokio::task::spawn_blocking(move || {
                    WorldPlan::new(seed, WorldParams::default())
                })
                .await
                .map_err(|e| AppError::internal(format!("building the world plan failed: {e}")))?
                .map_err(|e| AppError::internal(format!("invalid world settings: {e}")))?;
                Ok::<_, AppError>(Arc::new(built))
            })
            .await?;
        Ok(plan)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn bounded_and_lru() {
        let c = PlanCache::new(2, usize::MAX);
        let a = c.get_or_build(1).await.expect("plan");
        c.get_or_build(2).await.expect("plan");
        c.memo.run_pending_tasks();
        assert!(
            Arc::ptr_eq(&a, &c.get_or_build(1).await.expect("plan")),
            "hit"
        );
        c.memo.run_pending_tasks();
        c.get_or_build(3).await.expect("plan"); // evicts 2, the least recently used
        c.memo.run_pending_tasks();
        assert_eq!(c.size().0, 2);
        assert!(c.memo.contains(&1) && c.memo.contains(&3) && !c.memo.contains(&2));
    }
}
