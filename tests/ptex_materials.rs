//! Materials and decals in the Ptex bake (issue 20; `strata::ptex::spec`, `ptex::image`,
//! `ptex::decal`, `server::images`):
//!
//! - pages of worlds without `materials` or `decals` keep the bytes of the build before them
//!   (ETags pinned from that build's answers);
//! - a material override changes the albedo of exactly the texels where that material has
//!   weight; an image material reads its image there;
//! - a decal changes texels inside its rectangle only, its mask's edge blends, and a re-bake
//!   gives the same bytes;
//! - over HTTP: images upload and read back by content hash, edits naming them change the pages
//!   of the new version only, and bad input is refused with the field and the limit;
//! - the decoded images stay within their share of `--memory-budget`, and images the cache let
//!   go are decoded again into the same pages.

use axum::http::{Method, StatusCode};
use axum::Router;
use serde_json::{json, Value};
use std::collections::HashMap;
use std::sync::Arc;
use strata::compute::Compute;
use strata::element::Element;
use strata::ptex::bake::texel_materials;
use strata::ptex::face::{FaceSet, TileFacePlan};
use strata::ptex::image::{decode_png, hash_hex, image_hash, Image};
use strata::ptex::spec::{DecalSpec, MaterialSpec, PtexSpecs};
use strata::ptex::{bake_interior, MaterialSet, Pages};
use strata::server::{app, AppState};
use strata::store::{SceneStore, SqliteStore};
use strata::terrain::tile::{synthesize, TileKey};
use strata::terrain::world::WorldParams;
use strata::terrain::WorldPlan;

mod common;

use common::oneshot::{get_as, private_world, send};

const SEED: u64 = 5;
const KEY: TileKey = TileKey {
    lod: 2,
    x: 3,
    z: -2,
};
const RES: u32 = 32;

/// The decal image: magenta, its alpha 255 over the middle 8 × 8 pixels and falling to 0 over
/// the 4 pixels to each edge.
fn decal_png() -> Vec<u8> {
    let ramp = |i: u32| (i.min(15 - i) * 64).min(255) as u8;
    common::png::rgba(16, 16, |x, y| [250, 20, 200, ramp(x).min(ramp(y))])
}

/// A 4 × 4 checker of two colours.
fn checker_png() -> Vec<u8> {
    common::png::rgba(4, 4, |x, y| {
        if (x + y) % 2 == 0 {
            [10, 200, 30, 255]
        } else {
            [200, 200, 10, 255]
        }
    })
}

fn element(id: &str, bbox: ([f64; 2], [f64; 2]), rest: Value) -> Element {
    let mut v = rest;
    v["id"] = json!(id);
    v["bbox"] = json!({"min": bbox.0, "max": bbox.1});
    serde_json::from_value(v).expect("element")
}

fn plan() -> WorldPlan {
    WorldPlan::new(SEED, WorldParams::default()).expect("default world")
}

fn tile_set(plan: &WorldPlan, key: TileKey, mats: &MaterialSet) -> FaceSet {
    let faces = TileFacePlan::new(key, [false; 4], plan.lods.len() as u32 - 1);
    let tile = synthesize(plan, key);
    let mut set = faces.build(|t| (t == key).then_some(&tile), mats, plan);
    set.output = set.faces.len();
    set
}

fn bake(set: &FaceSet, mats: &MaterialSet) -> Pages {
    let mut pages = Pages::default();
    bake_interior(set, mats, RES, &mut pages);
    pages
}

