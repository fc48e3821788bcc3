//! Blocking computations that outlive the requests waiting for them, counted.
//!
//! Every long computation on the blocking pool (a tile's field and finish, an authored or
//! volume region's solve, a Ptex bake, a chunk's meshing) is a [`Work`]: it holds the
//! [`Cancel`] the computation polls. When nobody waits for the result any more (the future
//! awaiting it was dropped because its request timed out or its client left, or the last
//! request sharing a solve went), the work is *abandoned*: its flag is set, and from then on
//! it is counted in [`ABANDONED`] until its thread returns, as stopped (it answered
//! [`Cancelled`] at a check of its flag) or as finished (it ran to its end regardless). A
//! computation that checks its flag often enough stops soon after it is abandoned; one that
//! never checks it (a Ptex bake already running) runs to its end, and is counted so.
//!
//! `GET /metrics` shows them as `strata_work_after_cancel` (gauge: abandoned work still
//! running) and `strata_work_after_cancel_total{end="stopped"|"finished"}`.

use crate::terrain::cancel::{Cancel, Cancelled};
use std::sync::atomic::{AtomicI64, AtomicU64, AtomicU8, Ordering};
use std::sync::Arc;

/// The process's counters of abandoned work.
#[derive(Debug)]
pub struct Abandoned {
    /// Abandoned work whose thread has not returned yet.
    pub running: AtomicI64,
    /// Abandoned work that stopped at a check of its flag.
    pub stopped: AtomicU64,
    /// Abandoned work that ran to its end.
    pub finished: AtomicU64,
}

/// The counters of this process.
pub static ABANDONED: Abandoned = Abandoned {
    running: AtomicI64::new(0),
    stopped: AtomicU64::new(0),
    finished: AtomicU64::new(0),
};

const RUNNING: u8 = 0;
const GONE: u8 = 1;
const DONE: u8 = 2;

/// One blocking computation: its cancellation flag and whether anyone still waits for it.
#[derive(Debug)]
pub struct Work {
    cancel: Cancel,
    state: AtomicU8,
}

impl Work {
    /// A computation somebody waits for.
    pub fn new() -> Arc<Self> {
        Arc::new(Self {
            cancel: Cancel::new(),
            state: AtomicU8::new(RUNNING),
        })
    }

    /// The flag the computation polls.
    pub fn cancel(&self) -> &Cancel {
        &self.cancel
    }

    /// Nobody waits for the result any more: sets the flag and, unless the computation has
    /// already returned, counts it as running after its cancellation.
    pub fn abandon(&self) {
        ABANDONED.running.fetch_add(1, Ordering::AcqRel);
        if self
            .state
            .compare_exchange(RUNNING, GONE, Ordering::AcqRel, Ordering::Acquire)
            .is_ok()
        {
            self.cancel.cancel();
        } else {
            ABANDONED.running.fetch_sub(1, Ordering::AcqRel);
        }
    }

    /// The computation returned (`stopped`: it answered [`Cancelled`]); counted if it had been
    /// abandoned. Call it on the computation's thread as it returns.
    pub fn end(&self, stopped: bool) {
        if self.state.swap(DONE, Ordering::AcqRel) == GONE {
            ABANDONED.running.fetch_sub(1, Ordering::AcqRel);
            let end = if stopped {
                &ABANDONED.stopped
            } else {
                &ABANDONED.finished
            };
            end.fetch_add(1, Ordering::Relaxed);
        }
    }
}

/// Abandons its work when dropped before the work has returned.
struct Waiting(Arc<Work>);

impl Drop for Waiting {
    fn drop(&mut self) {
        self.0.abandon();
    }
}

/// Runs `f` on the blocking pool as a [`Work`]: if the returned future is dropped before `f`
/// returns, `f`'s flag is set and the work is counted in [`ABANDONED`]. `f` should poll the
/// flag it is given and answer [`Cancelled`] once it is set.
///
/// # Errors
/// What `f` answers ([`Cancelled`] only once nobody waits, so no caller sees it but in tests).
pub async fn run<T, F>(f: F) -> Result<T, Cancelled>
where
    T: Send + 'static,
    F: FnOnce(&Cancel) -> Result<T, Cancelled> + Send + 'static,
{
    let work = Work::new();
    let on_thread = work.clone();
    let task = tokio::task::spawn_blocking(move || {
        let r = f(on_thread.cancel());
        on_thread.end(r.is_err());
        r
    });
    let _waiting = Waiting(work);
    super::joined(task).await
}

/// [`run`] of a computation that never polls its flag: it runs to its end once started.
pub async fn run_to_end<T, F>(f: F) -> T
where
    T: Send + 'static,
    F: FnOnce() -> T + Send + 'static,
{
    match run(move |_| Ok(f())).await {
        Ok(t) => t,
        Err(Cancelled) => unreachable!("a computation that never polls its flag is not stopped"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn abandoned_work_is_counted_until_it_returns_and_by_how_it_ended() {
        // The counters are process-wide: compare differences, in one test.
        let before = (
            ABANDONED.stopped.load(Ordering::Relaxed),
            ABANDONED.finished.load(Ordering::Relaxed),
        );
        // Returned before anyone left: not counted.
        let w = Work::new();
        w.end(false);
        w.abandon();
        assert!(!w.cancel().is_cancelled());
        // Abandoned, then stopped at a check.
        let w = Work::new();
        w.abandon();
        assert!(w.cancel().is_cancelled());
        assert!(ABANDONED.running.load(Ordering::Relaxed) >= 1);
        w.end(true);
        // Abandoned, then ran to its end.
        let w = Work::new();
        w.abandon();
        w.end(false);
        assert_eq!(
            (
                ABANDONED.stopped.load(Ordering::Relaxed) - before.0,
                ABANDONED.finished.load(Ordering::Relaxed) - before.1
            ),
            (1, 1)
        );
    }
}
