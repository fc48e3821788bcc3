//! Ptex pages over HTTP (`strata::server::ptex_routes`, `api/ptex_pages_v1.md`) and `.ptx`
//! exports (`strata::encode::ptx`).
//!
//! - The tile and chunk routes answer the pack the library bakes for the key, the same bytes
//!   twice with a content-hash ETag, and refuse bad `res`, keys and over-budget bakes with errors
//!   naming the field.
//! - A `.ptx` written by an export is read back by the reader below, written from the published
//!   "Ptex File Format Specification" 1.3r1 (ptex.us/PtexFile.html), not from the writer: header,
//!   extended header, face info with adjacency, constant data, level info and every level's
//!   data, with level-0 texels equal to the HTTP pages' interior texels.

use axum::http::{Method, StatusCode};
use axum::Router;
use flate2::read::ZlibDecoder;
use std::io::Read;
use strata::compute::Compute;
use strata::encode::ptex::{encode, PackInfo, PackKind};
use strata::export::{members, ExportSpec, Product};
use strata::ptex::face::TileFacePlan;
use strata::ptex::{bake, MaterialSet, Pages};
use strata::server::ptex_routes::MAX_REQUEST_TEXELS;
use strata::server::{app, AppState};
use strata::terrain::tile::{synthesize, TileKey};
use strata::terrain::world::WorldParams;
use strata::terrain::WorldPlan;

mod common;

const SEED: u64 = 5;

async fn get(app: &Router, uri: &str) -> common::oneshot::Reply {
    common::oneshot::send::<&str>(app, Method::GET, uri, &[], None).await
}

fn u32_at(b: &[u8], o: usize) -> u32 {
    u32::from_le_bytes(b[o..o + 4].try_into().expect("4 bytes"))
}

fn u64_at(b: &[u8], o: usize) -> u64 {
    u64::from_le_bytes(b[o..o + 8].try_into().expect("8 bytes"))
}

fn f32_at(b: &[u8], o: usize) -> f32 {
    f32::from_le_bytes(b[o..o + 4].try_into().expect("4 bytes"))
}

/// The library's pack of tile `key` (no seams) at `res`.
fn library_tile_pack(plan: &WorldPlan, key: TileKey, res: u32) -> Vec<u8> {
    let faces = TileFacePlan::new(key, [false; 4], plan.lods.len() as u32 - 1);
    let tiles: Vec<_> = faces
        .tiles()
        .into_iter()
        .map(|t| synthesize(plan, t))
        .collect();
    let mats = MaterialSet::default_ground(plan.seed);
    let set = faces.build(|t| tiles.iter().find(|x| x.key == t), &mats, plan);
    let mut pages = Pages::default();
    bake(&set, &mats, res, &mut pages);
    let info = PackInfo {
        kind: PackKind::Tile,
        lod: key.lod,
        key: [key.x, 0, key.z],
        seed: plan.seed,
    };
    encode(&info, &set, &[], &pages)
}

/// The interior texels of face `f` of a pack, as `(albedo, normal, displacement)`.
fn pack_interior(pack: &[u8], f: usize) -> Vec<([u8; 4], [u8; 4], f32)> {
    let (r, faces, side) = (
        u32_at(pack, 48) as usize,
        u32_at(pack, 52) as usize,
        u32_at(pack, 56) as usize,
    );
    let per = side * side;
    let planes = 64 + 40 * faces;
    let mut out = Vec::new();
    for j in 0..r {
        for i in 0..r {
            let t = f * per + (j + 1) * side + i + 1;
            let a = planes + 4 * t;
            let n = planes + 4 * faces * per + 4 * t;
            let d = planes + 8 * faces * per + 4 * t;
            out.push((
                pack[a..a + 4].try_into().expect("4"),
                pack[n..n + 4].try_into().expect("4"),
                f32_at(pack, d),
            ));
        }
    }
    out
}

