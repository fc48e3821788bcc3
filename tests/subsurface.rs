//! Issue 6's properties of the layered subsurface (`strata::subsurface`).

use strata::subsurface::plan::{border_distance, ElementKind};
use strata::subsurface::{ChunkKey, SubsurfaceConfig, SubsurfacePlan, PRESETS};

const SIZE: u32 = 10;

fn plans() -> Vec<SubsurfacePlan> {
    let mut out = Vec::new();
    for name in PRESETS {
        for seed in [1u64, 7, 0xdead_beef_0042] {
            out.push(SubsurfacePlan::new(
                seed,
                SubsurfaceConfig::preset(name).expect("preset"),
            ));
        }
    }
    out
}

fn keys() -> Vec<ChunkKey> {
    let mut keys = Vec::new();
    for y in -4..=0 {
        for z in -2..3 {
            for x in -2..3 {
                keys.push(ChunkKey { x, y, z });
            }
        }
    }
    keys
}

#[test]
fn concentrations_sum_to_one() {
    for plan in plans() {
        let mut comps: Vec<Vec<(u32, f32)>> =
            plan.layers.iter().map(|l| l.composition.clone()).collect();
        for kind in [ElementKind::Vein, ElementKind::Cave] {
            for c in -6..6 {
                if let Some(e) = plan.element(kind, (c, 2 * c)) {
                    comps.push(e.composition);
                }
            }
        }
        for comp in comps {
            let sum: f32 = comp.iter().map(|c| c.1).sum();
            assert!((sum - 1.0).abs() < 1e-5, "{comp:?}");
            if comp.len() > 1 {
                assert!((0.5..=0.9).contains(&comp[0].1), "main {comp:?}");
            }
        }
        let chunk = plan.chunk(ChunkKey { x: 1, y: -2, z: -1 }, SIZE);
        for j in 0..SIZE {
            let v = chunk.voxel(3, j, 4);
            let sum: f32 = v.iter().map(|c| c.1).sum();
            assert!((sum - 1.0).abs() < 1e-5, "{v:?}");
        }
    }
}

fn flags(plan: &SubsurfacePlan, id: u32) -> strata::subsurface::config::Flags {
    plan.config
        .materials
        .iter()
        .find(|m| m.id == id)
        .expect("material")
        .flags
}

