//! Solved volume regions, by `(seed, digest)` ([`SolvedCache`]): each `volumes` element of each
//! world version is solved once ([`crate::volume::element::solve_volume`]).

use super::solved::SolvedCache;
use crate::scene::VolumeInput;
use crate::terrain::WorldPlan;
use crate::volume::element::{solve_volume, SolvedVolume};
use std::sync::Arc;

/// Most solved volume regions kept; the least recently used go first.
pub const VOLUME_CACHE_ENTRIES: usize = 16;

/// Solved volume regions.
pub type VolumeCache = SolvedCache<SolvedVolume>;

impl Default for VolumeCache {
    fn default() -> Self {
        Self::new(VOLUME_CACHE_ENTRIES)
    }
}

impl VolumeCache {
    /// The solved region of `volume` in the world `plan`, solving it if needed. `None` if the
    /// pipeline refused it (logged; chunks then show the heightfield there).
    pub async fn get(
        &self,
        plan: &Arc<WorldPlan>,
        volume: &VolumeInput,
    ) -> Option<Arc<SolvedVolume>> {
        let (p, spec) = (plan.clone(), volume.spec.clone());
        self.get_or_solve((plan.seed, volume.digest), "volume region", move || {
            solve_volume(&p, &spec)
        })
        .await
    }
}
