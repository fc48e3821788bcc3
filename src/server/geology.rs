//! Subsurface routes (issue 6): the stored limits of a column chunk and batched material
//! queries, for the `strata` elements of a world ([`crate::subsurface::world`]).
//!
//! | route | answer |
//! |---|---|
//! | `GET /v1/worlds/{id}/columns/{x}/{z}.json[?strata=ID][&size=N][&v=N]` | `strata.columns.v1`: the chunks of columns of stacked limits of voxel columns `[x·N, (x+1)·N) × [z·N, (z+1)·N)`, from below the deepest layer surface up to the ground, with the ground height of each column |
//! | `POST /v1/worlds/{id}/materials/query[?v=N]` `{points: [[x, y, z], …]}` | composition, main material and flow at each point |
//!
//! Both read the world's ground from its LOD-0 height tiles (the ground before cave breaches,
//! bilinear between vertices, at the voxel column's centre), so they follow the world's edits.
//! Limits: `size` in 1..=[`MAX_COLUMN_SIZE`] (default [`DEFAULT_COLUMN_SIZE`]); at most
//! [`MAX_QUERY_POINTS`] points per query, spread over at most [`MAX_QUERY_TILES`] LOD-0 tiles.
//! Errors are 400 JSON naming the field (`x`, `z`, `size`, `strata`, `points`, `points/3/1`…).
//! Both routes run in the synthesis slots and under the synthesis time limit, like the chunk
//! routes ([`AppState::limited`]); a column whose ground spans more LOD-0 tiles than
//! [`MAX_QUERY_TILES`] (a very small `world.cell_m`) is refused naming `size`.

use super::error::{code, truncate, AppError};
use super::http::query_param;
use super::params::parse_coord;
use super::route_table::RouteTable;
use super::view::{WorldAt, WorldView};
use super::AppState;
use crate::subsurface::chunk::{Chunk, ChunkKey};
use crate::subsurface::world::{ground_under, main_material, memos};
use crate::subsurface::Geology;
use crate::terrain::plan::TILE_QUADS;
use crate::terrain::{Tile, TileKey, WorldPlan};
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::sync::Arc;

/// Default voxel columns per side of a column chunk.
pub const DEFAULT_COLUMN_SIZE: u32 = 16;
/// Largest voxel columns per side of a column chunk.
pub const MAX_COLUMN_SIZE: u32 = 32;
/// Most points in one material query.
pub const MAX_QUERY_POINTS: usize = 4096;
/// Most LOD-0 tiles the points of one query may fall in.
pub const MAX_QUERY_TILES: usize = 64;
/// Largest material-query body, bytes.
pub const MAX_QUERY_BYTES: usize = 512 * 1024;

/// The subsurface routes.
pub fn routes() -> RouteTable {
    RouteTable::new()
        .get("/v1/worlds/{id}/columns/{x}/{z_ext}", columns)
        .post("/v1/worlds/{id}/materials/query", query)
}

/// The largest `|x|`, `|z|` of a column chunk of `size` voxels of `voxel_m` metres: chunk `c`
/// spans `[c, c + 1)·size·voxel_m`, so `|c| + 1` chunks must fit both in the coordinate limit
/// ([`crate::scene::MAX_COORD_M`]) and in the world's LOD-0 tiles on either side of the origin,
/// and chunk coordinates are `i32`.
fn max_column_chunk(plan: &WorldPlan, voxel_m: f64, size: u32) -> i64 {
    let tiles_m =
        plan.max_tile_coord(0) as f64 * TILE_QUADS as f64 * f64::from(plan.lods[0].spacing_m);
    let half_m = crate::scene::MAX_COORD_M.min(tiles_m);
    let chunks = (half_m / (voxel_m * f64::from(size))).floor() - 1.0;
    chunks.clamp(0.0, f64::from(i32::MAX)) as i64
}

/// The world's ground (before breaches) at `(x, z)` points, from its LOD-0 tiles.
struct Ground {
    spacing_m: f64,
    tiles: BTreeMap<(i64, i64), Arc<Tile>>,
    strata: Vec<Arc<Geology>>,
    memos: std::cell::RefCell<Vec<crate::subsurface::ElementMemo>>,
}

