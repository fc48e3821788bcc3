//! Ptex faces (§4.6): what a face is, the faces of a volume chunk and of a height tile, their
//! stable ids and the neighbour across every face edge.
//!
//! # A face
//!
//! A face is an `n × n` grid of control samples over its local uv square (`n = 2` for a
//! surface-nets quad, its four vertices; `n = 17` for a height-tile face, 16 × 16 lattice cells);
//! a texel at `(u, v)` reads the bilinear interpolation of the grid. Sample `(iu, iv)` is
//! [`FaceSet::samples`]`[first + iv·n + iu]`, at `uv = (iu, iv)/(n − 1)`. Positions are metres
//! relative to the face's anchor `A·256 m` ([`super::noise::ANCHOR_M`]), so each face's texels
//! are a function of the face alone, whichever set it is baked in.
//!
//! Edges follow [`crate::volume::mesh`]: edge `k` runs from corner `k` to corner `k + 1` of
//! `(0,0), (1,0), (1,1), (0,1)` (0: `v = 0`, 1: `u = 1`, 2: `v = 1`, 3: `u = 0`), and each edge
//! has a [`Link`] to the neighbouring face: its edge `k'`, the index `4k + k'` into
//! [`crate::volume::mesh::UV_TRANSFORMS`], and the part of the neighbour's edge it covers.
//!
//! # Volume chunks: one face per quad
//!
//! Face `q` of chunk `(lod, x, y, z)` is the chunk's quad `q` (the order of
//! `api/chunk_format_v1.md`, a pure function of the key and version), its grid the quad's
//! vertices `v0, v1, v3, v2` as samples `(0,0), (1,0), (0,1), (1,1)`; its class and uv space are
//! the quad's. Neighbours are the quad's Ptex adjacency; a neighbour owned by another chunk is
//! none, and that edge's border repeats the face's own edge texels.
//!
//! # Height tiles: a fixed grid of 4 × 4 faces per tile
//!
//! Face `(fi, fj)` of tile `(lod, x, z)` (`fi` east, `fj` south, both `0..4`, id `4·fj + fi`)
//! covers the tile's lattice cells `16·fi … 16·fi + 16` (x) by `16·fj … 16·fj + 16` (z): `u`
//! runs south (+z) and `v` east (+x), so `u × v` faces up like a `+Y` quad. Its global face
//! coordinates are `(lod, 4x + fi, 4z + fj)`. A grid rather than one face per tile: the
//! level-of-detail budget assigns resolutions per face by distance, and a whole tile (64 cells,
//! 64 m at LOD 0) spans too wide a range of distances near the viewer; at 256² texels a face
//! gives 16 texels per lattice cell at every LOD, the density of a 256² volume quad over 16
//! cells. Edge 0 is west, 1 south, 2 east, 3 north; the neighbour across edge `k` is the face
//! across that side, at edge `k + 2 (mod 4)` (transforms 2, 7, 8, 13). On a tile side drawn
//! snapped to the coarser LOD (`?seams=n,e,s,w`, as the tile routes), the faces along it link to
//! the coarser tile's face, two LOD-`k` faces wide, whose edge they cover half of ([`Span`]).

use super::material::MaterialSet;
use super::noise::ANCHOR_M;
use crate::terrain::plan::TILE_QUADS;
use crate::terrain::texture::{TexelRule, SURFACE_INPUTS};
use crate::terrain::tile::{surface_inputs, Tile, TileKey};
use crate::terrain::WorldPlan;
use crate::terrain::TILE_VERTS;
use crate::volume::chunk::{ChunkKey, ChunkMesh};
use crate::volume::mesh::{Neighbor, NONE};
use std::collections::BTreeMap;

/// Height-tile faces per tile side.
pub const TILE_FACES: usize = 4;
/// Lattice cells per height-tile face side.
pub const TILE_FACE_CELLS: usize = TILE_QUADS as usize / TILE_FACES;
/// "No face" in [`Link::face`].
pub const NO_FACE: u32 = u32::MAX;

