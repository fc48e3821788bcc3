//! Volume-chunk routes (issue 5): the surface-nets quad mesh of a 32³-cell chunk of the world's
//! solid ([`crate::volume::chunk`]), in the formats of `api/chunk_format_v1.md`.
//!
//! | route | product |
//! |---|---|
//! | `GET /v1/seeds/{seed}/chunks/{lod}/{x}/{y}/{z}.{json,bin,glb}` | chunk of a bare seed |
//! | `GET /v1/worlds/{id}/chunks/{lod}/{x}/{y}/{z}.{json,bin,glb}[?v=N]` | chunk of a stored world |
//!
//! Parameters are checked in the order seed/id (with access and `?v`), lod, x, y, z, format; errors are 400 JSON naming
//! the field ([`AppError`]). Limits: `lod` in `0..=3`, `|x|, |z| ≤ 2·max_tile_coord(lod) − 1`,
//! `|y| ≤ max_chunk_y(lod)`. A chunk's heights come from the same-LOD height tiles through the
//! stage cache, so a world chunk reflects the world's edits like its tiles do, and the caves of
//! the world's `strata` elements carve it ([`crate::subsurface::carve`]); its `volumes` elements
//! (solved once per version, [`super::volumes`]) blend in ([`crate::volume::element`]). Responses carry a
//! content-hash `ETag`; seed chunks are immutable, world chunks follow the world tiles' caching
//! (immutable when pinned with `?v=N`, short-lived otherwise).

use super::error::{code, AppError};
use super::params::{parse_coord, parse_format, parse_lod, split_extension};
use super::route_table::RouteTable;
use super::routes::{segments, CachedProduct, PathSegments};
use super::view::{WorldAt, WorldView};
use super::AppState;
use crate::encode::chunk::{encode_bin, encode_json, ChunkInfo, BIN_CONTENT_TYPE};
use crate::encode::{chunk_glb, Format};
use crate::scene::Rect;
use crate::subsurface::carve::{ground_rect, mesh_world_chunk};
use crate::terrain::{TileKey, WorldPlan};
use crate::volume::chunk::{
    gather_columns, max_chunk_xz, max_chunk_y, tiles_needed, ChunkKey, ChunkMesh, TileColumns,
    CHUNK_CELLS, MAX_CHUNK_LOD,
};
use crate::volume::mesh::QuadMesh;
use axum::extract::State;
use axum::http::HeaderMap;
use axum::response::Response;
use std::sync::Arc;

/// The volume-chunk routes.
pub fn routes() -> RouteTable {
    RouteTable::new()
        .get("/v1/seeds/{seed}/chunks/{lod}/{x}/{y}/{z_ext}", chunk)
        .get("/v1/worlds/{id}/chunks/{lod}/{x}/{y}/{z_ext}", chunk)
}

/// The five path segments of a chunk route (`{seed|id}/{lod}/{x}/{y}/{z_ext}`).
type Segments = PathSegments<(String, String, String, String, String)>;

/// Parses `lod`, `x`, `y`, `z.ext` and checks the chunk limits against `plan`. Public for the
/// fuzz target `path_params`.
pub fn parse_chunk(
    plan: &WorldPlan,
    lod: &str,
    x: &str,
    y: &str,
    z_ext: &str,
) -> Result<(ChunkKey, Format), AppError> {
    let lod = parse_lod(lod)?;
    if lod > MAX_CHUNK_LOD {
        return Err(AppError::bad_request(
            code::LOD_OUT_OF_RANGE,
            "lod",
            format!("chunk lod must be in 0..={MAX_CHUNK_LOD}, got {lod}"),
        ));
    }
    let x = parse_coord(x, "x")?;
    let y = parse_coord(y, "y")?;
    let (z, ext) = split_extension(z_ext);
    let z = parse_coord(z, "z")?;
    let format = parse_format(ext)?;
    if format == Format::Png {
        return Err(AppError::bad_request(
            code::UNKNOWN_FORMAT,
            "format",
            "chunks are available as .json, .bin or .glb",
        ));
    }
    let key = ChunkKey { lod, x, y, z };
    check_chunk_bounds(plan, key)?;
    Ok((key, format))
}

/// Checks `|x|, |z| ≤ 2·max_tile_coord(lod) − 1` and `|y| ≤ max_chunk_y(lod)`.
pub fn check_chunk_bounds(plan: &WorldPlan, key: ChunkKey) -> Result<(), AppError> {
    let xz = max_chunk_xz(plan.max_tile_coord(key.lod));
    let ymax = max_chunk_y(key.lod);
    for (field, v, max) in [("x", key.x, xz), ("y", key.y, ymax), ("z", key.z, xz)] {
        if v.unsigned_abs() > max.unsigned_abs() {
            return Err(AppError::bad_request(
                code::COORDINATE_OUT_OF_RANGE,
                field,
                format!(
                    "{field} = {v} is outside the supported world: |{field}| ≤ {max} for chunks at lod {}",
                    key.lod
                ),
            ));
        }
    }
    Ok(())
}

/// The ground-plane rectangle whose columns chunk `key` reads (its padded samples), metres: the
/// `strata` elements meeting it are the chunk's in worlds with `chunk_geology: 1`; those with
/// `2` take the elements meeting [`ground_rect`], the columns of the chunk and its neighbours.
fn chunk_rect(key: ChunkKey, spacing_m: f32) -> Rect {
    let s = f64::from(spacing_m);
    let side = CHUNK_CELLS as f64 * s;
    let (x0, z0) = (key.x as f64 * side, key.z as f64 * side);
    Rect {
        min: [x0 - s, z0 - s],
        max: [x0 + side + s, z0 + side + s],
    }
}

