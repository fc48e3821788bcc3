//! Tests of the landform, composite, tensor and copy-paste tools: each tool's defining property
//! checked on the solved region (region `[1000, 2000]–[1128, 2128]`, 1 m spacing at 129 samples).

use crate::{ground, height, plan, sample_at, solve};
use serde_json::json;
use strata::authoring::Displacement;

fn d_at(r: &Displacement, x: f64, z: f64) -> f64 {
    let (i, j) = sample_at(r, x, z);
    f64::from(r.d[j * r.grid.n + i])
}

#[test]
fn a_cliff_has_its_top_at_the_elevation_and_a_steep_face_downhill() {
    // The stroke heads east, so the face is on its right: south (+z).
    let top = ground(1064.0, 2064.0) + 18.0;
    let r = solve(
        json!([{"op": "cliff", "points": [[1020, 2064], [1108, 2064]],
        "top_elevation_m": top, "slope_deg": 60, "width_m": 12}]),
    );
    for x in [1040.0, 1064.0, 1090.0] {
        let (i, j) = sample_at(&r, x, 2064.0);
        assert!((height(&r, i, j) - top).abs() < 1e-3, "top edge at x = {x}");
        let face = height(&r, i, j) - height(&r, i, j + 6);
        let slope = (face / 6.0).atan().to_degrees();
        assert!(slope > 45.0, "face slope {slope:.1}° at x = {x}");
        let back = (height(&r, i, j) - height(&r, i, j - 6)).abs();
        let back = (back / 6.0).atan().to_degrees();
        assert!(
            back < slope,
            "the uphill side ({back:.1}°) is gentler than the face"
        );
    }
}

#[test]
fn a_river_has_its_bed_at_the_elevation_and_banks_rising_gently() {
    let bed = ground(1064.0, 2064.0) - 3.0;
    let r = solve(
        json!([{"op": "river", "points": [[1010, 2064], [1118, 2064]],
        "bed_elevation_m": bed, "bed_width_m": 4, "bank_slope_deg": 10, "bank_width_m": 20}]),
    );
    for x in [1040.0, 1064.0, 1090.0] {
        let (i, j) = sample_at(&r, x, 2064.0);
        for dj in [-2i64, -1, 0, 1, 2] {
            let h = height(&r, i, (j as i64 + dj) as usize);
            assert!((h - bed).abs() < 1e-3, "bed {h} at x = {x}, dz = {dj}");
        }
        for side in [-1i64, 1] {
            let at = |k: i64| height(&r, i, (j as i64 + side * k) as usize);
            assert!(
                at(4) > bed && at(10) > at(4),
                "bank rising at x = {x}, side {side}"
            );
            let slope = ((at(10) - at(2)) / 8.0).atan().to_degrees();
            assert!(
                (3.0..20.0).contains(&slope),
                "bank slope {slope:.1}° at x = {x}, side {side}"
            );
        }
    }
}

#[test]
fn free_crests_and_ravines_raise_and_lower_their_line_by_gradients_alone() {
    // Expected rise: tan(20°)·30 m·16/35 ≈ 5.0 m.
    let expected = 20f64.to_radians().tan() * 30.0 * 16.0 / 35.0;
    for (op, sign) in [("free_crest", 1.0), ("ravine", -1.0)] {
        let r = solve(json!([{"op": op, "points": [[1010, 2064], [1118, 2064]],
            "slope_deg": 20, "width_m": 30}]));
        assert!(!r
            .fixed
            .iter()
            .zip(&solve(json!([])).fixed)
            .any(|(a, b)| a != b));
        for x in [1050.0, 1064.0, 1080.0] {
            let rise = d_at(&r, x, 2064.0) - 0.5 * (d_at(&r, x, 2034.0) + d_at(&r, x, 2094.0));
            assert!(
                (0.6 * expected..1.3 * expected).contains(&(sign * rise)),
                "{op}: line {rise:.2} m relative to 30 m away at x = {x}, want ±{expected:.2}"
            );
        }
    }
}