#[test]
fn base_layer_at_the_bottom_and_incompatible_materials_never_adjacent() {
    // Preset B1 with incompatibilities: every odd pair is incompatible in the next layer, every
    // pair divisible by 3 in the same layer.
    for seed in 0..40u64 {
        let mut config = SubsurfaceConfig::preset("B1").expect("preset");
        for (n, a) in config.affinities.iter_mut().enumerate() {
            if n % 2 == 1 {
                a.next_layer = -1.0;
            }
            if n % 3 == 0 {
                a.same_layer = -1.0;
            }
        }
        config.validate().expect("valid");
        let plan = SubsurfacePlan::new(seed, config);
        assert!(plan
            .layers
            .first()
            .expect("a layer")
            .composition
            .iter()
            .all(|c| flags(&plan, c.0).base));
        for l in &plan.layers[1..] {
            assert!(l.composition.iter().all(|c| !flags(&plan, c.0).base));
        }
        for l in &plan.layers {
            for a in &l.composition {
                for b in &l.composition {
                    if a.0 != b.0 {
                        assert!(plan.affinity(a.0, b.0).0 >= 0.0, "same layer {a:?} {b:?}");
                    }
                }
            }
        }
        for w in plan.layers.windows(2) {
            for a in &w[0].composition {
                for b in &w[1].composition {
                    assert!(plan.affinity(a.0, b.0).1 >= 0.0, "next layer {a:?} {b:?}");
                }
            }
        }
        for c in -10..10 {
            if let Some(e) = plan.element(ElementKind::Vein, (c, -c)) {
                for a in &plan.layers[e.host].composition {
                    for b in &e.composition {
                        assert!(plan.affinity(a.0, b.0).1 >= 0.0, "vein {a:?} {b:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn voxel_queries_interpolate_the_stored_limits_and_match_the_direct_evaluation() {
    let (mut with_elements, mut blended) = (0, 0);
    for (plan, key) in plans().iter().flat_map(|p| {
        [(-1, -1, 2), (0, -2, 0), (1, -3, 1), (2, 0, -1)].map(|(x, y, z)| (p, ChunkKey { x, y, z }))
    }) {
        let chunk = plan.chunk(key, SIZE);
        with_elements += usize::from(chunk.palette.len() > plan.layers.len() + 1);
        blended += usize::from(chunk.limits.iter().any(|l| l.mix.lo != l.mix.hi));
        let mut limits = 0;
        for k in 0..SIZE {
            for i in 0..SIZE {
                let col = chunk.column(i, k);
                limits += col.len();
                assert_eq!(col.first().expect("bottom").y, 0);
                assert_eq!(u32::from(col.last().expect("top").y), SIZE - 1);
                assert!(col.len() >= 2 && col.len() <= SIZE as usize);
                for w in col.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    let ca = chunk.voxel(i, a.y.into(), k);
                    let cb = chunk.voxel(i, b.y.into(), k);
                    for j in a.y..=b.y {
                        let f = f32::from(j - a.y) / f32::from(b.y - a.y);
                        let v = chunk.voxel(i, j.into(), k);
                        let mut ids: Vec<u32> =
                            ca.iter().chain(&cb).chain(&v).map(|c| c.0).collect();
                        ids.sort();
                        ids.dedup();
                        let get = |c: &Vec<(u32, f32)>, id| {
                            c.iter().find(|e| e.0 == id).map_or(0.0, |e| e.1)
                        };
                        for id in ids {
                            let want = get(&ca, id) * (1.0 - f) + get(&cb, id) * f;
                            assert!((get(&v, id) - want).abs() < 1e-5, "interpolation");
                        }
                    }
                }
                for j in 0..SIZE {
                    let (x, y, z) = (
                        key.x * SIZE as i32 + i as i32,
                        key.y * SIZE as i32 + j as i32,
                        key.z * SIZE as i32 + k as i32,
                    );
                    let (direct, flow) = plan.voxel(x, y, z);
                    let stored = chunk.voxel(i, j, k);
                    let stored_flow = chunk.flow(i, j, k);
                    for c in 0..3 {
                        assert!(
                            (flow[c] - stored_flow[c]).abs() < 1e-4,
                            "flow {flow:?} vs {stored_flow:?}"
                        );
                    }
                    let norm = flow.iter().map(|c| c * c).sum::<f32>().sqrt();
                    let solid = !direct.iter().any(|c| c.0 == plan.void_id);
                    if solid && direct.len() == 1 {
                        assert!((norm - 1.0).abs() < 1e-4, "unit flow {flow:?}");
                    }
                    assert_eq!(
                        direct.iter().map(|c| c.0).collect::<Vec<_>>(),
                        stored
                            .iter()
                            .filter(|c| c.1 > 1e-5)
                            .map(|c| c.0)
                            .collect::<Vec<_>>(),
                        "materials at {x},{y},{z}"
                    );
                    for (d, s) in direct.iter().zip(stored.iter().filter(|c| c.1 > 1e-5)) {
                        assert!((d.1 - s.1).abs() < 1e-4, "{direct:?} vs {stored:?}");
                    }
                }
            }
        }
        assert!(limits < chunk.voxel_count());
    }
    assert!(
        with_elements > 10 && blended > 10,
        "{with_elements} {blended}"
    );
}

#[test]
fn veins_and_caves_lie_inside_their_bounding_squares() {
    let mut seen = 0;
    for plan in plans() {
        for kind in [ElementKind::Vein, ElementKind::Cave] {
            let side = plan.cell_side(kind);
            for c in -8..8 {
                let cell = (c, 3 - c);
                let Some(e) = plan.element(kind, cell) else {
                    continue;
                };
                seen += 1;
                assert_eq!(e.outline.len(), 128);
                assert!(e
                    .outline
                    .iter()
                    .all(|p| (0.0..=1.0).contains(&p.0) && (0.0..=1.0).contains(&p.1)));
                assert!(
                    e.origin.0 >= cell.0 as f32 * side
                        && e.origin.0 + e.side <= (cell.0 + 1) as f32 * side + 1e-3
                );
                assert!(
                    e.origin.1 >= cell.1 as f32 * side
                        && e.origin.1 + e.side <= (cell.1 + 1) as f32 * side + 1e-3
                );
                assert!(border_distance(&e.outline, 0.5, 0.5) > 0.0);
                // Every point with height lies in the square, and heights are within Eq. 6's range.
                let mut inside = 0;
                for k in -4..(e.side as i32 + 4) {
                    for i in -4..(e.side as i32 + 4) {
                        let (x, z) = (e.origin.0 + i as f32 + 0.5, e.origin.1 + k as f32 + 0.5);
                        if let Some(h) = e.height_at(x, z) {
                            inside += 1;
                            assert!(x >= e.origin.0 && x <= e.origin.0 + e.side);
                            assert!(z >= e.origin.1 && z <= e.origin.1 + e.side);
                            assert!(h >= 0.0 && h <= e.height + 1e-4);
                        }
                    }
                }
                assert!(inside > 0 || e.side < 3.0, "empty element {e:?}");
            }
        }
    }
    assert!(seen > 20, "only {seen} elements");
}

#[test]
fn chunks_are_identical_in_any_order_and_on_any_thread() {
    let plan = SubsurfacePlan::new(99, SubsurfaceConfig::preset("B3").expect("preset"));
    let keys = keys();
    let reference: Vec<Vec<u8>> = keys
        .iter()
        .map(|k| plan.chunk(*k, SIZE).to_bytes())
        .collect();
    // Shuffled orders (a fixed permutation per round), each chunk from a fresh plan.
    for round in 1..4u64 {
        let fresh = SubsurfacePlan::new(99, SubsurfaceConfig::preset("B3").expect("preset"));
        let mut order: Vec<usize> = (0..keys.len()).collect();
        order.sort_by_key(|&i| strata::terrain::hash::hash2(i as i32, round as i32, 5));
        for i in order {
            assert_eq!(
                fresh.chunk(keys[i], SIZE).to_bytes(),
                reference[i],
                "{:?}",
                keys[i]
            );
        }
    }
    for threads in [2usize, 3] {
        let results: Vec<(usize, Vec<u8>)> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..threads)
                .map(|t| {
                    let (plan, keys) = (&plan, &keys);
                    s.spawn(move || {
                        (t..keys.len())
                            .step_by(threads)
                            .rev()
                            .map(|i| (i, plan.chunk(keys[i], SIZE).to_bytes()))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().expect("thread"))
                .collect()
        });
        assert_eq!(results.len(), keys.len());
        for (i, bytes) in results {
            assert_eq!(bytes, reference[i]);
        }
    }
}

#[test]
fn presets_generate_layers_veins_and_caves() {
    for name in PRESETS {
        let plan = SubsurfacePlan::new(3, SubsurfaceConfig::preset(name).expect("preset"));
        assert!(
            plan.layers.len() >= 2,
            "{name}: {} layers",
            plan.layers.len()
        );
        let g = plan.config.general;
        let count = |kind| {
            (0..100)
                .filter(|c| plan.element(kind, (c % 10, c / 10)).is_some())
                .count()
        };
        let veins = count(ElementKind::Vein);
        let caves = count(ElementKind::Cave);
        assert_eq!(
            veins == 0,
            g.vein_density == 0.0 || !name.ends_with(['1', '3']),
            "{name} veins {veins}"
        );
        assert_eq!(
            caves == 0,
            !name.ends_with(['2', '3']),
            "{name} caves {caves}"
        );
    }
}

/// Every key a preset serialises is declared by `api/subsurface.schema.json`, and every key the
/// schema requires is serialised (a light consistency check; CI has no JSON Schema validator).
#[test]
fn schema_declares_the_configuration_fields() {
    let schema: serde_json::Value =
        serde_json::from_str(include_str!("../api/subsurface.schema.json")).expect("schema");
    fn resolve<'a>(
        schema: &'a serde_json::Value,
        node: &'a serde_json::Value,
    ) -> &'a serde_json::Value {
        match node.get("$ref").and_then(|r| r.as_str()) {
            Some(r) => resolve(schema, &schema["$defs"][r.trim_start_matches("#/$defs/")]),
            None => node,
        }
    }
    fn check(
        schema: &serde_json::Value,
        node: &serde_json::Value,
        value: &serde_json::Value,
        path: &str,
    ) {
        let node = resolve(schema, node);
        match value {
            serde_json::Value::Object(map) => {
                let props = node["properties"]
                    .as_object()
                    .unwrap_or_else(|| panic!("{path}: no properties"));
                for (k, v) in map {
                    let p = props
                        .get(k)
                        .unwrap_or_else(|| panic!("{path}/{k} not in the schema"));
                    check(schema, p, v, &format!("{path}/{k}"));
                }
                for r in node["required"].as_array().into_iter().flatten() {
                    assert!(
                        map.contains_key(r.as_str().expect("name")),
                        "{path}/{r} required"
                    );
                }
            }
            serde_json::Value::Array(items) if node.get("items").is_some_and(|i| i.is_object()) => {
                for (i, v) in items.iter().enumerate() {
                    check(schema, &node["items"], v, &format!("{path}/{i}"));
                }
            }
            _ => {}
        }
    }
    for name in PRESETS {
        let value =
            serde_json::to_value(SubsurfaceConfig::preset(name).expect("preset")).expect("json");
        check(&schema, &schema, &value, "");
    }
}

/// `src/subsurface` is pure like `src/terrain` (ARCHITECTURE.md): no tokio, axum or wgpu, no
/// server, device or compute front door, and no randomness besides `terrain::hash`.
#[test]
fn subsurface_is_pure() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/subsurface");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).expect("src/subsurface") {
        let path = entry.expect("entry").path();
        let text = std::fs::read_to_string(&path).expect("readable");
        n += 1;
        for banned in [
            "tokio::",
            "axum::",
            "wgpu::",
            "crate::server",
            "crate::gpu",
            "crate::compute",
            "getrandom",
            "rand::",
            "HashMap",
            "SystemTime",
        ] {
            assert!(
                !text.contains(banned),
                "{} mentions {banned}",
                path.display()
            );
        }
    }
    assert!(n >= 4);
}
