//! An export job survives the death of the replica running it: three `strata serve` replicas on
//! one PostgreSQL database (a throwaway cluster, `common::postgres`) and one shared archive
//! directory; an export started on one replica, which is SIGKILLed mid-job, is taken over by
//! another once its lease lapses, and its archive, served by every live replica, is byte for
//! byte the archive of the same export run uninterrupted. The same holds for one server on
//! SQLite, SIGKILLed and started again. Fails, never skips, without PostgreSQL.

mod common;

use common::replica::{create_world, request};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

const ADMIN: &str = "st_failover_admin";
/// `--export-lease`, seconds: short, so the takeover comes soon after the kill.
const LEASE_S: &str = "2";

async fn call(
    addr: &str,
    method: &'static str,
    path: String,
    body: Option<&Value>,
) -> (u16, Vec<u8>) {
    let headers = if body.is_some() {
        vec![("content-type", "application/json".to_string())]
    } else {
        Vec::new()
    };
    let body = body
        .map(|b| serde_json::to_vec(b).expect("json"))
        .unwrap_or_default();
    request(addr, ADMIN, method, path, headers, body).await
}

async fn status(addr: &str, job: &str) -> Value {
    let (code, body) = call(addr, "GET", format!("/v1/jobs/{job}"), None).await;
    assert_eq!(code, 200, "{addr}: {}", String::from_utf8_lossy(&body));
    serde_json::from_slice(&body).expect("json")
}

async fn start_export(addr: &str, world: &str, spec: &Value) -> String {
    let (code, body) = call(
        addr,
        "POST",
        format!("/v1/worlds/{world}/exports"),
        Some(spec),
    )
    .await;
    assert_eq!(code, 202, "{}", String::from_utf8_lossy(&body));
    let v: Value = serde_json::from_slice(&body).expect("json");
    v["job"].as_str().expect("job").to_string()
}