#[test]
fn a_fault_steps_by_its_throw_and_crossing_faults_add() {
    // Fault A heads south along x = 1064 (its right is west); fault B heads east along
    // z = 2064 (its right is south).
    let a =
        json!({"op": "fault", "points": [[1064, 2008], [1064, 2120]], "throw_m": 6, "width_m": 10});
    let b =
        json!({"op": "fault", "points": [[1008, 2064], [1120, 2064]], "throw_m": 4, "width_m": 10});
    let ra = solve(json!([a.clone()]));
    let step = d_at(&ra, 1054.0, 2040.0) - d_at(&ra, 1074.0, 2040.0);
    assert!(
        (-7.0..-4.0).contains(&step),
        "west minus east across fault A: {step:.2} m, want about −6"
    );
    let rb = solve(json!([b.clone()]));
    let both = solve(json!([a, b]));
    let worst = (0..both.d.len())
        .map(|v| (f64::from(both.d[v]) - f64::from(ra.d[v]) - f64::from(rb.d[v])).abs())
        .fold(0.0, f64::max);
    assert!(
        worst < 0.05,
        "crossing faults superpose additively: worst mismatch {worst:.4} m"
    );
    // In the south-west quadrant both right sides drop. (With `d = 0` on the border, the
    // steps are taken up by a gentle counter-slope over the region: about throw/128 m per
    // metre, so 20 m apart the two steps are worth about 10 − 1.6 m.)
    let sw = d_at(&both, 1054.0, 2074.0) - d_at(&both, 1074.0, 2054.0);
    assert!(
        (-11.0..-6.5).contains(&sw),
        "south-west minus north-east: {sw:.2} m, want about −8.4"
    );
}

#[test]
fn a_mountain_range_stroke_raises_a_ridge_above_its_surroundings() {
    let r = solve(
        json!([{"op": "mountain_range", "points": [[1015, 2064], [1064, 2060], [1113, 2064]],
        "height_m": 10, "width_m": 20, "seed": 3}]),
    );
    for (x, z) in [(1040.0, 2062.0), (1064.0, 2060.0), (1088.0, 2062.0)] {
        let ridge = d_at(&r, x, z);
        let around = 0.5 * (d_at(&r, x, z - 28.0) + d_at(&r, x, z + 28.0));
        assert!(
            ridge - around > 6.0,
            "ridge {ridge:.2} m vs surroundings {around:.2} m at x = {x}"
        );
    }
    // Spurs: the range is more than a single free crest.
    let single = solve(
        json!([{"op": "free_crest", "points": [[1015, 2064], [1064, 2060], [1113, 2064]],
        "slope_deg": (10.0f64 / (20.0 * 16.0 / 35.0)).atan().to_degrees(), "width_m": 20}]),
    );
    let differ =
        r.d.iter()
            .zip(&single.d)
            .filter(|(a, b)| (**a - **b).abs() > 0.5)
            .count();
    assert!(
        differ > 200,
        "spurs change {differ} samples by more than 0.5 m"
    );
}

#[test]
fn a_mesa_is_flat_at_its_elevation_with_a_steep_rim() {
    let e = ground(1064.0, 2064.0) + 12.0;
    let r = solve(
        json!([{"op": "mesa", "center": [1064, 2064], "radius_m": 20,
        "elevation_m": e, "slope_deg": 60, "cliff_width_m": 9}]),
    );
    let n = r.grid.n;
    let mut plateau = 0;
    for j in 0..n {
        for i in 0..n {
            let p = r.grid.position(i, j);
            if (p[0] - 1064.0).hypot(p[1] - 2064.0) < 19.0 {
                assert!((height(&r, i, j) - e).abs() < 1e-3, "plateau at {p:?}");
                plateau += 1;
            }
        }
    }
    assert!(plateau > 1000, "{plateau} plateau samples");
    let (ci, cj) = sample_at(&r, 1064.0, 2064.0);
    for (di, dj) in [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)] {
        let at = |k: i64| {
            height(
                &r,
                (ci as i64 + di * k) as usize,
                (cj as i64 + dj * k) as usize,
            )
        };
        let slope = ((at(20) - at(25)) / 5.0).atan().to_degrees();
        assert!(slope > 40.0, "rim slope {slope:.1}° toward ({di}, {dj})");
    }
}