/// The world-space `[x, z]` (anchor included) the bake interpolates at interior texel `(i, j)` of
/// face `f`.
fn texel_world(set: &FaceSet, f: usize, i: u32, j: u32) -> [f64; 2] {
    let face = &set.faces[f];
    let n = face.n as usize;
    let r = RES as f32;
    let (u, v) = ((i as f32 + 0.5) / r, (j as f32 + 0.5) / r);
    let (gu, gv) = (u * (n - 1) as f32, v * (n - 1) as f32);
    let (cu, cv) = (
        gu.floor().min((n - 2) as f32),
        gv.floor().min((n - 2) as f32),
    );
    let (fu, fv) = (gu - cu, gv - cv);
    let base = face.first as usize + cv as usize * n + cu as usize;
    let s = [base, base + 1, base + n, base + n + 1].map(|k| set.samples[k]);
    let w = [
        (1.0 - fu) * (1.0 - fv),
        fu * (1.0 - fv),
        (1.0 - fu) * fv,
        fu * fv,
    ];
    let p: [f32; 3] = std::array::from_fn(|c| (0..4).map(|k| w[k] * s[k].position[c]).sum::<f32>());
    [
        f64::from(face.anchor[0]) * 256.0 + f64::from(p[0]),
        f64::from(face.anchor[2]) * 256.0 + f64::from(p[2]),
    ]
}

/// Every interior texel: `(face, i, j, index into the planes)`.
fn texels(pages: &Pages) -> impl Iterator<Item = (usize, u32, u32, usize)> + '_ {
    (0..pages.faces).flat_map(move |f| {
        (0..RES)
            .flat_map(move |j| (0..RES).map(move |i| (f, i, j, pages.at(f, i as i32, j as i32))))
    })
}

/// The decal of the library tests: 60 × 36 m in the middle of the tile, turned 30°.
fn decal_element(hash: &str) -> (Element, [f64; 2]) {
    let foot = strata::scene::tile_footprint(&WorldParams::default(), KEY);
    let c = [
        (foot.min[0] + foot.max[0]) / 2.0 + 7.0,
        (foot.min[1] + foot.max[1]) / 2.0 - 5.0,
    ];
    let e = element(
        "puddle",
        ([c[0] - 40.0, c[1] - 40.0], [c[0] + 40.0, c[1] + 40.0]),
        json!({"image": hash, "center": c, "size_m": [60.0, 36.0], "rotation_deg": 30.0,
               "opacity": 1.0, "roughness": 0.1}),
    );
    (e, c)
}

#[test]
fn a_decal_changes_texels_inside_its_rectangle_only_and_its_mask_edge_blends() {
    let plan = plan();
    let png = decal_png();
    let hash = image_hash(&png);
    let (e, c) = decal_element(&hash_hex(&hash));
    let spec = DecalSpec::from_element(&e).expect("a valid decal");
    let specs = PtexSpecs {
        materials: Vec::new(),
        decals: vec![spec],
    };
    let images: HashMap<[u8; 32], Arc<Image>> =
        HashMap::from([(hash, Arc::new(decode_png(&png).expect("png")))]);
    let mats = specs.set(plan.seed, &images);
    assert_eq!(mats.validate(), Ok(()));
    let plain_mats = MaterialSet::default_ground(plan.seed);
    let set = tile_set(&plan, KEY, &plain_mats);
    let plain = bake(&set, &plain_mats);
    let with = bake(&set, &mats);
    assert_eq!(with, bake(&set, &mats), "a re-bake gives the same bytes");
    // The decal's (u, v) of a world point, from its placement (not from the bake's code).
    let (s, co) = 30f64.to_radians().sin_cos();
    let uv = |p: [f64; 2]| {
        let (dx, dz) = (p[0] - c[0], p[1] - c[1]);
        (
            (dx * co + dz * s) / 60.0 + 0.5,
            (dz * co - dx * s) / 36.0 + 0.5,
        )
    };
    // A texel is 2 m: its position may round across the edge.
    let margin = [2.0 / 60.0, 2.0 / 36.0];
    let (mut inside, mut solid, mut blended) = (0, 0, 0);
    for (f, i, j, k) in texels(&plain) {
        let p = texel_world(&set, f, i, j);
        let (u, v) = uv(p);
        let out = |t: f64, m: f64| t < -m || t > 1.0 + m;
        if out(u, margin[0]) || out(v, margin[1]) {
            assert_eq!(
                (with.albedo[k], with.normal[k], with.displacement[k]),
                (plain.albedo[k], plain.normal[k], plain.displacement[k]),
                "face {f} texel ({i}, {j}) lies outside the decal at uv ({u:.3}, {v:.3})"
            );
            continue;
        }
        assert_eq!(
            with.normal[k], plain.normal[k],
            "a decal leaves normals alone"
        );
        inside += 1;
        let a = with.albedo[k];
        if (0.4..=0.6).contains(&u) && (0.4..=0.6).contains(&v) {
            // Where the mask is 1: the decal's colour and roughness (0.1 → 26).
            for (got, want) in a.iter().zip([250u8, 20, 200, 26]) {
                assert!(got.abs_diff(want) <= 1, "face {f} ({i}, {j}): {a:?}");
            }
            solid += 1;
        }
        let r0 = plain.albedo[k][0];
        if a[0] > r0.saturating_add(20) && a[0] < 230 {
            blended += 1;
        }
    }
    assert!(inside > 100 && solid > 10, "{inside} inside, {solid} solid");
    assert!(
        blended > 10,
        "the mask's edge blends: {blended} texels in between"
    );
}

