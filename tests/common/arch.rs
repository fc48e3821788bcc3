//! The arch volume element the world tests place on the ground (Becher's Double Arch idea, from
//! `strata::volume::pipeline::scenes::arch`).

use serde_json::{json, Value};
use strata::volume::pipeline::scenes;

/// The arch element (id `arch`, a 64 m × 48 m box from the origin, 1 m spacing), its curves
/// lifted so their feet stand on `ground` metres: the scene's curves stand on `y = 4`.
pub fn arch_element(ground: f32) -> Value {
    let (_, scene, _) = scenes::arch([64, 32, 48]);
    let mut curves = serde_json::to_value(&scene.curves).expect("curves");
    for c in curves.as_array_mut().expect("array") {
        for p in c["control_points"].as_array_mut().expect("points") {
            let y = p[1].as_f64().expect("y");
            p[1] = json!(y - 4.0 + f64::from(ground));
        }
    }
    json!({"id": "arch", "bbox": {"min": [0, 0], "max": [64, 48]},
           "y_m": [ground - 12.0, ground + 36.0], "spacing_m": 1.0, "dead_zone_m": 6.0,
           "curves": curves})
}