impl Ground {
    /// The LOD-0 tile and vertex `(i, k)` whose cell holds `(x, z)`.
    fn cell(spacing_m: f64, x: f64, z: f64) -> ((i64, i64), (i64, i64)) {
        let (gx, gz) = (
            (x / spacing_m).floor() as i64,
            (z / spacing_m).floor() as i64,
        );
        (
            (gx.div_euclid(TILE_QUADS), gz.div_euclid(TILE_QUADS)),
            (gx.rem_euclid(TILE_QUADS), gz.rem_euclid(TILE_QUADS)),
        )
    }

    /// Fetches the tiles the points need. A point outside the world is an error naming
    /// `points/i`; more than [`MAX_QUERY_TILES`] tiles is an error naming `field` (the request
    /// field that set the points' spread).
    async fn load(
        st: &AppState,
        view: &WorldView,
        points: &[(f64, f64)],
        strata: Vec<Arc<Geology>>,
        field: &'static str,
    ) -> Result<Ground, AppError> {
        let plan = &view.plan;
        let spacing_m = f64::from(plan.lods[0].spacing_m);
        let max = plan.max_tile_coord(0);
        let mut keys = std::collections::BTreeSet::new();
        for (i, &(x, z)) in points.iter().enumerate() {
            let (t, _) = Ground::cell(spacing_m, x, z);
            if t.0.unsigned_abs() > max.unsigned_abs() || t.1.unsigned_abs() > max.unsigned_abs() {
                return Err(AppError::bad_request(
                    code::COORDINATE_OUT_OF_RANGE,
                    format!("points/{i}"),
                    format!("point {i} is outside the supported world (|x|, |z| < {max} tiles of LOD 0)"),
                ));
            }
            keys.insert(t);
        }
        if keys.len() > MAX_QUERY_TILES {
            return Err(AppError::bad_request(
                if field == "points" {
                    code::BAD_BODY
                } else {
                    code::BAD_PARAMETER
                },
                field,
                format!(
                    "the request spans {} LOD-0 tiles; at most {MAX_QUERY_TILES} per request",
                    keys.len()
                ),
            ));
        }
        let mut tiles = BTreeMap::new();
        for (tx, tz) in keys {
            let key = TileKey {
                lod: 0,
                x: tx,
                z: tz,
            };
            let tile = st.tile(view, key, [false; 4]).await;
            tiles.insert((tx, tz), tile);
        }
        Ok(Ground {
            spacing_m,
            tiles,
            memos: std::cell::RefCell::new(memos(&strata)),
            strata,
        })
    }

    /// Bilinear ground at `(x, z)`.
    fn at(&self, x: f64, z: f64) -> f64 {
        let s = self.spacing_m;
        let (t, (i, k)) = Ground::cell(s, x, z);
        let Some(tile) = self.tiles.get(&t) else {
            return 0.0;
        };
        let mut memos = self.memos.borrow_mut();
        let mut corner = |di: i64, dk: i64| {
            let (vi, vk) = (i + di, k + dk);
            let h = tile.heights[(vk * (TILE_QUADS + 1) + vi) as usize];
            let gx = t.0 * TILE_QUADS + vi;
            let gz = t.1 * TILE_QUADS + vk;
            f64::from(ground_under(
                &self.strata,
                &mut memos,
                gx as f64 * s,
                gz as f64 * s,
                h,
            ))
        };
        let (fx, fz) = (
            x / s - (t.0 * TILE_QUADS + i) as f64,
            z / s - (t.1 * TILE_QUADS + k) as f64,
        );
        crate::terrain::lattice::lerp2(
            corner(0, 0),
            corner(1, 0),
            corner(0, 1),
            corner(1, 1),
            fx,
            fz,
        )
    }
}

fn json_ok(body: Value, version: u64) -> Response {
    let mut res = (StatusCode::OK, axum::Json(body)).into_response();
    super::http::set_version_headers(&mut res, version, false);
    res.headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    res
}

