//! The water products over HTTP, driven through `strata::server::app` in-process: tile format v2
//! (`api/tile_format_v2.md`: the water surface and kind of every vertex, `?format=2`, v1 bytes
//! unchanged) and the river lines (`api/rivers_v1.md`) of seeds and worlds.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use strata::compute::Compute;
use strata::encode;
use strata::server::{app, AppState};
use strata::terrain::earth::rivers::MAX_CARVE_LOD;
use strata::terrain::earth::tile_rivers;
use strata::terrain::{Tile, TileKey, WorldParams, WorldPlan, TILE_VERTEX_COUNT};

mod common;

use common::oneshot::Reply;

const N: usize = TILE_VERTEX_COUNT;

fn service() -> Router {
    app(AppState::new(Compute::cpu()))
}

async fn get(app: &Router, uri: &str, headers: &[(&str, &str)]) -> Reply {
    common::oneshot::send(app, Method::GET, uri, headers, None).await
}

fn plan42() -> WorldPlan {
    WorldPlan::new(42, WorldParams::default()).expect("default world")
}

/// Little-endian reads at byte offsets, as a client of the spec would write them.
struct Le<'a>(&'a [u8]);

impl Le<'_> {
    fn u16(&self, o: usize) -> u16 {
        u16::from_le_bytes([self.0[o], self.0[o + 1]])
    }
    fn u32(&self, o: usize) -> usize {
        u32::from_le_bytes([self.0[o], self.0[o + 1], self.0[o + 2], self.0[o + 3]]) as usize
    }
    fn f32(&self, o: usize) -> f32 {
        f32::from_bits(self.u32(o) as u32)
    }
}

/// The water surface the spec defines: ground plus depth where wet, the ground where dry.
fn spec_surface(tile: &Tile, v: usize) -> f32 {
    let (h, d) = (tile.heights[v], tile.water_depth[v]);
    if d > 0.0 {
        h + d
    } else {
        h
    }
}

fn f32s(v: &Value) -> Vec<f32> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number") as f32)
        .collect()
}

fn tile_uri(prefix: &str, key: TileKey) -> String {
    format!("{prefix}/tiles/{}/{}/{}", key.lod, key.x, key.z)
}

#[tokio::test]
async fn v2_tiles_decode_back_to_the_tiles_water_and_v1_keeps_its_bytes() {
    let plan = plan42();
    let tile = common::water::lake_tile(&plan, 4, 100, 10);
    let uri = tile_uri("/v1/seeds/42", tile.key);
    let app = service();

    let r = get(&app, &format!("{uri}.bin?format=2"), &[]).await;
    r.ok();
    assert_eq!(
        r.header("content-type"),
        Some("application/vnd.strata.tile.v2")
    );
    let b = Le(&r.body);
    assert_eq!(&r.body[0..4], b"STRT");
    assert_eq!(b.u16(4), 2, "version");
    assert_eq!(b.u16(6), 128, "header_len");
    let k = b.u16(38) as usize;
    let [materials, depth, total, overrides, surface, kinds] =
        [92, 96, 100, 104, 108, 112].map(|o| b.u32(o));
    assert_eq!(total, r.body.len());
    assert_eq!(
        depth,
        128 + 16 * N + (N * k).div_ceil(4) * 4 + N.div_ceil(4) * 4
    );
    assert_eq!(materials, depth - N.div_ceil(4) * 4);
    assert_eq!(surface, depth + 4 * N);
    assert_eq!(kinds, surface + 4 * N);
    assert_eq!(total, kinds + N.div_ceil(4) * 4);
    assert_eq!(overrides, 0, "no volume override");
    assert!(r.body[116..128].iter().all(|&x| x == 0), "reserved");
    let (mut lake, mut river) = (0, 0);
    for v in 0..N {
        let (s, kind) = (b.f32(surface + 4 * v), r.body[kinds + v]);
        assert_eq!(s.to_bits(), spec_surface(&tile, v).to_bits(), "surface {v}");
        assert_eq!(kind, tile.water_kind[v], "kind {v}");
        assert_eq!(
            kind != 0,
            tile.water_depth[v] > 0.0,
            "vertex {v}: a kind where there is water, none where dry"
        );
        if kind == 0 {
            assert_eq!(s.to_bits(), b.f32(128 + 4 * v).to_bits(), "dry: the ground");
        } else {
            assert!(s > b.f32(128 + 4 * v), "wet: above the ground");
        }
        lake += usize::from(kind == 2);
        river += usize::from(kind == 3);
    }
    assert!(lake >= 100 && river >= 10, "lake {lake}, river {river}");
    assert!(r.body[kinds + N..].iter().all(|&x| x == 0), "zero padding");

    // Version 1 is the default, and its bytes are the v1 encoder's; v2 extends them.
    let v1 = get(&app, &format!("{uri}.bin"), &[]).await;
    v1.ok();
    assert_eq!(
        v1.header("content-type"),
        Some("application/vnd.strata.tile.v1")
    );
    assert_eq!(v1.body, encode::bin::encode(&plan, &tile));
    assert_eq!(v1.body.len(), surface);
    assert_eq!(Le(&v1.body).u16(4), 1);
    assert!(v1.body[108..128].iter().all(|&x| x == 0), "v1 reserved");
    assert_eq!(&v1.body[128..], &r.body[128..surface]);
    let explicit = get(&app, &format!("{uri}.bin?format=1"), &[]).await;
    assert_eq!(explicit.body, v1.body);
    assert_eq!(explicit.header("etag"), v1.header("etag"));
    assert_ne!(r.header("etag"), v1.header("etag"));

    let j = get(&app, &format!("{uri}.json?format=2"), &[]).await;
    j.ok();
    let doc = j.json();
    assert_eq!(doc["format"], "strata.tile.v2");
    let js = f32s(&doc["water_surface_m"]);
    assert_eq!(js.len(), N);
    for (v, s) in js.iter().enumerate() {
        assert_eq!(
            s.to_bits(),
            b.f32(surface + 4 * v).to_bits(),
            "json surface {v}"
        );
        assert_eq!(doc["water_kind"][v], tile.water_kind[v], "json kind {v}");
    }
    let j1 = get(&app, &format!("{uri}.json"), &[]).await;
    assert_eq!(j1.body, encode::json::encode(&plan, &tile));
    let d1 = j1.json();
    assert_eq!(d1["format"], "strata.tile.v1");
    assert!(d1.get("water_surface_m").is_none() && d1.get("water_kind").is_none());
}

