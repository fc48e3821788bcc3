//! Volume chunks of the world's solid (issue 5, "Volume chunks everywhere"): the surface-nets
//! quad mesh ([`super::mesh`], Becher §4.6) of a 32³-cell box, with quad classes and Ptex
//! adjacency.
//!
//! # Addressing
//!
//! Chunk `(lod, x, y, z)` has cell size `s = cell_m·2^lod` (LOD 0–[`MAX_CHUNK_LOD`]) and covers
//! world `[x·32·s, (x+1)·32·s) × [y·32·s, …) × [z·32·s, …)`. Global sample `(gx, gy, gz)` of a
//! LOD sits at world `(gx·s, gy·s, gz·s)`; the chunk's cells are global cells `32·x … 32·x + 31`
//! (and likewise in y, z). Limits: `|x|, |z| ≤ 2·max_tile_coord(lod) − 1` (the tiles' supported
//! world) and `|y| ≤ ` [`max_chunk_y`].
//!
//! # The solid
//!
//! For now the solid is the heightfield: `S(x, y, z) = (y − h(x, z))·n_y(x, z)`, the vertical
//! offset scaled by the y component of the tile's unit normal, which is the first-order distance
//! to the tilted surface plane (better than `y − h` on slopes, same zero set and sign). `h`, `n_y`
//! and the material come from the world's height tiles of the same LOD (vertex `(i, j)` of tile
//! `(tx, tz)` is column `(64·tx + i, 64·tz + j)`), so chunks follow the world's edits exactly as
//! tiles do. Caves of the world's `strata` elements carve it (`subsurface::carve`);
//! volume regions will replace `S` inside their boxes later.
//!
//! # The 1-cell padding rule (same-LOD seams)
//!
//! A chunk reads the 34³ samples of global indices `32·x − 1 … 32·x + 32` (one sample before its
//! first and one after its last cell corner). It meshes the 33³ cells `32·x − 1 … 32·x + 31` and
//! emits the quads of exactly the grid edges whose **lower sample** lies in `32·x … 32·x + 31`
//! (per axis). Every grid edge of the world therefore belongs to exactly one chunk, and the four
//! cells around an owned edge (which reach one cell below the chunk's first) are all inside the
//! padded grid. A vertex is a pure function of its cell's eight global samples, so a vertex on a
//! shared face (a cell `32·x − 1` of one chunk is cell 31 of its neighbour) has the same in-cell
//! offset, normal and material bit for bit in both chunks, and the union of same-LOD chunks is the
//! mesh of the whole world without duplicated or missing quads (`tests/chunks.rs`). Vertices of
//! padding cells that no owned quad uses are dropped. Positions are sent relative to the chunk
//! origin (`x·32·s, …`) in `f32`; [`ChunkMesh::global_cells`] and [`ChunkMesh::offsets`] give the
//! exact global placement. Ptex neighbours owned by another chunk are reported as none
//! (the quad's global grid edge, [`ChunkMesh::global_edges`], identifies them across chunks).
//! What reads the ground farther than the padding (the subsurface materials of
//! `subsurface::carve`) reads [`Columns::wide_heights`], the heights of the chunk's and its eight
//! neighbours' columns, from the same tiles: a function of the global column like the rest.
//!
//! # Cross-LOD seams: skirts
//!
//! Chunks of different LODs do not share vertices. Each chunk carries **skirts**: every boundary
//! edge of its mesh (a quad edge without a neighbour in the chunk; these all lie on the chunk's
//! border) is extruded straight down (−Y) by [`ChunkMesh::skirt_depth_m`] into a skirt quad wound
//! like the surface. `skirt_depth_m = 2·(largest height step between the two ends of a boundary
//! edge) + 8·s`, which bounds the vertical gap to a neighbour one LOD coarser (its surface
//! differs by the dropped octaves and the coarser placement; `tests/chunks.rs` checks the bound
//! along every seam of a fine/coarse pair). Skirts hang down because the solid is a heightfield;
//! when volume regions bring overhangs to chunks, transition cells (Transvoxel-style) are the
//! planned replacement — a documented deviation, as the paper meshes one region at one resolution
//! and has no LOD seams.

use super::mesh::{
    surface_nets_on, MeshError, MeshOptions, QuadClass, QuadMesh, SampleAttributes, NONE,
};
use super::offload::{CpuOnly, VolumeOffload};

