//! Worlds, scenes, durable edits, versions and access, driven through `strata::server::app` with
//! `tower::ServiceExt::oneshot` (no socket) on a SQLite store in a temporary directory.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::sync::{Arc, Mutex};
use strata::compute::Compute;
use strata::scene::{Dirty, Rect, Scene};
use strata::server::{app, AppState};
use strata::store::{SceneStore, SqliteStore};
mod common;

use common::oneshot::{send, Reply};

const ADMIN: &str = "server-admin-token-for-tests";
const PATCH: &str = "application/json-patch+json";

fn auth(token: Option<&str>) -> Vec<(&'static str, String)> {
    token
        .map(|t| vec![("authorization", format!("Bearer {t}"))])
        .unwrap_or_default()
}

async fn get(app: &Router, uri: &str, token: Option<&str>) -> Reply {
    let h = auth(token);
    let h: Vec<(&str, &str)> = h.iter().map(|(k, v)| (*k, v.as_str())).collect();
    send(app, Method::GET, uri, &h, None).await
}

async fn post_json(app: &Router, uri: &str, token: Option<&str>, body: &Value) -> Reply {
    let mut h = auth(token);
    h.push(("content-type", "application/json".into()));
    let h: Vec<(&str, &str)> = h.iter().map(|(k, v)| (*k, v.as_str())).collect();
    let bytes = serde_json::to_vec(body).expect("json");
    send(app, Method::POST, uri, &h, Some(&bytes)).await
}

async fn edit(
    app: &Router,
    id: &str,
    token: Option<&str>,
    if_match: Option<&str>,
    patch: &Value,
) -> Reply {
    let mut h = auth(token);
    h.push(("content-type", PATCH.into()));
    if let Some(m) = if_match {
        h.push(("if-match", m.into()));
    }
    let h: Vec<(&str, &str)> = h.iter().map(|(k, v)| (*k, v.as_str())).collect();
    let bytes = serde_json::to_vec(patch).expect("json");
    send(
        app,
        Method::POST,
        &format!("/v1/worlds/{id}/edits"),
        &h,
        Some(&bytes),
    )
    .await
}

/// A created world: id and its admin token.
struct World {
    id: String,
    admin: String,
}

async fn create(app: &Router, token: Option<&str>, body: Value) -> World {
    let r = post_json(app, "/v1/worlds", token, &body).await;
    r.status_is(StatusCode::CREATED);
    let v = r.json();
    assert_eq!(v["version"], 1);
    let id = v["id"].as_str().expect("id").to_string();
    assert_eq!(
        r.header("location"),
        Some(format!("/v1/worlds/{id}").as_str())
    );
    World {
        id,
        admin: v["tokens"]["admin"]
            .as_str()
            .expect("admin token")
            .to_string(),
    }
}

fn add_region(id: &str, x: f64) -> Value {
    json!([{"op": "add", "path": "/regions/-", "value": {
        "id": id, "bbox": {"min": [x, 0.0], "max": [x + 10.0, 10.0]}, "ops": []}}])
}

fn store_in(dir: &std::path::Path) -> Arc<dyn SceneStore> {
    Arc::new(SqliteStore::open_in_dir(dir).expect("open store"))
}

fn service(dir: &std::path::Path, admin: Option<&str>) -> Router {
    app(AppState::new(Compute::cpu()).with_worlds(store_in(dir), admin))
}

#[tokio::test]
async fn create_edit_read_and_versions() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), Some(ADMIN));
    let w = create(&app, Some(ADMIN), json!({"seed": 42})).await;
    let tok = Some(w.admin.as_str());

    let r = get(&app, &format!("/v1/worlds/{}", w.id), tok).await;
    assert_eq!(r.status, StatusCode::OK);
    let v = r.json();
    assert_eq!(
        (v["seed"].clone(), v["version"].clone(), v["public"].clone()),
        (json!(42), json!(1), json!(false))
    );
    assert_eq!(
        v["scene"],
        Scene::default().to_value(),
        "a bare seed gets the default scene"
    );
    assert_eq!(r.header("etag"), Some("\"1\""));

    let r = edit(&app, &w.id, tok, Some("1"), &add_region("hill", 100.0)).await;
    r.ok();
    assert_eq!(r.json()["version"], 2);
    assert_eq!(
        r.json()["dirty"],
        json!({"kind": "rects", "rects": [{"min": [100.0, 0.0], "max": [110.0, 10.0]}]})
    );
    // Quoted If-Match, as the ETag gives it.
    let r = edit(&app, &w.id, tok, Some("\"2\""), &add_region("lake", 300.0)).await;
    assert_eq!(r.json()["version"], 3);

    let v = get(&app, &format!("/v1/worlds/{}", w.id), tok).await.json();
    assert_eq!(v["version"], 3);
    let ids: Vec<&str> = v["scene"]["regions"]
        .as_array()
        .expect("regions")
        .iter()
        .map(|r| r["id"].as_str().expect("id"))
        .collect();
    assert_eq!(ids, ["hill", "lake"]);

    for (version, n) in [(1, 0), (2, 1), (3, 2)] {
        let r = get(
            &app,
            &format!("/v1/worlds/{}/versions/{version}", w.id),
            tok,
        )
        .await;
        assert_eq!(r.status, StatusCode::OK);
        assert_eq!(r.json()["version"], version);
        assert_eq!(
            r.json()["scene"]["regions"]
                .as_array()
                .expect("regions")
                .len(),
            n
        );
        assert!(r
            .header("cache-control")
            .is_some_and(|c| c.contains("immutable") && c.starts_with("private")));
    }
    get(&app, &format!("/v1/worlds/{}/versions/4", w.id), tok)
        .await
        .error(StatusCode::NOT_FOUND, "version_not_found", Some("v"));
    get(&app, &format!("/v1/worlds/{}/versions/zero", w.id), tok)
        .await
        .error(StatusCode::BAD_REQUEST, "bad_version", Some("v"));

    let log = get(&app, &format!("/v1/worlds/{}/edits?after=1", w.id), tok)
        .await
        .json();
    let versions: Vec<u64> = log["edits"]
        .as_array()
        .expect("edits")
        .iter()
        .map(|e| e["version"].as_u64().expect("version"))
        .collect();
    assert_eq!(versions, [2, 3]);
    assert_eq!(log["edits"][0]["patch"], add_region("hill", 100.0));

    let list = get(&app, "/v1/worlds", Some(ADMIN)).await.json();
    assert_eq!(list["worlds"][0]["id"], w.id.as_str());
    assert_eq!(
        get(&app, "/v1/worlds", None).await.json()["worlds"],
        json!([])
    );
    get(&app, "/v1/worlds/doesnotexist", tok).await.error(
        StatusCode::NOT_FOUND,
        "world_not_found",
        Some("id"),
    );
}

