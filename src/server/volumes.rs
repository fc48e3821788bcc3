//! Solved volume regions, by `(seed, digest)` ([`SolvedCache`]): each `volumes` element of each
//! world version is solved once ([`crate::volume::element::solve_volume`]). The digest covers
//! the element and the authored regions and `strata` elements whose edits its ground takes, so
//! editing any of them solves the region again.

use super::solved::SolvedCache;
use super::view::WorldView;
use super::AppState;
use crate::scene::VolumeInput;
use crate::volume::element::{ground_rect, solve_volume, SolvedVolume};
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
    /// The solved region of `volume` in the world `view`, solving it (and the authored regions
    /// its ground takes, through the state's region cache) if needed. `None` if the pipeline
    /// refused it (logged; chunks then show the heightfield there).
    pub async fn get(
        &self,
        st: &AppState,
        view: &WorldView,
        volume: &VolumeInput,
    ) -> Option<Arc<SolvedVolume>> {
        let plan = &view.plan;
        let rect = ground_rect(plan, &volume.spec);
        let mut key = blake3::Hasher::new();
        key.update(b"strata.volume-inputs\0");
        key.update(&volume.digest);
        for r in view.inputs.regions_meeting(&rect) {
            key.update(&r.digest);
        }
        for s in view.inputs.strata() {
            if s.rect().intersects(&rect) {
                key.update(&s.digest);
            }
        }
        let key = (plan.seed, *key.finalize().as_bytes());
        let edits = view.ground_edits(st, &rect).await;
        let (p, spec) = (plan.clone(), volume.spec.clone());
        self.get_or_solve(key, "volume region", move || {
            solve_volume(&p, &spec, &edits)
        })
        .await
    }
}
