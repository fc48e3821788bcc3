//! Solved authored regions, by digest: each region of each world version is solved once, on the
//! blocking pool, however many tiles ask for it at once.

use crate::authoring::{solve_region, Displacement};
use crate::scene::RegionInput;
use crate::terrain::WorldPlan;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use tokio::sync::OnceCell;

/// Most solved regions kept; the least recently used go first.
pub const REGION_CACHE_ENTRIES: usize = 64;

type Slot = Arc<OnceCell<Option<Arc<Displacement>>>>;
/// `(seed, region digest)` → the slot and its last use.
type Entries = HashMap<(u64, [u8; 32]), (Slot, u64)>;

/// Solutions by `(seed, region digest)`.
#[derive(Debug, Default)]
pub struct RegionCache {
    entries: Mutex<Entries>,
    clock: std::sync::atomic::AtomicU64,
}

impl RegionCache {
    /// The solution of `region` in the world `plan`, solving it if needed. `None` if the solver
    /// refused it (logged; the tile then shows the procedural world there).
    pub async fn get(
        &self,
        plan: &Arc<WorldPlan>,
        region: &RegionInput,
    ) -> Option<Arc<Displacement>> {
        let key = (plan.seed, region.digest);
        let now = self
            .clock
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let slot = {
            let mut map = self
                .entries
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            if !map.contains_key(&key) && map.len() >= REGION_CACHE_ENTRIES {
                if let Some(oldest) = map.iter().min_by_key(|(_, (_, t))| *t).map(|(k, _)| *k) {
                    map.remove(&oldest);
                }
            }
            let entry = map.entry(key).or_insert_with(|| (Slot::default(), now));
            entry.1 = now;
            entry.0.clone()
        };
        let (plan, spec) = (plan.clone(), region.spec.clone());
        slot.get_or_init(|| async move {
            let solved = tokio::task::spawn_blocking(move || solve_region(&plan, &spec)).await;
            match solved {
                Ok(Ok(d)) => Some(Arc::new(d)),
                Ok(Err(e)) => {
                    tracing::warn!("authored region not solved: {e}");
                    None
                }
                Err(e) => std::panic::resume_unwind(e.into_panic()),
            }
        })
        .await
        .clone()
    }
}