#[tokio::test]
async fn bad_format_versions_are_400_naming_format_and_the_allowed_values() {
    let app = service();
    for (uri, allowed) in [
        ("/v1/seeds/1/tiles/0/0/0.bin?format=3", "1, 2"),
        ("/v1/seeds/1/tiles/0/0/0.json?format=v2", "1, 2"),
        ("/v1/seeds/1/tiles/0/0/0.bin?format=2&format=2", "1, 2"),
        ("/v1/seeds/1/tiles/0/0/0.glb?format=2", "allowed: 1"),
        ("/v1/seeds/1/tiles/0/0/0.png?format=2", "allowed: 1"),
    ] {
        let r = get(&app, uri, &[]).await;
        r.error(StatusCode::BAD_REQUEST, "bad_parameter", Some("format"));
        let message = r.json()["error"]["message"]
            .as_str()
            .unwrap_or_default()
            .to_string();
        assert!(message.contains(allowed), "{uri}: {message}");
    }
    let info = get(&app, "/v1/info", &[]).await.json();
    let versions: Vec<(String, Value)> = info["formats"]
        .as_array()
        .expect("formats")
        .iter()
        .map(|f| {
            (
                f["extension"].as_str().unwrap_or("").to_string(),
                f["versions"].clone(),
            )
        })
        .collect();
    assert_eq!(
        versions,
        [
            ("json".to_string(), json!([1, 2])),
            ("bin".to_string(), json!([1, 2])),
            ("png".to_string(), json!([1])),
            ("glb".to_string(), json!([1])),
        ]
    );
    assert_eq!(info["limits"]["max_river_lod"], MAX_CARVE_LOD);
    let glb = get(&app, "/v1/seeds/1/tiles/0/0/0.glb?format=1", &[]).await;
    glb.ok();
    assert_eq!(
        glb.body,
        get(&app, "/v1/seeds/1/tiles/0/0/0.glb", &[]).await.body
    );
}

/// Checks one `strata.rivers.v1` line: one width and discharge per point, water levels that
/// never rise, widths and discharges that never fall, a known end.
fn check_line(line: &Value) {
    let points = line["points"].as_array().expect("points");
    assert!(points.len() >= 2, "{line}");
    assert_eq!(line["width_m"].as_array().map(Vec::len), Some(points.len()));
    assert_eq!(
        line["discharge_m3s"].as_array().map(Vec::len),
        Some(points.len())
    );
    let level: Vec<f32> = points
        .iter()
        .map(|p| p[2].as_f64().expect("level") as f32)
        .collect();
    for w in level.windows(2) {
        assert!(w[1] <= w[0], "the water rises downstream: {level:?}");
    }
    for field in ["width_m", "discharge_m3s"] {
        let v = f32s(&line[field]);
        assert!(v.iter().all(|&x| x > 0.0), "{field} {v:?}");
        for w in v.windows(2) {
            assert!(w[1] >= w[0], "{field} falls downstream: {v:?}");
        }
    }
    assert!(
        ["sea", "lake", "river", "continues"].contains(&line["ends"].as_str().unwrap_or("")),
        "{line}"
    );
    for node in ["from", "to"] {
        assert_eq!(line[node].as_array().map(Vec::len), Some(2), "{line}");
    }
}

