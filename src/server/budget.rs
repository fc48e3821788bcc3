//! The process-wide memory budget of the caches (`strata serve --memory-budget MB`, or
//! `STRATA_MEMORY_BUDGET`; default [`DEFAULT_MEMORY_BUDGET_MB`] = 512 MiB), split between the
//! eight caches by fixed fractions, since each is its own [`crate::cache::Memo`]:
//!
//! | cache | share | default |
//! |---|---|---|
//! | stage cache, finished tiles ([`crate::cache::StageCache`]) | 3/8 | 192 MiB |
//! | encoded bodies ([`super::bodies::BodyCache`]) | 3/16 | 96 MiB |
//! | meshed volume chunks ([`super::chunk_meshes::ChunkMeshCache`]) | 1/16 | 32 MiB |
//! | decoded images of materials and decals ([`super::images::ImageCache`]) | 1/8 | 64 MiB |
//! | solved authored regions ([`super::regions::RegionCache`]) | 1/8 | 64 MiB |
//! | solved volume regions ([`super::volumes::VolumeCache`]) | 1/16 | 32 MiB |
//! | world plans of stored worlds (`worlds::VersionPlans`) | 3/64 | 24 MiB |
//! | world plans of bare seeds (`plans::PlanCache`) | 1/64 | 8 MiB |
//!
//! Each cache counts what its entries hold (see each weigher), so their sum stays within the
//! budget; what the process holds besides is a fixed overhead on top, which `strata bench serve`
//! measures: code and runtime, requests in flight, allocator slack, and the `earth-1` river
//! block caches (`terrain::earth::rivers::network`, process-wide `moka` caches of their own,
//! 200 MiB in all) and climate node windows (`terrain::earth::climate`, 16 MiB), outside this
//! budget because `terrain` sits below `cache` and `server`.

/// Default of `--memory-budget`, MiB.
pub const DEFAULT_MEMORY_BUDGET_MB: u64 = 512;

/// The byte budget of each cache (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryBudget {
    /// The whole budget, bytes.
    pub total: usize,
    /// Stage cache (memory tier).
    pub stage: usize,
    /// Decoded images of the worlds' materials and decals.
    pub images: usize,
    /// Encoded bodies.
    pub bodies: usize,
    /// Meshed volume chunks.
    pub chunk_meshes: usize,
    /// Solved volume regions.
    pub volumes: usize,
    /// Solved authored regions.
    pub regions: usize,
    /// World plans of stored worlds, by `(world, version)`.
    pub world_plans: usize,
    /// World plans of bare seeds.
    pub seed_plans: usize,
}

impl MemoryBudget {
    /// `total` bytes split by the fixed fractions.
    pub fn new(total: usize) -> Self {
        let part = |n: usize, d: usize| total / d * n;
        Self {
            total,
            stage: part(3, 8),
            images: part(1, 8),
            bodies: part(3, 16),
            chunk_meshes: part(1, 16),
            volumes: part(1, 16),
            regions: part(1, 8),
            world_plans: part(3, 64),
            seed_plans: part(1, 64),
        }
    }

    /// `mb` MiB.
    pub fn from_mb(mb: u64) -> Self {
        Self::new(usize::try_from(mb << 20).unwrap_or(usize::MAX))
    }
}

impl Default for MemoryBudget {
    fn default() -> Self {
        Self::from_mb(DEFAULT_MEMORY_BUDGET_MB)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shares_add_up_to_the_budget_and_keep_todays_defaults() {
        let b = MemoryBudget::default();
        let sum = b.stage
            + b.images
            + b.bodies
            + b.chunk_meshes
            + b.volumes
            + b.regions
            + b.world_plans
            + b.seed_plans;
        assert_eq!(sum, b.total);
        // The images' eighth came out of the stage cache's half.
        assert_eq!(b.stage + b.images, crate::cache::DEFAULT_BUDGET_BYTES);
        assert_eq!(b.images, 64 << 20);
        assert_eq!(b.bodies, super::super::bodies::DEFAULT_BODY_BUDGET_BYTES);
        // The chunk meshes' sixteenth came out of the bodies' quarter.
        assert_eq!(b.bodies + b.chunk_meshes, 128 << 20);
        assert_eq!(
            b.chunk_meshes,
            super::super::chunk_meshes::CHUNK_MESH_CACHE_BYTES
        );
        let odd = MemoryBudget::new(1_000_003);
        let sum =
            odd.stage + odd.images + odd.bodies + odd.chunk_meshes + odd.volumes + odd.regions;
        assert!(sum + odd.world_plans + odd.seed_plans <= odd.total);
    }

    #[test]
    fn the_state_sizes_every_cache_from_the_budget() {
        let b = MemoryBudget::from_mb(64);
        let st = super::super::AppState::new(crate::compute::Compute::cpu()).with_memory_budget(b);
        assert_eq!(st.memory_budget(), b);
        assert_eq!(st.cache.budget_bytes(), 24 << 20);
        assert_eq!(st.images.stats().budget_bytes, 8 << 20);
        assert_eq!(st.bodies.budget_bytes(), 12 << 20);
        assert_eq!(st.chunk_meshes.stats().budget_bytes, 4 << 20);
        assert_eq!(st.volumes.size().2, 4 << 20);
        assert_eq!(st.regions.size().2, 8 << 20);
        assert!(st.plans.size().2 <= b.seed_plans as u64);
    }
}
