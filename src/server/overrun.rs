//! Work whose request has gone: a synthesis job whose request timed out (or whose client left)
//! after the job had started is cancelled ([`super::AppState::limited`]): it drops its work at
//! its next await and frees its slot, and the solves it waited for stop at their next check of
//! their cancellation flag unless another request waits for them ([`super::solved`]). Between
//! the timeout and the job's end it is counted as running after its timeout.
//!
//! A job that had not yet taken a slot when its request timed out never starts: its future is
//! dropped with the request's. `GET /metrics` shows `strata_synthesis_timeouts_total`, the gauge
//! `strata_synthesis_after_timeout` (the jobs running now whose request has gone: back to 0 as
//! soon as they are cancelled) and `strata_synthesis_cancelled_total`.

use std::sync::atomic::{AtomicI64, AtomicU64, AtomicU8, Ordering};
use std::sync::Arc;

const QUEUED: u8 = 0;
const RUNNING: u8 = 1;
const DONE: u8 = 2;
const ABANDONED: u8 = 3;

/// The process's counters of timed-out syntheses.
#[derive(Debug, Default)]
pub struct Overruns {
    /// Requests answered 503 `synthesis_timeout`.
    pub timeouts: AtomicU64,
    /// Jobs still running whose request timed out.
    pub running: AtomicI64,
    /// Started jobs cancelled because no request waited for them any more.
    pub cancelled: AtomicU64,
}

/// One job's state, shared by the request (which may time out) and the job's task.
#[derive(Debug)]
pub struct Tracker {
    state: AtomicU8,
    counters: Arc<Overruns>,
}

impl Tracker {
    /// A job not yet started.
    pub fn new(counters: Arc<Overruns>) -> Arc<Self> {
        Arc::new(Self {
            state: AtomicU8::new(QUEUED),
            counters,
        })
    }

    /// Marks the job started; the guard marks it done when dropped (at the end of the task,
    /// however it ends).
    pub fn start(self: &Arc<Self>) -> Running {
        let _ = self
            .state
            .compare_exchange(QUEUED, RUNNING, Ordering::AcqRel, Ordering::Acquire);
        Running(self.clone())
    }

    /// The request timed out: counts it, and counts the job as running after its timeout if it
    /// had started and not yet finished.
    pub fn timed_out(&self) {
        self.counters.timeouts.fetch_add(1, Ordering::Relaxed);
        if self
            .state
            .compare_exchange(RUNNING, ABANDONED, Ordering::AcqRel, Ordering::Acquire)
            .is_ok()
        {
            self.counters.running.fetch_add(1, Ordering::Relaxed);
        }
    }
}

/// A started job; dropping it ends the job.
#[derive(Debug)]
pub struct Running(Arc<Tracker>);

impl Running {
    /// Counts the job as cancelled (it ends without its result).
    pub fn cancelled(&self) {
        self.0.counters.cancelled.fetch_add(1, Ordering::Relaxed);
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if self.0.state.swap(DONE, Ordering::AcqRel) == ABANDONED {
            self.0.counters.running.fetch_sub(1, Ordering::Relaxed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_job_counts_as_running_after_its_timeout_only_while_it_runs() {
        let c = Arc::new(Overruns::default());
        // Timed out while queued: never counted as running.
        let t = Tracker::new(c.clone());
        t.timed_out();
        assert_eq!(c.running.load(Ordering::Relaxed), 0);
        // Timed out while running: counted until the job ends.
        let t = Tracker::new(c.clone());
        let job = t.start();
        t.timed_out();
        assert_eq!(c.running.load(Ordering::Relaxed), 1);
        drop(job);
        assert_eq!(c.running.load(Ordering::Relaxed), 0);
        // Finished before the timeout: not counted.
        let t = Tracker::new(c.clone());
        drop(t.start());
        t.timed_out();
        assert_eq!(c.running.load(Ordering::Relaxed), 0);
        assert_eq!(c.timeouts.load(Ordering::Relaxed), 3);
    }
}