#[tokio::test]
async fn tile_pages_are_the_library_bake_and_bad_input_names_the_field() {
    let app = app(AppState::new(Compute::cpu()));
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let key = TileKey {
        lod: 0,
        x: 3,
        z: -2,
    };
    let uri = format!("/v1/seeds/{SEED}/ptex/tiles/0/3/-2?res=16");
    let a = get(&app, &uri).await;
    a.ok();
    assert_eq!(
        a.header("content-type"),
        Some("application/vnd.strata.ptex.v1")
    );
    assert_eq!(&a.body[..4], b"STPX");
    assert_eq!((u32_at(&a.body, 48), u32_at(&a.body, 52)), (16, 16));
    assert_eq!(a.body, library_tile_pack(&plan, key, 16));
    let b = get(&app, &uri).await;
    assert_eq!(a.body, b.body, "same URL, same bytes");
    assert!(a.header("etag").is_some());
    // Errors name the field.
    for (q, field) in [
        ("", "res"),
        ("?res=12", "res"),
        ("?res=512", "res"),
        ("?res=16&res=16", "res"),
    ] {
        get(&app, &format!("/v1/seeds/{SEED}/ptex/tiles/0/3/-2{q}"))
            .await
            .error(StatusCode::BAD_REQUEST, "bad_parameter", Some(field));
    }
    get(
        &app,
        &format!("/v1/seeds/{SEED}/ptex/tiles/0/3/-2?res=16&seams=1,0"),
    )
    .await
    .error(StatusCode::BAD_REQUEST, "bad_seams", Some("seams"));
    get(
        &app,
        &format!("/v1/seeds/{SEED}/ptex/tiles/0/99999999/0?res=16"),
    )
    .await
    .error(
        StatusCode::BAD_REQUEST,
        "coordinate_out_of_range",
        Some("x"),
    );
}

#[tokio::test]
async fn chunk_pages_have_a_face_per_quad_and_big_bakes_are_refused_before_baking() {
    let app = app(AppState::new(Compute::cpu()));
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    // The chunk layer holding the ground at the middle of chunk column (0, 0).
    let tile = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 });
    let h = tile.heights[16 * 65 + 16];
    let y = (h / 32.0).floor() as i64;
    let chunk = get(&app, &format!("/v1/seeds/{SEED}/chunks/0/0/{y}/0.json")).await;
    chunk.ok();
    let quads = chunk.json()["quad_count"].as_u64().expect("quad_count") as u32;
    assert!(quads > 100, "{quads} quads");
    let p = get(&app, &format!("/v1/seeds/{SEED}/ptex/0/0/{y}/0?res=8")).await;
    p.ok();
    assert_eq!(u32_at(&p.body, 8), 0, "kind: volume chunk");
    assert_eq!(u32_at(&p.body, 52), quads, "a face per quad");
    let side = 10usize;
    assert_eq!(
        p.body.len(),
        64 + 40 * quads as usize + 12 * side * side * quads as usize
    );
    // Face ids are quad indices, classes the quads'.
    let json = chunk.json();
    for q in 0..quads as usize {
        let rec = 64 + 40 * q;
        assert_eq!(u32_at(&p.body, rec) as usize, q);
        assert_eq!(
            u64::from(p.body[rec + 4]),
            json["classes"][q].as_u64().expect("class")
        );
    }
    // 128² texels per face for every quad is over the budget: refused, naming res, the limit
    // and the largest res that fits.
    let too_big = get(&app, &format!("/v1/seeds/{SEED}/ptex/0/0/{y}/0?res=128")).await;
    too_big.error(StatusCode::BAD_REQUEST, "ptex_too_large", Some("res"));
    let message = too_big.json()["error"]["message"]
        .as_str()
        .expect("message")
        .to_string();
    let fits = (0..6)
        .map(|k| 128u64 >> k)
        .find(|r| r * r * u64::from(quads) <= MAX_REQUEST_TEXELS)
        .expect("some res fits");
    assert!(
        message.contains(&MAX_REQUEST_TEXELS.to_string())
            && message.contains(&format!("res {fits} fits")),
        "{message}"
    );
    get(&app, &format!("/v1/seeds/{SEED}/ptex/4/0/0/0?res=8"))
        .await
        .error(StatusCode::BAD_REQUEST, "lod_out_of_range", Some("lod"));
}

/// An edit of world `id`: the JSON Patch `patch` posted as the bearer of `token`.
async fn edit(app: &Router, id: &str, token: &str, patch: serde_json::Value) {
    let headers = [
        ("authorization", format!("Bearer {token}")),
        ("content-type", "application/json-patch+json".to_string()),
    ];
    let uri = format!("/v1/worlds/{id}/edits");
    let r = common::oneshot::send(
        app,
        Method::POST,
        &uri,
        &headers,
        Some(patch.to_string().as_bytes()),
    )
    .await;
    assert!(r.status.is_success(), "{:?}", r.status);
}

