//! Cross-origin requests (issue 18, "What to build" 8 and finding 9): an allow-list of origins
//! (`serve --cors-origin`) through `tower_http::cors`; preflights answered; a private world's
//! answers never carry `Access-Control-Allow-Origin: *` and only allowed origins get one; the
//! bare seeds' public products stay readable from every origin; the world stream's WebSocket
//! upgrade checks `Origin` against the same list.

use axum::http::{Method, StatusCode};
use axum::Router;
use strata::compute::Compute;
use strata::server::cors::CorsOrigins;
use strata::server::{app, AppState};

mod common;
use common::oneshot::{send, Reply};

const APP: &str = "https://app.example";
const EVIL: &str = "https://evil.example";

fn state(origins: &[&str]) -> AppState {
    AppState::new(Compute::cpu()).with_cors_origins(CorsOrigins::new(origins).expect("origins"))
}

/// A private world: its id and admin token.
async fn private_world(app: &Router) -> (String, String) {
    let r = send(
        app,
        Method::POST,
        "/v1/worlds",
        &[("content-type", "application/json")],
        Some(br#"{"seed":11}"#),
    )
    .await;
    let v = r.status_is(StatusCode::CREATED).json();
    (
        v["id"].as_str().expect("id").to_string(),
        v["tokens"]["admin"].as_str().expect("token").to_string(),
    )
}

fn allow_origin(r: &Reply) -> Option<&str> {
    r.header("access-control-allow-origin")
}

async fn preflight(app: &Router, uri: &str, origin: &str) -> Reply {
    send(
        app,
        Method::OPTIONS,
        uri,
        &[
            ("origin", origin),
            ("access-control-request-method", "GET"),
            ("access-control-request-headers", "authorization"),
        ],
        None,
    )
    .await
}

#[tokio::test]
async fn the_allow_list_governs_every_private_answer() {
    let app = app(state(&[APP]));
    let (id, token) = private_world(&app).await;
    let auth = format!("Bearer {token}");
    let tile = format!("/v1/worlds/{id}/tiles/3/0/0.json");

    // Preflight: answered (not 405), with the allowed origin, method and header.
    let r = preflight(&app, &tile, APP).await;
    assert!(r.status.is_success(), "{}", r.status);
    assert_eq!(allow_origin(&r), Some(APP));
    let methods = r.header("access-control-allow-methods").unwrap_or_default();
    assert!(
        methods.contains("GET") && methods.contains("PATCH"),
        "{methods}"
    );
    let headers = r.header("access-control-allow-headers").unwrap_or_default();
    assert!(headers.contains("authorization"), "{headers}");
    let r = preflight(&app, &tile, EVIL).await;
    assert_eq!(allow_origin(&r), None, "no grant for an origin not listed");

    // The private world's tile, with its token, from each origin.
    let r = send(
        &app,
        Method::GET,
        &tile,
        &[("origin", APP), ("authorization", auth.as_str())],
        None,
    )
    .await;
    r.ok();
    assert_eq!(allow_origin(&r), Some(APP));
    let vary: Vec<String> = r
        .headers
        .get_all("vary")
        .iter()
        .filter_map(|v| v.to_str().ok())
        .map(str::to_ascii_lowercase)
        .collect();
    assert!(vary.iter().any(|v| v.contains("origin")), "{vary:?}");
    let exposed = r
        .header("access-control-expose-headers")
        .unwrap_or_default()
        .to_ascii_lowercase();
    assert!(exposed.contains("etag"), "{exposed}");
    let r = send(
        &app,
        Method::GET,
        &tile,
        &[("origin", EVIL), ("authorization", auth.as_str())],
        None,
    )
    .await;
    r.ok();
    assert_eq!(allow_origin(&r), None);
    // Errors and the world's other routes follow the same list, and none says `*`.
    for (uri, origin) in [
        (format!("/v1/worlds/{id}"), APP),
        (format!("/v1/worlds/{id}/tiles/3/0/0.json"), EVIL),
        (format!("/v1/worlds/{id}/edits"), EVIL),
        (format!("/v1/worlds/{id}/tiles/99/0/0.json"), APP),
    ] {
        let r = send(
            &app,
            Method::GET,
            &uri,
            &[("origin", origin), ("authorization", auth.as_str())],
            None,
        )
        .await;
        assert_ne!(allow_origin(&r), Some("*"), "{uri}");
        let expected = (origin == APP).then_some(APP);
        assert_eq!(allow_origin(&r), expected, "{uri}");
    }

    // The bare seeds' products are public: any origin may read them, by name, not `*`.
    let r = send(
        &app,
        Method::GET,
        "/v1/seeds/11/tiles/3/0/0.json",
        &[("origin", EVIL)],
        None,
    )
    .await;
    r.ok();
    assert_eq!(allow_origin(&r), Some(EVIL));
    let r = preflight(&app, "/v1/seeds/11/tiles/3/0/0.json", EVIL).await;
    assert_eq!(allow_origin(&r), Some(EVIL));
}

#[tokio::test]
async fn without_a_list_worlds_are_same_origin_only_and_seeds_stay_public() {
    let app = app(state(&[]));
    let (id, token) = private_world(&app).await;
    let auth = format!("Bearer {token}");
    let r = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id}/tiles/3/0/0.json"),
        &[("origin", APP), ("authorization", auth.as_str())],
        None,
    )
    .await;
    r.ok();
    assert_eq!(allow_origin(&r), None);
    // The viewer's own requests carry no Origin (GET) or the server's own; neither needs a grant.
    let r = send(
        &app,
        Method::GET,
        &format!("/v1/worlds/{id}/tiles/3/0/0.json"),
        &[("authorization", auth.as_str())],
        None,
    )
    .await;
    r.ok();
    assert_eq!(allow_origin(&r), None);
    for uri in ["/v1/seeds/11/tiles/3/0/0.json", "/v1/info"] {
        let r = send(&app, Method::GET, uri, &[("origin", APP)], None).await;
        r.ok();
        assert_eq!(allow_origin(&r), Some(APP), "{uri}");
    }
}