/// A tile of mixed ground and a material covering between a tenth and nine tenths of its faces'
/// samples (the most common first) that the bake leaves out of more than 100 texels and gives
/// more than 100 alone: the first such pair of a fixed search.
fn mixed_tile(plan: &WorldPlan, mats: &MaterialSet) -> (FaceSet, u32) {
    for lod in [4, 6, 8, 10] {
        for x in -2..2 {
            for z in -2..2 {
                let set = tile_set(plan, TileKey { lod, x, z }, mats);
                let mut count: HashMap<u32, usize> = HashMap::new();
                for s in &set.samples {
                    *count.entry(s.material).or_default() += 1;
                }
                let n = set.samples.len();
                let mut candidates: Vec<(u32, usize)> = count
                    .into_iter()
                    .filter(|&(_, c)| 10 * c >= n && 10 * c <= 9 * n)
                    .collect();
                candidates.sort_by_key(|&(id, c)| (std::cmp::Reverse(c), id));
                // A material the bake's step 1 leaves out of some texels and gives others alone
                // (a biome's ground can share every texel of a tile in a wide biome blend).
                for (id, _) in candidates {
                    let (mut without, mut alone) = (0, 0);
                    for f in 0..set.faces.len() {
                        for j in 0..RES {
                            for i in 0..RES {
                                let ids: Vec<u32> = texel_materials(&set, mats, f, RES, i, j)
                                    .into_iter()
                                    .filter(|&(_, w)| w > 0.0)
                                    .map(|(m, _)| m as u32)
                                    .collect();
                                without += usize::from(!ids.contains(&id));
                                alone += usize::from(ids.iter().all(|&m| m == id));
                            }
                        }
                    }
                    if without > 100 && alone > 100 {
                        println!("tile {lod}/{x}/{z}, material {id}");
                        return (set, id);
                    }
                }
            }
        }
    }
    panic!("no tile of mixed ground found");
}

