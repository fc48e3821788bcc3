//! Incremental recompute: tiles are cached under the hash of their inputs, so repeating a request
//! runs no stage and an edit re-runs the field stage only for the tiles whose footprint, grown by
//! the margin (blur radius + 2 vertex spacings), meets what the edit changed. Driven through
//! `strata::server::app` with `tower::ServiceExt::oneshot`; stage runs are read from the cache's
//! counters and from `/metrics`.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::collections::BTreeSet;
use strata::cache::{Stage, StageCache};
use strata::compute::Compute;
use strata::encode::Format;
use strata::server::{app, AppState};
use strata::terrain::tile::snap_edges;
use strata::terrain::{synthesize, TileKey, WorldParams, WorldPlan};

mod common;

async fn send(
    app: &Router,
    method: Method,
    uri: &str,
    headers: &[(&str, &str)],
    body: Vec<u8>,
) -> (StatusCode, Vec<u8>) {
    let r = common::oneshot::send(app, method, uri, headers, Some(&body)).await;
    (r.status, r.body)
}

async fn get_ok(app: &Router, uri: &str) -> Vec<u8> {
    let (status, body) = send(app, Method::GET, uri, &[], Vec::new()).await;
    assert_eq!(
        status,
        StatusCode::OK,
        "{uri}: {}",
        String::from_utf8_lossy(&body)
    );
    body
}

fn json_of(body: &[u8]) -> Value {
    serde_json::from_slice(body)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(body)))
}

