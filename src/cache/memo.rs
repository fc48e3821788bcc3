//! [`Memo`], the one cache abstraction of the process: a `moka` cache bounded by a byte budget,
//! with single-flight computation of misses and hit, miss, join and eviction counters.
//!
//! - **Weight.** Every entry is weighed in bytes by the weigher given to [`Memo::new`] (what the
//!   entry holds: its arrays' capacities, its `Arc`'d payloads; approximate where stated by the
//!   weigher) plus [`ENTRY_OVERHEAD_BYTES`] for moka's slot. An entry heavier than the whole
//!   budget is not kept; a budget of 0 keeps nothing.
//! - **Eviction.** Least recently used first (moka's LRU policy, O(1) per operation: no scan).
//!   moka applies evictions in batches, so between two maintenance passes the weight may exceed
//!   the budget by what was inserted since the last one; [`Memo::stats`] runs the pending
//!   maintenance first, so its figures are exact.
//! - **Single flight.** Concurrent misses of one key compute once: [`Memo::get_or_compute`] and
//!   [`Memo::try_get_or_compute`] on threads (moka's own `entry().or_insert_with`), and
//!   [`Memo::get_or_compute_async`] / [`Memo::try_get_or_compute_async`] on async tasks (a map of
//!   in-flight `tokio::sync::OnceCell`s; the others wait and count as joined). A failed
//!   computation is not cached: the next caller computes again.

use std::collections::HashMap;
use std::future::Future;
use std::hash::Hash;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use tokio::sync::OnceCell;

/// Bytes counted per entry besides what its weigher says (moka's slot, the key's hash-map
/// cell, the LRU deque node).
pub const ENTRY_OVERHEAD_BYTES: usize = 128;

/// How a lookup was answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// From the cache.
    Hit,
    /// By a computation of the same key already under way (async lookups only).
    Joined,
    /// Computed by this call.
    Computed,
}

/// A snapshot of a [`Memo`]'s counters and sizes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemoStats {
    /// Lookups answered from the cache.
    pub hits: u64,
    /// Lookups that computed (or failed to compute) their value.
    pub misses: u64,
    /// Async lookups that waited for a computation of the same key.
    pub joined: u64,
    /// Entries evicted to stay within the budget.
    pub evictions: u64,
    /// Entries held.
    pub entries: u64,
    /// Bytes counted (the weights of the entries held).
    pub bytes: u64,
    /// The byte budget.
    pub budget_bytes: u64,
}

type Flight<V> = Arc<OnceCell<V>>;
/// An entry's weigher (without the overhead).
type Weigher<K, V> = Arc<dyn Fn(&K, &V) -> usize + Send + Sync>;

#[derive(Default)]
struct Counters {
    hits: AtomicU64,
    misses: AtomicU64,
    joined: AtomicU64,
    evictions: Arc<AtomicU64>,
}

/// A byte-bounded, single-flight cache of `K → V` (see the module docs). `V` is cloned out of
/// the cache on every hit: make it an `Arc` (or a tuple of them).
pub struct Memo<K, V> {
    cache: moka::sync::Cache<K, V>,
    weigh: Weigher<K, V>,
    budget: u64,
    inflight: Mutex<HashMap<K, Flight<V>>>,
    counters: Counters,
}

impl<K, V> std::fmt::Debug for Memo<K, V> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Memo")
            .field("budget", &self.budget)
            .finish_non_exhaustive()
    }
}

/// Locks `m`, taking the value over from a holder that panicked.
pub(crate) fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

