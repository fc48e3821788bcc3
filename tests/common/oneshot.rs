//! Requests to `strata::server::app` through `tower::ServiceExt::oneshot` (no socket), shared by
//! the tests that drive the router in-process.

use axum::body::Body;
use axum::http::{HeaderMap, Method, Request, StatusCode};
use axum::Router;
use http_body_util::BodyExt;
use serde_json::Value;
use tower::ServiceExt;

/// A response, body collected.
pub struct Reply {
    /// Status code.
    pub status: StatusCode,
    /// Headers.
    pub headers: HeaderMap,
    /// Body bytes.
    pub body: Vec<u8>,
}

impl Reply {
    /// The header `name` as text, if present and ASCII.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers.get(name).and_then(|v| v.to_str().ok())
    }

    /// The body as JSON; panics with the body text if it is not JSON.
    pub fn json(&self) -> Value {
        serde_json::from_slice(&self.body)
            .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&self.body)))
    }

    /// Asserts status 200, showing the body if not.
    pub fn ok(&self) {
        self.status_is(StatusCode::OK);
    }

    /// Asserts the status, showing the body if it differs; returns the reply for chaining.
    pub fn status_is(&self, status: StatusCode) -> &Self {
        assert_eq!(
            self.status,
            status,
            "{}",
            String::from_utf8_lossy(&self.body)
        );
        self
    }

    /// Asserts a JSON error with this status and code, a non-empty message and, if given, this
    /// field.
    pub fn error(&self, status: StatusCode, code: &str, field: Option<&str>) {
        self.status_is(status);
        let e = &self.json()["error"];
        assert_eq!(e["code"], code, "{e}");
        if let Some(f) = field {
            assert_eq!(e["field"], f, "{e}");
        }
        assert!(e["message"].as_str().is_some_and(|m| !m.is_empty()), "{e}");
    }
}

/// Sends one request with these headers and body to `app`.
pub async fn send<H: AsRef<str>>(
    app: &Router,
    method: Method,
    uri: &str,
    headers: &[(&str, H)],
    body: Option<&[u8]>,
) -> Reply {
    let mut req = Request::builder().method(method).uri(uri);
    for (k, v) in headers {
        req = req.header(*k, v.as_ref());
    }
    let body = body
        .map(|b| Body::from(b.to_vec()))
        .unwrap_or_else(Body::empty);
    let res = app
        .clone()
        .oneshot(req.body(body).expect("request"))
        .await
        .expect("infallible");
    let status = res.status();
    let headers = res.headers().clone();
    let body = res
        .into_body()
        .collect()
        .await
        .expect("body")
        .to_bytes()
        .to_vec();
    Reply {
        status,
        headers,
        body,
    }
}

/// `POST uri` with a JSON `body`, as the bearer of `token` if any.
pub async fn post_json(app: &Router, uri: &str, token: Option<&str>, body: &Value) -> Reply {
    let mut headers = vec![("content-type", "application/json".to_string())];
    if let Some(t) = token {
        headers.push(("authorization", format!("Bearer {t}")));
    }
    send(
        app,
        Method::POST,
        uri,
        &headers,
        Some(body.to_string().as_bytes()),
    )
    .await
}

/// `GET uri` as the bearer of `token`.
pub async fn get_as(app: &Router, uri: &str, token: &str) -> Reply {
    let headers = [("authorization", format!("Bearer {token}"))];
    send(app, Method::GET, uri, &headers, None).await
}

/// A new private world of `seed`: its id and admin token.
pub async fn private_world(app: &Router, seed: u64) -> (String, String) {
    let v = post_json(
        app,
        "/v1/worlds",
        None,
        &serde_json::json!({ "seed": seed }),
    )
    .await
    .status_is(StatusCode::CREATED)
    .json();
    (
        v["id"].as_str().expect("id").into(),
        v["tokens"]["admin"].as_str().expect("token").into(),
    )
}

/// Polls the export job at `status_url` as the bearer of `token` until it is done (5 minutes
/// at most); a failed job fails the test.
pub async fn wait_job_done(app: &Router, status_url: &str, token: &str) {
    let deadline = tokio::time::Instant::now() + std::time::Duration::from_secs(300);
    loop {
        let v = get_as(app, status_url, token)
            .await
            .status_is(StatusCode::OK)
            .json();
        if v["status"] == "done" {
            return;
        }
        assert_ne!(v["status"], "failed", "{v}");
        assert!(tokio::time::Instant::now() < deadline, "job stuck: {v}");
        tokio::time::sleep(std::time::Duration::from_millis(20)).await;
    }
}

/// A default CPU app (`strata::server::app`) served on a loopback socket in this process, for
/// tests that need a real connection (WebSockets); returns `host:port`.
pub async fn serve_cpu() -> String {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    tokio::spawn(async move {
        let state = strata::server::AppState::new(strata::compute::Compute::cpu());
        axum::serve(listener, strata::server::app(state))
            .await
            .expect("serve");
    });
    addr.to_string()
}
