//! Solutions by `(seed, element digest)`: each element of each world version is solved once, on
//! the blocking pool, however many requests ask for it at once; the least recently used go
//! first beyond the cache's byte budget. Authored regions ([`super::regions`]) and volume
//! regions ([`super::volumes`]) keep theirs here.
//!
//! A solve is shared by every request waiting for it and cancelled when the last of them has
//! gone (its request timed out or its client left): the waiters are counted, and the one whose
//! departure leaves none sets the solve's [`Cancel`], which the solver polls, so the blocking
//! thread stops within a bounded time and its memory is returned (a volume region's pipeline
//! polls it between its stages and before each diffusion sweep and V-cycle, so only a stage
//! without checks, the voxelization or a wavefront, runs to its end). A cancelled solve is
//! never kept, and a request arriving after the cancellation starts a new one. Each solve is a
//! [`crate::compute::work::Work`], so one that runs on after its cancellation is counted on
//! `/metrics`.

use crate::cache::memo::lock;
use crate::cache::Memo;
use crate::compute::work::Work;
use crate::terrain::cancel::Cancel;
use futures::future::{BoxFuture, FutureExt, Shared};
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What a solution holds, bytes (its arrays' capacities; approximate where a type says so).
pub trait Weigh {
    /// Bytes held, the value itself included.
    fn weight(&self) -> usize;
}

type Key = (u64, [u8; 32]);
/// A solve's outcome: the solution, a refusal (`None`), or `Err` once cancelled.
type Outcome<T> = Result<Option<Arc<T>>, crate::terrain::cancel::Cancelled>;

/// A solve under way: its shared outcome, its work (and cancellation flag) and the requests
/// awaiting it.
struct Running<T> {
    outcome: Shared<BoxFuture<'static, Outcome<T>>>,
    work: Arc<Work>,
    waiters: usize,
}

type Runs<T> = Arc<Mutex<HashMap<Key, Running<T>>>>;

/// Solutions of type `T` by `(seed, digest)`, within a byte budget. A refusal (`None`) is kept
/// too.
pub struct SolvedCache<T> {
    memo: Memo<Key, Option<Arc<T>>>,
    runs: Runs<T>,
    /// Solves whose blocking work has not ended, cancelled ones included until they stop.
    working: Arc<AtomicUsize>,
}

impl<T> std::fmt::Debug for SolvedCache<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SolvedCache")
            .field("memo", &self.memo)
            .finish_non_exhaustive()
    }
}

/// One request's interest in a running solve: dropping it (the request answered or gone)
/// cancels the solve if no other request waits for it.
struct Waiter<T> {
    runs: Runs<T>,
    key: Key,
}

impl<T> Drop for Waiter<T> {
    fn drop(&mut self) {
        let mut runs = lock(&self.runs);
        let Some(run) = runs.get_mut(&self.key) else {
            return;
        };
        run.waiters -= 1;
        if run.waiters == 0 {
            // A waiter that saw the solve finish has put it in the memo; a solve nobody needs
            // any more stops (or, finished, is dropped).
            run.work.abandon();
            runs.remove(&self.key);
        }
    }
}

impl<T: Weigh + Send + Sync + 'static> SolvedCache<T> {
    /// An empty cache of at most `budget_bytes` of solutions ([`Weigh::weight`] each, plus
    /// [`crate::cache::ENTRY_OVERHEAD_BYTES`]).
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            memo: Memo::new(budget_bytes, |_, v: &Option<Arc<T>>| {
                v.as_ref().map_or(0, |v| v.weight())
            }),
            runs: Arc::default(),
            working: Arc::default(),
        }
    }

    /// `(entries, bytes, budget bytes)`.
    pub fn size(&self) -> (u64, u64, u64) {
        let s = self.memo.stats();
        (s.entries, s.bytes, s.budget_bytes)
    }

    /// Solves whose work is still running on the blocking pool, those cancelled included until
    /// they have stopped at a check of their flag.
    pub fn running(&self) -> usize {
        self.working.load(Ordering::Acquire)
    }

    /// The solution under `key`, running `solve` on the blocking pool if there is none yet
    /// (joining the solve of `key` under way if there is one). `None` if `solve` refused
    /// (logged with `what`; the products then show the world without the element). `solve`
    /// polls the [`Cancel`] it is given: it is set when every caller waiting for the solve has
    /// gone, and `solve` should then answer an error soon; that error is neither kept nor
    /// seen by anyone.
    pub async fn get_or_solve<E: std::fmt::Display + Send + 'static>(
        &self,
        key: Key,
        what: &'static str,
        solve: impl FnOnce(&Cancel) -> Result<T, E> + Send + 'static,
    ) -> Option<Arc<T>> {
        if let Some(v) = self.memo.lookup(&key) {
            return v;
        }
        let outcome = {
            let mut runs = lock(&self.runs);
            let run = runs.entry(key).or_insert_with(|| {
                self.memo.count_miss();
                start(what, solve, &self.working)
            });
            run.waiters += 1;
            run.outcome.clone()
        };
        let _waiter = Waiter {
            runs: self.runs.clone(),
            key,
        };
        match outcome.await {
            Ok(v) => {
                self.memo.insert(key, v.clone());
                v
            }
            // Only a solve nobody waits for is cancelled, so no caller gets here.
            Err(_) => None,
        }
    }
}

/// Counts one solve in [`SolvedCache::running`] until it is dropped.
struct Working(Arc<AtomicUsize>);

impl Working {
    fn new(count: &Arc<AtomicUsize>) -> Self {
        count.fetch_add(1, Ordering::AcqRel);
        Self(count.clone())
    }
}

impl Drop for Working {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::AcqRel);
    }
}

/// Starts `solve` on the blocking pool with a fresh cancellation flag, counted in `working`
/// until it returns.
fn start<T: Send + Sync + 'static, E: std::fmt::Display + Send + 'static>(
    what: &'static str,
    solve: impl FnOnce(&Cancel) -> Result<T, E> + Send + 'static,
    working: &Arc<AtomicUsize>,
) -> Running<T> {
    let work = Work::new();
    let on_thread = work.clone();
    let working = Working::new(working);
    let task = tokio::task::spawn_blocking(move || {
        let flag = on_thread.cancel();
        let r = solve(flag);
        // The solve has ended: it leaves `working` before its work is counted as ended, so
        // whoever sees no abandoned work running sees no solve working either.
        drop(working);
        // A solve stopped by its flag answers whatever error; the flag says why.
        on_thread.end(r.is_err() && flag.is_cancelled());
        match flag.check() {
            Ok(()) => Ok(r),
            Err(c) => Err(c),
        }
    });
    let outcome = async move {
        match crate::compute::joined(task).await? {
            Ok(v) => Ok(Some(Arc::new(v))),
            Err(e) => {
                tracing::warn!("{what} not solved: {e}");
                Ok(None)
            }
        }
    }
    .boxed()
    .shared();
    Running {
        outcome,
        work,
        waiters: 0,
    }
}