impl<K, V> Memo<K, V>
where
    K: Hash + Eq + Clone + Send + Sync + 'static,
    V: Clone + Send + Sync + 'static,
{
    /// An empty cache of at most `budget_bytes`, each entry weighing `weigh(key, value)` +
    /// [`ENTRY_OVERHEAD_BYTES`].
    pub fn new(
        budget_bytes: usize,
        weigh: impl Fn(&K, &V) -> usize + Send + Sync + 'static,
    ) -> Self {
        let weigh: Weigher<K, V> = Arc::new(weigh);
        let evictions = Arc::new(AtomicU64::new(0));
        let counted = evictions.clone();
        let w = weigh.clone();
        let cache = moka::sync::Cache::builder()
            .max_capacity(budget_bytes as u64)
            .eviction_policy(moka::policy::EvictionPolicy::lru())
            .weigher(move |k: &K, v: &V| {
                u32::try_from(w(k, v) + ENTRY_OVERHEAD_BYTES).unwrap_or(u32::MAX)
            })
            .eviction_listener(move |_, _, cause| {
                if matches!(cause, moka::notification::RemovalCause::Size) {
                    counted.fetch_add(1, Ordering::Relaxed);
                }
            })
            .build();
        Self {
            cache,
            weigh,
            budget: budget_bytes as u64,
            inflight: Mutex::default(),
            counters: Counters {
                evictions,
                ..Counters::default()
            },
        }
    }

    /// The byte budget.
    pub fn budget_bytes(&self) -> usize {
        self.budget as usize
    }

    /// Bytes `(key, value)` is counted for, overhead included.
    pub fn weight(&self, key: &K, value: &V) -> usize {
        (self.weigh)(key, value) + ENTRY_OVERHEAD_BYTES
    }

    /// The value under `key`, if held (marks it recently used; counts nothing).
    pub fn get(&self, key: &K) -> Option<V> {
        self.cache.get(key)
    }

    /// The value under `key`, if held, counted as a hit (marks it recently used).
    pub fn lookup(&self, key: &K) -> Option<V> {
        let v = self.cache.get(key)?;
        self.counters.hits.fetch_add(1, Ordering::Relaxed);
        Some(v)
    }

    /// Counts a miss that the caller handles itself (as after a failed [`Memo::lookup`]).
    pub fn count_miss(&self) {
        self.counters.misses.fetch_add(1, Ordering::Relaxed);
    }

    /// Whether `key` is held (marks nothing, counts nothing).
    pub fn contains(&self, key: &K) -> bool {
        self.cache.contains_key(key)
    }

    /// Keeps `value` under `key` (replacing what was there), unless it weighs more than the
    /// whole budget.
    pub fn insert(&self, key: K, value: V) {
        if self.weight(&key, &value) as u64 <= self.budget {
            self.cache.insert(key, value);
        }
    }

    /// Removes every entry.
    pub fn clear(&self) {
        self.cache.invalidate_all();
        self.cache.run_pending_tasks();
    }

    /// Applies moka's pending bookkeeping (evictions, recency) now.
    pub fn run_pending_tasks(&self) {
        self.cache.run_pending_tasks();
    }

    /// The value under `key`, computing it with `compute` on a miss. Concurrent misses of one
    /// key on several threads run `compute` once; the others block until it is done.
    pub fn get_or_compute(&self, key: K, compute: impl FnOnce() -> V) -> V {
        let entry = self.cache.entry(key).or_insert_with(compute);
        self.count(entry.is_fresh());
        entry.into_value()
    }

    /// Like [`Memo::get_or_compute`] for a computation that can fail; a failure is not kept,
    /// and every thread that waited for it gets it.
    pub fn try_get_or_compute<E: Send + Sync + 'static>(
        &self,
        key: K,
        compute: impl FnOnce() -> Result<V, E>,
    ) -> Result<V, Arc<E>> {
        match self.cache.entry(key).or_try_insert_with(compute) {
            Ok(entry) => {
                self.count(entry.is_fresh());
                Ok(entry.into_value())
            }
            Err(e) => {
                self.count(true);
                Err(e)
            }
        }
    }

    fn count(&self, fresh: bool) {
        let c = if fresh {
            &self.counters.misses
        } else {
            &self.counters.hits
        };
        c.fetch_add(1, Ordering::Relaxed);
    }

    /// The value under `key` and how it was found, computing it with the future `compute`
    /// returns on a miss. Concurrent misses of one key on several tasks await one computation.
    pub async fn get_or_compute_async<F, Fut>(&self, key: K, compute: F) -> (V, Outcome)
    where
        F: FnOnce() -> Fut,
        Fut: Future<Output = V>,
    {
        match self
            .try_get_or_compute_async(key, || async {
                Ok::<V, std::convert::Infallible>(compute().await)
            })
            .await
        {
            Ok(found) => found,
            Err(never) => match never {},
        }
    }

    /// Like [`Memo::get_or_compute_async`] for a computation that can fail. A failure is not
    /// kept: it goes to this caller, and a task that was waiting runs its own computation.
    pub async fn try_get_or_compute_async<E, F, Fut>(
        &self,
        key: K,
        compute: F,
    ) -> Result<(V, Outcome), E>
    where
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<V, E>>,
    {
        if let Some(v) = self.cache.get(&key) {
            self.counters.hits.fetch_add(1, Ordering::Relaxed);
            return Ok((v, Outcome::Hit));
        }
        let cell = lock(&self.inflight).entry(key.clone()).or_default().clone();
        let guard = FlightGuard {
            memo: self,
            key: &key,
            cell,
        };
        let mut outcome = None;
        let result = guard
            .cell
            .get_or_try_init(|| async {
                // A flight may have landed between the lookup above and joining the map.
                if let Some(v) = self.cache.get(&key) {
                    outcome = Some(Outcome::Hit);
                    return Ok(v);
                }
                outcome = Some(Outcome::Computed);
                let v = compute().await?;
                self.insert(key.clone(), v.clone());
                Ok(v)
            })
            .await
            .cloned();
        let outcome = outcome.unwrap_or(Outcome::Joined);
        let counter = match outcome {
            Outcome::Hit => &self.counters.hits,
            Outcome::Joined => &self.counters.joined,
            Outcome::Computed => &self.counters.misses,
        };
        counter.fetch_add(1, Ordering::Relaxed);
        result.map(|v| (v, outcome))
    }

    /// The counters and sizes now (after applying moka's pending bookkeeping).
    pub fn stats(&self) -> MemoStats {
        self.cache.run_pending_tasks();
        let c = &self.counters;
        MemoStats {
            hits: c.hits.load(Ordering::Relaxed),
            misses: c.misses.load(Ordering::Relaxed),
            joined: c.joined.load(Ordering::Relaxed),
            evictions: c.evictions.load(Ordering::Relaxed),
            entries: self.cache.entry_count(),
            bytes: self.cache.weighted_size(),
            budget_bytes: self.budget,
        }
    }

    /// Async computations under way (for tests: finished flights are removed).
    pub fn in_flight(&self) -> usize {
        lock(&self.inflight).len()
    }
}

