//! `strata serve --store postgres://…` (README, "Scale out"): two real servers sharing one
//! PostgreSQL database (a throwaway cluster, `common::postgres`) see the same worlds, an edit
//! acknowledged by one is read back by the other and survives both, two editors racing with the
//! same `If-Match` on different servers get one 200 and one 409, and a store that is not
//! PostgreSQL or cannot be reached stops the server at start with a clear message.

mod common;

use common::raw::request;
use serde_json::{json, Value};
use std::process::Command;

const ADMIN: &str = "st_scale_out_admin";

fn database() -> String {
    tokio::runtime::Runtime::new()
        .expect("runtime")
        .block_on(common::postgres::database())
}

fn call(
    addr: &str,
    method: &str,
    path: &str,
    headers: &[(&str, &str)],
    body: &Value,
) -> (u16, Value) {
    let bearer = format!("Bearer {ADMIN}");
    let mut h = vec![("authorization", bearer.as_str())];
    h.extend_from_slice(headers);
    let bytes = if body.is_null() {
        Vec::new()
    } else {
        serde_json::to_vec(body).expect("json")
    };
    let (status, body) =
        request(addr, method, path, &h, &bytes).unwrap_or_else(|e| panic!("{method} {path}: {e}"));
    (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
}

fn edit(addr: &str, id: &str, if_match: &str, region: &str) -> (u16, Value) {
    call(
        addr,
        "POST",
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("content-type", "application/json-patch+json"),
            ("if-match", if_match),
        ],
        &json!([{"op": "add", "path": "/regions/-", "value":
            {"id": region, "bbox": {"min": [0, 0], "max": [10, 10]}}}]),
    )
}

fn serve(data: &std::path::Path, store: Option<&str>, env_url: Option<&str>) -> common::Server {
    let mut args = vec![
        "--data".to_string(),
        data.to_string_lossy().into_owned(),
        "--admin-token".into(),
        ADMIN.into(),
    ];
    if let Some(url) = store {
        args.extend(["--store".to_string(), url.to_string()]);
    }
    let envs: Vec<(&str, String)> = env_url
        .map(|u| vec![("STRATA_DATABASE_URL", u.to_string())])
        .unwrap_or_default();
    common::start(args, &envs)
}

#[test]
fn two_servers_share_the_worlds_of_one_database() {
    let url = database();
    let (dir_a, dir_b) = (
        tempfile::tempdir().expect("tmp"),
        tempfile::tempdir().expect("tmp"),
    );
    let a = serve(dir_a.path(), Some(&url), None);
    let b = serve(dir_b.path(), None, Some(&url));
    let (status, world) = call(
        &a.addr,
        "POST",
        "/v1/worlds",
        &[("content-type", "application/json")],
        &json!({"seed": 42}),
    );
    assert_eq!(status, 201, "{world}");
    let id = world["id"].as_str().expect("id").to_string();
    let (status, got) = call(
        &b.addr,
        "GET",
        &format!("/v1/worlds/{id}"),
        &[],
        &Value::Null,
    );
    assert_eq!((status, got["version"].clone()), (200, json!(1)), "{got}");

    let (status, applied) = edit(&b.addr, &id, "1", "hill");
    assert_eq!(
        (status, applied["version"].clone()),
        (200, json!(2)),
        "{applied}"
    );
    let (_, on_a) = call(
        &a.addr,
        "GET",
        &format!("/v1/worlds/{id}"),
        &[],
        &Value::Null,
    );
    assert_eq!(on_a["version"], 2);
    assert_eq!(on_a["scene"]["regions"][0]["id"], "hill");

    // Both editors expect version 2; the row lock lets exactly one through.
    let (addr_a, addr_b, id_a, id_b) = (a.addr.clone(), b.addr.clone(), id.clone(), id.clone());
    let ta = std::thread::spawn(move || edit(&addr_a, &id_a, "2", "from-a"));
    let tb = std::thread::spawn(move || edit(&addr_b, &id_b, "2", "from-b"));
    let mut statuses = [ta.join().expect("a").0, tb.join().expect("b").0];
    statuses.sort_unstable();
    assert_eq!(statuses, [200, 409]);

    // Nothing of it was in either data directory: a third server, on a fresh one, has it all.
    drop((a, b));
    let dir_c = tempfile::tempdir().expect("tmp");
    let c = serve(dir_c.path(), Some(&url), None);
    let (_, on_c) = call(
        &c.addr,
        "GET",
        &format!("/v1/worlds/{id}"),
        &[],
        &Value::Null,
    );
    assert_eq!(on_c["version"], 3);
    let regions = on_c["scene"]["regions"].as_array().expect("regions").len();
    assert_eq!(regions, 2);
    let (status, log) = call(
        &c.addr,
        "GET",
        &format!("/v1/worlds/{id}/edits?after=1"),
        &[],
        &Value::Null,
    );
    assert_eq!(status, 200, "{log}");
}

#[test]
fn a_store_that_is_not_postgres_or_not_reachable_stops_the_server() {
    let dir = tempfile::tempdir().expect("tmp");
    let run = |args: &[&str], env: Option<&str>| {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_strata"));
        cmd.args([
            "serve",
            "--addr",
            "127.0.0.1:0",
            "--backend",
            "cpu",
            "--data",
        ])
        .arg(dir.path())
        .args(args)
        .env("NO_COLOR", "1")
        .env_remove("STRATA_DATABASE_URL");
        if let Some(v) = env {
            cmd.env("STRATA_DATABASE_URL", v);
        }
        let out = cmd.output().expect("run strata serve");
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let (code, err) = run(&["--store", "mysql://db/strata"], None);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("postgres:// or postgresql:// URL"), "{err}");
    let (code, err) = run(&[], Some("sqlite:strata.db"));
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("STRATA_DATABASE_URL"), "{err}");
    // A closed port on loopback: refused at once.
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("port")
        .port();
    let (code, err) = run(
        &[
            "--store",
            &format!("postgres://strata@127.0.0.1:{port}/strata"),
        ],
        None,
    );
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("cannot open the PostgreSQL scene store"),
        "{err}"
    );
    assert!(
        !dir.path().join("strata.db").exists(),
        "no SQLite file is made beside a PostgreSQL store"
    );
}
