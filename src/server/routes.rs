//! Route table, handlers, conditional requests and the middleware stack.

use super::error::{code, AppError};
use super::params::{parse_seams, parse_tile_path, parse_tile_version};
use super::rate_limit::{Charge, Client};
use super::route_table::RouteTable;
use super::view::WorldAt;
use super::{AppState, MAX_BODY_BYTES};
use crate::encode::{self, Format, TileVersion};
use crate::terrain::plan::{TILE_QUADS, WORLD_LIMIT_CELLS};
use crate::terrain::scatter;
use crate::terrain::world::MATERIALS;
use crate::terrain::{Tile, WorldPlan, MAX_LOD, MIN_LOD, TILE_VERTEX_COUNT, TILE_VERTS};
use axum::extract::rejection::PathRejection;
use axum::extract::{DefaultBodyLimit, Path, RawQuery, Request, State};
use axum::http::{header, HeaderMap, HeaderName, HeaderValue, StatusCode, Uri};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::{Json, Router};
use serde_json::json;
use std::sync::Arc;
use tower_http::compression::predicate::{Predicate, SizeAbove};
use tower_http::compression::CompressionLayer;
use tower_http::services::ServeDir;
use tower_http::timeout::RequestBodyTimeoutLayer;
use tower_http::trace::TraceLayer;

/// `Cache-Control` of product URLs: their content is a pure function of the URL.
pub const IMMUTABLE: &str = "public, max-age=31536000, immutable";
/// Header with the height of PNG value 0, metres.
pub const HEIGHT_OFFSET_HEADER: &str = "x-strata-height-offset-m";
/// Header with the metres per PNG value unit.
pub const HEIGHT_SCALE_HEADER: &str = "x-strata-height-scale-m";
/// Hex digits of the blake3 content hash kept in the `ETag` (128 bits).
pub const ETAG_HEX_DIGITS: usize = 32;
/// JSON responses at least this long are gzip-compressed when the client accepts gzip.
pub const COMPRESS_MIN_BYTES: u16 = 256;

/// Every route the server serves, as the router is built from it (the module docs of [`super`]
/// describe them; `tests/openapi_routes.rs` compares them with `api/openapi.yaml`). The viewer
/// directory is the router's fallback, not a route.
pub fn table() -> RouteTable {
    RouteTable::new()
        .get("/healthz", healthz)
        .get("/v1/info", info)
        .get("/v1/seeds/{seed}/tiles/{lod}/{x}/{z_ext}", tile)
        .get("/v1/seeds/{seed}/scatter/{lod}/{x}/{z_ext}", scatter)
        .get("/metrics", super::metrics::render)
        .merge(super::rivers::routes())
        .merge(super::worlds::routes())
        .merge(super::region_io::routes())
        .merge(super::exports::routes())
        .merge(super::chunks::routes())
        .merge(super::ptex_routes::routes())
        .merge(super::images::routes())
        .merge(super::volume_routes::routes())
        .merge(super::geology::routes())
        .merge(super::stream_routes::router())
}

/// Builds the router from [`table`], with the viewer directory as its fallback.
pub fn router(state: AppState) -> Router {
    let routes = table()
        .into_router()
        .method_not_allowed_fallback(method_not_allowed);
    let routes = match &state.web {
        Some(dir) => {
            let files = ServeDir::new(dir);
            routes.fallback(move |req: Request| web_file(files.clone(), req))
        }
        None => routes.fallback(not_found),
    };
    let json_only =
        |status: StatusCode, _: axum::http::Version, h: &HeaderMap, _: &axum::http::Extensions| {
            status == StatusCode::OK
                && h.get(header::CONTENT_TYPE)
                    .and_then(|v| v.to_str().ok())
                    .is_some_and(|v| v.starts_with("application/json"))
        };
    let metrics = state.metrics.clone();
    let cors = state.cors.layer();
    let body_read_timeout = state.limits().body_read_timeout;
    routes
        .with_state(state)
        .layer(middleware::from_fn_with_state(
            metrics,
            super::metrics::track,
        ))
        .layer(RequestBodyTimeoutLayer::new(body_read_timeout))
        .layer(middleware::from_fn(limit_body))
        .layer(middleware::from_fn(json_errors))
        .layer(DefaultBodyLimit::max(MAX_BODY_BYTES))
        .layer(
            CompressionLayer::new()
                .gzip(true)
                .compress_when(SizeAbove::new(COMPRESS_MIN_BYTES).and(json_only)),
        )
        .layer(middleware::map_response(etag_per_encoding))
        .layer(cors)
        .layer(TraceLayer::new_for_http())
}