#[test]
fn the_list_takes_origins_only() {
    for bad in ["*", "app.example", "https://app.example/", "file://x"] {
        assert!(CorsOrigins::new([bad]).is_err(), "{bad}");
    }
    let o = strata_serve_refuses(&["--cors-origin", "*"]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

fn strata_serve_refuses(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_strata"))
        .arg("serve")
        .args(args)
        .output()
        .expect("run strata")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_world_stream_checks_the_origin() {
    use tokio_tungstenite::tungstenite::client::IntoClientRequest;
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    let app = app(state(&[APP]));
    let (id, token) = private_world(&app).await;
    tokio::spawn(async move { axum::serve(listener, app).await.expect("serve") });
    let connect = |path: String, origin: Option<String>| async move {
        let mut req = format!("ws://{addr}{path}")
            .into_client_request()
            .expect("request");
        if let Some(o) = origin {
            req.headers_mut()
                .insert("origin", o.parse().expect("origin"));
        }
        tokio_tungstenite::connect_async(req).await
    };
    let world = format!("/v1/worlds/{id}/stream?token={token}");
    let own = format!("http://{addr}");
    for origin in [None, Some(APP.to_string()), Some(own)] {
        let r = connect(world.clone(), origin.clone()).await;
        assert!(r.is_ok(), "{origin:?}: {r:?}");
    }
    match connect(world.clone(), Some(EVIL.to_string())).await {
        Err(tokio_tungstenite::tungstenite::Error::Http(res)) => {
            assert_eq!(res.status(), StatusCode::FORBIDDEN);
            let body: serde_json::Value =
                serde_json::from_slice(res.body().as_deref().unwrap_or_default()).expect("JSON");
            assert_eq!(body["error"]["field"], "Origin", "{body}");
        }
        other => panic!("an origin not listed opened the world stream: {other:?}"),
    }
    let seed = connect("/v1/seeds/11/stream".into(), Some(EVIL.to_string())).await;
    assert!(seed.is_ok(), "a bare seed's stream is public: {seed:?}");
}
