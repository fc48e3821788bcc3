//! River-line routes: the centre lines of the rivers that reach into a tile
//! ([`crate::terrain::earth::tile_rivers`]), as `strata.rivers.v1` JSON (`api/rivers_v1.md`).
//!
//! | route | product |
//! |---|---|
//! | `GET /v1/seeds/{seed}/rivers/{lod}/{x}/{z}.json` | river lines of a bare seed |
//! | `GET /v1/worlds/{id}/rivers/{lod}/{x}/{z}.json[?v=N]` | river lines of a stored world |
//!
//! Parameters are checked in the order seed/id (with access and `?v`), lod, x, z, format, world
//! bounds;
//! errors are 400 JSON naming the field ([`AppError`]). `lod` must be in
//! `0..=`[`MAX_CARVE_LOD`] (the lines are too costly to trace on coarser tiles): a larger one
//! is 400 `lod_out_of_range`. A world without rivers (classic, or `earth-1` stored before rivers
//! or with them disabled) answers `lines: []`. The lines depend on the world's settings alone,
//! not on its elements. They are traced on the blocking pool in one synthesis slot, and the body
//! is kept in the body cache under the tile's input hash. Seed answers are immutable; world
//! answers follow the world tiles' caching (immutable when pinned with `?v=N`).

use super::error::{code, AppError};
use super::params::{check_bounds, parse_coord, parse_format, parse_lod, split_extension};
use super::route_table::RouteTable;
use super::routes::{blocking, segments, CachedProduct, Segments};
use super::view::{WorldAt, WorldView};
use super::AppState;
use crate::encode::{rivers, Format};
use crate::terrain::earth::rivers::MAX_CARVE_LOD;
use crate::terrain::earth::tile_rivers;
use crate::terrain::TileKey;
use axum::extract::State;
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// The body cache's format tag of river lines.
const BODY_TAG: &str = "rivers.json";

/// The river-line routes.
pub fn routes() -> RouteTable {
    RouteTable::new()
        .get("/v1/seeds/{seed}/rivers/{lod}/{x}/{z_ext}", lines)
        .get("/v1/worlds/{id}/rivers/{lod}/{x}/{z_ext}", lines)
}

/// Parses `lod` (at most [`MAX_CARVE_LOD`]), `x` and `z.json`. Public for the fuzz target
/// `path_params`.
pub fn parse_key(lod: &str, x: &str, z_ext: &str) -> Result<TileKey, AppError> {
    let lod = parse_lod(lod)?;
    if lod as usize > MAX_CARVE_LOD {
        return Err(AppError::bad_request(
            code::LOD_OUT_OF_RANGE,
            "lod",
            format!("river lines are served at lod 0..={MAX_CARVE_LOD}, got {lod}"),
        ));
    }
    let x = parse_coord(x, "x")?;
    let (z, ext) = split_extension(z_ext);
    let z = parse_coord(z, "z")?;
    if parse_format(ext)? != Format::Json {
        return Err(AppError::bad_request(
            code::UNKNOWN_FORMAT,
            "format",
            "river lines are only available as .json",
        ));
    }
    Ok(TileKey { lod, x, z })
}

/// The river lines of tile `key` of the world `view`, from the body
/// cache or traced on the blocking pool in one synthesis slot (once for concurrent requests).
async fn product(
    st: &AppState,
    view: &WorldView,
    key: TileKey,
) -> Result<Arc<CachedProduct>, AppError> {
    // The tile's input hash covers the world's settings and the key, which the lines depend on.
    let body_key = (view.tile_hash(key, [false; 4]), BODY_TAG);
    let plan = view.plan.clone();
    st.bodies
        .get_or_encode(body_key, || {
            st.limited(async move {
                blocking(move || {
                    let spacing_m = plan.lods[key.lod as usize].spacing_m;
                    let lines = match &plan.earth {
                        Some(earth) => tile_rivers(earth, key, spacing_m),
                        None => Vec::new(),
                    };
                    let body = rivers::encode(key, spacing_m, &lines);
                    Arc::new(CachedProduct::new(
                        body,
                        Format::Json.content_type(),
                        Vec::new(),
                    ))
                })
                .await
            })
        })
        .await
}

/// `GET /v1/seeds/{seed}/rivers/{lod}/{x}/{z}.json` and
/// `GET /v1/worlds/{id}/rivers/{lod}/{x}/{z}.json[?v=N]`.
async fn lines(
    world: WorldAt,
    State(st): State<AppState>,
    path: Segments,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, z_ext) = segments(path)?;
    let key = parse_key(&lod, &x, &z_ext)?;
    check_bounds(&world.view.plan, key)?;
    let p = product(&st, &world.view, key).await?;
    Ok(world.finish(p.respond(&headers)))
}