/// An authored region of `side` metres centred on `(x, z)` that raises its centre to 300 m.
fn peak(id: &str, x: f64, z: f64, side: f64) -> serde_json::Value {
    serde_json::json!([{"op": "add", "path": "/regions/-", "value": {
        "id": id,
        "bbox": {"min": [x - side / 2.0, z - side / 2.0], "max": [x + side / 2.0, z + side / 2.0]},
        "samples": 65,
        "ops": [{"op": "elevation", "shape": {"point": [x, z]}, "elevation_m": 300, "radius_m": 40}]
    }}])
}

#[tokio::test]
async fn a_chunk_is_meshed_once_for_its_formats_and_pages_and_again_only_when_an_edit_meets_it() {
    let st = AppState::new(Compute::cpu());
    let app = app(st.clone());
    let (id, token) = common::oneshot::private_world(&app, SEED).await;
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let tile = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 });
    let y = (tile.heights[16 * 65 + 16] / 32.0).floor() as i64;
    let at = |v: u64, what: &str| format!("/v1/worlds/{id}/{what}?v={v}");
    let misses = || st.chunk_meshes.stats().misses;
    // Three formats and two page resolutions of one chunk: one meshing.
    let mut bodies = Vec::new();
    for what in [
        format!("chunks/0/0/{y}/0.json"),
        format!("chunks/0/0/{y}/0.bin"),
        format!("ptex/0/0/{y}/0"),
    ] {
        for res in ["8", "16"] {
            let uri = format!("{}&res={res}", at(1, &what));
            let r = common::oneshot::get_as(&app, &uri, &token).await;
            r.ok();
            bodies.push((uri, r.body));
        }
    }
    assert_eq!(misses(), 1, "one chunk, meshed once");
    assert!(st.chunk_meshes.stats().hits >= 5);
    assert!(st.chunk_meshes.stats().bytes > 0);
    // The cache changes no byte: a server that has not meshed the chunk answers the same.
    let mut fresh = AppState::new(Compute::cpu());
    fresh.worlds = st.worlds.clone();
    let fresh_app = strata::server::app(fresh);
    for (uri, body) in &bodies {
        let r = common::oneshot::get_as(&fresh_app, uri, &token).await;
        r.ok();
        assert_eq!(&r.body, body, "{uri}");
    }
    // An edit 4 km away keeps the mesh; one over the chunk meshes it again.
    edit(&app, &id, &token, peak("far", 4096.0, 4096.0, 512.0)).await;
    let pages = format!("{}&res=8", at(2, &format!("ptex/0/0/{y}/0")));
    common::oneshot::get_as(&app, &pages, &token).await.ok();
    assert_eq!(misses(), 1, "an edit elsewhere keeps the chunk's mesh");
    edit(&app, &id, &token, peak("near", 16.0, 16.0, 1024.0)).await;
    let chunk = at(3, &format!("chunks/0/0/{y}/0.json"));
    common::oneshot::get_as(&app, &chunk, &token).await.ok();
    assert_eq!(misses(), 2, "an edit over the chunk meshes it again");
}

#[tokio::test]
async fn a_tile_page_costs_at_most_the_stated_texels_and_info_states_the_limits() {
    let app = app(AppState::new(Compute::cpu()));
    let info = get(&app, "/v1/info").await;
    info.ok();
    let limits = &info.json()["limits"];
    assert_eq!(limits["max_ptex_texels"], MAX_REQUEST_TEXELS);
    assert_eq!(MAX_REQUEST_TEXELS, 1 << 20);
    assert!(limits["ptex_bake_threads"].as_u64().expect("threads") >= 1);
    // A tile's 16 faces and the 16 neighbouring faces its borders read, at 256²: 2²¹ texels,
    // refused before any work; at 128² they fit.
    let refused = get(&app, &format!("/v1/seeds/{SEED}/ptex/tiles/0/1/1?res=256")).await;
    refused.error(StatusCode::BAD_REQUEST, "ptex_too_large", Some("res"));
    let message = refused.json()["error"]["message"]
        .as_str()
        .expect("message")
        .to_string();
    assert!(
        message.contains("32 faces")
            && message.contains("2097152")
            && message.contains("1048576")
            && message.contains("res 128 fits"),
        "{message}"
    );
    let pages = get(&app, &format!("/v1/seeds/{SEED}/ptex/tiles/0/1/1?res=128")).await;
    pages.ok();
    assert_eq!(
        (u32_at(&pages.body, 48), u32_at(&pages.body, 52)),
        (128, 16)
    );
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let key = TileKey { lod: 0, x: 1, z: 1 };
    assert_eq!(pages.body, library_tile_pack(&plan, key, 128));
}