/// One control sample of a face.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sample {
    /// Position relative to the face's anchor, metres.
    pub position: [f32; 3],
    /// Material id (an index into the [`MaterialSet`]).
    pub material: u32,
    /// Unit outward normal.
    pub normal: [f32; 3],
    /// Amplitude of the noise displacement here, metres.
    pub noise_m: f32,
}

/// One face: its anchor and its grid of samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Face {
    /// Anchor, in units of 256 m: sample positions are relative to `anchor·256 m`.
    pub anchor: [i32; 3],
    /// Index of sample `(0, 0)` in [`FaceSet::samples`].
    pub first: u32,
    /// Samples per side (at least 2).
    pub n: u32,
    /// Nominal edge length, metres (a texel is `size_m / res`); the finest noise octave is the
    /// one at most half a texel wide.
    pub size_m: f32,
}

/// Which part of the neighbour's edge an edge covers, in the neighbour's edge parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Span {
    /// The whole edge (same size).
    Whole,
    /// `[0, ½]`: the neighbour is twice as large (a coarser height tile's face).
    FirstHalf,
    /// `[½, 1]`.
    SecondHalf,
}

/// The neighbour across one face edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Link {
    /// Index of the neighbouring face in the set, or [`NO_FACE`].
    pub face: u32,
    /// The neighbour's edge `k'` (0..4).
    pub edge: u8,
    /// `4·k + k'`, an index into [`crate::volume::mesh::UV_TRANSFORMS`].
    pub transform: u8,
    /// The part of the neighbour's edge this edge covers.
    pub span: Span,
}

impl Link {
    /// No neighbour: the border repeats the face's own edge texels.
    pub const NONE: Link = Link {
        face: NO_FACE,
        edge: 0,
        transform: 0,
        span: Span::Whole,
    };
}

/// Faces to bake: the first [`FaceSet::output`] are the product's, the others only lend their
/// texels to borders.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FaceSet {
    /// The faces.
    pub faces: Vec<Face>,
    /// Their control samples.
    pub samples: Vec<Sample>,
    /// The neighbour across each edge of each face.
    pub links: Vec<[Link; 4]>,
    /// How many leading faces are the product's.
    pub output: usize,
    /// Per sample, the inputs of the texel weighting function
    /// ([`crate::terrain::texture::surface_inputs`]) where the faces are height tiles of a world
    /// with `texturing.ptex_blend: 2`: the bake then weighs the materials of each texel by
    /// [`FaceSet::rule`] at the texel ([`super::bake`], step 1). Empty otherwise (volume chunks,
    /// stored worlds), where a texel blends its samples' materials.
    pub surface: Vec<[f32; SURFACE_INPUTS]>,
    /// The thresholds the bake evaluates with [`FaceSet::surface`].
    pub rule: Option<TexelRule>,
}

impl FaceSet {
    /// The thresholds the bake weighs the texels' materials by, where every sample has texel
    /// inputs ([`FaceSet::surface`]); `None` otherwise, where texels blend their samples'
    /// materials.
    pub fn texel_rule(&self) -> Option<&TexelRule> {
        self.rule
            .as_ref()
            .filter(|_| self.surface.len() == self.samples.len())
    }

    /// Adds a face whose samples are `grid` (`n × n`, `iu` fastest) at world positions
    /// `world(i)` (metres, `f64`), anchored at the floor of its first sample over 256 m.
    fn push_face(
        &mut self,
        n: usize,
        size_m: f32,
        mut sample: impl FnMut(usize) -> ([f64; 3], [f32; 3], u32, f32),
    ) {
        let first = self.samples.len() as u32;
        let p0 = sample(0).0;
        let anchor = p0.map(|c| (c / ANCHOR_M).floor() as i32);
        let origin = anchor.map(|a| f64::from(a) * ANCHOR_M);
        for i in 0..n * n {
            let (p, normal, material, noise_m) = sample(i);
            self.samples.push(Sample {
                position: std::array::from_fn(|c| (p[c] - origin[c]) as f32),
                material,
                normal,
                noise_m,
            });
        }
        self.faces.push(Face {
            anchor,
            first,
            n: n as u32,
            size_m,
        });
    }
}

