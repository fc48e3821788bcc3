//! The WGSL twin of the Ptex bake (`shaders/ptex.wgsl`, `strata::gpu::ptex`) against the CPU
//! reference (`strata::ptex::bake_interior`) on a software adapter (lavapipe), for volume-quad
//! faces and height-tile faces at two resolutions. REQUIRES an adapter: without one the test
//! fails with instructions, it never skips.
//!
//! Tolerance (reason in `src/gpu/ptex.rs`: the lattice and hashes are exact, the float
//! arithmetic may differ by contraction and few-ULP `sqrt` and `/`): albedo and roughness bytes
//! within 1 step; normal bytes within 2 steps (the normal is a difference quotient over half a
//! texel, which multiplies a rounding difference of the displacement); the dominant material
//! identical; displacement within 1e-4 m + 1e-5·|d|. At most 2 % of the texels may differ at all,
//! so a systematic deviation fails. The test prints how many texels are bit-identical.
//!
//! It runs on a tile where the texels weigh their materials by the proto-texturing thresholds
//! at the texel (`texturing.ptex_blend: 2`, the twin's `surface_weights` and `surface_slots`),
//! on one where the alpine zone's band crosses the ground too (`alpine_share`), and with a
//! world's materials and decals (`strata::ptex::spec`): an image material with albedo,
//! roughness and height images and a normal map, a procedural override, and two decals (one masked by its alpha,
//! one by a separate mask image with roughness, fading with the facing), over both face sets, so the twin's image
//! sampling, mip levels and decal placement are checked too. On lavapipe both comparisons are
//! bit-identical (the image bilinear interpolates the bytes, whose differences are exact, and
//! scales once); the bounds above still apply to other adapters.

mod common;

use strata::gpu::ptex::bake_interior_on_device;
use strata::ptex::bake::texel_materials;
use strata::ptex::face::TileFacePlan;
use strata::ptex::{bake_interior, FaceSet, MaterialSet, Pages};
use strata::terrain::texture::alpine_share;
use strata::terrain::tile::{synthesize, TileKey};
use strata::terrain::world::WorldParams;
use strata::terrain::WorldPlan;
use strata::volume::mesh::{surface_nets, MeshOptions, QuadMesh, SampleAttributes};

fn quad_set(mats: &MaterialSet) -> FaceSet {
    let dims = [14usize, 12, 13];
    let mut sdf = Vec::new();
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                let (x, y, z) = (x as f32, y as f32, z as f32);
                sdf.push((x * 0.61).sin() + (y * 0.83 + z * 0.3).cos() + (z * 0.47).sin() - 0.2);
            }
        }
    }
    let mut mesh = QuadMesh::default();
    surface_nets(
        &sdf,
        SampleAttributes::default(),
        &MeshOptions::new(dims, 2.0),
        &mut mesh,
    )
    .expect("valid grid");
    mesh.materials = (0..mesh.vertex_count()).map(|v| (v % 7) as u8).collect();
    let world = |v: u32| -> [f64; 3] {
        let p = mesh.positions[v as usize];
        [
            f64::from(p[0]) - 300.0,
            f64::from(p[1]) + 40.0,
            f64::from(p[2]) + 9000.0,
        ]
    };
    strata::ptex::face::quad_faces(
        &strata::ptex::face::QuadSource {
            quads: &mesh.quads,
            adjacency: &mesh.adjacency,
            world: &world,
            normals: &mesh.normals,
            materials: &mesh.materials,
            spacing_m: 2.0,
        },
        mats,
    )
}

fn tile_set(plan: &WorldPlan, mats: &MaterialSet) -> FaceSet {
    let key = TileKey {
        lod: 2,
        x: -1,
        z: 3,
    };
    let faces = TileFacePlan::new(key, [false; 4], plan.lods.len() as u32 - 1);
    let tile = synthesize(plan, key);
    faces.build(|t| (t == key).then_some(&tile), mats, plan)
}