#[tokio::test]
async fn region_stats_read_the_authored_heights() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), Some(ADMIN));
    let w = create(&app, Some(ADMIN), json!({"seed": 42})).await;
    let tok = Some(w.admin.as_str());
    let patch = json!([{"op": "add", "path": "/regions/-", "value": {
        "id": "peak", "bbox": {"min": [0.0, 0.0], "max": [128.0, 128.0]}, "samples": 65,
        "ops": [{"op": "elevation", "shape": {"point": [64.0, 64.0]}, "elevation_m": 333.0, "radius_m": 3.0}]}}]);
    assert_eq!(
        edit(&app, &w.id, tok, None, &patch).await.status,
        StatusCode::OK
    );
    let base = format!("/v1/worlds/{}/regions/peak/stats", w.id);

    let r = get(&app, &format!("{base}?point=64,64"), tok).await;
    r.ok();
    let s = &r.json()["stats"];
    let e = s["elevation_mean_m"].as_f64().expect("elevation");
    assert!((e - 333.0).abs() < 1e-3, "elevation at the constraint {e}");
    // Around the peak the slopes are real numbers of degrees, steepest at least the mean.
    let r = get(&app, &format!("{base}?rect=40,40;90,90&v=2"), tok).await;
    r.ok();
    let s = &r.json()["stats"];
    let (mean, steep) = (
        s["mean_slope_deg"].as_f64().expect("mean"),
        s["steepest_slope_deg"].as_f64().expect("steepest"),
    );
    assert!(mean > 1.0 && steep >= mean && steep < 90.0, "{s}");
    assert!(s["elevation_max_m"].as_f64() >= s["elevation_min_m"].as_f64());
    let r = get(&app, &format!("{base}?polyline=10,64;64,64;120,64"), tok).await;
    assert_eq!(r.status, StatusCode::OK);

    get(&app, &format!("{base}?point=abc"), tok).await.error(
        StatusCode::BAD_REQUEST,
        "bad_coordinate",
        Some("point"),
    );
    get(&app, &base, tok)
        .await
        .error(StatusCode::BAD_REQUEST, "bad_coordinate", Some("point"));
    get(&app, &format!("{base}?rect=1,2"), tok).await.error(
        StatusCode::BAD_REQUEST,
        "bad_coordinate",
        Some("rect"),
    );
    get(&app, &format!("{base}?point=500,500"), tok)
        .await
        .error(StatusCode::BAD_REQUEST, "bad_coordinate", Some("point"));
    get(
        &app,
        &format!("/v1/worlds/{}/regions/nope/stats?point=1,1", w.id),
        tok,
    )
    .await
    .error(StatusCode::NOT_FOUND, "not_found", Some("rid"));
    get(&app, &format!("{base}?point=64,64&v=9"), tok)
        .await
        .error(StatusCode::NOT_FOUND, "version_not_found", None);
}

#[tokio::test]
async fn bare_seed_world_serves_the_seed_products_with_version_caching() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), None);
    let w = create(
        &app,
        None,
        json!({"seed": "18446744073709551615", "public": true}),
    )
    .await;
    let seed = get(
        &app,
        "/v1/seeds/18446744073709551615/tiles/1/-2/3.bin",
        None,
    )
    .await;
    let pinned = get(
        &app,
        &format!("/v1/worlds/{}/tiles/1/-2/3.bin?v=1", w.id),
        None,
    )
    .await;
    let latest = get(&app, &format!("/v1/worlds/{}/tiles/1/-2/3.bin", w.id), None).await;
    assert_eq!(pinned.status, StatusCode::OK);
    assert_eq!(
        pinned.body, seed.body,
        "a bare seed world is the seed's world"
    );
    assert_eq!(latest.body, seed.body);
    assert_eq!(
        pinned.header("cache-control"),
        Some("public, max-age=31536000, immutable")
    );
    assert_eq!(latest.header("cache-control"), Some("public, max-age=5"));
    assert_eq!(latest.header("etag"), seed.header("etag"));
    assert_eq!(latest.header("x-strata-version"), Some("1"));
    let etag = latest.header("etag").expect("etag").to_string();
    let r = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{}/tiles/1/-2/3.bin", w.id),
        &[("if-none-match", etag.as_str())],
        None,
    )
    .await;
    assert_eq!(r.status, StatusCode::NOT_MODIFIED);

    let scatter = get(
        &app,
        &format!("/v1/worlds/{}/scatter/0/0/0.json?v=1", w.id),
        None,
    )
    .await;
    assert_eq!(scatter.status, StatusCode::OK);
    assert_eq!(
        scatter.body,
        get(
            &app,
            "/v1/seeds/18446744073709551615/scatter/0/0/0.json",
            None
        )
        .await
        .body
    );

    let refused = [
        (
            "tiles/1/-2/3.bin?v=2",
            StatusCode::NOT_FOUND,
            "version_not_found",
            "v",
        ),
        (
            "tiles/1/-2/3.bin?v=x",
            StatusCode::BAD_REQUEST,
            "bad_version",
            "v",
        ),
        (
            "tiles/13/0/0.bin",
            StatusCode::BAD_REQUEST,
            "lod_out_of_range",
            "lod",
        ),
        (
            "scatter/0/0/0.bin",
            StatusCode::BAD_REQUEST,
            "unknown_format",
            "format",
        ),
    ];
    for (path, status, code, field) in refused {
        get(&app, &format!("/v1/worlds/{}/{path}", w.id), None)
            .await
            .error(status, code, Some(field));
    }
}

