//! A throwaway PostgreSQL cluster for the tests of the PostgreSQL store
//! ([`strata::harness::postgres`]), started on first use by each test binary and stopped (its
//! directory removed) when the binary exits. Each caller of [`database`] gets a new empty
//! database in it, so tests do not see each other's worlds. Without PostgreSQL's binaries the
//! tests fail with a message that says how to install them: they never skip.

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::OnceLock;
pub use strata::harness::postgres::Cluster;

static CLUSTER: OnceLock<Cluster> = OnceLock::new();
static NEXT_DB: AtomicU32 = AtomicU32::new(0);

/// Stops the cluster and removes its directory when the test binary exits.
extern "C" fn stop_at_exit() {
    if let Some(c) = CLUSTER.get() {
        c.stop();
    }
}

/// The cluster of this test binary, started on first use.
///
/// # Panics
/// It cannot be started (the message says why).
pub fn cluster() -> &'static Cluster {
    CLUSTER.get_or_init(|| {
        let c = Cluster::start().unwrap_or_else(|e| panic!("the PostgreSQL tests: {e:#}"));
        // SAFETY: registers a plain `extern "C"` function.
        unsafe { libc::atexit(stop_at_exit) };
        c
    })
}

/// `postgres://strata@127.0.0.1:<port>/<db>`.
pub fn url(db: &str) -> String {
    cluster().url(db)
}

/// Connects to database `db`, waiting up to 30 s for the cluster to accept connections.
///
/// # Panics
/// It does not within 30 s.
pub async fn connect(db: &str) -> tokio_postgres::Client {
    cluster()
        .connect(db)
        .await
        .unwrap_or_else(|e| panic!("{e:#}"))
}

/// A new empty database in the cluster; returns its URL.
pub async fn database() -> String {
    let name = format!(
        "t{}_{}",
        std::process::id(),
        NEXT_DB.fetch_add(1, Ordering::SeqCst)
    );
    cluster()
        .database(&name)
        .await
        .unwrap_or_else(|e| panic!("{e:#}"))
}
