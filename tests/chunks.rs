//! Volume chunks (`strata::volume::chunk`, routes in `strata::server::chunks`): same-LOD seams
//! match exactly, cross-LOD seams are closed by skirts within their depth, the HTTP routes
//! validate their input with errors naming the field, answer the same bytes with an immutable
//! content-hash ETag, serve empty chunks as valid empty meshes, and the glb passes the Khronos
//! glTF validator with no errors.

use axum::body::Body;
use axum::http::{header, Method, Request, StatusCode};
use axum::Router;
use http_body_util::BodyExt;
use std::collections::{HashMap, HashSet};
use strata::compute::Compute;
use strata::server::{app, AppState};
use strata::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan};
use strata::volume::chunk::{mesh_chunk, tiles_needed, ChunkKey, ChunkMesh};
use strata::volume::mesh::{QuadMesh, NONE};
use tower::ServiceExt;

mod common;

const SEED: u64 = 7;

struct World {
    plan: WorldPlan,
    tiles: HashMap<TileKey, Tile>,
}

impl World {
    fn new() -> Self {
        Self {
            plan: WorldPlan::new(SEED, WorldParams::default()).expect("default world"),
            tiles: HashMap::new(),
        }
    }

    fn chunk(&mut self, key: ChunkKey) -> ChunkMesh {
        let needed = tiles_needed(key);
        for &(x, z) in &needed {
            let tk = TileKey { lod: key.lod, x, z };
            let plan = &self.plan;
            self.tiles.entry(tk).or_insert_with(|| synthesize(plan, tk));
        }
        let cols = common::columns::columns(key, &self.tiles);
        let s = self.plan.lods[key.lod as usize].spacing_m;
        mesh_chunk(key, s, &cols, &mut QuadMesh::default()).expect("mesh")
    }

    /// The chunk layers `y` whose padded box the ground crosses in chunk column `(x, z)`.
    fn layers(&mut self, lod: u32, x: i64, z: i64) -> std::ops::RangeInclusive<i64> {
        let key = ChunkKey { lod, x, y: 0, z };
        let s = self.plan.lods[lod as usize].spacing_m;
        let mut lo = f32::INFINITY;
        let mut hi = f32::NEG_INFINITY;
        for (tx, tz) in tiles_needed(key) {
            let tk = TileKey { lod, x: tx, z: tz };
            let plan = &self.plan;
            let t = self.tiles.entry(tk).or_insert_with(|| synthesize(plan, tk));
            for &h in &t.heights {
                lo = lo.min(h);
                hi = hi.max(h);
            }
        }
        let layer = |h: f32| (h / (32.0 * s)).floor() as i64;
        layer(lo) - 1..=layer(hi) + 1
    }
}

/// World position of a vertex, metres (exact placement from its global cell and offset).
fn world_pos(m: &ChunkMesh, v: usize, s: f32) -> [f64; 3] {
    std::array::from_fn(|k| (m.global_cells[v][k] as f64 + m.offsets[v][k] as f64) * s as f64)
}