/// A scene whose world differs from the default, so its products are not the seed's.
fn custom_scene() -> Value {
    let mut s = Scene::default().to_value();
    s["world"]["sea_level_m"] = json!(12.5);
    s["world"]["earth"]["gain"] = json!(0.45);
    s
}

#[tokio::test]
async fn versioned_tiles_are_identical_after_reopening_the_store() {
    let dir = tempfile::tempdir().expect("tmp");
    let paths = ["tiles/0/0/0.bin", "tiles/2/-1/1.png", "scatter/0/1/0.json"];
    let (id, token, before) = {
        let app = service(dir.path(), Some(ADMIN));
        let w = create(
            &app,
            Some(ADMIN),
            json!({"seed": 7, "scene": custom_scene()}),
        )
        .await;
        let tok = Some(w.admin.as_str());
        let patch = json!([{"op": "replace", "path": "/world/earth/mountain_relief_m",
                            "value": 3000.0}]);
        assert_eq!(
            edit(&app, &w.id, tok, None, &patch).await.status,
            StatusCode::OK
        );
        let mut before = Vec::new();
        for v in [1, 2] {
            for p in paths {
                let r = get(&app, &format!("/v1/worlds/{}/{p}?v={v}", w.id), tok).await;
                assert_eq!(r.status, StatusCode::OK, "{p}");
                before.push(r.body);
            }
        }
        assert_ne!(before[0], before[3], "the edit changed the world");
        let seed_tile = get(&app, "/v1/seeds/7/tiles/0/0/0.bin", None).await.body;
        assert_ne!(
            before[0], seed_tile,
            "the custom scene is not the default world"
        );
        (w.id, w.admin, before)
    };
    // Everything of the first state is dropped: the same file is opened anew.
    let app = service(dir.path(), Some(ADMIN));
    let tok = Some(token.as_str());
    let v = get(&app, &format!("/v1/worlds/{id}"), tok).await.json();
    assert_eq!(v["version"], 2);
    assert_eq!(v["scene"]["world"]["earth"]["mountain_relief_m"], 3000.0);
    let mut after = Vec::new();
    for v in [1, 2] {
        for p in paths {
            after.push(
                get(&app, &format!("/v1/worlds/{id}/{p}?v={v}"), tok)
                    .await
                    .body,
            );
        }
    }
    assert!(
        before == after,
        "versioned products changed across a reopen"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn racing_editors_with_the_same_if_match_one_wins() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), None);
    let w = create(&app, None, json!({"seed": 1})).await;
    let tok = w.admin.as_str();
    for round in 1..=8u64 {
        let m = round.to_string();
        let a = add_region(&format!("a{round}"), 0.0);
        let b = add_region(&format!("b{round}"), 50.0);
        let (ra, rb) = tokio::join!(
            edit(&app, &w.id, Some(tok), Some(&m), &a),
            edit(&app, &w.id, Some(tok), Some(&m), &b)
        );
        let mut statuses = [ra.status, rb.status];
        statuses.sort();
        assert_eq!(
            statuses,
            [StatusCode::OK, StatusCode::CONFLICT],
            "round {round}"
        );
        let loser = if ra.status == StatusCode::CONFLICT {
            ra
        } else {
            rb
        };
        loser.error(StatusCode::CONFLICT, "version_conflict", Some("If-Match"));
    }
    let v = get(&app, &format!("/v1/worlds/{}", w.id), Some(tok))
        .await
        .json();
    assert_eq!(v["version"], 9);
    assert_eq!(v["scene"]["regions"].as_array().expect("regions").len(), 8);
}

