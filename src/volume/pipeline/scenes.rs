//! Reference scenes for tests and `strata bench volume`: an arch after the paper's Double Arch
//! (Fig. 13, here one arch of four curves over a flat heightfield) and an overhanging cliff
//! (Fig. 12's "edges of already existing cliffs overhanging": a stepped heightfield decorated
//! with four curves).

use super::curve::{ConstraintPoint, FeatureCurve};
use super::grid::Grid;
use super::proxy::Heightfield;
use super::region::{PipelineParams, Scene};

/// A seed curve through `points` whose ribbons face `normal` (projected perpendicular to the
/// tangent) with `width` metres per ribbon, flat, material `material`.
pub fn facing_curve(
    points: &[[f32; 3]],
    normal: [f32; 3],
    width: f32,
    material: u16,
) -> FeatureCurve {
    let mut c = FeatureCurve {
        control_points: points.to_vec(),
        constraints: Vec::new(),
        seed: true,
    };
    c.constraints = [0.0, 0.5, 1.0]
        .iter()
        .map(|&t| ConstraintPoint::facing(&c, t, normal, width, 0.0, 0.5, 0.5, material))
        .collect();
    c
}

/// A flat heightfield patch at `height` covering `[x0, x1] × [z0, z1]` with 2 m spacing.
pub fn flat_ground(height: f32, x0: f32, x1: f32, z0: f32, z1: f32) -> Heightfield {
    stepped_ground(|_| height, x0, x1, z0, z1)
}

/// A heightfield patch whose height depends on x only.
pub fn stepped_ground(h: impl Fn(f32) -> f32, x0: f32, x1: f32, z0: f32, z1: f32) -> Heightfield {
    let spacing = 2.0;
    let w = ((x1 - x0) / spacing).ceil() as usize + 1;
    let d = ((z1 - z0) / spacing).ceil() as usize + 1;
    let mut heights = Vec::with_capacity(w * d);
    for _ in 0..d {
        for i in 0..w {
            heights.push(h(x0 + spacing * i as f32));
        }
    }
    Heightfield {
        origin: [x0, z0],
        spacing,
        dims: [w, d],
        heights,
        alpha: 0.3,
        beta: 0.5,
        material: 0,
    }
}

/// The arch scene on a grid of `dims` samples scaled to a 64 × 32 × 48 m box (spacing
/// `64 / dims[0]` m): an arch spanning x from 6 to 58 m at z = 24 m over flat ground at y = 4 m,
/// modelled by its extrados (normals up/out), intrados (normals down/in) and two side curves
/// (normals ±z). The dead zone is 6 m: the legs are 11 m wide at the ground, and the heightfield
/// must not survive inside them (Fig. 6).
pub fn arch(dims: [usize; 3]) -> (Grid, Scene, PipelineParams) {
    let spacing = 64.0 / dims[0] as f32;
    let grid = Grid {
        dims,
        origin: [0.0; 3],
        spacing,
    };
    let z = 24.0;
    let p = |x: f32, y: f32, zz: f32| [x, y, zz];
    let extrados = facing_curve(
        &[
            p(6.0, 4.5, z),
            p(14.0, 22.0, z),
            p(24.0, 28.0, z),
            p(40.0, 28.0, z),
            p(50.0, 22.0, z),
            p(58.0, 4.5, z),
        ],
        [0.0, 1.0, 0.0],
        5.0,
        1,
    );
    let intrados = facing_curve(
        &[
            p(17.0, 4.5, z),
            p(21.0, 14.0, z),
            p(28.0, 18.0, z),
            p(36.0, 18.0, z),
            p(43.0, 14.0, z),
            p(47.0, 4.5, z),
        ],
        [0.0, -1.0, 0.0],
        5.0,
        2,
    );
    let mid = |zz: f32| {
        [
            p(11.5, 7.5, zz),
            p(17.5, 18.0, zz),
            p(26.0, 23.0, zz),
            p(38.0, 23.0, zz),
            p(46.5, 18.0, zz),
            p(52.5, 7.5, zz),
        ]
    };
    let front = facing_curve(&mid(z + 5.0), [0.0, 0.0, 1.0], 3.0, 1);
    let back = facing_curve(&mid(z - 5.0), [0.0, 0.0, -1.0], 3.0, 1);
    let scene = Scene {
        curves: vec![extrados, intrados, front, back],
        meshes: Vec::new(),
        heightfield: Some(flat_ground(4.0, -4.0, 68.0, -4.0, 68.0)),
    };
    let params = PipelineParams {
        dead_zone_m: 6.0,
        ..PipelineParams::default()
    };
    (grid, scene, params)
}

/// The overhang scene on a grid of `dims` samples scaled to a 48 × 40 × 32 m box: a cliff at
/// x = 16 m from the ground (y = 4 m) to a plateau (y = 26 m), whose top is extended by a
/// shelf reaching x ≈ 29 m with its underside at y ≈ 18 m. Default parameters.
pub fn overhang(dims: [usize; 3]) -> (Grid, Scene, PipelineParams) {
    let spacing = 48.0 / dims[0] as f32;
    let grid = Grid {
        dims,
        origin: [0.0; 3],
        spacing,
    };
    let along = |x: f32, y: f32| {
        [
            [x, y, -2.0],
            [x, y, 8.0],
            [x, y, 16.0],
            [x, y, 24.0],
            [x, y, 34.0],
        ]
    };
    let top = facing_curve(&along(21.0, 26.0), [0.0, 1.0, 0.0], 7.0, 1);
    let under = facing_curve(&along(24.0, 18.0), [0.0, -1.0, 0.0], 5.0, 2);
    let lip = facing_curve(&along(29.5, 22.0), [1.0, 0.0, 0.0], 3.5, 2);
    let face = facing_curve(&along(16.0, 12.5), [1.0, 0.0, 0.0], 8.0, 3);
    let scene = Scene {
        curves: vec![top, under, lip, face],
        meshes: Vec::new(),
        heightfield: Some(stepped_ground(
            |x| if x < 16.0 { 26.0 } else { 4.0 },
            -4.0,
            52.0,
            -4.0,
            36.0,
        )),
    };
    (grid, scene, PipelineParams::default())
}

/// The arch of [`arch`] as a `volumes` scene element (id `arch`, a 64 m × 48 m box from the
/// origin, 1 m spacing), its curves lifted so their feet stand on `ground` metres (the scene's
/// curves stand on `y = 4`): what the world tests and `strata bench serve` place on the ground.
pub fn arch_element(ground: f32) -> serde_json::Value {
    let (_, scene, _) = arch([64, 32, 48]);
    let mut curves = serde_json::to_value(&scene.curves).expect("curves serialise");
    for c in curves.as_array_mut().into_iter().flatten() {
        for p in c["control_points"].as_array_mut().into_iter().flatten() {
            let y = p[1].as_f64().unwrap_or(0.0);
            p[1] = serde_json::json!(y - 4.0 + f64::from(ground));
        }
    }
    serde_json::json!({"id": "arch", "bbox": {"min": [0, 0], "max": [64, 48]},
           "y_m": [ground - 12.0, ground + 36.0], "spacing_m": 1.0, "dead_zone_m": 6.0,
           "curves": curves})
}
