//! Ptex pages over stream protocol v2 (`api/stream_protocol_v2.md`, "Ptex pages"), with a real
//! client (tokio-tungstenite) against the app on a real socket: a scripted fly-through (a
//! sequence of view messages) never makes the client hold more than its session's budget, keeps
//! the vista level complete for every face of the view, gives the nearest faces in view the
//! highest levels, and serves the HTTP route's bytes; an edit re-bakes only the faces it
//! touched, and an edit of the materials re-bakes the pages without re-sending a tile; the
//! server's budget refuses a session it cannot hold.

use serde_json::{json, Value};
use std::collections::{HashMap, HashSet};
use std::time::Duration;
use strata::edits::{synthesize, TileEdits};
use strata::ptex::budget::{distance_in_view, page_bytes, FaceBounds, LEVEL_RES};
use strata::ptex::face::TileFaceKey;
use strata::scene::Rect;
use strata::stream::protocol::TileFrame;
use strata::stream::ptex::PageFace;
use strata::stream::ptex::{face_reach, PtexSettings, PtexView};
use strata::stream::ptex_frame::{decode, PageRecord, PtexFrame};
use strata::stream::view::select;
use strata::terrain::{TileKey, WorldParams, WorldPlan};
use tokio_tungstenite::tungstenite::Message;

mod common;

use common::ws::{connect, create_world, send, serve_ptex, Ws};

const SEED: u64 = 11;
/// The session budget of these tests: every face of a `[1, 1]` view at the vista level, and a
/// few slots at each detail level (one at 256²).
const SESSION_BYTES: u64 = 6 << 20;

fn settings() -> PtexSettings {
    PtexSettings {
        session_bytes: SESSION_BYTES,
        server_bytes: 2 * SESSION_BYTES,
        ..PtexSettings::default()
    }
}

async fn next(ws: &mut Ws) -> Message {
    common::ws::next(ws, Duration::from_secs(300)).await
}

/// The tile face of a page record: these sessions never ask for chunk faces' pages, so a chunk
/// face here fails the test.
fn tile_face(r: &PageRecord) -> TileFaceKey {
    match r.face {
        PageFace::Tile(f) => f,
        PageFace::Chunk(c) => {
            panic!("a page of chunk face {c:?} sent to a client that did not ask")
        }
    }
}

fn ground_at(x: i64, z: i64) -> f32 {
    let plan = WorldPlan::new(SEED, WorldParams::default()).expect("default world");
    let t = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[(z * 65 + x) as usize]
}

/// What the client holds: the vista page of each face (its bounds) and which face each detail
/// slot holds, for the faces of the tiles of its current view.
#[derive(Default)]
struct Replica {
    tiles: HashSet<TileKey>,
    vista: HashMap<TileFaceKey, FaceBounds>,
    /// Level and slot of each face holding a detail page.
    detail: HashMap<TileFaceKey, (u8, u32)>,
    slots: [HashMap<u32, TileFaceKey>; 5],
    budget: u64,
    capacity: [usize; 5],
}

impl Replica {
    fn set_view(&mut self, tiles: HashSet<TileKey>) {
        self.tiles = tiles;
        let tiles = &self.tiles;
        self.vista.retain(|f, _| tiles.contains(&f.tile()));
        let gone: Vec<TileFaceKey> = self
            .detail
            .keys()
            .filter(|f| !tiles.contains(&f.tile()))
            .copied()
            .collect();
        for f in gone {
            self.free(f);
        }
    }

    fn free(&mut self, f: TileFaceKey) {
        if let Some((l, s)) = self.detail.remove(&f) {
            let slots = &mut self.slots[l as usize - 1];
            if slots.get(&s) == Some(&f) {
                slots.remove(&s);
            }
        }
    }

    fn take(&mut self, frame: &PtexFrame) {
        for r in &frame.records {
            if !self.tiles.contains(&tile_face(r).tile()) {
                continue;
            }
            if frame.level == 0 {
                self.vista.insert(tile_face(r), r.bounds);
                continue;
            }
            self.free(tile_face(r));
            if let Some(old) = self.slots[frame.level as usize - 1].insert(r.slot, tile_face(r)) {
                self.detail.remove(&old);
            }
            self.detail.insert(tile_face(r), (frame.level, r.slot));
        }
    }