/// Pearson correlation of two series.
pub fn correlation(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    sab / (saa * sbb).sqrt()
}

/// Least-squares `v ≈ a + b·x + c·z`: `[a, b, c]` (normal equations, Cramer's rule).
pub fn affine_fit(p: &[[f64; 2]], v: &[f64]) -> [f64; 3] {
    let mut m = [[0.0f64; 3]; 3];
    let mut rhs = [0.0f64; 3];
    for (q, y) in p.iter().zip(v) {
        let row = [1.0, q[0], q[1]];
        for (mr, ra) in m.iter_mut().zip(row) {
            for (mc, rb) in mr.iter_mut().zip(row) {
                *mc += ra * rb;
            }
        }
        for (r, ra) in rhs.iter_mut().zip(row) {
            *r += ra * y;
        }
    }
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    let mut out = [0.0; 3];
    for (c, o) in out.iter_mut().enumerate() {
        let mut a = m;
        for (row, r) in a.iter_mut().zip(rhs) {
            row[c] = r;
        }
        *o = det(a) / d;
    }
    out
}

/// How a pasted region's gradients match the source's over the core of the footprint (15 m
/// from its centre in source metres): correlation and gain against the mapped source gradients,
/// the unedited terrain's correlation, and how many samples were compared.
///
/// Poisson pasting keeps the copy's relief but reconciles its large-scale slope with the
/// surroundings: the heights are the copy's plus a harmonic correction, whose gradient over the
/// core is close to affine in position. So the gradients are compared with each component's
/// best affine fit in position removed.
pub fn paste_agreement(
    r: &Displacement,
    src: &strata::authoring::paste::PasteSource,
    at: &strata::authoring::paste::Placement,
) -> (f64, f64, f64, usize) {
    let h = r.grid.spacing_m;
    let (mut pasted, mut expected, mut before) = (Vec::new(), Vec::new(), Vec::new());
    let mut positions = Vec::new();
    let n = r.grid.n;
    for j in 1..n - 1 {
        for i in 1..n - 1 {
            let p = r.grid.position(i, j);
            // The core of the footprint: away from its boundary, where the blend acts.
            let (q, _) = at.source_of(src, p);
            if (q[0] - src.center[0]).abs() > 15.0 || (q[1] - src.center[1]).abs() > 15.0 {
                continue;
            }
            let read = |dx: f64, dz: f64| src.height(at.source_of(src, [p[0] + dx, p[1] + dz]).0);
            expected.push((read(h, 0.0) - read(-h, 0.0)) / (2.0 * h));
            expected.push((read(0.0, h) - read(0.0, -h)) / (2.0 * h));
            pasted.push((height(r, i + 1, j) - height(r, i - 1, j)) / (2.0 * h));
            pasted.push((height(r, i, j + 1) - height(r, i, j - 1)) / (2.0 * h));
            positions.push([p[0] - at.target[0], p[1] - at.target[1]]);
            let v = j * n + i;
            before.push((f64::from(r.base[v + 1]) - f64::from(r.base[v - 1])) / (2.0 * h));
            before.push((f64::from(r.base[v + n]) - f64::from(r.base[v - n])) / (2.0 * h));
        }
    }
    for series in [&mut pasted, &mut expected, &mut before] {
        for k in 0..2 {
            let values: Vec<f64> = series.iter().skip(k).step_by(2).copied().collect();
            let fit = affine_fit(&positions, &values);
            for (v, p) in series.iter_mut().skip(k).step_by(2).zip(&positions) {
                *v -= fit[0] + fit[1] * p[0] + fit[2] * p[1];
            }
        }
    }
    let c = correlation(&pasted, &expected);
    let c0 = correlation(&before, &expected);
    let gain = pasted
        .iter()
        .zip(&expected)
        .map(|(a, b)| a * b)
        .sum::<f64>()
        / expected.iter().map(|b| b * b).sum::<f64>();
    (c, gain, c0, pasted.len() / 2)
}

