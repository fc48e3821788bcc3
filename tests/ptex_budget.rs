//! The Ptex level-of-detail budget (`strata::ptex::budget`, Becher §4.7): over a scripted
//! fly-through the pages held never exceed the budget, the vista level stays complete, the
//! nearest faces in view hold the highest levels, the bake lists keep a client's replica of the
//! slots exact, and an edit re-bakes only the faces it touched.

use strata::ptex::budget::{
    distance_in_view, page_bytes, Bake, Budget, BudgetConfig, FaceBounds, View, LEVEL_RES,
};

/// A ground of `n × n` faces of 16 m (a height tile's faces at LOD 0).
fn ground(n: usize) -> Vec<FaceBounds> {
    (0..n * n)
        .map(|i| FaceBounds {
            centre: [
                (i % n) as f32 * 16.0 + 8.0,
                ((i / 7) % 5) as f32,
                (i / n) as f32 * 16.0 + 8.0,
            ],
            radius: 11.4,
        })
        .collect()
}

/// View `t` of a fly-through: a loop over the ground at 40 m, looking ahead and down.
fn view(t: usize, n: usize) -> View {
    let side = n as f32 * 16.0;
    let a = t as f32 * 0.07;
    let eye = [
        side * (0.5 + 0.3 * a.cos()),
        40.0,
        side * (0.5 + 0.3 * a.sin()),
    ];
    let (dx, dz) = (-a.sin(), a.cos());
    let f = [dx * 0.94, -0.34, dz * 0.94];
    let l = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
    View {
        eye,
        forward: f.map(|c| c / l),
        cos_half_angle: 0.8,
        far_m: 2500.0,
    }
}

fn config(faces: usize) -> BudgetConfig {
    BudgetConfig {
        bytes: faces as u64 * page_bytes(8) + (48 << 20),
        thresholds_m: [2000.0, 900.0, 400.0, 160.0, 60.0],
    }
}

#[test]
fn a_fly_through_stays_within_the_budget_with_the_nearest_faces_highest() {
    let n = 120;
    let faces = ground(n);
    let cfg = config(faces.len());
    let mut budget = Budget::new(cfg, faces.len()).expect("the vista level fits");
    let vista = budget.vista();
    assert_eq!(vista.len(), faces.len(), "every face has a vista page");
    assert!(
        budget.capacity().iter().all(|&c| c > 0),
        "{:?}",
        budget.capacity()
    );
    // The client's replica: which face each slot of each detail level holds.
    let mut replica: Vec<Vec<Option<u32>>> =
        budget.capacity().iter().map(|&c| vec![None; c]).collect();
    let mut total_bakes = 0;
    let mut top_seen = 0;
    for t in 0..90 {
        let v = view(t, n);
        let changed = budget.update(&faces, &v);
        let bakes = changed.bake;
        total_bakes += bakes.len();
        for f in &changed.to_vista {
            assert_eq!(budget.level(*f as usize), 0);
            for level in replica.iter_mut() {
                for s in level.iter_mut() {
                    if *s == Some(*f) {
                        *s = None;
                    }
                }
            }
        }
        assert!(
            bakes.iter().all(|b| b.level > 0),
            "vista pages are never re-baked by a view"
        );
        for b in &bakes {
            // Whatever the slot held before is replaced; the face leaves its old slot.
            for level in replica.iter_mut() {
                for s in level.iter_mut() {
                    if *s == Some(b.face) {
                        *s = None;
                    }
                }
            }
            replica[b.level as usize - 1][b.slot as usize] = Some(b.face);
        }
        assert!(
            budget.bytes_held() <= cfg.bytes,
            "view {t}: {} > {}",
            budget.bytes_held(),
            cfg.bytes
        );
        // Levels by distance: among faces in view, a nearer one never has a lower level; faces
        // out of view hold only the vista page; thresholds hold.
        let mut visible: Vec<(f32, usize)> = Vec::new();
        for (f, b) in faces.iter().enumerate() {
            match distance_in_view(b, &v) {
                Some(d) => visible.push((d, f)),
                None => assert_eq!(budget.level(f), 0, "view {t}: face {f} out of view"),
            }
        }
        visible.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for w in visible.windows(2) {
            assert!(
                budget.level(w[0].1) >= budget.level(w[1].1),
                "view {t}: {w:?}"
            );
        }
        for &(d, f) in &visible {
            let l = budget.level(f);
            if l > 0 {
                assert!(
                    d <= cfg.thresholds_m[l as usize - 1],
                    "view {t}: face {f} at {d} m, level {l}"
                );
            }
            top_seen = top_seen.max(l);
        }
        // The replica holds exactly the faces at detail levels, each once.
        for f in 0..faces.len() {
            let l = budget.level(f) as usize;
            let held: usize = replica
                .iter()
                .flatten()
                .filter(|s| **s == Some(f as u32))
                .count();
            assert_eq!(held, usize::from(l > 0), "view {t}: face {f}");
            if l > 0 {
                assert!(
                    replica[l - 1].contains(&Some(f as u32)),
                    "view {t}: face {f} level {l}"
                );
            }
        }
        // A level's slots are used when enough faces are near enough: the nearest face in view
        // (within the top threshold) holds the top level.
        if let Some(&(d, f)) = visible.first() {
            if d <= cfg.thresholds_m[4] {
                assert_eq!(
                    usize::from(budget.level(f)),
                    LEVEL_RES.len() - 1,
                    "view {t}"
                );
            }
        }
    }
    assert_eq!(top_seen, 5, "the fly-through reaches the 256² level");
    assert!(total_bakes > 0);
    // The same views give the same bakes.
    let mut again = Budget::new(cfg, faces.len()).expect("fits");
    let mut first = Budget::new(cfg, faces.len()).expect("fits");
    for t in 0..10 {
        assert_eq!(
            first.update(&faces, &view(t, n)),
            again.update(&faces, &view(t, n))
        );
    }
}

