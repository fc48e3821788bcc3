//! The smooth hill: an elevation constraint with a C² ring (`ring_m`), checked on the solved
//! region (region `[1000, 2000]–[1128, 2128]`, 1 m spacing at 129 samples), against the same
//! constraint without a ring, whose solve meets it with a kink.

use crate::{ground, height, solve, spec};
use serde_json::json;
use strata::authoring::Displacement;

const CENTRE: [f64; 2] = [1064.0, 2064.0];
const RADIUS_M: f64 = 4.0;
const RING_M: f64 = 40.0;

/// The displacement `d` and the height along the row through the centre, eastwards from it:
/// `(distance from the centre, d, h)` per sample.
fn east_profile(r: &Displacement) -> Vec<(f64, f64, f64)> {
    let n = r.grid.n;
    let (ci, cj) = crate::sample_at(r, CENTRE[0], CENTRE[1]);
    (ci..n)
        .map(|i| {
            let p = r.grid.position(i, cj);
            (
                p[0] - CENTRE[0],
                f64::from(r.d[cj * n + i]),
                height(r, i, cj),
            )
        })
        .collect()
}

/// Second differences `v[k−1] − 2v[k] + v[k+1]` at the samples whose distance lies within
/// `half` of `at`, the largest in magnitude.
fn largest_second_difference(profile: &[(f64, f64)], at: f64, half: f64) -> f64 {
    (1..profile.len() - 1)
        .filter(|&k| (profile[k].0 - at).abs() <= half)
        .map(|k| (profile[k - 1].1 - 2.0 * profile[k].1 + profile[k + 1].1).abs())
        .fold(0.0, f64::max)
}

#[test]
fn a_hill_with_a_ring_is_c2_at_both_edges_of_the_ring_and_the_plain_constraint_is_not() {
    let e = ground(CENTRE[0], CENTRE[1]) + 30.0;
    let hill = solve(
        json!([{"op": "elevation", "shape": {"point": CENTRE}, "elevation_m": e,
        "radius_m": RADIUS_M, "ring_m": RING_M}]),
    );
    let plain = solve(
        json!([{"op": "elevation", "shape": {"point": CENTRE}, "elevation_m": e,
        "radius_m": RADIUS_M}]),
    );
    let ring = east_profile(&hill);
    let bare = east_profile(&plain);
    let outer = RADIUS_M + RING_M;
    // Across the ring the displacement d = (e − h_p)·S falls outwards but for the ground's own
    // rise: between neighbours it grows by at most |Δh_p| (S decreases, e − h_p stays positive).
    for w in ring.windows(2) {
        if w[0].0 >= RADIUS_M && w[1].0 <= outer {
            let ground_rise = ((w[1].2 - w[1].1) - (w[0].2 - w[0].1)).abs();
            assert!(w[1].1 <= w[0].1 + ground_rise + 1e-4, "d rises from {w:?}");
        }
    }
    let beyond = ring
        .iter()
        .filter(|s| s.0 > outer)
        .map(|s| s.1.abs())
        .fold(0.0, f64::max);
    assert!(beyond < 1e-3, "d is {beyond} m beyond the ring");
    // At the outer edge the height is the procedural ground's on both sides, so d is what has to
    // be C²: its second differences there are those of A·S(t) near t = 0, S″(t) ≈ 60t, at most
    // A·60·(2/40)/40² ≈ 0.06 m within two samples (A ≈ 30 m), and 0 beyond. The plain
    // constraint's free samples are harmonic around it: its kink at the constraint's edge gives
    // a second difference of metres.
    let d = |p: &[(f64, f64, f64)]| p.iter().map(|s| (s.0, s.1)).collect::<Vec<_>>();
    let h = |p: &[(f64, f64, f64)]| p.iter().map(|s| (s.0, s.2)).collect::<Vec<_>>();
    let outer_edge = largest_second_difference(&d(&ring), outer, 2.0);
    let plain_edge = largest_second_difference(&d(&bare), RADIUS_M, 2.0);
    // At the inner edge the height is e on the inside: h is what has to be C² there (the
    // procedural ground's own curvature is multiplied by 1 − S, which vanishes there).
    let inner_edge = largest_second_difference(&h(&ring), RADIUS_M, 2.0);
    let inner_plain = largest_second_difference(&h(&bare), RADIUS_M, 2.0);
    println!(
        "largest |second difference| (1 m spacing): ring's outer edge {outer_edge:.4} m, inner \
         edge {inner_edge:.4} m; the plain constraint's edge {plain_edge:.3} m (d), {inner_plain:.3} m (h)"
    );
    assert!(
        outer_edge < 0.08,
        "a kink at the ring's outer edge: {outer_edge} m"
    );
    assert!(
        inner_edge < 0.08,
        "a kink at the ring's inner edge: {inner_edge} m"
    );
    assert!(
        plain_edge > 1.0,
        "the plain constraint shows no kink: {plain_edge} m"
    );
    // Across the ring the second difference changes smoothly: between neighbours by at most
    // the third derivative's bound A·max|S‴|/ring³ = 30·60/40³ ≈ 0.03 m plus the ground's share.
    let profile = d(&ring);
    let second: Vec<f64> = (1..profile.len() - 1)
        .filter(|&k| profile[k].0 > RADIUS_M + 1.0 && profile[k].0 < outer + 2.0)
        .map(|k| profile[k - 1].1 - 2.0 * profile[k].1 + profile[k + 1].1)
        .collect();
    let jump = second
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(0.0, f64::max);
    println!("largest change of the second difference across the ring: {jump:.4} m");
    assert!(jump < 0.1, "the second difference jumps by {jump} m");
}

#[test]
fn a_ring_is_refused_naming_the_field_and_the_limit() {
    let refuse = |op: serde_json::Value| {
        let element: strata::element::Element = serde_json::from_value(json!({"id": "r",
            "bbox": {"min": [1000, 2000], "max": [1128, 2128]}, "samples": 129, "ops": [op]}))
        .expect("element");
        strata::authoring::RegionSpec::from_element(&element).expect_err("refused")
    };
    let op = |ring: f64| {
        json!({"op": "elevation", "shape": {"point": CENTRE}, "elevation_m": 10,
            "radius_m": RADIUS_M, "ring_m": ring})
    };
    let e = refuse(op(3.0));
    assert_eq!(e.pointer, "/ops/0/ring_m");
    assert!(
        e.message.contains("at least 4 sample spacings") && e.message.contains("(4 m)"),
        "{}",
        e.message
    );
    let e = refuse(op(70.0));
    assert_eq!(e.pointer, "/ops/0/ring_m");
    assert!(
        e.message.contains("beyond the region's bbox"),
        "{}",
        e.message
    );
    let e = refuse(op(-1.0));
    assert_eq!(e.pointer, "/ops/0/ring_m");
    // Without the field the operation is the one stored worlds hold, and serialises as before.
    let _ = spec(
        129,
        json!([{"op": "elevation", "shape": {"point": CENTRE}, "elevation_m": 10}]),
    );
    let parsed: strata::authoring::Op = serde_json::from_value(
        json!({"op": "elevation", "shape": {"point": CENTRE}, "elevation_m": 10.0, "radius_m": 0.0}),
    )
    .expect("an op");
    assert!(!serde_json::to_string(&parsed)
        .expect("json")
        .contains("ring_m"));
}