/// Bakes the tile with material `id` given by `element`, and checks that texels whose samples
/// lack it keep every byte and texels whose samples are all `id` pass `check`.
fn check_override(
    element_rest: Value,
    images: &HashMap<[u8; 32], Arc<Image>>,
    check: impl Fn([u8; 4]),
) {
    let plan = plan();
    let plain_mats = MaterialSet::default_ground(plan.seed);
    let (set, id) = mixed_tile(&plan, &plain_mats);
    let name = plain_mats.materials[id as usize].name.to_string();
    let mut rest = element_rest;
    rest["name"] = json!(name);
    let e = element("m", ([0.0, 0.0], [0.0, 0.0]), rest);
    let specs = PtexSpecs {
        materials: vec![MaterialSpec::from_element(&e).expect("a valid material")],
        decals: Vec::new(),
    };
    let mats = specs.set(plan.seed, images);
    assert_eq!(mats.validate(), Ok(()));
    let plain = bake(&set, &plain_mats);
    let with = bake(&set, &mats);
    assert_eq!(with, bake(&set, &mats), "a re-bake gives the same bytes");
    let (mut without, mut only) = (0, 0);
    for (f, i, j, k) in texels(&plain) {
        // The materials the bake's step 1 gives the texel (`ptex_blend: 2`: those of positive
        // weight by the thresholds at the texel).
        let ids: Vec<u32> = texel_materials(&set, &plain_mats, f, RES, i, j)
            .into_iter()
            .filter(|&(_, w)| w > 0.0)
            .map(|(m, _)| m as u32)
            .collect();
        if !ids.contains(&id) {
            assert_eq!(
                (with.albedo[k], with.normal[k], with.displacement[k]),
                (plain.albedo[k], plain.normal[k], plain.displacement[k]),
                "face {f} ({i}, {j}) has no weight of {name}"
            );
            without += 1;
        } else if ids.iter().all(|&x| x == id) {
            check(with.albedo[k]);
            assert_ne!(with.albedo[k], plain.albedo[k], "face {f} ({i}, {j})");
            only += 1;
        }
    }
    println!("{name}: {without} texels without it, {only} of it alone");
    assert!(
        without > 100 && only > 100,
        "{without} without, {only} alone"
    );
}

#[test]
fn a_material_override_changes_the_albedo_where_it_has_weight_and_nowhere_else() {
    check_override(
        json!({"base": [1.0, 0.0, 0.0], "tint": [1.0, 0.0, 0.0]}),
        &HashMap::new(),
        |a| assert_eq!(&a[..3], &[255, 0, 0]),
    );
}

#[test]
fn an_image_material_reads_its_image_where_it_has_weight_and_nowhere_else() {
    let png = checker_png();
    let hash = image_hash(&png);
    let images = HashMap::from([(hash, Arc::new(decode_png(&png).expect("png")))]);
    check_override(
        json!({"texture": {"albedo": hash_hex(&hash), "repeat_m": 8}}),
        &images,
        // Every albedo is a blend of the two checker colours (G 200 in both).
        |a| assert!(a[1].abs_diff(200) <= 1 && a[2] <= 31, "{a:?}"),
    );
}

// ---- HTTP ----

fn service(dir: &std::path::Path) -> Router {
    let store: Arc<dyn SceneStore> = Arc::new(SqliteStore::open_in_dir(dir).expect("store"));
    app(AppState::new(Compute::cpu()).with_worlds(store, None))
}

async fn upload(app: &Router, id: &str, token: Option<&str>, png: &[u8]) -> common::oneshot::Reply {
    let mut headers = vec![("content-type", "image/png".to_string())];
    if let Some(t) = token {
        headers.push(("authorization", format!("Bearer {t}")));
    }
    send(
        app,
        Method::POST,
        &format!("/v1/worlds/{id}/images"),
        &headers,
        Some(png),
    )
    .await
}

async fn edit(app: &Router, id: &str, token: &str, patch: Value) -> common::oneshot::Reply {
    let headers = [
        ("content-type", "application/json-patch+json".to_string()),
        ("authorization", format!("Bearer {token}")),
    ];
    send(
        app,
        Method::POST,
        &format!("/v1/worlds/{id}/edits"),
        &headers,
        Some(patch.to_string().as_bytes()),
    )
    .await
}