async fn healthz() -> Response {
    let mut res = Json(json!({ "status": "ok" })).into_response();
    res.headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

async fn info(State(st): State<AppState>) -> Result<Response, AppError> {
    let plan = st.plan(0).await?;
    let limits = st.limits();
    let cell_m = plan.params.cell_m as f64;
    let doc = json!({
        "name": "strata",
        "version": env!("CARGO_PKG_VERSION"),
        "api": "v1",
        "backend": st.compute.info(),
        "limits": {
            "min_lod": MIN_LOD,
            "max_lod": MAX_LOD,
            "tile_size": TILE_VERTS,
            "tile_quads": TILE_QUADS,
            "vertex_count": TILE_VERTEX_COUNT,
            "world_limit_cells": WORLD_LIMIT_CELLS,
            "world_limit_m": WORLD_LIMIT_CELLS * cell_m,
            "max_tile_coord": (MIN_LOD..=MAX_LOD).map(|l| plan.max_tile_coord(l)).collect::<Vec<_>>(),
            "max_concurrent_syntheses": limits.max_concurrent_syntheses,
            "synthesis_timeout_ms": limits.synthesis_timeout.as_millis() as u64,
            "max_body_bytes": MAX_BODY_BYTES,
            "plan_cache_seeds": limits.plan_cache_seeds,
            "memory_budget_bytes": st.memory_budget().total,
            "max_river_lod": crate::terrain::earth::rivers::MAX_CARVE_LOD,
            "scatter_max_candidates": scatter::MAX_CANDIDATES,
            "max_log_entries": crate::store::MAX_LOG_ENTRIES,
            "max_stream_message_bytes": crate::stream::session::MAX_MESSAGE_BYTES,
            "header_read_timeout_ms": limits.header_read_timeout.as_millis() as u64,
            "body_read_timeout_ms": limits.body_read_timeout.as_millis() as u64,
            "max_connections": limits.max_connections,
            "max_export_tiles": crate::export::MAX_EXPORT_TILES,
            "export_world_budget_bytes": st.jobs.limits().world_budget_bytes,
            "export_disk_budget_bytes": st.jobs.limits().disk_budget_bytes,
            "export_max_age_s": st.jobs.limits().max_age.as_secs(),
            "rate_limit_per_minute": st.rate.per_minute(),
            "ptex_session_budget_bytes": st.ptex.settings().session_bytes,
            "ptex_server_budget_bytes": st.ptex.settings().server_bytes,
            "ptex_thresholds_m": st.ptex.settings().thresholds_m,
            "max_region_samples": crate::authoring::spec_tools::MAX_ACCEPTED_SAMPLES,
            "max_region_cell_steps": crate::authoring::spec_tools::MAX_REGION_CELL_STEPS,
            "max_ptex_texels": super::ptex_routes::MAX_REQUEST_TEXELS,
            "ptex_bake_threads": super::ptex_routes::bake_threads(),
        },
        "formats": Format::ALL.iter().map(|f| json!({
            "extension": f.extension(),
            "content_type": f.content_type(),
            "products": if *f == Format::Json { vec!["tiles", "scatter", "rivers"] } else { vec!["tiles"] },
            "versions": TileVersion::ALL.iter().filter(|v| v.has(*f)).map(|v| v.number()).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "world": {
            "params": "default",
            "cell_m": plan.params.cell_m,
            "sea_level_m": plan.params.sea_level_m,
            "biomes": plan.params.biomes.iter().map(|b| b.name.as_str()).collect::<Vec<_>>(),
            "materials": MATERIALS,
        },
    });
    let mut res = Json(doc).into_response();
    res.headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    Ok(res)
}

/// The four path segments of a product route (`{seed|id}/{lod}/{x}/{z_ext}`), or why axum could
/// not extract them.
pub(super) type Segments = PathSegments<(String, String, String, String)>;

/// Path segments `T` of a route, or why axum could not extract them.
pub(super) type PathSegments<T> = Result<Path<T>, PathRejection>;

/// Unwraps the path segments of a route. When axum could not extract them (for example,
/// percent-encoding that is not UTF-8), the answer is 400 `bad_path` with the rejection in the
/// message, instead of axum's plain-text rejection.
pub(super) fn segments<T>(path: PathSegments<T>) -> Result<T, AppError> {
    match path {
        Ok(Path(s)) => Ok(s),
        Err(e) => Err(AppError::new(
            StatusCode::BAD_REQUEST,
            code::BAD_PATH,
            format!("invalid path: {e}"),
        )),
    }
}

/// `GET /v1/seeds/{seed}/tiles/{lod}/{x}/{z}.{ext}` and
/// `GET /v1/worlds/{id}/tiles/{lod}/{x}/{z}.{ext}[?v=N]`, both `[?seams=n,e,s,w][&format=1|2]`.
/// A tile whose body is not cached is charged to the client's rate limit ([`super::rate_limit`]).
pub(super) async fn tile(
    client: Client,
    world: WorldAt,
    State(st): State<AppState>,
    path: Segments,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, z_ext) = segments(path)?;
    let (key, format) = parse_tile_path(&world.view.plan, &lod, &x, &z_ext)?;
    let seams = parse_seams(query.as_deref())?;
    let version = parse_tile_version(query.as_deref(), format)?;
    let hash = world.view.tile_hash(key, seams);
    if !st.tile_is_cached(hash, format, version) {
        st.rate.check(&client)?;
    }
    let product = st
        .tile_product_hashed(&world.view, hash, key, seams, format, version)
        .await?;
    Ok(world.finish(product.respond(&headers)))
}

/// `GET /v1/seeds/{seed}/scatter/{lod}/{x}/{z}.json` and
/// `GET /v1/worlds/{id}/scatter/{lod}/{x}/{z}.json[?v=N]`.
pub(super) async fn scatter(
    _charge: Charge,
    world: WorldAt,
    State(st): State<AppState>,
    path: Segments,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (_, lod, x, z_ext) = segments(path)?;
    let (key, format) = parse_tile_path(&world.view.plan, &lod, &x, &z_ext)?;
    check_scatter_format(format)?;
    check_scatter_cost(&world.view.plan, key.lod)?;
    let (state, view) = (st.clone(), world.view.clone());
    let product = st
        .limited(async move {
            let tile = state.tile(&view, key, [false; 4]).await;
            scatter_product(view.plan.clone(), tile).await
        })
        .await?;
    Ok(world.finish(product.respond(&headers)))
}

/// Refuses a scatter request for any format but JSON: 400 `unknown_format` naming `format`.
pub(super) fn check_scatter_format(format: Format) -> Result<(), AppError> {
    if format == Format::Json {
        return Ok(());
    }
    Err(AppError::bad_request(
        code::UNKNOWN_FORMAT,
        "format",
        "scatter is only available as .json",
    ))
}

/// Refuses scatter that would visit more than [`scatter::MAX_CANDIDATES`] candidates: 400
/// `lod_out_of_range` naming `lod`, before any work.
pub(super) fn check_scatter_cost(plan: &WorldPlan, lod: u32) -> Result<(), AppError> {
    match scatter::cost_error(plan, lod) {
        Some(message) => Err(AppError::bad_request(
            code::LOD_OUT_OF_RANGE,
            "lod",
            message,
        )),
        None => Ok(()),
    }
}

/// Encodes the scatter points of `tile` (of the world `plan`) as a JSON product, on the
/// blocking pool.
pub(super) async fn scatter_product(
    plan: Arc<WorldPlan>,
    tile: Arc<Tile>,
) -> Result<Product, AppError> {
    let body = blocking(move || encode::scatter::encode(&plan, &tile)).await?;
    Ok(Product {
        body,
        content_type: Format::Json.content_type(),
        extra: Vec::new(),
    })
}

/// Runs the encoding `f` (or the tracing of river lines, [`super::rivers`]) on the blocking
/// thread pool. If the task panics or is cancelled, the failure is logged and the answer is 500
/// `internal` ("encoding failed").
pub(super) async fn blocking<T: Send + 'static>(
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, AppError> {
    tokio::task::spawn_blocking(f).await.map_err(|e| {
        tracing::error!("encoding failed: {e}");
        AppError::internal("encoding failed")
    })
}

async fn not_found(uri: Uri) -> AppError {
    AppError::not_found(uri.path())
}

/// Longest file name the viewer directory can hold (`NAME_MAX` on Linux), bytes.
pub const MAX_FILE_NAME_BYTES: usize = 255;

/// A file of the viewer directory. A path segment longer than any file name is 404 `not_found`
/// without a look-up (the file system would refuse it with `ENAMETOOLONG`), and a file that
/// cannot be read is 500 `internal`, both in the JSON error shape.
async fn web_file(mut files: ServeDir, req: Request) -> Response {
    let path = req.uri().path().to_owned();
    let too_long = path
        .split('/')
        .any(|s| percent_encoding::percent_decode_str(s).count() > MAX_FILE_NAME_BYTES);
    if too_long {
        return AppError::not_found(&path).into_response();
    }
    match files.try_call(req).await {
        Ok(res) if res.status() == StatusCode::NOT_FOUND => {
            AppError::not_found(&path).into_response()
        }
        Ok(res) => res.map(axum::body::Body::new),
        Err(e) if e.kind() == std::io::ErrorKind::InvalidFilename => {
            AppError::not_found(&path).into_response()
        }
        Err(e) => {
            tracing::warn!(path = %super::error::truncate(&path, 200), "cannot read a viewer file: {e}");
            AppError::internal("cannot read the file").into_response()
        }
    }
}

/// Every error in the JSON shape of [`AppError`]. A path whose percent-encoding is not UTF-8 is
/// refused before routing (400 `bad_path`), whatever the route. Any other error
/// response that is not JSON (an extractor's rejection, such as the body limit met by a chunked
/// body) is rewritten with the code of its status and its text as the message; its `Allow` and
/// `Upgrade` headers are kept.
async fn json_errors(req: Request, next: Next) -> Response {
    if percent_encoding::percent_decode_str(req.uri().path())
        .decode_utf8()
        .is_err()
    {
        return AppError::new(
            StatusCode::BAD_REQUEST,
            code::BAD_PATH,
            "the path's percent-encoding is not UTF-8",
        )
        .into_response();
    }
    let res = next.run(req).await;
    let is_json = res
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.starts_with("application/json"));
    if res.status().as_u16() < 400 || is_json {
        return res;
    }
    let (parts, body) = res.into_parts();
    let status = parts.status;
    let text = axum::body::to_bytes(body, 4096)
        .await
        .map(|b| String::from_utf8_lossy(&b).trim().to_owned())
        .unwrap_or_default();
    let message = if text.is_empty() {
        status.canonical_reason().unwrap_or("error").to_owned()
    } else {
        text
    };
    let error = match status {
        StatusCode::NOT_FOUND => AppError::new(status, code::NOT_FOUND, message),
        StatusCode::METHOD_NOT_ALLOWED => AppError::new(status, code::METHOD_NOT_ALLOWED, message),
        StatusCode::PAYLOAD_TOO_LARGE => AppError::new(
            status,
            code::PAYLOAD_TOO_LARGE,
            format!("request bodies are limited to {MAX_BODY_BYTES} bytes ({message})"),
        )
        .with_field("body"),
        StatusCode::UNSUPPORTED_MEDIA_TYPE => {
            AppError::new(status, code::UNSUPPORTED_MEDIA_TYPE, message).with_field("Content-Type")
        }
        StatusCode::UPGRADE_REQUIRED => {
            AppError::new(status, code::UPGRADE_REQUIRED, message).with_field("Upgrade")
        }
        s if s.is_server_error() => AppError::new(s, code::INTERNAL, message),
        s => AppError::new(s, code::BAD_REQUEST, message),
    };
    let mut out = error.into_response();
    for name in [header::ALLOW, header::UPGRADE, header::RETRY_AFTER] {
        if let Some(v) = parts.headers.get(&name) {
            out.headers_mut().insert(name, v.clone());
        }
    }
    out
}

async fn method_not_allowed() -> AppError {
    AppError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        code::METHOD_NOT_ALLOWED,
        "this method is not supported here; the Allow header lists those that are",
    )
}

/// Refuses declared bodies larger than [`MAX_BODY_BYTES`] before any handler runs.
async fn limit_body(req: Request, next: Next) -> Response {
    let declared = req
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > MAX_BODY_BYTES as u64) {
        return AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::PAYLOAD_TOO_LARGE,
            format!("request bodies are limited to {MAX_BODY_BYTES} bytes"),
        )
        .into_response();
    }
    next.run(req).await
}

