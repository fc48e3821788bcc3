//! Solved volume regions, by digest: each `volumes` element of each world version is solved once
//! (the Becher pipeline, [`crate::volume::element::solve_volume`]) on the blocking pool, however
//! many chunks ask for it at once.

use crate::scene::VolumeInput;
use crate::terrain::WorldPlan;
use crate::volume::element::{solve_volume, SolvedVolume};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use tokio::sync::OnceCell;

/// Most solved volume regions kept; the least recently used go first.
pub const VOLUME_CACHE_ENTRIES: usize = 16;

type Slot = Arc<OnceCell<Option<Arc<SolvedVolume>>>>;
/// `(seed, volume digest)` → the slot and its last use.
type Entries = HashMap<(u64, [u8; 32]), (Slot, u64)>;

/// Solutions by `(seed, volume digest)`.
#[derive(Debug, Default)]
pub struct VolumeCache {
    entries: Mutex<Entries>,
    clock: std::sync::atomic::AtomicU64,
}

impl VolumeCache {
    /// The solved region of `volume` in the world `plan`, solving it if needed. `None` if the
    /// pipeline refused it (logged; chunks then show the heightfield there).
    pub async fn get(
        &self,
        plan: &Arc<WorldPlan>,
        volume: &VolumeInput,
    ) -> Option<Arc<SolvedVolume>> {
        let key = (plan.seed, volume.digest);
        let now = self
            .clock
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let slot = {
            let mut map = self
                .entries
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            if !map.contains_key(&key) && map.len() >= VOLUME_CACHE_ENTRIES {
                if let Some(oldest) = map.iter().min_by_key(|(_, (_, t))| *t).map(|(k, _)| *k) {
                    map.remove(&oldest);
                }
            }
            let entry = map.entry(key).or_insert_with(|| (Slot::default(), now));
            entry.1 = now;
            entry.0.clone()
        };
        let (plan, spec) = (plan.clone(), volume.spec.clone());
        slot.get_or_init(|| async move {
            let solved = tokio::task::spawn_blocking(move || solve_volume(&plan, &spec)).await;
            match solved {
                Ok(Ok(v)) => Some(Arc::new(v)),
                Ok(Err(e)) => {
                    tracing::warn!("volume region not solved: {e}");
                    None
                }
                Err(e) => std::panic::resume_unwind(e.into_panic()),
            }
        })
        .await
        .clone()
    }
}