/// `GET /v1/worlds/{id}/columns/{x}/{z}.json`.
async fn columns(
    world: WorldAt,
    State(st): State<AppState>,
    Path((id, x, z_ext)): Path<(String, String, String)>,
    RawQuery(query): RawQuery,
) -> Result<Response, AppError> {
    let query = query.as_deref();
    let x = parse_coord(&x, "x")?;
    let Some(z) = z_ext.strip_suffix(".json") else {
        return Err(AppError::bad_request(
            code::UNKNOWN_FORMAT,
            "format",
            "column chunks are available as .json",
        ));
    };
    let z = parse_coord(z, "z")?;
    let size = match query_param(query, "size") {
        None => DEFAULT_COLUMN_SIZE,
        Some(s) => match s.parse::<u32>() {
            Ok(n) if (1..=MAX_COLUMN_SIZE).contains(&n) => n,
            _ => {
                return Err(AppError::bad_request(
                    code::BAD_PARAMETER,
                    "size",
                    format!(
                        "size must be an integer in 1..={MAX_COLUMN_SIZE}, got {:?}",
                        truncate(s, 40)
                    ),
                ))
            }
        },
    };
    let view = world.view;
    let (version, plan) = (view.version(), view.plan.clone());
    let strata = view.inputs.strata();
    let input = match query_param(query, "strata") {
        Some(sid) => strata.iter().find(|s| s.spec.id == sid).ok_or_else(|| {
            AppError::bad_request(
                code::NOT_FOUND,
                "strata",
                format!(
                    "world {id} has no strata element {:?} at version {version}",
                    truncate(sid, 128)
                ),
            )
        })?,
        None => match strata {
            [one] => one,
            [] => {
                return Err(AppError::new(
                    StatusCode::NOT_FOUND,
                    code::NOT_FOUND,
                    format!("world {id} has no strata element at version {version}"),
                )
                .with_field("strata"))
            }
            _ => {
                return Err(AppError::bad_request(
                    code::BAD_PARAMETER,
                    "strata",
                    "the world has several strata elements: name one with ?strata=ID",
                ))
            }
        },
    };
    let geology = input.geology(plan.seed);
    let v = geology.voxel_m();
    let limit = max_column_chunk(&plan, v, size);
    for (field, c) in [("x", x), ("z", z)] {
        if c.unsigned_abs() > limit.unsigned_abs() {
            return Err(AppError::bad_request(
                code::COORDINATE_OUT_OF_RANGE,
                field,
                format!(
                    "|{field}| must be at most {limit} column chunks of {size} voxels of {v} m, got {c}"
                ),
            ));
        }
    }
    let centres: Vec<(f64, f64)> = (0..size * size)
        .map(|c| {
            let (i, k) = (i64::from(c % size), i64::from(c / size));
            (
                ((x * i64::from(size) + i) as f64 + 0.5) * v,
                ((z * i64::from(size) + k) as f64 + 0.5) * v,
            )
        })
        .collect();
    let state = st.clone();
    let body = st
        .limited(async move {
            let ground =
                Ground::load(&state, &view, &centres, vec![geology.clone()], "size").await?;
            tokio::task::spawn_blocking(move || {
        let ground_m: Vec<f64> = centres.iter().map(|&(cx, cz)| ground.at(cx, cz)).collect();
        let (xi, zi) = (
            i32::try_from(x).unwrap_or(i32::MAX),
            i32::try_from(z).unwrap_or(i32::MAX),
        );
        let bounds = geology.bounds();
        let (lo, _) = geology.plan.depth_range();
        let bottom = ((lo - 1.0) / size as f32).floor() as i32;
        let chunks: Vec<Value> = (bottom..0)
            .map(|cy| {
                let key = ChunkKey {
                    x: xi,
                    y: cy,
                    z: zi,
                };
                chunk_json(&geology.plan.chunk_within(key, size, Some(bounds)))
            })
            .collect();
        json!({
            "format": "strata.columns.v1",
            "strata": geology.spec.id,
            "version": version,
            "x": x,
            "z": z,
            "size": size,
            "voxel_m": v,
            "origin_m": [(x * i64::from(size)) as f64 * v, (z * i64::from(size)) as f64 * v],
            "ground_m": ground_m,
            "chunks": chunks,
        })
    })
    .await
    .map_err(|e| AppError::internal(format!("column synthesis failed: {e}")))
        })
        .await?;
    Ok(json_ok(body, version))
}

/// One stored chunk: palette, limit counts per column, limits `[y, lo, hi, t, fx, fy, fz]`.
fn chunk_json(c: &Chunk) -> Value {
    let limits: Vec<Value> = c
        .limits
        .iter()
        .map(|l| json!([l.y, l.mix.lo, l.mix.hi, l.mix.t, l.flow[0], l.flow[1], l.flow[2]]))
        .collect();
    json!({
        "y": c.key.y,
        "palette": c.palette,
        "counts": c.counts,
        "limits": limits,
    })
}

