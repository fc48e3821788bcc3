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
//! - memory: a least-recently-used map of `Arc<Tile>` bounded by a byte budget
//!   ([`DEFAULT_BUDGET_BYTES`] = 256 MiB unless told otherwise). Each tile counts its
//!   [`tile_bytes`]: the `Tile` struct, the capacities of its five arrays and
//!   [`ENTRY_OVERHEAD_BYTES`] of bookkeeping — about 153 KiB for a 65×65 tile with 4 biomes, so
//!   the default holds some 1 700 tiles. Inserting past the budget evicts the least recently used
//!   tiles; a tile larger than the whole budget is not kept (a budget of 0 disables the tier).
//! - disk ([`DiskCache`], `strata serve --cache-dir DIR`): one file per tile,
//!   `DIR/<first two hex digits>/<64 hex digits>.tile`, written to a temporary name and renamed,
//!   so readers see whole files or none; each file carries its hash and a blake3 checksum, and a
//!   file that fails either check is deleted and counted as an error. The disk tier is not
//!   bounded: delete the directory (or any files in it) at any time. Files named by an old
//!   [`crate::scene::TILE_CODE_VERSION`] are never read again.
//! - compute: `compute::Compute::tile_cached` runs the stages (`field`, `snap` strips,
//!   `finish`), counting each run here, and the result enters memory and disk.
//!
//! Concurrent requests for the same missing hash share one computation (the others wait for it
//! and count as `joined`). Counters: memory hits, disk hits, joined, misses (computed), stage
//! runs per [`Stage`], evictions, disk writes and errors; [`StageCache::stats`] reads them.
//!
//! No axum and no knowledge of HTTP: locking, the in-flight cells and the disk tier's blocking
//! I/O (run on tokio's blocking pool) are all it does besides bookkeeping.

use crate::terrain::plan::{MAX_LOD, TILE_VERTEX_COUNT};
use crate::terrain::world::MAX_BIOMES;
use crate::terrain::{Tile, TileKey};
use std::collections::{BTreeMap, HashMap};
use std::future::Future;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use tokio::sync::OnceCell;

/// Default byte budget of the memory tier: 256 MiB.
pub const DEFAULT_BUDGET_BYTES: usize = 256 << 20;
/// Bytes counted per memory entry besides the tile itself (map slot, LRU node, `Arc` header).
pub const ENTRY_OVERHEAD_BYTES: usize = 128;
/// Version of the disk file layout.
pub const DISK_FORMAT_VERSION: u32 = 3;
/// Magic at the start of a disk cache file.
pub const DISK_MAGIC: [u8; 4] = *b"STRC";

/// A tile's input hash (see the module docs).
pub type InputHash = [u8; 32];

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

/// Bytes a tile is counted for in the memory budget.
pub fn tile_bytes(t: &Tile) -> usize {
    std::mem::size_of::<Tile>()
        + t.heights.capacity() * 4
        + t.normals.capacity() * 12
        + t.weights.capacity() * 4
        + t.materials.capacity()
        + t.water_depth.capacity() * 4
        + ENTRY_OVERHEAD_BYTES
}

struct Slot {
    tile: Arc<Tile>,
    bytes: usize,
    tick: u64,
}

#[derive(Default)]
struct Lru {
    map: HashMap<InputHash, Slot>,
    /// Last use → hash; the first entry is the least recently used.
    order: BTreeMap<u64, InputHash>,
    clock: u64,
    bytes: usize,
}

impl Lru {
    fn touch(&mut self, hash: &InputHash) -> Option<Arc<Tile>> {
        self.clock += 1;
        let now = self.clock;
        let slot = self.map.get_mut(hash)?;
        self.order.remove(&slot.tick);
        slot.tick = now;
        self.order.insert(now, *hash);
        Some(slot.tile.clone())
    }

    /// Inserts and evicts down to `budget`; returns the number of evictions.
    fn insert(&mut self, hash: InputHash, tile: Arc<Tile>, budget: usize) -> u64 {
        let bytes = tile_bytes(&tile);
        if bytes > budget {
            return 0;
        }
        self.clock += 1;
        let now = self.clock;
        if let Some(old) = self.map.insert(
            hash,
            Slot {
                tile,
                bytes,
                tick: now,
            },
        ) {
            self.order.remove(&old.tick);
            self.bytes -= old.bytes;
        }
        self.order.insert(now, hash);
        self.bytes += bytes;
        let mut evicted = 0;
        while self.bytes > budget {
            let Some((_, victim)) = self.order.pop_first() else {
                break;
            };
            if let Some(slot) = self.map.remove(&victim) {
                self.bytes -= slot.bytes;
                evicted += 1;
            }
        }
        evicted
    }
}

