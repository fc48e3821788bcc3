//! Acknowledged edits survive SIGKILL: the real `strata` binary is killed while a client streams
//! edits, restarted on the same data directory, and every acknowledged version must be there.

use serde_json::{json, Value};
use std::ffi::OsStr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const ADMIN: &str = "crash-test-admin-token";

mod common;

use common::raw::request;
use common::Server;

fn start(data: &std::path::Path) -> Server {
    common::start(
        [
            OsStr::new("--admin-token"),
            OsStr::new(ADMIN),
            OsStr::new("--data"),
            data.as_os_str(),
        ],
        &[],
    )
}

fn json(body: &[u8]) -> Value {
    serde_json::from_slice(body).expect("JSON body")
}

#[test]
fn acknowledged_edits_survive_sigkill() {
    let data = tempfile::tempdir().expect("tmp");
    let mut server = start(data.path());
    let admin = format!("Bearer {ADMIN}");
    let (status, body) = request(
        &server.addr,
        "POST",
        "/v1/worlds",
        &[
            ("Authorization", &admin),
            ("Content-Type", "application/json"),
        ],
        br#"{"seed": 4242}"#,
    )
    .expect("create");
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&body));
    let created = json(&body);
    let id = created["id"].as_str().expect("id").to_string();
    let token = format!(
        "Bearer {}",
        created["tokens"]["admin"].as_str().expect("token")
    );

    // Version 2 changes the world settings, so its tiles differ from version 1's; both versioned
    // URLs must give the same bytes after the restart.
    let (status, body) = request(
        &server.addr,
        "POST",
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("Authorization", &token),
            ("Content-Type", "application/json-patch+json"),
            ("If-Match", "1"),
        ],
        br#"[{"op":"replace","path":"/world/earth/erosion","value":0.5}]"#,
    )
    .expect("settings edit");
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    let tile_urls = [
        format!("/v1/worlds/{id}/tiles/0/1/-1.bin?v=1"),
        format!("/v1/worlds/{id}/tiles/0/1/-1.bin?v=2"),
        format!("/v1/worlds/{id}/tiles/3/-2/0.json?v=2"),
    ];
    let tiles_before: Vec<Vec<u8>> = tile_urls
        .iter()
        .map(|u| {
            let (status, body) =
                request(&server.addr, "GET", u, &[("Authorization", &token)], b"").expect("tile");
            assert_eq!(status, 200, "{u}");
            body
        })
        .collect();
    assert!(
        tiles_before[0] != tiles_before[1],
        "the settings edit changes the tile"
    );

    // The editor: one region per edit, each conditional on the last acknowledged version.
    let acked: Arc<Mutex<Vec<(u64, String)>>> = Arc::default();
    let stop = Arc::new(AtomicBool::new(false));
    let editor = {
        let (addr, id, token) = (server.addr.clone(), id.clone(), token.clone());
        let (acked, stop) = (acked.clone(), stop.clone());
        std::thread::spawn(move || {
            let mut version = 2u64;
            let started = Instant::now();
            for i in 0..100_000u64 {
                if stop.load(Ordering::Relaxed) || started.elapsed() > Duration::from_secs(120) {
                    break;
                }
                let region = format!("r{i}");
                let patch = json!([{"op": "add", "path": "/regions/-", "value":
                    {"id": region, "bbox": {"min": [i as f64, 0.5], "max": [i as f64 + 1.0, 2.5]}}}]);
                let if_match = version.to_string();
                let reply = request(
                    &addr,
                    "POST",
                    &format!("/v1/worlds/{id}/edits"),
                    &[
                        ("Authorization", &token),
                        ("Content-Type", "application/json-patch+json"),
                        ("If-Match", &if_match),
                    ],
                    patch.to_string().as_bytes(),
                );
                match reply {
                    Ok((200, body)) => {
                        version = json(&body)["version"].as_u64().expect("version");
                        assert_eq!(version, i + 3, "one version per edit");
                        acked.lock().expect("lock").push((version, region));
                    }
                    Ok((status, body)) => panic!(
                        "edit {i} refused with {status}: {}",
                        String::from_utf8_lossy(&body)
                    ),
                    // The server was killed: this edit is not acknowledged.
                    Err(_) => break,
                }
            }
        })
    };

    let deadline = Instant::now() + Duration::from_secs(60);
    while acked.lock().expect("lock").len() < 40 {
        assert!(Instant::now() < deadline, "edits are too slow");
        std::thread::sleep(Duration::from_millis(5));
    }
    // SIGKILL while the editor is mid-stream.
    server.child.kill().expect("SIGKILL");
    server.child.wait().expect("reaped");
    stop.store(true, Ordering::Relaxed);
    editor.join().expect("editor thread");
    let acked = acked.lock().expect("lock").clone();
    let last = acked.last().expect("some edits acknowledged").0;

    let server = start(data.path());
    let (status, body) = request(
        &server.addr,
        "GET",
        &format!("/v1/worlds/{id}"),
        &[("Authorization", &token)],
        b"",
    )
    .expect("get world");
    assert_eq!(status, 200);
    let world = json(&body);
    let latest = world["version"].as_u64().expect("version");
    // The edit in flight at the kill may or may not have committed; none acknowledged is lost.
    assert!(
        latest == last || latest == last + 1,
        "latest version {latest}, last acknowledged {last}"
    );
    let regions: Vec<&str> = world["scene"]["regions"]
        .as_array()
        .expect("regions")
        .iter()
        .map(|r| r["id"].as_str().expect("id"))
        .collect();
    for (version, region) in &acked {
        assert_eq!(
            regions.get(*version as usize - 3),
            Some(&region.as_str()),
            "acknowledged edit of version {version} is missing from the latest scene"
        );
        let (status, body) = request(
            &server.addr,
            "GET",
            &format!("/v1/worlds/{id}/versions/{version}"),
            &[("Authorization", &token)],
            b"",
        )
        .expect("get version");
        assert_eq!(status, 200, "version {version}");
        let scene = &json(&body)["scene"];
        let n = scene["regions"].as_array().expect("regions").len();
        assert_eq!(n as u64, version - 2, "version {version}");
        assert_eq!(scene["regions"][n - 1]["id"], region.as_str());
    }
    for (u, before) in tile_urls.iter().zip(&tiles_before) {
        let (status, body) =
            request(&server.addr, "GET", u, &[("Authorization", &token)], b"").expect("tile");
        assert_eq!(status, 200, "{u}");
        assert_eq!(&body, before, "{u} changed across the restart");
    }
    // The world is still editable where it left off.
    let (status, body) = request(
        &server.addr,
        "POST",
        &format!("/v1/worlds/{id}/edits"),
        &[
            ("Authorization", &token),
            ("Content-Type", "application/json-patch+json"),
            ("If-Match", &latest.to_string()),
        ],
        b"[]",
    )
    .expect("edit after restart");
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    assert_eq!(json(&body)["version"], latest + 1);
    eprintln!(
        "{} edits acknowledged before SIGKILL; latest after restart {latest}",
        acked.len()
    );
}
