//! Solved volume regions, by `(seed, digest)` ([`SolvedCache`]): each `volumes` element of each
//! world version is solved once ([`crate::volume::element::solve_volume`]). The digest covers
//! the element and the authored regions and `strata` elements whose edits its ground takes, so
//! editing any of them solves the region again.

use super::solved::{SolvedCache, Weigh};
use super::view::WorldView;
use super::AppState;
use crate::scene::VolumeInput;
use crate::volume::element::{ground_rect, solve_volume_on, SolvedVolume};
use std::sync::Arc;

/// Default byte budget of solved volume regions (the share of [`super::budget::MemoryBudget`]);
/// the least recently used go first.
pub const VOLUME_CACHE_BYTES: usize = 32 << 20;

/// Solved volume regions.
pub type VolumeCache = SolvedCache<SolvedVolume>;

impl Default for VolumeCache {
    fn default() -> Self {
        Self::new(VOLUME_CACHE_BYTES)
    }
}

/// The fields' and the voxelization's arrays (the element itself and the grid by their struct
/// size only: approximate).
impl Weigh for SolvedVolume {
    fn weight(&self) -> usize {
        fn f32s<const N: usize>(v: &[Vec<f32>; N]) -> usize {
            v.iter().map(|v| 4 * v.capacity()).sum()
        }
        let f = &self.fields;
        let x = &f.voxelized;
        std::mem::size_of::<Self>()
            + f32s(&f.normal)
            + f32s(&f.bitangent)
            + 4 * (f.surface.capacity()
                + f.surface_raw.capacity()
                + f.surface_layer.capacity()
                + f.alpha.capacity()
                + f.beta.capacity()
                + f.confidence.capacity())
            + 2 * f.material.capacity()
            + f32s(&x.normal)
            + f32s(&x.bitangent)
            + 4 * (x.surface.capacity() + x.alpha.capacity() + x.beta.capacity())
            + 2 * x.material.capacity()
            + x.omega_n.capacity()
            + x.omega_r.capacity()
            + x.omega_s.capacity()
            + std::mem::size_of_val(x.pass_stats.as_slice())
    }
}

/// The key of `volume`'s solution in the world `view`: the seed, and a blake3 of the element's
/// digest and those of the authored regions and `strata` elements its ground takes.
pub(super) fn volume_key(view: &WorldView, volume: &VolumeInput) -> (u64, [u8; 32]) {
    let rect = ground_rect(&view.plan, &volume.spec);
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
    (view.plan.seed, *key.finalize().as_bytes())
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
        let key = volume_key(view, volume);
        let edits = view.ground_edits(st, &rect).await;
        let (p, spec) = (plan.clone(), volume.spec.clone());
        let offload = st.compute.offload();
        self.get_or_solve(key, "volume region", move |cancel| {
            solve_volume_on(&p, &spec, &edits, &offload, cancel)
        })
        .await
    }
}
