//! A world stored with the first river valleys keeps its bytes: its scene has no
//! `world.earth.rivers.valleys` and no `world.earth.gullies`, which mean `1`, and today's server
//! answers the tiles (formats 1 and 2) the old server answered, bit for bit
//! (`tests/fixtures/rivers-world/`). New worlds and bare seeds get `valleys: 8` and `gullies: 3`,
//! whose tiles differ; the worlds stored with `valleys: 2` to `7` keep theirs too, and so do one
//! stored with `valleys: 6` before new worlds got the coarse lattice, one stored with
//! `gullies: 2` and one stored with every gully octave (before `gully_first: 1`).

mod common;

use common::fixture::get;

const WORLD: &str = "c7ff83f4aec16857c06ae2d9";
const FIXTURE: &str = "rivers-world";

/// Serves fixture `fixture` and checks that world `world` answers every pinned tile (formats 1
/// and 2, at `version`) with the pinned bytes: `tiles` of them. Returns the data directory and
/// the server (kept alive by the caller) and the stored scene at `version`.
async fn stored_world(
    fixture: &str,
    world: &str,
    version: u64,
    tiles: usize,
) -> (tempfile::TempDir, common::Server, serde_json::Value) {
    let (data, server) = common::fixture::serve(fixture);
    let checked = common::fixture::check_pinned(&server, fixture, "tiles.blake3", |format, key| {
        let query = if format == "2" { "&format=2" } else { "" };
        format!("/v1/worlds/{world}/tiles/{key}.bin?v={version}{query}")
    })
    .await;
    assert_eq!(checked, tiles, "every fixture tile was checked");
    let (status, body) = get(
        &server.addr,
        &format!("/v1/worlds/{world}/versions/{version}"),
    )
    .await;
    assert_eq!(status, 200);
    let doc: serde_json::Value = serde_json::from_slice(&body).expect("scene JSON");
    (data, server, doc["scene"].clone())
}

/// How many of fixture `fixture`'s pinned format-1 tiles seed 42 (today's default world)
/// answers with other bytes on `server`.
async fn bare_seed_differs(server: &common::Server, fixture: &str) -> usize {
    let pinned = std::fs::read_to_string(common::fixture::path(fixture, "tiles.blake3"))
        .expect("fixture hashes");
    let mut differ = 0;
    for line in pinned.lines().filter(|l| l.starts_with("1 ")) {
        let mut parts = line.split_whitespace().skip(1);
        let (key, hash) = (parts.next().expect("key"), parts.next().expect("hash"));
        let (status, bare) = get(&server.addr, &format!("/v1/seeds/42/tiles/{key}.bin")).await;
        assert_eq!(status, 200, "{key}");
        differ += usize::from(blake3::hash(&bare).to_hex().as_str() != hash);
    }
    differ
}

#[tokio::test]
async fn a_world_stored_with_the_first_valleys_serves_the_same_tile_bytes() {
    let expected = std::fs::read_to_string(common::fixture::path(FIXTURE, "tiles.blake3"))
        .expect("fixture hashes");
    // The stored scene has rivers but no `valleys`, and reading it does not add one.
    let (_data, server, doc) = stored_world(FIXTURE, WORLD, 1, 20).await;
    let rivers = &doc["world"]["earth"]["rivers"];
    assert_eq!(rivers["enabled"], true, "{rivers}");
    assert!(rivers.get("valleys").is_none(), "{rivers}");
    let earth = &doc["world"]["earth"];
    assert!(earth.get("gullies").is_none(), "{earth}");

    // A bare seed is the new default, `valleys: 7`: the carved tile over a river differs.
    let stored = expected
        .lines()
        .find(|l| l.starts_with("1 3/-24/50 "))
        .and_then(|l| l.split_whitespace().nth(2))
        .expect("the river tile's line");
    let (status, bare) = get(&server.addr, "/v1/seeds/42/tiles/3/-24/50.bin").await;
    assert_eq!(status, 200);
    assert_ne!(
        blake3::hash(&bare).to_hex().as_str(),
        stored,
        "bare seeds carve valleys: 7 and incised gullies"
    );
}

