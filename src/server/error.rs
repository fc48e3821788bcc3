//! The one error type of the HTTP service and its JSON shape.
//!
//! Every error response has the body `{"error": {"code", "message", "field"}}` where `code` is a
//! stable machine-readable string (listed in [`code`]), `message` is for humans and may change,
//! and `field` names the offending request parameter or is `null`.

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use std::borrow::Cow;

/// The stable error codes.
pub mod code {
    /// `seed` is not a decimal `u64`.
    pub const BAD_SEED: &str = "bad_seed";
    /// `lod` is not an integer.
    pub const BAD_LOD: &str = "bad_lod";
    /// `lod` is an integer outside `0..=12`.
    pub const LOD_OUT_OF_RANGE: &str = "lod_out_of_range";
    /// `x` or `z` is not an integer.
    pub const BAD_COORDINATE: &str = "bad_coordinate";
    /// `x` or `z` is an integer outside the supported world.
    pub const COORDINATE_OUT_OF_RANGE: &str = "coordinate_out_of_range";
    /// The extension names no format (or is missing).
    pub const UNKNOWN_FORMAT: &str = "unknown_format";
    /// `seams` is not four comma-separated `0`/`1` flags.
    pub const BAD_SEAMS: &str = "bad_seams";
    /// The path is not valid (e.g. percent-encoding that is not UTF-8).
    pub const BAD_PATH: &str = "bad_path";
    /// No route or file matches the path.
    pub const NOT_FOUND: &str = "not_found";
    /// The route exists but not for this method.
    pub const METHOD_NOT_ALLOWED: &str = "method_not_allowed";
    /// A WebSocket route was requested without a WebSocket upgrade; `field` is `Upgrade`.
    pub const UPGRADE_REQUIRED: &str = "upgrade_required";
    /// The request is malformed in a way no more specific code covers; the message says how.
    pub const BAD_REQUEST: &str = "bad_request";
    /// The request body is larger than the limit.
    pub const PAYLOAD_TOO_LARGE: &str = "payload_too_large";
    /// Tile synthesis did not finish (queueing included) within the time limit; retry later.
    pub const SYNTHESIS_TIMEOUT: &str = "synthesis_timeout";
    /// The server holds its limit of connections; retry later.
    pub const TOO_MANY_CONNECTIONS: &str = "too_many_connections";
    /// The server is shutting down and did not finish the work; retry later.
    pub const SHUTTING_DOWN: &str = "shutting_down";
    /// A bug or an unexpected failure on the server.
    pub const INTERNAL: &str = "internal";
    /// No world has this id (or the id is malformed).
    pub const WORLD_NOT_FOUND: &str = "world_not_found";
    /// The world has no such version.
    pub const VERSION_NOT_FOUND: &str = "version_not_found";
    /// `v` or `If-Match` is not a version number.
    pub const BAD_VERSION: &str = "bad_version";
    /// `If-Match` names a version that is not the latest.
    pub const VERSION_CONFLICT: &str = "version_conflict";
    /// The request needs a bearer token and has none, or one the server does not know.
    pub const UNAUTHENTICATED: &str = "unauthenticated";
    /// The token does not grant this operation.
    pub const FORBIDDEN: &str = "forbidden";
    /// A query parameter is missing or not a valid value; `field` names it.
    pub const BAD_PARAMETER: &str = "bad_parameter";
    /// The body is not the JSON the route expects; `field` is a JSON pointer into it.
    pub const BAD_BODY: &str = "bad_body";
    /// The body's `Content-Type` is not the one the route accepts.
    pub const UNSUPPORTED_MEDIA_TYPE: &str = "unsupported_media_type";
    /// A JSON Patch operation cannot be applied; `field` is `/<operation index>`.
    pub const PATCH_FAILED: &str = "patch_failed";
    /// The scene (given, or made by an edit) is invalid; `field` is a JSON pointer into it.
    pub const INVALID_SCENE: &str = "invalid_scene";
    /// The scene would be larger than the limit.
    pub const SCENE_TOO_LARGE: &str = "scene_too_large";
    /// An export request names an impossible export; `field` is a JSON pointer into the body.
    pub const INVALID_EXPORT: &str = "invalid_export";
    /// The export job queue is full; retry later.
    pub const TOO_MANY_JOBS: &str = "too_many_jobs";
    /// No export job has this id (or it was forgotten).
    pub const JOB_NOT_FOUND: &str = "job_not_found";
    /// The export job has not finished yet: its archive is not ready.
    pub const JOB_NOT_DONE: &str = "job_not_done";
    /// The export job failed: there is no archive.
    pub const JOB_FAILED: &str = "job_failed";
    /// The export job's archive expired and was deleted.
    pub const JOB_EXPIRED: &str = "job_expired";
    /// The export's archive may be larger than a disk budget allows; `field` is `/region` and
    /// the message names the budget and its bytes.
    pub const EXPORT_TOO_LARGE: &str = "export_too_large";
    /// The export's archive does not fit the disk budget beside the archives already held;
    /// `field` names the budget; retry after `Retry-After` seconds.
    pub const EXPORT_QUOTA_EXCEEDED: &str = "export_quota_exceeded";
    /// The client (its address or its token) made more expensive requests than the rate limit
    /// allows; `field` names the limit; retry after `Retry-After` seconds.
    pub const RATE_LIMITED: &str = "rate_limited";
    /// A Ptex bake of more than `ptex_routes::MAX_REQUEST_TEXELS` texels (`res² ×` faces);
    /// `field` is `res`.
    pub const PTEX_TOO_LARGE: &str = "ptex_too_large";
    /// An uploaded image is not a PNG within the limits (`ptex::image`); `field` is `body`.
    pub const INVALID_IMAGE: &str = "invalid_image";
    /// The world holds `store::MAX_WORLD_IMAGES` images already; `field` is `body`.
    pub const TOO_MANY_IMAGES: &str = "too_many_images";
    /// No image of that hash in the world; `field` is `hash`.
    pub const IMAGE_NOT_FOUND: &str = "image_not_found";
}