/// A compressed representation gets its own entity tag, `"<hash>-gzip"`, as different bytes must.
async fn etag_per_encoding(mut res: Response) -> Response {
    let gzip = res
        .headers()
        .get(header::CONTENT_ENCODING)
        .is_some_and(|v| v.as_bytes() == b"gzip");
    if gzip {
        let tag = res
            .headers()
            .get(header::ETAG)
            .and_then(|v| v.to_str().ok())
            .and_then(|t| t.strip_prefix('"')?.strip_suffix('"').map(str::to_owned));
        if let Some(tag) = tag {
            if let Ok(v) = HeaderValue::from_str(&format!("\"{tag}-gzip\"")) {
                res.headers_mut().insert(header::ETAG, v);
            }
        }
    }
    res
}

/// An encoded product ready to be answered.
#[derive(Debug)]
pub struct Product {
    /// The bytes.
    pub body: Vec<u8>,
    /// `Content-Type`.
    pub content_type: &'static str,
    /// Extra headers (`X-Strata-*`).
    pub extra: Vec<(HeaderName, String)>,
}

impl From<encode::EncodedTile> for Product {
    /// A tile product: a PNG carries its height mapping in the `X-Strata-Height-*` headers.
    fn from(t: encode::EncodedTile) -> Self {
        let extra = t
            .png_mapping
            .map(|m| {
                vec![
                    (
                        HeaderName::from_static(HEIGHT_OFFSET_HEADER),
                        m.offset_m.to_string(),
                    ),
                    (
                        HeaderName::from_static(HEIGHT_SCALE_HEADER),
                        m.scale_m.to_string(),
                    ),
                ]
            })
            .unwrap_or_default();
        Product {
            body: t.body,
            content_type: t.content_type,
            extra,
        }
    }
}