/// Removes a finished (or abandoned) flight from the in-flight map.
struct FlightGuard<'a, K: Hash + Eq, V> {
    memo: &'a Memo<K, V>,
    key: &'a K,
    cell: Flight<V>,
}

impl<K: Hash + Eq, V> Drop for FlightGuard<'_, K, V> {
    fn drop(&mut self) {
        let mut inflight = lock(&self.memo.inflight);
        if let Some(current) = inflight.get(self.key) {
            // Done, or nobody but the map and this guard holds it (every waiter left).
            if Arc::ptr_eq(current, &self.cell)
                && (self.cell.initialized() || Arc::strong_count(&self.cell) <= 2)
            {
                inflight.remove(self.key);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;
    use std::time::Duration;

    fn bytes_memo(budget: usize) -> Memo<u32, Arc<Vec<u8>>> {
        Memo::new(budget, |_, v: &Arc<Vec<u8>>| v.capacity())
    }

    #[test]
    fn eight_threads_missing_one_key_compute_once() {
        let memo = Arc::new(bytes_memo(1 << 20));
        let runs = Arc::new(AtomicUsize::new(0));
        let barrier = Arc::new(std::sync::Barrier::new(8));
        let threads: Vec<_> = (0..8)
            .map(|_| {
                let (memo, runs, barrier) = (memo.clone(), runs.clone(), barrier.clone());
                std::thread::spawn(move || {
                    barrier.wait();
                    memo.get_or_compute(7, || {
                        runs.fetch_add(1, Ordering::SeqCst);
                        std::thread::sleep(Duration::from_millis(100));
                        Arc::new(vec![1u8; 1000])
                    })
                })
            })
            .collect();
        let got: Vec<_> = threads
            .into_iter()
            .map(|t| t.join().expect("thread"))
            .collect();
        assert_eq!(runs.load(Ordering::SeqCst), 1, "one computation");
        assert!(got.iter().all(|v| Arc::ptr_eq(v, &got[0])), "one value");
        let s = memo.stats();
        assert_eq!((s.misses, s.hits, s.entries), (1, 7, 1));
    }

    #[tokio::test(flavor = "multi_thread", worker_threads = 4)]
    async fn eight_tasks_missing_one_key_compute_once() {
        let memo = Arc::new(bytes_memo(1 << 20));
        let runs = Arc::new(AtomicUsize::new(0));
        let barrier = Arc::new(tokio::sync::Barrier::new(8));
        let tasks: Vec<_> = (0..8)
            .map(|_| {
                let (memo, runs, barrier) = (memo.clone(), runs.clone(), barrier.clone());
                tokio::spawn(async move {
                    barrier.wait().await;
                    memo.get_or_compute_async(7, || async {
                        runs.fetch_add(1, Ordering::SeqCst);
                        tokio::time::sleep(Duration::from_millis(100)).await;
                        Arc::new(vec![1u8; 1000])
                    })
                    .await
                })
            })
            .collect();
        let mut got = Vec::new();
        for t in tasks {
            got.push(t.await.expect("task"));
        }
        assert_eq!(runs.load(Ordering::SeqCst), 1, "one computation");
        assert!(got.iter().all(|(v, _)| Arc::ptr_eq(v, &got[0].0)));
        let computed = got.iter().filter(|(_, o)| *o == Outcome::Computed).count();
        assert_eq!(computed, 1);
        let s = memo.stats();
        assert_eq!(s.misses, 1);
        assert_eq!(s.hits + s.joined, 7);
        assert_eq!(memo.in_flight(), 0, "flights are cleaned up");
    }

    #[tokio::test]
    async fn a_failed_async_computation_is_not_kept() {
        let memo = bytes_memo(1 << 20);
        let r = memo
            .try_get_or_compute_async(1, || async { Err::<Arc<Vec<u8>>, _>("no") })
            .await;
        assert_eq!(r.err(), Some("no"));
        assert!(!memo.contains(&1));
        let (v, o) = memo
            .try_get_or_compute_async(1, || async { Ok::<_, &str>(Arc::new(vec![2u8])) })
            .await
            .expect("second try");
        assert_eq!((v[0], o), (2, Outcome::Computed));
        assert_eq!(memo.in_flight(), 0);
    }

    #[test]
    fn weighted_eviction_keeps_the_weight_within_the_budget() {
        let one = 10_000 + ENTRY_OVERHEAD_BYTES;
        let budget = 10 * one + one / 2;
        let memo = bytes_memo(budget);
        for k in 0..100u32 {
            memo.insert(k, Arc::new(vec![0u8; 10_000]));
            if k % 7 == 0 {
                memo.run_pending_tasks();
                assert!(memo.stats().bytes <= budget as u64);
            }
        }
        let s = memo.stats();
        assert_eq!(s.entries, 10, "{s:?}");
        assert_eq!(s.bytes, 10 * one as u64);
        assert!(s.bytes <= s.budget_bytes);
        assert_eq!(s.evictions, 90);
        // The most recent ten are the ones kept.
        assert!((90..100).all(|k| memo.contains(&k)));
        // Heavier than the whole budget: not kept.
        memo.insert(1000, Arc::new(vec![0u8; budget]));
        assert!(!memo.contains(&1000));
        // A budget of 0 keeps nothing.
        let none = bytes_memo(0);
        none.insert(1, Arc::new(Vec::new()));
        assert_eq!(none.stats().entries, 0);
    }

    #[test]
    fn least_recently_used_goes_first() {
        let one = 1000 + ENTRY_OVERHEAD_BYTES;
        let memo = bytes_memo(2 * one + one / 2);
        memo.insert(1, Arc::new(vec![0u8; 1000]));
        memo.insert(2, Arc::new(vec![0u8; 1000]));
        memo.run_pending_tasks();
        assert!(memo.get(&1).is_some()); // 1 is now more recent than 2
        memo.run_pending_tasks();
        memo.insert(3, Arc::new(vec![0u8; 1000]));
        memo.run_pending_tasks();
        assert!(memo.contains(&1) && memo.contains(&3) && !memo.contains(&2));
    }
}