/// A world stored with `valleys: 2` and the lattice split (the default of new worlds at
/// `b09fbec`) keeps its bytes (`tests/fixtures/valleys2-world/`).
#[tokio::test]
async fn a_world_stored_with_the_second_valleys_serves_the_same_tile_bytes() {
    const WORLD2: &str = "2e8854b197caf02ebd61ed80";
    const FIXTURE2: &str = "valleys2-world";
    let (_data, _server, scene) = stored_world(FIXTURE2, WORLD2, 1, 20).await;
    let earth = &scene["world"]["earth"];
    assert_eq!(earth["rivers"]["valleys"], 2, "{earth}");
    assert_eq!(earth["lattice_cells"], 16, "{earth}");
}

/// A world stored with `valleys: 3` (the default of new worlds at `9c11dba`) keeps its bytes
/// (`tests/fixtures/valleys3-world/`).
#[tokio::test]
async fn a_world_stored_with_the_third_valleys_serves_the_same_tile_bytes() {
    const WORLD3: &str = "f78fa8d5daf52fef3cc7abe5";
    const FIXTURE3: &str = "valleys3-world";
    let (_data, _server, scene) = stored_world(FIXTURE3, WORLD3, 1, 34).await;
    assert_eq!(scene["world"]["earth"]["rivers"]["valleys"], 3);
}

/// A world stored with `valleys: 4` and `lakes: 2` (`tests/fixtures/valleys4-world/`) keeps its
/// bytes.
#[tokio::test]
async fn a_world_stored_with_the_fourth_valleys_serves_the_same_tile_bytes() {
    const WORLD4: &str = "2da01e54111ab1b68701ca3b";
    const FIXTURE4: &str = "valleys4-world";
    let (_data, _server, scene) = stored_world(FIXTURE4, WORLD4, 1, 34).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(rivers["valleys"], 4, "{rivers}");
    assert_eq!(rivers["lakes"], 2, "{rivers}");
}

/// A world stored with spilling lakes (`lakes: 3`, `tests/fixtures/lakes3-world/`) keeps its
/// bytes, at the outlet of a lake too, where new worlds (`lakes: 4`) keep a sill.
#[tokio::test]
async fn a_world_stored_with_the_third_lakes_serves_the_same_tile_bytes() {
    const WORLD: &str = "5a5a562e2374e4b29e09148a";
    const FIXTURE: &str = "lakes3-world";
    let (_data, _server, scene) = stored_world(FIXTURE, WORLD, 2, 44).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(rivers["lakes"], 3, "{rivers}");
}

