//! The `range` area of `strata bench realism`: a temperate mountain range about 160 km from the
//! origin of seed 42, whose summits reach above 2.8 km.

use strata::terrain::tile::{synthesize, Tile, TileKey};
use strata::terrain::WorldPlan;

/// The centre of the area (its 8 and 64 m blocks), metres.
pub const RANGE: (f64, f64) = (114_700.0, 114_700.0);
/// The LOD of [`range_tiles`] (32 m spacing).
pub const LOD: u32 = 5;

/// The 4 × 4 LOD-5 tiles (2 km each) around the range's centre.
pub fn range_tiles(plan: &WorldPlan) -> Vec<Tile> {
    let span = 64.0 * plan.lods[LOD as usize].spacing_m as f64;
    let (cx, cz) = ((RANGE.0 / span) as i64, (RANGE.1 / span) as i64);
    (cz - 2..cz + 2)
        .flat_map(|z| (cx - 2..cx + 2).map(move |x| TileKey { lod: LOD, x, z }))
        .map(|key| synthesize(plan, key))
        .collect()
}
