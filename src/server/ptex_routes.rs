//! Ptex page routes (issue 20): the baked faces of a volume chunk or a height tile
//! ([`crate::ptex`]) as the pack of `api/ptex_pages_v1.md`.
//!
//! | route | product |
//! |---|---|
//! | `GET /v1/seeds/{seed}/ptex/{lod}/{x}/{y}/{z}?res=R` | a chunk's quads |
//! | `GET /v1/worlds/{id}/ptex/{lod}/{x}/{y}/{z}?res=R[&v=N]` | likewise, of a stored world |
//! | `GET /v1/seeds/{seed}/ptex/tiles/{lod}/{x}/{z}?res=R[&seams=n,e,s,w]` | a tile's 4 × 4 faces |
//! | `GET /v1/worlds/{id}/ptex/tiles/{lod}/{x}/{z}?res=R[&v=N][&seams=…]` | likewise |
//!
//! `res` is required, a power of two in `8..=256` (else 400 `bad_parameter`, field `res`). The
//! cost, `res² × faces baked`, is checked before baking against [`MAX_PTEX_TEXELS`] (else 400
//! `ptex_too_large`, field `res`): for a tile before any work (its faces and the neighbouring
//! faces its borders read are known from the key), for a chunk after meshing (its quads). Keys
//! and their limits are those of the chunk and tile routes. Bodies are not cached (their tiles
//! are), so every request is charged to the client's rate limit; responses carry a content-hash
//! `ETag` and the world products' caching headers. Baking runs on the CPU reference
//! ([`crate::ptex::bake`]) in one synthesis slot.

use super::chunks::{check_chunk_bounds, mesh};
use super::error::{code, AppError};
use super::params::{check_bounds, parse_coord, parse_lod, parse_seams, percent_decode};
use super::route_table::RouteTable;
use super::routes::{segments, CachedProduct, PathSegments};
use super::view::WorldAt;
use super::AppState;
use crate::encode::ptex::{encode, PackInfo, PackKind, CONTENT_TYPE};
use crate::ptex::face::{chunk_faces, TileFacePlan};
use crate::ptex::{bake, valid_res, MaterialSet, Pages, MAX_PTEX_TEXELS};
use crate::terrain::TileKey;
use crate::volume::chunk::{ChunkKey, MAX_CHUNK_LOD};
use axum::extract::{RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// The Ptex page routes.
pub fn routes() -> RouteTable {
    RouteTable::new()
        .get("/v1/seeds/{seed}/ptex/{lod}/{x}/{y}/{z}", chunk_pages)
        .get("/v1/worlds/{id}/ptex/{lod}/{x}/{y}/{z}", chunk_pages)
        .get("/v1/seeds/{seed}/ptex/tiles/{lod}/{x}/{z}", tile_pages)
        .get("/v1/worlds/{id}/ptex/tiles/{lod}/{x}/{z}", tile_pages)
}

/// `?res=R`: required, once, a power of two in `8..=256`.
pub fn parse_res(query: Option<&str>) -> Result<u32, AppError> {
    let bad = |m: String| AppError::bad_request(code::BAD_PARAMETER, "res", m);
    let mut found = None;
    for pair in query.unwrap_or("").split('&').filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        if percent_decode(k).as_deref() != Some("res") {
            continue;
        }
        if found.is_some() {
            return Err(bad("res given more than once".into()));
        }
        let v = percent_decode(v).unwrap_or_default();
        match v.parse::<u32>() {
            Ok(r) if valid_res(r) => found = Some(r),
            _ => {
                return Err(bad(format!(
                    "res must be a power of two in 8..=256, got {:?}",
                    v.chars().take(40).collect::<String>()
                )))
            }
        }
    }
    found.ok_or_else(|| bad("res is required: a power of two in 8..=256".into()))
}

/// Refuses a bake of `faces` faces at `res` over [`MAX_PTEX_TEXELS`].
fn check_cost(res: u32, faces: usize) -> Result<(), AppError> {
    let texels = u64::from(res) * u64::from(res) * faces as u64;
    if texels > MAX_PTEX_TEXELS {
        return Err(AppError::bad_request(
            code::PTEX_TOO_LARGE,
            "res",
            format!(
                "{faces} faces at res {res} are {texels} texels; at most {MAX_PTEX_TEXELS} per request"
            ),
        ));
    }
    Ok(())
}