#[derive(Default)]
struct Counters {
    hits: AtomicU64,
    disk_hits: AtomicU64,
    joined: AtomicU64,
    misses: AtomicU64,
    runs: [AtomicU64; 3],
    micros: [AtomicU64; 3],
    evictions: AtomicU64,
}

type Flight = Arc<OnceCell<Arc<Tile>>>;

/// The bounded tile cache (see the module docs). Share it behind an `Arc`.
pub struct StageCache {
    budget: usize,
    lru: Mutex<Lru>,
    inflight: Mutex<HashMap<InputHash, Flight>>,
    disk: Option<Arc<DiskCache>>,
    counters: Counters,
}

impl std::fmt::Debug for StageCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("StageCache")
            .field("budget", &self.budget)
            .field("disk", &self.disk.as_ref().map(|d| d.dir()))
            .finish_non_exhaustive()
    }
}

impl Default for StageCache {
    fn default() -> Self {
        Self::new(DEFAULT_BUDGET_BYTES)
    }
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

/// Removes a finished (or abandoned) flight from the in-flight map.
struct FlightGuard<'a> {
    cache: &'a StageCache,
    hash: InputHash,
    cell: Flight,
}

impl Drop for FlightGuard<'_> {
    fn drop(&mut self) {
        let mut inflight = lock(&self.cache.inflight);
        if let Some(current) = inflight.get(&self.hash) {
            // Done, or nobody but the map and this guard holds it (every waiter left).
            if Arc::ptr_eq(current, &self.cell)
                && (self.cell.initialized() || Arc::strong_count(&self.cell) <= 2)
            {
                inflight.remove(&self.hash);
            }
        }
    }
}

enum Source {
    Memory,
    Disk,
    Computed,
}

