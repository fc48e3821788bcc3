//! What the world routes share over HTTP: access checks ([`authorize`]), the version a request
//! names (`?v=N`, [`requested_version`], `If-Match`, [`parse_if_match`]), JSON bodies and
//! answers with the one error shape ([`parse_body`], [`json_response`], [`store_error`]) and the
//! caching headers of world products ([`product_headers`]).
//!
//! A product URL with `v` is immutable (`Cache-Control: public, max-age=31536000, immutable`,
//! `private` for private worlds); without `v` it is the latest version, cached for
//! [`LATEST_MAX_AGE_S`] seconds and revalidated by its content-hash `ETag`. Every product
//! answer names its version in [`VERSION_HEADER`].

use super::access::{caller, Caller};
use super::error::{code, AppError};
use super::routes::IMMUTABLE;
use super::AppState;
use crate::store::{valid_world_id, Role, StoreError, WorldMeta};
use axum::http::{header, HeaderMap, HeaderName, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde_json::Value;

/// Seconds a product URL without `v` (the latest version) may be cached.
pub const LATEST_MAX_AGE_S: u32 = 5;

/// Header naming the version a product or scene answer is of.
pub const VERSION_HEADER: &str = "x-strata-version";

/// The media type of edits.
pub const JSON_PATCH: &str = "application/json-patch+json";

/// Maps a store failure to its HTTP answer.
pub(super) fn store_error(e: StoreError) -> AppError {
    match e {
        StoreError::WorldNotFound(id) => world_not_found(&id),
        StoreError::VersionNotFound { version, latest } => AppError::new(
            StatusCode::NOT_FOUND,
            code::VERSION_NOT_FOUND,
            format!("version {version} does not exist; the latest is {latest}"),
        )
        .with_field("v"),
        StoreError::Conflict { expected, latest } => AppError::new(
            StatusCode::CONFLICT,
            code::VERSION_CONFLICT,
            format!("If-Match names version {expected} but the latest is {latest}"),
        )
        .with_field("If-Match"),
        StoreError::Patch { operation, message } => AppError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            code::PATCH_FAILED,
            format!("patch operation {operation} cannot be applied: {message}"),
        )
        .with_field(format!("/{operation}")),
        StoreError::Invalid(e) => AppError::bad_request(
            code::INVALID_SCENE,
            e.pointer.clone(),
            format!("the scene would be invalid: {}", e.message),
        ),
        StoreError::TooLarge { bytes, limit } => AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::SCENE_TOO_LARGE,
            format!("the scene would be {bytes} bytes; the limit is {limit}"),
        ),
        StoreError::TooManyImages { limit } => AppError::new(
            StatusCode::CONFLICT,
            code::TOO_MANY_IMAGES,
            format!("a world holds at most {limit} images"),
        )
        .with_field("body"),
        StoreError::Duplicate(_) | StoreError::Backend(_) => {
            tracing::error!("scene store: {e}");
            AppError::internal("the scene store failed")
        }
    }
}

fn world_not_found(id: &str) -> AppError {
    AppError::new(
        StatusCode::NOT_FOUND,
        code::WORLD_NOT_FOUND,
        format!("no world {:?}", super::error::truncate(id, 64)),
    )
    .with_field("id")
}

/// The world `id` and the caller, after checking that the caller has `need` on it.
pub(crate) async fn authorize(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    need: Role,
) -> Result<(WorldMeta, Caller), AppError> {
    if !valid_world_id(id) {
        return Err(world_not_found(id));
    }
    let w = &st.worlds;
    let who = caller(headers, w.admin(), &*w.store).await?;
    let meta = w.store.meta(id).await.map_err(store_error)?;
    who.require(&meta, need)?;
    Ok((meta, who))
}

/// Checks that the caller has `need` on world `id` and that the body is JSON (a missing
/// `Content-Type` is accepted), then parses the body as [`parse_body`] does. Returns the world
/// and the parsed body; the checks run in that order, so the first failing one is answered.
pub(super) async fn authorized_body<T: serde::de::DeserializeOwned>(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    need: Role,
    body: &[u8],
) -> Result<(WorldMeta, T), AppError> {
    let (meta, _) = authorize(st, headers, id, need).await?;
    check_content_type(headers, "application/json", false)?;
    Ok((meta, parse_body(body)?))
}

