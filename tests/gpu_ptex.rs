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

mod common;

use strata::gpu::ptex::bake_interior_on_device;
use strata::ptex::face::TileFacePlan;
use strata::ptex::{bake_interior, FaceSet, MaterialSet, Pages};
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
    faces.build(|t| (t == key).then_some(&tile), mats)
}

fn compare(name: &str, set: &FaceSet, mats: &MaterialSet, res: u32) {
    let (device, queue) = common::device::device("gpu_ptex");
    let mut cpu = Pages::default();
    bake_interior(set, mats, res, &mut cpu);
    let mut gpu = Pages::default();
    bake_interior_on_device(&device, &queue, set, mats, res, &mut gpu).expect("the GPU bake");
    assert_eq!((gpu.res, gpu.faces), (cpu.res, cpu.faces));
    let (mut identical, mut total) = (0usize, 0usize);
    for f in 0..cpu.faces {
        for ((ca, cn, cd), (ga, gn, gd)) in cpu.interior(f).zip(gpu.interior(f)) {
            total += 1;
            if (ca, cn, cd.to_bits()) == (ga, gn, gd.to_bits()) {
                identical += 1;
                continue;
            }
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
    println!("{name} at {res}²: {identical} of {total} texels bit-identical");
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