#[tokio::test]
async fn auth_matrix() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), Some(ADMIN));
    let public = create(&app, Some(ADMIN), json!({"seed": 1, "public": true})).await;
    let private = create(&app, Some(ADMIN), json!({"seed": 2})).await;
    let other = create(&app, Some(ADMIN), json!({"seed": 3})).await;
    let mut tokens = std::collections::BTreeMap::new();
    for role in ["read", "edit", "admin"] {
        let r = post_json(
            &app,
            &format!("/v1/worlds/{}/tokens", private.id),
            Some(&private.admin),
            &json!({ "role": role }),
        )
        .await;
        assert_eq!(r.status, StatusCode::CREATED);
        assert_eq!(r.json()["role"], role);
        assert_eq!(r.header("cache-control"), Some("no-store"));
        tokens.insert(role, r.json()["token"].as_str().expect("token").to_string());
    }
    let (ok, created) = (StatusCode::OK, StatusCode::CREATED);
    let (u, f) = (StatusCode::UNAUTHORIZED, StatusCode::FORBIDDEN);
    // Columns: read public world, read private world, private world tile, edit, mint token,
    // create world, change access.
    let matrix: [(&str, Option<String>, [StatusCode; 7]); 5] = [
        ("none", None, [ok, u, u, u, u, u, u]),
        (
            "read",
            Some(tokens["read"].clone()),
            [ok, ok, ok, f, f, f, f],
        ),
        (
            "edit",
            Some(tokens["edit"].clone()),
            [ok, ok, ok, ok, f, f, f],
        ),
        (
            "admin",
            Some(tokens["admin"].clone()),
            [ok, ok, ok, ok, created, f, ok],
        ),
        (
            "server admin",
            Some(ADMIN.to_string()),
            [ok, ok, ok, ok, created, created, ok],
        ),
    ];
    for (name, token, want) in matrix {
        let t = token.as_deref();
        let got = [
            get(&app, &format!("/v1/worlds/{}", public.id), t).await,
            get(&app, &format!("/v1/worlds/{}", private.id), t).await,
            get(
                &app,
                &format!("/v1/worlds/{}/tiles/3/0/0.bin", private.id),
                t,
            )
            .await,
            edit(
                &app,
                &private.id,
                t,
                None,
                &add_region(&format!("r-{}", name.replace(' ', "-")), 0.0),
            )
            .await,
            post_json(
                &app,
                &format!("/v1/worlds/{}/tokens", private.id),
                t,
                &json!({"role": "read"}),
            )
            .await,
            post_json(&app, "/v1/worlds", t, &json!({"seed": 9})).await,
            post_json(
                &app,
                &format!("/v1/worlds/{}/access", private.id),
                t,
                &json!({"public": false}),
            )
            .await,
        ];
        for (i, (r, w)) in got.iter().zip(want).enumerate() {
            assert_eq!(
                r.status,
                w,
                "role {name}, operation {i}: {}",
                String::from_utf8_lossy(&r.body)
            );
            if w == u {
                r.error(u, "unauthenticated", None);
                assert_eq!(
                    r.header("www-authenticate"),
                    Some("Bearer realm=\"strata\"")
                );
            }
            if w == f {
                r.error(f, "forbidden", None);
            }
        }
    }
    // A token of one world grants nothing on another private world; unknown tokens are 401
    // even where no token is needed.
    get(
        &app,
        &format!("/v1/worlds/{}", other.id),
        Some(&tokens["admin"]),
    )
    .await
    .error(f, "forbidden", None);
    get(
        &app,
        &format!("/v1/worlds/{}", public.id),
        Some("st_not-a-token"),
    )
    .await
    .error(u, "unauthenticated", None);
    let r = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{}", private.id),
        &[("authorization", "Basic dXNlcjpwYXNz")],
        None,
    )
    .await;
    r.error(u, "unauthenticated", None);
    // Making a world public opens reads, not edits.
    let r = post_json(
        &app,
        &format!("/v1/worlds/{}/access", private.id),
        Some(&private.admin),
        &json!({"public": true}),
    )
    .await;
    assert_eq!(r.json(), json!({"id": private.id, "public": true}));
    assert_eq!(
        get(&app, &format!("/v1/worlds/{}", private.id), None)
            .await
            .status,
        ok
    );
    assert_eq!(
        edit(&app, &private.id, None, None, &json!([])).await.status,
        u
    );
    assert_eq!(
        edit(&app, &private.id, Some(&tokens["read"]), None, &json!([]))
            .await
            .status,
        f
    );
    // Without a server admin token anyone may create worlds.
    let open_dir = tempfile::tempdir().expect("tmp");
    let open = service(open_dir.path(), None);
    assert_eq!(
        post_json(&open, "/v1/worlds", None, &json!({"seed": 5}))
            .await
            .status,
        created
    );
}

/// Collects everything the global tracing subscriber writes.
#[derive(Clone, Default)]
struct Capture(Arc<Mutex<Vec<u8>>>);

impl std::io::Write for Capture {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.lock().expect("lock").extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[tokio::test]
async fn tokens_never_appear_in_logs() {
    let capture = Capture::default();
    let writer = capture.clone();
    let subscriber = tracing_subscriber::fmt()
        .with_max_level(tracing::Level::TRACE)
        .with_ansi(false)
        .with_writer(move || writer.clone())
        .finish();
    // Global, so the blocking pool's threads log here too (no other test sets one).
    tracing::subscriber::set_global_default(subscriber).expect("first global subscriber");

    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), Some(ADMIN));
    let w = create(&app, Some(ADMIN), json!({"seed": 11})).await;
    let minted = post_json(
        &app,
        &format!("/v1/worlds/{}/tokens", w.id),
        Some(&w.admin),
        &json!({"role": "edit"}),
    )
    .await
    .json();
    let edit_token = minted["token"].as_str().expect("token").to_string();
    assert_eq!(
        edit(
            &app,
            &w.id,
            Some(&edit_token),
            Some("1"),
            &add_region("x", 0.0)
        )
        .await
        .status,
        StatusCode::OK
    );
    edit(
        &app,
        &w.id,
        Some(&edit_token),
        Some("1"),
        &add_region("y", 0.0),
    )
    .await;
    get(
        &app,
        &format!("/v1/worlds/{}/tiles/4/0/0.json?v=2", w.id),
        Some(&w.admin),
    )
    .await;
    get(
        &app,
        &format!("/v1/worlds/{}", w.id),
        Some("st_wrong-token-value"),
    )
    .await;
    post_json(&app, "/v1/worlds", Some(&edit_token), &json!({"seed": 1})).await;

    let text = String::from_utf8(capture.0.lock().expect("lock").clone()).expect("utf-8");
    assert!(
        text.contains("edit committed") && text.contains("world created"),
        "logs captured:\n{text}"
    );
    assert!(
        text.contains("started processing request"),
        "request traces captured"
    );
    for secret in [
        ADMIN,
        w.admin.as_str(),
        edit_token.as_str(),
        "st_wrong-token-value",
    ] {
        assert!(!text.contains(secret), "a token appears in the logs");
        // Nor its hex body alone.
        let body = secret.strip_prefix("st_").unwrap_or(secret);
        assert!(!text.contains(body), "a token appears in the logs");
    }
}

