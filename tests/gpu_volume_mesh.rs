//! The WGSL twin of surface-nets meshing (`shaders/volume_mesh.wgsl`, `strata::gpu::volume_mesh`)
//! against the CPU reference on a software adapter (lavapipe). REQUIRES an adapter: without one
//! the test fails with instructions, it never skips.
//!
//! Tolerance (reason in `src/gpu/volume_mesh.rs`): vertex cells, quads, classes, grid edges and
//! adjacency identical (they depend only on signs); offsets within 1e-5 cell units and normal
//! components within 1e-5, the room WGSL leaves for fused multiply-adds and 2.5-ULP `/` and
//! `sqrt` on values of magnitude ≤ 1. The test prints how many values are bit-identical.

mod common;

use strata::gpu::volume_mesh::VolumeMeshKernel;
use strata::volume::mesh::{surface_nets, MeshOptions, QuadMesh, SampleAttributes};

const OFFSET_TOL: f32 = 1e-5;
const NORMAL_TOL: f32 = 1e-5;

fn device() -> (wgpu::Device, wgpu::Queue) {
    common::device::device("gpu_volume_mesh")
}

fn field(dims: [usize; 3], f: impl Fn(f32, f32, f32) -> f32) -> Vec<f32> {
    let mut out = Vec::new();
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                out.push(f(x as f32, y as f32, z as f32));
            }
        }
    }
    out
}

#[test]
fn gpu_mesh_matches_cpu() {
    let (device, queue) = device();
    let kernel = VolumeMeshKernel::new(&device).expect("pipeline");
    let noisy = |n: usize| {
        let c = (n as f32 - 1.0) / 2.0;
        field([n, n - 3, n + 2], move |x, y, z| {
            ((x - c).powi(2) + (y - c).powi(2) + (z - c).powi(2)).sqrt() - 0.33 * n as f32
                + 1.7 * (0.5 * x).sin() * (0.43 * y).cos() * (0.37 * z).sin()
        })
    };
    let cases = [
        (noisy(40), [40, 37, 42], [0u32; 3], [u32::MAX; 3]),
        (noisy(34), [34, 31, 36], [1; 3], [33; 3]),
    ];
    for (sdf, dims, qmin, qmax) in cases {
        let opts = MeshOptions {
            quad_min: qmin,
            quad_max: qmax,
            ..MeshOptions::new(dims, 0.5)
        };
        let mut cpu = QuadMesh::default();
        surface_nets(&sdf, SampleAttributes::default(), &opts, &mut cpu).expect("cpu");
        let mut gpu = QuadMesh::default();
        kernel
            .mesh(&device, &queue, &sdf, &opts, &mut gpu, None)
            .expect("gpu job");
        assert!(cpu.quad_count() > 1000, "{}", cpu.quad_count());
        assert_eq!(gpu.cells, cpu.cells, "vertex cells");
        assert_eq!(gpu.quads, cpu.quads, "quads");
        assert_eq!(gpu.classes, cpu.classes, "classes");
        assert_eq!(gpu.edges, cpu.edges, "grid edges");
        assert_eq!(gpu.adjacency, cpu.adjacency, "adjacency");
        let (mut exact, mut worst_o, mut worst_n) = (0, 0.0f32, 0.0f32);
        for v in 0..cpu.vertex_count() {
            for k in 0..3 {
                let (a, b) = (gpu.offsets[v][k], cpu.offsets[v][k]);
                let (na, nb) = (gpu.normals[v][k], cpu.normals[v][k]);
                exact += usize::from(a.to_bits() == b.to_bits())
                    + usize::from(na.to_bits() == nb.to_bits());
                worst_o = worst_o.max((a - b).abs());
                worst_n = worst_n.max((na - nb).abs());
            }
        }
        println!(
            "{dims:?}: {} vertices, {} quads; {exact}/{} values bit-identical; worst offset {worst_o:e}, normal {worst_n:e}",
            cpu.vertex_count(),
            cpu.quad_count(),
            6 * cpu.vertex_count()
        );
        assert!(worst_o <= OFFSET_TOL, "offset differs by {worst_o}");
        assert!(worst_n <= NORMAL_TOL, "normal differs by {worst_n}");
    }
}