/// Cells per chunk side.
pub const CHUNK_CELLS: usize = 32;
/// Samples per padded chunk side: one before, 32 cells' 33 corners.
pub const CHUNK_SAMPLES: usize = CHUNK_CELLS + 2;
/// Finest chunk LOD.
pub const MIN_CHUNK_LOD: u32 = 0;
/// Coarsest chunk LOD.
pub const MAX_CHUNK_LOD: u32 = 3;
/// Vertical extent of the chunk world, in LOD-0 cells: `|Y| ≤ 16384·cell_m`.
pub const CHUNK_Y_LIMIT_CELLS: i64 = 16_384;
/// Tile vertices per tile side minus one (tile column stride).
const TILE_QUADS: i64 = 64;

/// Address of a volume chunk.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ChunkKey {
    /// Level of detail: cell size `cell_m·2^lod`.
    pub lod: u32,
    /// Chunk column along +X.
    pub x: i64,
    /// Chunk layer along +Y (up).
    pub y: i64,
    /// Chunk row along +Z.
    pub z: i64,
}

impl ChunkKey {
    /// Global index of the chunk's first cell along x, y, z.
    pub fn first_cell(&self) -> [i64; 3] {
        [self.x, self.y, self.z].map(|c| c * CHUNK_CELLS as i64)
    }
}

/// Largest `|y|` of a chunk at `lod`.
pub fn max_chunk_y(lod: u32) -> i64 {
    CHUNK_Y_LIMIT_CELLS / (CHUNK_CELLS as i64 * (1i64 << lod)) - 1
}

/// Largest `|x|`, `|z|` of a chunk at `lod` given the tiles' `max_tile_coord(lod)`.
pub fn max_chunk_xz(max_tile_coord: i64) -> i64 {
    2 * max_tile_coord - 1
}

/// The tiles `(tx, tz)` of the chunk's LOD whose vertices the chunk reads (one to four).
pub fn tiles_needed(key: ChunkKey) -> Vec<(i64, i64)> {
    let [gx, _, gz] = key.first_cell();
    let span = |g: i64| {
        let (a, b) = (
            (g - 1).div_euclid(TILE_QUADS),
            (g + CHUNK_CELLS as i64).div_euclid(TILE_QUADS),
        );
        a..=b
    };
    let mut out = Vec::new();
    for tz in span(gz) {
        for tx in span(gx) {
            out.push((tx, tz));
        }
    }
    out
}

/// Columns of the wide height window around a chunk's padded grid on every side
/// ([`Columns::wide_heights`]): with them the window holds the columns of the chunk and of its
/// eight neighbours, which lie in the tiles of [`tiles_needed`].
pub const WIDE_MARGIN: usize = CHUNK_CELLS - 1;
/// Columns per side of the wide height window: three chunks' worth.
pub const WIDE_SAMPLES: usize = CHUNK_SAMPLES + 2 * WIDE_MARGIN;

/// The columns a chunk reads: `34 × 34` values, index `i + 34·j` for global column
/// `(32·x − 1 + i, 32·z − 1 + j)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Columns {
    /// Ground height, metres.
    pub heights: Vec<f32>,
    /// Y component of the unit ground normal.
    pub normal_y: Vec<f32>,
    /// Material id (tile proto-texturing material).
    pub materials: Vec<u8>,
    /// Ground heights of the wide window, metres: `96 × 96` values ([`WIDE_SAMPLES`]), index
    /// `i + 96·j` for global column `(32·x − 32 + i, 32·z − 32 + j)`, the padded grid's columns
    /// and [`WIDE_MARGIN`] more on every side. What `subsurface::carve` reads the ground under a
    /// vertex's material probe from (worlds with `chunk_geology: 2`); the solid reads `heights`.
    pub wide_heights: Vec<f32>,
}

/// A tile's per-vertex data the chunk needs (65×65, index `j·65 + i`).
#[derive(Clone, Copy, Debug)]
pub struct TileColumns<'a> {
    /// Tile column and row at the chunk's LOD.
    pub tile: (i64, i64),
    /// Heights, metres.
    pub heights: &'a [f32],
    /// Unit normals.
    pub normals: &'a [[f32; 3]],
    /// Materials.
    pub materials: &'a [u8],
}