/// Creates a public world from a bare seed: `(id, admin token)`.
async fn create_world(app: &Router, seed: u64) -> (String, String) {
    let body = serde_json::to_vec(&json!({ "seed": seed, "public": true })).expect("json");
    let (status, body) = send(
        app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "application/json")],
        body,
    )
    .await;
    assert_eq!(
        status,
        StatusCode::CREATED,
        "{}",
        String::from_utf8_lossy(&body)
    );
    let v = json_of(&body);
    assert_eq!(v["version"], 1);
    (
        v["id"].as_str().expect("id").to_string(),
        v["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}

/// Applies a JSON Patch; returns the new version.
async fn edit(app: &Router, id: &str, token: &str, patch: Value) -> u64 {
    let auth = format!("Bearer {token}");
    let (status, body) = send(
        app,
        Method::POST,
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("content-type", "application/json-patch+json"),
            ("authorization", &auth),
        ],
        serde_json::to_vec(&patch).expect("json"),
    )
    .await;
    assert_eq!(status, StatusCode::OK, "{}", String::from_utf8_lossy(&body));
    json_of(&body)["version"].as_u64().expect("version")
}

fn field_runs(state: &AppState) -> u64 {
    state.cache.stats().runs_of(Stage::Field)
}

/// The 4×4 block of LOD-0 tiles the tests request.
fn block() -> Vec<TileKey> {
    (0..4)
        .flat_map(|z| (0..4).map(move |x| TileKey { lod: 0, x, z }))
        .collect()
}

/// The tiles of `keys` whose footprint grown by the margin meets `bbox` (closed rectangles),
/// computed here from the documented rule rather than by the library.
fn touched(keys: &[TileKey], min: [f64; 2], max: [f64; 2]) -> BTreeSet<TileKey> {
    let w = WorldParams::default();
    let spacing = w.cell_m as f64;
    let size = 64.0 * spacing;
    let margin = strata::scene::margin_m(&w, 0);
    keys.iter()
        .copied()
        .filter(|k| {
            let lo = [k.x as f64 * size - margin, k.z as f64 * size - margin];
            let hi = [
                (k.x + 1) as f64 * size + margin,
                (k.z + 1) as f64 * size + margin,
            ];
            (0..2).all(|a| lo[a] <= max[a] && min[a] <= hi[a])
        })
        .collect()
}

fn tile_uri(id: &str, k: TileKey, version: u64) -> String {
    format!(
        "/v1/worlds/{id}/tiles/{}/{}/{}.bin?v={version}",
        k.lod, k.x, k.z
    )
}

/// Requests every tile of `keys` at `version` one by one; returns the tiles whose request ran
/// the field stage (asserting it ran at most once each) and their bodies.
async fn request_block(
    app: &Router,
    state: &AppState,
    id: &str,
    keys: &[TileKey],
    version: u64,
) -> (BTreeSet<TileKey>, Vec<Vec<u8>>) {
    let mut ran = BTreeSet::new();
    let mut bodies = Vec::new();
    for &k in keys {
        let before = field_runs(state);
        bodies.push(get_ok(app, &tile_uri(id, k, version)).await);
        match field_runs(state) - before {
            0 => {}
            1 => {
                ran.insert(k);
            }
            n => panic!("{k:?} ran the field stage {n} times"),
        }
    }
    (ran, bodies)
}

/// The value of an unlabelled or labelled sample line of the `/metrics` text.
fn metric(text: &str, series: &str) -> u64 {
    text.lines()
        .find_map(|l| l.strip_prefix(series)?.strip_prefix(' '))
        .unwrap_or_else(|| panic!("no {series} in /metrics"))
        .parse()
        .expect("integer sample")
}

#[tokio::test]
async fn an_edit_recomputes_only_the_tiles_it_touches() {
    let state = AppState::new(Compute::cpu());
    let app = app(state.clone());
    let (id, token) = create_world(&app, 2024).await;
    let keys = block();
    let all: BTreeSet<TileKey> = keys.iter().copied().collect();

    // First requests: every tile runs each stage once.
    let (ran, v1) = request_block(&app, &state, &id, &keys, 1).await;
    assert_eq!(ran, all);
    let s = state.cache.stats();
    assert_eq!(
        (
            s.runs_of(Stage::Field),
            s.runs_of(Stage::Finish),
            s.runs_of(Stage::Snap)
        ),
        (16, 16, 0)
    );
    assert_eq!((s.misses, s.hits), (16, 0));

    // Again: all hits, no stage runs.
    let (ran, again) = request_block(&app, &state, &id, &keys, 1).await;
    assert!(ran.is_empty(), "re-requests ran {ran:?}");
    assert_eq!(again, v1);
    let s = state.cache.stats();
    // Answered from the encoded-body cache, which sits in front of the stage cache.
    let body_hits = state.bodies.hits.load(std::sync::atomic::Ordering::Relaxed);
    assert_eq!(
        (s.runs_of(Stage::Field), s.misses, s.hits + body_hits),
        (16, 16, 16)
    );

    // A region covering a 1.5 m square at the corner of tiles (1, 1) to (2, 2): the tiles whose
    // footprint plus margin meets it run again, the rest are hits.
    let (min, max) = ([127.0, 127.0], [128.5, 128.5]);
    let v2 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "add", "path": "/regions/-",
                 "value": { "id": "hill", "bbox": { "min": min, "max": max },
                            "ops": [{ "op": "amplify", "center": [127.75, 127.75],
                                      "radius_m": 1, "factor": 1 }] } }]),
    )
    .await;
    assert_eq!(v2, 2);
    let expect = touched(&keys, min, max);
    // The earth-1 margin is two vertex spacings (2 m at LOD 0): the square is in reach of the
    // four tiles around the corner, (1..=2)², and of no other.
    assert_eq!(
        expect,
        (1..=2)
            .flat_map(|x| (1..=2).map(move |z| TileKey { lod: 0, x, z }))
            .collect(),
        "the margin rule as documented (2 spacings at LOD 0)"
    );
    let (ran, bodies) = request_block(&app, &state, &id, &keys, v2).await;
    assert_eq!(
        ran, expect,
        "exactly the touched tiles re-run the field stage"
    );
    assert_eq!(field_runs(&state), 16 + expect.len() as u64);
    // The region's one operation changes nothing (an amplify brush of factor 1: the
    // displacement is exactly 0), so the recomputed tiles equal the old ones.
    assert_eq!(bodies, v1);
    // The old version is still cached under its own hashes.
    let (ran, _) = request_block(&app, &state, &id, &keys, 1).await;
    assert!(ran.is_empty(), "version 1 re-ran {ran:?}");

    // A region just outside the block's north-west corner, within the margin of tile (0, 0),
    // touches only that tile of the block.
    let (min, max) = ([-3.0, -3.0], [-1.0, -1.0]);
    let v3 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "add", "path": "/regions/-",
                 "value": { "id": "corner", "bbox": { "min": min, "max": max } } }]),
    )
    .await;
    let expect = touched(&keys, min, max);
    assert_eq!(expect, BTreeSet::from([TileKey { lod: 0, x: 0, z: 0 }]));
    let before = field_runs(&state);
    let (ran, _) = request_block(&app, &state, &id, &keys, v3).await;
    assert_eq!(ran, expect);
    assert_eq!(field_runs(&state), before + 1);

    // An edit far away (changing an element's fields and box) touches none of them.
    let v4 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "add", "path": "/regions/-",
                 "value": { "id": "far", "bbox": { "min": [5000.0, 5000.0], "max": [5100.0, 5100.0] } } }]),
    )
    .await;
    let (ran, _) = request_block(&app, &state, &id, &keys, v4).await;
    assert!(ran.is_empty(), "a far edit re-ran {ran:?}");

    // Changing the first region's other fields touches the tiles its box reaches.
    let hill = touched(&keys, [127.0, 127.0], [128.5, 128.5]);
    let v5 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "replace", "path": "/regions/0/ops/0/radius_m", "value": 2 }]),
    )
    .await;
    let (ran, _) = request_block(&app, &state, &id, &keys, v5).await;
    assert_eq!(ran, hill);

    // Moving it off the block gives those tiles the inputs they had at version 1 (no element
    // in reach, same settings): the cache is keyed by inputs, not versions, so nothing runs —
    // except tiles the corner region also reaches, whose inputs (corner alone) are new.
    let v6 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "replace", "path": "/regions/0/bbox",
                 "value": { "min": [5000.0, 0.0], "max": [5001.0, 1.0] } }]),
    )
    .await;
    let (ran, bodies) = request_block(&app, &state, &id, &keys, v6).await;
    let corner = touched(&keys, [-3.0, -3.0], [-1.0, -1.0]);
    let new_inputs: BTreeSet<TileKey> = hill.intersection(&corner).copied().collect();
    assert_eq!(
        ran, new_inputs,
        "moving back to version 1's inputs re-ran {ran:?}"
    );
    assert_eq!(bodies, v1);

    // The world settings: every tile runs again, with new bytes.
    let v7 = edit(
        &app,
        &id,
        &token,
        json!([{ "op": "replace", "path": "/world/earth/plain_relief_m", "value": 120.0 }]),
    )
    .await;
    let before = field_runs(&state);
    let (ran, bodies) = request_block(&app, &state, &id, &keys, v7).await;
    assert_eq!(ran, all);
    assert_eq!(field_runs(&state), before + 16);
    assert_ne!(bodies, v1);

    // The counters on /metrics.
    let text = String::from_utf8(get_ok(&app, "/metrics").await).expect("utf8");
    let s = state.cache.stats();
    assert_eq!(
        metric(&text, "strata_stage_runs_total{stage=\"field\"}"),
        s.runs_of(Stage::Field)
    );
    assert_eq!(
        metric(&text, "strata_stage_runs_total{stage=\"finish\"}"),
        s.runs_of(Stage::Finish)
    );
    assert_eq!(
        metric(&text, "strata_stage_cache_hits_total{tier=\"memory\"}"),
        s.hits
    );
    assert_eq!(metric(&text, "strata_stage_cache_misses_total"), s.misses);
    assert_eq!(
        metric(&text, "strata_stage_cache_misses_total"),
        s.runs_of(Stage::Field)
    );
    assert_eq!(metric(&text, "strata_stage_cache_bytes"), s.bytes);
    assert!(s.bytes > 0 && s.bytes <= s.budget_bytes);
}

