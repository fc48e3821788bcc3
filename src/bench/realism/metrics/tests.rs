//! Unit tests of the terrain statistics ([`super`]) on surfaces whose answers are known
//! (planes, cones, fBm, steps).

use super::*;

/// SplitMix64 in [0, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }
}

/// A surface whose power spectrum is `|k|^beta` (random phases, spectral synthesis).
fn fbm(n: usize, beta: f64, seed: u64) -> Grid {
    let mut rng = Rng(seed);
    let mut data: Vec<Complex<f64>> = (0..n * n)
        .map(|k| {
            let (kx, kz) = (signed(k % n, n), signed(k / n, n));
            let r = kx.hypot(kz);
            let amp = if r == 0.0 { 0.0 } else { r.powf(beta / 2.0) };
            let phase = rng.next() * std::f64::consts::TAU;
            Complex::from_polar(amp, phase)
        })
        .collect();
    fft2(&mut data, n, n, true);
    let heights: Vec<f32> = data.iter().map(|c| c.re as f32).collect();
    let scale = 300.0 / heights.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    Grid::new(n, n, 10.0, heights.iter().map(|v| v * scale).collect())
}

#[test]
fn tilted_plane_slope_is_its_angle() {
    let t = 30f64.to_radians().tan();
    let g = Grid::from_fn(64, 48, 5.0, |x, z| 100.0 + x * t * 0.6 + z * t * 0.8);
    let s = slopes(&g, f64::NEG_INFINITY);
    assert!((s.median_deg - 30.0).abs() < 0.01, "{s:?}");
    assert!((s.p95_deg - 30.0).abs() < 0.01, "{s:?}");
    assert!(
        s.steepest_step_deg < 30.0 && s.cliff_fraction == 0.0,
        "{s:?}"
    );
}

#[test]
fn a_step_one_cell_wide_is_a_cliff() {
    // A 10° plane with a 100 m step between x = 100 and 105 m (cells of 5 m).
    let t = 10f64.to_radians().tan();
    let g = Grid::from_fn(64, 48, 5.0, |x, z| {
        100.0 + z * t + if x > 102.0 { 100.0 } else { 0.0 }
    });
    let s = slopes(&g, f64::NEG_INFINITY);
    assert!(
        (s.steepest_step_deg - 20f64.atan().to_degrees()).abs() < 0.1,
        "{s:?}"
    );
    // One pair in each of the 46 interior rows, of 2 · 62 · 46 pairs.
    assert!(
        (s.cliff_fraction - 46.0 / (2.0 * 62.0 * 46.0)).abs() < 1e-9,
        "{s:?}"
    );
}

#[test]
fn cone_drains_and_bowl_is_a_depression() {
    let cone = Grid::from_fn(101, 101, 10.0, |x, z| {
        500.0 - (x - 500.0).hypot(z - 500.0) * 0.5
    });
    let d = depressions(&cone, f64::NEG_INFINITY, 2.0);
    assert_eq!(d.fraction, 0.0, "{d:?}");
    let bowl = Grid::from_fn(101, 101, 10.0, |x, z| {
        (x - 500.0).abs().max((z - 500.0).abs()) * 0.5
    });
    let d = depressions(&bowl, f64::NEG_INFINITY, 2.0);
    assert!(d.fraction > 0.9, "{d:?}");
    // The sea is an outlet: the same bowl flooded to 200 m drains into it.
    let d = depressions(&bowl, 200.0, 2.0);
    assert_eq!(d.fraction, 0.0, "{d:?}");
    let e = extrema(&cone, f64::NEG_INFINITY);
    assert!((e.peaks_per_km2 - 1.0 / (99.0 * 99.0 * 100.0 / 1e6)).abs() < 1e-9);
    assert_eq!(e.pits_per_km2, 0.0);
}

#[test]
fn radial_surface_is_isotropic_and_a_ridge_is_not() {
    let hill = Grid::from_fn(256, 256, 1.0, |x, z| {
        let r2 = (x - 127.5).powi(2) + (z - 127.5).powi(2);
        50.0 * (-r2 / (2.0 * 25.0 * 25.0)).exp()
    });
    let a = anisotropy(&hill, f64::NEG_INFINITY);
    assert!(a.ratio < 1.1, "{a:?}");
    let ridge = Grid::from_fn(256, 256, 1.0, |x, z| {
        50.0 * (-(z - 127.5).powi(2) / 800.0).exp() + 0.001 * x
    });
    let a = anisotropy(&ridge, f64::NEG_INFINITY);
    assert!(a.ratio > 10.0, "{a:?}");
}

