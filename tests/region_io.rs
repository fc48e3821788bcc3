//! Import and export of authored regions over HTTP (issue 4, item 4): the PNG16 heightmap and
//! the gradient map out of a region, and a PNG16 heightmap pasted in, driven through
//! `strata::server::app` with `tower::ServiceExt::oneshot` on a SQLite store in a temporary
//! directory.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::sync::Arc;
use strata::authoring::exchange::{encode_png16, import_gradient_map, import_png16};
use strata::authoring::{solve_region, RegionSpec};
use strata::compute::Compute;
use strata::scene::Scene;
use strata::server::{app, AppState};
use strata::store::SqliteStore;
use strata::terrain::poisson::gradient::extract_samples;
use strata::terrain::poisson::GridSpec;
use strata::terrain::WorldPlan;
mod common;

use common::oneshot::{send, Reply};

const ADMIN: &str = "server-admin-token-for-tests";
const SEED: u64 = 42;

struct World {
    app: Router,
    id: String,
    token: String,
    _dir: tempfile::TempDir,
}

impl World {
    /// A world of seed [`SEED`] with the given regions.
    async fn new(regions: Value) -> Self {
        let dir = tempfile::tempdir().expect("tmp");
        let store = Arc::new(SqliteStore::open_in_dir(dir.path()).expect("store"));
        let app = app(AppState::new(Compute::cpu()).with_worlds(store, Some(ADMIN)));
        let body = json!({"seed": SEED, "scene": {"regions": regions}});
        let r = send(
            &app,
            Method::POST,
            "/v1/worlds",
            &[
                ("authorization", format!("Bearer {ADMIN}")),
                ("content-type", "application/json".into()),
            ],
            Some(&serde_json::to_vec(&body).expect("json")),
        )
        .await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.json());
        let v = r.json();
        Self {
            app,
            id: v["id"].as_str().expect("id").into(),
            token: v["tokens"]["admin"].as_str().expect("token").into(),
            _dir: dir,
        }
    }

    async fn get(&self, path: &str) -> Reply {
        let uri = format!("/v1/worlds/{}{path}", self.id);
        let auth = [("authorization", format!("Bearer {}", self.token))];
        send(&self.app, Method::GET, &uri, &auth, None).await
    }

    async fn post_png(&self, path: &str, content_type: &str, body: Vec<u8>) -> Reply {
        self.post_png_if(path, content_type, body, None).await
    }

    /// As [`World::post_png`], with an `If-Match` header if given.
    async fn post_png_if(
        &self,
        path: &str,
        content_type: &str,
        body: Vec<u8>,
        if_match: Option<&str>,
    ) -> Reply {
        let uri = format!("/v1/worlds/{}{path}", self.id);
        let mut h = vec![
            ("authorization", format!("Bearer {}", self.token)),
            ("content-type", content_type.to_string()),
        ];
        if let Some(v) = if_match {
            h.push(("if-match", v.to_string()));
        }
        send(&self.app, Method::POST, &uri, &h, Some(&body)).await
    }
}

fn peak() -> Value {
    json!({"id": "peak", "bbox": {"min": [0.0, 0.0], "max": [128.0, 128.0]}, "samples": 65,
        "ops": [{"op": "crest", "points": [[10.0, 64.0], [118.0, 64.0]], "elevation_m": 300.0,
                 "slope_deg": 25.0, "width_m": 20.0}]})
}

/// The region solved directly (not through HTTP): heights `base + d`, metres.
fn solved_heights(region: &Value) -> (Vec<f32>, usize, f64) {
    let scene = Scene::from_value(&json!({"regions": [region]})).expect("scene");
    let spec = RegionSpec::from_element(&scene.regions[0]).expect("spec");
    let plan = WorldPlan::new(SEED, scene.world.clone()).expect("plan");
    let r = solve_region(&plan, &spec).expect("solved");
    let h = r.base.iter().zip(&r.d).map(|(b, d)| b + d).collect();
    (h, r.grid.n, r.grid.spacing_m)
}

fn number_header(r: &Reply, name: &str) -> f64 {
    r.header(name)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("header {name}"))
}