/// What [`quad_faces`] reads of a quad mesh, by vertex index.
pub struct QuadSource<'a> {
    /// Quads (vertex indices in the class's order).
    pub quads: &'a [[u32; 4]],
    /// Ptex adjacency of each quad.
    pub adjacency: &'a [[Neighbor; 4]],
    /// World position of each vertex, metres.
    pub world: &'a dyn Fn(u32) -> [f64; 3],
    /// Unit normals.
    pub normals: &'a [[f32; 3]],
    /// Material ids.
    pub materials: &'a [u8],
    /// Cell size, metres (a face's nominal size).
    pub spacing_m: f32,
}

impl std::fmt::Debug for QuadSource<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("QuadSource")
            .field("quads", &self.quads.len())
            .field("spacing_m", &self.spacing_m)
            .finish_non_exhaustive()
    }
}

/// One face per quad, in quad order, all of them output.
pub fn quad_faces(src: &QuadSource<'_>, mats: &MaterialSet) -> FaceSet {
    let mut set = FaceSet::default();
    for quad in src.quads {
        // Samples (0,0), (1,0), (0,1), (1,1) are vertices 0, 1, 3, 2.
        let order = [quad[0], quad[1], quad[3], quad[2]];
        set.push_face(2, src.spacing_m, |i| {
            let v = order[i];
            let m = u32::from(src.materials[v as usize]);
            (
                (src.world)(v),
                src.normals[v as usize],
                m,
                mats.materials[mats.index(m)].noise_m,
            )
        });
    }
    set.links = src
        .adjacency
        .iter()
        .map(|row| {
            row.map(|nb| {
                if nb.quad == NONE {
                    Link::NONE
                } else {
                    Link {
                        face: nb.quad,
                        edge: nb.edge,
                        transform: nb.transform,
                        span: Span::Whole,
                    }
                }
            })
        })
        .collect();
    set.output = set.faces.len();
    set
}

/// The faces of a meshed volume chunk (cells of `spacing_m` metres): one per quad.
pub fn chunk_faces(mesh: &ChunkMesh, spacing_m: f32, mats: &MaterialSet) -> FaceSet {
    let s = f64::from(spacing_m);
    let world = |v: u32| -> [f64; 3] {
        let (c, o) = (mesh.global_cells[v as usize], mesh.offsets[v as usize]);
        std::array::from_fn(|k| (c[k] as f64 + f64::from(o[k])) * s)
    };
    quad_faces(
        &QuadSource {
            quads: &mesh.quads,
            adjacency: &mesh.adjacency,
            world: &world,
            normals: &mesh.normals,
            materials: &mesh.materials,
            spacing_m,
        },
        mats,
    )
}

/// Global coordinates of a height-tile face: `(lod, 4·x + fi, 4·z + fj)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TileFaceKey {
    /// Level of detail.
    pub lod: u32,
    /// Face column (east is +x).
    pub fx: i64,
    /// Face row (south is +z).
    pub fz: i64,
}

impl TileFaceKey {
    /// The tile holding the face.
    pub fn tile(self) -> TileKey {
        let t = TILE_FACES as i64;
        TileKey {
            lod: self.lod,
            x: self.fx.div_euclid(t),
            z: self.fz.div_euclid(t),
        }
    }

    /// The face's id within its tile, `4·fj + fi`.
    pub fn id(self) -> u32 {
        let t = TILE_FACES as i64;
        (self.fz.rem_euclid(t) * t + self.fx.rem_euclid(t)) as u32
    }
}

/// A face of a volume chunk: quad `quad` of chunk `chunk` (face id = quad index,
/// `api/ptex_pages_v1.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ChunkFaceKey {
    /// The chunk.
    pub chunk: ChunkKey,
    /// The quad's index in the chunk's `quads`.
    pub quad: u32,
}