#[test]
fn copy_paste_reproduces_the_rotated_scaled_source_gradients() {
    use strata::authoring::paste::{PasteSource, Placement};
    let (min, max) = ([1500.0, 2500.0], [1560.0, 2560.0]);
    let at = Placement {
        target: [1064.0, 2064.0],
        rotation_deg: 30.0,
        scale: 1.25,
        warp: Default::default(),
    };
    let r = solve(
        json!([{"op": "copy_paste", "source_min": min, "source_max": max,
        "target": at.target, "rotation_deg": at.rotation_deg, "scale": at.scale}]),
    );
    let src = PasteSource::sample(&plan(), min, max, r.grid.spacing_m / at.scale);
    let (c, gain, c0, count) = paste_agreement(&r, &src, &at);
    println!(
        "copy-paste: {count} gradients, correlation {c:.3} (unedited {c0:.3}), gain {gain:.3}"
    );
    assert!(count > 1000, "{count} samples");
    assert!(c > 0.95, "correlation {c:.3}");
    assert!((0.85..1.15).contains(&gain), "gain {gain:.3}");
    assert!(c0 < c - 0.2, "the unedited terrain correlates {c0:.3}");
}

/// Mean |∂h/∂x| and |∂h/∂z| of the solved heights over those of the procedural heights, in a
/// 24 m square around the region's centre.
fn slope_ratios(r: &Displacement) -> [f64; 2] {
    let n = r.grid.n;
    let (ci, cj) = sample_at(r, 1064.0, 2064.0);
    let (mut proc, mut edited) = ([0.0; 2], [0.0; 2]);
    for j in cj - 12..cj + 12 {
        for i in ci - 12..ci + 12 {
            let v = j * n + i;
            for (k, u) in [(0, v + 1), (1, v + n)] {
                proc[k] += (f64::from(r.base[u]) - f64::from(r.base[v])).abs();
                edited[k] += (height(r, u % n, u / n) - height(r, i, j)).abs();
            }
        }
    }
    [edited[0] / proc[0], edited[1] / proc[1]]
}

#[test]
fn a_directional_tensor_steepens_slopes_along_its_direction_and_flattens_them_across() {
    // θ = 0 (along x), μ = 0.6: the target scales ∂h/∂x by 1.6 and ∂h/∂z by 0.4.
    let r = solve(
        json!([{"op": "directional_tensor", "center": [1064, 2064], "radius_m": 40,
        "angle_deg": 0, "strength": 0.6}]),
    );
    let [along, across] = slope_ratios(&r);
    println!("directional tensor μ 0.6: slope ratio along {along:.2}, across {across:.2}");
    assert!((1.15..1.7).contains(&along), "along {along:.2}");
    assert!((0.3..0.85).contains(&across), "across {across:.2}");
    // A stroke heading east does the same.
    let r = solve(
        json!([{"op": "stroke_tensor", "points": [[1010, 2064], [1118, 2064]],
        "radius_m": 60, "strength": 0.9}]),
    );
    let [along, across] = slope_ratios(&r);
    println!("stroke tensor μ 0.9: slope ratio along {along:.2}, across {across:.2}");
    // The stroke's weight varies across it, so the scaled field has curl and the solve meets
    // the amplification less than the reduction.
    assert!(
        along > 1.05 && across < 0.75 && along - across > 0.4,
        "stroke: along {along:.2}, across {across:.2}"
    );
}

