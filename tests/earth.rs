//! Properties of the `earth-1` generator (the default world): LOD consistency within the stated
//! bound, biome weights that do not depend on the LOD, and an elevation distribution with
//! mountains, lowlands and deep oceans near the origin.

use strata::terrain::earth;
use strata::terrain::{FieldJob, WorldParams, WorldPlan};

fn plan() -> WorldPlan {
    WorldPlan::new(42, WorldParams::default()).expect("the default world is valid")
}

/// Height and weights of one lattice sample `(gx, gz)` of `lod` (a 1×1 field job: every value is
/// a function of the sample's world position, so this is the tile vertex's value).
fn sample(p: &WorldPlan, lod: u32, gx: i64, gz: i64) -> (f32, Vec<f32>) {
    let e = p.earth.as_ref().expect("an earth-1 plan");
    let f = earth::field(
        e,
        p.lods[lod as usize].spacing_m,
        FieldJob::new(lod, gx, gz, 1, 1),
    );
    (f.heights[0], f.weights)
}

#[test]
fn a_vertex_moves_between_lods_by_at_most_the_stated_bound() {
    let p = plan();
    // World points on every LOD's lattice: mountains near (110 km, 0), plains at the origin,
    // the far east and negative coordinates.
    let centres: [(i64, i64); 4] = [
        (110_592, 0),
        (0, 0),
        (620_544, 309_248),
        (-120_832, -40_960),
    ];
    let mut worst = 0.0f32;
    for lod in [1u32, 3, 6, 9, 12] {
        let step = 1i64 << lod;
        let bound = p.lod_error_bound_m(lod);
        assert!(
            bound.is_finite() && bound >= 0.0,
            "bound {bound} at LOD {lod}"
        );
        for (cx, cz) in centres {
            for k in 0..25i64 {
                // Lattice points of LOD `lod` spread over ~40 samples of it.
                let (i, j) = (cx / step + 7 * (k % 5) - 14, cz / step + 9 * (k / 5) - 18);
                let (coarse, wc) = sample(&p, lod, i, j);
                let (fine, wf) = sample(&p, 0, i * step, j * step);
                let d = (coarse - fine).abs();
                assert!(
                    d <= bound,
                    "LOD {lod} at ({}, {}) m: |Δh| {d} m above the bound {bound} m",
                    i * step,
                    j * step
                );
                worst = worst.max(d / bound.max(1e-6));
                // The climate lattice is fixed in world metres: the same weights bit for bit.
                assert_eq!(
                    wc.iter().map(|w| w.to_bits()).collect::<Vec<_>>(),
                    wf.iter().map(|w| w.to_bits()).collect::<Vec<_>>(),
                    "weights at LOD {lod} and 0 differ at ({}, {}) m",
                    i * step,
                    j * step
                );
            }
        }
    }
    // The bound is not vacuous: some vertex uses a good part of it.
    assert!(worst > 0.01, "largest |Δh| ÷ bound {worst}");
}

#[test]
fn the_region_around_the_origin_has_peaks_lowlands_and_deep_ocean() {
    let p = plan();
    // 400 km × 400 km around the origin at LOD 10 (1 024 m spacing).
    let lod = 10u32;
    let n = 391usize;
    let half = (n / 2) as i64;
    let e = p.earth.as_ref().expect("an earth-1 plan");
    let f = earth::field(
        e,
        p.lods[lod as usize].spacing_m,
        FieldJob::new(lod, -half, -half, n, n),
    );
    let mut land: Vec<f32> = f.heights.iter().copied().filter(|h| *h > 0.0).collect();
    land.sort_by(f32::total_cmp);
    let highest = land.last().copied().unwrap_or(0.0);
    let deepest = f.heights.iter().copied().fold(f32::INFINITY, f32::min);
    let median_land = land[land.len() / 2];
    let frac_land = land.len() as f64 / f.heights.len() as f64;
    assert!(highest >= 3000.0, "highest point {highest} m");
    assert!(deepest <= -3000.0, "deepest point {deepest} m");
    // Mostly lowlands: half the land below 600 m and at most a quarter above 1 500 m (Earth:
    // about a fifth).
    assert!(median_land < 600.0, "median land height {median_land} m");
    let high = land.iter().filter(|h| **h > 1500.0).count() as f64 / land.len() as f64;
    assert!(
        high < 0.25,
        "{:.1} % of the land above 1 500 m",
        high * 100.0
    );
    assert!((0.3..0.9).contains(&frac_land), "land fraction {frac_land}");
}

