//! Ptex pages of volume chunks over stream protocol v2 (`api/stream_protocol_v2.md`, "Ptex
//! pages"), with a real client (tokio-tungstenite) against the app on a real socket, in a world
//! with the arch volume element: a client that asks for them (`ptex.chunks`) gets a vista page
//! for every face (surface-nets quad) of every chunk it holds, in frames naming chunk faces,
//! within its session's budget, byte for byte the pages of the HTTP chunk route at the same
//! version, and detail pages for the nearest, 16² at most (a quad is one lattice cell); an edit that sends a chunk again sends its faces'
//! pages again at the new version; a client that does not ask gets tile faces only; a budget
//! that cannot hold a chunk's faces holds none of them and says so once.

use futures::StreamExt;
use serde_json::{json, Value};
use std::collections::{HashMap, HashSet};
use std::time::Duration;
use strata::edits::{synthesize, TileEdits};
use strata::ptex::budget::page_bytes;
use strata::stream::protocol::ChunkFrame;
use strata::stream::ptex::{chunk_frame_quads, PageFace, PtexSettings, CHUNK_FACE_MAX_LEVEL};
use strata::stream::ptex_frame::{decode, PtexFrame};
use strata::terrain::{TileKey, WorldParams, WorldPlan};
use strata::volume::chunk::ChunkKey;
use tokio_tungstenite::tungstenite::Message;

mod common;

use common::ws::{connect, create_world, send, serve_ptex, Ws};

const SEED: u64 = 7;

fn ground_at(x: i64, z: i64) -> f32 {
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let t = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[(z * 65 + x) as usize]
}

/// A public world of seed 7 with the arch standing at (32, 24); its id and admin token.
async fn arch_world(addr: &str) -> (String, String) {
    let arch = common::arch::arch_element(ground_at(32, 24));
    create_world(addr, SEED, Some(json!({"volumes": [arch]}))).await
}

/// What arrives until `idle`.
#[derive(Default)]
struct Received {
    /// The chunk frames' chunks, their quad counts and versions.
    chunks: Vec<(ChunkKey, u32, u64)>,
    ptex: Vec<PtexFrame>,
    msgs: Vec<Value>,
}

async fn until_idle(ws: &mut Ws) -> Received {
    let mut got = Received::default();
    loop {
        let m = tokio::time::timeout(Duration::from_secs(300), ws.next())
            .await
            .expect("a message in time")
            .expect("stream open")
            .expect("message");
        match m {
            Message::Binary(b) => {
                if let Some(c) = ChunkFrame::decode(&b) {
                    let quads = chunk_frame_quads(&b).expect("a bin chunk's quad count");
                    got.chunks.push((c.key, quads, c.version));
                } else if let Some(p) = decode(&b) {
                    got.ptex.push(p);
                }
            }
            Message::Text(t) => {
                let v: Value = serde_json::from_str(&t).expect("JSON");
                let idle = v["type"] == "idle";
                got.msgs.push(v);
                if idle {
                    return got;
                }
            }
            _ => {}
        }
    }
}

/// The page of face `id` in a pack of `api/ptex_pages_v1.md`: albedo, normal, displacement.
fn pack_page(pack: &[u8], id: usize) -> (Vec<u8>, Vec<u8>, Vec<u8>) {
    let u32_at =
        |o: usize| u32::from_le_bytes(pack[o..o + 4].try_into().expect("4 bytes")) as usize;
    let (faces, side) = (u32_at(52), u32_at(56));
    let per = side * side * 4;
    let planes = 64 + faces * 40;
    let plane = |p: usize| pack[planes + p * faces * per + id * per..][..per].to_vec();
    (plane(0), plane(1), plane(2))
}

