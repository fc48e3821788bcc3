//! Cooperative cancellation of the long pure computations (an authored region's solve, its
//! erosion brushes, a volume region's pipeline).
//!
//! The caller hands a [`Cancel`] to the `_on` entry points beside the offload hooks; the long
//! loops poll it at bounded intervals (a band of lattice rows while a region samples the world,
//! a multigrid cycle, 64 droplets, a thermal-erosion sweep; the volume pipeline between its
//! stages) and, once it is set, stop and answer [`Cancelled`]. A cancelled
//! computation returns no partial result, so its caller has nothing to keep. The flag is a
//! plain atomic: whoever decides that nobody needs the result any more (the server, when every
//! request waiting for it has gone) sets it with [`Cancel::cancel`].

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Why a computation stopped early: its [`Cancel`] was set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("cancelled: nobody waits for the result any more")]
pub struct Cancelled;

/// A cancellation flag; clones share it. [`Cancel::never`] is never set and costs nothing to
/// poll.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Option<Arc<AtomicBool>>);

impl Cancel {
    /// A flag nobody can set: the computation runs to its end.
    pub fn never() -> Self {
        Self(None)
    }

    /// A flag not yet set.
    pub fn new() -> Self {
        Self(Some(Arc::new(AtomicBool::new(false))))
    }

    /// Sets the flag: the computations polling it (this one and its clones) stop at their next
    /// check.
    pub fn cancel(&self) {
        if let Some(flag) = &self.0 {
            flag.store(true, Ordering::Relaxed);
        }
    }

    /// Whether the flag is set.
    pub fn is_cancelled(&self) -> bool {
        self.0.as_ref().is_some_and(|f| f.load(Ordering::Relaxed))
    }

    /// `Err(Cancelled)` once the flag is set.
    ///
    /// # Errors
    /// [`Cancelled`] if the flag is set.
    pub fn check(&self) -> Result<(), Cancelled> {
        if self.is_cancelled() {
            Err(Cancelled)
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clones_share_the_flag_and_never_is_never_set() {
        let c = Cancel::new();
        let d = c.clone();
        assert_eq!(d.check(), Ok(()));
        c.cancel();
        assert_eq!(d.check(), Err(Cancelled));
        let n = Cancel::never();
        n.cancel();
        assert!(!n.is_cancelled());
    }
}
