//! Import and export of an authored region over HTTP (issue 4, item 4), with the encodings of
//! [`crate::authoring::exchange`] (Guérin et al. 2022, §3):
//!
//! | route | who | answer |
//! |---|---|---|
//! | `GET /v1/worlds/{id}/regions/{rid}/heightmap.png[?v=N]` | read | 16-bit greyscale PNG of the solved heights; range in `X-Strata-Lo-M` / `X-Strata-Hi-M` |
//! | `GET /v1/worlds/{id}/regions/{rid}/gradients.png[?v=N]` | read | the two-channel gradient map (16-bit RGB, blue 0); `m` in `X-Strata-Gradient-M` |
//! | `POST /v1/worlds/{id}/regions/{rid}/heightmap.png?lo_m=&hi_m=[&spacing_m=&target=x,z&rotation_deg=&scale=]` (`image/png`) | edit | `{id, version, region, op}` after the commit |
//!
//! The import appends to the region, at the latest version, a `copy_paste` operation whose
//! source is the uploaded heightmap carried inline in the scene (base64, at most
//! [`MAX_HEIGHTMAP_BASE64`] characters, so at most [`MAX_IMPORT_PNG_BYTES`] of PNG): its
//! gradients replace the region's over the footprint and the reconstruction blends it into the
//! surroundings. By default the image spans the region (`spacing_m = max(width, depth) /
//! (max(pixels) − 1)`, centred on the region's centre); the query places it otherwise. The
//! scene stays the one source of truth: the import is an ordinary edit, in the edit log. With
//! `If-Match` it applies only to that version (409 otherwise); without it, a concurrent edit is
//! retried on the new head up to [`super::worlds::EDIT_ATTEMPTS`] times.

use super::edit_service::commit_on_head;
use super::error::{code, truncate, AppError};
use super::http::{
    authorize, check_content_type, json_response, parse_if_match, query_param, set_version_headers,
};
use super::route_table::RouteTable;
use super::view::{WorldAt, WorldView};
use super::AppState;
use crate::authoring::exchange::{export_gradient_map, export_png16, ExchangeError};
use crate::authoring::spec_tools::{Heightmap, MAX_HEIGHTMAP_BASE64};
use crate::authoring::Displacement;
use crate::store::Role;
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderMap, HeaderName, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde_json::{json, Value};
use std::sync::Arc;

/// Largest uploaded PNG, bytes: what fits in [`MAX_HEIGHTMAP_BASE64`] base64 characters.
pub const MAX_IMPORT_PNG_BYTES: usize = MAX_HEIGHTMAP_BASE64 / 4 * 3;
/// Elevation of PNG value 0 on export, metres.
pub const LO_HEADER: &str = "x-strata-lo-m";
/// Elevation of PNG value 65535 on export, metres.
pub const HI_HEADER: &str = "x-strata-hi-m";
/// The gradient map's `m` (largest absolute component) on export.
pub const GRADIENT_M_HEADER: &str = "x-strata-gradient-m";

/// The routes of this module (merged into the service's router).
pub(super) fn routes() -> RouteTable {
    RouteTable::new()
        .get(
            "/v1/worlds/{id}/regions/{rid}/heightmap.png",
            region_png::<HeightmapPng>,
        )
        .post("/v1/worlds/{id}/regions/{rid}/heightmap.png", heightmap_in)
        .get(
            "/v1/worlds/{id}/regions/{rid}/gradients.png",
            region_png::<GradientsPng>,
        )
}

fn bad(field: &'static str, message: impl Into<String>) -> AppError {
    AppError::bad_request(code::BAD_PARAMETER, field, message)
}

/// A finite number from the query, or `default` when absent (`None` default: required).
fn number(query: Option<&str>, name: &'static str, default: Option<f64>) -> Result<f64, AppError> {
    match (query_param(query, name), default) {
        (Some(v), _) => v
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| bad(name, format!("{name} must be a finite number"))),
        (None, Some(d)) => Ok(d),
        (None, None) => Err(bad(name, format!("{name} is required"))),
    }
}

/// The solved region `rid` of the world `view` (stored world `id`).
pub(super) async fn solved(
    st: &AppState,
    view: &WorldView,
    id: &str,
    rid: &str,
) -> Result<Arc<Displacement>, AppError> {
    let region = view
        .inputs
        .region(rid)
        .ok_or_else(|| no_region(id, rid, view.version()))?;
    st.regions
        .get(&view.plan, region, st.compute.offload())
        .await
        .ok_or_else(|| AppError::internal("the region could not be solved"))
}

/// 404 `not_found` naming `rid`: world `id` has no region `rid` at `version`.
pub(super) fn no_region(id: &str, rid: &str, version: u64) -> AppError {
    AppError::new(
        StatusCode::NOT_FOUND,
        code::NOT_FOUND,
        format!(
            "world {id} has no region {:?} at version {version}",
            truncate(rid, 128)
        ),
    )
    .with_field("rid")
}

