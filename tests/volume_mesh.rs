//! Properties of the surface-nets quad mesher (`strata::volume::mesh`, Becher §4.6): closed
//! surfaces are watertight, consistently oriented manifolds with the right Euler characteristic;
//! Ptex adjacency is symmetric with inverse uv transforms and maps shared edge points to the same
//! world point from both sides; normals are unit and outward; non-manifold edges pair up
//! symmetrically; the vertices and quads agree with the `fast-surface-nets` crate.

use std::collections::{HashMap, HashSet};
use strata::volume::mesh::ptex::edge_point;
use strata::volume::mesh::{
    surface_nets, MeshOptions, QuadClass, QuadMesh, SampleAttributes, NONE, UV_TRANSFORMS,
};

mod common;

fn grid(dims: [usize; 3], f: impl Fn(f32, f32, f32) -> f32) -> Vec<f32> {
    let mut out = Vec::with_capacity(dims[0] * dims[1] * dims[2]);
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                out.push(f(x as f32, y as f32, z as f32));
            }
        }
    }
    out
}

fn mesh(dims: [usize; 3], sdf: &[f32]) -> QuadMesh {
    let mut m = QuadMesh::default();
    surface_nets(
        sdf,
        SampleAttributes::default(),
        &MeshOptions::new(dims, 1.0),
        &mut m,
    )
    .expect("valid grid");
    m
}

fn sphere(n: usize, r: f32) -> ([usize; 3], Vec<f32>, [f32; 3]) {
    let c = (n as f32 - 1.0) / 2.0 + 0.123;
    let dims = [n, n, n];
    let sdf = grid(dims, |x, y, z| {
        ((x - c).powi(2) + (y - c).powi(2) + (z - c).powi(2)).sqrt() - r
    });
    (dims, sdf, [c, c, c])
}

fn torus(n: usize, big: f32, small: f32) -> ([usize; 3], Vec<f32>) {
    let c = (n as f32 - 1.0) / 2.0 + 0.071;
    let dims = [n, n, n];
    let sdf = grid(dims, |x, y, z| {
        let (dx, dy, dz) = (x - c, y - c, z - c);
        let q = (dx * dx + dz * dz).sqrt() - big;
        (q * q + dy * dy).sqrt() - small
    });
    (dims, sdf)
}

/// Checks closedness, manifoldness and orientation; returns (V, E, F, components).
fn topology(m: &QuadMesh) -> (i64, i64, i64, usize) {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    let mut used = vec![false; m.vertex_count()];
    for q in &m.quads {
        for k in 0..4 {
            *directed.entry((q[k], q[(k + 1) % 4])).or_default() += 1;
            used[q[k] as usize] = true;
        }
    }
    assert!(used.iter().all(|&u| u), "every vertex belongs to a quad");
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "directed edge {a}->{b} used {n} times (orientation)");
        assert!(
            directed.contains_key(&(b, a)),
            "edge {a}-{b} is a boundary edge: the mesh is not watertight"
        );
    }
    let counts = common::topology::counts(m);
    assert_eq!(counts.1 as usize, directed.len() / 2, "undirected edges");
    counts
}

#[test]
fn sphere_is_a_watertight_genus_0_manifold() {
    for (n, r) in [(16, 5.0), (40, 15.3), (33, 2.2)] {
        let (dims, sdf, _) = sphere(n, r);
        let m = mesh(dims, &sdf);
        let (v, e, f, comps) = topology(&m);
        let chi = v - e + f;
        assert_eq!(comps, 1, "one component");
        assert_eq!(chi, 2, "sphere n={n} r={r}: V={v} E={e} F={f}");
        assert_eq!((2 - chi) / 2, 0, "genus 0");
    }
}

#[test]
fn torus_has_euler_characteristic_0() {
    let (dims, sdf) = torus(48, 13.0, 5.0);
    let m = mesh(dims, &sdf);
    let (v, e, f, comps) = topology(&m);
    assert_eq!(comps, 1);
    assert_eq!(v - e + f, 0, "torus: V={v} E={e} F={f}");
}