/// Page `k` of a frame: albedo, normal, displacement (the pack's byte layout).
fn frame_page(frame: &PtexFrame, k: usize) -> (Vec<u8>, Vec<u8>, Vec<u8>) {
    let per = frame.pages.texels_per_face();
    let t = k * per..(k + 1) * per;
    (
        frame.pages.albedo[t.clone()].concat(),
        frame.pages.normal[t.clone()].concat(),
        frame.pages.displacement[t]
            .iter()
            .flat_map(|d| d.to_le_bytes())
            .collect(),
    )
}

async fn http_pack(addr: &str, id: &str, key: ChunkKey, res: u32, v: u64) -> Vec<u8> {
    let path = format!(
        "/v1/worlds/{id}/ptex/{}/{}/{}/{}?res={res}&v={v}",
        key.lod, key.x, key.y, key.z
    );
    let (status, body) = strata::bench::http::http(addr, "GET", &path, &[], "")
        .await
        .expect("HTTP");
    assert_eq!(status, 200, "{path}: {}", String::from_utf8_lossy(&body));
    body
}

/// The chunk pages of `frames`: (chunk, quad) → (level, frame index, page index).
fn chunk_pages(frames: &[PtexFrame]) -> Vec<(ChunkKey, u32, u8, usize, usize)> {
    let mut out = Vec::new();
    for (i, f) in frames.iter().enumerate() {
        for (k, r) in f.records.iter().enumerate() {
            if let PageFace::Chunk(c) = r.face {
                out.push((c.chunk, c.quad, f.level, i, k));
            }
        }
    }
    out
}

/// The view over the arch from `y`, with two rings of LOD-0 chunks unless `tiles_only`, asking
/// for chunk faces' pages when `chunks`.
fn view(y: f64, chunks: bool, tiles_only: bool) -> Value {
    let rings: &[u32] = if tiles_only { &[] } else { &[2] };
    json!({"type": "view", "x": 32, "z": 24, "y": y, "rings": [1], "chunk_rings": rings,
           "ptex": {"forward": [0.0, -0.5, -1.0], "half_angle_deg": 45, "far_m": 2000, "chunks": chunks}})
}