#[tokio::test]
async fn bad_input_names_the_field() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path(), None);
    let w = create(&app, None, json!({"seed": 3})).await;
    let tok = w.admin.as_str();
    let auth = format!("Bearer {tok}");
    let uri = format!("/v1/worlds/{}/edits", w.id);
    let raw = |ct: &'static str, body: &'static str| {
        let (app, uri, auth) = (app.clone(), uri.clone(), auth.clone());
        async move {
            send(
                &app,
                Method::POST,
                &uri,
                &[("authorization", auth.as_str()), ("content-type", ct)],
                Some(body.as_bytes()),
            )
            .await
        }
    };
    raw(PATCH, "[{\"op\": \"add\",")
        .await
        .error(StatusCode::BAD_REQUEST, "bad_body", Some("body"));
    raw("application/json", "[]").await.error(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        Some("Content-Type"),
    );
    let r = send(
        &app,
        Method::POST,
        &uri,
        &[("authorization", &auth)],
        Some(b"[]"),
    )
    .await;
    r.error(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        Some("Content-Type"),
    );
    raw(PATCH, "{\"op\": \"add\"}")
        .await
        .error(StatusCode::BAD_REQUEST, "bad_body", None);
    let r = raw(PATCH, "[{\"op\": \"test\", \"path\": \"/regions\", \"value\": []}, {\"op\": \"frobnicate\", \"path\": \"/x\"}]").await;
    r.error(StatusCode::BAD_REQUEST, "bad_body", None);
    assert!(
        r.json()["error"]["field"]
            .as_str()
            .is_some_and(|f| f.starts_with("/1")),
        "{}",
        r.json()
    );
    // Operation 3 fails: the earlier ones are undone with it.
    let patch = json!([
        {"op": "test", "path": "/regions", "value": []},
        {"op": "add", "path": "/regions/-", "value": {"id": "a", "bbox": {"min": [0, 0], "max": [1, 1]}}},
        {"op": "replace", "path": "/world/sea_level_m", "value": 4.0},
        {"op": "remove", "path": "/regions/7"}
    ]);
    edit(&app, &w.id, Some(tok), None, &patch).await.error(
        StatusCode::UNPROCESSABLE_ENTITY,
        "patch_failed",
        Some("/3"),
    );
    let failed_test = json!([{"op": "test", "path": "/world/cell_m", "value": 2.0}]);
    edit(&app, &w.id, Some(tok), None, &failed_test)
        .await
        .error(StatusCode::UNPROCESSABLE_ENTITY, "patch_failed", Some("/0"));
    let gain = json!([{"op": "replace", "path": "/world/earth/gain", "value": 5}]);
    edit(&app, &w.id, Some(tok), None, &gain).await.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/world/earth/gain"),
    );
    let typed = json!([{"op": "replace", "path": "/world/cell_m", "value": "one"}]);
    edit(&app, &w.id, Some(tok), None, &typed).await.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/world/cell_m"),
    );
    let unknown = json!([{"op": "add", "path": "/rivers", "value": []}]);
    edit(&app, &w.id, Some(tok), None, &unknown).await.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/rivers"),
    );
    let bbox = json!([{"op": "add", "path": "/decals/-", "value": {"id": "d", "bbox": {"min": [5, 0], "max": [1, 1]}}}]);
    edit(&app, &w.id, Some(tok), None, &bbox).await.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/decals/0/bbox/max/0"),
    );
    // Issue 18, finding 1: a region over ±1e9 m was accepted and its first tile grew the
    // process to 13 GB; it is refused before any work, naming the field and the limit.
    let huge = json!([{"op": "add", "path": "/regions/-", "value": {"id": "huge",
        "bbox": {"min": [-1e9, -1e9], "max": [1e9, 1e9]}, "samples": 33, "ops": []}}]);
    let r = edit(&app, &w.id, Some(tok), None, &huge).await;
    let message = r.json()["error"]["message"]
        .as_str()
        .unwrap_or_default()
        .to_string();
    r.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/regions/0/bbox/min/0"),
    );
    assert!(message.contains("within ±1048576 m"), "{message}");
    for bad in ["abc", "0", "1, 2", "\"x\""] {
        edit(&app, &w.id, Some(tok), Some(bad), &json!([]))
            .await
            .error(StatusCode::BAD_REQUEST, "bad_version", Some("If-Match"));
    }
    edit(&app, &w.id, Some(tok), Some("5"), &json!([]))
        .await
        .error(StatusCode::CONFLICT, "version_conflict", Some("If-Match"));
    // Nothing above changed the world.
    let v = get(&app, &format!("/v1/worlds/{}", w.id), Some(tok))
        .await
        .json();
    assert_eq!(v["version"], 1);
    assert_eq!(v["scene"], Scene::default().to_value());

    // World creation.
    let mut scene = Scene::default().to_value();
    scene["world"]["earth"]["gain"] = json!(5);
    let bad_bodies = [
        (
            json!({"seed": 1, "scene": scene}),
            "invalid_scene",
            Some("/scene/world/earth/gain"),
        ),
        (json!({"seed": "x1"}), "bad_seed", Some("/seed")),
        (json!({"seed": 1, "colour": "red"}), "bad_body", None),
        (json!({"scene": {}}), "bad_body", Some("body")),
        (
            json!({"seed": 1, "public": "yes"}),
            "bad_body",
            Some("/public"),
        ),
    ];
    for (body, code, field) in bad_bodies {
        post_json(&app, "/v1/worlds", None, &body).await.error(
            StatusCode::BAD_REQUEST,
            code,
            field,
        );
    }
    send(
        &app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "application/json")],
        Some(b"{"),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_body", Some("body"));
    send(
        &app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "text/plain")],
        Some(b"{}"),
    )
    .await
    .error(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        Some("Content-Type"),
    );
    post_json(
        &app,
        &format!("/v1/worlds/{}/tokens", w.id),
        Some(tok),
        &json!({"role": "owner"}),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_body", Some("/role"));
    send(
        &app,
        Method::DELETE,
        &format!("/v1/worlds/{}", w.id),
        &[] as &[(&str, &str)],
        None,
    )
    .await
    .error(StatusCode::METHOD_NOT_ALLOWED, "method_not_allowed", None);
}

