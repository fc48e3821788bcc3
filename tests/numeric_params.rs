//! Numeric path and query parameters at and beyond the limits of their integer types (issue 18,
//! finding 7): every one is refused with a 400 JSON error naming its own field and the limit,
//! never wrapped round into another tile's or chunk's data.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::sync::Arc;
use strata::compute::Compute;
use strata::server::{app, AppState};
use strata::subsurface::SubsurfaceConfig;
use strata::terrain::plan::TILE_QUADS;
use strata::terrain::{WorldParams, WorldPlan};

mod common;
use common::oneshot::{send, Reply};

const ADMIN: &str = "numeric-admin-token";
const SEED: u64 = 7;
const MIN: &str = "-9223372036854775808";
const MAX: &str = "9223372036854775807";

fn router(dir: &std::path::Path) -> Router {
    let store = strata::store::SqliteStore::open_in_dir(dir).expect("store");
    app(AppState::new(Compute::cpu()).with_worlds(Arc::new(store), Some(ADMIN)))
}

async fn request(app: &Router, method: Method, uri: &str, body: Option<Value>) -> Reply {
    let auth = format!("Bearer {ADMIN}");
    let mut headers = vec![("authorization", auth.as_str())];
    if body.is_some() {
        headers.push(("content-type", "application/json"));
    }
    let bytes = body.map(|b| b.to_string().into_bytes());
    send(app, method, uri, &headers, bytes.as_deref()).await
}

/// Asserts a 400 with `code` naming `field`, whose message states `limit`.
fn refused(r: &Reply, code: &str, field: &str, limit: &str) {
    r.error(StatusCode::BAD_REQUEST, code, Some(field));
    let message = r.json()["error"]["message"].to_string();
    assert!(
        message.contains(limit),
        "the message names the limit {limit}: {message}"
    );
}

#[tokio::test]
async fn integers_beyond_their_range_are_refused_naming_the_field() {
    let dir = tempfile::tempdir().expect("tempdir");
    let app = router(dir.path());
    let config = serde_json::to_value(SubsurfaceConfig::preset("B2").expect("B2")).expect("json");
    let strata = json!({"id": "rock", "bbox": {"min": [-3000, -3000], "max": [3000, 3000]},
                        "config": config, "voxel_m": 1.0});
    let r = request(
        &app,
        Method::POST,
        "/v1/worlds",
        Some(json!({"seed": SEED, "scene": {"strata": [strata]}})),
    )
    .await;
    r.status_is(StatusCode::CREATED);
    let id = r.json()["id"].as_str().expect("id").to_string();

    // Column chunks: i64::MIN used to pass `|x| ≤ limit` as a wrapped negative number and answer
    // chunk (0, 0)'s data.
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("plan");
    let world_m =
        plan.max_tile_coord(0) as f64 * TILE_QUADS as f64 * f64::from(plan.lods[0].spacing_m);
    for size in [1u32, 16] {
        let limit = ((world_m.min(1e9) / f64::from(size)).floor() - 1.0) as i64;
        let text = format!("at most {limit} column chunks");
        for (x, z, field) in [
            (MIN.to_string(), "0".to_string(), "x"),
            ("0".to_string(), MIN.to_string(), "z"),
            (MAX.to_string(), "0".to_string(), "x"),
            ((limit + 1).to_string(), "0".to_string(), "x"),
            ("0".to_string(), (-limit - 1).to_string(), "z"),
        ] {
            let uri = format!("/v1/worlds/{id}/columns/{x}/{z}.json?size={size}");
            let r = request(&app, Method::GET, &uri, None).await;
            refused(&r, "coordinate_out_of_range", field, &text);
        }
    }
    let r = request(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id}/columns/0/0.json?size=16"),
        None,
    )
    .await;
    r.ok();
    assert_eq!(r.json()["x"], 0);
    for size in ["4294967296", "-1", "0", "33"] {
        let uri = format!("/v1/worlds/{id}/columns/0/0.json?size={size}");
        let r = request(&app, Method::GET, &uri, None).await;
        refused(&r, "bad_parameter", "size", "1..=32");
    }

    // The edit log's limit is at most 1000, as documented.
    for limit in ["1001", "0", "18446744073709551616", "-1", "+5"] {
        let uri = format!("/v1/worlds/{id}/edits?limit={limit}");
        let r = request(&app, Method::GET, &uri, None).await;
        refused(&r, "bad_parameter", "limit", "1..=1000");
    }
    let r = request(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id}/edits?limit=1000"),
        None,
    )
    .await;
    r.ok();

    // Tiles, chunks and rivers of seeds and worlds.
    let max0 = plan.max_tile_coord(0).to_string();
    for uri in [
        format!("/v1/seeds/{SEED}/tiles/0/{MIN}/0.json"),
        format!("/v1/seeds/{SEED}/scatter/0/{MIN}/0.json"),
        format!("/v1/worlds/{id}/tiles/0/{MIN}/0.json"),
        format!("/v1/seeds/{SEED}/rivers/0/{MIN}/0.json"),
    ] {
        let r = request(&app, Method::GET, &uri, None).await;
        refused(&r, "coordinate_out_of_range", "x", &max0);
    }
    for uri in [
        format!("/v1/seeds/{SEED}/chunks/0/0/{MIN}/0.json"),
        format!("/v1/worlds/{id}/chunks/0/0/{MIN}/0.json"),
    ] {
        let r = request(&app, Method::GET, &uri, None).await;
        r.error(
            StatusCode::BAD_REQUEST,
            "coordinate_out_of_range",
            Some("y"),
        );
    }

    // An export region at the ends of i64 is refused naming its entry.
    for (region, field) in [
        (json!([i64::MIN, 0, 1, 1]), "/region/0"),
        (json!([0, 0, i64::MIN, 1]), "/region/2"),
        (json!([0, 0, 1, i64::MAX]), "/region/3"),
    ] {
        let body = json!({"lod": 0, "region": region, "products": ["tiles"], "formats": ["bin"]});
        let r = request(
            &app,
            Method::POST,
            &format!("/v1/worlds/{id}/exports"),
            Some(body),
        )
        .await;
        r.error(StatusCode::BAD_REQUEST, "invalid_export", Some(field));
    }
}
