//! Surface-nets quad meshing with quad classes and Ptex adjacency (Becher et al., *Feature-based
//! volumetric terrain generation*, §4.6 "Surface Mesh Reconstruction", Fig. 7).
//!
//! The input is a signed distance grid `S` in the project's shared convention: `dims = [nx, ny,
//! nz]` samples, sample `(x, y, z)` at index `x + nx·(y + ny·z)`, y up, `f32`, **negative inside
//! the solid**, samples `spacing_m` metres apart. The surface is the zero set of `S`.
//!
//! # Algorithm (Naïve Surface Nets, Gibson 1998, as the paper uses it)
//!
//! One pass over the cells (cell `c` is the cube between samples `c` and `c + (1,1,1)`), in index
//! order (x fastest):
//!
//! 1. **Vertex.** A cell whose eight corners do not all have the same sign ("solid" is `S < 0`,
//!    "air" is `S ≥ 0`) gets one vertex at the mean of the zero crossings `t = S₀ / (S₀ − S₁)` of
//!    its sign-changing edges ([`CELL_EDGES`]). Its in-cell offset in `[0, 1]³` is kept
//!    ([`QuadMesh::offsets`]) beside the position so callers can rebuild positions exactly.
//! 2. **Normal.** The normal is `∇S / |∇S|` at the vertex, with `∇S` the gradient of the trilinear
//!    interpolant of the cell's corners, i.e. the central difference of `S` across the cell
//!    weighted to the vertex position (the paper computes normals "as the gradient of S"; this is
//!    its central-difference form on one cell, so no sample outside the cell is read). It points
//!    toward increasing `S`, i.e. out of the solid. A zero gradient gives `+Y`.
//! 3. **Attributes.** With per-sample inputs ([`SampleAttributes`]): the material id of the
//!    sample nearest to the vertex (material is categorical; the paper propagates it
//!    nearest-neighbour), and the noise parameters interpolated trilinearly at the vertex.
//! 4. **Quads.** Each of the three grid edges leaving the cell's minimum corner `p` along +X, +Y,
//!    +Z that changes sign emits one quad joining the vertices of the four cells around that edge,
//!    when those four cells exist and `p` lies in the caller's quad range
//!    ([`MeshOptions::quad_min`], [`MeshOptions::quad_max`]; used by chunks for ownership). As the
//!    paper says, a cell emits at most three quads, and there are six cases: the edge's axis and
//!    its sign change give the [`QuadClass`].
//! 5. **Ptex adjacency** ([`ptex`]): a second pass over the quads finds the neighbour across each
//!    of the four edges of every quad and the uv transform between them.
//!
//! # Quad classes, vertex order and local uv spaces (Fig. 7)
//!
//! Let the quad's grid edge run along axis `a` from sample `p` to `p + eₐ`, and `(b, c)` be the
//! other two axes in cyclic order (`a = X → (Y, Z)`, `Y → (Z, X)`, `Z → (X, Y)`). The four cells
//! around the edge are `c(j_b, j_c) = p − (1 − j_b)·e_b − (1 − j_c)·e_c`. Class `+A` means the
//! edge goes from solid at `p` to air at `p + eₐ` (the surface faces `+a`); `−A` the reverse.
//! Vertex order (the quad's local uv space is given by its vertex order, as Ptex does: vertex 0
//! at `uv = (0,0)`, 1 at `(1,0)`, 2 at `(1,1)`, 3 at `(0,1)`):
//!
//! | class | vertices 0, 1, 2, 3 | `u` along | `v` along | front (`u × v`) |
//! |---|---|---|---|---|
//! | `+X` | `c00 c10 c11 c01` | +Y | +Z | +X |
//! | `−X` | `c00 c01 c11 c10` | +Z | +Y | −X |
//! | `+Y` | `c00 c10 c11 c01` | +Z | +X | +Y |
//! | `−Y` | `c00 c01 c11 c10` | +X | +Z | −Y |
//! | `+Z` | `c00 c10 c11 c01` | +X | +Y | +Z |
//! | `−Z` | `c00 c01 c11 c10` | +Y | +X | −Z |
//!
//! Every quad is counter-clockwise seen from outside (from the air, the direction of increasing
//! `S`): consistent winding, outward front faces.
//!
//! Edge `k` of a quad runs from vertex `k` to vertex `k + 1 (mod 4)`: edge 0 is `v = 0`, edge 1
//! `u = 1`, edge 2 `v = 1`, edge 3 `u = 0`.
//!
//! # Non-manifold edges
//!
//! A mesh edge joins the vertices of two face-adjacent cells; the quads sharing it are the
//! sign-changing grid edges of the square face between the cells. That square has two sign
//! changes (a manifold edge, two quads) or four (corners alternate in sign: four quads on one
//! edge). For four, the rule is **solid corners stay apart**: each quad is paired with the quad
//! whose grid edge shares its *solid* endpoint on that face, i.e. the surface wraps each solid
//! corner separately (the two solid corners are not joined through the face). The pairing is a
//! pure function of the face's four signs, so it is symmetric and the paired quads traverse the
//! shared edge in opposite directions (tested).