#[tokio::test]
async fn pages_without_materials_keep_the_bytes_of_the_build_before_them() {
    // ETags the build before materials and decals answered (main at ba41da2) for a new world
    // of the same seed, whose settings were later defaults' until `lakes: 5` filled a lake over
    // the first tile: a world with today's settings but `lakes: 4`.
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let mut scene = strata::scene::Scene::default().to_value();
    scene["world"]["earth"]["rivers"]["lakes"] = json!(4);
    let v = common::oneshot::post_json(
        &app,
        "/v1/worlds",
        None,
        &json!({"seed": SEED, "scene": scene}),
    )
    .await
    .status_is(StatusCode::CREATED)
    .json();
    let (id, token) = (
        v["id"].as_str().expect("id").to_string(),
        v["tokens"]["admin"].as_str().expect("token").to_string(),
    );
    let (default_id, default_token) = private_world(&app, SEED).await;
    for (path, etag) in [
        (
            "ptex/tiles/2/3/-2?res=16",
            "\"51c96abc914522309e7cf06113d4b6b9\"",
        ),
        (
            "ptex/tiles/0/-1/1?res=32",
            "\"ab6fbe9be93853df22d559ae0395e170\"",
        ),
    ] {
        // A bare seed has today's default (`lakes: 5`): it answers what a new world of the
        // default settings answers.
        let seed = get_as(&app, &format!("/v1/seeds/{SEED}/{path}"), &token).await;
        seed.ok();
        let fresh = get_as(
            &app,
            &format!("/v1/worlds/{default_id}/{path}"),
            &default_token,
        )
        .await;
        fresh.ok();
        assert_eq!(seed.header("etag"), fresh.header("etag"), "{path}");
        let world = get_as(&app, &format!("/v1/worlds/{id}/{path}"), &token).await;
        world.ok();
        assert_eq!(world.header("etag"), Some(etag), "{path}");
    }
}