#[test]
fn an_edit_rebakes_only_the_touched_faces_and_an_oversized_vista_is_refused() {
    let n = 40;
    let faces = ground(n);
    let cfg = config(faces.len());
    let mut budget = Budget::new(cfg, faces.len()).expect("fits");
    budget.update(&faces, &view(0, n));
    let near = (0..faces.len())
        .find(|&f| budget.level(f) > 0)
        .expect("a face at a detail level") as u32;
    let far = (0..faces.len())
        .find(|&f| budget.level(f) == 0)
        .expect("a face at the vista level") as u32;
    let mut got = budget.invalidate(&[near, far]);
    got.sort();
    let mut want = vec![
        Bake {
            face: near,
            level: 0,
            slot: near,
        },
        Bake {
            face: far,
            level: 0,
            slot: far,
        },
    ];
    let level = budget.level(near as usize);
    let unchanged = budget.update(&faces, &view(0, n));
    assert_eq!(
        unchanged,
        Default::default(),
        "an unchanged view bakes nothing"
    );
    let detail = budget.invalidate(&[near]);
    want.push(
        *detail
            .iter()
            .find(|b| b.level == level)
            .expect("the detail page"),
    );
    want.sort();
    assert_eq!(got, want);
    assert!(Budget::new(BudgetConfig { bytes: 1000, ..cfg }, faces.len()).is_err());
}