pub mod nets;
pub mod ptex;

pub use nets::{surface_nets, surface_nets_on};
pub use ptex::{uv_transform, UvTransform, UV_TRANSFORMS};

/// "No quad" in [`Neighbor::quad`] and the internal index tables.
pub const NONE: u32 = u32::MAX;

/// Corner `i` of a cell is at offset `(i & 1, (i >> 1) & 1, (i >> 2) & 1)` from its minimum corner.
pub const CELL_CORNERS: [[u32; 3]; 8] = [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [0, 1, 1],
    [1, 1, 1],
];

/// The twelve edges of a cell as corner pairs (lower corner first). Edge `4·a + o₁ + 2·o₂` runs
/// along axis `a` with offsets `o₁`, `o₂` along the axes `(a + 1) mod 3`, `(a + 2) mod 3`.
pub const CELL_EDGES: [[usize; 2]; 12] = cell_edges();

const fn cell_edges() -> [[usize; 2]; 12] {
    let mut out = [[0usize; 2]; 12];
    let mut a = 0;
    while a < 3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let mut o = 0;
        while o < 4 {
            let lo = ((o & 1) << b) | (((o >> 1) & 1) << c);
            out[4 * a + o] = [lo, lo | (1 << a)];
            o += 1;
        }
        a += 1;
    }
    out
}

/// The six quad classes of Fig. 7: the axis of the grid edge a quad crosses and the direction its
/// front faces. The discriminant is the wire value (`2·axis + (sign < 0)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum QuadClass {
    /// Grid edge along X, solid at lower x: faces +X.
    PosX = 0,
    /// Grid edge along X, solid at higher x: faces −X.
    NegX = 1,
    /// Grid edge along Y, solid below: faces +Y (ground).
    PosY = 2,
    /// Grid edge along Y, solid above: faces −Y (ceiling, overhang).
    NegY = 3,
    /// Grid edge along Z, solid at lower z: faces +Z.
    PosZ = 4,
    /// Grid edge along Z, solid at higher z: faces −Z.
    NegZ = 5,
}

impl QuadClass {
    /// All classes by wire value.
    pub const ALL: [QuadClass; 6] = [
        QuadClass::PosX,
        QuadClass::NegX,
        QuadClass::PosY,
        QuadClass::NegY,
        QuadClass::PosZ,
        QuadClass::NegZ,
    ];

    /// The class of a grid edge along `axis` (0 = X, 1 = Y, 2 = Z) whose lower sample is solid
    /// (`solid_low`) or air.
    pub fn new(axis: usize, solid_low: bool) -> Self {
        Self::ALL[2 * (axis % 3) + usize::from(!solid_low)]
    }

    /// The class with wire value `v`, if any.
    pub fn from_u8(v: u8) -> Option<Self> {
        Self::ALL.get(v as usize).copied()
    }

    /// Axis of the crossed grid edge: 0 = X, 1 = Y, 2 = Z.
    pub fn axis(self) -> usize {
        self as usize / 2
    }

    /// Whether the front faces the positive axis direction.
    pub fn positive(self) -> bool {
        (self as usize).is_multiple_of(2)
    }

    /// Unit front direction (outward normal of the flat quad).
    pub fn front(self) -> [i32; 3] {
        let mut d = [0; 3];
        d[self.axis()] = if self.positive() { 1 } else { -1 };
        d
    }

    /// The axes of the local `u` and `v` directions (both point toward positive world axes).
    pub fn uv_axes(self) -> [usize; 2] {
        let a = self.axis();
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        if self.positive() {
            [b, c]
        } else {
            [c, b]
        }
    }

    /// Short name, e.g. `"+X"`.
    pub fn name(self) -> &'static str {
        ["+X", "-X", "+Y", "-Y", "+Z", "-Z"][self as usize]
    }
}

/// The neighbour of a quad across one of its edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Neighbor {
    /// Index of the neighbouring quad, or [`NONE`] at the mesh boundary (grid border or outside
    /// the quad range).
    pub quad: u32,
    /// The neighbour's edge (0..4) that is shared; 0 when there is no neighbour.
    pub edge: u8,
    /// Index into [`UV_TRANSFORMS`]: `4·k + edge`, where `k` is this quad's edge.
    pub transform: u8,
}

impl Neighbor {
    /// No neighbour.
    pub const NONE: Neighbor = Neighbor {
        quad: NONE,
        edge: 0,
        transform: 0,
    };
}

/// Optional per-sample inputs carried into the vertex data (each the length of the grid).
#[derive(Clone, Copy, Debug, Default)]
pub struct SampleAttributes<'a> {
    /// Material id per sample; a vertex takes the one of the sample nearest to it.
    pub materials: Option<&'a [u8]>,
    /// Noise parameters per sample; a vertex takes their trilinear interpolation.
    pub noise: Option<&'a [[f32; 4]]>,
}

