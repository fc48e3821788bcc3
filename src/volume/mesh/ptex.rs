//! Ptex adjacency (§4.6): the neighbour across each quad edge and the 16-entry table of uv
//! transforms between neighbouring local uv spaces (McDonald's real-time Ptex, the paper's [23]).
//!
//! # The uv-transform table
//!
//! Edge `k` of a quad is `P_k(t) = base_k + t·dir_k`, `t ∈ [0, 1]`, with `base = (0,0), (1,0),
//! (1,1), (0,1)` and `dir_k` the unit vector `(1,0)` turned `k` quarter turns counter-clockwise.
//! Two consistently oriented quads traverse their shared edge in opposite directions: this
//! quad's edge `k` at parameter `t` is the neighbour's edge `k'` at `1 − t`, and stepping out of
//! this quad is stepping into the neighbour. The map from this quad's uv space (extended beyond
//! `[0,1]²`) to the neighbour's is therefore the rigid motion `uv' = L·uv + T` with
//! `L = rot90^((k' + 2 − k) mod 4)` and `T = base_k' + dir_k' − L·base_k`. There are 4 × 4 = 16
//! of them, indexed `4·k + k'` ([`UV_TRANSFORMS`]); entry `4·k' + k` is the inverse of `4·k + k'`.
//!
//! The paper stores the neighbour's class and maps class pairs to the table; here the entry index
//! is stored directly in [`super::Neighbor::transform`] (same information, one lookup less).
//!
//! # Finding neighbours
//!
//! A quad's edge `k` joins the vertices of two face-adjacent cells; the other quads on that mesh
//! edge cross the other three grid edges of the square face between the cells. Which one is the
//! neighbour follows from the four corner signs of that square alone (the non-manifold rule of
//! [`super`]), and its index is read from the per-vertex table of the quads on each cell edge
//! that [`super::nets`] fills while emitting quads (the paper's "indices of generated quads
//! stored per vertex in a fixed pattern").

use super::{Neighbor, QuadMesh, NONE};

/// An affine map of uv space with integer coefficients: `u' = m[0][0]·u + m[0][1]·v + t[0]`,
/// `v' = m[1][0]·u + m[1][1]·v + t[1]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UvTransform {
    /// Linear part (a rotation by a multiple of 90°).
    pub m: [[i8; 2]; 2],
    /// Translation.
    pub t: [i8; 2],
}

impl UvTransform {
    /// Applies the map to `(u, v)`.
    pub fn apply(&self, uv: [f32; 2]) -> [f32; 2] {
        let m = self.m.map(|r| r.map(f32::from));
        [
            m[0][0] * uv[0] + m[0][1] * uv[1] + f32::from(self.t[0]),
            m[1][0] * uv[0] + m[1][1] * uv[1] + f32::from(self.t[1]),
        ]
    }
}

const BASE: [[i8; 2]; 4] = [[0, 0], [1, 0], [1, 1], [0, 1]];
const DIR: [[i8; 2]; 4] = [[1, 0], [0, 1], [-1, 0], [0, -1]];

const fn rot(r: usize) -> [[i8; 2]; 2] {
    match r % 4 {
        0 => [[1, 0], [0, 1]],
        1 => [[0, -1], [1, 0]],
        2 => [[-1, 0], [0, -1]],
        _ => [[0, 1], [-1, 0]],
    }
}

/// The transform from a quad's uv space to its neighbour's when this quad's edge `k` is the
/// neighbour's edge `k2` (both `0..4`).
pub const fn uv_transform(k: usize, k2: usize) -> UvTransform {
    let m = rot(k2 + 6 - k);
    let b = BASE[k % 4];
    let lb = [
        m[0][0] * b[0] + m[0][1] * b[1],
        m[1][0] * b[0] + m[1][1] * b[1],
    ];
    let t = [
        BASE[k2 % 4][0] + DIR[k2 % 4][0] - lb[0],
        BASE[k2 % 4][1] + DIR[k2 % 4][1] - lb[1],
    ];
    UvTransform { m, t }
}

/// The 16 uv transforms, index `4·k + k'` (see the module docs).
pub const UV_TRANSFORMS: [UvTransform; 16] = {
    let mut out = [UvTransform {
        m: [[0; 2]; 2],
        t: [0; 2],
    }; 16];
    let mut i = 0;
    while i < 16 {
        out[i] = uv_transform(i / 4, i % 4);
        i += 1;
    }
    out
};