fn compare(name: &str, set: &FaceSet, mats: &MaterialSet, res: u32) {
    let (device, queue) = common::device::device("gpu_ptex");
    let mut cpu = Pages::default();
    bake_interior(set, mats, res, &mut cpu);
    let mut gpu = Pages::default();
    bake_interior_on_device(&device, &queue, set, mats, res, &mut gpu).expect("the GPU bake");
    assert_eq!((gpu.res, gpu.faces), (cpu.res, cpu.faces));
    let (mut identical, mut total) = (0usize, 0usize);
    // Texels whose albedo, normal or displacement differ at all.
    let mut differ = [0usize; 3];
    for f in 0..cpu.faces {
        for ((ca, cn, cd), (ga, gn, gd)) in cpu.interior(f).zip(gpu.interior(f)) {
            total += 1;
            if (ca, cn, cd.to_bits()) == (ga, gn, gd.to_bits()) {
                identical += 1;
                continue;
            }
            differ[0] += usize::from(ca != ga);
            differ[1] += usize::from(cn != gn);
            differ[2] += usize::from(cd.to_bits() != gd.to_bits());
            for c in 0..4 {
                assert!(
                    ca[c].abs_diff(ga[c]) <= 1,
                    "{name} face {f}: albedo {ca:?} vs {ga:?}"
                );
            }
            for c in 0..3 {
                let d = (cn[c] as i8 as i32 - gn[c] as i8 as i32).abs();
                assert!(d <= 2, "{name} face {f}: normal {cn:?} vs {gn:?}");
            }
            assert_eq!(cn[3], gn[3], "{name} face {f}: dominant material");
            assert!(
                (cd - gd).abs() <= 1e-4 + 1e-5 * cd.abs(),
                "{name} face {f}: displacement {cd} vs {gd}"
            );
        }
    }
    println!(
        "{name} at {res}²: {identical} of {total} texels bit-identical; albedo, normal, \
         displacement differ in {differ:?}"
    );
    assert!(total > 0);
    assert!(
        (total - identical) as f64 <= 0.02 * total as f64,
        "{name}: {} of {total} texels differ",
        total - identical
    );
}

#[test]
fn gpu_bake_matches_cpu_on_quads_and_tile_faces() {
    let plan = WorldPlan::new(3, WorldParams::default()).expect("default world");
    let mats = MaterialSet::default_ground(3);
    let quads = quad_set(&mats);
    assert!(quads.faces.len() > 100, "{} quads", quads.faces.len());
    compare("quads", &quads, &mats, 8);
    compare("quads", &quads, &mats, 32);
    let tiles = tile_set(&plan, &mats);
    assert_eq!(tiles.faces.len(), 16);
    compare("tile", &tiles, &mats, 64);
}

/// The faces of tile `(lod, x, z)` of seed 42's default world, every face baked.
fn default_world_tile(lod: u32, x: i64, z: i64, mats: &MaterialSet) -> FaceSet {
    let plan = WorldPlan::new(42, WorldParams::default()).expect("default world");
    let key = TileKey { lod, x, z };
    let tile = synthesize(&plan, key);
    let mut set = TileFacePlan::new(key, [false; 4], plan.lods.len() as u32 - 1).build(
        |t| (t == key).then_some(&tile),
        mats,
        &plan,
    );
    set.output = set.faces.len();
    set
}

#[test]
fn gpu_bake_matches_cpu_where_texels_weigh_their_materials() {
    // A tile of the default world (`texturing.ptex_blend: 2`) where the snow line crosses
    // gentle ground and rock outcrops: the texels weigh snow, rock and grass by the thresholds
    // at the texel (`surface_weights` in the twin), many of them two materials or more.
    let mats = MaterialSet::default_ground(42);
    let set = default_world_tile(5, 63, 64, &mats);
    assert!(set.rule.is_some() && set.surface.len() == set.samples.len());
    let mixed = (0..set.faces.len())
        .flat_map(|f| (0..64u32).flat_map(move |j| (0..64u32).map(move |i| (f, i, j))))
        .filter(|&(f, i, j)| texel_materials(&set, &mats, f, 64, i, j).len() >= 2)
        .count();
    assert!(mixed > 1000, "{mixed} texels of two materials or more");
    compare("snow-line tile", &set, &mats, 64);
}

