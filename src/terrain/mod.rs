//! The world function: pure algorithms on plain data.
//!
//! **This module imports no tokio, axum or wgpu** (checked by `tests/architecture.rs`): everything
//! here is a deterministic function of `(seed, settings, key)` that any backend, test or tool can
//! call.

pub mod biome;
pub mod blur;
pub mod cancel;
pub mod earth;
pub mod fractal;
pub mod hash;
pub mod lattice;
pub mod noise;
pub mod offload;
pub mod plan;
pub mod poisson;
pub mod scatter;
pub mod texture;
pub mod tile;
pub mod world;

pub use plan::{WorldPlan, MAX_LOD, MIN_LOD, TILE_VERTEX_COUNT, TILE_VERTS};
pub use tile::{synthesize, FieldJob, Tile, TileKey};
pub use world::{Generator, WorldParams};
