//! The glb reader of volume-region input meshes (`volume::mesh_import::glb_triangles`): any bytes
//! are refused with an error or read within the reader's bounds, never a panic and never
//! unbounded work (libFuzzer's `-timeout` and `-rss_limit_mb` catch the latter).
#![no_main]

use libfuzzer_sys::fuzz_target;
use strata::volume::mesh_import::glb_triangles;

/// The triangle budget of one volume element, as a scene grants it.
const MAX_TRIANGLES: usize = 1 << 16;

fuzz_target!(|data: &[u8]| {
    if let Ok(triangles) = glb_triangles(data, None, MAX_TRIANGLES) {
        assert!(triangles.len() <= MAX_TRIANGLES);
        assert!(triangles.iter().flatten().flatten().all(|c| c.is_finite()));
    }
});