    fn message(&mut self, m: &Value) {
        self.budget = m["budget_bytes"].as_u64().expect("budget_bytes");
        for (l, c) in m["capacity"]
            .as_array()
            .expect("capacity")
            .iter()
            .enumerate()
        {
            self.capacity[l] = c.as_u64().expect("a slot count") as usize;
        }
        assert!(
            m["held_bytes"].as_u64().expect("held_bytes") <= self.budget,
            "{m}"
        );
        for f in m["to_vista"].as_array().expect("to_vista") {
            let a: Vec<i64> = f
                .as_array()
                .expect("[lod, fx, fz]")
                .iter()
                .map(|v| v.as_i64().expect("integer"))
                .collect();
            self.free(TileFaceKey {
                lod: a[0] as u32,
                fx: a[1],
                fz: a[2],
            });
        }
    }

    fn bytes(&self) -> u64 {
        let detail: u64 = self
            .slots
            .iter()
            .enumerate()
            .map(|(l, s)| s.len() as u64 * page_bytes(LEVEL_RES[l + 1]))
            .sum();
        self.vista.len() as u64 * page_bytes(LEVEL_RES[0]) + detail
    }

    fn level(&self, f: TileFaceKey) -> u8 {
        self.detail.get(&f).map_or(0, |d| d.0)
    }
}

/// Reads until `idle`, granting a credit per frame and checking the budget after each; returns
/// the Ptex frames and the text messages.
async fn until_idle(ws: &mut Ws, replica: &mut Replica) -> (Vec<PtexFrame>, Vec<Value>) {
    let (frames, msgs, _) = until_idle_counting_tiles(ws, replica).await;
    (frames, msgs)
}

/// [`until_idle`], and the number of tile frames that came.
async fn until_idle_counting_tiles(
    ws: &mut Ws,
    replica: &mut Replica,
) -> (Vec<PtexFrame>, Vec<Value>, usize) {
    let (mut frames, mut msgs, mut tiles) = (Vec::new(), Vec::new(), 0);
    loop {
        match next(ws).await {
            Message::Binary(b) => {
                send(ws, json!({"type": "credit", "frames": 1})).await;
                if let Some(f) = decode(&b) {
                    replica.take(&f);
                    frames.push(f);
                } else {
                    TileFrame::decode(&b).expect("a tile or Ptex frame");
                    tiles += 1;
                }
                assert!(
                    replica.bytes() <= replica.budget,
                    "the client holds {} bytes of pages; the budget is {}",
                    replica.bytes(),
                    replica.budget
                );
            }
            Message::Text(t) => {
                let v: Value = serde_json::from_str(&t).expect("JSON");
                assert_ne!(v["type"], "error", "{v}");
                if v["type"] == "ptex" {
                    replica.message(&v);
                }
                let idle = v["type"] == "idle";
                msgs.push(v);
                if idle {
                    return (frames, msgs, tiles);
                }
            }
            _ => {}
        }
    }
}

/// The faces whose vista pages (level 0) `frames` carry.
fn vista_faces(frames: &[PtexFrame]) -> HashSet<TileFaceKey> {
    frames
        .iter()
        .filter(|f| f.level == 0)
        .flat_map(|f| f.records.iter().map(tile_face))
        .collect()
}