#[tokio::test]
async fn edits_are_broadcast_after_commit_and_counted() {
    let dir = tempfile::tempdir().expect("tmp");
    let state = AppState::new(Compute::cpu()).with_worlds(store_in(dir.path()), None);
    let mut events = state.subscribe_edits();
    let app = app(state);
    let w = create(&app, None, json!({"seed": 5, "public": true})).await;
    let tok = Some(w.admin.as_str());
    assert_eq!(
        edit(&app, &w.id, tok, None, &add_region("r", 20.0))
            .await
            .status,
        StatusCode::OK
    );
    let e = events.try_recv().expect("an event per accepted edit");
    assert_eq!((e.world.as_str(), e.version), (w.id.as_str(), 2));
    assert_eq!(
        e.dirty,
        Dirty::Rects(vec![Rect {
            min: [20.0, 0.0],
            max: [30.0, 10.0]
        }])
    );
    let world_edit = json!([{"op": "replace", "path": "/world/sea_level_m", "value": 1.0}]);
    edit(&app, &w.id, tok, None, &world_edit).await;
    assert_eq!(events.try_recv().expect("event").dirty, Dirty::Everything);
    edit(&app, &w.id, tok, Some("1"), &world_edit).await;
    assert!(
        events.try_recv().is_err(),
        "refused edits are not broadcast"
    );

    get(
        &app,
        &format!("/v1/worlds/{}/tiles/5/0/0.bin?v=2", w.id),
        None,
    )
    .await;
    get(
        &app,
        &format!("/v1/worlds/{}/tiles/5/1/0.bin?v=2", w.id),
        None,
    )
    .await;
    let m = get(&app, "/metrics", None).await;
    assert_eq!(m.status, StatusCode::OK);
    assert!(m
        .header("content-type")
        .is_some_and(|c| c.starts_with("text/plain; version=0.0.4")));
    let text = String::from_utf8(m.body).expect("utf-8");
    for line in [
        "strata_edits_total{result=\"applied\"} 2",
        "strata_edits_total{result=\"conflict\"} 1",
        "strata_worlds_created_total 1",
        "strata_http_requests_total{method=\"POST\",route=\"/v1/worlds/{id}/edits\",status=\"200\"} 2",
        "strata_http_requests_total{method=\"POST\",route=\"/v1/worlds/{id}/edits\",status=\"409\"} 1",
        "strata_http_request_duration_seconds_count{route=\"/v1/worlds/{id}/tiles/{lod}/{x}/{z_ext}\"} 2",
        "strata_plan_cache_hits_total{cache=\"worlds\"} 1",
        "strata_plan_cache_misses_total{cache=\"worlds\"} 1",
        "strata_edit_subscribers 1",
    ] {
        assert!(text.contains(line), "missing {line:?} in\n{text}");
    }
}

/// A small JSON Schema (2020-12) checker covering the keywords `api/scene.schema.json` uses.
fn check_schema(root: &Value, schema: &Value, v: &Value, at: &str) -> Result<(), String> {
    let fail = |what: &str| Err(format!("{at}: {what}"));
    if let Some(b) = schema.as_bool() {
        return if b { Ok(()) } else { fail("false schema") };
    }
    if let Some(r) = schema.get("$ref").and_then(Value::as_str) {
        let target = root
            .pointer(r.strip_prefix('#').expect("local ref"))
            .expect("ref target");
        check_schema(root, target, v, at)?;
    }
    if let Some(t) = schema.get("type").and_then(Value::as_str) {
        let ok = match t {
            "object" => v.is_object(),
            "array" => v.is_array(),
            "string" => v.is_string(),
            "boolean" => v.is_boolean(),
            "number" => v.is_number(),
            "integer" => v.is_u64() || v.is_i64() || v.as_f64().is_some_and(|f| f.fract() == 0.0),
            other => panic!("type {other}"),
        };
        if !ok {
            return fail(&format!("not {t}"));
        }
    }
    if let Some(e) = schema.get("enum").and_then(Value::as_array) {
        if !e.contains(v) {
            return fail("not in enum");
        }
    }
    if schema.get("const").is_some_and(|c| c != v) {
        return fail("not the constant");
    }
    if let Some(x) = v.as_f64() {
        let num = |k: &str| schema.get(k).and_then(Value::as_f64);
        if num("minimum").is_some_and(|m| x < m) || num("maximum").is_some_and(|m| x > m) {
            return fail("out of range");
        }
        if num("exclusiveMinimum").is_some_and(|m| x <= m) {
            return fail("out of range");
        }
    }
    if let Some(s) = v.as_str() {
        if schema
            .get("minLength")
            .and_then(Value::as_u64)
            .is_some_and(|m| (s.chars().count() as u64) < m)
        {
            return fail("too short");
        }
    }
    if let Some(o) = v.as_object() {
        let props = schema.get("properties").and_then(Value::as_object);
        for req in schema
            .get("required")
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            if !o.contains_key(req.as_str().expect("name")) {
                return fail(&format!("missing {req}"));
            }
        }
        for (k, val) in o {
            let sub = format!("{at}/{k}");
            match props.and_then(|p| p.get(k)) {
                Some(s) => check_schema(root, s, val, &sub)?,
                None => {
                    if let Some(extra) = schema.get("additionalProperties") {
                        check_schema(root, extra, val, &sub)?;
                    }
                }
            }
        }
    }
    if let Some(a) = v.as_array() {
        let n = a.len() as u64;
        if schema
            .get("minItems")
            .and_then(Value::as_u64)
            .is_some_and(|m| n < m)
            || schema
                .get("maxItems")
                .and_then(Value::as_u64)
                .is_some_and(|m| n > m)
        {
            return fail("wrong length");
        }
        let prefix = schema.get("prefixItems").and_then(Value::as_array);
        for (i, item) in a.iter().enumerate() {
            let sub = format!("{at}/{i}");
            match prefix.and_then(|p| p.get(i)) {
                Some(s) => check_schema(root, s, item, &sub)?,
                None => {
                    if let Some(s) = schema.get("items") {
                        check_schema(root, s, item, &sub)?;
                    }
                }
            }
        }
    }
    Ok(())
}