/// A PNG answer with the version and extra headers.
fn png_response(bytes: Vec<u8>, version: u64, extra: &[(&'static str, String)]) -> Response {
    let mut res = (StatusCode::OK, bytes).into_response();
    let h = res.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static("image/png"));
    h.insert(
        header::CACHE_CONTROL,
        HeaderValue::from_static("private, no-cache"),
    );
    set_version_headers(&mut res, version, false);
    let h = res.headers_mut();
    for (k, v) in extra {
        if let Ok(v) = HeaderValue::from_str(v) {
            h.insert(HeaderName::from_static(k), v);
        }
    }
    res
}

async fn blocking<T: Send + 'static>(
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, AppError> {
    tokio::task::spawn_blocking(f)
        .await
        .map_err(|_| AppError::internal("image encoding failed"))
}

/// A PNG and the extra headers that describe it (header name, value).
type EncodedPng = (Vec<u8>, Vec<(&'static str, String)>);

/// A PNG export of an authored region: its encoder, and what a failure of it is called.
trait RegionPng: 'static {
    /// Names the encoding in the message of the 500 `internal` answer when it fails.
    const WHAT: &'static str;
    /// Encodes the solved region as a PNG and the extra headers that describe it.
    fn encode(region: &Displacement) -> Result<EncodedPng, ExchangeError>;
}

/// `heightmap.png`: the 16-bit heights, their range in [`LO_HEADER`] and [`HI_HEADER`].
struct HeightmapPng;

impl RegionPng for HeightmapPng {
    const WHAT: &'static str = "heightmap encoding";
    fn encode(region: &Displacement) -> Result<EncodedPng, ExchangeError> {
        let png = export_png16(region)?;
        let extra = vec![
            (LO_HEADER, png.lo_m.to_string()),
            (HI_HEADER, png.hi_m.to_string()),
        ];
        Ok((png.bytes, extra))
    }
}

/// `gradients.png`: the gradient map, its `m` in [`GRADIENT_M_HEADER`].
struct GradientsPng;

impl RegionPng for GradientsPng {
    const WHAT: &'static str = "gradient map encoding";
    fn encode(region: &Displacement) -> Result<EncodedPng, ExchangeError> {
        let png = export_gradient_map(region)?;
        Ok((png.bytes, vec![(GRADIENT_M_HEADER, png.m.to_string())]))
    }
}

/// `GET /v1/worlds/{id}/regions/{rid}/heightmap.png[?v=N]` (with `P` = [`HeightmapPng`]) and
/// `…/gradients.png[?v=N]` (with [`GradientsPng`]): the region is solved after checking read
/// access, `P` encodes it on the blocking pool, and the answer is [`png_response`]. An encoding
/// failure is 500 `internal` with the message `"{P::WHAT}: {error}"`.
async fn region_png<P: RegionPng>(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    Path((id, rid)): Path<(String, String)>,
) -> Result<Response, AppError> {
    let version = world.view.version();
    let region = solved(&st, &world.view, &id, &rid).await?;
    let (bytes, extra) = blocking(move || P::encode(&region))
        .await?
        .map_err(|e| AppError::internal(format!("{}: {e}", P::WHAT)))?;
    Ok(png_response(bytes, version, &extra))
}

/// `POST /v1/worlds/{id}/regions/{rid}/heightmap.png?lo_m=&hi_m=[…]`: appends a copy-paste of
/// the uploaded heightmap to the region (see the module docs).
async fn heightmap_in(
    State(st): State<AppState>,
    Path((id, rid)): Path<(String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    use base64::Engine;
    authorize(&st, &headers, &id, Role::Edit).await?;
    check_content_type(&headers, "image/png", true)?;
    if body.len() > MAX_IMPORT_PNG_BYTES {
        return Err(AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::PAYLOAD_TOO_LARGE,
            format!(
                "the heightmap is {} bytes; the limit is {MAX_IMPORT_PNG_BYTES}",
                body.len()
            ),
        )
        .with_field("body"));
    }
    let expected = parse_if_match(&headers)?;
    let q = query.as_deref();
    let lo_m = number(q, "lo_m", None)?;
    let hi_m = number(q, "hi_m", None)?;
    let png_base64 = base64::engine::general_purpose::STANDARD.encode(&body);
    // Without `If-Match` the paste goes on the latest version (retried on a concurrent edit).
    let (applied, ops) = commit_on_head(&st, &id, expected, |scene, version| {
        import_patch(scene, &id, &rid, version, q, lo_m, hi_m, &png_base64)
    })
    .await?;
    let mut res = json_response(
        StatusCode::OK,
        json!({ "id": id, "version": applied.version, "region": rid, "op": ops }),
        "no-store",
    );
    set_version_headers(&mut res, applied.version, false);
    Ok(res)
}

/// The edit that appends the import's `copy_paste` operation to region `rid` of `scene` (the
/// world's scene at `version`), and the new operation's index.
#[allow(clippy::too_many_arguments)]
fn import_patch(
    scene: &Value,
    id: &str,
    rid: &str,
    version: u64,
    q: Option<&str>,
    lo_m: f64,
    hi_m: f64,
    png_base64: &str,
) -> Result<(json_patch::Patch, usize), AppError> {
    let regions = scene["regions"].as_array().cloned().unwrap_or_default();
    let Some((index, element)) = regions
        .iter()
        .enumerate()
        .find(|(_, r)| r["id"].as_str() == Some(rid))
    else {
        return Err(no_region(id, rid, version));
    };
    let bbox = |k: &str, c: usize| element["bbox"][k][c].as_f64().unwrap_or(0.0);
    let (min, max) = (
        [bbox("min", 0), bbox("min", 1)],
        [bbox("max", 0), bbox("max", 1)],
    );
    let mut map = Heightmap {
        png_base64: png_base64.to_string(),
        lo_m,
        hi_m,
        spacing_m: 1.0,
    };
    let img = map
        .decode()
        .map_err(|e| AppError::bad_request(code::BAD_BODY, "body", e))?;
    let side = (img.width.max(img.height) - 1) as f64;
    let fit = (max[0] - min[0]).max(max[1] - min[1]) / side;
    map.spacing_m = number(q, "spacing_m", Some(fit))?;
    let target = match query_param(q, "target") {
        None => [0.5 * (min[0] + max[0]), 0.5 * (min[1] + max[1])],
        Some(t) => {
            let xz: Vec<f64> = t.split(',').filter_map(|v| v.trim().parse().ok()).collect();
            match xz.as_slice() {
                [x, z] if x.is_finite() && z.is_finite() => [*x, *z],
                _ => return Err(bad("target", "target must be x,z in metres")),
            }
        }
    };
    let extent = map.extent_m(img.width, img.height);
    let op = json!({
        "op": "copy_paste",
        "source_min": [0.0, 0.0],
        "source_max": extent,
        "target": target,
        "rotation_deg": number(q, "rotation_deg", Some(0.0))?,
        "scale": number(q, "scale", Some(1.0))?,
        "heightmap": map,
    });
    let ops = element["ops"].as_array().map_or(0, Vec::len);
    let patch: json_patch::Patch = serde_json::from_value(json!([
        {"op": "test", "path": format!("/regions/{index}/id"), "value": rid},
        {"op": "add", "path": format!("/regions/{index}/ops/-"), "value": op},
    ]))
    .map_err(|e| AppError::internal(format!("import patch: {e}")))?;
    Ok((patch, ops))
}

/// Parses `x,z;x,z;…` (metres) for the stats readout.
fn parse_points(text: &str, field: &'static str) -> Result<Vec<[f64; 2]>, AppError> {
    let bad = || {
        AppError::bad_request(
            code::BAD_COORDINATE,
            field,
            format!("{field} must be x,z pairs in metres separated by ';'"),
        )
    };
    let points = text
        .split(';')
        .map(|pair| {
            let mut it = pair.split(',').map(|v| v.trim().parse::<f64>());
            match (it.next(), it.next(), it.next()) {
                (Some(Ok(x)), Some(Ok(z)), None) if x.is_finite() && z.is_finite() => Ok([x, z]),
                _ => Err(bad()),
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    if points.is_empty() || points.len() > crate::authoring::MAX_POINTS {
        return Err(bad());
    }
    Ok(points)
}

/// `GET /v1/worlds/{id}/regions/{rid}/stats?point=x,z | polyline=x,z;x,z;… |
/// rect=x0,z0;x1,z1 [&v=N]`: elevation (min, mean, max, metres) and mean and steepest slope
/// (degrees) of the authored region's heights over a point, a curve or a rectangle (Guérin et al.
/// §6.3).
pub(super) async fn region_stats(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    Path((id, rid)): Path<(String, String)>,
    RawQuery(query): RawQuery,
) -> Result<Response, AppError> {
    use crate::authoring::stats::{stats, StatsShape};
    let query = query.as_deref();
    let view = &world.view;
    let version = view.version();
    let shape = match (
        query_param(query, "point"),
        query_param(query, "polyline"),
        query_param(query, "rect"),
    ) {
        (Some(p), None, None) => StatsShape::Point(parse_points(p, "point")?[0]),
        (None, Some(p), None) => StatsShape::Polyline(parse_points(p, "polyline")?),
        (None, None, Some(p)) => match parse_points(p, "rect")?.as_slice() {
            [a, b] => StatsShape::Rect {
                min: [a[0].min(b[0]), a[1].min(b[1])],
                max: [a[0].max(b[0]), a[1].max(b[1])],
            },
            _ => {
                return Err(AppError::bad_request(
                    code::BAD_COORDINATE,
                    "rect",
                    "rect must be two corners: x0,z0;x1,z1",
                ))
            }
        },
        _ => {
            return Err(AppError::bad_request(
                code::BAD_COORDINATE,
                "point",
                "give exactly one of point, polyline and rect",
            ))
        }
    };
    let solved = super::region_io::solved(&st, view, &id, &rid).await?;
    let s = stats(&solved, &shape)
        .map_err(|e| AppError::bad_request(code::BAD_COORDINATE, e.field, e.message))?;
    let mut res = json_response(
        StatusCode::OK,
        json!({ "region": rid, "version": version, "stats": s }),
        "private, no-cache",
    );
    set_version_headers(&mut res, version, false);
    Ok(res)
}