impl StageCache {
    /// A memory-only cache with a budget of `budget_bytes`.
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            budget: budget_bytes,
            lru: Mutex::default(),
            inflight: Mutex::default(),
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
        self.budget
    }

    /// The disk tier's directory, if there is one.
    pub fn disk_dir(&self) -> Option<&Path> {
        self.disk.as_ref().map(|d| d.dir())
    }

    /// The tile under `hash` if it is in memory (marks it recently used; counts nothing).
    pub fn get(&self, hash: &InputHash) -> Option<Arc<Tile>> {
        lock(&self.lru).touch(hash)
    }

    /// Whether memory holds `hash` (marks nothing, counts nothing).
    pub fn contains(&self, hash: &InputHash) -> bool {
        lock(&self.lru).map.contains_key(hash)
    }

    /// Puts a tile in memory under `hash`, evicting the least recently used beyond the budget.
    pub fn insert(&self, hash: InputHash, tile: Arc<Tile>) {
        let evicted = lock(&self.lru).insert(hash, tile, self.budget);
        self.counters
            .evictions
            .fetch_add(evicted, Ordering::Relaxed);
    }

    /// Counts one run of `stage`.
    pub fn record_run(&self, stage: Stage, took: std::time::Duration) {
        self.counters.runs[stage.index()].fetch_add(1, Ordering::Relaxed);
        self.counters.micros[stage.index()].fetch_add(took.as_micros() as u64, Ordering::Relaxed);
    }

    /// The counters and sizes now.
    pub fn stats(&self) -> CacheStats {
        let c = &self.counters;
        let (entries, bytes) = {
            let lru = lock(&self.lru);
            (lru.map.len() as u64, lru.bytes as u64)
        };
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
            hits: c.hits.load(Ordering::Relaxed),
            disk_hits: c.disk_hits.load(Ordering::Relaxed),
            joined: c.joined.load(Ordering::Relaxed),
            misses: c.misses.load(Ordering::Relaxed),
            runs: std::array::from_fn(|i| c.runs[i].load(Ordering::Relaxed)),
            micros: std::array::from_fn(|i| c.micros[i].load(Ordering::Relaxed)),
            evictions: c.evictions.load(Ordering::Relaxed),
            entries,
            bytes,
            budget_bytes: self.budget as u64,
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
        if let Some(t) = self.get(&hash) {
            self.counters.hits.fetch_add(1, Ordering::Relaxed);
            return t;
        }
        let guard = FlightGuard {
            cache: self,
            hash,
            cell: lock(&self.inflight).entry(hash).or_default().clone(),
        };
        let mut source = None;
        let tile = guard
            .cell
            .get_or_init(|| async {
                // A flight may have landed between the lookup above and joining the map.
                if let Some(t) = self.get(&hash) {
                    source = Some(Source::Memory);
                    return t;
                }
                if let Some(t) = self.read_disk(hash).await {
                    let t = Arc::new(t);
                    self.insert(hash, t.clone());
                    source = Some(Source::Disk);
                    return t;
                }
                let t = Arc::new(compute().await);
                self.insert(hash, t.clone());
                self.write_disk(hash, t.clone()).await;
                source = Some(Source::Computed);
                t
            })
            .await
            .clone();
        let counter = match source {
            Some(Source::Memory) => &self.counters.hits,
            Some(Source::Disk) => &self.counters.disk_hits,
            Some(Source::Computed) => &self.counters.misses,
            None => &self.counters.joined,
        };
        counter.fetch_add(1, Ordering::Relaxed);
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

/// The disk tier: one file per tile under a directory (see the module docs for the layout).
#[derive(Debug)]
pub struct DiskCache {
    dir: PathBuf,
    writes: AtomicU64,
    errors: AtomicU64,
    temp: AtomicU64,
}

fn hex(hash: &InputHash) -> String {
    hash.iter().map(|b| format!("{b:02x}")).collect()
}

impl DiskCache {
    /// The disk tier in `dir`, created if missing.
    pub fn open(dir: impl Into<PathBuf>) -> std::io::Result<Self> {
        let dir = dir.into();
        std::fs::create_dir_all(&dir)?;
        Ok(Self {
            dir,
            writes: AtomicU64::new(0),
            errors: AtomicU64::new(0),
            temp: AtomicU64::new(0),
        })
    }

    /// The directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The file of a hash: `DIR/<hh>/<64 hex digits>.tile`.
    pub fn path(&self, hash: &InputHash) -> PathBuf {
        let h = hex(hash);
        self.dir.join(&h[..2]).join(format!("{h}.tile"))
    }

    /// The tile under `hash`, if its file exists and is intact. A damaged file is deleted.
    pub fn read(&self, hash: &InputHash) -> Option<Tile> {
        let path = self.path(hash);
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return None,
            Err(e) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: cannot read: {e}");
                return None;
            }
        };
        match decode_tile(&bytes, hash) {
            Ok(t) => Some(t),
            Err(why) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: dropping a bad file: {why}");
                let _ = std::fs::remove_file(&path);
                None
            }
        }
    }

    /// Writes the tile under `hash` (to a temporary file, then renamed into place).
    pub fn write(&self, hash: &InputHash, tile: &Tile) {
        let path = self.path(hash);
        let result = (|| -> std::io::Result<()> {
            let parent = path.parent().unwrap_or(&self.dir);
            std::fs::create_dir_all(parent)?;
            let n = self.temp.fetch_add(1, Ordering::Relaxed);
            let tmp = parent.join(format!(".{}.{}.{n}.tmp", hex(hash), std::process::id()));
            let written = std::fs::File::create(&tmp)
                .and_then(|mut f| f.write_all(&encode_tile(hash, tile)))
                .and_then(|()| std::fs::rename(&tmp, &path));
            if written.is_err() {
                let _ = std::fs::remove_file(&tmp);
            }
            written
        })();
        match result {
            Ok(()) => {
                self.writes.fetch_add(1, Ordering::Relaxed);
            }
            Err(e) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: cannot write: {e}");
            }
        }
    }
}

/// Header: magic, format version, hash, lod, x, z, spacing, biome count, skirt depth.
const HEADER_LEN: usize = 4 + 4 + 32 + 4 + 8 + 8 + 4 + 4 + 4;