/// Polls `addr` until job `job` is done (never failed), within 300 s.
async fn wait_done(addr: &str, job: &str) -> Value {
    let deadline = Instant::now() + Duration::from_secs(300);
    loop {
        let s = status(addr, job).await;
        assert_ne!(s["status"], "failed", "{s}");
        if s["status"] == "done" {
            return s;
        }
        assert!(Instant::now() < deadline, "not done within 300 s: {s}");
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
}

async fn archive(addr: &str, job: &str) -> Vec<u8> {
    let (code, body) = call(addr, "GET", format!("/v1/jobs/{job}/archive"), None).await;
    assert_eq!(code, 200, "{addr}: {}", String::from_utf8_lossy(&body));
    body
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_export_job_survives_the_death_of_its_replica() {
    let url = common::postgres::database().await;
    let dirs: Vec<tempfile::TempDir> = (0..4).map(|_| tempfile::tempdir().expect("tmp")).collect();
    let shared = dirs[3].path().join("exports");
    let mut replicas: Vec<common::Server> = dirs[..3]
        .iter()
        .map(|d| {
            common::start(
                [
                    "--data",
                    d.path().to_str().expect("utf-8"),
                    "--admin-token",
                    ADMIN,
                    "--store",
                    &url,
                    "--shared-dir",
                    shared.to_str().expect("utf-8"),
                    "--export-lease",
                    LEASE_S,
                ],
                &[],
            )
        })
        .collect();
    let addrs: Vec<String> = replicas.iter().map(|r| r.addr.clone()).collect();

    // A world at version 2 with an authored region, so the replica that takes the job over must
    // solve the same edits as the one that admitted it.
    let (world, _) = create_world(&addrs[0], ADMIN, 21).await;
    let patch = json!([{"op": "add", "path": "/regions/-", "value":
        {"id": "mesa", "bbox": {"min": [40.0, 40.0], "max": [300.0, 260.0]}}}]);
    let (code, body) = request(
        &addrs[1],
        ADMIN,
        "POST",
        format!("/v1/worlds/{world}/edits"),
        vec![("content-type", "application/json-patch+json".into())],
        serde_json::to_vec(&patch).expect("json"),
    )
    .await;
    assert_eq!(code, 200, "{}", String::from_utf8_lossy(&body));
    let spec = json!({"lod": 1, "region": [0, 0, 8, 6], "products": ["tiles", "scatter"],
                      "formats": ["bin", "png"], "v": 2});

    // The uninterrupted run, on replica 2.
    let whole = start_export(&addrs[2], &world, &spec).await;
    wait_done(&addrs[2], &whole).await;
    let expected = archive(&addrs[2], &whole).await;
    assert!(expected.len() > 10_000, "{} bytes", expected.len());

    // The same export on replica 0, SIGKILLed once some tiles are written and before the last.
    let job = start_export(&addrs[0], &world, &spec).await;
    let deadline = Instant::now() + Duration::from_secs(300);
    let at_kill = loop {
        let s = status(&addrs[0], &job).await;
        if s["done"].as_u64().expect("done") > 0 {
            break s;
        }
        assert!(Instant::now() < deadline, "no progress: {s}");
        tokio::time::sleep(Duration::from_millis(10)).await;
    };
    replicas[0].child.kill().expect("SIGKILL replica 0");
    let _ = replicas[0].child.wait();
    assert_eq!(at_kill["status"], "running", "killed mid-job: {at_kill}");
    assert!(
        at_kill["done"].as_u64() < at_kill["total"].as_u64(),
        "killed before the last tile: {at_kill}"
    );

    // Both live replicas answer for the job while another takes it over and finishes it.
    let s = status(&addrs[2], &job).await;
    assert!(
        ["queued", "running"].contains(&s["status"].as_str().unwrap_or("")),
        "{s}"
    );
    let done = wait_done(&addrs[1], &job).await;
    assert_eq!(done["download_url"], format!("/v1/jobs/{job}/archive"));
    assert_eq!(done["done"], done["total"]);
    for addr in &addrs[1..] {
        let bytes = archive(addr, &job).await;
        assert!(
            bytes == expected,
            "{addr}: the resumed archive differs from the uninterrupted one"
        );
        // The events of the job, whichever replica ran it (the other reads them from the store).
        // (An SSE body is chunked: read raw, the chunk sizes left in.)
        let bearer = format!("Bearer {ADMIN}");
        let (code, events) = strata::bench::http::http(
            addr,
            "GET",
            &format!("/v1/jobs/{job}/events"),
            &[("Authorization", &bearer)],
            "",
        )
        .await
        .expect("events");
        let events = String::from_utf8_lossy(&events);
        assert_eq!(code, 200, "{addr}: {events}");
        assert!(events.contains("event: done"), "{addr}: {events}");
    }
    // The dead replica's partial archive is gone; the two archives remain.
    let mut left: Vec<String> = std::fs::read_dir(&shared)
        .expect("shared dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let mut want = vec![format!("{whole}.tar"), format!("{job}.tar")];
    want.sort();
    assert_eq!(left, want);
}

/// One server on SQLite, SIGKILLed mid-export and started again on the same data directory:
/// it takes its own job over once the lease lapses and the archive is the uninterrupted run's.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_export_job_survives_a_restart_of_a_single_server() {
    let data = tempfile::tempdir().expect("tmp");
    let args = [
        "--data",
        data.path().to_str().expect("utf-8"),
        "--admin-token",
        ADMIN,
        "--export-lease",
        LEASE_S,
    ];
    let mut server = common::start(args, &[]);
    let (world, _) = create_world(&server.addr, ADMIN, 22).await;
    let spec = json!({"lod": 1, "region": [-4, 0, 4, 6], "products": ["tiles", "scatter"],
                      "formats": ["bin", "png"]});
    let whole = start_export(&server.addr, &world, &spec).await;
    wait_done(&server.addr, &whole).await;
    let expected = archive(&server.addr, &whole).await;

    let job = start_export(&server.addr, &world, &spec).await;
    let deadline = Instant::now() + Duration::from_secs(300);
    let at_kill = loop {
        let s = status(&server.addr, &job).await;
        if s["done"].as_u64().expect("done") > 0 {
            break s;
        }
        assert!(Instant::now() < deadline, "no progress: {s}");
        tokio::time::sleep(Duration::from_millis(10)).await;
    };
    server.child.kill().expect("SIGKILL the server");
    let _ = server.child.wait();
    assert_eq!(at_kill["status"], "running", "killed mid-job: {at_kill}");
    assert!(at_kill["done"].as_u64() < at_kill["total"].as_u64());

    let again = common::start(args, &[]);
    wait_done(&again.addr, &job).await;
    assert!(
        archive(&again.addr, &job).await == expected,
        "the archive redone after the restart differs from the uninterrupted one"
    );
    // The first run's archive outlived the restart too.
    assert!(archive(&again.addr, &whole).await == expected);
}
