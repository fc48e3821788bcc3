//! `gullies: 3` (new worlds): the erosion filter's stripes fade out where the phasors of a
//! lattice cell's corners cancel, instead of turning from crest to trough within a sample
//! (`terrain::earth::kernel::GULLY_PHASOR_FLOOR2`). With `gullies: 2` such a turn is the full
//! depth of a gully as a cliff one sample wide: in the range 115 km from the origin the viewer
//! showed walls hundreds of metres high with a comb of stripes on them, and the heights of one
//! LOD-3 tile drop 170 m between two samples 8 m apart.
//!
//! `gully_first: 1` (new worlds): the coarsest gully octave (8 km cells) is left out. Its
//! stripes run straight across a cell and are about 9 % of the relief deep, so in the range they
//! cut canyons a few hundred metres deep that run dead straight for kilometres (the dark trench
//! of the viewer at (111.5 km, 119 km)); the rivers carve the valleys of that scale.

use strata::bench::realism::{metrics, sample};
use strata::terrain::{WorldParams, WorldPlan};

/// The 8 × 8 LOD-3 tiles (8 m spacing, 4.1 km square) from tile (216, 228), around (113.7 km,
/// 118.8 km) in the range, where the viewer showed the walls.
const TILES: (i64, i64) = (216, 228);

/// The 8 × 8 LOD-3 tiles from tile (214, 228), around (111.5 km, 119 km), where the coarsest
/// gully octave cut a straight canyon.
const CANYON_TILES: (i64, i64) = (214, 228);

/// The steepest step between neighbouring samples of `plan`'s ground in the 8 × 8 LOD-3 tiles
/// from `tiles` (rise over run), the share of steps steeper than 63° and the median slope in
/// degrees, as `strata bench realism` measures them.
fn steepness(plan: &WorldPlan, tiles: (i64, i64)) -> (f64, f64, f64) {
    let s = sample::sample(plan, 3, tiles.0, tiles.1, 8, 8);
    let slopes = metrics::slopes(&s.grid, 0.0);
    (
        slopes.steepest_step_deg.to_radians().tan(),
        slopes.cliff_fraction,
        slopes.median_deg,
    )
}

/// Seed 42's world with `gullies` and `gully_first`, the rest as new worlds have it.
fn world(gullies: u32, gully_first: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1 is the default");
    assert_eq!(
        (earth.gullies, earth.gully_first),
        (3, 1),
        "new worlds have gullies: 3 and gully_first: 1"
    );
    (earth.gullies, earth.gully_first) = (gullies, gully_first);
    WorldPlan::new(42, params).expect("a valid world")
}

#[test]
fn gullies_leave_no_cliff_one_sample_wide() {
    // Every gully octave, as the worlds stored with `gullies: 2` and `3` have them.
    let (worst3, steep3, _) = steepness(&world(3, 0), TILES);
    let (worst2, steep2, _) = steepness(&world(2, 0), TILES);
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

#[test]
fn new_worlds_leave_out_the_gullies_that_cut_straight_canyons() {
    let (worst_all, steep_all, median_all) = steepness(&world(3, 0), CANYON_TILES);
    let (worst, steep, median) = steepness(&world(3, 1), CANYON_TILES);
    eprintln!(
        "steepest rise over run: every octave {worst_all:.2}, without the coarsest {worst:.2}; \
         pairs steeper than 63°: {:.3} % and {:.3} %; median slope {median_all:.1}° and \
         {median:.1}°",
        100.0 * steep_all,
        100.0 * steep
    );
    // The canyon's walls: 0.17 % of the steps steeper than 63° and the steepest at 79° (rise
    // over run 5.3) with every octave; without the coarsest, 0.003 % and 68° (2.4).
    assert!(
        steep_all > 1e-3 && worst_all > 4.0,
        "the canyon is in the area: {steep_all}, {worst_all}"
    );
    assert!(
        steep < 0.1 * steep_all && worst < 3.0,
        "no canyon walls without the coarsest octave: {steep} against {steep_all}, {worst}"
    );
    // The rest of the relief keeps its slopes: the median moves by 0.6° (20.0° to 19.4°).
    assert!(
        (median - median_all).abs() < 2.0,
        "the relief keeps its slopes: median {median}° against {median_all}°"
    );
}

#[test]
fn gully_first_is_at_most_the_octaves() {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1 is the default");
    earth.gully_first = earth.gully_octaves + 1;
    let err = WorldPlan::new(42, params).expect_err("more octaves left out than there are");
    assert!(format!("{err:#}").contains("earth.gully_first"), "{err:#}");
}