/// The point of edge `k` at parameter `t`, in uv.
pub fn edge_point(k: usize, t: f32) -> [f32; 2] {
    let (b, d) = (BASE[k % 4], DIR[k % 4]);
    [
        f32::from(b[0]) + t * f32::from(d[0]),
        f32::from(b[1]) + t * f32::from(d[1]),
    ]
}

/// Fills `mesh.adjacency` from the quads, their grid edges and the per-vertex quad slots.
pub(crate) fn adjacency(sdf: &[f32], dims: [usize; 3], mesh: &mut QuadMesh) {
    let (sy, sz) = (dims[0] as i64, (dims[0] * dims[1]) as i64);
    let solid = |p: [i64; 3]| sdf[(p[0] + sy * p[1] + sz * p[2]) as usize] < 0.0;
    mesh.adjacency.clear();
    mesh.adjacency.reserve(mesh.quads.len());
    for q in 0..mesh.quads.len() {
        let quad = mesh.quads[q];
        let class = mesh.classes[q];
        let a = class.axis();
        let p = mesh.edges[q].map(i64::from);
        let mut ea = [0i64; 3];
        ea[a] = 1;
        let p1 = add(p, ea);
        let mut row = [Neighbor::NONE; 4];
        for (k, slot) in row.iter_mut().enumerate() {
            let (v0, v1) = (quad[k], quad[(k + 1) % 4]);
            let (c0, c1) = (mesh.cells[v0 as usize], mesh.cells[v1 as usize]);
            let Some(d) = (0..3).find(|&i| c0[i] != c1[i]) else {
                continue;
            };
            // The face lies in the plane spanned by `a` and `e`; it extends from Q's edge toward
            // the cells' side along `e`.
            let e = 3 - a - d;
            let step = if i64::from(c0[e]) < p[e] { -1 } else { 1 };
            let mut de = [0i64; 3];
            de[e] = step;
            let (r0, r1) = (add(p, de), add(p1, de));
            let (s0, s1, sr0, sr1) = (solid(p), solid(p1), solid(r0), solid(r1));
            let lo_e = if step < 0 { de } else { [0; 3] };
            // Partner grid edge: (lower sample, axis).
            let third_at_p0 = (add(p, lo_e), e);
            let third_at_p1 = (add(p1, lo_e), e);
            let partner = if sr0 == sr1 {
                if sr0 == s0 {
                    third_at_p1
                } else {
                    third_at_p0
                }
            } else if sr0 == s0 {
                (r0, a)
            } else if s0 {
                // Checkerboard face: pair with the quad sharing this quad's solid corner.
                third_at_p0
            } else {
                debug_assert!(s1);
                third_at_p1
            };
            let n = lookup(mesh, v0, partner);
            if n == NONE {
                continue;
            }
            let other = mesh.quads[n as usize];
            if let Some(k2) = (0..4).find(|&j| other[j] == v1 && other[(j + 1) % 4] == v0) {
                *slot = Neighbor {
                    quad: n,
                    edge: k2 as u8,
                    transform: (4 * k + k2) as u8,
                };
            } else {
                debug_assert!(false, "quad {q} edge {k}: neighbour {n} is not opposite");
            }
        }
        mesh.adjacency.push(row);
    }
}

fn add(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// The quad on grid edge `(lower sample, axis)`, read from the slots of vertex `v` (whose cell
/// contains that edge), or [`NONE`].
fn lookup(mesh: &QuadMesh, v: u32, (lo, axis): ([i64; 3], usize)) -> u32 {
    let c = mesh.cells[v as usize].map(i64::from);
    let (b, cc) = ((axis + 1) % 3, (axis + 2) % 3);
    let (o1, o2) = (lo[b] - c[b], lo[cc] - c[cc]);
    if !(0..2).contains(&o1) || !(0..2).contains(&o2) || lo[axis] != c[axis] {
        debug_assert!(
            false,
            "grid edge {lo:?}/{axis} is not an edge of cell {c:?}"
        );
        return NONE;
    }
    mesh.slots[v as usize][4 * axis + (o1 + 2 * o2) as usize]
}