/// The world-space box of a chunk's padded samples, metres (`[x, y, z]` corners).
pub(super) fn chunk_box(key: ChunkKey, spacing_m: f32) -> ([f64; 3], [f64; 3]) {
    let s = f64::from(spacing_m);
    let first = key.first_cell();
    (
        first.map(|c| (c - 1) as f64 * s),
        first.map(|c| (c + CHUNK_CELLS as i64 + 1) as f64 * s),
    )
}

/// The height tiles chunk `key` reads its columns from (the same LOD's).
pub(super) fn tile_keys(key: ChunkKey) -> impl Iterator<Item = TileKey> {
    tiles_needed(key)
        .into_iter()
        .map(move |(x, z)| TileKey { lod: key.lod, x, z })
}

/// The ground-plane rectangle whose `strata` elements chunk `key` takes: [`ground_rect`] in
/// worlds with `chunk_geology` 2 and later, else [`chunk_rect`].
pub(super) fn columns_rect(plan: &WorldPlan, key: ChunkKey, spacing_m: f32) -> Rect {
    let chunk_geology = plan.params.chunk_geology;
    if chunk_geology >= 2 {
        ground_rect(key, spacing_m, chunk_geology)
    } else {
        chunk_rect(key, spacing_m)
    }
}

/// The mesh of chunk `key` of the world `view`: from the state's chunk mesh cache
/// ([`super::chunk_meshes`]), or meshed (its tiles through the stage cache, its strata and
/// volume elements) on the blocking pool; the caller holds the synthesis slot.
pub(super) async fn mesh(
    st: &AppState,
    view: &Arc<WorldView>,
    key: ChunkKey,
) -> Result<Arc<ChunkMesh>, AppError> {
    let hash = super::chunk_meshes::mesh_key(view, key);
    st.chunk_meshes
        .get(hash, || mesh_uncached(st, view, key))
        .await
}

/// Meshes chunk `key` of the world `view` on the blocking pool.
async fn mesh_uncached(
    st: &AppState,
    view: &Arc<WorldView>,
    key: ChunkKey,
) -> Result<ChunkMesh, AppError> {
    let mut tiles = Vec::new();
    for tk in tile_keys(key) {
        tiles.push(((tk.x, tk.z), st.tile(view, tk, [false; 4]).await));
    }
    let plan = &view.plan;
    let spacing_m = plan.lods[key.lod as usize].spacing_m;
    let rect = columns_rect(plan, key, spacing_m);
    let strata = view.inputs.strata_meeting(plan.seed, &rect);
    let (lo, hi) = chunk_box(key, spacing_m);
    let mut volumes = Vec::new();
    for v in view.inputs.volumes_meeting(lo, hi) {
        if let Some(solved) = st.volumes.get(st, view, &v).await {
            volumes.push(solved);
        }
    }
    let offload = st.compute.offload();
    let view = view.clone();
    tokio::task::spawn_blocking(move || {
        let views: Vec<TileColumns<'_>> = tiles
            .iter()
            .map(|(t, tile)| TileColumns {
                tile: *t,
                heights: &tile.heights,
                normals: &tile.normals,
                materials: &tile.materials,
            })
            .collect();
        let cols = gather_columns(key, &views)
            .ok_or_else(|| AppError::internal("chunk tiles are incomplete"))?;
        mesh_world_chunk(
            key,
            &view.plan,
            &cols,
            &volumes,
            &strata,
            &mut QuadMesh::default(),
            &offload,
        )
        .map_err(|e| AppError::internal(format!("chunk meshing failed: {e}")))
    })
    .await
    .map_err(|e| AppError::internal(format!("chunk synthesis failed: {e}")))?
}

/// Meshes and encodes chunk `key` of the world `view` in one synthesis slot (the chunk route's
/// body; the stream's chunk frames carry the same bytes).
pub(super) async fn product(
    st: &AppState,
    view: Arc<WorldView>,
    key: ChunkKey,
    format: Format,
) -> Result<CachedProduct, AppError> {
    let state = st.clone();
    st.limited(async move {
        let mesh = mesh(&state, &view, key).await?;
        let info = ChunkInfo {
            seed: view.plan.seed,
            key,
            spacing_m: view.plan.lods[key.lod as usize].spacing_m,
        };
        tokio::task::spawn_blocking(move || {
            let (body, content_type) = match format {
                Format::Json => (encode_json(&info, &mesh), Format::Json.content_type()),
                Format::Bin => (encode_bin(&info, &mesh), BIN_CONTENT_TYPE),
                _ => (chunk_glb::encode(&info, &mesh), Format::Glb.content_type()),
            };
            CachedProduct::new(body, content_type, Vec::new())
        })
        .await
        .map_err(|e| AppError::internal(format!("chunk encoding failed: {e}")))
    })
    .await
}

/// `GET /v1/seeds/{seed}/chunks/{lod}/{x}/{y}/{z}.{ext}` and
/// `GET /v1/worlds/{id}/chunks/{lod}/{x}/{y}/{z}.{ext}[?v=N]`. Chunk bodies are not cached
/// (their tiles and meshes are, [`super::chunk_meshes`]), so every request encodes its chunk and
/// is charged to the client's rate limit ([`super::rate_limit`]).
async fn chunk(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    path: Segments,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, y, z_ext) = segments(path)?;
    let (key, format) = parse_chunk(&world.view.plan, &lod, &x, &y, &z_ext)?;
    let p = product(&st, world.view.clone(), key, format).await?;
    Ok(world.finish(p.respond(&headers)))
}
