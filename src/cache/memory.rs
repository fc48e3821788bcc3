//! The memory tier of the stage cache: finished tiles in a [`Memo`] under their input hash,
//! in front of the optional [`DiskCache`] (see the [module docs](super)).

use super::memo::{Memo, Outcome, ENTRY_OVERHEAD_BYTES};
use super::{DiskCache, InputHash};
use crate::terrain::Tile;
use std::future::Future;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// Default byte budget of the memory tier: 256 MiB.
pub const DEFAULT_BUDGET_BYTES: usize = 256 << 20;

/// A stage of tile synthesis, as counted by the cache.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// The tile's 67×67 field (heights and biome weights with a one-vertex margin).
    Field,
    /// One seam strip: 33 samples of the next coarser LOD along an edge flagged in `seams`.
    Snap,
    /// Normals, materials, water, skirts and seam snapping of a field into a tile.
    Finish,
}

impl Stage {
    /// All stages, in pipeline order.
    pub const ALL: [Stage; 3] = [Stage::Field, Stage::Snap, Stage::Finish];

    /// The stage's name in metrics: `field`, `snap`, `finish`.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Field => "field",
            Stage::Snap => "snap",
            Stage::Finish => "finish",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// A snapshot of the counters and sizes of a [`StageCache`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheStats {
    /// Lookups answered from memory.
    pub hits: u64,
    /// Lookups answered from disk.
    pub disk_hits: u64,
    /// Lookups that waited for a computation of the same hash already under way.
    pub joined: u64,
    /// Lookups that found nothing and computed the tile.
    pub misses: u64,
    /// Runs of each stage, indexed like [`Stage::ALL`] (`field`, `snap`, `finish`).
    pub runs: [u64; 3],
    /// Time spent in each stage (wall clock, including queueing on the blocking pool), µs.
    pub micros: [u64; 3],
    /// Tiles evicted from memory to stay within the budget.
    pub evictions: u64,
    /// Tiles in memory.
    pub entries: u64,
    /// Bytes counted in memory ([`tile_bytes`] of each entry).
    pub bytes: u64,
    /// The memory budget, bytes.
    pub budget_bytes: u64,
    /// Files written to the disk tier.
    pub disk_writes: u64,
    /// Disk tier failures (unreadable, corrupt or unwritable files).
    pub disk_errors: u64,
}

impl CacheStats {
    /// Runs of one stage.
    pub fn runs_of(&self, stage: Stage) -> u64 {
        self.runs[stage.index()]
    }

    /// Seconds spent in one stage.
    pub fn seconds_of(&self, stage: Stage) -> f64 {
        self.micros[stage.index()] as f64 * 1e-6
    }
}

/// What a tile holds: the `Tile` struct and the capacities of all its arrays.
fn tile_payload_bytes(t: &Tile) -> usize {
    std::mem::size_of::<Tile>()
        + t.heights.capacity() * 4
        + t.normals.capacity() * 12
        + t.weights.capacity() * 4
        + t.materials.capacity()
        + t.water_depth.capacity() * 4
        + t.water_kind.capacity()
        + t.volume_override.capacity()
}

/// Bytes a tile is counted for in the memory budget: what it holds (the `Tile` struct and the
/// capacities of all its arrays, the water kinds and volume-override marks included) and
/// [`ENTRY_OVERHEAD_BYTES`] of bookkeeping.
pub fn tile_bytes(t: &Tile) -> usize {
    tile_payload_bytes(t) + ENTRY_OVERHEAD_BYTES
}

#[derive(Default)]
struct Counters {
    disk_hits: AtomicU64,
    misses: AtomicU64,
    runs: [AtomicU64; 3],
    micros: [AtomicU64; 3],
}

/// The bounded tile cache (see the module docs). Share it behind an `Arc`.
pub struct StageCache {
    memory: Memo<InputHash, Arc<Tile>>,
    disk: Option<Arc<DiskCache>>,
    counters: Counters,
}

impl std::fmt::Debug for StageCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("StageCache")
            .field("budget", &self.memory.budget_bytes())
            .field("disk", &self.disk.as_ref().map(|d| d.dir()))
            .finish_non_exhaustive()
    }
}

impl Default for StageCache {
    fn default() -> Self {
        Self::new(DEFAULT_BUDGET_BYTES)
    }
}

