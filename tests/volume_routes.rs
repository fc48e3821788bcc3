//! Volume-region routes and inputs (issue 5, "input meshes uploaded as glTF/glb" and "Exports"):
//! a glb mesh (uploaded or inline base64, with a node transform) solves to the same region as the
//! same triangles inline; the region's whole mesh as glb passes the Khronos glTF validator; the
//! curves go out and back in as JSON through a versioned, If-Match-checked scene edit; bad
//! input is refused with the field named.

use axum::http::{header, Method, StatusCode};
use axum::Router;
use base64::Engine as _;
use serde_json::{json, Value};
use strata::compute::Compute;
use strata::edits::{synthesize, TileEdits};
use strata::scene::{Element, Scene};
use strata::server::{app, AppState};
use strata::terrain::{TileKey, WorldParams, WorldPlan};
use strata::volume::element::{solve_volume, VolumeSpec};
use strata::volume::mesh_import::{triangles_to_glb, write_glb, Mat4, IDENTITY};

mod common;

const SEED: u64 = 7;

async fn send(
    app: &Router,
    method: Method,
    uri: &str,
    headers: &[(&str, &str)],
    body: Vec<u8>,
) -> (StatusCode, axum::http::HeaderMap, Vec<u8>) {
    let r = common::oneshot::send(app, method, uri, headers, Some(&body)).await;
    (r.status, r.headers, r.body)
}

fn json_of(body: &[u8]) -> Value {
    serde_json::from_slice(body)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(body)))
}

fn field_of(body: &[u8]) -> Value {
    json_of(body)["error"]["field"].clone()
}