#[test]
fn gpu_bake_matches_cpu_in_the_alpine_zone() {
    // A tile of the range 115 km from the origin whose upper slopes cross the alpine zone's band
    // (`texturing.alpine_fraction`) up to the snow: the twin's `alpine_share` splits the
    // ground of thousands of vertices between rock and the biomes' ground.
    let mats = MaterialSet::default_ground(42);
    let set = default_world_tile(5, 56, 54, &mats);
    let rule = set.rule.expect("texel rule");
    assert!(rule.alpine_fraction > 0.0);
    let alpine = set
        .surface
        .iter()
        .map(|s| alpine_share(rule.alpine_fraction, s[0] - s[1], s[1]))
        .filter(|a| *a > 0.0 && *a < 1.0)
        .count();
    assert!(alpine > 1000, "{alpine} vertices inside the alpine band");
    compare("alpine tile", &set, &mats, 64);
}

/// A 32² tangent-space normal map of ripples: normals tilted up to about 35° both ways along
/// each axis.
fn normal_map() -> Vec<u8> {
    common::png::rgba(32, 32, |x, y| {
        let (a, b) = ((x as f32 * 0.4).sin() * 0.6, (y as f32 * 0.25).cos() * 0.4);
        let inv = 1.0 / (a * a + b * b + 1.0).sqrt();
        let byte = |c: f32| ((c * inv * 0.5 + 0.5) * 255.0).round() as u8;
        [byte(a), byte(b), byte(1.0), 255]
    })
}

/// A set with images: `grass` an image material (with a normal map), `rock` overridden, and two decals at `a` and
/// `b` (world `[x, z]`, metres).
fn textured(seed: u64, a: [f64; 2], b: [f64; 2]) -> MaterialSet {
    use std::collections::HashMap;
    use std::sync::Arc;
    use strata::ptex::image::{decode_png, hash_hex, image_hash};
    use strata::ptex::spec::{DecalSpec, MaterialSpec, PtexSpecs};
    let pngs = [
        common::png::rgba(32, 32, |x, y| {
            [(x * 8) as u8, (y * 8) as u8, ((x ^ y) * 8) as u8, 255]
        }),
        common::png::rgba(16, 16, |x, y| [((x + y) * 8) as u8, 0, 0, 255]),
        common::png::rgba(64, 64, |x, y| {
            let v = (((x as f32 * 0.3).sin() + (y as f32 * 0.2).cos()) * 60.0 + 128.0) as u8;
            [v, v, v, 255]
        }),
        common::png::rgba(16, 8, |x, y| {
            let e = x.min(15 - x).min(2 * y.min(7 - y));
            [200, 40, 90, (e * 50).min(255) as u8]
        }),
        common::png::rgba(8, 8, |x, _| [(x * 36) as u8, 0, 0, 255]),
        normal_map(),
    ];
    let hashes: Vec<String> = pngs.iter().map(|p| hash_hex(&image_hash(p))).collect();
    let images = pngs
        .iter()
        .map(|p| (image_hash(p), Arc::new(decode_png(p).expect("png"))))
        .collect::<HashMap<_, _>>();
    let el = |v: serde_json::Value| -> strata::element::Element {
        serde_json::from_value(v).expect("element")
    };
    let zero = serde_json::json!({"min": [0, 0], "max": [0, 0]});
    let box_at = |c: [f64; 2]| {
        serde_json::json!({"min": [c[0] - 30.0, c[1] - 30.0],
                                                   "max": [c[0] + 30.0, c[1] + 30.0]})
    };
    let specs = PtexSpecs {
        materials: vec![
            MaterialSpec::from_element(&el(serde_json::json!({"id": "g", "bbox": zero,
                "name": "grass", "relief_m": 0.3, "texture": {"albedo": hashes[0],
                "roughness": hashes[1], "height": hashes[2], "normal": hashes[5],
                "repeat_m": 4}})))
            .expect("grass"),
            MaterialSpec::from_element(&el(serde_json::json!({"id": "r", "bbox": zero,
                "name": "rock", "base": [0.2, 0.3, 0.4], "roughness": [0.1, 0.9]})))
            .expect("rock"),
        ],
        decals: vec![
            DecalSpec::from_element(&el(serde_json::json!({"id": "a", "bbox": box_at(a),
                "image": hashes[3], "center": a, "size_m": [24, 14], "rotation_deg": 20})))
            .expect("decal a"),
            DecalSpec::from_element(&el(serde_json::json!({"id": "b", "bbox": box_at(b),
                "image": hashes[0], "mask": hashes[4], "center": b, "size_m": [18, 18],
                "rotation_deg": -35, "opacity": 0.8, "roughness": 0.2,
                "projection": "top_down_facing"})))
            .expect("decal b"),
        ],
    };
    let set = specs.set(seed, &images);
    assert_eq!(set.validate(), Ok(()));
    assert_eq!((set.images.len(), set.decals.len()), (6, 2));
    set
}