#[tokio::test]
async fn an_uploaded_decal_shows_in_the_pages_of_the_new_version_and_bad_input_is_refused() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    let (id, token) = private_world(&app, SEED).await;
    let tok = Some(token.as_str());
    let page = format!("/v1/worlds/{id}/ptex/tiles/2/3/-2?res=32");
    let before = get_as(&app, &page, &token).await;
    before.ok();

    // Uploads: the role, the media type and the image limits come first.
    let png = decal_png();
    upload(&app, &id, None, &png)
        .await
        .status_is(StatusCode::UNAUTHORIZED);
    send(
        &app,
        Method::POST,
        &format!("/v1/worlds/{id}/images"),
        &[("authorization", format!("Bearer {token}"))],
        Some(&png),
    )
    .await
    .error(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        "unsupported_media_type",
        Some("Content-Type"),
    );
    upload(&app, &id, tok, b"not a png at all, just text")
        .await
        .error(StatusCode::BAD_REQUEST, "invalid_image", Some("body"));
    let odd = upload(&app, &id, tok, &common::png::rgba(3, 2, |_, _| [0; 4])).await;
    odd.error(StatusCode::BAD_REQUEST, "invalid_image", Some("body"));
    assert!(odd.json()["error"]["message"]
        .as_str()
        .is_some_and(|m| m.contains("1024")));
    let r = upload(&app, &id, tok, &png).await;
    r.status_is(StatusCode::CREATED);
    let hex = hash_hex(&image_hash(&png));
    assert_eq!(r.json()["image"], json!(hex));
    assert_eq!(
        (r.json()["width"].clone(), r.json()["height"].clone()),
        (json!(16), json!(16))
    );
    upload(&app, &id, tok, &png).await.status_is(StatusCode::OK);
    let back = get_as(&app, &format!("/v1/worlds/{id}/images/{hex}"), &token).await;
    back.ok();
    assert_eq!(back.body, png);
    get_as(
        &app,
        &format!("/v1/worlds/{id}/images/{}", "0".repeat(64)),
        &token,
    )
    .await
    .error(StatusCode::NOT_FOUND, "image_not_found", Some("hash"));

    // Edits are checked before anything is stored: the image must be the world's, every field
    // within its limit.
    let (good, _) = decal_element(&hex);
    let good = serde_json::to_value(&good).expect("json");
    let add = |v: &Value| json!([{"op": "add", "path": "/decals/-", "value": v}]);
    let mut unknown = good.clone();
    unknown["image"] = json!("ab".repeat(32));
    let mut outside = good.clone();
    outside["bbox"]["max"][0] = json!(good["center"][0].as_f64().expect("x") + 1.0);
    let mut opaque = good.clone();
    opaque["opacity"] = json!(1.5);
    for (v, field) in [
        (&unknown, "/decals/0/image"),
        (&outside, "/decals/0/bbox"),
        (&opaque, "/decals/0/opacity"),
    ] {
        edit(&app, &id, &token, add(v)).await.error(
            StatusCode::BAD_REQUEST,
            "invalid_scene",
            Some(field),
        );
    }
    let material = json!([{"op": "add", "path": "/materials/-", "value": {
        "id": "m", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "rock",
        "texture": {"albedo": hex, "repeat_m": 3}}}]);
    let e = edit(&app, &id, &token, material).await;
    e.error(
        StatusCode::BAD_REQUEST,
        "invalid_scene",
        Some("/materials/0/texture/repeat_m"),
    );
    assert!(e.json()["error"]["message"]
        .as_str()
        .is_some_and(|m| m.contains("power of two")));

    // The decal: version 2's pages change, version 1's stay as they were.
    edit(&app, &id, &token, add(&good)).await.ok();
    let after = get_as(&app, &page, &token).await;
    after.ok();
    assert_ne!(after.body, before.body, "the decal shows");
    assert_eq!(
        get_as(&app, &page, &token).await.body,
        after.body,
        "same bytes again"
    );
    let v1 = get_as(&app, &format!("{page}&v=1"), &token).await;
    assert_eq!(v1.body, before.body, "version 1 keeps its pages");
    // A tile far from the decal keeps its bytes at version 2.
    let far = format!("/v1/worlds/{id}/ptex/tiles/2/-5/4?res=16");
    assert_eq!(
        get_as(&app, &far, &token).await.body,
        get_as(&app, &format!("{far}&v=1"), &token).await.body
    );
}

/// `strata_cache_bytes` and `strata_cache_budget_bytes` of the `images` cache, from `/metrics`.
async fn image_cache_bytes(app: &Router) -> (f64, f64) {
    let m = send::<&str>(app, Method::GET, "/metrics", &[], None).await;
    let text = String::from_utf8_lossy(&m.body).to_string();
    let read = |name: &str| {
        let line = format!("{name}{{cache=\"images\"}} ");
        text.lines()
            .find_map(|l| l.strip_prefix(line.as_str()))
            .and_then(|v| v.trim().parse::<f64>().ok())
            .unwrap_or_else(|| panic!("{line} missing from /metrics"))
    };
    (
        read("strata_cache_bytes"),
        read("strata_cache_budget_bytes"),
    )
}