#[tokio::test]
async fn a_region_exports_its_heights_and_gradients_as_png16() {
    let w = World::new(json!([peak()])).await;
    let (want, n, spacing) = solved_heights(&peak());

    let r = w.get("/regions/peak/heightmap.png").await;
    r.ok();
    assert_eq!(r.header("content-type"), Some("image/png"));
    assert_eq!(r.header("x-strata-version"), Some("1"));
    let (lo, hi) = (
        number_header(&r, "x-strata-lo-m"),
        number_header(&r, "x-strata-hi-m"),
    );
    let img = import_png16(&r.body, lo, hi).expect("a PNG16 heightmap");
    assert_eq!((img.width, img.height), (n, n));
    // Within half a quantisation step of the region's own solve (plus f32 rounding).
    let step = (hi - lo) / 65535.0;
    let worst = img
        .values
        .iter()
        .zip(&want)
        .map(|(a, b)| f64::from((a - b).abs()))
        .fold(0.0, f64::max);
    println!(
        "heightmap.png: {n}², range {lo:.2}..{hi:.2} m, worst error {worst:.4} m (step {step:.4})"
    );
    assert!(worst <= 0.5 * step + 1e-3, "worst {worst} m, step {step}");
    assert!(hi >= 299.99, "the crest is the top: {hi}");

    let r = w.get("/regions/peak/gradients.png?v=1").await;
    r.ok();
    assert_eq!(r.header("content-type"), Some("image/png"));
    let m = number_header(&r, "x-strata-gradient-m") as f32;
    let map = import_gradient_map(&r.body, m).expect("a gradient map");
    let grid = GridSpec::new(n, n, spacing).expect("grid");
    let (mut sx, mut sz) = (vec![0.0; n * n], vec![0.0; n * n]);
    extract_samples(grid, &want, &mut sx, &mut sz);
    // One step of the paper's 16-bit encoding is m / 2^15; rounding errs by half of it, and
    // the f32 rounding of the two solves adds a little.
    let (dx, dz) = &map.values;
    let tol = m / 32768.0 + 1e-4;
    for (a, b) in sx.iter().chain(&sz).zip(dx.iter().chain(dz)) {
        assert!((a - b).abs() <= tol, "{a} vs {b} (m {m})");
    }
    // North of the crest the ground rises southward.
    assert!(dz[(32 - 4) * n + 32] > 0.2);

    // Errors name the field.
    w.get("/regions/nope/heightmap.png").await.error(
        StatusCode::NOT_FOUND,
        "not_found",
        Some("rid"),
    );
    w.get("/regions/peak/gradients.png?v=7").await.error(
        StatusCode::NOT_FOUND,
        "version_not_found",
        Some("v"),
    );
    w.get("/regions/peak/heightmap.png?v=x").await.error(
        StatusCode::BAD_REQUEST,
        "bad_version",
        Some("v"),
    );
    let anonymous = send(
        &w.app,
        Method::GET,
        &format!("/v1/worlds/{}/regions/peak/heightmap.png", w.id),
        &[] as &[(&str, &str)],
        None,
    )
    .await;
    assert!(
        anonymous.status == StatusCode::UNAUTHORIZED || anonymous.status == StatusCode::FORBIDDEN,
        "a private world's region needs a token: {}",
        anonymous.status
    );
}

/// A 65 × 65 heightmap: a ridge and a bump over a tilted plane, metres.
fn upload() -> Vec<f32> {
    let side = 65;
    (0..side * side)
        .map(|v| {
            let (x, z) = ((v % side) as f64 - 32.0, (v / side) as f64 - 32.0);
            let bump = 30.0 * (-(x * x + z * z) / 120.0).exp();
            let ridge = 12.0 * (-(x - z).powi(2) / 40.0).exp();
            (100.0 + 0.2 * x + bump + ridge) as f32
        })
        .collect()
}