impl From<encode::EncodedTile> for CachedProduct {
    fn from(t: encode::EncodedTile) -> Self {
        let p = Product::from(t);
        CachedProduct::new(p.body, p.content_type, p.extra)
    }
}

/// The entity tag of some bytes: the first [`ETAG_HEX_DIGITS`] hex digits of their blake3 hash.
pub fn content_hash(body: &[u8]) -> String {
    let hex = blake3::hash(body).to_hex();
    hex[..ETAG_HEX_DIGITS].to_string()
}

/// The tag of `If-None-Match` that matches `hash` (any encoding variant, weak or strong, or `*`),
/// normalised to the form this server sends.
fn matching_tag(req: &HeaderMap, hash: &str) -> Option<String> {
    for value in req.get_all(header::IF_NONE_MATCH) {
        let Ok(value) = value.to_str() else { continue };
        for tag in value.split(',').map(str::trim) {
            if tag == "*" {
                return Some(format!("\"{hash}\""));
            }
            let opaque = tag.strip_prefix("W/").unwrap_or(tag);
            let Some(inner) = opaque.strip_prefix('"').and_then(|t| t.strip_suffix('"')) else {
                continue;
            };
            if inner == hash {
                return Some(format!("\"{hash}\""));
            }
            if inner.strip_suffix("-gzip") == Some(hash) {
                return Some(format!("\"{hash}-gzip\""));
            }
        }
    }
    None
}