/// Gathers a chunk's [`Columns`] from the tiles of [`tiles_needed`]; `None` if one is missing.
pub fn gather_columns(key: ChunkKey, tiles: &[TileColumns<'_>]) -> Option<Columns> {
    let [gx0, _, gz0] = key.first_cell();
    let n = CHUNK_SAMPLES;
    let w = WIDE_SAMPLES as i64;
    let mut out = Columns {
        heights: Vec::with_capacity(n * n),
        normal_y: Vec::with_capacity(n * n),
        materials: Vec::with_capacity(n * n),
        wide_heights: Vec::with_capacity(WIDE_SAMPLES * WIDE_SAMPLES),
    };
    let first = -1 - WIDE_MARGIN as i64;
    for j in 0..w {
        let gz = gz0 + first + j;
        let tz = gz.div_euclid(TILE_QUADS);
        let row = (gz.rem_euclid(TILE_QUADS) * 65) as usize;
        let mut tile: Option<&TileColumns<'_>> = None;
        for i in 0..w {
            let gx = gx0 + first + i;
            let t = (gx.div_euclid(TILE_QUADS), tz);
            if tile.is_none_or(|c| c.tile != t) {
                tile = Some(tiles.iter().find(|c| c.tile == t)?);
            }
            let v = row + gx.rem_euclid(TILE_QUADS) as usize;
            out.wide_heights.push(*tile?.heights.get(v)?);
        }
    }
    for j in 0..n as i64 {
        let gz = gz0 - 1 + j;
        for i in 0..n as i64 {
            let gx = gx0 - 1 + i;
            let t = (gx.div_euclid(TILE_QUADS), gz.div_euclid(TILE_QUADS));
            let v = (gz.rem_euclid(TILE_QUADS) * 65 + gx.rem_euclid(TILE_QUADS)) as usize;
            let tile = tiles.iter().find(|c| c.tile == t)?;
            out.heights.push(*tile.heights.get(v)?);
            out.normal_y.push(tile.normals.get(v)?[1]);
            out.materials.push(*tile.materials.get(v)?);
        }
    }
    Some(out)
}

/// Fills the padded chunk grid: `sdf` and per-sample `materials` (34³ each, shared grid
/// convention, sample `(i, j, k)` = global `(32·x − 1 + i, 32·y − 1 + j, 32·z − 1 + k)`).
pub fn chunk_sdf(
    key: ChunkKey,
    spacing_m: f32,
    cols: &Columns,
    sdf: &mut Vec<f32>,
    materials: &mut Vec<u8>,
) {
    let n = CHUNK_SAMPLES;
    let gy0 = key.first_cell()[1] - 1;
    let s = spacing_m as f64;
    sdf.clear();
    materials.clear();
    for k in 0..n {
        for j in 0..n {
            let y = (gy0 + j as i64) as f64 * s;
            for i in 0..n {
                let c = k * n + i;
                sdf.push(((y - cols.heights[c] as f64) * cols.normal_y[c] as f64) as f32);
                materials.push(cols.materials[c]);
            }
        }
    }
}

/// The mesh of one chunk with skirts.
#[derive(Clone, Debug, Default)]
pub struct ChunkMesh {
    /// Positions relative to the chunk origin `(x·32·s, y·32·s, z·32·s)`, metres.
    pub positions: Vec<[f32; 3]>,
    /// Unit outward normals.
    pub normals: Vec<[f32; 3]>,
    /// Material id per vertex.
    pub materials: Vec<u8>,
    /// Global cell of each vertex (exact placement: `(cell + offset)·s`).
    pub global_cells: Vec<[i64; 3]>,
    /// In-cell offset of each vertex, cell units.
    pub offsets: Vec<[f32; 3]>,
    /// Quads (vertex indices).
    pub quads: Vec<[u32; 4]>,
    /// Quad classes.
    pub classes: Vec<QuadClass>,
    /// Global lower sample of each quad's grid edge.
    pub global_edges: Vec<[i64; 3]>,
    /// Ptex neighbours (quad index within this chunk, or [`NONE`]).
    pub adjacency: Vec<[super::mesh::Neighbor; 4]>,
    /// Skirt vertices (bottoms), relative to the chunk origin; skirt quads index the surface
    /// vertices `0..V` and these as `V + i`.
    pub skirt_positions: Vec<[f32; 3]>,
    /// Skirt quads, wound like the surface.
    pub skirt_quads: Vec<[u32; 4]>,
    /// How far skirts hang below their boundary edge, metres.
    pub skirt_depth_m: f32,
    /// Subsurface material id per vertex (the `strata` element's material found half a voxel
    /// inside the solid, `subsurface::carve`), [`NO_GEOLOGY`] where no element is in
    /// force; empty when none touches the chunk.
    pub geology: Vec<u32>,
}

/// [`ChunkMesh::geology`] of a vertex no `strata` element covers.
pub const NO_GEOLOGY: u32 = u32::MAX;

/// Meshes a chunk from its columns. `scratch` is reused between calls.
pub fn mesh_chunk(
    key: ChunkKey,
    spacing_m: f32,
    cols: &Columns,
    scratch: &mut QuadMesh,
) -> Result<ChunkMesh, MeshError> {
    let mut sdf = Vec::new();
    let mut mats = Vec::new();
    chunk_sdf(key, spacing_m, cols, &mut sdf, &mut mats);
    mesh_sdf(key, spacing_m, &sdf, &mats, scratch, &CpuOnly)
}

/// Meshes a chunk's padded grid as [`chunk_sdf`] lays it out (34³ values, negative inside the
/// solid), e.g. after caves carved it (`subsurface::carve`), with the surface nets offered to
/// `dev`.
pub fn mesh_sdf(
    key: ChunkKey,
    spacing_m: f32,
    sdf: &[f32],
    mats: &[u8],
    scratch: &mut QuadMesh,
    dev: &dyn VolumeOffload,
) -> Result<ChunkMesh, MeshError> {
    let n = CHUNK_SAMPLES;
    let opts = MeshOptions {
        quad_min: [1; 3],
        quad_max: [1 + CHUNK_CELLS as u32; 3],
        ..MeshOptions::new([n; 3], spacing_m)
    };
    let attrs = SampleAttributes {
        materials: Some(mats),
        noise: None,
    };
    surface_nets_on(sdf, attrs, &opts, scratch, dev)?;
    Ok(assemble(key, spacing_m, scratch))
}

/// Drops unused vertices, moves positions to the chunk frame and adds skirts.
fn assemble(key: ChunkKey, spacing_m: f32, m: &QuadMesh) -> ChunkMesh {
    let mut remap = vec![NONE; m.vertex_count()];
    let mut out = ChunkMesh::default();
    let first = key.first_cell();
    let s = spacing_m as f64;
    for q in &m.quads {
        for &v in q {
            let r = &mut remap[v as usize];
            if *r != NONE {
                continue;
            }
            *r = out.positions.len() as u32;
            let (c, f) = (m.cells[v as usize], m.offsets[v as usize]);
            out.positions.push(std::array::from_fn(|k| {
                ((c[k] as f64 - 1.0 + f[k] as f64) * s) as f32
            }));
            out.normals.push(m.normals[v as usize]);
            out.materials.push(m.materials[v as usize]);
            out.global_cells
                .push(std::array::from_fn(|k| first[k] - 1 + c[k] as i64));
            out.offsets.push(f);
        }
    }
    out.quads = m
        .quads
        .iter()
        .map(|q| q.map(|v| remap[v as usize]))
        .collect();
    out.classes.clone_from(&m.classes);
    out.global_edges = m
        .edges
        .iter()
        .map(|e| std::array::from_fn(|k| first[k] - 1 + e[k] as i64))
        .collect();
    out.adjacency.clone_from(&m.adjacency);
    add_skirts(&mut out, spacing_m);
    out
}

/// Extrudes every boundary edge down by the skirt depth (module docs).
fn add_skirts(out: &mut ChunkMesh, spacing_m: f32) {
    let mut boundary = Vec::new();
    let mut step = 0.0f32;
    for (q, quad) in out.quads.iter().enumerate() {
        for k in 0..4 {
            if out.adjacency[q][k].quad == NONE {
                let (a, b) = (quad[k], quad[(k + 1) % 4]);
                boundary.push((a, b));
                step =
                    step.max((out.positions[a as usize][1] - out.positions[b as usize][1]).abs());
            }
        }
    }
    let depth = 2.0 * step + 8.0 * spacing_m;
    out.skirt_depth_m = if boundary.is_empty() { 0.0 } else { depth };
    let v = out.positions.len() as u32;
    let mut bottom = std::collections::BTreeMap::new();
    for &(a, b) in &boundary {
        let mut bottom_of = |i: u32, out: &mut ChunkMesh| {
            *bottom.entry(i).or_insert_with(|| {
                let p = out.positions[i as usize];
                out.skirt_positions.push([p[0], p[1] - depth, p[2]]);
                v + out.skirt_positions.len() as u32 - 1
            })
        };
        let (ba, bb) = (bottom_of(a, out), bottom_of(b, out));
        // The surface runs a → b; the skirt shares that edge the other way round.
        out.skirt_quads.push([b, a, ba, bb]);
    }
}
