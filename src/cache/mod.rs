//! The stage cache: finished tiles kept under the hash of their inputs, so a request for a tile
//! whose inputs have not changed runs no stage at all, and an edit recomputes only the tiles it
//! touches.
//!
//! **Key.** A 32-byte input hash, [`crate::scene::SceneInputs::tile`]: blake3 over the code
//! version, the seed, the world settings (canonical JSON), the key `(lod, x, z)`, the seam flags
//! and the scene elements whose `bbox` meets the tile's footprint grown by the blur radius + 2
//! vertex spacings. Equal hashes mean equal tiles; the cache never looks inside the value to
//! decide anything.
//!
//! **Tiers.** Memory first, then disk (optional), then compute:
//! - memory ([`memory`]): a [`Memo`] of `Arc<Tile>` bounded by a byte budget
//!   ([`DEFAULT_BUDGET_BYTES`] = 256 MiB unless told otherwise; `strata serve --memory-budget`
//!   gives it half of the process-wide budget). Each tile counts its [`tile_bytes`]: the `Tile`
//!   struct, the capacities of all its arrays (heights, normals, weights, materials, water depth
//!   and kind, volume-override marks) and [`ENTRY_OVERHEAD_BYTES`] of bookkeeping — about
//!   153 KiB for a 65×65 tile with 4 biomes and no water kinds, so the default holds some 1 700
//!   tiles. Inserting past the budget evicts the least recently used tiles; a tile larger than
//!   the whole budget is not kept (a budget of 0 disables the tier).
//! - disk ([`DiskCache`], [`disk`]; the file form is [`codec`]: `strata serve --cache-dir DIR`): one file per tile,
//!   `DIR/<first two hex digits>/<64 hex digits>.tile`, written to a temporary name and renamed,
//!   so readers see whole files or none; each file carries its hash and a blake3 checksum, and a
//!   file that fails either check is deleted and counted as an error. The disk tier is not
//!   bounded: delete the directory (or any files in it) at any time. Files named by an old
//!   [`crate::scene::TILE_CODE_VERSION`] are never read again.
//! - compute: `compute::Compute::tile_cached` runs the stages (`field`, `snap` strips,
//!   `finish`), counting each run here, and the result enters memory and disk.
//!
//! Concurrent requests for the same missing hash share one disk read or computation (the others
//! wait for it and count as `joined`; [`Memo`]'s single flight). Counters: memory hits, disk
//! hits, joined, misses (computed), stage runs per [`Stage`], evictions, disk writes and errors;
//! [`StageCache::stats`] reads them.
//!
//! [`Memo`] ([`memo`]) is the one cache abstraction of the process: the server's body, plan and
//! solution caches are `Memo`s too.
//!
//! No axum and no knowledge of HTTP: the memo, the in-flight cells and the disk tier's blocking
//! I/O (run on tokio's blocking pool) are all it does besides bookkeeping.

pub mod codec;
pub mod disk;
pub mod memo;
pub mod memory;

pub use codec::{decode_tile, encode_tile, DISK_FORMAT_VERSION, DISK_MAGIC};
pub use disk::DiskCache;
pub use memo::{Memo, MemoStats, Outcome, ENTRY_OVERHEAD_BYTES};
pub use memory::{tile_bytes, CacheStats, Stage, StageCache, DEFAULT_BUDGET_BYTES};

/// A tile's input hash (see the module docs).
pub type InputHash = [u8; 32];

/// What the tests of the cache tiers share.
#[cfg(test)]
pub(crate) mod test_util {
    use super::InputHash;
    use crate::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan};

    /// Tile `(2, x, -1)` of a classic world of seed 3.
    pub fn tile(x: i64) -> Tile {
        let plan = WorldPlan::new(3, WorldParams::classic()).expect("plan");
        synthesize(&plan, TileKey { lod: 2, x, z: -1 })
    }

    /// An input hash of one repeated byte.
    pub fn h(n: u8) -> InputHash {
        [n; 32]
    }
}