/// The disk form of a tile: the header, then heights, normals (x, y, z), weights, materials,
/// water depth, a byte saying whether the volume-override marks follow and the marks (one byte
/// per vertex), a byte saying whether the water kinds follow and the kinds (one byte per vertex),
/// all little-endian, then blake3 of everything before it.
pub fn encode_tile(hash: &InputHash, t: &Tile) -> Vec<u8> {
    let n = t.heights.len();
    let mut out = Vec::with_capacity(HEADER_LEN + n * (4 + 12 + 1 + 4) + t.weights.len() * 4 + 32);
    out.extend_from_slice(&DISK_MAGIC);
    out.extend_from_slice(&DISK_FORMAT_VERSION.to_le_bytes());
    out.extend_from_slice(hash);
    out.extend_from_slice(&t.key.lod.to_le_bytes());
    out.extend_from_slice(&t.key.x.to_le_bytes());
    out.extend_from_slice(&t.key.z.to_le_bytes());
    out.extend_from_slice(&t.spacing_m.to_le_bytes());
    out.extend_from_slice(&(t.biome_count as u32).to_le_bytes());
    out.extend_from_slice(&t.skirt_depth_m.to_le_bytes());
    for v in &t.heights {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in t.normals.iter().flatten() {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in &t.weights {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&t.materials);
    for v in &t.water_depth {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.push(u8::from(!t.volume_override.is_empty()));
    out.extend_from_slice(&t.volume_override);
    out.push(u8::from(!t.water_kind.is_empty()));
    out.extend_from_slice(&t.water_kind);
    let sum = blake3::hash(&out);
    out.extend_from_slice(sum.as_bytes());
    out
}

struct Reader<'a> {
    bytes: &'a [u8],
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let (head, rest) = self.bytes.split_at(N);
        self.bytes = rest;
        head.try_into().unwrap_or([0; N])
    }

    fn f32s(&mut self, n: usize) -> Vec<f32> {
        (0..n).map(|_| f32::from_le_bytes(self.take())).collect()
    }
}

/// Parses [`encode_tile`]'s output, checking the checksum, the hash and every length.
pub fn decode_tile(bytes: &[u8], hash: &InputHash) -> Result<Tile, String> {
    if bytes.len() < HEADER_LEN + 32 {
        return Err(format!("{} bytes is too short", bytes.len()));
    }
    let (body, sum) = bytes.split_at(bytes.len() - 32);
    if blake3::hash(body).as_bytes() != sum {
        return Err("checksum mismatch".into());
    }
    let mut r = Reader { bytes: body };
    if r.take::<4>() != DISK_MAGIC {
        return Err("not a strata cache file".into());
    }
    let version = u32::from_le_bytes(r.take());
    if version != DISK_FORMAT_VERSION {
        return Err(format!("format version {version}"));
    }
    if &r.take::<32>() != hash {
        return Err("the file holds another hash".into());
    }
    let lod = u32::from_le_bytes(r.take());
    let x = i64::from_le_bytes(r.take());
    let z = i64::from_le_bytes(r.take());
    let spacing_m = f32::from_le_bytes(r.take());
    let k = u32::from_le_bytes(r.take()) as usize;
    let skirt_depth_m = f32::from_le_bytes(r.take());
    if lod > MAX_LOD || k == 0 || k > MAX_BIOMES {
        return Err(format!("lod {lod} or biome count {k} out of range"));
    }
    let n = TILE_VERTEX_COUNT;
    let fixed = n * (4 + 12 + 4 * k + 1 + 4) + 2;
    if ![fixed, fixed + n, fixed + 2 * n].contains(&r.bytes.len()) {
        return Err(format!("{} payload bytes for {k} biomes", r.bytes.len()));
    }
    let heights = r.f32s(n);
    let normals = r
        .f32s(3 * n)
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    let weights = r.f32s(n * k);
    let materials = r.bytes[..n].to_vec();
    r.bytes = &r.bytes[n..];
    let water_depth = r.f32s(n);
    let optional = |r: &mut Reader| -> Result<Vec<u8>, String> {
        if r.take::<1>()[0] != 1 {
            return Ok(Vec::new());
        }
        if r.bytes.len() < n {
            return Err("a section is cut short".into());
        }
        let (head, rest) = r.bytes.split_at(n);
        r.bytes = rest;
        Ok(head.to_vec())
    };
    let volume_override = optional(&mut r)?;
    if r.bytes.is_empty() {
        return Err("the water-kind flag is missing".into());
    }
    let water_kind = optional(&mut r)?;
    if !r.bytes.is_empty() {
        return Err(format!("{} bytes left over", r.bytes.len()));
    }
    Ok(Tile {
        key: TileKey { lod, x, z },
        spacing_m,
        biome_count: k,
        heights,
        normals,
        weights,
        materials,
        water_depth,
        water_kind,
        skirt_depth_m,
        volume_override,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::{synthesize, WorldParams, WorldPlan};

    fn tile(x: i64) -> Tile {
        let plan = WorldPlan::new(3, WorldParams::classic()).expect("plan");
        synthesize(&plan, TileKey { lod: 2, x, z: -1 })
    }

    fn h(n: u8) -> InputHash {
        [n; 32]
    }

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
        assert!(c.get(&h(1)).is_some()); // 1 is now more recent than 2
        c.insert(h(3), t.clone());
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
        assert!(lock(&c.inflight).is_empty(), "flights are cleaned up");
    }

    #[test]
    fn disk_format_round_trips_and_rejects_damage() {
        let t = tile(5);
        let bytes = encode_tile(&h(7), &t);
        assert_eq!(decode_tile(&bytes, &h(7)).expect("decodes"), t);
        assert!(decode_tile(&bytes, &h(8)).is_err(), "other hash");
        let mut bad = bytes.clone();
        bad[100] ^= 1;
        assert!(decode_tile(&bad, &h(7)).is_err(), "checksum");
        assert!(decode_tile(&bytes[..bytes.len() - 1], &h(7)).is_err());
        assert!(decode_tile(&[], &h(7)).is_err());
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