#[test]
fn scene_schema_describes_what_the_server_accepts() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("api/scene.schema.json");
    let schema: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("schema"))
        .expect("schema is JSON");
    assert_eq!(
        schema["$schema"],
        "https://json-schema.org/draft/2020-12/schema"
    );
    let check = |v: &Value| check_schema(&schema, &schema, v, "");

    let mut full = Scene::default().to_value();
    for kind in strata::scene::ELEMENT_KINDS {
        full[kind] = json!([{"id": format!("{kind}-1"), "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
                             "anything": {"else": [1, 2]}}]);
    }
    // Regions are interpreted (issue 4): their fields are the grid and the tool operations.
    full["regions"] = json!([{"id": "regions-1", "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
        "samples": 65, "ops": [{"op": "elevation", "shape": {"point": [0.0, 1.0]}, "elevation_m": 3.0, "radius_m": 1.0},
            {"op": "sketch", "png_base64": "iVBORw0KGgoAAAANSUhEUgAAAAQAAAAEEAAAAADcCh3hAAAALElEQVR42mNgYPBTOK3w/z8DA0PsgVcJpxUY5B1KDU4rzHEASpQa9CwoNQAA3DMMWSByqQoAAAAASUVORK5CYII=",
             "min_m": -20.0, "max_m": 30.0, "blend_m": 1.0},
            {"op": "basis", "png_base64": "iVBORw0KGgoAAAANSUhEUgAAAAQAAAAECAAAAACMmsGiAAAAEElEQVR42mP438BQz4BKAABTxAf5l+Fu2QAAAABJRU5ErkJggg==",
             "period_m": 4.0, "amplitude_m": 1.0, "weight": 0.5, "blend_m": 0.5}]}]);
    // So are volume regions (issue 5): the vertical extent, grid spacing and primitives.
    full["volumes"] = json!([{"id": "volumes-1", "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
        "y_m": [0.0, 8.0], "spacing_m": 1.0, "dead_zone_m": 2.0, "curves": [], "meshes": [],
        "ground": {"alpha": 0.3, "beta": 0.5, "material": 0}}]);
    // So are strata elements (issue 6): a preset or a configuration, the voxel size, carving,
    // and whether tiles mark where caves open (issue 19).
    full["strata"] = json!([{"id": "strata-1", "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
        "preset": "B2", "voxel_m": 0.5, "carve": false, "mark_openings": true}]);
    // So are materials and decals (issue 20): overrides or new materials, procedural or with
    // images, and decals with a placement, a mask and roughness.
    let image = "0123456789abcdef".repeat(4);
    full["materials"] = json!([{"id": "materials-1", "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
        "name": "moss", "base": [0.2, 0.4, 0.1], "tint": [0.1, 0.3, 0.1], "roughness": [0.6, 0.9],
        "relief_m": 0.05, "noise_m": 0.02, "freq_log2": 1, "octaves": 3,
        "texture": {"albedo": image, "roughness": image, "height": image, "normal": image,
            "repeat_m": 2}}]);
    full["decals"] = json!([{"id": "decals-1", "bbox": {"min": [-5.0, 0.0], "max": [5.0, 2.0]},
        "image": image, "mask": image, "center": [0.0, 1.0], "size_m": [4.0, 1.5],
        "rotation_deg": 10.0, "opacity": 0.5, "roughness": 0.3, "projection": "top_down"}]);
    for good in [json!({}), Scene::default().to_value(), full.clone()] {
        Scene::from_value(&good).expect("the server accepts it");
        check(&good).expect("the schema accepts it");
    }
    // Every object of the stored scene is fully described: no field the schema does not name.
    fn closed(root: &Value, schema: &Value, v: &Value, at: &str) {
        let schema = match schema.get("$ref").and_then(Value::as_str) {
            Some(r) => root.pointer(&r[1..]).expect("ref"),
            None => schema,
        };
        if let Some(o) = v.as_object() {
            if schema.get("additionalProperties") == Some(&Value::Bool(true)) {
                return;
            }
            for (k, val) in o {
                let s = schema["properties"]
                    .get(k)
                    .unwrap_or_else(|| panic!("{at}/{k} undocumented"));
                closed(root, s, val, &format!("{at}/{k}"));
            }
        }
        if let Some(a) = v.as_array() {
            for (i, item) in a.iter().enumerate() {
                let s = schema
                    .get("prefixItems")
                    .and_then(|p| p.get(i))
                    .or_else(|| schema.get("items"));
                if let Some(s) = s {
                    closed(root, s, item, &format!("{at}/{i}"));
                }
            }
        }
    }
    closed(&schema, &schema, &full, "");

    let bad = |pointer: &str, value: Value| {
        let mut v = Scene::default().to_value();
        *v.pointer_mut(pointer).expect("pointer") = value;
        v
    };
    for (doc, pointer) in [
        (bad("/world/earth/gain", json!(5.0)), "/world/earth/gain"),
        (
            bad("/world/biomes/2/relief/erosion", json!(3.0)),
            "/world/biomes/2/relief/erosion",
        ),
        (bad("/world/cell_m", json!(0.0)), "/world/cell_m"),
        (
            bad("/world/biomes/0/ground", json!("lava")),
            "/world/biomes/0/ground",
        ),
        (
            bad("/world/earth/octaves", json!(21)),
            "/world/earth/octaves",
        ),
        (
            bad("/world/layout/dispersion_d", json!(1.5)),
            "/world/layout/dispersion_d",
        ),
        (bad("/world/biomes", json!([])), "/world/biomes"),
        (json!({"regions": [{"id": "a"}]}), "/regions/0"),
        (
            json!({"regions": [{"id": "a", "bbox": {"min": [0, 0], "max": [1]}}]}),
            "/regions/0/bbox/max",
        ),
        (json!({"world": {"cell_m": 1.0}}), "/world"),
        (json!({"rivers": []}), "/rivers"),
    ] {
        let server = Scene::from_value(&doc).expect_err("the server refuses it");
        assert_eq!(server.pointer, pointer, "{}", server.message);
        assert!(check(&doc).is_err(), "the schema refuses {pointer}");
    }
    // Materials and decals are checked when written (stored free-form ones keep loading).
    let decal = |k: &str, v: Value| {
        let mut d = full["decals"][0].clone();
        d[k] = v;
        json!({ "decals": [d] })
    };
    for (doc, pointer) in [
        (decal("opacity", json!(2.0)), "/decals/0/opacity"),
        (decal("size_m", json!([4.0, 0.0])), "/decals/0/size_m/1"),
        (decal("projection", json!("side")), "/decals/0/projection"),
        (
            json!({"materials": [{"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]},
                   "name": "rock", "texture": {"albedo": image, "repeat_m": 3.0}}]}),
            "/materials/0/texture/repeat_m",
        ),
    ] {
        let scene = Scene::from_value(&doc).expect("it reads");
        let server = scene
            .check_costs(None)
            .expect_err("the server refuses to write it");
        assert_eq!(server.pointer, pointer, "{}", server.message);
        assert!(check(&doc).is_err(), "the schema refuses {pointer}");
    }
}

