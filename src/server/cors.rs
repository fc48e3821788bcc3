//! Cross-origin requests (`tower_http::cors`) and the `Origin` check of the WebSocket routes.
//!
//! The policy, one allow-list for HTTP and WebSockets ([`CorsOrigins`], `serve --cors-origin`):
//! - The bare seeds' routes (`/v1/seeds/…`), `/v1/info` and `/healthz` need no token and hold
//!   nothing private: every origin may read them (the request's origin is mirrored, never `*`).
//! - Everything else (worlds, their products and streams, exports, jobs, metrics) may be read
//!   from the server's own origin, where the bundled viewer runs and browsers need no CORS
//!   headers, and from the origins of the allow-list. Without a list that is the own origin only.
//! - Preflights (`OPTIONS` with `Access-Control-Request-Method`) are answered by the layer; an
//!   origin that is not allowed gets no `Access-Control-Allow-Origin` and the browser refuses.
//! - A world's WebSocket upgrade with an `Origin` header is refused (403 `forbidden`, field
//!   `Origin`) unless the origin is the server's own (the `Host` it was asked for) or in the
//!   list; a bare seed's stream is open to every origin, like its products. Without an
//!   `Origin` header (not a browser) every upgrade is allowed.

use super::error::{code, AppError};
use super::http::VERSION_HEADER;
use super::routes::{HEIGHT_OFFSET_HEADER, HEIGHT_SCALE_HEADER};
use axum::http::{header, HeaderMap, HeaderName, HeaderValue, Method, StatusCode};
use std::sync::Arc;
use std::time::Duration;
use tower_http::cors::{AllowOrigin, CorsLayer};

/// How long browsers may cache a preflight's answer.
pub const PREFLIGHT_MAX_AGE: Duration = Duration::from_secs(600);

/// The origins besides the server's own that may call every route from a browser.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CorsOrigins(Arc<Vec<HeaderValue>>);

impl CorsOrigins {
    /// The list of `origins` (each checked with [`parse_origin`]).
    ///
    /// # Errors
    /// The first entry that is not an origin, and why.
    pub fn new<I, S>(origins: I) -> Result<Self, String>
    where
        I: IntoIterator<Item = S>,
        S: AsRef<str>,
    {
        let list = origins
            .into_iter()
            .map(|o| parse_origin(o.as_ref()))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self(Arc::new(list)))
    }

    /// The allowed origins.
    pub fn origins(&self) -> &[HeaderValue] {
        &self.0
    }

    /// Whether the list allows `origin`.
    pub fn allows(&self, origin: &HeaderValue) -> bool {
        self.0.iter().any(|o| o == origin)
    }

    /// The CORS layer of this policy.
    pub fn layer(&self) -> CorsLayer {
        let list = self.clone();
        let expose = [
            header::ETAG,
            header::LOCATION,
            header::RETRY_AFTER,
            HeaderName::from_static(HEIGHT_OFFSET_HEADER),
            HeaderName::from_static(HEIGHT_SCALE_HEADER),
            HeaderName::from_static(VERSION_HEADER),
            HeaderName::from_static(super::region_io::LO_HEADER),
            HeaderName::from_static(super::region_io::HI_HEADER),
            HeaderName::from_static(super::region_io::GRADIENT_M_HEADER),
        ];
        CorsLayer::new()
            .allow_origin(AllowOrigin::predicate(move |origin, parts| {
                list.allows(origin) || is_public(parts.uri.path())
            }))
            .allow_methods([
                Method::GET,
                Method::HEAD,
                Method::POST,
                Method::PUT,
                Method::PATCH,
            ])
            .allow_headers([
                header::AUTHORIZATION,
                header::CONTENT_TYPE,
                header::IF_MATCH,
                header::IF_NONE_MATCH,
            ])
            .expose_headers(expose)
            .max_age(PREFLIGHT_MAX_AGE)
    }

    /// Checks the `Origin` of a WebSocket upgrade to a route that is not public (a world's
    /// stream; a bare seed's stream, like its products, is open to every origin).
    ///
    /// # Errors
    /// 403 `forbidden` naming `Origin` when the origin may not open the stream.
    pub fn check_upgrade(&self, headers: &HeaderMap) -> Result<(), AppError> {
        let Some(origin) = headers.get(header::ORIGIN) else {
            return Ok(());
        };
        if self.allows(origin) || same_origin(origin, headers) {
            return Ok(());
        }
        Err(AppError::new(
            StatusCode::FORBIDDEN,
            code::FORBIDDEN,
            "this origin may not open the stream: it is not the server's own and not in the \
             server's --cors-origin list",
        )
        .with_field("Origin"))
    }
}

/// Whether every origin may read `path`.
fn is_public(path: &str) -> bool {
    path.starts_with("/v1/seeds/") || path == "/v1/info" || path == "/healthz"
}

/// Whether `origin` names the host the request was sent to.
fn same_origin(origin: &HeaderValue, headers: &HeaderMap) -> bool {
    let (Ok(origin), Some(host)) = (
        origin.to_str(),
        headers.get(header::HOST).and_then(|h| h.to_str().ok()),
    ) else {
        return false;
    };
    origin
        .split_once("://")
        .is_some_and(|(_, authority)| authority.eq_ignore_ascii_case(host))
}

/// An origin as browsers send it: `http` or `https`, `://`, a host and an optional port, no
/// path and no trailing slash (`https://maps.example.org`, `http://localhost:5173`).
///
/// # Errors
/// Why `s` is not such an origin (`*` included: the list names origins).
pub fn parse_origin(s: &str) -> Result<HeaderValue, String> {
    let bad = |why: &str| format!("{s:?} is not an origin such as https://maps.example.org: {why}");
    let Some((scheme, authority)) = s.split_once("://") else {
        return Err(bad("it has no scheme://"));
    };
    if scheme != "http" && scheme != "https" {
        return Err(bad("the scheme must be http or https"));
    }
    let valid = |c: char| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | ':' | '[' | ']');
    if authority.is_empty() || !authority.chars().all(valid) {
        return Err(bad(
            "the host may hold letters, digits, '.', '-', ':' and [ ] only",
        ));
    }
    HeaderValue::from_str(s).map_err(|e| bad(&e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn origins_parse() {
        for good in [
            "https://maps.example.org",
            "http://localhost:5173",
            "http://[::1]:8080",
        ] {
            assert!(parse_origin(good).is_ok(), "{good}");
        }
        for bad in [
            "*",
            "maps.example.org",
            "ftp://x",
            "https://x/",
            "https://",
            "https://a b",
        ] {
            assert!(parse_origin(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn upgrades_check_the_origin() {
        let list = CorsOrigins::new(["https://app.example"]).expect("list");
        let headers = |origin: Option<&str>| {
            let mut h = HeaderMap::new();
            h.insert(
                header::HOST,
                HeaderValue::from_static("strata.example:8080"),
            );
            if let Some(o) = origin {
                h.insert(header::ORIGIN, HeaderValue::from_str(o).expect("origin"));
            }
            h
        };
        assert!(list.check_upgrade(&headers(None)).is_ok());
        assert!(list
            .check_upgrade(&headers(Some("https://app.example")))
            .is_ok());
        assert!(list
            .check_upgrade(&headers(Some("http://strata.example:8080")))
            .is_ok());
        let refused = list
            .check_upgrade(&headers(Some("https://evil.example")))
            .expect_err("refused");
        assert_eq!(
            (refused.code, refused.field.as_deref()),
            ("forbidden", Some("Origin"))
        );
    }
}
