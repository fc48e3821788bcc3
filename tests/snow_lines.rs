//! Whose snow line a vertex of an `earth-1` world reads (`world.earth.snow_lines`,
//! `strata::terrain::earth::climate::sea_snow_lines`):
//!
//! - with `snow_lines: 2` (new worlds) the sea-level climate's: in the mountain range 160 km
//!   from the origin (temperate latitudes), snow lies only on the summits, and a tile's snow
//!   vertices are exactly those above that line (plus the aspect and noise shift), on ground
//!   neither steep nor wet;
//! - with `snow_lines: 1` (worlds stored before it) the line of the biomes the climate made
//!   colder with altitude, so the same range is more than half snow, down to about 1,300 m;
//! - a stored world's document without `snow_lines` reads as 1 (its bytes:
//!   `tests/rivers_world.rs`), new scenes write 2, and other values are refused naming the field.

use strata::terrain::earth::{snow_shift, tile_sea_snow_lines};
use strata::terrain::tile::Tile;
use strata::terrain::world::material;
use strata::terrain::{WorldParams, WorldPlan};

mod common;
use common::range::range_tiles;

const SEED: u64 = 42;

fn plan(snow_lines: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    params.earth.as_mut().expect("earth-1").snow_lines = snow_lines;
    WorldPlan::new(SEED, params).expect("default world")
}

/// Land vertices, snow vertices and the lowest snow vertex's height of `tiles`.
fn snow_cover(tiles: &[Tile]) -> (usize, usize, f32) {
    let (mut land, mut snow, mut lowest) = (0, 0, f32::INFINITY);
    for t in tiles {
        for (v, &h) in t.heights.iter().enumerate() {
            if h <= 0.0 {
                continue;
            }
            land += 1;
            if t.materials[v] == material::SNOW {
                snow += 1;
                lowest = lowest.min(h);
            }
        }
    }
    (land, snow, lowest)
}

#[test]
fn the_range_keeps_its_snow_on_the_summits_with_the_sea_level_snow_lines() {
    let (new, old) = (plan(2), plan(1));
    let tiles = range_tiles(&new);
    let (land, snow, lowest) = snow_cover(&tiles);
    let highest = tiles
        .iter()
        .flat_map(|t| t.heights.iter().copied())
        .fold(f32::MIN, f32::max);
    println!(
        "snow_lines 2: {snow} of {land} land vertices snow, the lowest at {lowest:.0} m (summit {highest:.0} m)"
    );
    assert!(highest > 2800.0, "the range's summits reach {highest} m");
    assert!(snow > 0, "the summits hold snow");
    assert!(lowest > 2400.0, "snow at {lowest} m");
    // The same heights (the snow line is the texturing's alone), but the line of the cooled
    // biomes: the tundra's 600 m on the upper slopes.
    let tiles_old = range_tiles(&old);
    for (a, b) in tiles.iter().zip(&tiles_old) {
        assert_eq!(a.heights, b.heights, "{:?}", a.key);
    }
    let (_, snow_old, lowest_old) = snow_cover(&tiles_old);
    println!("snow_lines 1: {snow_old} snow, the lowest at {lowest_old:.0} m");
    assert!(
        2 * snow_old > land && lowest_old < 1500.0,
        "{snow_old} of {land}, lowest {lowest_old}"
    );

    // Every gentle, dry vertex clearly above its sea-level line (moved by its aspect and
    // noise) is snow, and none clearly below it.
    let earth = new.earth.as_ref().expect("earth-1");
    let rule = new.texture.texel_rule();
    let blend = rule.blend_m;
    let (mut above, mut below) = (0, 0);
    for t in &tiles {
        let sea = tile_sea_snow_lines(earth, t.key, t.spacing_m);
        let shift = snow_shift(earth, t.key, t.spacing_m, &t.normals);
        assert_eq!(sea.len(), t.heights.len());
        for (v, &h) in t.heights.iter().enumerate() {
            let gentle = t.normals[v][1] > rule.rock_cos.0 + 0.01;
            if !gentle || h < 10.0 {
                continue;
            }
            let line = sea[v] + shift[v];
            let is_snow = t.materials[v] == material::SNOW;
            if h > line + blend + 0.5 {
                assert!(
                    is_snow,
                    "{:?} vertex {v}: {h} m above the line {line} m",
                    t.key
                );
                above += 1;
            } else if h < line - blend - 0.5 {
                assert!(
                    !is_snow,
                    "{:?} vertex {v}: {h} m below the line {line} m",
                    t.key
                );
                below += 1;
            }
        }
    }
    println!("{above} vertices clearly above their line, {below} clearly below");
    assert!(above > 0 && below > 10_000, "{above} above, {below} below");
}

#[test]
fn new_scenes_read_the_sea_level_snow_lines_and_stored_ones_keep_theirs() {
    let scene = strata::scene::Scene::default().to_value();
    assert_eq!(scene["world"]["earth"]["snow_lines"], 2);
    let mut stored = scene.clone();
    stored["world"]["earth"]
        .as_object_mut()
        .expect("earth settings")
        .remove("snow_lines");
    let parsed = strata::scene::Scene::from_value(&stored).expect("a stored scene reads");
    assert_eq!(parsed.to_value()["world"]["earth"].get("snow_lines"), None);
    for bad in [
        serde_json::json!(0),
        serde_json::json!(3),
        serde_json::json!("2"),
    ] {
        let mut s = scene.clone();
        s["world"]["earth"]["snow_lines"] = bad.clone();
        let err = strata::scene::Scene::from_value(&s).expect_err("refused");
        assert!(format!("{err:?}").contains("snow_lines"), "{bad}: {err:?}");
    }
}
