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

use super::{Neighbor, QuadClass, QuadMesh, NONE};

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

/// What edge `k` of a quad of some class needs, relative to the cell `c0` of its vertex `k`:
/// the corner bits of the face's samples `P0 = p`, `P1 = p + eₐ`, `R0 = p + δ`, `R1 = P1 + δ` in
/// `c0`'s corner mask, and the slots in `c0`'s quad table of the three other grid edges of the
/// face (the edge `P0–R0`, the edge `P1–R1`, the parallel edge `R0–R1`).
#[derive(Clone, Copy, Debug, Default)]
struct EdgeRule {
    bits: [u8; 4],
    slots: [u8; 3],
}

/// The cells of a quad's vertices relative to its grid edge's lower sample `p` (module docs of
/// [`super`]: `c(j_b, j_c) = p − (1 − j_b)·e_b − (1 − j_c)·e_c`, in the class's vertex order).
fn vertex_cells(class: QuadClass) -> [[i64; 3]; 4] {
    let a = class.axis();
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    let cell = |jb: i64, jc: i64| {
        let mut v = [0i64; 3];
        v[b] = jb - 1;
        v[c] = jc - 1;
        v
    };
    if class.positive() {
        [cell(0, 0), cell(1, 0), cell(1, 1), cell(0, 1)]
    } else {
        [cell(0, 0), cell(0, 1), cell(1, 1), cell(1, 0)]
    }
}

/// The [`EdgeRule`] of every class and edge.
fn edge_rules() -> [[EdgeRule; 4]; 6] {
    let mut out = [[EdgeRule::default(); 4]; 6];
    for class in QuadClass::ALL {
        let a = class.axis();
        let cells = vertex_cells(class);
        for k in 0..4 {
            let (c0, c1) = (cells[k], cells[(k + 1) % 4]);
            let d = (0..3).find(|&i| c0[i] != c1[i]).unwrap_or(a);
            let e = 3 - a - d;
            let mut de = [0i64; 3];
            de[e] = if c0[e] < 0 { -1 } else { 1 };
            let mut ea = [0i64; 3];
            ea[a] = 1;
            let lo_e = if de[e] < 0 { de } else { [0; 3] };
            let rel = |s: [i64; 3]| [s[0] - c0[0], s[1] - c0[1], s[2] - c0[2]];
            let bit = |s: [i64; 3]| {
                let r = rel(s);
                (r[0] + 2 * r[1] + 4 * r[2]) as u8
            };
            let slot = |lo: [i64; 3], axis: usize| {
                let r = rel(lo);
                (4 * axis as i64 + r[(axis + 1) % 3] + 2 * r[(axis + 2) % 3]) as u8
            };
            out[class as usize][k] = EdgeRule {
                bits: [bit([0; 3]), bit(ea), bit(de), bit(add(ea, de))],
                slots: [slot(lo_e, e), slot(add(ea, lo_e), e), slot(de, a)],
            };
        }
    }
    out
}

/// Fills `mesh.adjacency` from the quads, the per-vertex quad slots and the vertices' corner
/// masks. Edge `k` of quad `Q` joins the vertices of cells `c0`, `c1`; the face between them is a
/// face of `c0`, so its four corner signs are bits of `c0`'s mask and its four grid edges are
/// slots of `c0`'s quad table: which slot holds the neighbour depends only on the signs and on
/// `(class, k)`.
pub(crate) fn adjacency(mesh: &mut QuadMesh) {
    let rules = edge_rules();
    mesh.adjacency.clear();
    mesh.adjacency.reserve(mesh.quads.len());
    for (quad, class) in mesh.quads.iter().zip(&mesh.classes) {
        let mut row = [Neighbor::NONE; 4];
        for (k, slot) in row.iter_mut().enumerate() {
            let rule = rules[*class as usize][k];
            let (v0, v1) = (quad[k], quad[(k + 1) % 4]);
            let mask = mesh.masks[v0 as usize];
            let [s0, s1, sr0, sr1] = rule.bits.map(|b| (mask >> b) & 1 == 1);
            let partner = if sr0 == sr1 {
                // Two sign changes: P1–R1 if R matches P0, else P0–R0.
                if sr0 == s0 {
                    rule.slots[1]
                } else {
                    rule.slots[0]
                }
            } else if sr0 == s0 {
                rule.slots[2]
            } else if s0 {
                // Checkerboard face: pair with the quad sharing this quad's solid corner.
                rule.slots[0]
            } else {
                debug_assert!(s1);
                rule.slots[1]
            };
            let n = mesh.slots[v0 as usize][partner as usize];
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
                debug_assert!(false, "edge {k}: neighbour {n} is not opposite");
            }
        }
        mesh.adjacency.push(row);
    }
}

fn add(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