#[test]
fn normals_are_unit_and_outward_and_quads_face_out() {
    let (dims, sdf, c) = sphere(32, 11.0);
    let m = mesh(dims, &sdf);
    assert!(m.quad_count() > 500);
    for (p, n) in m.positions.iter().zip(&m.normals) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-5, "normal length {len}");
        let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        let dl = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let cos = (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / dl;
        assert!(cos > 0.95, "normal is not radial: cos {cos}");
    }
    for (q, class) in m.quads.iter().zip(&m.classes) {
        let p = q.map(|i| m.positions[i as usize]);
        let d1 = sub(p[2], p[0]);
        let d2 = sub(p[3], p[1]);
        let face = cross(d1, d2);
        let centre = [0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k] + p[3][k]) / 4.0 - c[k]);
        assert!(dot(face, centre) > 0.0, "quad winds inward");
        // The flat quad's front agrees with its class.
        let front = class.front().map(|v| v as f32);
        assert!(
            dot(face, front) > 0.0,
            "class {class:?} disagrees with winding"
        );
        // u × v of the class table is the front.
        let [ua, va] = class.uv_axes();
        let mut u = [0.0; 3];
        let mut v = [0.0; 3];
        u[ua] = 1.0;
        v[va] = 1.0;
        assert_eq!(cross(u, v), front);
    }
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[test]
fn uv_table_entries_invert_each_other_and_glue_edges() {
    for k in 0..4 {
        for k2 in 0..4 {
            let t = UV_TRANSFORMS[4 * k + k2];
            let back = UV_TRANSFORMS[4 * k2 + k];
            for uv in [[0.3f32, 0.7], [1.5, -0.25], [0.0, 1.0]] {
                let there = t.apply(uv);
                let again = back.apply(there);
                assert!((again[0] - uv[0]).abs() < 1e-6 && (again[1] - uv[1]).abs() < 1e-6);
            }
            for s in [0.0f32, 0.25, 1.0] {
                let p = t.apply(edge_point(k, s));
                let want = edge_point(k2, 1.0 - s);
                assert_eq!(p, want, "table {k}->{k2} at t={s}");
            }
            // Stepping out of this quad steps into the neighbour.
            let mid_out = {
                let e = edge_point(k, 0.5);
                let inward = [0.5 - e[0], 0.5 - e[1]];
                [e[0] - 0.25 * inward[0] * 2.0, e[1] - 0.25 * inward[1] * 2.0]
            };
            let q = t.apply(mid_out);
            assert!(
                (0.0..=1.0).contains(&q[0]) && (0.0..=1.0).contains(&q[1]),
                "{q:?}"
            );
        }
    }
}

/// Adjacency symmetric with inverse transforms, and shared edge points coincide in world space.
fn check_adjacency(m: &QuadMesh, allow_boundary: bool) -> usize {
    let mut boundary = 0;
    for q in 0..m.quad_count() {
        for k in 0..4 {
            let n = m.adjacency[q][k];
            if n.quad == NONE {
                boundary += 1;
                assert!(allow_boundary, "quad {q} edge {k} has no neighbour");
                continue;
            }
            assert_eq!(n.transform as usize, 4 * k + n.edge as usize);
            let back = m.adjacency[n.quad as usize][n.edge as usize];
            assert_eq!(back.quad as usize, q, "neighbour of neighbour");
            assert_eq!(back.edge as usize, k);
            assert_eq!(
                back.transform as usize,
                4 * n.edge as usize + k,
                "inverse transform"
            );
            for t in [0.0f32, 0.2, 0.5, 0.9, 1.0] {
                let uv = edge_point(k, t);
                let uv2 = UV_TRANSFORMS[n.transform as usize].apply(uv);
                let a = m.patch_point(q, uv[0], uv[1]);
                let b = m.patch_point(n.quad as usize, uv2[0], uv2[1]);
                let d = sub(a, b);
                assert!(
                    dot(d, d).sqrt() < 1e-4,
                    "edge point differs: {a:?} vs {b:?}"
                );
            }
        }
    }
    boundary
}

#[test]
fn adjacency_is_symmetric_on_closed_surfaces() {
    let (dims, sdf, _) = sphere(30, 10.4);
    check_adjacency(&mesh(dims, &sdf), false);
    let (dims, sdf) = torus(40, 11.0, 4.2);
    check_adjacency(&mesh(dims, &sdf), false);
}