#[test]
fn scene_module_is_pure() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/scene");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).expect("src/scene") {
        let path = entry.expect("entry").path();
        let text = std::fs::read_to_string(&path).expect("readable");
        for banned in [
            "tokio::",
            "axum::",
            "wgpu::",
            "rusqlite",
            "crate::server",
            "crate::store",
        ] {
            assert!(
                !text.contains(banned),
                "{} mentions {banned}",
                path.display()
            );
        }
        n += 1;
    }
    assert!(n >= 2);
}

/// Stream sessions subscribe per world: an edit reaches the sessions of its world only, with the
/// view of the version it made (plan and parsed scene, built once), so no session reads the
/// store per edit.
#[tokio::test]
async fn stream_sessions_hear_only_their_world_with_the_new_view() {
    use strata::stream::session::SourceView;
    let dir = tempfile::tempdir().expect("tmp");
    let state = AppState::new(Compute::cpu()).with_worlds(store_in(dir.path()), None);
    let worlds = state.worlds.clone();
    let app = app(state);
    let a = create(&app, None, json!({"seed": 5, "public": true})).await;
    let b = create(&app, None, json!({"seed": 6, "public": true})).await;
    let mut hears_a = worlds.subscribe_world(&a.id);
    let mut hears_a_too = worlds.subscribe_world(&a.id);
    edit(
        &app,
        &b.id,
        Some(b.admin.as_str()),
        None,
        &add_region("r", 20.0),
    )
    .await;
    assert!(
        hears_a.try_recv().is_err(),
        "an edit of another world does not reach a's sessions"
    );
    let reply = edit(
        &app,
        &a.id,
        Some(a.admin.as_str()),
        None,
        &add_region("r", 20.0),
    )
    .await;
    assert_eq!(reply.status, StatusCode::OK);
    let e = hears_a.try_recv().expect("a's edit reaches a's session");
    let e2 = hears_a_too.try_recv().expect("and every session of a");
    assert_eq!(e.view.version(), 2);
    assert_eq!(e.view.plan().seed, 5);
    assert_eq!(e.view.view.world, Some((a.id.clone(), 2)));
    assert!(
        e.view.view.inputs.region("r").is_some(),
        "the view has the edit"
    );
    assert!(
        Arc::ptr_eq(&e.view.view, &e2.view.view),
        "one view, built once for every session"
    );
    assert_eq!(
        e.dirty,
        Dirty::Rects(vec![Rect {
            min: [20.0, 0.0],
            max: [30.0, 10.0]
        }])
    );
}
