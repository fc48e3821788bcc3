//! A world stored by the first `earth-1` (before rivers) keeps its bytes: its scene has no
//! `world.earth.rivers`, which means no rivers, and today's server answers the tiles the old
//! server answered, bit for bit (`tests/fixtures/earth1-world/`), and its glb tiles have no
//! water node. New worlds get rivers. Its scene has no `world.scatter.lattice` either, so it keeps
//! the `scan` scatter lattice: the same scatter bytes, and a 400 where a scan tile costs too much.

mod common;

use common::fixture::pinned_get;

const WORLD: &str = "ef03f35e5725d0b89309b207";

/// The fixture's directory under `tests/fixtures`.
const FIXTURE: &str = "earth1-world";

fn fixture(name: &str) -> std::path::PathBuf {
    common::fixture::path(FIXTURE, name)
}

fn serve_fixture() -> (tempfile::TempDir, common::Server) {
    common::fixture::serve(FIXTURE)
}

#[tokio::test]
async fn a_world_stored_by_the_first_earth_generator_serves_the_same_tile_bytes() {
    let (_data, server) = serve_fixture();
    let expected = std::fs::read_to_string(fixture("tiles.blake3")).expect("fixture hashes");
    let mut checked = 0;
    for line in expected.lines() {
        let parts: Vec<&str> = line.split_whitespace().collect();
        let [version, key, hash] = parts[..] else {
            panic!("bad fixture line {line:?}");
        };
        pinned_get(
            &server,
            &format!("/v1/worlds/{WORLD}/tiles/{key}.bin?v={version}"),
            hash,
        )
        .await;
        // Its tiles carry no water kinds, so its glb keeps the terrain's one node: no water.
        let glb = format!("/v1/worlds/{WORLD}/tiles/{key}.glb?v={version}");
        let (status, body) = strata::bench::http::http_get(&server.addr, &glb)
            .await
            .expect("request");
        assert_eq!(status, 200, "{glb}");
        let json_len = u32::from_le_bytes([body[12], body[13], body[14], body[15]]) as usize;
        let doc: serde_json::Value =
            serde_json::from_slice(&body[20..20 + json_len]).expect("glb JSON chunk");
        assert_eq!(doc["nodes"].as_array().map(Vec::len), Some(1), "{glb}");
        assert!(doc.get("materials").is_none(), "{glb}");
        checked += 1;
    }
    assert_eq!(checked, 13, "every fixture tile was checked");
}

#[tokio::test]
async fn a_world_stored_before_the_levels_lattice_keeps_its_scatter_and_refuses_costly_lods() {
    let (_data, server) = serve_fixture();
    let expected = std::fs::read_to_string(fixture("scatter.blake3")).expect("fixture hashes");
    let (mut checked, mut points) = (0, 0);
    for line in expected.lines() {
        let parts: Vec<&str> = line.split_whitespace().collect();
        let [version, key, hash, count] = parts[..] else {
            panic!("bad fixture line {line:?}");
        };
        let path = format!("/v1/worlds/{WORLD}/scatter/{key}.json?v={version}");
        let body = pinned_get(&server, &path, hash).await;
        let doc: serde_json::Value = serde_json::from_slice(&body).expect("scatter JSON");
        let n = doc["points"].as_array().map_or(0, Vec::len);
        assert_eq!(n.to_string(), count, "{path}");
        points += n;
        checked += 1;
    }
    assert_eq!(checked, 11, "every fixture line was checked");
    assert!(points > 100, "the pinned tiles carry points ({points})");

    // LOD 7 would visit 2049² candidates of the scan lattice: refused before any work.
    let path = format!("/v1/worlds/{WORLD}/scatter/7/0/0.json?v=1");
    let (status, body) = strata::bench::http::http_get(&server.addr, &path)
        .await
        .expect("request");
    assert_eq!(status, 400, "{path}");
    let err: serde_json::Value = serde_json::from_slice(&body).expect("JSON error");
    assert_eq!(err["error"]["code"], "lod_out_of_range", "{err}");
    assert_eq!(err["error"]["field"], "lod", "{err}");
    let message = err["error"]["message"].as_str().unwrap_or_default();
    assert!(
        message.contains("4194304") && message.contains("up to LOD 6"),
        "{message}"
    );
}