/// Chunks of a 2×2 column block at LOD 0, all layers the ground crosses: shared vertices agree
/// bit for bit, every grid edge is owned once, and the union is a manifold without holes
/// inside the block.
#[test]
fn same_lod_seams_match_exactly() {
    let mut w = World::new();
    let mut chunks = Vec::new();
    for x in 0..2 {
        for z in 0..2 {
            for y in w.layers(0, x, z) {
                let key = ChunkKey { lod: 0, x, y, z };
                chunks.push((key, w.chunk(key)));
            }
        }
    }
    assert!(chunks.iter().map(|(_, m)| m.quads.len()).sum::<usize>() > 2000);
    // Vertices by global cell: identical data wherever they appear.
    let mut vertices: HashMap<[i64; 3], ([u32; 3], [u32; 3], u8)> = HashMap::new();
    let mut shared = 0;
    for (_, m) in &chunks {
        for v in 0..m.positions.len() {
            let data = (
                m.offsets[v].map(f32::to_bits),
                m.normals[v].map(f32::to_bits),
                m.materials[v],
            );
            if let Some(old) = vertices.insert(m.global_cells[v], data) {
                assert_eq!(old, data, "vertex {:?} differs", m.global_cells[v]);
                shared += 1;
            }
        }
    }
    assert!(shared > 100, "chunks share their seam vertices: {shared}");
    // Grid edges: each owned by one chunk.
    let mut edges = HashSet::new();
    for (_, m) in &chunks {
        for (e, c) in m.global_edges.iter().zip(&m.classes) {
            assert!(
                edges.insert((*e, c.axis())),
                "grid edge {e:?} emitted twice"
            );
        }
    }
    // The union as a mesh over global cells: interior mesh edges are shared by two quads with
    // opposite directions (no hole, no duplicate).
    let mut directed: HashMap<([i64; 3], [i64; 3]), usize> = HashMap::new();
    for (_, m) in &chunks {
        for q in &m.quads {
            for k in 0..4 {
                let a = m.global_cells[q[k] as usize];
                let b = m.global_cells[q[(k + 1) % 4] as usize];
                *directed.entry((a, b)).or_default() += 1;
            }
        }
    }
    let inside = |c: [i64; 3]| (1..62).contains(&c[0]) && (1..62).contains(&c[2]);
    let mut interior = 0;
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "directed edge used twice");
        if inside(a) && inside(b) {
            interior += 1;
            assert!(directed.contains_key(&(b, a)), "hole at {a:?}-{b:?}");
        }
    }
    assert!(interior > 1000);
    // Within one chunk, Ptex neighbours are symmetric.
    for (_, m) in &chunks {
        for (q, row) in m.adjacency.iter().enumerate() {
            for (k, n) in row.iter().enumerate() {
                if n.quad != NONE {
                    let back = m.adjacency[n.quad as usize][n.edge as usize];
                    assert_eq!((back.quad as usize, back.edge as usize), (q, k));
                }
            }
        }
    }
}

/// Height of the chunks' surface triangles at `(x, z)` nearest to `near`, if any covers it.
fn surface_height(
    chunks: &[(ChunkKey, ChunkMesh)],
    s: f32,
    x: f64,
    z: f64,
    near: f64,
) -> Option<f64> {
    let mut best: Option<f64> = None;
    for (_, m) in chunks {
        for q in &m.quads {
            for tri in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
                let p = tri.map(|v| world_pos(m, v as usize, s));
                let d = (p[1][0] - p[0][0]) * (p[2][2] - p[0][2])
                    - (p[2][0] - p[0][0]) * (p[1][2] - p[0][2]);
                if d.abs() < 1e-12 {
                    continue;
                }
                let l1 =
                    ((x - p[0][0]) * (p[2][2] - p[0][2]) - (p[2][0] - p[0][0]) * (z - p[0][2])) / d;
                let l2 =
                    ((p[1][0] - p[0][0]) * (z - p[0][2]) - (x - p[0][0]) * (p[1][2] - p[0][2])) / d;
                let eps = 1e-9;
                if l1 < -eps || l2 < -eps || l1 + l2 > 1.0 + eps {
                    continue;
                }
                let y = p[0][1] + l1 * (p[1][1] - p[0][1]) + l2 * (p[2][1] - p[0][1]);
                if best.is_none_or(|b| (y - near).abs() < (b - near).abs()) {
                    best = Some(y);
                }
            }
        }
    }
    best
}

