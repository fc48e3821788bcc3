//! A world stored before `earth-1` keeps its bytes: its scene names no generator, which means
//! `classic`, and today's server answers the tiles the old server answered, bit for bit
//! (`tests/fixtures/classic-world/`). New worlds get `earth-1`.

mod common;

use common::fixture::get;

const WORLD: &str = "8207d904ca1fed302bc4dce8";
const FIXTURE: &str = "classic-world";

#[tokio::test]
async fn a_world_stored_by_the_classic_default_serves_the_same_tile_bytes() {
    let (_data, server) = common::fixture::serve(FIXTURE);
    let expected = std::fs::read_to_string(common::fixture::path(FIXTURE, "tiles.blake3"))
        .expect("fixture hashes");
    let checked = common::fixture::check_pinned(&server, FIXTURE, "tiles.blake3", |v, key| {
        format!("/v1/worlds/{WORLD}/tiles/{key}.bin?v={v}")
    })
    .await;
    assert_eq!(checked, 12, "every fixture tile was checked");

    // The stored scene names no generator (so it is classic) ...
    let (status, body) = get(&server.addr, &format!("/v1/worlds/{WORLD}/versions/1")).await;
    assert_eq!(status, 200);
    let text = String::from_utf8_lossy(&body);
    assert!(!text.contains("generator\":\"earth-1"), "{text}");
    // ... while a bare seed is the new default world, whose tiles differ.
    let (status, bare) = get(&server.addr, "/v1/seeds/42/tiles/0/0/0.bin").await;
    assert_eq!(status, 200);
    let stored_line = expected.lines().next().expect("a line");
    assert!(stored_line.starts_with("1 0/0/0 "));
    assert_ne!(
        blake3::hash(&bare).to_hex().as_str(),
        stored_line.split_whitespace().nth(2).expect("hash"),
        "bare seeds use earth-1"
    );
}

#[test]
fn new_scenes_name_the_earth_generator_and_classic_scenes_name_none() {
    let earth = strata::scene::Scene::default().to_value();
    assert_eq!(earth["world"]["generator"], "earth-1");
    assert!(earth["world"]["earth"].is_object());
    let mut classic = strata::scene::Scene::default();
    classic.world = strata::terrain::WorldParams::classic();
    let v = classic.to_value();
    assert!(v["world"].get("generator").is_none(), "{}", v["world"]);
    assert!(v["world"].get("earth").is_none());
    let parsed = strata::scene::Scene::from_value(&v).expect("a classic scene is valid");
    assert_eq!(parsed.world.generator, strata::terrain::Generator::Classic);
}