/// The step across edge `k` of a tile face, `(dx, dz)` in faces.
const TILE_EDGE_STEP: [(i64, i64); 4] = [(-1, 0), (0, 1), (1, 0), (0, -1)];
/// The `?seams` flag (`n, e, s, w`) of the tile side edge `k` faces.
const TILE_EDGE_SEAM: [usize; 4] = [3, 2, 1, 0];

/// The faces of a height tile and their neighbours, before any sample is read.
#[derive(Clone, Debug, PartialEq)]
pub struct TileFacePlan {
    /// The tile's 16 faces in id order, then the neighbouring faces their borders read.
    pub faces: Vec<TileFaceKey>,
    /// The links of every face (only the tile's own faces have any).
    pub links: Vec<[Link; 4]>,
}

/// The face set of tile `key` of `plan` with its east side snapped to the LOD above (so a
/// border reads a coarser neighbour), its tiles synthesised here: the unit tests' fixture.
#[cfg(test)]
pub(crate) fn test_face_set(
    plan: &crate::terrain::WorldPlan,
    key: TileKey,
    mats: &MaterialSet,
) -> FaceSet {
    let faces = TileFacePlan::new(key, [false, true, false, false], 12);
    let tiles: Vec<Tile> = faces
        .tiles()
        .into_iter()
        .map(|t| crate::terrain::synthesize(plan, t))
        .collect();
    faces.build(|t| tiles.iter().find(|x| x.key == t), mats, plan)
}

impl TileFacePlan {
    /// The faces of tile `key` drawn with `seams` (`n, e, s, w`: the sides snapped to the LOD
    /// above, ignored when `key.lod` is `max_lod`).
    pub fn new(key: TileKey, seams: [bool; 4], max_lod: u32) -> Self {
        let t = TILE_FACES as i64;
        let own: Vec<TileFaceKey> = (0..t * t)
            .map(|id| TileFaceKey {
                lod: key.lod,
                fx: key.x * t + id % t,
                fz: key.z * t + id / t,
            })
            .collect();
        let mut extra: BTreeMap<TileFaceKey, ()> = BTreeMap::new();
        let mut wanted = Vec::new();
        for f in &own {
            let mut row = [(f.lod, 0i64, 0i64, Span::Whole); 4];
            for (k, slot) in row.iter_mut().enumerate() {
                let (dx, dz) = TILE_EDGE_STEP[k];
                let (nx, nz) = (f.fx + dx, f.fz + dz);
                let n = TileFaceKey {
                    lod: f.lod,
                    fx: nx,
                    fz: nz,
                };
                let crosses = n.tile() != key;
                *slot = if crosses && seams[TILE_EDGE_SEAM[k]] && key.lod < max_lod {
                    // The coarser face is two faces wide; the along-edge face index's parity
                    // says which half of its edge this one covers, in the coarser edge's
                    // parameter (edges 0 and 1 run toward +z and +x, edges 2 and 3 back).
                    let along = if k % 2 == 0 { nz } else { nx };
                    let k2 = (k + 2) % 4;
                    let low = along.rem_euclid(2) == 0;
                    let span = if low == (k2 < 2) {
                        Span::FirstHalf
                    } else {
                        Span::SecondHalf
                    };
                    (f.lod + 1, nx.div_euclid(2), nz.div_euclid(2), span)
                } else {
                    (f.lod, nx, nz, Span::Whole)
                };
                let target = TileFaceKey {
                    lod: slot.0,
                    fx: slot.1,
                    fz: slot.2,
                };
                if target.lod != key.lod || target.tile() != key {
                    extra.insert(target, ());
                }
            }
            wanted.push(row);
        }
        let mut faces = own.clone();
        faces.extend(extra.keys().copied());
        let index: BTreeMap<TileFaceKey, u32> = faces
            .iter()
            .enumerate()
            .map(|(i, f)| (*f, i as u32))
            .collect();
        let mut links: Vec<[Link; 4]> = wanted
            .iter()
            .map(|row| {
                std::array::from_fn(|k| {
                    let (lod, fx, fz, span) = row[k];
                    let k2 = (k + 2) % 4;
                    Link {
                        face: index[&TileFaceKey { lod, fx, fz }],
                        edge: k2 as u8,
                        transform: (4 * k + k2) as u8,
                        span,
                    }
                })
            })
            .collect();
        links.resize(faces.len(), [Link::NONE; 4]);
        Self { faces, links }
    }

