//! `gullies: 3` (new worlds): the erosion filter's stripes fade out where the phasors of a
//! lattice cell's corners cancel, instead of turning from crest to trough within a sample
//! (`terrain::earth::kernel::GULLY_PHASOR_FLOOR2`). With `gullies: 2` such a turn is the full
//! depth of a gully as a cliff one sample wide: in the range 115 km from the origin the viewer
//! showed walls hundreds of metres high with a comb of stripes on them, and the heights of one
//! LOD-3 tile drop 170 m between two samples 8 m apart.

use strata::bench::realism::{metrics, sample};
use strata::terrain::{WorldParams, WorldPlan};

/// The 8 × 8 LOD-3 tiles (8 m spacing, 4.1 km square) from tile (216, 228), around (113.7 km,
/// 118.8 km) in the range, where the viewer showed the walls.
const TILES: (i64, i64) = (216, 228);

/// The steepest step between neighbouring samples of `plan`'s ground there (rise over run) and
/// the share of steps steeper than 63°, as `strata bench realism` measures them.
fn steepness(plan: &WorldPlan) -> (f64, f64) {
    let s = sample::sample(plan, 3, TILES.0, TILES.1, 8, 8);
    let slopes = metrics::slopes(&s.grid, 0.0);
    (
        slopes.steepest_step_deg.to_radians().tan(),
        slopes.cliff_fraction,
    )
}

fn world(gullies: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1 is the default");
    assert_eq!(earth.gullies, 3, "new worlds have gullies: 3");
    earth.gullies = gullies;
    WorldPlan::new(42, params).expect("a valid world")
}

#[test]
fn gullies_leave_no_cliff_one_sample_wide() {
    let (worst3, steep3) = steepness(&world(3));
    let (worst2, steep2) = steepness(&world(2));
    eprintln!(
        "steepest rise over run: gullies 2 {worst2:.2}, 3 {worst3:.2}; \
         pairs steeper than 63°: {:.3} % and {:.3} %",
        100.0 * steep2,
        100.0 * steep3
    );
    // 8 is 83°: a face that steep over 8 m is a cliff the relief's own layers do not make here
    // (the steepest pair with gullies: 3 rises 5.3, 79°, where a ridged crest meets a gully).
    assert!(
        worst3 < 8.0,
        "gullies: 3 leave a cliff: rise over run {worst3}"
    );
    assert!(
        worst2 > 8.0,
        "the cliffs of gullies: 2 are in the area: {worst2}"
    );
    assert!(
        steep3 < 0.5 * steep2,
        "gullies: 3 halve the steep pairs at least: {steep3} against {steep2}"
    );
}