/// Refuses a body whose `Content-Type` is present and not `want` (parameters ignored); with
/// `required`, a missing `Content-Type` is refused too.
pub(super) fn check_content_type(
    headers: &HeaderMap,
    want: &str,
    required: bool,
) -> Result<(), AppError> {
    let got = headers
        .get(header::CONTENT_TYPE)
        .map(|v| v.to_str().unwrap_or("?"));
    let ok = match got {
        None => !required,
        Some(v) => v
            .split(';')
            .next()
            .is_some_and(|t| t.trim().eq_ignore_ascii_case(want)),
    };
    if ok {
        return Ok(());
    }
    Err(AppError::new(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        code::UNSUPPORTED_MEDIA_TYPE,
        format!(
            "the body must be {want}, got {}",
            got.map(|g| super::error::truncate(g, 60))
                .unwrap_or_else(|| "no Content-Type".into())
        ),
    )
    .with_field("Content-Type"))
}

fn pointer_of(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    path.iter()
        .filter_map(|s| match s {
            Segment::Seq { index } => Some(format!("/{index}")),
            Segment::Map { key } => Some(format!("/{}", crate::scene::escape_token(key))),
            Segment::Enum { variant } => Some(format!("/{}", crate::scene::escape_token(variant))),
            Segment::Unknown => None,
        })
        .collect()
}

/// Parses a JSON body; a syntax error blames `body`, a shape error the JSON pointer of the
/// offending value.
pub(super) fn parse_body<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, AppError> {
    let value: Value = serde_json::from_slice(body).map_err(|e| {
        AppError::bad_request(code::BAD_BODY, "body", format!("the body is not JSON: {e}"))
    })?;
    serde_path_to_error::deserialize(value).map_err(|e| {
        let pointer = pointer_of(e.path());
        AppError::bad_request(
            code::BAD_BODY,
            if pointer.is_empty() {
                "body".to_string()
            } else {
                pointer
            },
            format!("{}", e.inner()),
        )
    })
}

pub(super) fn json_response(status: StatusCode, body: Value, cache: &'static str) -> Response {
    let mut res = (status, Json(body)).into_response();
    res.headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    res
}

fn version_etag(version: u64) -> String {
    format!("\"{version}\"")
}

pub(super) fn set_version_headers(res: &mut Response, version: u64, etag: bool) {
    let h = res.headers_mut();
    h.insert(
        HeaderName::from_static(VERSION_HEADER),
        HeaderValue::from(version),
    );
    if etag {
        if let Ok(v) = HeaderValue::from_str(&version_etag(version)) {
            h.insert(header::ETAG, v);
        }
    }
}

/// A version number: 1 to 19 ASCII digits, at least 1.
pub(crate) fn parse_version(s: &str, field: &'static str) -> Result<u64, AppError> {
    let bad = || {
        AppError::bad_request(
            code::BAD_VERSION,
            field,
            format!(
                "{field} must be a version number (a positive integer), got {:?}",
                super::error::truncate(s, 40)
            ),
        )
    };
    if s.is_empty() || s.len() > 19 || !s.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    match s.parse::<u64>() {
        Ok(v) if v >= 1 => Ok(v),
        _ => Err(bad()),
    }
}

/// The value of a query parameter (first occurrence, no percent-decoding: the parameters read
/// here are plain integers).
pub(crate) fn query_param<'a>(query: Option<&'a str>, name: &str) -> Option<&'a str> {
    query?
        .split('&')
        .filter_map(|p| p.split_once('=').or(Some((p, ""))))
        .find(|(k, _)| *k == name)
        .map(|(_, v)| v)
}