/// A noisy field with many small blobs has checkerboard faces: four quads on one edge.
#[test]
fn non_manifold_edges_pair_symmetrically() {
    let dims = [24, 20, 22];
    let mut state = 0x1234_5678_9abc_def0u64;
    let sdf: Vec<f32> = (0..dims[0] * dims[1] * dims[2])
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 40) as f32 / (1u64 << 24) as f32 - 0.5
        })
        .collect();
    let m = mesh(dims, &sdf);
    // Count mesh edges with four quads.
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for q in &m.quads {
        for k in 0..4 {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let four = count.values().filter(|&&n| n == 4).count();
    assert!(four > 50, "the random field has non-manifold edges: {four}");
    let boundary = check_adjacency(&m, true);
    assert!(boundary > 0, "the grid border cuts the surface");
    // Away from the grid border every quad edge is paired: both cells of the edge and all their
    // neighbours exist, so every quad on the face between them exists.
    let inner = |v: u32| {
        let c = m.cells[v as usize];
        (0..3).all(|k| c[k] >= 1 && (c[k] as usize) + 3 <= dims[k])
    };
    let mut checked = 0;
    for (q, quad) in m.quads.iter().enumerate() {
        for k in 0..4 {
            let (a, b) = (quad[k], quad[(k + 1) % 4]);
            if inner(a) && inner(b) {
                assert_ne!(
                    m.adjacency[q][k].quad, NONE,
                    "interior quad {q} edge {k} unpaired"
                );
                if count[&(a.min(b), a.max(b))] == 4 {
                    checked += 1;
                }
            }
        }
    }
    assert!(
        checked > 100,
        "interior non-manifold quad edges checked: {checked}"
    );
}

#[test]
fn attributes_pass_through() {
    let (dims, sdf, _) = sphere(20, 6.0);
    let materials: Vec<u8> = grid(dims, |x, _, _| x).iter().map(|&x| x as u8).collect();
    let noise: Vec<[f32; 4]> = grid(dims, |x, y, z| x + 2.0 * y + 3.0 * z)
        .iter()
        .map(|&v| [v, 1.0, 0.0, -v])
        .collect();
    let mut m = QuadMesh::default();
    let attrs = SampleAttributes {
        materials: Some(&materials),
        noise: Some(&noise),
    };
    surface_nets(&sdf, attrs, &MeshOptions::new(dims, 0.5), &mut m).expect("mesh");
    for i in 0..m.vertex_count() {
        let c = m.cells[i];
        let f = m.offsets[i];
        let p = m.positions[i];
        for k in 0..3 {
            assert!((0.0..=1.0).contains(&f[k]));
            assert_eq!(p[k], ((c[k] as f64 + f[k] as f64) * 0.5) as f32);
        }
        // Nearest sample's x: material = round(cell + offset).
        assert_eq!(m.materials[i], (c[0] + u32::from(f[0] >= 0.5)) as u8);
        // Noise is linear in the sample coordinates, so trilinear interpolation is exact.
        let want = (c[0] as f32 + f[0]) + 2.0 * (c[1] as f32 + f[1]) + 3.0 * (c[2] as f32 + f[2]);
        assert!(
            (m.noise[i][0] - want).abs() < 1e-3,
            "{} vs {want}",
            m.noise[i][0]
        );
        assert!((m.noise[i][1] - 1.0).abs() < 1e-6);
    }
}

#[test]
fn bad_input_is_an_error() {
    let mut m = QuadMesh::default();
    let opts = MeshOptions::new([4, 4, 4], 1.0);
    assert!(surface_nets(&[0.0; 63], SampleAttributes::default(), &opts, &mut m).is_err());
    let opts1 = MeshOptions::new([1, 4, 4], 1.0);
    assert!(surface_nets(&[0.0; 16], SampleAttributes::default(), &opts1, &mut m).is_err());
    let bad = MeshOptions::new([4, 4, 4], f32::NAN);
    assert!(surface_nets(&[0.0; 64], SampleAttributes::default(), &bad, &mut m).is_err());
    let short = [0u8; 10];
    let attrs = SampleAttributes {
        materials: Some(&short),
        noise: None,
    };
    assert!(surface_nets(&[0.0; 64], attrs, &opts, &mut m).is_err());
    // All air and all solid: an empty mesh.
    surface_nets(&[1.0; 64], SampleAttributes::default(), &opts, &mut m).expect("air");
    assert_eq!((m.vertex_count(), m.quad_count()), (0, 0));
    surface_nets(&[-1.0; 64], SampleAttributes::default(), &opts, &mut m).expect("solid");
    assert_eq!((m.vertex_count(), m.quad_count()), (0, 0));
}

/// Same vertices (as a set of positions) and the same number of quads as `fast-surface-nets`.
#[test]
fn agrees_with_fast_surface_nets() {
    use fast_surface_nets::ndshape::{RuntimeShape, Shape};
    use fast_surface_nets::{surface_nets as fsn, SurfaceNetsBuffer};
    let (dims, sdf) = torus(36, 10.0, 4.0);
    let m = mesh(dims, &sdf);
    let shape = RuntimeShape::<u32, 3>::new(dims.map(|d| d as u32));
    assert_eq!(shape.size() as usize, sdf.len());
    let mut buf = SurfaceNetsBuffer::default();
    let max = dims.map(|d| d as u32 - 1);
    fsn(&sdf, &shape, [0; 3], max, &mut buf);
    assert_eq!(buf.positions.len(), m.vertex_count());
    assert_eq!(buf.indices.len(), 6 * m.quad_count());
    let key = |p: &[f32; 3]| p.map(|v| (v * 1024.0).round() as i64);
    let ours: HashSet<[i64; 3]> = m.positions.iter().map(key).collect();
    let theirs: HashSet<[i64; 3]> = buf.positions.iter().map(key).collect();
    assert_eq!(ours, theirs);
    let classes: HashSet<QuadClass> = m.classes.iter().copied().collect();
    assert_eq!(classes.len(), 6, "a torus has all six classes");
}
