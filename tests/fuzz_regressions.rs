//! Inputs found by fuzzing (`fuzz/`, README's testing section) that once cost far more than
//! their size, kept as tests so the bounds that fixed them stay.
//!
//! The glb reader (`volume::mesh_import`) was bounded by its file size, node visits and
//! triangle budget, yet a small file could still make it loop: a mesh of thousands of
//! primitives reached through thousands of node visits, each re-reading a large accessor while
//! yielding no triangle. Each case below is refused with an error naming its bound, and quickly.
//!
//! An edit's JSON Patch (`store::patch_scene`) panicked inside json-patch when an operation
//! failed after a `copy` to the end of an array, since its undo of the copy failed; a panic in
//! the store's writer is a 500 for an edit token holder's request.

use serde_json::json;
use std::time::{Duration, Instant};
use strata::scene::Scene;
use strata::store::{canonical_scene, patch_scene, StoreError};
use strata::volume::mesh_import::{
    glb_triangles, write_glb, MAX_ACCESSOR_ELEMENTS, MAX_NODE_VISITS, MAX_PRIMITIVE_VISITS,
};

/// Far more than any of these cases needs once bounded; the unbounded reader took minutes.
const QUICK: Duration = Duration::from_secs(5);

/// A glb whose node 0 has `visits` children, each node 1, which holds mesh 0 of `primitives`
/// primitives in `mode` that all read the POSITION accessor 0 of `positions` positions (at the
/// origin). With `one_index` each primitive also reads an index accessor of one index, so it
/// yields no triangle whatever its mode.
fn fan_out(
    visits: usize,
    primitives: usize,
    positions: usize,
    mode: u64,
    one_index: bool,
) -> Vec<u8> {
    let bin = vec![0u8; positions * 12 + 4];
    let n = bin.len();
    let mut primitive = json!({"attributes": {"POSITION": 0}, "mode": mode});
    if one_index {
        primitive["indices"] = json!(1);
    }
    let doc = json!({
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"children": vec![1; visits]}, {"mesh": 0}],
        "meshes": [{"primitives": vec![primitive; primitives]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": positions, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5121, "count": 1, "type": "SCALAR"}
        ],
        "bufferViews": [
            {"buffer": 0, "byteLength": positions * 12},
            {"buffer": 0, "byteOffset": positions * 12, "byteLength": 4}
        ],
        "buffers": [{"byteLength": n}],
    });
    write_glb(&doc, &bin)
}

fn refused_quickly(glb: &[u8], needle: &str) {
    let start = Instant::now();
    let err = glb_triangles(glb, None, 1 << 20).expect_err("the file is refused");
    assert!(err.0.contains(needle), "{err}");
    assert!(start.elapsed() < QUICK, "took {:?}", start.elapsed());
}

#[test]
fn thousands_of_primitives_under_thousands_of_visits_are_refused() {
    // Points (mode 0) yield no triangle and were skipped without counting.
    let visits = MAX_NODE_VISITS - 2;
    let primitives = MAX_PRIMITIVE_VISITS / visits + 1;
    let glb = fan_out(visits, primitives, 1, 0, false);
    refused_quickly(
        &glb,
        &format!("more than {MAX_PRIMITIVE_VISITS} mesh primitives"),
    );
}

#[test]
fn rereading_a_large_accessor_through_many_primitives_is_refused() {
    // Each primitive reads 16 positions and one index: 17 elements and no triangle, within the
    // primitive bound.
    let positions = 16;
    let reads = MAX_ACCESSOR_ELEMENTS / (positions + 1) + 1;
    let primitives = 64;
    assert!(reads <= MAX_PRIMITIVE_VISITS);
    let glb = fan_out(reads / primitives + 1, primitives, positions, 4, true);
    refused_quickly(
        &glb,
        &format!("more than {MAX_ACCESSOR_ELEMENTS} accessor elements"),
    );
    // One large accessor read through a few visits.
    let positions = 40_000;
    let glb = fan_out(MAX_ACCESSOR_ELEMENTS / positions + 1, 1, positions, 4, true);
    refused_quickly(
        &glb,
        &format!("more than {MAX_ACCESSOR_ELEMENTS} accessor elements"),
    );
}

#[test]
fn a_node_listing_itself_as_its_child_thousands_of_times_is_refused() {
    let doc = json!({
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"children": vec![0; 50_000]}],
    });
    refused_quickly(&write_glb(&doc, &[]), "node visits");
}

#[test]
fn a_mesh_within_every_bound_is_still_read() {
    // 3 positions, one triangle, under 1000 visits of one primitive each.
    let doc = json!({
        "asset": {"version": "2.0"},
        "nodes": [{"children": vec![1; 1000]}, {"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36}],
    });
    let mut bin = vec![0u8; 36];
    bin[12..16].copy_from_slice(&1f32.to_le_bytes());
    bin[28..32].copy_from_slice(&1f32.to_le_bytes());
    let glb = write_glb(&doc, &bin);
    assert_eq!(
        glb_triangles(&glb, None, 1 << 20).expect("read").len(),
        1000
    );
}

#[test]
fn a_failing_patch_after_a_copy_to_the_end_of_an_array_is_refused_without_a_panic() {
    let doc = canonical_scene(&json!({})).expect("a new scene");
    let old = Scene::from_value(&doc).expect("it parses");
    let patch: json_patch::Patch = serde_json::from_value(json!([
        {"op": "copy", "from": "/regions", "path": "/regions/-"},
        {"op": "move", "from": "/regions", "path": "/regi/regions/0/id"}
    ]))
    .expect("a JSON Patch");
    let err = patch_scene(doc, &old, &patch).expect_err("the second operation fails");
    assert!(
        matches!(err, StoreError::Patch { operation: 1, .. }),
        "{err:?}"
    );
}
