//! The lattice split of `earth-1` (`terrain::earth::lattice`): the interpolated large-scale part
//! (from the 16 m lattice, whose nodes read the 256 m one, and from the 256 m lattice alone at
//! LODs 4–7) matches evaluating every layer at every sample to within a stated bound, and every
//! tile that holds a vertex gives it the same bits.

use strata::terrain::earth::{self, lattice};
use strata::terrain::{FieldJob, WorldParams, WorldPlan};

fn plans(seed: u64) -> (WorldPlan, WorldPlan) {
    let split = WorldPlan::new(seed, WorldParams::default()).expect("plan");
    let mut p = WorldParams::default();
    let e = p.earth.as_mut().expect("earth");
    (e.lattice_cells, e.coarse_lattice_cells) = (None, None);
    (split, WorldPlan::new(seed, p).expect("plan"))
}

/// Heights of a field job without the river carve (the carve is the same function of the
/// height in both plans; it is left out so the comparison sees the split alone).
fn heights(plan: &WorldPlan, job: FieldJob) -> Vec<f32> {
    let mut e = plan.earth.clone().expect("earth");
    e.rivers = None;
    earth::field(&e, plan.lods[job.lod as usize].spacing_m, job).heights
}

#[test]
fn new_worlds_split_the_fine_lods_and_stored_ones_do_not() {
    let (split, direct) = plans(7);
    let e = split.earth.as_ref().expect("earth");
    // LODs 0–3: the 16 m lattice, its nodes reading the 256 m lattice's macro fields and two
    // longest layers.
    for lod in 0..=3 {
        let lat = e.lods[lod]
            .lattice
            .expect("LODs finer than the lattice split");
        assert_eq!(lat.step, 16 >> lod);
        assert!(lat.prefix >= 6, "LOD {lod}: prefix {}", lat.prefix);
        let outer = lat.outer.expect("the coarse lattice above the fine one");
        assert_eq!((outer.step, outer.prefix), (256 >> lod, 2), "LOD {lod}");
    }
    // LODs 4–7 (16 to 128 m): the 256 m lattice alone.
    for lod in 4..=7 {
        let lat = e.lods[lod]
            .lattice
            .expect("LODs finer than the coarse lattice");
        assert_eq!(
            (lat.step, lat.prefix, lat.outer),
            (256 >> lod, 2, None),
            "LOD {lod}"
        );
    }
    assert!(e.lods[8..].iter().all(|l| l.lattice.is_none()));
    let d = direct.earth.as_ref().expect("earth");
    assert!(d.lods.iter().all(|l| l.lattice.is_none()));
    // A world stored with the 16 m lattice and before the coarse one (the default of new worlds
    // until then, with every gully octave: tests/rivers_world.rs serves one) splits LODs 0–3 as
    // it did.
    let mut p = WorldParams::default();
    let earth = p.earth.as_mut().expect("earth");
    (earth.coarse_lattice_cells, earth.gully_first) = (None, 0);
    let fine = WorldPlan::new(7, p).expect("plan");
    let f = fine.earth.as_ref().expect("earth");
    for (lod, l) in f.lods.iter().enumerate() {
        let expected = (lod <= 3).then_some((16 >> lod, 13));
        assert_eq!(
            l.lattice.map(|lat| (lat.step, lat.prefix)),
            expected,
            "LOD {lod}"
        );
        assert!(l.lattice.is_none_or(|lat| lat.outer.is_none()));
    }
}