/// A `.ptx` file as the specification describes it.
struct Ptx {
    nchannels: usize,
    nlevels: usize,
    nfaces: usize,
    /// Per face: `(ulog2, vlog2, adjedges, flags, adjfaces)`.
    faces: Vec<(u8, u8, u8, u8, [i32; 4])>,
    constant: Vec<f32>,
    /// Per level, per face in the level's order: channels separated, `f32`.
    levels: Vec<Vec<Vec<f32>>>,
}

fn unzip(data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    ZlibDecoder::new(data)
        .read_to_end(&mut out)
        .expect("zlib data");
    out
}

/// Reads a float32 quad-mesh `.ptx` (the only kind this test needs), checking the fixed fields.
fn read_ptx(b: &[u8]) -> Ptx {
    assert_eq!(&b[0..4], b"Ptex", "magic");
    assert_eq!(u32_at(b, 4), 1, "major version");
    assert_eq!(u32_at(b, 8), 1, "meshtype quad");
    assert_eq!(u32_at(b, 12), 3, "datatype float32");
    assert_eq!(u32_at(b, 16), 0xffff_ffff, "no alpha channel");
    let nchannels = u16::from_le_bytes([b[20], b[21]]) as usize;
    let nlevels = u16::from_le_bytes([b[22], b[23]]) as usize;
    let nfaces = u32_at(b, 24) as usize;
    let extheader = u32_at(b, 28) as usize;
    let faceinfo = u32_at(b, 32) as usize;
    let constdata = u32_at(b, 36) as usize;
    let levelinfo = u32_at(b, 40) as usize;
    let leveldata = u64_at(b, 48) as usize;
    let (meta_zip, meta_mem) = (u32_at(b, 56), u32_at(b, 60));
    assert_eq!((meta_zip, meta_mem), (0, 0), "no meta data");
    // Extended header (at 64): border modes, large meta data, edit data.
    assert!(extheader >= 40);
    let ext = &b[64..64 + extheader];
    assert_eq!(
        (u32_at(ext, 0), u32_at(ext, 4)),
        (0, 0),
        "clamp border modes"
    );
    assert_eq!(u64_at(ext, 24), 0, "no edit data");
    let mut at = 64 + extheader;
    let info = unzip(&b[at..at + faceinfo]);
    at += faceinfo;
    assert_eq!(info.len(), 20 * nfaces, "20 bytes of face info per face");
    let faces = (0..nfaces)
        .map(|f| {
            let r = &info[20 * f..20 * f + 20];
            let adj = std::array::from_fn(|k| u32_at(r, 4 + 4 * k) as i32);
            (r[0], r[1], r[2], r[3], adj)
        })
        .collect();
    let constant: Vec<f32> = unzip(&b[at..at + constdata])
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes(c.try_into().expect("4")))
        .collect();
    at += constdata;
    assert_eq!(levelinfo, 16 * nlevels);
    let info: Vec<(usize, usize, usize)> = (0..nlevels)
        .map(|l| {
            let o = at + 16 * l;
            (
                u64_at(b, o) as usize,
                u32_at(b, o + 8) as usize,
                u32_at(b, o + 12) as usize,
            )
        })
        .collect();
    at += levelinfo;
    let start = at;
    let mut levels = Vec::new();
    for (size, header, count) in info {
        let sizes: Vec<u32> = unzip(&b[at..at + header])
            .chunks_exact(4)
            .map(|c| u32::from_le_bytes(c.try_into().expect("4")))
            .collect();
        assert_eq!(sizes.len(), count);
        let mut p = at + header;
        let mut faces_data = Vec::new();
        for s in sizes {
            assert_eq!(s >> 30, 1, "zip encoding");
            let n = (s & 0x3fff_ffff) as usize;
            let raw = unzip(&b[p..p + n]);
            faces_data.push(
                raw.chunks_exact(4)
                    .map(|c| f32::from_le_bytes(c.try_into().expect("4")))
                    .collect(),
            );
            p += n;
        }
        assert_eq!(p - at, size, "level size includes its header");
        at = p;
        levels.push(faces_data);
    }
    assert_eq!(at - start, leveldata, "total level data");
    assert_eq!(u64_at(b, at), 0, "compatibility barrier");
    assert_eq!(
        u64_at(ext, 32) as usize,
        at + 8,
        "edit data position: the end"
    );
    Ptx {
        nchannels,
        nlevels,
        nfaces,
        faces,
        constant,
        levels,
    }
}