/// The fine column x = 1 (cells 32–63) meets the coarse
/// LOD-1 column x = 1 (LOD-0 cells 64–127) at X = 64 m. Every skirt-bearing vertex on the seam
/// side lies within its skirt depth of the other LOD's surface at the same (x, z).
#[test]
fn cross_lod_seams_are_closed_by_skirts() {
    let mut w = World::new();
    let s0 = w.plan.lods[0].spacing_m;
    let s1 = w.plan.lods[1].spacing_m;
    for (fz, cz) in [(0i64, 0i64), (1, 0), (-1, -1)] {
        let fine: Vec<(ChunkKey, ChunkMesh)> = w
            .layers(0, 1, fz)
            .map(|y| ChunkKey {
                lod: 0,
                x: 1,
                y,
                z: fz,
            })
            .collect::<Vec<_>>()
            .into_iter()
            .map(|k| (k, w.chunk(k)))
            .collect();
        let coarse: Vec<(ChunkKey, ChunkMesh)> = w
            .layers(1, 1, cz)
            .map(|y| ChunkKey {
                lod: 1,
                x: 1,
                y,
                z: cz,
            })
            .collect::<Vec<_>>()
            .into_iter()
            .map(|k| (k, w.chunk(k)))
            .collect();
        let z_range = (
            fz as f64 * 32.0 * s0 as f64,
            (fz + 1) as f64 * 32.0 * s0 as f64,
        );
        let mut checked = 0;
        let mut worst = 0.0f64;
        for (side, own, other, s_own, s_other, seam_cell) in [
            ("fine", &fine, &coarse, s0, s1, 63i64),
            ("coarse", &coarse, &fine, s1, s0, 31i64),
        ] {
            for (_, m) in own.iter() {
                let tops: HashSet<u32> = m.skirt_quads.iter().flat_map(|q| [q[0], q[1]]).collect();
                for &v in &tops {
                    let v = v as usize;
                    if m.global_cells[v][0] != seam_cell {
                        continue;
                    }
                    let p = world_pos(m, v, s_own);
                    if p[2] < z_range.0 + 1.0 || p[2] > z_range.1 - 1.0 {
                        continue;
                    }
                    let Some(y) = surface_height(other, s_other, p[0], p[2], p[1]) else {
                        continue;
                    };
                    let gap = (p[1] - y).abs();
                    worst = worst.max(gap / m.skirt_depth_m as f64);
                    assert!(
                        gap <= m.skirt_depth_m as f64,
                        "{side} seam vertex at {p:?}: other surface at {y}, gap {gap} > skirt {}",
                        m.skirt_depth_m
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked >= 20, "seam vertices checked: {checked}");
        println!(
            "fine z {fz} / coarse z {cz}: {checked} seam vertices, worst gap {:.0}% of the skirt",
            100.0 * worst
        );
    }
}

async fn get(
    app: &Router,
    uri: &str,
    headers: &[(&str, &str)],
) -> (StatusCode, axum::http::HeaderMap, Vec<u8>) {
    let r = common::oneshot::send(app, Method::GET, uri, headers, None).await;
    (r.status, r.headers, r.body)
}

/// A layer `y` holding the ground at the centre of chunk column (0, 0), LOD `lod`.
fn ground_layer(lod: u32) -> i64 {
    ground_layer_at(lod, 0, 0)
}

/// The chunk layer that holds the ground at the middle of chunk column `(x, z)` of `lod`.
fn ground_layer_at(lod: u32, x: i64, z: i64) -> i64 {
    let w = World::new();
    let (gx, gz) = (x * 32 + 16, z * 32 + 16);
    let key = TileKey {
        lod,
        x: gx.div_euclid(64),
        z: gz.div_euclid(64),
    };
    let t = synthesize(&w.plan, key);
    let s = w.plan.lods[lod as usize].spacing_m;
    let v = gz.rem_euclid(64) as usize * 65 + gx.rem_euclid(64) as usize;
    (t.heights[v] / (32.0 * s)).floor() as i64
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn routes_validate_and_cache() {
    let app = app(AppState::new(Compute::cpu()));
    let y = ground_layer(0);
    let uri = format!("/v1/seeds/{SEED}/chunks/0/0/{y}/0.json");
    let (status, h, body) = get(&app, &uri, &[]).await;
    assert_eq!(status, StatusCode::OK, "{}", String::from_utf8_lossy(&body));
    assert_eq!(h[header::CONTENT_TYPE], "application/json");
    assert_eq!(
        h[header::CACHE_CONTROL],
        "public, max-age=31536000, immutable"
    );
    let doc: serde_json::Value = serde_json::from_slice(&body).expect("json");
    assert_eq!(doc["format"], "strata.chunk.v1");
    let q = doc["quad_count"].as_u64().expect("count") as usize;
    assert!(q > 100, "the ground layer has quads: {q}");
    assert_eq!(doc["quads"].as_array().map(Vec::len), Some(4 * q));
    assert_eq!(doc["classes"].as_array().map(Vec::len), Some(q));
    assert_eq!(doc["adjacency"].as_array().map(Vec::len), Some(12 * q));
    // Same URL, same bytes; the ETag answers 304.
    let (_, h2, body2) = get(&app, &uri, &[]).await;
    assert_eq!(body, body2);
    let etag = h2[header::ETAG].to_str().expect("etag").to_string();
    let (status, _, _) = get(&app, &uri, &[("if-none-match", &etag)]).await;
    assert_eq!(status, StatusCode::NOT_MODIFIED);
    // The binary header.
    let (status, h, bin) = get(&app, &format!("/v1/seeds/{SEED}/chunks/0/0/{y}/0.bin"), &[]).await;
    assert_eq!(status, StatusCode::OK);
    assert_eq!(h[header::CONTENT_TYPE], "application/vnd.strata.chunk.v1");
    assert_eq!(&bin[..4], b"STCK");
    assert_eq!(u32::from_le_bytes(bin[4..8].try_into().expect("4")), 1);
    assert_eq!(
        u32::from_le_bytes(bin[84..88].try_into().expect("4")) as usize,
        q
    );
    let v = u32::from_le_bytes(bin[80..84].try_into().expect("4")) as usize;
    let (sv, sq) = (
        u32::from_le_bytes(bin[88..92].try_into().expect("4")) as usize,
        u32::from_le_bytes(bin[92..96].try_into().expect("4")) as usize,
    );
    let pad = |n: usize| n.div_ceil(4) * 4;
    let want = 96 + 24 * v + pad(v) + 16 * q + pad(q) + 32 * q + 24 * q + 12 * sv + 16 * sq;
    assert_eq!(bin.len(), want, "bin length follows the spec");
    // Empty chunks: far above and far below the ground.
    for (yy, what) in [(400i64, "air"), (-400, "solid")] {
        let (status, _, body) = get(
            &app,
            &format!("/v1/seeds/{SEED}/chunks/0/0/{yy}/0.json"),
            &[],
        )
        .await;
        assert_eq!(status, StatusCode::OK, "{what}");
        let doc: serde_json::Value = serde_json::from_slice(&body).expect("json");
        assert_eq!(doc["quad_count"], 0, "{what}");
        assert_eq!(doc["vertex_count"], 0, "{what}");
    }
    // Errors name the field.
    for (uri, field, status) in [
        (format!("/v1/seeds/{SEED}/chunks/4/0/0/0.json"), "lod", 400),
        (format!("/v1/seeds/{SEED}/chunks/x/0/0/0.json"), "lod", 400),
        (format!("/v1/seeds/{SEED}/chunks/0/1.5/0/0.json"), "x", 400),
        (format!("/v1/seeds/{SEED}/chunks/0/0/512/0.json"), "y", 400),
        (format!("/v1/seeds/{SEED}/chunks/3/0/-64/0.json"), "y", 400),
        (
            format!("/v1/seeds/{SEED}/chunks/0/0/0/99999999.json"),
            "z",
            400,
        ),
        (
            format!("/v1/seeds/{SEED}/chunks/0/0/0/0.png"),
            "format",
            400,
        ),
        (format!("/v1/seeds/{SEED}/chunks/0/0/0/0"), "format", 400),
        ("/v1/seeds/-1/chunks/0/0/0/0.json".to_string(), "seed", 400),
    ] {
        let (s, h, body) = get(&app, &uri, &[]).await;
        assert_eq!(s.as_u16(), status, "{uri}");
        assert!(h[header::CONTENT_TYPE]
            .to_str()
            .expect("ct")
            .starts_with("application/json"));
        let e: serde_json::Value = serde_json::from_slice(&body).expect("json error");
        assert_eq!(e["error"]["field"], field, "{uri}: {e}");
    }
    // The edge of the world is accepted, one beyond is not.
    // |x|, |z| ≤ 2·max_tile_coord(lod) − 1 = 2·2047 − 1 at LOD 3 (the tiles' world edge).
    let (s, _, body) = get(
        &app,
        &format!("/v1/seeds/{SEED}/chunks/3/4093/0/-4093.bin"),
        &[],
    )
    .await;
    assert_eq!(s, StatusCode::OK, "{}", String::from_utf8_lossy(&body));
    for (uri, field) in [
        (format!("/v1/seeds/{SEED}/chunks/3/4094/0/0.bin"), "x"),
        (format!("/v1/seeds/{SEED}/chunks/3/0/0/-4094.bin"), "z"),
    ] {
        let (s, _, body) = get(&app, &uri, &[]).await;
        assert_eq!(s, StatusCode::BAD_REQUEST);
        let e: serde_json::Value = serde_json::from_slice(&body).expect("json error");
        assert_eq!(e["error"]["field"], field);
        assert_eq!(e["error"]["code"], "coordinate_out_of_range");
    }
    // |y| ≤ 16384 / (32·2^lod) − 1 = 63 at LOD 3.
    let (s, _, _) = get(&app, &format!("/v1/seeds/{SEED}/chunks/3/0/64/0.json"), &[]).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    let (s, _, _) = get(
        &app,
        &format!("/v1/seeds/{SEED}/chunks/3/0/-63/0.json"),
        &[],
    )
    .await;
    assert_eq!(s, StatusCode::OK);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn world_chunks_are_served() {
    let app = app(AppState::new(Compute::cpu()));
    let req = Request::builder()
        .method(Method::POST)
        .uri("/v1/worlds")
        .header(header::CONTENT_TYPE, "application/json")
        .body(Body::from(format!(r#"{{"seed": {SEED}, "public": true}}"#)))
        .expect("request");
    let res = app.clone().oneshot(req).await.expect("infallible");
    let status = res.status();
    let body = res.into_body().collect().await.expect("body").to_bytes();
    assert!(
        status.is_success(),
        "{status}: {}",
        String::from_utf8_lossy(&body)
    );
    let doc: serde_json::Value = serde_json::from_slice(&body).expect("json");
    let id = doc["id"].as_str().expect("id").to_string();
    let y = ground_layer(1);
    let (s, h, world_body) = get(
        &app,
        &format!("/v1/worlds/{id}/chunks/1/0/{y}/0.json?v=1"),
        &[],
    )
    .await;
    assert_eq!(
        s,
        StatusCode::OK,
        "{}",
        String::from_utf8_lossy(&world_body)
    );
    assert!(h[header::CACHE_CONTROL]
        .to_str()
        .expect("cc")
        .contains("immutable"));
    // An unedited world's chunk is the seed's chunk.
    let (_, _, seed_body) = get(
        &app,
        &format!("/v1/seeds/{SEED}/chunks/1/0/{y}/0.json"),
        &[],
    )
    .await;
    assert_eq!(world_body, seed_body);
    let (s, _, body) = get(
        &app,
        &format!("/v1/worlds/{id}/chunks/1/0/{y}/0.json?v=9"),
        &[],
    )
    .await;
    assert_eq!(
        s,
        StatusCode::NOT_FOUND,
        "{}",
        String::from_utf8_lossy(&body)
    );
    let e: serde_json::Value = serde_json::from_slice(&body).expect("JSON error");
    assert_eq!(
        (e["error"]["code"].as_str(), e["error"]["field"].as_str()),
        (Some("version_not_found"), Some("v")),
        "{e}"
    );
    // The version query is refused as on the tile routes: not a number, zero, or more than 19
    // digits (leading zeros included).
    for bad in ["x", "0", "00000000000000000001", ""] {
        let (s, _, body) = get(
            &app,
            &format!("/v1/worlds/{id}/chunks/1/0/{y}/0.json?v={bad}"),
            &[],
        )
        .await;
        assert_eq!(s, StatusCode::BAD_REQUEST, "v={bad}");
        let e: serde_json::Value = serde_json::from_slice(&body).expect("JSON error");
        assert_eq!(
            (e["error"]["code"].as_str(), e["error"]["field"].as_str()),
            (Some("bad_version"), Some("v")),
            "v={bad}: {e}"
        );
    }
    let (s, _, _) = get(&app, "/v1/worlds/nope/chunks/1/0/0/0.json", &[]).await;
    assert_eq!(s, StatusCode::NOT_FOUND);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn glb_chunks_pass_the_khronos_validator() {
    let app = app(AppState::new(Compute::cpu()));
    let mut files = Vec::new();
    for lod in [0u32, 2, 3] {
        let (y, y2) = (ground_layer(lod), ground_layer_at(lod, -3, 2));
        for (x, yy, z) in [(0, y, 0), (-3, y2, 2), (0, 400 >> lod, 0)] {
            let (s, _, body) = get(
                &app,
                &format!("/v1/seeds/{SEED}/chunks/{lod}/{x}/{yy}/{z}.glb"),
                &[],
            )
            .await;
            assert_eq!(s, StatusCode::OK);
            files.push((format!("chunk_{lod}_{x}_{yy}_{z}.glb"), body));
        }
    }
    let reports = common::gltf::validate("chunks", &files);
    for r in &reports {
        assert_eq!(r["errors"], 0, "validator errors: {r}");
    }
    assert!(
        reports
            .iter()
            .filter(|r| r["triangles"].as_u64().unwrap_or(0) > 100)
            .count()
            >= 6,
        "ground chunks have triangles"
    );
}