#[test]
fn erosion_keeps_the_constraints_and_wears_the_peak_down() {
    let e = ground(1064.0, 2064.0) + 25.0;
    let before = json!([
        {"op": "elevation", "shape": {"point": [1050, 2050]}, "elevation_m": e - 15.0, "radius_m": 1},
        {"op": "mesa", "center": [1080, 2080], "radius_m": 5, "elevation_m": e, "slope_deg": 70, "cliff_width_m": 6},
        {"op": "noise", "center": [1064, 2064], "radius_m": 50, "amplitude_m": 4, "wavelength_m": 6}
    ]);
    let mut eroded_ops = before.as_array().expect("array").clone();
    eroded_ops.push(json!({"op": "erosion", "center": [1064, 2064], "radius_m": 45, "talus_deg": 20, "iterations": 200}));
    let plain = solve(before);
    let eroded = solve(serde_json::Value::Array(eroded_ops));
    assert_eq!(plain.fixed, eroded.fixed, "the same samples are fixed");
    for (v, fixed) in plain.fixed.iter().enumerate() {
        if *fixed {
            assert_eq!(plain.d[v], eroded.d[v], "fixed sample {v} moved");
        }
    }
    // Roughness (mean |discrete Laplacian|) and the highest sample inside the brush, at least
    // 12 m from the constraints.
    let n = plain.grid.n;
    let measure = |r: &Displacement| {
        let (ci, cj) = sample_at(r, 1064.0, 2064.0);
        let (mut rough, mut count, mut top, mut steep) = (0.0, 0.0, f64::MIN, 0.0);
        for j in cj - 25..cj + 25 {
            for i in ci - 25..ci + 25 {
                let lap = height(r, i + 1, j)
                    + height(r, i - 1, j)
                    + height(r, i, j + 1)
                    + height(r, i, j - 1)
                    - 4.0 * height(r, i, j);
                rough += lap.abs();
                let slope = (height(r, i + 1, j) - height(r, i, j)).abs() / r.grid.spacing_m;
                if slope > 25f64.to_radians().tan() {
                    steep += 1.0;
                }
                count += 1.0;
                let p = r.grid.position(i, j);
                let clear = [[1050.0, 2050.0], [1080.0, 2080.0]]
                    .iter()
                    .all(|c: &[f64; 2]| (p[0] - c[0]).hypot(p[1] - c[1]) > 12.0);
                if clear && !r.fixed[j * n + i] {
                    top = top.max(height(r, i, j));
                }
            }
        }
        (rough / count, top, steep / count)
    };
    let (rough0, top0, steep0) = measure(&plain);
    let (rough1, top1, steep1) = measure(&eroded);
    println!(
        "erosion: roughness {rough0:.3} → {rough1:.3} m, highest free sample {top0:.2} → \
         {top1:.2} m, share of x-edges steeper than 25° {steep0:.3} → {steep1:.3}"
    );
    assert!(
        steep1 < 0.5 * steep0,
        "steep share {steep0:.3} → {steep1:.3}"
    );
    assert!(top1 < top0 - 0.5, "peak {top0:.2} → {top1:.2}");
    // The brush is local: beyond its radius the heights stay as they were, up to the solver's
    // tolerance (relative residual 1e-6, a few millimetres here), and the material it moved
    // stays inside (thermal steps conserve it).
    let (mut outside, mut net, mut moved) = (0.0f64, 0.0f64, 0.0f64);
    for v in 0..n * n {
        let delta = f64::from(eroded.d[v] - plain.d[v]);
        let p = plain.grid.position(v % n, v / n);
        if (p[0] - 1064.0).hypot(p[1] - 2064.0) > 46.0 {
            outside = outside.max(delta.abs());
        }
        net += delta;
        moved += delta.abs();
    }
    println!(
        "erosion: moved {moved:.1} m·samples, net {net:.3}, largest change outside {outside:.2e} m"
    );
    assert!(
        outside < 5e-3,
        "the brush moved the heights outside it by {outside} m"
    );
    assert!(net.abs() < 1e-2 * moved, "net {net} of {moved}");
}