#[test]
fn held_faces_come_and_go_within_the_budget_and_evicted_slots_are_announced() {
    let n = 40;
    let faces = ground(n);
    // Room for the vista pages of every face and a few slots of each detail level.
    let cfg = BudgetConfig {
        bytes: faces.len() as u64 * page_bytes(8) + 12 * page_bytes(256),
        thresholds_m: [2000.0, 900.0, 400.0, 160.0, 60.0],
    };
    let mut budget = Budget::new(cfg, 0).expect("no faces fit");
    assert_eq!(budget.held(), 0);
    // Hold the half of the faces ahead of the first view: the detail levels share what their
    // vista pages leave.
    let half = faces.len() / 2;
    for f in half..faces.len() {
        budget.hold(f).expect("fits");
    }
    let few = budget.capacity();
    budget.update(&faces, &view(0, n));
    assert!(budget.bytes_held() <= cfg.bytes);
    let detailed: Vec<usize> = (0..faces.len()).filter(|&f| budget.level(f) > 0).collect();
    assert!(!detailed.is_empty(), "near faces hold detail pages");
    assert!(
        detailed.iter().all(|&f| f >= half),
        "faces not held are not classified"
    );
    // Holding every face shrinks the detail levels; the faces in slots that went away are
    // back at the vista level and listed by the next update.
    for f in 0..faces.len() {
        budget.hold(f).expect("the vista level of every face fits");
    }
    let many = budget.capacity();
    assert!(many.iter().zip(few).all(|(m, f)| *m <= f) && many != few);
    assert!(budget.bytes_held() <= cfg.bytes);
    let next = budget.update(&faces, &view(0, n));
    for f in &detailed {
        if budget.level(*f) == 0 {
            assert!(
                next.to_vista.contains(&(*f as u32)),
                "face {f} lost its slot"
            );
        }
    }
    // Releasing a face frees its slot; a released face is not classified or re-baked.
    let top = (0..faces.len())
        .find(|&f| budget.level(f) > 0)
        .expect("a face at a detail level");
    budget.release(top);
    assert!(!budget.is_held(top) && budget.level(top) == 0);
    assert!(budget.invalidate(&[top as u32]).is_empty());
    budget.update(&faces, &view(0, n));
    assert_eq!(budget.level(top), 0);
    // More faces than the vista level holds are refused.
    let full = faces.len() as u64 * page_bytes(8);
    let mut tight = Budget::new(BudgetConfig { bytes: full, ..cfg }, 0).expect("fits");
    for f in 0..faces.len() {
        tight.hold(f).expect("exactly fits");
    }
    assert!(tight.hold(faces.len()).is_err());
}

/// A face held up to a level (a volume chunk's quad, held up to 16²) never holds a finer one:
/// the next nearest faces take the finer levels' slots, and it takes a slot of its highest level
/// when its distance allows; without the cap the same face takes the finest slot.
#[test]
fn a_face_held_up_to_a_level_leaves_the_finer_slots_to_the_next_nearest() {
    let view = View {
        eye: [0.0, 10.0, 0.0],
        forward: [1.0, 0.0, 0.0],
        cos_half_angle: 0.5,
        far_m: 5000.0,
    };
    // Faces in a row ahead of the eye, face 0 nearest.
    let faces: Vec<FaceBounds> = (0..40)
        .map(|i| FaceBounds {
            centre: [20.0 + 10.0 * i as f32, 10.0, 0.0],
            radius: 1.0,
        })
        .collect();
    let cfg = BudgetConfig {
        // Every face's vista page and exactly one slot at the finest level.
        bytes: faces.len() as u64 * page_bytes(8) + 5 * page_bytes(256),
        thresholds_m: [4000.0, 3000.0, 2000.0, 1000.0, 500.0],
    };
    let run = |cap: u8| {
        let mut b = Budget::empty(cfg);
        b.hold_up_to(0, cap).expect("fits");
        for f in 1..faces.len() {
            b.hold(f).expect("fits");
        }
        b.update(&faces, &view);
        b
    };
    let free = run(5);
    assert_eq!(free.capacity()[4], 1, "one 256² slot");
    assert_eq!(
        free.level(0),
        5,
        "uncapped, the nearest face takes the finest slot"
    );
    let capped = run(1);
    assert_eq!(
        capped.level(0),
        1,
        "capped at 16², the nearest face holds 16²"
    );
    assert_eq!(capped.level(1), 5, "the next nearest takes the finest slot");
    for f in 0..faces.len() {
        assert!(capped.level(f) <= if f == 0 { 1 } else { 5 });
    }
    // The other faces hold what they held without the cap, one place nearer.
    let levels = |b: &Budget| (1..faces.len()).map(|f| b.level(f)).collect::<Vec<_>>();
    let shifted: Vec<u8> = (0..faces.len() - 1).map(|f| free.level(f)).collect();
    assert_eq!(levels(&capped), shifted);
}
