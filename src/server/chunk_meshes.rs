//! Meshed volume chunks by the hash of their inputs ([`ChunkMeshCache`]), within their share of
//! `--memory-budget` ([`super::budget`]).
//!
//! A chunk's mesh ([`crate::volume::chunk::ChunkMesh`]) is read by four products: the chunk
//! route's three formats, the stream's chunk frames, the chunk Ptex route and the stream
//! sessions' Ptex batches, which bake a chunk's quads one level and at most
//! [`crate::stream::ptex::BATCH_TEXELS`] texels at a time. Each of them used to mesh the chunk
//! again, a session's pages once per batch: the README's arch chunk (1,919 quads) answered its
//! `.bin` in 11 ms, most of it meshing, against a batch's 4 ms of baking; from this cache the
//! `.bin` takes under 1 ms (release build, this machine). They now share one mesh per input
//! hash.
//!
//! The key ([`mesh_key`]) is a blake3 of what meshing reads: the chunk's key, the input hashes of
//! the height tiles under it ([`super::view::WorldView::tile_hash`]: the code version, the seed,
//! the world settings and the surface elements meeting each tile), the digests of the `strata`
//! elements meeting its columns and the keys of the solved volume regions meeting its box
//! ([`super::volumes::volume_key`]). Meshing is a pure function of those, so a cached mesh is the
//! one meshing again would give, and an edit elsewhere in the world keeps it.

use super::error::AppError;
use super::view::WorldView;
use crate::cache::{Memo, MemoStats};
use crate::volume::chunk::{ChunkKey, ChunkMesh};
use std::future::Future;
use std::sync::Arc;

/// Default byte budget of meshed chunks (the share of [`super::budget::MemoryBudget`]).
pub const CHUNK_MESH_CACHE_BYTES: usize = 32 << 20;

/// Meshed chunks by input hash.
pub struct ChunkMeshCache {
    memo: Memo<[u8; 32], Arc<ChunkMesh>>,
}

impl std::fmt::Debug for ChunkMeshCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ChunkMeshCache")
            .field("budget", &self.memo.budget_bytes())
            .finish()
    }
}

impl Default for ChunkMeshCache {
    fn default() -> Self {
        Self::new(CHUNK_MESH_CACHE_BYTES)
    }
}

/// The bytes a mesh's arrays hold (their capacities).
fn weight(mesh: &ChunkMesh) -> usize {
    fn bytes<T>(v: &Vec<T>) -> usize {
        v.capacity() * std::mem::size_of::<T>()
    }
    std::mem::size_of::<ChunkMesh>()
        + bytes(&mesh.positions)
        + bytes(&mesh.normals)
        + bytes(&mesh.materials)
        + bytes(&mesh.global_cells)
        + bytes(&mesh.offsets)
        + bytes(&mesh.quads)
        + bytes(&mesh.classes)
        + bytes(&mesh.global_edges)
        + bytes(&mesh.adjacency)
        + bytes(&mesh.skirt_positions)
        + bytes(&mesh.skirt_quads)
        + bytes(&mesh.geology)
}

impl ChunkMeshCache {
    /// An empty cache of at most `budget_bytes`.
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            memo: Memo::new(budget_bytes, |_, mesh: &Arc<ChunkMesh>| weight(mesh)),
        }
    }

    /// Hits, misses, evictions and bytes.
    pub fn stats(&self) -> MemoStats {
        self.memo.stats()
    }

    /// The mesh of input hash `key`: from the cache, from a meshing of the same key under way,
    /// or from `mesh` (a failure is not kept).
    pub(super) async fn get<F, Fut>(
        &self,
        key: [u8; 32],
        mesh: F,
    ) -> Result<Arc<ChunkMesh>, AppError>
    where
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<ChunkMesh, AppError>>,
    {
        let (mesh, _) = self
            .memo
            .try_get_or_compute_async(key, || async { mesh().await.map(Arc::new) })
            .await?;
        Ok(mesh)
    }
}

/// The input hash of chunk `key` of the world `view` (see the module docs).
pub(super) fn mesh_key(view: &WorldView, key: ChunkKey) -> [u8; 32] {
    let spacing_m = view.plan.lods[key.lod as usize].spacing_m;
    let mut h = blake3::Hasher::new();
    h.update(b"strata.chunk-mesh\0");
    h.update(&key.lod.to_le_bytes());
    for c in [key.x, key.y, key.z] {
        h.update(&c.to_le_bytes());
    }
    for tile in super::chunks::tile_keys(key) {
        h.update(&view.tile_hash(tile, [false; 4]));
    }
    let rect = super::chunks::columns_rect(&view.plan, key, spacing_m);
    for s in view.inputs.strata() {
        if s.rect().intersects(&rect) {
            h.update(&s.digest);
        }
    }
    let (lo, hi) = super::chunks::chunk_box(key, spacing_m);
    for v in view.inputs.volumes_meeting(lo, hi) {
        let (seed, digest) = super::volumes::volume_key(view, &v);
        h.update(&seed.to_le_bytes());
        h.update(&digest);
    }
    *h.finalize().as_bytes()
}