/// Most texels one HTTP Ptex request may bake (`max_ptex_texels` of `/v1/info`): the route
/// serves a chunk's pages at `res` only when `res² × quads` is within it.
const MAX_HTTP_TEXELS: u64 = 1 << 20;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_face_of_the_held_chunks_gets_the_http_routes_page_within_the_budget() {
    let settings = PtexSettings::default();
    let (addr, id, mut ws) = open_session(settings).await;
    let y = f64::from(ground_at(32, 24)) + 40.0;
    send(&mut ws, view(y, true, false)).await;
    let got = until_idle(&mut ws).await;
    for m in &got.msgs {
        assert_ne!(m["type"], "error", "{m}");
    }
    assert!(!got.chunks.is_empty(), "the arch's chunks arrive");
    let quads: HashMap<ChunkKey, u32> = got.chunks.iter().map(|c| (c.0, c.1)).collect();
    let total: u32 = quads.values().sum();
    assert!(total > 0, "the arch's chunks have quads");
    let pages = chunk_pages(&got.ptex);
    // Every face of every held chunk has its vista page, once.
    let vista: HashSet<(ChunkKey, u32)> = pages
        .iter()
        .filter(|p| p.2 == 0)
        .map(|p| (p.0, p.1))
        .collect();
    let want: HashSet<(ChunkKey, u32)> = quads
        .iter()
        .flat_map(|(&k, &q)| (0..q).map(move |i| (k, i)))
        .collect();
    assert_eq!(vista, want, "a vista page for each face of each chunk");
    assert_eq!(
        pages.iter().filter(|p| p.2 == 0).count(),
        total as usize,
        "each vista page once"
    );
    // Frames hold one kind of face.
    for f in &got.ptex {
        let chunk = f.records.iter().filter(|r| r.face.is_chunk()).count();
        assert!(
            chunk == 0 || chunk == f.records.len(),
            "a frame mixes faces"
        );
    }
    // Detail pages for the nearest faces, chunk faces among them (the camera is 40 m above the
    // arch, within every level's threshold), at 16² only (a quad's finest level); the finer
    // levels go to tile faces.
    assert!(
        pages.iter().any(|p| p.2 > 0),
        "some chunk face gets a detail page"
    );
    assert!(
        pages.iter().all(|p| p.2 <= CHUNK_FACE_MAX_LEVEL),
        "a chunk face holds 16² at most"
    );
    assert!(
        got.ptex
            .iter()
            .any(|f| f.level > CHUNK_FACE_MAX_LEVEL && !f.records.is_empty()),
        "the finer levels go to tile faces"
    );
    // Within the budget: what the client holds (the last `ptex` message's count) and every page
    // it received fit the session's bytes.
    let last = got
        .msgs
        .iter()
        .rev()
        .find(|m| m["type"] == "ptex")
        .expect("a ptex message");
    let budget = last["budget_bytes"].as_u64().expect("budget");
    assert_eq!(budget, settings.session_bytes);
    assert!(
        last["held_bytes"].as_u64().expect("held") <= budget,
        "{last}"
    );
    let tile_faces = got
        .ptex
        .iter()
        .filter(|f| f.level == 0)
        .flat_map(|f| f.records.iter())
        .filter(|r| !r.face.is_chunk())
        .count();
    assert_eq!(
        last["faces"].as_u64().expect("faces") as usize,
        tile_faces + total as usize,
        "the budget holds the tiles' and the chunks' faces"
    );
    let received: u64 = got
        .ptex
        .iter()
        .map(|f| f.records.len() as u64 * page_bytes(f.pages.res))
        .sum();
    assert!(received <= budget, "{received} bytes of pages > {budget}");
    // Byte for byte the HTTP route's pages, at each level that came and the route serves for
    // the chunk (the vista level always), for every chunk.
    let mut compared = 0;
    for (key, q) in &quads {
        for level in 0..=5u8 {
            let of_level: Vec<_> = pages
                .iter()
                .filter(|p| p.0 == *key && p.2 == level)
                .collect();
            if of_level.is_empty() {
                continue;
            }
            let res = got.ptex[of_level[0].3].pages.res;
            if u64::from(res * res) * u64::from(*q) > MAX_HTTP_TEXELS {
                continue;
            }
            compared += of_level.len();
            let pack = http_pack(&addr, &id, *key, res, 1).await;
            for p in of_level {
                assert_eq!(
                    frame_page(&got.ptex[p.3], p.4),
                    pack_page(&pack, p.1 as usize),
                    "{key:?} quad {} at {res}²: the HTTP route's page",
                    p.1
                );
            }
        }
    }
    assert!(compared >= total as usize, "every vista page compared");

    // An edit in the arch's box: the chunks it touches come again, and so do their faces'
    // vista pages, at version 2.
    let patch = json!([{"op": "add", "path": "/regions/-",
                        "value": {"id": "r1", "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    send(
        &mut ws,
        json!({"type": "edit", "id": "e1", "patch": patch, "if_match": 1}),
    )
    .await;
    let fresh = until_idle(&mut ws).await;
    assert!(!fresh.chunks.is_empty(), "the edit sends chunks again");
    let again = chunk_pages(&fresh.ptex);
    for (key, q, v) in &fresh.chunks {
        assert_eq!(*v, 2);
        let vista = again.iter().filter(|p| p.0 == *key && p.2 == 0).count();
        assert_eq!(vista, *q as usize, "{key:?}: every face's vista page again");
        let pack = http_pack(&addr, &id, *key, 8, 2).await;
        for p in again.iter().filter(|p| p.0 == *key && p.2 == 0) {
            assert_eq!(fresh.ptex[p.3].version, 2);
            assert_eq!(
                frame_page(&fresh.ptex[p.3], p.4),
                pack_page(&pack, p.1 as usize)
            );
        }
    }
}

/// A server with `settings`, the arch world on it, and a protocol-2 session to it that has
/// said hello and been granted 1,024 frames: the server's address, the world's id, the socket.
async fn open_session(settings: PtexSettings) -> (String, String, Ws) {
    let addr = serve_ptex(settings).await;
    let (id, token) = arch_world(&addr).await;
    let path = format!("/v1/worlds/{id}/stream?protocol=2&token={token}");
    let mut ws = connect(&addr, &path).await;
    until_hello(&mut ws).await;
    send(&mut ws, json!({"type": "credit", "frames": 1024})).await;
    (addr, id, ws)
}

async fn until_hello(ws: &mut Ws) {
    loop {
        let m = tokio::time::timeout(Duration::from_secs(30), ws.next())
            .await
            .expect("hello in time")
            .expect("stream open")
            .expect("message");
        if let Message::Text(t) = m {
            let v: Value = serde_json::from_str(&t).expect("JSON");
            if v["type"] == "hello" {
                return;
            }
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_does_not_ask_gets_tile_faces_only_and_a_small_budget_holds_no_chunk() {
    // Without `chunks`, as clients before chunk pages: no chunk face is held or sent.
    let (_, _, mut ws) = open_session(PtexSettings::default()).await;
    let y = f64::from(ground_at(32, 24)) + 40.0;
    send(&mut ws, view(y, false, false)).await;
    let got = until_idle(&mut ws).await;
    assert!(!got.chunks.is_empty(), "the arch's chunks arrive");
    assert!(!got.ptex.is_empty(), "tile pages arrive");
    assert!(
        chunk_pages(&got.ptex).is_empty(),
        "no chunk page for a client that did not ask"
    );
    let tiles = got
        .ptex
        .iter()
        .filter(|f| f.level == 0)
        .map(|f| f.records.len())
        .sum::<usize>();
    let last = got
        .msgs
        .iter()
        .rev()
        .find(|m| m["type"] == "ptex")
        .expect("ptex");
    assert_eq!(last["faces"].as_u64().expect("faces") as usize, tiles);

    // A budget that holds the view's tile faces and half the largest chunk's: the tiles are held
    // first (a view without chunks), then the chunks come; the largest does not fit and none of
    // its faces is held or sent, and the session says so once.
    let quads = got.chunks.iter().map(|c| c.1).max().expect("a chunk");
    let small = PtexSettings {
        session_bytes: (tiles as u64 + u64::from(quads) / 2) * page_bytes(8),
        server_bytes: 1 << 30,
        ..PtexSettings::default()
    };
    let (_, _, mut ws) = open_session(small).await;
    send(&mut ws, view(y, true, true)).await;
    let first = until_idle(&mut ws).await;
    assert!(first.chunks.is_empty(), "no chunk rings, no chunks");
    send(&mut ws, view(y, true, false)).await;
    let got = until_idle(&mut ws).await;
    let msgs: Vec<&Value> = first.msgs.iter().chain(&got.msgs).collect();
    let refusals = msgs
        .iter()
        .filter(|m| m["type"] == "error" && m["code"] == "ptex_budget_exceeded")
        .count();
    assert_eq!(refusals, 1, "one refusal: {msgs:?}");
    let pages = chunk_pages(&got.ptex);
    let with_pages: HashSet<ChunkKey> = pages.iter().map(|p| p.0).collect();
    for k in &with_pages {
        let q = got.chunks.iter().find(|c| c.0 == *k).expect("held").1;
        let vista = pages.iter().filter(|p| p.0 == *k && p.2 == 0).count();
        assert_eq!(vista, q as usize, "{k:?}: all of a chunk's faces or none");
    }
    let largest = got
        .chunks
        .iter()
        .find(|c| c.1 == quads)
        .expect("the largest")
        .0;
    assert!(
        !with_pages.contains(&largest),
        "the largest chunk's faces do not fit"
    );
    let tile_pages = first
        .ptex
        .iter()
        .filter(|f| f.level == 0)
        .map(|f| f.records.len())
        .sum::<usize>();
    assert_eq!(tile_pages, tiles, "the tiles' faces all fit first");
}