    /// The tiles the faces lie in (the tile itself first), without repeats.
    pub fn tiles(&self) -> Vec<TileKey> {
        let mut out: Vec<TileKey> = Vec::new();
        for f in &self.faces {
            let t = f.tile();
            if !out.contains(&t) {
                out.push(t);
            }
        }
        out
    }

    /// The face set, reading each face's samples from its tile (`tile(key)`) of the world
    /// `plan` (which says how the bake weighs the tiles' materials: [`FaceSet::surface`]); a
    /// face whose tile is missing is dropped with the links to it (those borders repeat their
    /// own edge).
    pub fn build<'a>(
        &self,
        tile: impl Fn(TileKey) -> Option<&'a Tile>,
        mats: &MaterialSet,
        plan: &WorldPlan,
    ) -> FaceSet {
        let mut set = FaceSet::default();
        let mut remap = vec![NO_FACE; self.faces.len()];
        // Each tile's texel inputs, computed once for the faces it holds.
        let mut inputs: Vec<(TileKey, Option<Vec<[f32; SURFACE_INPUTS]>>)> = Vec::new();
        for (i, f) in self.faces.iter().enumerate() {
            let Some(t) = tile(f.tile()) else { continue };
            let at = match inputs.iter().position(|(k, _)| *k == t.key) {
                Some(at) => at,
                None => {
                    inputs.push((t.key, surface_inputs(plan, t)));
                    inputs.len() - 1
                }
            };
            remap[i] = set.faces.len() as u32;
            push_tile_face(&mut set, t, *f, mats, inputs[at].1.as_deref());
        }
        if !set.surface.is_empty() {
            set.rule = Some(plan.texture.texel_rule());
        }
        for (i, row) in self.links.iter().enumerate() {
            if remap[i] == NO_FACE {
                continue;
            }
            set.links
                .push(row.map(|l| match remap.get(l.face as usize) {
                    Some(&face) if face != NO_FACE => Link { face, ..l },
                    _ => Link::NONE,
                }));
        }
        set.output = (TILE_FACES * TILE_FACES).min(set.faces.len());
        set
    }
}

/// Appends face `f` of tile `t` (its 17 × 17 lattice samples), and their texel inputs where
/// the tile has them (`surface`, by tile vertex).
fn push_tile_face(
    set: &mut FaceSet,
    t: &Tile,
    f: TileFaceKey,
    mats: &MaterialSet,
    surface: Option<&[[f32; SURFACE_INPUTS]]>,
) {
    let c = TILE_FACE_CELLS;
    let n = c + 1;
    let t_faces = TILE_FACES as i64;
    let (fi, fj) = (
        f.fx.rem_euclid(t_faces) as usize,
        f.fz.rem_euclid(t_faces) as usize,
    );
    let s = f64::from(t.spacing_m);
    let (gx0, gz0) = (t.key.x * TILE_QUADS, t.key.z * TILE_QUADS);
    set.push_face(n, t.spacing_m * c as f32, |k| {
        // Sample (iu, iv): u runs south (j), v east (i).
        let (iu, iv) = (k % n, k / n);
        let (i, j) = (fi * c + iv, fj * c + iu);
        let v = j * TILE_VERTS + i;
        let m = t.materials[v];
        (
            [
                (gx0 + i as i64) as f64 * s,
                f64::from(t.heights[v]),
                (gz0 + j as i64) as f64 * s,
            ],
            t.normals[v],
            u32::from(m),
            mats.materials[mats.index(u32::from(m))].noise_m,
        )
    });
    if let Some(surface) = surface {
        for k in 0..n * n {
            let (iu, iv) = (k % n, k / n);
            set.surface
                .push(surface[(fj * c + iu) * TILE_VERTS + fi * c + iv]);
        }
    }
}