#[tokio::test]
async fn an_uploaded_png16_is_pasted_and_the_region_takes_its_gradients() {
    let field = json!({"id": "field", "bbox": {"min": [0.0, 0.0], "max": [128.0, 128.0]},
        "samples": 65, "ops": []});
    let w = World::new(json!([peak(), field])).await;
    let png = encode_png16(65, 65, &upload()).expect("png");
    let path = format!(
        "/regions/field/heightmap.png?lo_m={}&hi_m={}",
        png.lo_m, png.hi_m
    );
    let r = w.post_png(&path, "image/png", png.bytes.clone()).await;
    r.ok();
    assert_eq!(r.json()["version"], 2);
    assert_eq!(r.json()["op"], 0);
    let scene = w.get("").await.json()["scene"].clone();
    let op = &scene["regions"][1]["ops"][0];
    assert_eq!(op["op"], "copy_paste");
    assert_eq!(
        op["heightmap"]["spacing_m"], 2.0,
        "the image spans the region"
    );
    assert_eq!(op["target"], json!([64.0, 64.0]));

    // The image spans the region sample for sample, so the pasted target gradient is the
    // image's on every edge, and the reconstruction's discrete Laplacian equals the image's at
    // every free sample (the blend toward the procedural border is harmonic).
    let r = w.get("/regions/field/heightmap.png?v=2").await;
    r.ok();
    let (lo, hi) = (
        number_header(&r, "x-strata-lo-m"),
        number_header(&r, "x-strata-hi-m"),
    );
    let out = import_png16(&r.body, lo, hi).expect("heightmap").values;
    let source = import_png16(&png.bytes, png.lo_m, png.hi_m)
        .expect("upload")
        .values;
    let n = 65;
    let lap = |h: &[f32], i: usize, j: usize| {
        let at = |i: usize, j: usize| f64::from(h[j * n + i]);
        at(i + 1, j) + at(i - 1, j) + at(i, j + 1) + at(i, j - 1) - 4.0 * at(i, j)
    };
    let mut worst: f64 = 0.0;
    let mut curvature: f64 = 0.0;
    for j in 1..n - 1 {
        for i in 1..n - 1 {
            worst = worst.max((lap(&out, i, j) - lap(&source, i, j)).abs());
            curvature = curvature.max(lap(&source, i, j).abs());
        }
    }
    let step = (hi - lo) / 65535.0;
    println!(
        "import: largest Laplacian mismatch {worst:.4} m (image's largest {curvature:.3} m, \
         export step {step:.4} m)"
    );
    // Five export samples, each off by half a step, plus the solver's tolerance.
    assert!(worst < 3.0 * step + 0.01, "Laplacian mismatch {worst} m");
    assert!(curvature > 1.0, "the image has relief: {curvature}");
    // The other region is untouched.
    let before = w.get("/regions/peak/heightmap.png?v=1").await.body;
    assert_eq!(w.get("/regions/peak/heightmap.png").await.body, before);
}

#[tokio::test]
async fn a_bad_upload_is_refused_naming_the_field() {
    let w = World::new(json!([peak()])).await;
    let png = encode_png16(65, 65, &upload()).expect("png");
    let path = "/regions/peak/heightmap.png";
    w.post_png(&format!("{path}?hi_m=1"), "image/png", png.bytes.clone())
        .await
        .error(StatusCode::BAD_REQUEST, "bad_parameter", Some("lo_m"));
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=x"),
        "image/png",
        png.bytes.clone(),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_parameter", Some("hi_m"));
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=1&target=5"),
        "image/png",
        png.bytes.clone(),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_parameter", Some("target"));
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=1"),
        "image/png",
        b"not a png".to_vec(),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_body", Some("body"));
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=1"),
        "application/json",
        png.bytes.clone(),
    )
    .await
    .error(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        Some("Content-Type"),
    );
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=1"),
        "image/png",
        vec![0; 400_000],
    )
    .await
    .error(
        StatusCode::PAYLOAD_TOO_LARGE,
        "payload_too_large",
        Some("body"),
    );
    // A scale out of range is refused by the scene's validation, naming the operation's field.
    w.post_png(
        &format!("{path}?lo_m=0&hi_m=1&scale=50"),
        "image/png",
        png.bytes.clone(),
    )
    .await
    .error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/regions/0/ops/1/scale"),
    );
    w.post_png(
        "/regions/nope/heightmap.png?lo_m=0&hi_m=1",
        "image/png",
        png.bytes.clone(),
    )
    .await
    .error(StatusCode::NOT_FOUND, "not_found", Some("rid"));
    // A stale or malformed If-Match is refused like an edit's.
    let ok_path = format!("{path}?lo_m=0&hi_m=1");
    w.post_png_if(&ok_path, "image/png", png.bytes.clone(), Some("\"7\""))
        .await
        .error(StatusCode::CONFLICT, "version_conflict", Some("If-Match"));
    w.post_png_if(&ok_path, "image/png", png.bytes.clone(), Some("seven"))
        .await
        .error(StatusCode::BAD_REQUEST, "bad_version", Some("If-Match"));
    // Nothing was committed.
    assert_eq!(w.get("").await.json()["version"], 1);
    // The current version is accepted.
    let r = w
        .post_png_if(&ok_path, "image/png", png.bytes, Some("1"))
        .await;
    r.ok();
    assert_eq!(r.json()["version"], 2);
}