impl Product {
    /// 200 with the body, or 304 if `If-None-Match` names it; caching headers on both.
    pub fn respond(self, req: &HeaderMap) -> Response {
        CachedProduct::new(self.body, self.content_type, self.extra).respond(req)
    }
}

/// A product with its content hash computed once, shared by every answer that serves it.
#[derive(Debug, Clone)]
pub struct CachedProduct {
    /// The bytes (reference counted: answering clones no bytes).
    pub body: axum::body::Bytes,
    /// Content hash, the ETag's value.
    pub hash: String,
    /// `Content-Type`.
    pub content_type: &'static str,
    /// Extra headers (`X-Strata-*`).
    pub extra: Vec<(HeaderName, String)>,
}

impl CachedProduct {
    /// Hashes `body` once.
    pub fn new(
        body: Vec<u8>,
        content_type: &'static str,
        extra: Vec<(HeaderName, String)>,
    ) -> Self {
        Self {
            hash: content_hash(&body),
            body: body.into(),
            content_type,
            extra,
        }
    }

    /// The answer: 200 with the body, or 304 when `If-None-Match` names it; with the ETag and
    /// cache headers.
    pub fn respond(&self, req: &HeaderMap) -> Response {
        let (mut res, etag) = match matching_tag(req, &self.hash) {
            Some(tag) => (StatusCode::NOT_MODIFIED.into_response(), tag),
            None => {
                let mut res = (StatusCode::OK, self.body.clone()).into_response();
                res.headers_mut().insert(
                    header::CONTENT_TYPE,
                    HeaderValue::from_static(self.content_type),
                );
                (res, format!("\"{}\"", self.hash))
            }
        };
        let h = res.headers_mut();
        if let Ok(v) = HeaderValue::from_str(&etag) {
            h.insert(header::ETAG, v);
        }
        h.insert(header::CACHE_CONTROL, HeaderValue::from_static(IMMUTABLE));
        h.insert(
            header::X_CONTENT_TYPE_OPTIONS,
            HeaderValue::from_static("nosniff"),
        );
        for (name, value) in &self.extra {
            if let Ok(v) = HeaderValue::from_str(value) {
                h.insert(name.clone(), v);
            }
        }
        res
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn if_none_match_forms() {
        let h = |v: &str| {
            let mut m = HeaderMap::new();
            m.insert(
                header::IF_NONE_MATCH,
                HeaderValue::from_str(v).expect("header"),
            );
            m
        };
        assert_eq!(
            matching_tag(&h("\"abc\""), "abc").as_deref(),
            Some("\"abc\"")
        );
        assert_eq!(
            matching_tag(&h("W/\"abc\""), "abc").as_deref(),
            Some("\"abc\"")
        );
        assert_eq!(
            matching_tag(&h("\"x\", \"abc-gzip\""), "abc").as_deref(),
            Some("\"abc-gzip\"")
        );
        assert_eq!(matching_tag(&h("*"), "abc").as_deref(), Some("\"abc\""));
        assert_eq!(matching_tag(&h("\"abd\""), "abc"), None);
        assert_eq!(matching_tag(&h("abc"), "abc"), None);
        assert_eq!(matching_tag(&HeaderMap::new(), "abc"), None);
    }
}
