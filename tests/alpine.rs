//! The alpine zone (`world.texturing.alpine_fraction`, `strata::terrain::texture`): above the
//! tree line bare rock and scree take over the ground below the snow line.
//!
//! - In new worlds (`0.25`) the range 160 km from the origin turns to rock on its upper slopes:
//!   every vertex whose material the zone changes becomes rock and lies inside the band (from
//!   `(1 − a)·L` to the snow line, `L` the line's height above the sea), every gentle, dry vertex
//!   in the band's upper quarter is rock, and nothing below the band changes;
//! - a stored world's document without `alpine_fraction` reads as 0 (no zone: its materials
//!   and pages keep their bytes, `tests/rivers_world.rs`), new scenes write 0.25, and values out
//!   of `[0, 0.9]` are refused naming the field.
//!
//! The WGSL twin of the texel weights is compared with the CPU's on a tile the band crosses in
//! `tests/gpu_ptex.rs`.

use strata::terrain::earth::{snow_shift, tile_sea_snow_lines};
use strata::terrain::texture::alpine_share;
use strata::terrain::world::material;
use strata::terrain::{WorldParams, WorldPlan};

mod common;
use common::range::range_tiles;

const SEED: u64 = 42;

fn plan(alpine_fraction: f32) -> WorldPlan {
    let mut params = WorldParams::default();
    params.texturing.alpine_fraction = alpine_fraction;
    WorldPlan::new(SEED, params).expect("default world")
}

#[test]
fn the_range_turns_to_rock_between_its_tree_line_and_its_snow() {
    let default = WorldParams::default().texturing.alpine_fraction;
    assert_eq!(default, 0.25, "new worlds' alpine zone");
    let (new, bare) = (plan(default), plan(0.0));
    let earth = new.earth.as_ref().expect("earth-1");
    let rule = new.texture.texel_rule();
    let (blend, sea_level) = (rule.blend_m, new.params.sea_level_m);
    let (mut changed, mut upper, mut below) = (0, 0, 0);
    for (t, b) in range_tiles(&new).iter().zip(range_tiles(&bare)) {
        // The zone is the texturing's alone: the same heights.
        assert_eq!(t.heights, b.heights, "{:?}", t.key);
        let sea = tile_sea_snow_lines(earth, t.key, t.spacing_m);
        let shift = snow_shift(earth, t.key, t.spacing_m, &t.normals);
        for (v, &h) in t.heights.iter().enumerate() {
            let line = sea[v] + shift[v];
            let band = default * (line - sea_level).max(0.0);
            let (m, m0) = (t.materials[v], b.materials[v]);
            if m != m0 {
                assert_eq!(m, material::ROCK, "{:?} vertex {v} at {h} m", t.key);
                assert!(
                    h > line - band && alpine_share(default, line - sea_level, h - line) > 0.0,
                    "{:?} vertex {v}: {h} m is below the band from {} m",
                    t.key,
                    line - band
                );
                changed += 1;
            }
            let gentle = t.normals[v][1] > rule.rock_cos.0 + 0.01;
            if gentle && h > 10.0 && h > line - band / 4.0 + 0.5 && h < line - blend - 0.5 {
                assert_eq!(m, material::ROCK, "{:?} vertex {v} at {h} m", t.key);
                upper += 1;
            }
            if h > 10.0 && h < line - band - 0.5 {
                below += 1;
            }
        }
    }
    println!(
        "{changed} vertices turned to rock, {upper} gentle vertices in the band's upper quarter, {below} below the band"
    );
    assert!(changed > 2_000, "{changed} vertices changed");
    assert!(upper > 100, "{upper} vertices in the band's upper quarter");
    assert!(below > 10_000, "{below} vertices below the band");
}

#[test]
fn new_scenes_write_the_alpine_zone_and_stored_ones_have_none() {
    let scene = strata::scene::Scene::default().to_value();
    assert_eq!(scene["world"]["texturing"]["alpine_fraction"], 0.25);
    let mut stored = scene.clone();
    stored["world"]["texturing"]
        .as_object_mut()
        .expect("texturing settings")
        .remove("alpine_fraction");
    let parsed = strata::scene::Scene::from_value(&stored).expect("a stored scene reads");
    assert_eq!(
        parsed.to_value()["world"]["texturing"].get("alpine_fraction"),
        None
    );
    for bad in [
        serde_json::json!(-0.1),
        serde_json::json!(0.95),
        serde_json::json!("0.3"),
    ] {
        let mut s = scene.clone();
        s["world"]["texturing"]["alpine_fraction"] = bad.clone();
        let err = strata::scene::Scene::from_value(&s).expect_err("refused");
        assert!(
            format!("{err:?}").contains("alpine_fraction"),
            "{bad}: {err:?}"
        );
    }
}