#[tokio::test]
async fn decoded_images_stay_within_their_share_of_the_memory_budget_and_bake_the_same_pages() {
    // A 2 MiB budget leaves the images 256 KiB: three of the four 128² images below (87,380
    // bytes each with their mip chain) fit, the fourth evicts one.
    let dir = tempfile::tempdir().expect("tmp");
    let store: Arc<dyn SceneStore> = Arc::new(SqliteStore::open_in_dir(dir.path()).expect("store"));
    let small = app(AppState::new(Compute::cpu())
        .with_memory_budget(strata::server::budget::MemoryBudget::from_mb(2))
        .with_worlds(store, None));
    let (id, token) = private_world(&small, SEED).await;
    let mut patch = Vec::new();
    for (i, name) in ["rock", "grass", "sand", "dirt"].into_iter().enumerate() {
        let png = common::png::rgba(128, 128, |x, y| {
            let on = (x / 16 + y / 16) % 2 == 0;
            [40 * i as u8 + if on { 90 } else { 10 }, 200, 30, 255]
        });
        upload(&small, &id, Some(&token), &png)
            .await
            .status_is(StatusCode::CREATED);
        patch.push(json!({"op": "add", "path": "/materials/-", "value": {
            "id": format!("m{i}"), "bbox": {"min": [0, 0], "max": [0, 0]}, "name": name,
            "texture": {"albedo": hash_hex(&image_hash(&png)), "repeat_m": 4}}}));
    }
    edit(&small, &id, &token, Value::Array(patch)).await.ok();

    let pages = [
        format!("/v1/worlds/{id}/ptex/tiles/2/3/-2?res=16"),
        format!("/v1/worlds/{id}/ptex/tiles/0/-1/1?res=32"),
        format!("/v1/worlds/{id}/ptex/tiles/1/0/0?res=16"),
    ];
    let mut first = Vec::new();
    for page in &pages {
        let r = get_as(&small, page, &token).await;
        r.ok();
        first.push(r.body);
        let (bytes, budget) = image_cache_bytes(&small).await;
        assert_eq!(budget, (256 << 10) as f64);
        assert!(
            bytes > 0.0 && bytes <= budget,
            "{bytes} bytes of images against {budget}"
        );
    }
    // A server with the default budget, on the same store, bakes the same pages: the images the
    // small one let go and decoded again gave the same texels.
    let big = service(dir.path());
    for (page, body) in pages.iter().zip(&first) {
        let r = get_as(&big, page, &token).await;
        r.ok();
        assert_eq!(&r.body, body, "{page}");
    }
    let (bytes, _) = image_cache_bytes(&big).await;
    assert_eq!(
        bytes,
        4.0 * (87_380.0 + 128.0),
        "the default share holds all four"
    );
}

#[tokio::test]
async fn an_export_bakes_the_worlds_decal_into_its_ptx() {
    let jobs = tempfile::tempdir().expect("tmp");
    let app = app(AppState::new(Compute::cpu()).with_jobs_dir(jobs.path()));
    let (id, token) = private_world(&app, SEED).await;
    let png = decal_png();
    let hex = hash_hex(&image_hash(&png));
    upload(&app, &id, Some(&token), &png)
        .await
        .status_is(StatusCode::CREATED);
    let (decal, _) = decal_element(&hex);
    let patch = json!([{"op": "add", "path": "/decals/-", "value": decal}]);
    edit(&app, &id, &token, patch).await.ok();
    let started = common::oneshot::post_json(
        &app,
        &format!("/v1/worlds/{id}/exports"),
        Some(&token),
        &json!({"lod": KEY.lod, "region": [KEY.x, KEY.z, KEY.x + 1, KEY.z + 1],
                "products": ["ptex"], "ptex_res": RES}),
    )
    .await
    .status_is(StatusCode::ACCEPTED)
    .json();
    let status_url = started["status_url"].as_str().expect("status url");
    common::oneshot::wait_job_done(&app, status_url, &token).await;
    let url = started["download_url"].as_str().expect("download url");
    let archive = get_as(&app, url, &token).await;
    archive.ok();
    let members = strata::export::tar::read_members(&archive.body).expect("tar");
    let name = format!("ptex/{}/{}/{}.ptx", KEY.lod, KEY.x, KEY.z);
    let (_, ptx) = members
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("no {name} in the archive"));

    // The library's .ptx of the tile with the world's decal, and without it.
    let plan = plan();
    let tile = synthesize(&plan, KEY);
    let specs = PtexSpecs {
        materials: Vec::new(),
        decals: vec![DecalSpec::from_element(&decal).expect("decal")],
    };
    let images = HashMap::from([(image_hash(&png), Arc::new(decode_png(&png).expect("png")))]);
    let mats = specs.set(plan.seed, &images);
    let want = strata::export::ptx_member(&plan, &mats, &tile, RES);
    let plain = strata::export::ptx_member(&plan, &MaterialSet::default_ground(SEED), &tile, RES);
    assert!(*ptx == want, "the export bakes the world's decal");
    assert!(want != plain, "the decal changes the tile's .ptx");
}