/// The CPU reference of a tile with seams, encoded.
fn fresh(plan: &WorldPlan, key: TileKey, seams: [bool; 4], format: Format) -> Vec<u8> {
    let mut tile = synthesize(plan, key);
    snap_edges(plan, &mut tile, seams);
    strata::encode::tile(plan, &tile, format, strata::encode::TileVersion::V1)
        .expect("encodes")
        .body
}

#[tokio::test]
async fn cached_bytes_equal_freshly_computed_bytes() {
    let dir = tempfile::tempdir().expect("tempdir");
    let disk_state = || {
        AppState::new(Compute::cpu()).with_cache(
            StageCache::default()
                .with_disk(dir.path())
                .expect("cache dir"),
        )
    };
    let seed = 77;
    let plan = WorldPlan::new(seed, WorldParams::default()).expect("plan");
    let cases = [
        (
            TileKey {
                lod: 0,
                x: -3,
                z: 5,
            },
            [false; 4],
            Format::Bin,
        ),
        (
            TileKey {
                lod: 2,
                x: 1,
                z: -2,
            },
            [true, false, false, true],
            Format::Bin,
        ),
        (
            TileKey { lod: 1, x: 0, z: 0 },
            [false, true, true, false],
            Format::Json,
        ),
        (TileKey { lod: 3, x: 7, z: 7 }, [false; 4], Format::Png),
    ];
    let uri = |k: TileKey, seams: [bool; 4], f: Format| {
        let s = seams.map(|b| if b { "1" } else { "0" }).join(",");
        format!(
            "/v1/seeds/{seed}/tiles/{}/{}/{}.{}?seams={s}",
            k.lod,
            k.x,
            k.z,
            f.extension()
        )
    };

    let state = disk_state();
    let app = app(state.clone());
    for (key, seams, format) in cases {
        let want = fresh(&plan, key, seams, format);
        let computed = get_ok(&app, &uri(key, seams, format)).await;
        let cached = get_ok(&app, &uri(key, seams, format)).await;
        assert_eq!(computed, want, "{key:?} computed");
        assert_eq!(cached, want, "{key:?} from memory");
    }
    let s = state.cache.stats();
    let body_hits = state.bodies.hits.load(std::sync::atomic::Ordering::Relaxed);
    assert_eq!((s.misses, s.hits + body_hits, s.disk_writes), (4, 4, 4));
    assert_eq!(s.runs_of(Stage::Snap), 4, "one strip per seam flag");

    // A world made from the bare seed has the same inputs, so its tiles are the seed's entries.
    let (id, _) = create_world(&app, seed).await;
    let (key, seams, format) = cases[1];
    let world_uri = format!(
        "/v1/worlds/{id}/tiles/{}/{}/{}.bin?v=1&seams=1,0,0,1",
        key.lod, key.x, key.z
    );
    assert_eq!(
        get_ok(&app, &world_uri).await,
        fresh(&plan, key, seams, format)
    );
    assert_eq!(state.cache.stats().misses, 4, "the world's tile was a hit");

    // A new process (empty memory, same directory): every tile comes from disk, bit for bit.
    let state = disk_state();
    let app = strata::server::app(state.clone());
    for (key, seams, format) in cases {
        assert_eq!(
            get_ok(&app, &uri(key, seams, format)).await,
            fresh(&plan, key, seams, format),
            "{key:?} from disk"
        );
    }
    let s = state.cache.stats();
    assert_eq!((s.disk_hits, s.misses, s.runs_of(Stage::Field)), (4, 0, 0));
    // Scatter goes through the same cache: the LOD-0 tile without seams is a memory hit now.
    let (key, _, _) = cases[0];
    get_ok(
        &app,
        &format!(
            "/v1/seeds/{seed}/scatter/{}/{}/{}.json",
            key.lod, key.x, key.z
        ),
    )
    .await;
    assert_eq!(state.cache.stats().runs_of(Stage::Field), 0);
}