#[test]
fn the_split_matches_the_direct_sum_within_its_bound() {
    let (split, direct) = plans(42);
    // Plains near the origin, mountains far out, negative coordinates.
    let (mut worst, mut p99_worst) = (0.0f32, 0.0f32);
    for (lod, x, z) in [
        (0u32, -40, 20),
        (0, 1700, -20),
        (0, -3000, -7000),
        (2, 90, -300),
        (3, -8, -8),
        (5, -3, 2),
        (7, 3, -1),
    ] {
        let job = FieldJob::new(lod, x * 64 - 1, z * 64 - 1, 67, 67);
        let (a, b) = (heights(&split, job), heights(&direct, job));
        let relief = a.iter().fold(0.0f32, |m, h| m.max((h - a[0]).abs()));
        assert!(relief > 1.0, "a flat job tests nothing");
        let mut d: Vec<f32> = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).collect();
        d.sort_by(f32::total_cmp);
        worst = worst.max(d[d.len() - 1]);
        p99_worst = p99_worst.max(d[d.len() * 99 / 100]);
    }
    // Smooth layers with twelve nodes a wavelength come within 0.2 % of their amplitude. The
    // gully stripes turn sharply around the points where their blended phasor vanishes, and
    // there the interpolation rounds them off by up to a few metres (measured: p99 0.8 m, the
    // largest 3.3 m, in a 512 m tile with 16 m of relief at LOD 3). The 256 m lattice holds the
    // macro fields and the two longest layers, forty nodes a wavelength and more: at LODs 5 and
    // 7, in tiles of 113 and 213 m relief, p99 0.04 and 0.01 m, the largest 0.4 and 0.14 m.
    assert!(
        p99_worst < 1.0,
        "99th percentile of the difference {p99_worst} m"
    );
    assert!(worst < 5.0, "largest difference {worst} m");
    assert!(worst > 0.0, "the split changed nothing: is it in use?");
}

#[test]
fn every_tile_gives_a_vertex_the_same_bits() {
    let (split, _) = plans(3);
    let e = split.earth.as_ref().expect("earth");
    // LOD 0 (two lattices) and LOD 5 (the coarse one alone): two overlapping jobs offset by a
    // non-multiple of the node steps.
    for lod in [0u32, 5] {
        let spacing = split.lods[lod as usize].spacing_m;
        let a = earth::field(e, spacing, FieldJob::new(lod, -37, 11, 67, 67)).heights;
        let b = earth::field(e, spacing, FieldJob::new(lod, -37 + 29, 11 + 45, 67, 67)).heights;
        for j in 0..(67 - 45) {
            for i in 0..(67 - 29) {
                let va = a[(j + 45) * 67 + i + 29];
                let vb = b[j * 67 + i];
                assert_eq!(
                    va.to_bits(),
                    vb.to_bits(),
                    "LOD {lod}: vertex ({i}, {j}) differs"
                );
            }
        }
    }
}

#[test]
fn a_vertex_on_a_node_takes_the_nodes_values() {
    assert_eq!(lattice::weights(0.0), [0.0, 1.0, 0.0, 0.0]);
    for t in [0.125f32, 0.25, 0.5, 0.875] {
        let w = lattice::weights(t);
        assert!(
            (w.iter().sum::<f32>() - 1.0).abs() < 1e-6,
            "weights at {t} sum to 1"
        );
    }
}

#[test]
fn new_scenes_use_lattices_of_16_and_256_cells_and_refuse_other_than_powers_of_two() {
    let scene = strata::scene::Scene::default().to_value();
    assert_eq!(scene["world"]["earth"]["lattice_cells"], 16);
    assert_eq!(scene["world"]["earth"]["coarse_lattice_cells"], 256);
    // A scene stored before a split existed has no field for it, and keeps evaluating those
    // layers where it did (its bytes: tests/earth1_world.rs, tests/rivers_world.rs).
    for field in ["lattice_cells", "coarse_lattice_cells"] {
        let mut stored = scene.clone();
        stored["world"]["earth"]
            .as_object_mut()
            .expect("earth settings")
            .remove(field);
        let parsed = strata::scene::Scene::from_value(&stored).expect("a stored scene reads");
        assert_eq!(parsed.to_value()["world"]["earth"].get(field), None);
    }
    for (field, bad) in [
        ("lattice_cells", serde_json::json!(12)),
        ("lattice_cells", serde_json::json!(1)),
        ("lattice_cells", serde_json::json!(512)),
        ("lattice_cells", serde_json::json!(-16)),
        ("lattice_cells", serde_json::json!(16.5)),
        ("coarse_lattice_cells", serde_json::json!(384)),
        ("coarse_lattice_cells", serde_json::json!(2)),
        ("coarse_lattice_cells", serde_json::json!(8192)),
        // Not coarser than twice the 16-cell lattice.
        ("coarse_lattice_cells", serde_json::json!(16)),
    ] {
        let mut s = scene.clone();
        s["world"]["earth"][field] = bad.clone();
        let err = strata::scene::Scene::from_value(&s).expect_err("refused");
        assert!(format!("{err:?}").contains(field), "{bad}: {err:?}");
    }
}