/// Creates a public world with `scene`; returns its id and admin token.
async fn create(app: &Router, scene: Value) -> (String, String) {
    let body = json!({ "seed": SEED, "public": true, "scene": scene });
    let (s, _, b) = send(
        app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "application/json")],
        body.to_string().into_bytes(),
    )
    .await;
    assert_eq!(s, StatusCode::CREATED, "{}", String::from_utf8_lossy(&b));
    let doc = json_of(&b);
    (
        doc["id"].as_str().expect("id").to_string(),
        doc["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}

fn ground_at(x: i64, z: i64) -> f32 {
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let t = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[(z * 65 + x) as usize]
}

/// The unit cube `[-1, 1]³` as 12 triangles, counter-clockwise seen from outside.
fn unit_cube() -> Vec<[[f32; 3]; 3]> {
    let v = [
        [-1.0, -1.0, -1.0],
        [1.0, -1.0, -1.0],
        [1.0, 1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
        [1.0, -1.0, 1.0],
        [1.0, 1.0, 1.0],
        [-1.0, 1.0, 1.0],
    ];
    let idx: [[usize; 3]; 12] = [
        [0, 3, 2],
        [0, 2, 1],
        [4, 5, 6],
        [4, 6, 7],
        [0, 1, 5],
        [0, 5, 4],
        [3, 7, 6],
        [3, 6, 2],
        [0, 4, 7],
        [0, 7, 3],
        [1, 2, 6],
        [1, 6, 5],
    ];
    idx.iter().map(|t| t.map(|i| v[i])).collect()
}

/// A box with a floating cube (6 m half side, centre `c`) and no curves.
fn cube_element(ground: f32, meshes: Value) -> Value {
    json!({"id": "cube", "bbox": {"min": [0, 0], "max": [48, 48]},
           "y_m": [ground - 8.0, ground + 32.0], "spacing_m": 1.0, "dead_zone_m": 3.0,
           "meshes": meshes})
}

fn cube_placement(ground: f32) -> Mat4 {
    let mut m = IDENTITY;
    m[0] = 6.0;
    m[5] = 6.0;
    m[10] = 6.0;
    m[12] = 24.0;
    m[13] = ground + 16.0;
    m[14] = 24.0;
    m
}

fn solve(element: &Value) -> Vec<f32> {
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let e: Element = serde_json::from_value(element.clone()).expect("element");
    let spec = VolumeSpec::from_element(&e).expect("valid element");
    solve_volume(&plan, &spec, &TileEdits::default())
        .expect("solved")
        .fields
        .surface
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_uploaded_glb_solves_like_the_same_triangles_inline() {
    let ground = ground_at(24, 24);
    let m = cube_placement(ground);
    // The cube placed by hand: 6·p + t, exactly what the node matrix computes.
    let placed: Vec<[[f32; 3]; 3]> = unit_cube()
        .iter()
        .map(|t| t.map(|p| [6.0 * p[0] + m[12], 6.0 * p[1] + m[13], 6.0 * p[2] + m[14]]))
        .collect();
    let glb = triangles_to_glb(&unit_cube(), Some(&m));
    let inline = cube_element(ground, json!([{ "triangles": placed, "material": 3 }]));
    let app = app(AppState::new(Compute::cpu()));
    let (id, token) = create(
        &app,
        json!({ "volumes": [cube_element(ground, json!([]))] }),
    )
    .await;
    let auth = format!("Bearer {token}");
    // Upload the glb as version 2.
    let (s, h, b) = send(
        &app,
        Method::POST,
        &format!("/v1/worlds/{id}/volumes/cube/meshes?material=3"),
        &[
            ("authorization", &auth),
            ("content-type", "model/gltf-binary"),
            ("if-match", "\"1\""),
        ],
        glb.clone(),
    )
    .await;
    assert_eq!(s, StatusCode::CREATED, "{}", String::from_utf8_lossy(&b));
    let doc = json_of(&b);
    assert_eq!(doc["version"], 2);
    assert_eq!(doc["mesh"], 0);
    assert_eq!(doc["triangles"], 12);
    assert_eq!(h["x-strata-version"], "2");
    // The stored element solves to the same region as the inline triangles, bit for bit.
    let (_, _, b) = send(&app, Method::GET, &format!("/v1/worlds/{id}"), &[], vec![]).await;
    let stored = json_of(&b)["scene"]["volumes"][0].clone();
    assert!(stored["meshes"][0]["glb_base64"].is_string());
    let (with_glb, with_inline) = (solve(&stored), solve(&inline));
    assert!(
        with_glb == with_inline,
        "uploaded glb and inline triangles differ"
    );
    let without = solve(&cube_element(ground, json!([])));
    assert!(with_glb != without, "the cube changes the region");
    // The same glb inline as base64 in the element (no upload) solves the same too.
    let b64 = base64::engine::general_purpose::STANDARD.encode(&glb);
    let inline_glb = cube_element(ground, json!([{ "glb_base64": b64, "material": 3 }]));
    assert!(solve(&inline_glb) == with_inline);
    // And the element transform is applied after the node's: the glb without its node matrix
    // but with the same placement as `transform`.
    let bare =
        base64::engine::general_purpose::STANDARD.encode(triangles_to_glb(&unit_cube(), None));
    let transformed = cube_element(
        ground,
        json!([{ "glb_base64": bare, "transform": m, "material": 3 }]),
    );
    assert!(solve(&transformed) == with_inline);
    // The exported meshes of both worlds have the same counts.
    let (id2, _) = create(&app, json!({ "volumes": [inline] })).await;
    let counts = |glb: &[u8]| {
        let len = u32::from_le_bytes(glb[12..16].try_into().expect("4")) as usize;
        let doc: Value = serde_json::from_slice(&glb[20..20 + len]).expect("glb JSON");
        let x = &doc["nodes"][0]["extras"];
        (x["vertex_count"].clone(), x["quad_count"].clone())
    };
    let (s, _, a) = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id}/volumes/cube/mesh.glb?v=2"),
        &[],
        vec![],
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    let (s, _, b) = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id2}/volumes/cube/mesh.glb?v=1"),
        &[],
        vec![],
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(counts(&a), counts(&b));
    assert!(counts(&a).1.as_u64().expect("quads") > 100);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_glb_is_refused_with_the_field_named() {
    let ground = ground_at(24, 24);
    let app = app(AppState::new(Compute::cpu()));
    let (id, token) = create(
        &app,
        json!({ "volumes": [cube_element(ground, json!([]))] }),
    )
    .await;
    let auth = format!("Bearer {token}");
    let upload = |uri: String, ct: &'static str, body: Vec<u8>| {
        let (app, auth) = (app.clone(), auth.clone());
        async move {
            send(
                &app,
                Method::POST,
                &uri,
                &[("authorization", &auth), ("content-type", ct)],
                body,
            )
            .await
        }
    };
    let good = triangles_to_glb(&unit_cube(), Some(&cube_placement(ground)));
    let uri = format!("/v1/worlds/{id}/volumes/cube/meshes");
    let (s, _, b) = upload(
        uri.clone(),
        "model/gltf-binary",
        b"glTF but not really".to_vec(),
    )
    .await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "body");
    let mut cut = good.clone();
    cut.truncate(good.len() - 16);
    let (s, _, b) = upload(uri.clone(), "model/gltf-binary", cut).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "body");
    let (s, _, b) = upload(uri.clone(), "application/json", good.clone()).await;
    assert_eq!(s, StatusCode::UNSUPPORTED_MEDIA_TYPE);
    assert_eq!(field_of(&b), "Content-Type");
    let (s, _, b) = upload(format!("{uri}?alpha=x"), "model/gltf-binary", good.clone()).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "alpha");
    let (s, _, b) = upload(
        format!("/v1/worlds/{id}/volumes/nope/meshes"),
        "model/gltf-binary",
        good.clone(),
    )
    .await;
    assert_eq!(s, StatusCode::NOT_FOUND);
    assert_eq!(field_of(&b), "vid");
    // Too many triangles for the element (65 536 in all): one triangle indexed 65 537 times.
    let mut bin: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|f| f.to_le_bytes())
        .collect();
    let n = 3 * 65_537usize;
    bin.extend((0..n).flat_map(|i| ((i % 3) as u16).to_le_bytes()));
    let doc = json!({
        "asset": { "version": "2.0" }, "scene": 0, "scenes": [{ "nodes": [0] }],
        "nodes": [{ "mesh": 0 }],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "indices": 1 }] }],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3" },
            { "bufferView": 1, "componentType": 5123, "count": n, "type": "SCALAR" }],
        "bufferViews": [{ "buffer": 0, "byteOffset": 0, "byteLength": 36 },
                        { "buffer": 0, "byteOffset": 36, "byteLength": 2 * n }],
        "buffers": [{ "byteLength": bin.len() }],
    });
    let many = write_glb(&doc, &bin);
    assert!(many.len() < 512 * 1024);
    let (s, _, b) = upload(uri.clone(), "model/gltf-binary", many).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "body");
    assert!(json_of(&b)["error"]["message"]
        .as_str()
        .expect("message")
        .contains("65536"));
    // Nothing was committed.
    let (_, h, _) = send(&app, Method::GET, &format!("/v1/worlds/{id}"), &[], vec![]).await;
    assert_eq!(h["x-strata-version"], "1");
    // Inline: a bad base64 glb and a bad transform name their pointers.
    let scene =
        |meshes: Value| Scene::from_value(&json!({ "volumes": [cube_element(ground, meshes)] }));
    let e = scene(json!([{ "glb_base64": "AAAA" }])).expect_err("bad glb");
    assert_eq!(e.pointer, "/volumes/0/meshes/0/glb_base64");
    let e = scene(json!([{ "triangles": [], "glb_base64": "AAAA" }])).expect_err("both");
    assert_eq!(e.pointer, "/volumes/0/meshes/0");
    let b64 = base64::engine::general_purpose::STANDARD.encode(&good);
    let e = scene(json!([{ "triangles": [] }, { "glb_base64": b64, "transform": vec![0; 16] }]))
        .expect_err("singular transform");
    assert_eq!(e.pointer, "/volumes/0/meshes/1/transform");
    scene(json!([{ "triangles": [] }, { "glb_base64": b64 }])).expect("valid");
    let e = Scene::from_value(&json!({ "volumes": [{
        "id": "v", "bbox": {"min": [0, 0], "max": [8, 8]}, "y_m": [0, 8],
        "expand_curves": { "step_m": 0 } }] }))
    .expect_err("expansion settings");
    assert_eq!(e.pointer, "/volumes/0/expand_curves/step_m");
}