fn faces_of(tiles: &HashSet<TileKey>) -> Vec<TileFaceKey> {
    let mut out = Vec::new();
    for t in tiles {
        for id in 0..16 {
            out.push(TileFaceKey {
                lod: t.lod,
                fx: t.x * 4 + id % 4,
                fz: t.z * 4 + id / 4,
            });
        }
    }
    out
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

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_fly_through_stays_within_the_budget_with_every_vista_and_the_nearest_faces_highest() {
    let addr = serve_ptex(settings()).await;
    let mut ws = connect(&addr, &format!("/v1/seeds/{SEED}/stream?protocol=2")).await;
    next(&mut ws).await;
    send(&mut ws, json!({"type": "credit", "frames": 16})).await;
    let y = f64::from(ground_at(32, 32)) + 24.0;
    let ptex = PtexView {
        forward: [1.0, -0.35, 0.2],
        half_angle_deg: 40.0,
        far_m: 3000.0,
        chunks: false,
    };
    let rings = [1u32, 1];
    let mut replica = Replica::default();
    let (mut top, mut moved, mut checked) = (0u8, 0usize, false);
    for t in 0..6 {
        let (x, z) = (8.0 + 24.0 * t as f64, 32.0 - 6.0 * t as f64);
        let tiles: HashSet<TileKey> = select(x, z, &rings, 1.0).iter().map(|v| v.key).collect();
        replica.set_view(tiles.clone());
        send(
            &mut ws,
            json!({"type": "view", "x": x, "z": z, "y": y, "rings": rings,
                   "ptex": {"forward": ptex.forward, "half_angle_deg": ptex.half_angle_deg,
                            "far_m": ptex.far_m}}),
        )
        .await;
        let (frames, msgs) = until_idle(&mut ws, &mut replica).await;
        assert!(
            msgs.iter().any(|m| m["type"] == "ptex") || t > 0,
            "the opt-in is answered with the session's budget"
        );
        assert_eq!(replica.budget, SESSION_BYTES);
        moved += frames.iter().filter(|f| f.level > 0).count();
        // The vista level is complete: every face of every tile of the view has its page.
        for f in faces_of(&tiles) {
            assert!(
                replica.vista.contains_key(&f),
                "view {t}: {f:?} has no vista page"
            );
        }
        // Levels by distance: among the faces in view, a nearer one never holds a lower level,
        // no face beyond a level's threshold holds it, and faces out of view hold the vista
        // page only.
        let view = ptex.view([x, y, z]).expect("a valid view");
        let mut visible: Vec<(f32, TileFaceKey)> = Vec::new();
        for (f, b) in &replica.vista {
            match distance_in_view(b, &view) {
                Some(d) => visible.push((d, *f)),
                None => assert_eq!(replica.level(*f), 0, "view {t}: {f:?} is out of view"),
            }
        }
        visible.sort_by(|a, b| a.0.total_cmp(&b.0));
        for w in visible.windows(2) {
            if w[0].0 < w[1].0 {
                assert!(
                    replica.level(w[0].1) >= replica.level(w[1].1),
                    "view {t}: {:?} at level {} is nearer than {:?} at level {}",
                    w[0],
                    replica.level(w[0].1),
                    w[1],
                    replica.level(w[1].1)
                );
            }
        }
        let thresholds = PtexSettings::default().thresholds_m;
        for (d, f) in &visible {
            let l = replica.level(*f);
            if l > 0 {
                assert!(d <= &thresholds[l as usize - 1], "view {t}: {f:?} at {d} m");
            }
            top = top.max(l);
        }
        let (d, f) = visible[0];
        assert!(d <= thresholds[4] && replica.capacity[4] > 0, "view {t}");
        assert_eq!(replica.level(f), 5, "view {t}: the nearest face holds 256²");
        // A vista page is the HTTP route's page of the same face.
        if !checked {
            let vt = select(x, z, &rings, 1.0)[0];
            let face = TileFaceKey {
                lod: vt.key.lod,
                fx: vt.key.x * 4 + 1,
                fz: vt.key.z * 4 + 2,
            };
            let frame = frames
                .iter()
                .find(|fr| fr.level == 0 && fr.records.iter().any(|r| tile_face(r) == face))
                .expect("the vista page of a face of the nearest tile");
            let k = frame
                .records
                .iter()
                .position(|r| tile_face(r) == face)
                .expect("record");
            let seams: Vec<&str> = vt
                .seams
                .iter()
                .map(|s| if *s { "1" } else { "0" })
                .collect();
            let path = format!(
                "/v1/seeds/{SEED}/ptex/tiles/{}/{}/{}?res=8&seams={}",
                vt.key.lod,
                vt.key.x,
                vt.key.z,
                seams.join(",")
            );
            let (status, pack) = strata::bench::http::http(&addr, "GET", &path, &[], "")
                .await
                .expect("HTTP");
            assert_eq!(status, 200, "{path}");
            let (albedo, normal, disp) = pack_page(&pack, 9);
            let per = frame.pages.texels_per_face();
            let range = k * per..(k + 1) * per;
            assert_eq!(albedo, frame.pages.albedo[range.clone()].concat());
            assert_eq!(normal, frame.pages.normal[range.clone()].concat());
            let d: Vec<u8> = frame.pages.displacement[range]
                .iter()
                .flat_map(|v| v.to_le_bytes())
                .collect();
            assert_eq!(disp, d);
            checked = true;
        }
    }
    assert_eq!(top, 5, "the fly-through reaches the 256² level");
    assert!(moved > 0, "detail pages were baked");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_edit_rebakes_only_the_faces_it_touched() {
    let addr = serve_ptex(settings()).await;
    let (id, token) = create_world(&addr, SEED, None).await;
    let mut ws = connect(
        &addr,
        &format!("/v1/worlds/{id}/stream?protocol=2&token={token}"),
    )
    .await;
    next(&mut ws).await;
    send(&mut ws, json!({"type": "credit", "frames": 16})).await;
    let ground = ground_at(24, 24);
    let (x, y, z) = (8.0, f64::from(ground) + 24.0, 24.0);
    let rings = [1u32];
    let tiles: HashSet<TileKey> = select(x, z, &rings, 1.0).iter().map(|v| v.key).collect();
    let mut replica = Replica::default();
    replica.set_view(tiles.clone());
    send(
        &mut ws,
        json!({"type": "view", "x": x, "z": z, "y": y, "rings": rings,
               "ptex": {"forward": [1.0, -0.4, 0.0]}}),
    )
    .await;
    until_idle(&mut ws, &mut replica).await;
    let before: HashMap<TileFaceKey, (u8, u32)> = replica.detail.clone();
    // A bump of 8 m in a 32 m box inside tile (0, 0).
    let bbox = ([40.0, 8.0], [72.0, 40.0]);
    let region = json!({"id": "bump", "bbox": {"min": bbox.0, "max": bbox.1}, "samples": 33,
        "ops": [{"op": "elevation", "shape": {"point": [56, 24]},
                 "elevation_m": ground + 8.0, "radius_m": 4}]});
    send(
        &mut ws,
        json!({"type": "edit", "id": "e1",
               "patch": [{"op": "add", "path": "/regions/-", "value": region}]}),
    )
    .await;
    let (frames, msgs) = until_idle(&mut ws, &mut replica).await;
    assert!(
        msgs.iter().any(|m| m["type"] == "ack" && m["version"] == 2),
        "{msgs:?}"
    );
    let params = WorldParams::default();
    let touched: HashSet<TileFaceKey> = faces_of(&tiles)
        .into_iter()
        .filter(|f| {
            face_reach(&params, *f).intersects(&Rect {
                min: bbox.0,
                max: bbox.1,
            })
        })
        .collect();
    assert!(!touched.is_empty() && touched.len() < 16 * tiles.len());
    let vista = vista_faces(&frames);
    assert_eq!(
        vista, touched,
        "the vista pages of exactly the touched faces are baked again"
    );
    assert!(frames.iter().all(|f| f.version == 2));
    for f in frames.iter().filter(|f| f.level > 0) {
        for r in &f.records {
            assert!(
                touched.contains(&tile_face(r))
                    || before.get(&tile_face(r)) != Some(&(f.level, r.slot)),
                "{:?} was not touched but its level-{} page in slot {} was baked again",
                tile_face(r),
                f.level,
                r.slot
            );
        }
    }
    for (f, held) in &before {
        if touched.contains(f) && replica.detail.get(f) == Some(held) {
            assert!(
                frames
                    .iter()
                    .any(|fr| fr.level == held.0 && fr.records.iter().any(|r| tile_face(r) == *f)),
                "{f:?} was touched and keeps its level-{} slot but was not baked again",
                held.0
            );
        }
    }

    // A material override changes every page and no tile: the pages come again, the tiles do
    // not (no invalidation, no tile frame).
    let material = json!({"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "grass",
        "base": [0.6, 0.2, 0.1]});
    send(
        &mut ws,
        json!({"type": "edit", "id": "e2",
               "patch": [{"op": "add", "path": "/materials/-", "value": material}]}),
    )
    .await;
    let (frames, msgs, tile_frames) = until_idle_counting_tiles(&mut ws, &mut replica).await;
    assert!(
        msgs.iter().any(|m| m["type"] == "ack" && m["version"] == 3),
        "{msgs:?}"
    );
    assert!(
        !msgs.iter().any(|m| m["type"] == "invalidate"),
        "a material edit invalidates no tile: {msgs:?}"
    );
    assert_eq!(tile_frames, 0, "a material edit re-sends no tile");
    let vista = vista_faces(&frames);
    assert_eq!(
        vista,
        faces_of(&tiles).into_iter().collect(),
        "every vista page is baked again with the new material"
    );
    assert!(frames.iter().all(|f| f.version == 3));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_session_the_servers_budget_cannot_hold_is_refused_naming_the_field() {
    let addr = serve_ptex(PtexSettings {
        session_bytes: SESSION_BYTES,
        server_bytes: SESSION_BYTES,
        ..PtexSettings::default()
    })
    .await;
    // The budgets are reported.
    let (status, info) = strata::bench::http::http(&addr, "GET", "/v1/info", &[], "")
        .await
        .expect("HTTP");
    assert_eq!(status, 200);
    let info: Value = serde_json::from_slice(&info).expect("JSON");
    assert_eq!(info["limits"]["ptex_session_budget_bytes"], SESSION_BYTES);
    assert_eq!(info["limits"]["ptex_server_budget_bytes"], SESSION_BYTES);
    let view = json!({"type": "view", "x": 8, "z": 8, "rings": [0],
                      "ptex": {"forward": [1, 0, 0]}});
    let mut first = connect(&addr, &format!("/v1/seeds/{SEED}/stream?protocol=2")).await;
    next(&mut first).await;
    send(&mut first, view.clone()).await;
    let m: Value = loop {
        if let Message::Text(t) = next(&mut first).await {
            let v: Value = serde_json::from_str(&t).expect("JSON");
            if v["type"] == "ptex" {
                break v;
            }
        }
    };
    assert_eq!(m["budget_bytes"], SESSION_BYTES);
    let mut second = connect(&addr, &format!("/v1/seeds/{SEED}/stream?protocol=2")).await;
    next(&mut second).await;
    send(&mut second, view.clone()).await;
    let e: Value = loop {
        if let Message::Text(t) = next(&mut second).await {
            let v: Value = serde_json::from_str(&t).expect("JSON");
            if v["type"] == "error" {
                break v;
            }
        }
    };
    assert_eq!(
        (e["code"].as_str(), e["field"].as_str()),
        (Some("ptex_unavailable"), Some("ptex"))
    );
    // A bad view direction is refused naming the field.
    send(
        &mut second,
        json!({"type": "view", "x": 8, "z": 8, "rings": [0], "ptex": {"forward": [0, 0, 0]}}),
    )
    .await;
    let e: Value = loop {
        if let Message::Text(t) = next(&mut second).await {
            let v: Value = serde_json::from_str(&t).expect("JSON");
            if v["type"] == "error" {
                break v;
            }
        }
    };
    assert_eq!(
        (e["code"].as_str(), e["field"].as_str()),
        (Some("bad_ptex"), Some("ptex.forward"))
    );
    // The first session's end gives its budget back.
    drop(first);
    let mut third = connect(&addr, &format!("/v1/seeds/{SEED}/stream?protocol=2")).await;
    next(&mut third).await;
    let granted = tokio::time::timeout(Duration::from_secs(60), async {
        loop {
            send(&mut third, view.clone()).await;
            loop {
                if let Message::Text(t) = next(&mut third).await {
                    let v: Value = serde_json::from_str(&t).expect("JSON");
                    match v["type"].as_str() {
                        Some("ptex") => return,
                        Some("error") => break,
                        _ => {}
                    }
                }
            }
            tokio::time::sleep(Duration::from_millis(200)).await;
        }
    })
    .await;
    assert!(
        granted.is_ok(),
        "the budget came back when the first session ended"
    );
}

#[test]
fn the_budgets_come_from_the_flags_or_the_environment() {
    use clap::Parser;
    use strata::cli::{Cli, Command};
    let settings = |argv: &[&str]| {
        let cli = Cli::try_parse_from(argv).expect("a valid command line");
        let Command::Serve(args) = cli.command else {
            panic!("not serve")
        };
        args.ptex_settings()
    };
    let s = settings(&[
        "strata",
        "serve",
        "--ptex-session-budget",
        "8",
        "--ptex-server-budget",
        "100",
    ]);
    assert_eq!((s.session_bytes, s.server_bytes), (8 << 20, 100 << 20));
    let d = settings(&["strata", "serve"]);
    assert_eq!(d, PtexSettings::default());
    assert!(Cli::try_parse_from(["strata", "serve", "--ptex-session-budget", "0"]).is_err());
    // The environment, when no flag is given (no other test here reads these variables).
    std::env::set_var("STRATA_PTEX_SESSION_BUDGET", "16");
    let e = settings(&["strata", "serve"]);
    std::env::remove_var("STRATA_PTEX_SESSION_BUDGET");
    assert_eq!(e.session_bytes, 16 << 20);
}