#[tokio::test]
async fn seed_river_lines_descend_and_are_the_librarys() {
    let plan = plan42();
    let earth = plan.earth.as_ref().expect("earth-1");
    let app = service();
    let mut lines_seen = 0;
    let mut ends = std::collections::BTreeSet::new();
    let coarsest = MAX_CARVE_LOD as u32;
    let tiles = [
        (6, 0, 0),
        (6, -1, 1),
        (6, 1, 1),
        (coarsest, 0, 0),
        (coarsest, 0, 1),
        (coarsest, 1, 0),
        // Lines that end in a lake (with `lakes: 5` the lakes nearer the origin spill).
        (coarsest, 1, -2),
    ];
    for (lod, x, z) in tiles {
        let key = TileKey { lod, x, z };
        let uri = format!("/v1/seeds/42/rivers/{lod}/{x}/{z}.json");
        let r = get(&app, &uri, &[]).await;
        r.ok();
        assert_eq!(r.header("content-type"), Some("application/json"));
        assert_eq!(
            r.header("cache-control"),
            Some("public, max-age=31536000, immutable")
        );
        let spacing = plan.lods[lod as usize].spacing_m;
        let lines = tile_rivers(earth, key, spacing);
        assert_eq!(
            r.body,
            encode::rivers::encode(key, spacing, &lines),
            "{uri}"
        );
        let doc = r.json();
        assert_eq!(doc["format"], "strata.rivers.v1");
        assert_eq!(
            (doc["lod"].clone(), doc["x"].clone(), doc["z"].clone()),
            (json!(lod), json!(x), json!(z))
        );
        assert_eq!(doc["spacing_m"], json!(spacing));
        let span = 64.0 * spacing;
        let (x0, z0) = (x as f32 * span, z as f32 * span);
        for line in doc["lines"].as_array().expect("lines") {
            check_line(line);
            ends.insert(line["ends"].as_str().unwrap_or_default().to_string());
            // Some point of the line, widened by its channel, lies on the tile.
            let reach = line["points"].as_array().expect("points").iter().any(|p| {
                let (px, pz) = (
                    p[0].as_f64().unwrap_or(f64::NAN) as f32,
                    p[1].as_f64().unwrap_or(f64::NAN) as f32,
                );
                let m = 200.0;
                px >= x0 - m && px <= x0 + span + m && pz >= z0 - m && pz <= z0 + span + m
            });
            assert!(reach, "{uri}: a line far from the tile: {line}");
            lines_seen += 1;
        }
        let etag = r.header("etag").expect("etag").to_string();
        let again = get(&app, &uri, &[("if-none-match", &etag)]).await;
        assert_eq!(again.status, StatusCode::NOT_MODIFIED);
    }
    assert!(lines_seen >= 10, "{lines_seen} lines");
    for end in ["sea", "lake", "river", "continues"] {
        assert!(ends.contains(end), "no line ends in {end}: {ends:?}");
    }
}

#[tokio::test]
async fn river_lines_refuse_coarse_lods_and_other_formats() {
    let app = service();
    let too_coarse = format!("/v1/seeds/42/rivers/{}/0/0.json", MAX_CARVE_LOD + 1);
    let cases = [
        (too_coarse.as_str(), "lod_out_of_range", "lod"),
        ("/v1/seeds/42/rivers/12/0/0.json", "lod_out_of_range", "lod"),
        ("/v1/seeds/42/rivers/13/0/0.json", "lod_out_of_range", "lod"),
        ("/v1/seeds/42/rivers/x/0/0.json", "bad_lod", "lod"),
        ("/v1/seeds/42/rivers/6/0/0.bin", "unknown_format", "format"),
        ("/v1/seeds/42/rivers/6/0/0", "unknown_format", "format"),
        (
            "/v1/seeds/42/rivers/0/99999/0.json",
            "coordinate_out_of_range",
            "x",
        ),
        ("/v1/seeds/-1/rivers/0/0/0.json", "bad_seed", "seed"),
    ];
    for (uri, code, field) in cases {
        get(&app, uri, &[])
            .await
            .error(StatusCode::BAD_REQUEST, code, Some(field));
    }
    let r = get(&app, &too_coarse, &[]).await;
    let message = r.json()["error"]["message"]
        .as_str()
        .unwrap_or_default()
        .to_string();
    assert!(
        message.contains(&format!("0..={MAX_CARVE_LOD}")),
        "names the limit: {message}"
    );
}