/// Uploads without `If-Match` that race each other all land: none replaces another's mesh
/// (the first upload creates the element's `meshes` list, so a patch built from a stale read
/// would overwrite the list), and each answer names the index its mesh really has.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_uploads_without_if_match_all_land_at_their_reported_index() {
    let ground = ground_at(24, 24);
    let app = app(AppState::new(Compute::cpu()));
    let (id, token) = create(
        &app,
        json!({ "volumes": [common::arch::arch_element(ground)] }),
    )
    .await;
    let auth = format!("Bearer {token}");
    let upload = |material: u16| {
        let (app, auth, id) = (app.clone(), auth.clone(), id.clone());
        let glb = triangles_to_glb(&unit_cube(), Some(&cube_placement(ground)));
        async move {
            let (s, _, b) = send(
                &app,
                Method::POST,
                &format!("/v1/worlds/{id}/volumes/arch/meshes?material={material}"),
                &[
                    ("authorization", &auth),
                    ("content-type", "model/gltf-binary"),
                ],
                glb,
            )
            .await;
            assert_eq!(s, StatusCode::CREATED, "{}", String::from_utf8_lossy(&b));
            (material, json_of(&b))
        }
    };
    // Three contenders and three attempts each: every round commits at least one of them.
    let tasks = [1, 2, 3].map(|m| tokio::spawn(upload(m)));
    let mut answers = Vec::new();
    for t in tasks {
        answers.push(t.await.expect("upload task"));
    }
    let (_, _, body) = send(&app, Method::GET, &format!("/v1/worlds/{id}"), &[], vec![]).await;
    let doc = json_of(&body);
    assert_eq!(doc["version"], 4, "one version per upload");
    let meshes = doc["scene"]["volumes"][0]["meshes"].clone();
    assert_eq!(meshes.as_array().map(Vec::len), Some(3), "{meshes}");
    let mut versions = Vec::new();
    for (material, answer) in answers {
        let k = answer["mesh"].as_u64().expect("mesh index") as usize;
        assert_eq!(
            meshes[k]["material"], material,
            "upload {material} reported index {k}"
        );
        versions.push(answer["version"].as_u64().expect("version"));
    }
    versions.sort_unstable();
    assert_eq!(versions, [2, 3, 4]);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_region_mesh_glb_passes_the_khronos_validator() {
    let ground = ground_at(32, 24);
    let app = app(AppState::new(Compute::cpu()));
    let (id, _) = create(
        &app,
        json!({ "volumes": [common::arch::arch_element(ground)] }),
    )
    .await;
    let uri = format!("/v1/worlds/{id}/volumes/arch/mesh.glb?v=1");
    let (s, h, glb) = send(&app, Method::GET, &uri, &[], vec![]).await;
    assert_eq!(s, StatusCode::OK, "{}", String::from_utf8_lossy(&glb));
    assert_eq!(h[header::CONTENT_TYPE], "model/gltf-binary");
    assert!(h[header::CACHE_CONTROL]
        .to_str()
        .expect("cc")
        .contains("immutable"));
    let etag = h[header::ETAG].to_str().expect("etag").to_string();
    let (s, _, _) = send(&app, Method::GET, &uri, &[("if-none-match", &etag)], vec![]).await;
    assert_eq!(s, StatusCode::NOT_MODIFIED);
    // Errors: unknown volume, unknown version, bad version.
    for (u, status, field) in [
        (format!("/v1/worlds/{id}/volumes/nope/mesh.glb"), 404, "vid"),
        (
            format!("/v1/worlds/{id}/volumes/arch/mesh.glb?v=9"),
            404,
            "v",
        ),
        (
            format!("/v1/worlds/{id}/volumes/arch/mesh.glb?v=x"),
            400,
            "v",
        ),
    ] {
        let (s, _, b) = send(&app, Method::GET, &u, &[], vec![]).await;
        assert_eq!(s.as_u16(), status, "{u}");
        assert_eq!(field_of(&b), field, "{u}");
    }
    let reports = common::gltf::validate("volume-glb", &[("arch.glb".to_string(), glb)]);
    assert_eq!(reports.len(), 1);
    assert_eq!(reports[0]["errors"], 0, "validator errors: {}", reports[0]);
    let triangles = reports[0]["triangles"].as_u64().unwrap_or(0);
    assert!(
        triangles > 1000,
        "the arch region has a real mesh: {triangles}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn curves_round_trip_as_json_through_versioned_edits() {
    let ground = ground_at(32, 24);
    let app = app(AppState::new(Compute::cpu()));
    let element = common::arch::arch_element(ground);
    let (id, token) = create(&app, json!({ "volumes": [element.clone()] })).await;
    let auth = format!("Bearer {token}");
    let uri = format!("/v1/worlds/{id}/volumes/arch/curves.json");
    let (s, h, out) = send(&app, Method::GET, &uri, &[], vec![]).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(h[header::ETAG], "\"1\"");
    let doc = json_of(&out);
    assert_eq!(doc, json!({ "curves": element["curves"] }));
    let put = |body: Vec<u8>, if_match: &'static str| {
        let (app, auth, uri) = (app.clone(), auth.clone(), uri.clone());
        async move {
            send(
                &app,
                Method::PUT,
                &uri,
                &[
                    ("authorization", &auth),
                    ("content-type", "application/json"),
                    ("if-match", if_match),
                ],
                body,
            )
            .await
        }
    };
    // The same document back: a new version with the same curves.
    let (s, h, b) = put(out.clone(), "\"1\"").await;
    assert_eq!(s, StatusCode::OK, "{}", String::from_utf8_lossy(&b));
    assert_eq!(json_of(&b)["version"], 2);
    assert_eq!(h[header::ETAG], "\"2\"");
    let (_, _, again) = send(&app, Method::GET, &uri, &[], vec![]).await;
    assert_eq!(json_of(&again), doc);
    // A changed document: lift every curve by 2 m.
    let mut lifted = doc.clone();
    for c in lifted["curves"].as_array_mut().expect("curves") {
        for p in c["control_points"].as_array_mut().expect("points") {
            p[1] = json!(p[1].as_f64().expect("y") + 2.0);
        }
    }
    let (s, _, _) = put(lifted.to_string().into_bytes(), "\"2\"").await;
    assert_eq!(s, StatusCode::OK);
    let (_, _, now) = send(&app, Method::GET, &uri, &[], vec![]).await;
    assert_eq!(json_of(&now), lifted);
    let (_, _, old) = send(&app, Method::GET, &format!("{uri}?v=2"), &[], vec![]).await;
    assert_eq!(json_of(&old), doc, "earlier versions keep their curves");
    // A stale If-Match is a conflict; nothing is committed.
    let (s, _, b) = put(out.clone(), "\"2\"").await;
    assert_eq!(s, StatusCode::CONFLICT);
    assert_eq!(field_of(&b), "If-Match");
    // Invalid curves name the field inside the body.
    let mut bad = doc.clone();
    bad["curves"][2]["control_points"] = json!([[0, 0, 0]]);
    let (s, _, b) = put(bad.to_string().into_bytes(), "*").await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "/curves/2/control_points");
    let (s, _, b) = put(br#"{"curves": 3}"#.to_vec(), "*").await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(field_of(&b), "body");
    let (s, _, b) = send(
        &app,
        Method::PUT,
        &format!("/v1/worlds/{id}/volumes/nope/curves.json"),
        &[("authorization", &auth)],
        out.clone(),
    )
    .await;
    assert_eq!(s, StatusCode::NOT_FOUND);
    assert_eq!(field_of(&b), "vid");
    // Editing needs a token.
    let (s, _, _) = send(&app, Method::PUT, &uri, &[], out.clone()).await;
    assert!(
        s == StatusCode::UNAUTHORIZED || s == StatusCode::FORBIDDEN,
        "{s}"
    );
    let (_, h, _) = send(&app, Method::GET, &format!("/v1/worlds/{id}"), &[], vec![]).await;
    assert_eq!(h["x-strata-version"], "3");
}

#[test]
fn expand_curves_in_the_element_runs_the_expansion_stage() {
    let ground = ground_at(32, 24);
    let plain = common::arch::arch_element(ground);
    let mut expanded = plain.clone();
    expanded["expand_curves"] = json!({ "step_m": 0.5, "spacing_m": 2.0, "min_distance_m": 3.0 });
    let (a, b) = (solve(&plain), solve(&expanded));
    assert!(a != b, "the expanded curves change the region");
    assert!(b == solve(&expanded), "the stage is deterministic");
    assert!(b.iter().all(|s| s.is_finite()));
}