/// A world stored with the default of new worlds before `valleys: 5` (`valleys: 3` and
/// `lakes: 4`, `tests/fixtures/lakes4-world/`) keeps its bytes, where a bare seed, with the later
/// valleys, carves some of those tiles differently.
#[tokio::test]
async fn a_world_stored_with_the_third_valleys_and_fourth_lakes_serves_the_same_tile_bytes() {
    const WORLD: &str = "7b17dd174bc41c52d847e85a";
    const FIXTURE: &str = "lakes4-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 44).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(
        (&rivers["valleys"], &rivers["lakes"]),
        (&3.into(), &4.into()),
        "{rivers}"
    );
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed carves later valleys, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before `valleys: 6` (`valleys: 5` and
/// `lakes: 4`, `tests/fixtures/valleys5-world/`) keeps its bytes, where a bare seed, `valleys: 6`,
/// whose walls are gentler in low relief, carves some of those tiles differently.
#[tokio::test]
async fn a_world_stored_with_the_fifth_valleys_serves_the_same_tile_bytes() {
    const WORLD: &str = "bb61cdcb5d903e32f303403f";
    const FIXTURE: &str = "valleys5-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 44).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(
        (&rivers["valleys"], &rivers["lakes"]),
        (&5.into(), &4.into()),
        "{rivers}"
    );
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed carves valleys: 6, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before the coarse lattice and the sea-level
/// snow lines (`valleys: 6`, `lattice_cells: 16`, no `coarse_lattice_cells` and no `snow_lines`,
/// `tests/fixtures/valleys6-world/`) keeps its bytes, where a bare seed, whose LODs 0–7
/// interpolate the macro fields and the two longest layers from a 256 m lattice and whose snow
/// starts at the sea-level climate's line, gives other bytes.
#[tokio::test]
async fn a_world_stored_with_the_sixth_valleys_and_no_coarse_lattice_serves_the_same_tile_bytes() {
    const WORLD: &str = "960fa06a7301e7fd03952c53";
    const FIXTURE: &str = "valleys6-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 48).await;
    let earth = &scene["world"]["earth"];
    assert_eq!(
        (&earth["rivers"]["valleys"], &earth["lattice_cells"]),
        (&6.into(), &16.into()),
        "{earth}"
    );
    assert_eq!(earth.get("coarse_lattice_cells"), None, "{earth}");
    assert_eq!(earth.get("snow_lines"), None, "{earth}");
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed reads the coarse lattice and the sea-level snow lines, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before `gullies: 3` (`gullies: 2`, the coarse
/// lattice, the sea-level snow lines and the alpine zone, `tests/fixtures/gullies2-world/`)
/// keeps its bytes, in the range's mountains too, where a bare seed, whose gullies fade out
/// where their phasors cancel, gives other bytes.
#[tokio::test]
async fn a_world_stored_with_the_second_gullies_serves_the_same_tile_bytes() {
    const WORLD: &str = "d0f1ce5947322442edd5f13c";
    const FIXTURE: &str = "gullies2-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 52).await;
    let world = &scene["world"];
    assert_eq!(world["earth"]["gullies"], 2, "{world}");
    assert_eq!(world["earth"]["coarse_lattice_cells"], 256, "{world}");
    assert_eq!(world["texturing"]["alpine_fraction"], 0.25, "{world}");
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed has gullies: 3, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before `gully_first: 1` (every gully octave,
/// `tests/fixtures/gullies3-world/`) keeps its bytes, in the range's canyon too, where a bare
/// seed, which leaves the coarsest gully octave out (and carves `valleys: 7`), gives other
/// bytes.
#[tokio::test]
async fn a_world_stored_with_every_gully_octave_serves_the_same_tile_bytes() {
    const WORLD: &str = "154157a960e10ed0752e2d07";
    const FIXTURE: &str = "gullies3-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 54).await;
    let earth = &scene["world"]["earth"];
    assert_eq!(earth["gullies"], 3, "{earth}");
    assert_eq!(earth.get("gully_first"), None, "{earth}");
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed leaves the coarsest gully octave out, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before the coarse network (`valleys: 7`,
/// `lakes: 4`, no `coarse`; `tests/fixtures/lakes4-coarse0-world/`) keeps its bytes, at LODs
/// 9 to 12 too, where a bare seed carves the coarse network's valleys and shows its lakes.
#[tokio::test]
async fn a_world_stored_with_the_fourth_lakes_and_no_coarse_network_serves_the_same_tile_bytes() {
    const WORLD: &str = "0feba0a97a5cda0562a6d6da";
    const FIXTURE: &str = "lakes4-coarse0-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 70).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(rivers["valleys"], 7, "{rivers}");
    assert_eq!(rivers["lakes"], 4, "{rivers}");
    assert_eq!(rivers.get("coarse"), None, "{rivers}");
    let differ = bare_seed_differs(&server, FIXTURE).await;
    assert!(
        differ > 0,
        "a bare seed carves LODs 9 and 10 with the coarse network, which no fixture tile shows"
    );
}

/// A world stored with the default of new worlds before `lakes: 5` and `lines: 2` (`valleys: 7`,
/// `lakes: 4`, `coarse: 1`, no `lines`; `tests/fixtures/lakes4-coarse1-world/`) keeps the bytes
/// of its tiles and of its river lines, where a bare seed fills more lakes and follows the
/// carved curves in more points.
#[tokio::test]
async fn a_world_stored_with_the_fourth_lakes_and_the_first_lines_serves_the_same_bytes() {
    const WORLD: &str = "b33d4a762ecdda94accda92c";
    const FIXTURE: &str = "lakes4-coarse1-world";
    let (_data, server, scene) = stored_world(FIXTURE, WORLD, 1, 80).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(rivers["lakes"], 4, "{rivers}");
    assert_eq!(rivers["coarse"], 1, "{rivers}");
    assert_eq!(rivers.get("lines"), None, "{rivers}");
    let lines = common::fixture::check_pinned(&server, FIXTURE, "rivers.blake3", |_, key| {
        format!("/v1/worlds/{WORLD}/rivers/{key}.json?v=1")
    })
    .await;
    assert_eq!(lines, 9, "every fixture body of river lines was checked");
    assert!(
        bare_seed_differs(&server, FIXTURE).await > 0,
        "a bare seed fills its lakes with lakes: 5"
    );
    let pinned = std::fs::read_to_string(common::fixture::path(FIXTURE, "rivers.blake3"))
        .expect("fixture hashes");
    let mut differ = 0;
    for line in pinned.lines() {
        let parts: Vec<&str> = line.split_whitespace().collect();
        let (status, bare) = get(
            &server.addr,
            &format!("/v1/seeds/42/rivers/{}.json", parts[1]),
        )
        .await;
        assert_eq!(status, 200, "{line}");
        differ += usize::from(blake3::hash(&bare).to_hex().as_str() != parts[2]);
    }
    assert!(
        differ >= 5,
        "a bare seed's lines follow the curves in more points: {differ} of 9 differ"
    );
}

/// Serves fixture `fixture` (world `world`, stored with the default of new worlds of then:
/// `valleys`, `lakes`, `lines: 2`), checks every pinned tile and river-line body, and that a bare
/// seed differs in most fixture tiles (`why` says what changed since).
async fn a_stored_default_keeps_its_bytes(
    fixture: &str,
    world: &str,
    (valleys, lakes): (u32, u32),
    (tiles, lines, least): (usize, usize, usize),
    why: &str,
) {
    let (_data, server, scene) = stored_world(fixture, world, 1, tiles).await;
    let rivers = &scene["world"]["earth"]["rivers"];
    assert_eq!(rivers["valleys"], valleys, "{rivers}");
    assert_eq!(rivers["lakes"], lakes, "{rivers}");
    assert_eq!(rivers["lines"], 2, "{rivers}");
    let checked_lines =
        common::fixture::check_pinned(&server, fixture, "rivers.blake3", |_, key| {
            format!("/v1/worlds/{world}/rivers/{key}.json?v=1")
        })
        .await;
    assert_eq!(
        checked_lines, lines,
        "every fixture body of river lines was checked"
    );
    let differ = bare_seed_differs(&server, fixture).await;
    assert!(
        differ >= least,
        "{why}, which at least {least} of the {} format-1 fixture tiles show: {differ} differ",
        tiles / 2
    );
}

/// A world stored with the default of new worlds before `valleys: 8` (`valleys: 7`, `lakes: 5`,
/// `coarse: 1`, `lines: 2`; `tests/fixtures/valleys7-world/`) keeps the bytes of its tiles and of
/// its river lines, where a bare seed sizes its valleys by their rivers: narrower floodplains
/// and less bend for the small ones, so its tiles and most of its lines differ.
#[tokio::test]
async fn a_world_stored_with_the_seventh_valleys_serves_the_same_bytes() {
    a_stored_default_keeps_its_bytes(
        "valleys7-world",
        "89412016ba7f5e484bb83405",
        (7, 5),
        (80, 9, 20),
        "a bare seed sizes its valleys",
    )
    .await;
}

/// A world stored with the default of new worlds before `lakes: 6` (`valleys: 8`, `lakes: 5`,
/// `coarse: 1`, `lines: 2`; `tests/fixtures/lakes5-world/`) keeps the bytes of its tiles and of
/// its river lines, where a bare seed's network sees the hollows (its node heights at most the
/// LOD of one node spacing's), so its rivers and lakes move and most fixture tiles differ.
#[tokio::test]
async fn a_world_stored_with_the_fifth_lakes_serves_the_same_bytes() {
    a_stored_default_keeps_its_bytes(
        "lakes5-world",
        "f059eb7d1298d0313139ab23",
        (8, 5),
        (80, 9, 20),
        "a bare seed's network sees the hollows",
    )
    .await;
}

/// A world stored with the default of new worlds before `lakes: 7` (`valleys: 8`, `lakes: 6`,
/// `coarse: 1`, `lines: 2`; `tests/fixtures/lakes6-world/`) keeps the bytes of its tiles and of
/// its river lines, where a bare seed's coarse network searches 30 of its own spacings for an
/// outlet and leaves spilling lakes from their saddles, so the tiles it carves (LODs 9 and 10)
/// and those that show its lakes (11 and 12) differ: 19 of the fixture's 59 format-1 tiles, 13
/// of them among those added for it over the far area's basins, the range and the viewer's
/// square. (No flood of the fine network that the fixture's finer tiles read stops by its
/// limits: those tiles and the river lines keep their bytes in a bare seed too.)
#[tokio::test]
async fn a_world_stored_with_the_sixth_lakes_serves_the_same_bytes() {
    a_stored_default_keeps_its_bytes(
        "lakes6-world",
        "5d60b73c5d6afe4839a3cdfb",
        (8, 6),
        (118, 13, 15),
        "a bare seed's coarse network fills the basins a hundred kilometres across",
    )
    .await;
}

/// A world stored with the default of new worlds before `lakes: 8` (`valleys: 8`, `lakes: 7`,
/// `coarse: 1`, `lines: 2`; `tests/fixtures/lakes7-world/`) keeps the bytes of its tiles and of
/// its river lines, where a bare seed's shores sink the ground inside its lakes towards their
/// nodes' heights and its coarse network's floods visit up to 2,048 nodes, so the tiles that
/// show a lake whose ground rose above its nodes differ: 36 of the fixture's 59 format-1 tiles.
/// (The networks' rivers stay, so do the river lines.)
#[tokio::test]
async fn a_world_stored_with_the_seventh_lakes_serves_the_same_bytes() {
    a_stored_default_keeps_its_bytes(
        "lakes7-world",
        "7cffb23ed3388683ee553404",
        (8, 7),
        (118, 13, 30),
        "a bare seed's shores sink the ground inside its lakes",
    )
    .await;
}

#[test]
fn new_scenes_carve_the_eighth_valleys_and_accept_only_known_ones() {
    let scene = strata::scene::Scene::default().to_value();
    assert_eq!(scene["world"]["earth"]["rivers"]["valleys"], 8);
    assert_eq!(scene["world"]["earth"]["rivers"]["lakes"], 8);
    assert_eq!(scene["world"]["earth"]["rivers"]["coarse"], 1);
    assert_eq!(scene["world"]["earth"]["rivers"]["lines"], 2);
    let mut first = scene.clone();
    first["world"]["earth"]["rivers"]["lines"] = serde_json::json!(1);
    strata::scene::Scene::from_value(&first).expect("the first lines are accepted");
    let mut bad = scene.clone();
    bad["world"]["earth"]["rivers"]["lines"] = serde_json::json!(3);
    let err = strata::scene::Scene::from_value(&bad).expect_err("lines 3 is refused");
    assert!(format!("{err:?}").contains("rivers/lines"), "{err:?}");
    let mut without = scene.clone();
    without["world"]["earth"]["rivers"]["coarse"] = serde_json::json!(0);
    strata::scene::Scene::from_value(&without).expect("no coarse network is accepted");
    let mut bad = scene.clone();
    bad["world"]["earth"]["rivers"]["coarse"] = serde_json::json!(2);
    let err = strata::scene::Scene::from_value(&bad).expect_err("coarse 2 is refused");
    assert!(format!("{err:?}").contains("rivers/coarse"), "{err:?}");
    for known in [3, 4, 5, 6, 7] {
        let mut older = scene.clone();
        older["world"]["earth"]["rivers"]["valleys"] = serde_json::json!(known);
        strata::scene::Scene::from_value(&older).expect("older valleys are accepted");
    }
    assert_eq!(scene["world"]["earth"]["gullies"], 3);
    let mut bad = scene.clone();
    bad["world"]["earth"]["rivers"]["valleys"] = serde_json::json!(9);
    let err = strata::scene::Scene::from_value(&bad).expect_err("valleys 9 is refused");
    assert!(format!("{err:?}").contains("rivers/valleys"), "{err:?}");
    for known in [1, 2, 3, 4, 5, 6, 7] {
        let mut other = scene.clone();
        other["world"]["earth"]["rivers"]["lakes"] = serde_json::json!(known);
        strata::scene::Scene::from_value(&other).expect("other known lakes are accepted");
    }
    let mut bad = scene.clone();
    bad["world"]["earth"]["rivers"]["lakes"] = serde_json::json!(9);
    let err = strata::scene::Scene::from_value(&bad).expect_err("lakes 9 is refused");
    assert!(format!("{err:?}").contains("rivers/lakes"), "{err:?}");
}