async fn post(app: &Router, uri: &str, token: Option<&str>, kind: &str, body: &Value) -> Reply {
    let bearer = token.map(|t| format!("Bearer {t}"));
    let mut h: Vec<(&str, &str)> = vec![("content-type", kind)];
    if let Some(b) = &bearer {
        h.push(("authorization", b));
    }
    let bytes = serde_json::to_vec(body).expect("json");
    common::oneshot::send(app, Method::POST, uri, &h, Some(&bytes)).await
}

#[tokio::test]
async fn world_river_lines_follow_the_version_and_the_access() {
    let app = service();
    let r = post(
        &app,
        "/v1/worlds",
        None,
        "application/json",
        &json!({"seed": 42}),
    )
    .await;
    r.status_is(StatusCode::CREATED);
    let v = r.json();
    let id = v["id"].as_str().expect("id").to_string();
    let admin = v["tokens"]["admin"].as_str().expect("token").to_string();
    let bearer = format!("Bearer {admin}");
    let auth = [("authorization", bearer.as_str())];
    let rivers = |v: &str| format!("/v1/worlds/{id}/rivers/6/-1/1.json{v}");

    get(&app, &rivers("?v=1"), &[])
        .await
        .error(StatusCode::UNAUTHORIZED, "unauthenticated", None);
    let seed = get(&app, "/v1/seeds/42/rivers/6/-1/1.json", &[]).await;
    let pinned = get(&app, &rivers("?v=1"), &auth).await;
    pinned.ok();
    assert_eq!(
        pinned.body, seed.body,
        "the default scene has the seed's rivers"
    );
    assert!(!pinned.json()["lines"].as_array().expect("lines").is_empty());
    assert_eq!(
        pinned.header("cache-control"),
        Some("private, max-age=31536000, immutable")
    );
    assert_eq!(pinned.header("x-strata-version"), Some("1"));
    assert_eq!(pinned.header("vary"), Some("Authorization"));

    let patch = json!([{"op": "replace", "path": "/world/earth/rivers/enabled", "value": false}]);
    post(
        &app,
        &format!("/v1/worlds/{id}/edits"),
        Some(&admin),
        "application/json-patch+json",
        &patch,
    )
    .await
    .ok();
    let latest = get(&app, &rivers(""), &auth).await;
    latest.ok();
    assert_eq!(latest.header("x-strata-version"), Some("2"));
    assert_eq!(latest.header("cache-control"), Some("private, max-age=5"));
    let doc = latest.json();
    assert_eq!(
        doc["lines"],
        json!([]),
        "a world without rivers has no lines"
    );
    assert_eq!(doc["format"], "strata.rivers.v1");
    assert_eq!(
        get(&app, &rivers("?v=1"), &auth).await.body,
        pinned.body,
        "version 1 keeps its lines"
    );
    get(&app, &rivers("?v=3"), &auth).await.error(
        StatusCode::NOT_FOUND,
        "version_not_found",
        Some("v"),
    );
    let too_coarse = MAX_CARVE_LOD + 1;
    get(
        &app,
        &format!("/v1/worlds/{id}/rivers/{too_coarse}/0/0.json"),
        &auth,
    )
    .await
    .error(StatusCode::BAD_REQUEST, "lod_out_of_range", Some("lod"));

    // Without rivers a tile has no kinds: v2 writes kind 0 everywhere, the sea's water included.
    let key = TileKey { lod: 9, x: 0, z: 1 };
    let t = get(
        &app,
        &format!(
            "{}.json?format=2&v=2",
            tile_uri(&format!("/v1/worlds/{id}"), key)
        ),
        &auth,
    )
    .await;
    t.ok();
    let doc = t.json();
    let heights = f32s(&doc["heights"]);
    let depth = f32s(&doc["water_depth"]);
    let surface = f32s(&doc["water_surface_m"]);
    assert!(depth.iter().any(|&d| d > 0.0), "this tile reaches the sea");
    for v in 0..N {
        assert_eq!(doc["water_kind"][v], 0, "vertex {v}");
        let want = if depth[v] > 0.0 {
            heights[v] + depth[v]
        } else {
            heights[v]
        };
        assert_eq!(surface[v].to_bits(), want.to_bits(), "vertex {v}");
    }
}