/// Parses `{points: [[x, y, z], …]}`.
fn parse_points(body: &[u8]) -> Result<Vec<[f64; 3]>, AppError> {
    let v: Value = serde_json::from_slice(body).map_err(|e| {
        AppError::bad_request(code::BAD_BODY, "", format!("the body is not JSON: {e}"))
    })?;
    let Some(points) = v.get("points").and_then(Value::as_array) else {
        return Err(AppError::bad_request(
            code::BAD_BODY,
            "points",
            "the body must be {\"points\": [[x, y, z], …]}",
        ));
    };
    if points.len() > MAX_QUERY_POINTS {
        return Err(AppError::bad_request(
            code::BAD_BODY,
            "points",
            format!(
                "at most {MAX_QUERY_POINTS} points per query, got {}",
                points.len()
            ),
        ));
    }
    let mut out = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let coords = p.as_array().filter(|a| a.len() == 3).ok_or_else(|| {
            AppError::bad_request(
                code::BAD_BODY,
                format!("points/{i}"),
                "a point is [x, y, z] in metres",
            )
        })?;
        let mut q = [0.0; 3];
        for (a, c) in coords.iter().enumerate() {
            q[a] = c
                .as_f64()
                .filter(|f| f.is_finite() && f.abs() <= crate::scene::MAX_COORD_M)
                .ok_or_else(|| {
                    AppError::bad_request(
                        code::BAD_COORDINATE,
                        format!("points/{i}/{a}"),
                        format!(
                            "must be a number of metres within ±{}",
                            crate::scene::MAX_COORD_M
                        ),
                    )
                })?;
        }
        out.push(q);
    }
    Ok(out)
}

/// `POST /v1/worlds/{id}/materials/query`.
async fn query(
    world: WorldAt,
    State(st): State<AppState>,
    body: Bytes,
) -> Result<Response, AppError> {
    if body.len() > MAX_QUERY_BYTES {
        return Err(AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::PAYLOAD_TOO_LARGE,
            format!("a material query is at most {MAX_QUERY_BYTES} bytes"),
        ));
    }
    let points = parse_points(&body)?;
    let view = world.view;
    let version = view.version();
    let strata: Vec<Arc<Geology>> = view
        .inputs
        .strata()
        .iter()
        .map(|s| s.geology(view.seed()))
        .collect();
    // The ground is read at the centre of each point's voxel column.
    let centres: Vec<(f64, f64)> = points
        .iter()
        .map(
            |p| match crate::subsurface::world::in_force(&strata, p[0], p[2]) {
                Some(k) => strata[k].column_centre(p[0], p[2]),
                None => (p[0], p[2]),
            },
        )
        .collect();
    let state = st.clone();
    let body = st
        .limited(async move {
    let ground = Ground::load(&state, &view, &centres, strata.clone(), "points").await?;
    tokio::task::spawn_blocking(move || {
        let mut memos = memos(&strata);
        let results: Vec<Value> = points
            .iter()
            .zip(&centres)
            .map(|(p, &(cx, cz))| {
                let g = ground.at(cx, cz);
                let Some(k) = crate::subsurface::world::in_force(&strata, p[0], p[2]) else {
                    return json!({"strata": null, "ground_m": g, "composition": [], "main": null, "flow": null});
                };
                let geo = &strata[k];
                let (comp, flow) = geo.composition(p[0], p[1], p[2], g, &mut memos[k]);
                let names: Vec<Value> = comp
                    .iter()
                    .map(|&(mid, c)| {
                        let name = geo
                            .plan
                            .config
                            .materials
                            .iter()
                            .find(|m| m.id == mid)
                            .map(|m| m.name.as_str())
                            .unwrap_or("");
                        json!({"id": mid, "name": name, "concentration": c})
                    })
                    .collect();
                json!({
                    "strata": geo.spec.id,
                    "voxel": geo.voxel_of(p[0], p[1], p[2], g),
                    "ground_m": g,
                    "composition": names,
                    "main": main_material(&comp),
                    "flow": flow,
                })
            })
            .collect();
        json!({ "version": version, "results": results })
    })
    .await
    .map_err(|e| AppError::internal(format!("material query failed: {e}")))
        })
        .await?;
    Ok(json_ok(body, version))
}