/// An error answered to the client.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{code}: {message}")]
pub struct AppError {
    /// HTTP status (4xx or 5xx).
    pub status: StatusCode,
    /// Stable code from [`code`].
    pub code: &'static str,
    /// Human-readable explanation.
    pub message: String,
    /// The offending request parameter or JSON pointer, if one is to blame.
    pub field: Option<Cow<'static, str>>,
    /// Seconds for the `Retry-After` header, if the client should retry later.
    pub retry_after_s: Option<u64>,
}

#[derive(Serialize)]
struct Body<'a> {
    error: Inner<'a>,
}

#[derive(Serialize)]
struct Inner<'a> {
    code: &'a str,
    message: &'a str,
    field: Option<&'a str>,
}

impl AppError {
    /// A 400 Bad Request blaming `field`.
    pub fn bad_request(
        code: &'static str,
        field: impl Into<Cow<'static, str>>,
        message: impl Into<String>,
    ) -> Self {
        Self {
            status: StatusCode::BAD_REQUEST,
            code,
            message: message.into(),
            field: Some(field.into()),
            retry_after_s: None,
        }
    }

    /// The same error blaming `field`.
    pub fn with_field(mut self, field: impl Into<Cow<'static, str>>) -> Self {
        self.field = Some(field.into());
        self
    }

    /// The same error with `Retry-After: seconds`.
    pub fn with_retry_after(mut self, seconds: u64) -> Self {
        self.retry_after_s = Some(seconds);
        self
    }

    /// 404 `not_found`.
    pub fn not_found(path: &str) -> Self {
        Self {
            status: StatusCode::NOT_FOUND,
            code: code::NOT_FOUND,
            message: format!("no route or file for {}", truncate(path, 200)),
            field: None,
            retry_after_s: None,
        }
    }

    /// 500 `internal`.
    pub fn internal(message: impl Into<String>) -> Self {
        Self {
            status: StatusCode::INTERNAL_SERVER_ERROR,
            code: code::INTERNAL,
            message: message.into(),
            field: None,
            retry_after_s: None,
        }
    }

    /// Any status and code without a field.
    pub fn new(status: StatusCode, code: &'static str, message: impl Into<String>) -> Self {
        Self {
            status,
            code,
            message: message.into(),
            field: None,
            retry_after_s: None,
        }
    }
}

/// At most `max` characters of `s` (for echoing client input in messages).
pub fn truncate(s: &str, max: usize) -> String {
    match s.char_indices().nth(max) {
        Some((i, _)) => format!("{}…", &s[..i]),
        None => s.to_string(),
    }
}

impl IntoResponse for AppError {
    fn into_response(self) -> Response {
        let body = Body {
            error: Inner {
                code: self.code,
                message: &self.message,
                field: self.field.as_deref(),
            },
        };
        let bytes = serde_json::to_vec(&body).unwrap_or_default();
        let mut res = (self.status, bytes).into_response();
        let h = res.headers_mut();
        h.insert(
            header::CONTENT_TYPE,
            HeaderValue::from_static("application/json"),
        );
        h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
        if self.status == StatusCode::UNAUTHORIZED {
            h.insert(
                header::WWW_AUTHENTICATE,
                HeaderValue::from_static("Bearer realm=\"strata\""),
            );
        }
        if let Some(s) = self.retry_after_s {
            h.insert(header::RETRY_AFTER, HeaderValue::from(s));
        } else if self.status == StatusCode::SERVICE_UNAVAILABLE {
            h.insert(header::RETRY_AFTER, HeaderValue::from_static("1"));
        }
        res
    }
}
