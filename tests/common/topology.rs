//! Counts that decide a quad mesh's topology (Euler characteristic `V − E + F`, components), for
//! the tests of the volume meshes.

use std::collections::HashSet;
use strata::volume::mesh::QuadMesh;

/// Vertices, undirected edges, quads and connected components (union-find over the quads'
/// vertices; an isolated vertex is a component of its own).
pub fn counts(m: &QuadMesh) -> (i64, i64, i64, usize) {
    let mut edges = HashSet::new();
    let mut parent: Vec<usize> = (0..m.vertex_count()).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for q in &m.quads {
        for k in 0..4 {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            edges.insert((a.min(b), a.max(b)));
        }
        for k in 1..4 {
            let (a, b) = (
                find(&mut parent, q[0] as usize),
                find(&mut parent, q[k] as usize),
            );
            parent[a] = b;
        }
    }
    let roots: HashSet<usize> = (0..m.vertex_count())
        .map(|i| find(&mut parent, i))
        .collect();
    (
        m.vertex_count() as i64,
        edges.len() as i64,
        m.quad_count() as i64,
        roots.len(),
    )
}