/// Grid description and quad range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshOptions {
    /// Samples along x, y, z.
    pub dims: [usize; 3],
    /// Distance between neighbouring samples, metres.
    pub spacing_m: f32,
    /// Quads are emitted for grid edges whose lower sample `p` has `quad_min ≤ p < quad_max` (per
    /// axis), besides needing all four cells around the edge inside the grid.
    pub quad_min: [u32; 3],
    /// See [`MeshOptions::quad_min`].
    pub quad_max: [u32; 3],
}

impl MeshOptions {
    /// The whole grid: every quad whose four cells exist.
    pub fn new(dims: [usize; 3], spacing_m: f32) -> Self {
        Self {
            dims,
            spacing_m,
            quad_min: [0; 3],
            quad_max: [u32::MAX; 3],
        }
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.dims[0] * self.dims[1] * self.dims[2]
    }

    /// Whether the grid has no sample.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Why a grid cannot be meshed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// A dimension is below 2 or the grid has more than [`MAX_SAMPLES`] samples.
    #[error("grid dims {0:?}: each must be at least 2 and the product at most {MAX_SAMPLES}")]
    BadDims([usize; 3]),
    /// A slice does not have one value per sample.
    #[error("{field} has {got} values, the grid has {want} samples")]
    Length {
        /// Which input.
        field: &'static str,
        /// Its length.
        got: usize,
        /// Samples in the grid.
        want: usize,
    },
    /// The spacing is not a positive finite number.
    #[error("spacing_m must be positive and finite, got {0}")]
    BadSpacing(f32),
}

/// Largest grid accepted: 512³ samples (indices and vertex counts stay far below `u32::MAX`).
pub const MAX_SAMPLES: usize = 512 * 512 * 512;

/// The mesh (caller-owned, reused between calls: [`surface_nets`] clears and refills it, keeping
/// the allocations). Vertex arrays are parallel; quad arrays are parallel.
#[derive(Clone, Debug, Default)]
pub struct QuadMesh {
    /// Grid cell (minimum corner sample) of each vertex.
    pub cells: Vec<[u32; 3]>,
    /// Offset of each vertex inside its cell, in cell units, each component in `[0, 1]`.
    pub offsets: Vec<[f32; 3]>,
    /// Vertex positions relative to sample `(0, 0, 0)`, metres: `(cell + offset)·spacing_m`.
    pub positions: Vec<[f32; 3]>,
    /// Unit outward normals (`∇S / |∇S|`).
    pub normals: Vec<[f32; 3]>,
    /// Material id of each vertex (0 without input).
    pub materials: Vec<u8>,
    /// Noise parameters of each vertex (zeros without input).
    pub noise: Vec<[f32; 4]>,
    /// Vertex indices of each quad, in the order of the class table above.
    pub quads: Vec<[u32; 4]>,
    /// Class of each quad.
    pub classes: Vec<QuadClass>,
    /// Lower sample `p` of the grid edge each quad crosses (with the class's axis, the edge).
    pub edges: Vec<[u32; 3]>,
    /// Neighbour across each edge of each quad.
    pub adjacency: Vec<[Neighbor; 4]>,
    /// Scratch: vertex index of each cell, or [`NONE`].
    pub(crate) cell_vertex: Vec<u32>,
    /// Scratch: the quad on each of a vertex's twelve cell edges ([`CELL_EDGES`] order).
    pub(crate) slots: Vec<[u32; 12]>,
    /// Scratch: corner sign mask of each vertex's cell (bit `i` = corner `i` is solid).
    pub(crate) masks: Vec<u8>,
    /// Scratch: sign bits of two sample slices.
    pub(crate) signs: Vec<u64>,
}

impl QuadMesh {
    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of quads.
    pub fn quad_count(&self) -> usize {
        self.quads.len()
    }

    /// Empties every array, keeping the allocations.
    pub fn clear(&mut self) {
        self.cells.clear();
        self.offsets.clear();
        self.positions.clear();
        self.normals.clear();
        self.materials.clear();
        self.noise.clear();
        self.quads.clear();
        self.classes.clear();
        self.edges.clear();
        self.adjacency.clear();
        self.slots.clear();
        self.masks.clear();
    }

    /// The point of quad `q`'s bilinear patch at local `(u, v)`, metres.
    pub fn patch_point(&self, q: usize, u: f32, v: f32) -> [f32; 3] {
        let [a, b, c, d] = self.quads[q].map(|i| self.positions[i as usize]);
        let w = [(1.0 - u) * (1.0 - v), u * (1.0 - v), u * v, (1.0 - u) * v];
        std::array::from_fn(|k| w[0] * a[k] + w[1] * b[k] + w[2] * c[k] + w[3] * d[k])
    }
}
