//! An edit: a JSON Patch applied to a stored scene and the result validated, cost limits
//! included (`store::patch_scene`, what `POST /v1/worlds/{id}/edits` and stream edits commit).
//! Any bytes are refused or give a scene that parses again to the same document.
#![no_main]

use libfuzzer_sys::fuzz_target;
use serde_json::{json, Value};
use std::sync::OnceLock;
use strata::scene::Scene;
use strata::store::{canonical_scene, patch_scene};

/// A new world's scene with one small authored region, so patches can reach an element.
fn base() -> &'static (Value, Scene) {
    static BASE: OnceLock<(Value, Scene)> = OnceLock::new();
    BASE.get_or_init(|| {
        let doc = canonical_scene(&json!({
            "regions": [{
                "id": "peak",
                "bbox": {"min": [0, 0], "max": [256, 256]},
                "samples": 33,
                "ops": [{"op": "elevation", "shape": {"point": [128, 128]}, "elevation_m": 400, "radius_m": 6}]
            }]
        }))
        .expect("the base scene is valid");
        let scene = Scene::from_value(&doc).expect("the base scene parses");
        (doc, scene)
    })
}

fuzz_target!(|data: &[u8]| {
    let Ok(patch) = serde_json::from_slice::<json_patch::Patch>(data) else {
        return;
    };
    let (doc, old) = base();
    if let Ok((text, scene)) = patch_scene(doc.clone(), old, &patch) {
        let stored: Value = serde_json::from_str(&text).expect("the stored text is JSON");
        let again = Scene::from_value(&stored).expect("a stored scene parses again");
        assert_eq!(again.to_value(), scene.to_value());
    }
});