#[test]
fn the_erosion_filter_carves_the_mountains_and_nothing_else_changes() {
    // Same world without the gully layers: the heights differ where the relief is steep, and
    // the climate weights are untouched.
    let p = plan();
    let mut params = WorldParams::default();
    params.earth.as_mut().expect("earth settings").erosion = 0.0;
    let flat = WorldPlan::new(42, params).expect("valid");
    let job = FieldJob::new(6, 1720, -40, 32, 32);
    let (a, b) = (
        earth::field(p.earth.as_ref().expect("plan"), 64.0, job),
        earth::field(flat.earth.as_ref().expect("plan"), 64.0, job),
    );
    assert_eq!(a.weights, b.weights);
    let moved = a
        .heights
        .iter()
        .zip(&b.heights)
        .filter(|(x, y)| (*x - *y).abs() > 1.0)
        .count();
    assert!(moved > a.heights.len() / 2, "{moved} samples carved");
}

#[test]
fn snow_lies_lower_on_north_facing_slopes() {
    // Mountain tiles around (110 km, 0) at LOD 6, textured with and without the snow line's
    // aspect-and-noise shift: north-facing vertices (normal z < −0.2, the shift lowers their snow
    // line) only gain snow, south-facing ones (z > 0.2) only lose it, and both change somewhere.
    use strata::terrain::texture::proto_texture_batch;
    use strata::terrain::world::material;
    use strata::terrain::{synthesize, TileKey};
    // Without the alpine zone: it splits the ground below the snow line between rock and the
    // biomes' ground, so a vertex whose snow weight falls a little can still have snow as its
    // heaviest material, and the dominant material no longer follows the line's shift alone.
    let mut params = WorldParams::default();
    params.texturing.alpine_fraction = 0.0;
    let p = WorldPlan::new(42, params).expect("valid");
    let e = p.earth.as_ref().expect("an earth-1 plan");
    let (mut gained, mut lost) = (0usize, 0usize);
    for x in 16..36 {
        for z in -6..6 {
            let t = synthesize(&p, TileKey { lod: 6, x, z });
            let ny: Vec<f32> = t.normals.iter().map(|n| n[1]).collect();
            let shift = earth::snow_shift(e, t.key, t.spacing_m, &t.normals);
            // New worlds read the sea-level climate's line (`snow_lines: 2`): the plain
            // texturing reads it too, without aspect or noise.
            let sea = earth::tile_sea_snow_lines(e, t.key, t.spacing_m);
            let mut plain = vec![0u8; t.heights.len()];
            proto_texture_batch(
                &p.texture,
                &t.heights,
                &ny,
                &t.weights,
                &sea,
                &[],
                &mut plain,
            );
            for v in 0..t.heights.len() {
                let (was, is) = (plain[v] == material::SNOW, t.materials[v] == material::SNOW);
                let nz = t.normals[v][2];
                if nz < -0.2 && shift[v] < 0.0 {
                    assert!(is || !was, "a north-facing vertex lost its snow");
                    gained += (is && !was) as usize;
                }
                if nz > 0.2 && shift[v] > 0.0 {
                    assert!(was || !is, "a south-facing vertex gained snow");
                    lost += (was && !is) as usize;
                }
            }
        }
    }
    assert!(gained > 50 && lost > 50, "gained {gained}, lost {lost}");
}