#[test]
fn spectrum_slope_of_synthetic_fbm_is_its_exponent() {
    for (beta, seed) in [(-2.4, 1), (-3.6, 2)] {
        let g = fbm(256, beta, seed);
        let s = spectrum(&g);
        assert!((s.slope - beta).abs() < 0.25, "beta {beta}: {s:?}");
    }
}

#[test]
fn laplacian_ratio_sees_a_step_on_the_border() {
    let border: Vec<bool> = (0..128 * 128)
        .map(|k| ((k % 128) as i64 - 64).abs() < 4)
        .collect();
    let smooth = Grid::from_fn(128, 128, 2.0, |x, z| 0.01 * (x * x + z * z));
    let r = border_curvature(&smooth, &border)
        .ratio()
        .unwrap_or(f64::NAN);
    assert!((r - 1.0).abs() < 0.01, "{r}");
    let step = Grid::from_fn(128, 128, 2.0, |x, z| {
        0.01 * (x * x + z * z) + if x >= 128.0 { 20.0 } else { 0.0 }
    });
    let r = border_curvature(&step, &border).ratio().unwrap_or(f64::NAN);
    assert!(r > 10.0, "{r}");
    assert_eq!(
        border_curvature(&step, &vec![false; 128 * 128]).ratio(),
        None
    );
}

#[test]
fn hypsometry_of_a_plane_and_resampling() {
    let g = Grid::from_fn(101, 101, 1.0, |x, _| x);
    let hy = hypsometry(&g, f64::NEG_INFINITY);
    assert!((hy.integral - 0.5).abs() < 1e-9, "{hy:?}");
    assert!((hy.relative[2] - 0.5).abs() < 0.02, "{hy:?}");
    let b = g.block_average(10.0);
    assert_eq!((b.w, b.h), (10, 10));
    assert!((b.heights[0] - 4.5).abs() < 1e-6);
    let r = g.resample(2.5);
    assert_eq!((r.w, r.h), (41, 41));
    assert!((r.heights[1] - 2.5).abs() < 1e-6);
}

#[test]
fn a_border_ratio_needs_cells_on_both_sides() {
    // The far area at 64 m once compared 260,093 border cells with 7 others.
    let lopsided = BorderCurvature {
        border_sum: 260_093.0,
        border_cells: 260_093,
        other_sum: 3.0,
        other_cells: 7,
    };
    assert!(lopsided.ratio().is_some());
    assert!(lopsided.one_side_only(0.01));
    assert_eq!(lopsided.two_sided_ratio(0.01), None);
    // The origin's area at 64 m: 47,774 border cells of 260,100.
    let fair = BorderCurvature {
        border_sum: 47_774.0 * 1.2,
        border_cells: 47_774,
        other_sum: 212_326.0,
        other_cells: 212_326,
    };
    assert!(!fair.one_side_only(0.01));
    let r = fair.two_sided_ratio(0.01).unwrap_or(f64::NAN);
    assert!((r - 1.2).abs() < 1e-9, "{r}");
    // No border at all is not "one side only": there is nothing to compare.
    let none = BorderCurvature {
        other_sum: 1.0,
        other_cells: 100,
        ..BorderCurvature::default()
    };
    assert!(!none.one_side_only(0.01));
    assert_eq!(none.two_sided_ratio(0.01), None);
}

#[test]
fn water_fraction_counts_wet_land_only() {
    // A plane rising east from 10.5 m below the sea to 20.5 m above it: the first 11 columns
    // are sea, and of the 21 columns of land the first 10 hold water (as do the sea's, which
    // count for nothing).
    let g = Grid::from_fn(32, 8, 1.0, |x, _| x - 10.5);
    let water: Vec<f32> = (0..g.heights.len())
        .map(|n| if n % 32 < 21 { 0.5 } else { f32::NAN })
        .collect();
    assert_eq!(water_fraction(&g, 0.0, &water), 10.0 / 21.0);
    assert_eq!(
        water_fraction(&g, 0.0, &vec![f32::NAN; g.heights.len()]),
        0.0
    );
    assert!(water_fraction(&g, 100.0, &water).is_nan(), "no land");
}