#[test]
fn a_painted_region_holds_its_elevation_inside_and_nowhere_else() {
    let e = ground(1064.0, 2064.0) + 12.0;
    let poly = [
        [1040.0, 2040.0],
        [1090.0, 2045.0],
        [1080.0, 2090.0],
        [1045.0, 2080.0],
    ];
    let r = solve(
        json!([{"op": "elevation", "shape": {"region": poly}, "elevation_m": e,
                          "radius_m": 0}]),
    );
    let n = r.grid.n;
    let (mut inside, mut outside_moved) = (0, 0);
    for j in 0..n {
        for i in 0..n {
            let p = r.grid.position(i, j);
            if strata::authoring::raster::inside_polygon(&poly, p) {
                inside += 1;
                assert!((height(&r, i, j) - e).abs() < 1e-3, "inside at {p:?}");
            } else if (height(&r, i, j) - e).abs() < 1e-3 && !r.fixed[j * n + i] {
                outside_moved += 1;
            }
        }
    }
    assert!(inside > 1500, "{inside} samples painted");
    assert!(
        outside_moved < inside / 20,
        "{outside_moved} free samples sit at the elevation"
    );
    // Refused: fewer than three points, or one elevation per point.
    let bad = |ops: serde_json::Value| {
        strata::authoring::RegionSpec::from_element(
            &serde_json::from_value(json!({"id": "r",
                "bbox": {"min": [1000, 2000], "max": [1128, 2128]}, "ops": ops}))
            .expect("element"),
        )
        .expect_err("refused")
        .pointer
    };
    assert_eq!(
        bad(
            json!([{"op": "elevation", "shape": {"region": [[1010, 2010], [1020, 2010]]},
                    "elevation_m": 1}])
        ),
        "/ops/0/shape/region"
    );
    assert_eq!(
        bad(json!([{"op": "elevation", "shape": {"region": poly}, "elevations_m": [1, 2, 3, 4]}])),
        "/ops/0/elevations_m"
    );
}

/// Mean slope (degrees, positive rising) from `(i, j)` over `k` samples along `(di, dj)`.
fn slope_along(r: &Displacement, i: usize, j: usize, di: i64, dj: i64, k: i64) -> f64 {
    let (a, b) = (
        height(r, i, j),
        height(
            r,
            (i as i64 + di * k) as usize,
            (j as i64 + dj * k) as usize,
        ),
    );
    let run = (k as f64) * r.grid.spacing_m * ((di * di + dj * dj) as f64).sqrt();
    ((b - a) / run).atan().to_degrees()
}

#[test]
fn a_curve_gradient_constraint_gives_each_side_its_slope() {
    // The stroke heads east: its left is north (−z), its right south (+z).
    let r = solve(
        json!([{"op": "slope_curve", "points": [[1010, 2064], [1118, 2064]],
                          "slope_left_deg": 10, "slope_right_deg": 35, "width_m": 24}]),
    );
    let flat = solve(json!([]));
    for x in [1040.0, 1064.0, 1090.0] {
        let (i, j) = sample_at(&r, x, 2064.0);
        // Falling away from the curve: a negative slope going outward, over the inner part of
        // the band where the constraint has full weight.
        let right = -slope_along(&r, i, j + 2, 0, 1, 10);
        let left = -slope_along(&r, i, j - 2, 0, -1, 10);
        let right0 = -slope_along(&flat, i, j + 2, 0, 1, 10);
        println!(
            "slope_curve at x = {x}: left {left:.1}°, right {right:.1}° (unedited {right0:.1}°)"
        );
        assert!(
            (right - 35.0).abs() < 3.0,
            "right side {right:.1}° at x = {x}"
        );
        assert!((left - 10.0).abs() < 3.0, "left side {left:.1}° at x = {x}");
    }
}

#[test]
fn a_point_gradient_constraint_sets_the_slope_and_direction_at_its_centre() {
    // 25° rising toward +z (direction 90°).
    let r = solve(
        json!([{"op": "slope_point", "center": [1064, 2064], "radius_m": 16,
                          "slope_deg": 25, "direction_deg": 90}]),
    );
    let (i, j) = sample_at(&r, 1064.0, 2064.0);
    let along = slope_along(&r, i, j - 2, 0, 1, 4);
    let across = slope_along(&r, i - 2, j, 1, 0, 4);
    println!("slope_point: {along:.1}° along +z, {across:.1}° across");
    assert!(
        (along - 25.0).abs() < 5.0,
        "{along:.1}° along the direction"
    );
    assert!(across.abs() < 8.0, "{across:.1}° across it");
}