/// The one tile synthesis (`edits::tile_jobs` + `edits::assemble`, what `compute` runs) equals the
/// terrain layer's reference (`terrain::synthesize`, then `snap_edges`) bit for bit without edits,
/// for every seam combination, at a LOD with a coarser neighbour and at the coarsest LOD.
#[test]
fn the_one_synthesis_equals_the_terrain_reference_with_seams() {
    let plan = WorldPlan::new(3, WorldParams::default()).expect("plan");
    let none = strata::edits::TileEdits::default();
    for key in [
        TileKey {
            lod: 2,
            x: -1,
            z: 3,
        },
        TileKey {
            lod: strata::terrain::MAX_LOD,
            x: 0,
            z: -1,
        },
    ] {
        for bits in 0..16u8 {
            let seams = [0, 1, 2, 3].map(|i| bits & (1 << i) != 0);
            let mut want = synthesize(&plan, key);
            snap_edges(&plan, &mut want, seams);
            let got = strata::edits::synthesize_with_seams(&plan, key, seams, &none);
            assert_eq!(got, want, "{key:?} seams {seams:?}");
        }
        let strips = strata::edits::tile_jobs(&plan, key, [true; 4]).len() - 1;
        let expected = if key.lod == strata::terrain::MAX_LOD {
            0
        } else {
            4
        };
        assert_eq!(strips, expected, "seam strips of {key:?}");
    }
}

/// Eight concurrent requests of one uncached tile body synthesise and encode it once: the body
/// cache and the stage cache are single-flight, and the seven others are answered by that one
/// computation.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn eight_concurrent_requests_of_one_body_encode_it_once() {
    use std::sync::atomic::Ordering;
    use strata::encode::TileVersion;
    let state = AppState::new(Compute::cpu());
    let view = state.bare_view(11).await.expect("view");
    let key = TileKey {
        lod: 1,
        x: 2,
        z: -3,
    };
    let barrier = std::sync::Arc::new(tokio::sync::Barrier::new(8));
    let requests: Vec<_> = (0..8)
        .map(|_| {
            let (state, view, barrier) = (state.clone(), view.clone(), barrier.clone());
            tokio::spawn(async move {
                barrier.wait().await;
                state
                    .tile_product(&view, key, [false; 4], Format::Bin, TileVersion::V1)
                    .await
                    .expect("product")
            })
        })
        .collect();
    let mut bodies = Vec::new();
    for r in requests {
        bodies.push(r.await.expect("task"));
    }
    assert!(bodies.iter().all(|b| b.body == bodies[0].body));
    assert_eq!(
        state.bodies.misses.load(Ordering::Relaxed),
        1,
        "one encoding"
    );
    assert_eq!(
        state.bodies.hits.load(Ordering::Relaxed),
        7,
        "seven answered by it"
    );
    assert_eq!(
        state.cache.stats().runs_of(Stage::Field),
        1,
        "one synthesis"
    );
}