/// How many interior texels of `set` at `res` differ between `mats` and `bare` (`mats` with
/// something left out), in albedo and in normal: so the comparisons cover the decals' and the
/// normal maps' texels.
fn changed_texels(set: &FaceSet, mats: &MaterialSet, bare: &MaterialSet, res: u32) -> [usize; 2] {
    let (mut a, mut b) = (Pages::default(), Pages::default());
    bake_interior(set, mats, res, &mut a);
    bake_interior(set, bare, res, &mut b);
    let differ = |x: &[[u8; 4]], y: &[[u8; 4]]| x.iter().zip(y).filter(|(p, q)| p != q).count();
    [differ(&a.albedo, &b.albedo), differ(&a.normal, &b.normal)]
}

/// Texels of `set` at `res` the decals of `mats` change (albedo) and its normal maps tilt.
fn decal_and_normal_map_texels(set: &FaceSet, mats: &MaterialSet, res: u32) -> [usize; 2] {
    let mut undecorated = mats.clone();
    undecorated.decals.clear();
    let mut unmapped = mats.clone();
    for m in &mut unmapped.materials {
        if let Some(t) = m.texture.as_mut() {
            t.normal = None;
        }
    }
    [
        changed_texels(set, mats, &undecorated, res)[0],
        changed_texels(set, mats, &unmapped, res)[1],
    ]
}

#[test]
fn gpu_bake_matches_cpu_with_image_materials_and_decals() {
    let plan = WorldPlan::new(3, WorldParams::default()).expect("default world");
    // The quads span x −300…−274, z 9000…9024 (see quad_set).
    let mats = textured(3, [-290.0, 9008.0], [-280.0, 9016.0]);
    let quads = quad_set(&mats);
    let [touched, tilted] = decal_and_normal_map_texels(&quads, &mats, 32);
    assert!(
        touched > 1000,
        "the decals touch {touched} texels of the quads"
    );
    assert!(
        tilted > 300,
        "the normal map tilts {tilted} texels of the quads"
    );
    // Decal b fades with the facing: some quads in its footprint are steep or face down.
    let mut everywhere = mats.clone();
    for d in &mut everywhere.decals {
        d.facing = false;
    }
    let faded = changed_texels(&quads, &mats, &everywhere, 32)[0];
    assert!(
        faded > 50,
        "the facing fade spares {faded} texels of the quads"
    );
    compare("textured quads", &quads, &mats, 8);
    compare("textured quads", &quads, &mats, 32);
    // Tile (2, −1, 3) spans x −256…0, z 768…1024 at 1 m cells.
    let foot = strata::scene::tile_footprint(
        &WorldParams::default(),
        TileKey {
            lod: 2,
            x: -1,
            z: 3,
        },
    );
    let c = [
        (foot.min[0] + foot.max[0]) / 2.0,
        (foot.min[1] + foot.max[1]) / 2.0,
    ];
    let mats = textured(3, c, [c[0] + 20.0, c[1] - 15.0]);
    let tiles = tile_set(&plan, &mats);
    let [touched, tilted] = decal_and_normal_map_texels(&tiles, &mats, 64);
    assert!(
        touched > 300,
        "the decals touch {touched} texels of the tile"
    );
    assert!(
        tilted > 300,
        "the normal map tilts {tilted} texels of the tile"
    );
    compare("textured tile", &tiles, &mats, 64);
}
