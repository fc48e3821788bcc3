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
//! cost, `res² × faces baked`, is checked before baking against [`MAX_REQUEST_TEXELS`] (else 400
//! `ptex_too_large`, field `res`, the message naming the limit and the largest `res` that fits):
//! for a tile before any work (its 16 faces and the neighbouring faces its borders read are
//! known from the key: 32 without seams, so `res` 128 at most), for a chunk after meshing (its
//! quads). Keys and their limits are those of the chunk and tile routes. Bodies are not cached
//! (their tiles are), so every request is charged to the client's rate limit; responses carry a
//! content-hash `ETag` and the world products' caching headers.
//!
//! Pages bake with the world version's materials and decals ([`world_materials`]: the default
//! set for bare seeds and worlds without those elements), so they are a function of the seed,
//! the scene version and the key. Baking runs on the CPU reference ([`crate::ptex::bake`]) in one synthesis slot, on a pool of
//! [`bake_threads`] threads shared by every request, so bakes together take at most that many
//! cores whatever the load; a bake whose request has gone (timed out, or its client left) while
//! it waited for the pool is skipped. A bake already running ends first (the bake polls no
//! flag), and `/metrics` counts it in `strata_work_after_cancel_total{end="finished"}`.

use super::chunks::{check_chunk_bounds, mesh};
use super::error::{code, AppError};
use super::images::world_materials;
use super::params::{check_bounds, parse_coord, parse_lod, parse_seams, percent_decode};
use super::route_table::RouteTable;
use super::routes::{segments, CachedProduct, PathSegments};
use super::view::WorldAt;
use super::AppState;
use crate::compute::work;
use crate::encode::ptex::{encode, PackInfo, PackKind, CONTENT_TYPE};
use crate::ptex::face::{chunk_faces, TileFacePlan};
use crate::ptex::{bake, valid_res, MaterialSet, Pages, MIN_RES};
use crate::terrain::TileKey;
use crate::volume::chunk::{ChunkKey, MAX_CHUNK_LOD};
use axum::extract::{RawQuery, State};
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::{Arc, OnceLock};

/// Most texels one request may bake, `res² ×` faces baked (a tile's 16 faces and the
/// neighbouring faces its borders read, a chunk's quads): about a second of one core (`strata
/// bench abuse` measured 1.09 s for a chunk's pages at the largest `res` its quads allow, 0.43 s
/// for a tile's at `res` 128), so that a request stays within the 2 s of CPU every route is
/// held to.
pub const MAX_REQUEST_TEXELS: u64 = 1 << 20;

/// Threads of the pool every bake of these routes runs on: half the cores, at least one.
pub fn bake_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| (n.get() / 2).max(1))
}

/// The pool of [`bake_threads`] threads the routes bake on (`None` if it cannot be built: the
/// bake then runs on the caller's thread).
fn bake_pool() -> Option<&'static rayon::ThreadPool> {
    static POOL: OnceLock<Option<rayon::ThreadPool>> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(bake_threads())
            .thread_name(|i| format!("strata-ptex-{i}"))
            .build()
            .map_err(|e| tracing::warn!("no Ptex bake pool: {e}"))
            .ok()
    })
    .as_ref()
}

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

/// Refuses a bake of `faces` faces at `res` over [`MAX_REQUEST_TEXELS`], naming the largest
/// `res` that fits, if any.
pub fn check_cost(res: u32, faces: usize) -> Result<(), AppError> {
    let texels = |r: u32| u64::from(r) * u64::from(r) * faces as u64;
    if texels(res) <= MAX_REQUEST_TEXELS {
        return Ok(());
    }
    let fits = (0..)
        .map(|k| res >> k)
        .take_while(|r| *r >= MIN_RES)
        .find(|r| texels(*r) <= MAX_REQUEST_TEXELS);
    let hint = match fits {
        Some(r) => format!("; res {r} fits"),
        None => String::new(),
    };
    Err(AppError::bad_request(
        code::PTEX_TOO_LARGE,
        "res",
        format!(
            "{faces} faces at res {res} are {} texels; at most {MAX_REQUEST_TEXELS} texels per request{hint}",
            texels(res)
        ),
    ))
}

/// Bakes `set` at `res` and encodes its pack on the bake pool, unless nobody waits for it any
/// more by the time the pool takes it up.
async fn bake_pack(
    set: crate::ptex::FaceSet,
    classes: Vec<u8>,
    info: PackInfo,
    res: u32,
    mats: Arc<MaterialSet>,
) -> Result<CachedProduct, AppError> {
    let run = move |cancel: &crate::terrain::cancel::Cancel| {
        cancel.check()?;
        let mut pages = Pages::default();
        bake(&set, &mats, res, &mut pages);
        Ok(CachedProduct::new(
            encode(&info, &set, &classes, &pages),
            CONTENT_TYPE,
            Vec::new(),
        ))
    };
    work::run(move |cancel| match bake_pool() {
        Some(pool) => pool.install(|| run(cancel)),
        None => run(cancel),
    })
    .await
    .map_err(|_| AppError::internal("the Ptex bake was cancelled"))
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
            let mats = world_materials(&state, &view).await?;
            let set = chunk_faces(&chunk, spacing_m, &mats);
            let classes = chunk.classes.iter().map(|c| *c as u8).collect();
            let info = PackInfo {
                kind: PackKind::Chunk,
                lod: key.lod,
                key: [key.x, key.y, key.z],
                seed: view.plan.seed,
            };
            bake_pack(set, classes, info, res, mats).await
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
            let mats = world_materials(&state, &view).await?;
            let set = faces.build(
                |t| tiles.iter().find(|x| x.key == t).map(Arc::as_ref),
                &mats,
                &view.plan,
            );
            let info = PackInfo {
                kind: PackKind::Tile,
                lod: key.lod,
                key: [key.x, 0, key.z],
                seed: view.plan.seed,
            };
            bake_pack(set, Vec::new(), info, res, mats).await
        })
        .await?;
    Ok(world.finish(product.respond(&headers)))
}