/// Bakes `set` at `res` and encodes its pack, on the blocking pool.
async fn bake_pack(
    set: crate::ptex::FaceSet,
    classes: Vec<u8>,
    info: PackInfo,
    res: u32,
) -> Result<CachedProduct, AppError> {
    tokio::task::spawn_blocking(move || {
        let mats = MaterialSet::default_ground(info.seed);
        let mut pages = Pages::default();
        bake(&set, &mats, res, &mut pages);
        CachedProduct::new(
            encode(&info, &set, &classes, &pages),
            CONTENT_TYPE,
            Vec::new(),
        )
    })
    .await
    .map_err(|e| AppError::internal(format!("ptex bake failed: {e}")))
}

/// `GET /v1/seeds/{seed}/ptex/{lod}/{x}/{y}/{z}?res=R` and its world twin.
async fn chunk_pages(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    path: PathSegments<(String, String, String, String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, y, z) = segments(path)?;
    let lod = parse_lod(&lod)?;
    if lod > MAX_CHUNK_LOD {
        return Err(AppError::bad_request(
            code::LOD_OUT_OF_RANGE,
            "lod",
            format!("chunk lod must be in 0..={MAX_CHUNK_LOD}, got {lod}"),
        ));
    }
    let key = ChunkKey {
        lod,
        x: parse_coord(&x, "x")?,
        y: parse_coord(&y, "y")?,
        z: parse_coord(&z, "z")?,
    };
    check_chunk_bounds(&world.view.plan, key)?;
    let res = parse_res(query.as_deref())?;
    let (state, view) = (st.clone(), world.view.clone());
    let product = st
        .limited(async move {
            let chunk = mesh(&state, &view, key).await?;
            check_cost(res, chunk.quads.len())?;
            let spacing_m = view.plan.lods[key.lod as usize].spacing_m;
            let mats = MaterialSet::default_ground(view.plan.seed);
            let set = chunk_faces(&chunk, spacing_m, &mats);
            let classes = chunk.classes.iter().map(|c| *c as u8).collect();
            let info = PackInfo {
                kind: PackKind::Chunk,
                lod: key.lod,
                key: [key.x, key.y, key.z],
                seed: view.plan.seed,
            };
            bake_pack(set, classes, info, res).await
        })
        .await?;
    Ok(world.finish(product.respond(&headers)))
}

/// `GET /v1/seeds/{seed}/ptex/tiles/{lod}/{x}/{z}?res=R[&seams=n,e,s,w]` and its world twin.
async fn tile_pages(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    path: PathSegments<(String, String, String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, z) = segments(path)?;
    let plan = &world.view.plan;
    let key = TileKey {
        lod: parse_lod(&lod)?,
        x: parse_coord(&x, "x")?,
        z: parse_coord(&z, "z")?,
    };
    check_bounds(plan, key)?;
    let seams = parse_seams(query.as_deref())?;
    let res = parse_res(query.as_deref())?;
    let faces = TileFacePlan::new(key, seams, plan.lods.len() as u32 - 1);
    check_cost(res, faces.faces.len())?;
    let (state, view) = (st.clone(), world.view.clone());
    let product = st
        .limited(async move {
            let mut tiles = Vec::new();
            for t in faces.tiles() {
                if check_bounds(&view.plan, t).is_err() {
                    continue;
                }
                let s = if t == key { seams } else { [false; 4] };
                tiles.push(state.tile(&view, t, s).await);
            }
            let mats = MaterialSet::default_ground(view.plan.seed);
            let set = faces.build(
                |t| tiles.iter().find(|x| x.key == t).map(Arc::as_ref),
                &mats,
            );
            let info = PackInfo {
                kind: PackKind::Tile,
                lod: key.lod,
                key: [key.x, 0, key.z],
                seed: view.plan.seed,
            };
            bake_pack(set, Vec::new(), info, res).await
        })
        .await?;
    Ok(world.finish(product.respond(&headers)))
}