/// `If-Match`: absent or `*` is no condition; else one version, plain or quoted (`5`, `"5"`,
/// `W/"5"`), or the entity tag of a gzip answer (`"5-gzip"`, [`super::routes`]'
/// `etag_per_encoding`), which a client echoing the `ETag` it was given sends back.
pub(super) fn parse_if_match(headers: &HeaderMap) -> Result<Option<u64>, AppError> {
    let Some(v) = headers.get(header::IF_MATCH) else {
        return Ok(None);
    };
    let bad = || {
        AppError::bad_request(
            code::BAD_VERSION,
            "If-Match",
            "If-Match must be one version number, plain or quoted",
        )
    };
    let s = v.to_str().map_err(|_| bad())?.trim();
    if s == "*" {
        return Ok(None);
    }
    let s = s.strip_prefix("W/").unwrap_or(s);
    let s = match s.strip_prefix('"').and_then(|t| t.strip_suffix('"')) {
        Some(tag) => tag.strip_suffix("-gzip").unwrap_or(tag),
        None => s,
    };
    parse_version(s, "If-Match").map(Some).map_err(|_| bad())
}

/// Caching headers of any product of world `meta` at `version` (tiles, chunks, region meshes):
/// immutable when `pinned` by `?v=N`, short-lived otherwise; private and varying by
/// `Authorization` unless the world is public; the version header.
pub(super) fn product_headers(res: &mut Response, meta: &WorldMeta, version: u64, pinned: bool) {
    let cache = match (pinned, meta.public) {
        (true, true) => IMMUTABLE.to_string(),
        (true, false) => "private, max-age=31536000, immutable".to_string(),
        (false, true) => format!("public, max-age={LATEST_MAX_AGE_S}"),
        (false, false) => format!("private, max-age={LATEST_MAX_AGE_S}"),
    };
    if let Ok(v) = HeaderValue::from_str(&cache) {
        res.headers_mut().insert(header::CACHE_CONTROL, v);
    }
    if !meta.public {
        res.headers_mut()
            .insert(header::VARY, HeaderValue::from_static("Authorization"));
    }
    set_version_headers(res, version, false);
}

/// The version a product request names with `?v=N` (the latest without), checked against the
/// world's latest.
pub(crate) fn requested_version(meta: &WorldMeta, query: Option<&str>) -> Result<u64, AppError> {
    let version = match query_param(query, "v") {
        None => meta.version,
        Some(v) => parse_version(v, "v")?,
    };
    if version > meta.version {
        return Err(store_error(StoreError::VersionNotFound {
            version,
            latest: meta.version,
        })
        .with_field("v"));
    }
    Ok(version)
}

/// Checks that the caller may read world `id`, then returns the world and the version the
/// request names with `?v=N` (the latest without), checked as [`requested_version`] does.
pub(super) async fn readable_version(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    query: Option<&str>,
) -> Result<(WorldMeta, u64), AppError> {
    let (meta, _) = authorize(st, headers, id, Role::Read).await?;
    let version = requested_version(&meta, query)?;
    Ok((meta, version))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn if_match_forms() {
        let h = |v: &str| {
            let mut m = HeaderMap::new();
            m.insert(header::IF_MATCH, HeaderValue::from_str(v).expect("value"));
            m
        };
        assert_eq!(parse_if_match(&HeaderMap::new()).expect("none"), None);
        assert_eq!(parse_if_match(&h("*")).expect("any"), None);
        assert_eq!(parse_if_match(&h("7")).expect("plain"), Some(7));
        assert_eq!(parse_if_match(&h("\"7\"")).expect("quoted"), Some(7));
        assert_eq!(parse_if_match(&h("W/\"7\"")).expect("weak"), Some(7));
        assert_eq!(parse_if_match(&h("\"7-gzip\"")).expect("gzip tag"), Some(7));
        for bad in [
            "0",
            "-1",
            "x",
            "\"7",
            "7, 8",
            "99999999999999999999",
            "7-gzip",
            "\"7-gzip-gzip\"",
            "\"-gzip\"",
        ] {
            let e = parse_if_match(&h(bad)).expect_err(bad);
            assert_eq!(e.field.as_deref(), Some("If-Match"), "{bad}");
        }
    }

    #[test]
    fn query_params() {
        assert_eq!(query_param(Some("v=3&seams=1,0,0,0"), "v"), Some("3"));
        assert_eq!(query_param(Some("seams=1,0,0,0&v=4"), "v"), Some("4"));
        assert_eq!(query_param(Some("vv=3"), "v"), None);
        assert_eq!(query_param(Some("v"), "v"), Some(""));
        assert_eq!(query_param(None, "v"), None);
    }
}
