//! Solved authored regions, by `(seed, digest)` ([`SolvedCache`]).

use super::solved::{SolvedCache, Weigh};
use crate::authoring::{solve_region_on, Displacement};
use crate::compute::Offload;
use crate::scene::RegionInput;
use crate::terrain::WorldPlan;
use std::sync::Arc;

/// Default byte budget of solved regions (the share of [`super::budget::MemoryBudget`]); the
/// least recently used go first. It holds the largest region a stored scene may hold (2049²
/// samples of `d`, `base` and `fixed`: about 38 MB; a scene accepts 1025² today, about 9.5 MB):
/// a region heavier than the cache's budget is never kept, and every tile that reads it solves
/// it again, so a `--memory-budget` under 320 MiB makes the largest regions cost a solve per
/// tile.
pub const REGION_CACHE_BYTES: usize = 64 << 20;

/// Solved authored regions.
pub type RegionCache = SolvedCache<Displacement>;

impl Default for RegionCache {
    fn default() -> Self {
        Self::new(REGION_CACHE_BYTES)
    }
}

impl Weigh for Displacement {
    fn weight(&self) -> usize {
        std::mem::size_of::<Self>()
            + self.id.capacity()
            + 4 * (self.d.capacity() + self.base.capacity())
            + self.fixed.capacity()
    }
}

impl RegionCache {
    /// The solution of `region` in the world `plan`, solving it if needed. `None` if the solver
    /// refused it (logged; the tile then shows the procedural world there).
    pub async fn get(
        &self,
        plan: &Arc<WorldPlan>,
        region: &RegionInput,
        offload: Offload,
    ) -> Option<Arc<Displacement>> {
        let (p, spec) = (plan.clone(), region.spec.clone());
        self.get_or_solve(
            (plan.seed, region.digest),
            "authored region",
            move |cancel| solve_region_on(&p, &spec, &offload, cancel),
        )
        .await
    }
}