impl StageCache {
    /// A memory-only cache with a budget of `budget_bytes`.
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            memory: Memo::new(budget_bytes, |_, t: &Arc<Tile>| tile_payload_bytes(t)),
            disk: None,
            counters: Counters::default(),
        }
    }

    /// Adds the disk tier in `dir` (created if missing).
    pub fn with_disk(mut self, dir: impl Into<PathBuf>) -> std::io::Result<Self> {
        self.disk = Some(Arc::new(DiskCache::open(dir)?));
        Ok(self)
    }

    /// The memory budget, bytes.
    pub fn budget_bytes(&self) -> usize {
        self.memory.budget_bytes()
    }

    /// The disk tier's directory, if there is one.
    pub fn disk_dir(&self) -> Option<&Path> {
        self.disk.as_ref().map(|d| d.dir())
    }

    /// The tile under `hash` if it is in memory (marks it recently used; counts nothing).
    pub fn get(&self, hash: &InputHash) -> Option<Arc<Tile>> {
        self.memory.get(hash)
    }

    /// Whether memory holds `hash` (marks nothing, counts nothing).
    pub fn contains(&self, hash: &InputHash) -> bool {
        self.memory.contains(hash)
    }

    /// Puts a tile in memory under `hash`, evicting the least recently used beyond the budget.
    pub fn insert(&self, hash: InputHash, tile: Arc<Tile>) {
        self.memory.insert(hash, tile);
    }

    /// Applies the memory tier's pending bookkeeping (recency, evictions) now.
    pub fn run_pending_tasks(&self) {
        self.memory.run_pending_tasks();
    }

    /// Counts one run of `stage`.
    pub fn record_run(&self, stage: Stage, took: std::time::Duration) {
        self.counters.runs[stage.index()].fetch_add(1, Ordering::Relaxed);
        self.counters.micros[stage.index()].fetch_add(took.as_micros() as u64, Ordering::Relaxed);
    }

    /// The counters and sizes now.
    pub fn stats(&self) -> CacheStats {
        let c = &self.counters;
        let m = self.memory.stats();
        let (disk_writes, disk_errors) = self
            .disk
            .as_ref()
            .map(|d| {
                (
                    d.writes.load(Ordering::Relaxed),
                    d.errors.load(Ordering::Relaxed),
                )
            })
            .unwrap_or_default();
        CacheStats {
            hits: m.hits,
            disk_hits: c.disk_hits.load(Ordering::Relaxed),
            joined: m.joined,
            misses: c.misses.load(Ordering::Relaxed),
            runs: std::array::from_fn(|i| c.runs[i].load(Ordering::Relaxed)),
            micros: std::array::from_fn(|i| c.micros[i].load(Ordering::Relaxed)),
            evictions: m.evictions,
            entries: m.entries,
            bytes: m.bytes,
            budget_bytes: m.budget_bytes,
            disk_writes,
            disk_errors,
        }
    }

    /// The tile under `hash`: from memory, else from disk, else from `compute` (whose result is
    /// kept in memory and written to disk). Concurrent callers with the same hash share one disk
    /// read or computation.
    pub async fn get_or_compute<F, Fut>(&self, hash: InputHash, compute: F) -> Arc<Tile>
    where
        F: FnOnce() -> Fut,
        Fut: Future<Output = Tile>,
    {
        let mut from_disk = false;
        let (tile, outcome) = self
            .memory
            .get_or_compute_async(hash, || async {
                if let Some(t) = self.read_disk(hash).await {
                    from_disk = true;
                    return Arc::new(t);
                }
                let t = Arc::new(compute().await);
                self.write_disk(hash, t.clone()).await;
                t
            })
            .await;
        if outcome == Outcome::Computed {
            let counter = if from_disk {
                &self.counters.disk_hits
            } else {
                &self.counters.misses
            };
            counter.fetch_add(1, Ordering::Relaxed);
        }
        tile
    }

    async fn read_disk(&self, hash: InputHash) -> Option<Tile> {
        let disk = self.disk.clone()?;
        tokio::task::spawn_blocking(move || disk.read(&hash))
            .await
            .ok()
            .flatten()
    }

    async fn write_disk(&self, hash: InputHash, tile: Arc<Tile>) {
        if let Some(disk) = self.disk.clone() {
            // A failed write only costs a later recomputation; `write` counts and logs it.
            let _ = tokio::task::spawn_blocking(move || disk.write(&hash, &tile)).await;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cache::test_util::{h, tile};

    #[test]
    fn lru_within_the_byte_budget() {
        let t = Arc::new(tile(0));
        let one = tile_bytes(&t);
        // The module docs' figure: about 153 KiB with the default 4 biomes.
        assert_eq!(t.biome_count, 4);
        assert!((150 << 10..156 << 10).contains(&one), "{one}");
        let c = StageCache::new(2 * one + one / 2);
        c.insert(h(1), t.clone());
        c.insert(h(2), t.clone());
        c.run_pending_tasks();
        assert!(c.get(&h(1)).is_some()); // 1 is now more recent than 2
        c.run_pending_tasks();
        c.insert(h(3), t.clone());
        c.run_pending_tasks();
        assert!(c.contains(&h(1)) && c.contains(&h(3)) && !c.contains(&h(2)));
        let s = c.stats();
        assert_eq!((s.entries, s.bytes, s.evictions), (2, 2 * one as u64, 1));
        // Re-inserting a key replaces it without double counting.
        c.insert(h(3), t.clone());
        assert_eq!(c.stats().bytes, 2 * one as u64);
        // Larger than the budget: not kept.
        let tiny = StageCache::new(one - 1);
        tiny.insert(h(1), t);
        assert_eq!(tiny.stats().entries, 0);
    }

    #[test]
    fn tile_bytes_counts_every_array() {
        let mut t = tile(0);
        t.volume_override = Vec::new();
        t.water_kind = Vec::new();
        let before = tile_bytes(&t);
        t.volume_override = vec![1; 4225];
        t.water_kind = vec![2; 4225];
        assert_eq!(tile_bytes(&t), before + 2 * 4225);
        t.heights.reserve_exact(100);
        assert_eq!(
            tile_bytes(&t),
            before + 2 * 4225 + 4 * (t.heights.capacity() - t.heights.len())
        );
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 4)]
    async fn eight_concurrent_misses_of_one_tile_compute_once() {
        let c = Arc::new(StageCache::default());
        let runs = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let barrier = Arc::new(tokio::sync::Barrier::new(8));
        let tasks: Vec<_> = (0..8)
            .map(|_| {
                let (c, runs, barrier) = (c.clone(), runs.clone(), barrier.clone());
                tokio::spawn(async move {
                    barrier.wait().await;
                    c.get_or_compute(h(4), || async {
                        runs.fetch_add(1, Ordering::SeqCst);
                        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
                        tile(4)
                    })
                    .await
                })
            })
            .collect();
        for t in tasks {
            t.await.expect("task");
        }
        assert_eq!(runs.load(Ordering::SeqCst), 1, "one computation");
        let s = c.stats();
        assert_eq!(s.misses, 1);
        assert_eq!(s.hits + s.joined, 7);
    }

    #[tokio::test]
    async fn counts_hits_misses_and_joins() {
        let c = StageCache::default();
        let a = c.get_or_compute(h(1), || async { tile(0) }).await;
        let b = c
            .get_or_compute(h(1), || async { panic!("must not compute a hit") })
            .await;
        assert!(Arc::ptr_eq(&a, &b));
        // Two concurrent lookups of a new hash share one computation.
        let (x, y) = tokio::join!(
            c.get_or_compute(h(2), || async {
                tokio::time::sleep(std::time::Duration::from_millis(50)).await;
                tile(1)
            }),
            c.get_or_compute(h(2), || async { panic!("joined, not computed") }),
        );
        assert!(Arc::ptr_eq(&x, &y));
        let s = c.stats();
        assert_eq!((s.hits, s.misses, s.joined, s.disk_hits), (1, 2, 1, 0));
        assert_eq!(c.memory.in_flight(), 0, "flights are cleaned up");
    }

    #[tokio::test]
    async fn disk_tier_survives_a_new_cache_and_drops_bad_files() {
        let dir = tempfile::tempdir().expect("tempdir");
        let t = tile(2);
        {
            let c = StageCache::new(DEFAULT_BUDGET_BYTES)
                .with_disk(dir.path())
                .expect("disk");
            let expect = t.clone();
            c.get_or_compute(h(9), || async { expect }).await;
            assert_eq!(c.stats().disk_writes, 1);
        }
        let c = StageCache::new(DEFAULT_BUDGET_BYTES)
            .with_disk(dir.path())
            .expect("disk");
        let got = c
            .get_or_compute(h(9), || async { panic!("must come from disk") })
            .await;
        assert_eq!(*got, t);
        assert_eq!(c.stats().disk_hits, 1);
        // A damaged file is an error, is deleted, and the tile is computed again.
        let disk = DiskCache::open(dir.path()).expect("disk");
        let path = disk.path(&h(9));
        let mut bytes = std::fs::read(&path).expect("file");
        bytes[60] ^= 0xff;
        std::fs::write(&path, bytes).expect("write");
        assert!(disk.read(&h(9)).is_none());
        assert!(!path.exists());
        assert_eq!(disk.errors.load(Ordering::Relaxed), 1);
    }
}