/// The albedo and normal planes of a tile's page pack (`api/ptex_pages_v1.md`).
fn planes(body: &[u8]) -> (&[u8], &[u8]) {
    let word = |at: usize| u32::from_le_bytes(body[at..at + 4].try_into().expect("u32")) as usize;
    let (faces, side) = (word(52), word(56));
    let plane = faces * side * side * 4;
    let start = 64 + 40 * faces;
    (
        &body[start..start + plane],
        &body[start + plane..start + 2 * plane],
    )
}

#[tokio::test]
async fn a_normal_map_tilts_the_pages_normals_and_nothing_else() {
    let dir = tempfile::tempdir().expect("tmp");
    let app = service(dir.path());
    // Ripples along the map's x: normals leaning up to 35° either way.
    let ripples = common::png::rgba(16, 16, |x, _| {
        let a = (x as f32 * 0.8).sin() * 0.7;
        let inv = 1.0 / (a * a + 1.0).sqrt();
        [
            ((a * inv * 0.5 + 0.5) * 255.0).round() as u8,
            128,
            ((inv * 0.5 + 0.5) * 255.0).round() as u8,
            255,
        ]
    });
    let albedo = checker_png();
    let mut bodies = Vec::new();
    for normal in [None, Some(&ripples)] {
        let (id, token) = private_world(&app, SEED).await;
        // One repeat of 64 m: 4 m a pixel, coarser than the page's 2 m texels, so the page
        // reads the map's full level (a finer repeat would be its mean, nearly flat, there).
        let mut texture = json!({"albedo": hash_hex(&image_hash(&albedo)), "repeat_m": 64});
        for png in [Some(&albedo), normal].into_iter().flatten() {
            upload(&app, &id, Some(&token), png)
                .await
                .status_is(StatusCode::CREATED);
        }
        if let Some(png) = normal {
            texture["normal"] = json!(hash_hex(&image_hash(png)));
        }
        // Every ground material of the tile is the same image material.
        let patch: Vec<Value> = ["seabed", "sand", "grass", "dirt", "rock", "snow"]
            .into_iter()
            .map(|name| {
                json!({"op": "add", "path": "/materials/-", "value": {
                    "id": name, "bbox": {"min": [0, 0], "max": [0, 0]}, "name": name,
                    "texture": texture}})
            })
            .collect();
        edit(&app, &id, &token, Value::Array(patch)).await.ok();
        let page = format!("/v1/worlds/{id}/ptex/tiles/2/3/-2?res=32");
        let r = get_as(&app, &page, &token).await;
        r.ok();
        bodies.push(r.body);
    }
    let ((albedo_a, normal_a), (albedo_b, normal_b)) = (planes(&bodies[0]), planes(&bodies[1]));
    assert_eq!(
        albedo_a, albedo_b,
        "a normal map changes no albedo or roughness"
    );
    // On ground the map's x runs along world z (the Y plane's coordinates are (z, x)): the
    // normals lean north and south by the map, in most texels by tens of steps.
    let (mut moved, mut total, mut most) = (0usize, 0usize, 0u8);
    for (a, b) in normal_a.chunks(4).zip(normal_b.chunks(4)) {
        total += 1;
        let dz = (a[2] as i8).abs_diff(b[2] as i8);
        moved += usize::from(dz > 2);
        most = most.max(dz);
        assert_eq!(a[3], b[3], "the dominant material stays");
    }
    assert!(moved * 2 > total, "{moved} of {total} normals lean");
    assert!(most > 40, "the largest lean is {most} steps");
}