#[tokio::test]
async fn an_exported_ptx_reads_back_with_the_http_pages_texels() {
    let app = app(AppState::new(Compute::cpu()));
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let key = TileKey {
        lod: 1,
        x: -1,
        z: 2,
    };
    let res = 16usize;
    let pages = get(
        &app,
        &format!("/v1/seeds/{SEED}/ptex/tiles/1/-1/2?res={res}"),
    )
    .await;
    pages.ok();
    let spec = ExportSpec {
        lod: 1,
        x0: -1,
        z0: 2,
        x1: 0,
        z1: 3,
        products: vec![Product::Ptex],
        formats: vec![],
        ptex_res: Some(res as u32),
    };
    spec.validate(&plan).expect("valid spec");
    let tile = synthesize(&plan, key);
    let m = members(&plan, &spec, &tile).expect("members");
    assert_eq!(m.len(), 1);
    assert_eq!(m[0].0, "ptex/1/-1/2.ptx");
    let ptx = read_ptx(&m[0].1);
    assert_eq!((ptx.nchannels, ptx.nfaces, ptx.nlevels), (8, 16, 5));
    // Face info: 16² texels, adjacency of the 4 × 4 grid (edges west, south, east, north).
    for (id, &(ulog2, vlog2, adjedges, flags, adj)) in ptx.faces.iter().enumerate() {
        assert_eq!((ulog2, vlog2, flags), (4, 4, 0));
        let (fi, fj) = (id as i32 % 4, id as i32 / 4);
        let across = [(fi - 1, fj), (fi, fj + 1), (fi + 1, fj), (fi, fj - 1)];
        for (k, (x, z)) in across.into_iter().enumerate() {
            let inside = (0..4).contains(&x) && (0..4).contains(&z);
            assert_eq!(
                adj[k],
                if inside { 4 * z + x } else { -1 },
                "face {id} edge {k}"
            );
            if inside {
                assert_eq!(
                    (adjedges >> (2 * k)) & 3,
                    ((k + 2) % 4) as u8,
                    "face {id} edge {k}"
                );
            }
        }
    }
    // Level 0: the HTTP pages' interior texels, channel by channel.
    for f in 0..16 {
        let want = pack_interior(&pages.body, f);
        let data = &ptx.levels[0][f];
        assert_eq!(data.len(), 8 * res * res);
        for (t, (a, n, d)) in want.iter().enumerate() {
            let ch = |c: usize| data[c * res * res + t];
            for (c, byte) in a.iter().enumerate() {
                assert_eq!(
                    ch(c),
                    f32::from(*byte) / 255.0,
                    "face {f} texel {t} channel {c}"
                );
            }
            for (c, byte) in n.iter().take(3).enumerate() {
                assert_eq!(
                    ch(4 + c),
                    f32::from(*byte as i8) / 127.0,
                    "face {f} texel {t} normal"
                );
            }
            assert_eq!(
                ch(7).to_bits(),
                d.to_bits(),
                "face {f} texel {t} displacement"
            );
        }
    }
    // Each reduction level halves the faces by 2 × 2 means; the constant data is the mean.
    for l in 1..ptx.nlevels {
        let (side, fine) = (res >> l, res >> (l - 1));
        for f in 0..16 {
            let (a, b) = (&ptx.levels[l - 1][f], &ptx.levels[l][f]);
            assert_eq!(b.len(), 8 * side * side);
            for c in 0..8 {
                for v in 0..side {
                    for u in 0..side {
                        let at = |du: usize, dv: usize| {
                            a[c * fine * fine + (2 * v + dv) * fine + 2 * u + du]
                        };
                        let mean = (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) / 4.0;
                        let got = b[c * side * side + v * side + u];
                        assert!(
                            (got - mean).abs() <= 1e-6 * (1.0 + mean.abs()),
                            "level {l} face {f}"
                        );
                    }
                }
            }
        }
    }
    for f in 0..16 {
        for c in 0..8 {
            let level0 = &ptx.levels[0][f][c * res * res..(c + 1) * res * res];
            let mean = level0.iter().map(|v| f64::from(*v)).sum::<f64>() / (res * res) as f64;
            let got = f64::from(ptx.constant[8 * f + c]);
            assert!(
                (got - mean).abs() <= 1e-5 * (1.0 + mean.abs()),
                "constant face {f} channel {c}"
            );
        }
    }
}
