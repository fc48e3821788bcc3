//! Ptex faces and their texture baking (issue 20): Becher et al., *Feature-based volumetric
//! terrain generation*, §4.6 (per-primitive Ptex parameters) and §4.7 (texture baking), with
//! Burley and Lacewell's per-face texture mapping and McDonald's real-time Ptex (the paper's
//! [24] and [23]).
//!
//! Every face owns a square texture of `res × res` texels (`res` a power of two from
//! [`MIN_RES`] to [`MAX_RES`]) in its local uv space, plus a one-texel border copied from its
//! neighbours through the uv transforms of [`crate::volume::mesh::ptex`], so a client can filter
//! across face edges with plain bilinear lookups. Pure: no I/O, no device, caller-owned output.
//!
//! - [`face`]: what a face is (a grid of control samples in a local uv space), the faces of a
//!   volume chunk (one per surface-nets quad) and of a height tile (a fixed grid of
//!   [`TILE_FACES`]² faces), stable face ids and the neighbour across every face edge;
//! - [`material`]: the procedural ground materials (albedo, roughness, relief, noise
//!   displacement), deterministic from their parameters;
//! - [`image`]: uploaded PNGs decoded with their mip chains, sampled bilinearly;
//! - [`decal`]: decals, top-down images baked over the materials;
//! - [`spec`]: the `materials` and `decals` scene elements and the set a world's make;
//! - [`noise`]: the hashed value noise the materials and the displacement read;
//! - [`bake`]: the §4.7 bake of a face's interior texels (the CPU reference of
//!   `shaders/ptex.wgsl`);
//! - [`border`]: the one-texel borders taken from the neighbours;
//! - [`budget`]: the level-of-detail budget: a vista level for every face, detail levels for
//!   the nearest faces in view, slots reused;
//! - [`pages`]: the baked texels of a set of faces, the layout of `api/ptex_pages_v1.md`;
//! - [`select`]: baking chosen faces of a set with their borders (a stream session's pages).
//!
//! Units: metres, world axes x east, y up, z south.

pub mod bake;
pub mod border;
pub mod budget;
pub mod decal;
pub mod face;
pub mod image;
pub mod material;
pub mod noise;
pub mod pages;
pub mod select;
pub mod spec;

pub use bake::{bake, bake_interior};
pub use face::{Face, FaceSet, Link, Sample, Span, TILE_FACES, TILE_FACE_CELLS};
pub use material::{Material, MaterialSet};
pub use pages::Pages;

/// Smallest face resolution, texels per side (the paper's vista level).
pub const MIN_RES: u32 = 8;
/// Largest face resolution, texels per side (the paper's highest detail level).
pub const MAX_RES: u32 = 256;

/// Most texels one request may bake (`res² ×` faces baked, neighbours included): a height tile's
/// 16 faces and up to 16 neighbouring faces at 256².
pub const MAX_PTEX_TEXELS: u64 = 1 << 21;

/// Whether `res` is a face resolution: a power of two in `MIN_RES..=MAX_RES`.
pub fn valid_res(res: u32) -> bool {
    res.is_power_of_two() && (MIN_RES..=MAX_RES).contains(&res)
}
