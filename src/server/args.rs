//! `strata serve` options.

use crate::gpu::BackendChoice;
use std::net::SocketAddr;
use std::path::PathBuf;

/// `strata serve` options.
#[derive(Debug, clap::Args)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub addr: SocketAddr,
    /// Data directory (scene store, caches).
    #[arg(long, default_value = "data")]
    pub data: PathBuf,
    /// Scene store: a PostgreSQL URL (`postgres://user:password@host:5432/strata`), for replicas
    /// sharing one database. Read from `STRATA_DATABASE_URL` when not given. Without one, the
    /// embedded SQLite file `<data>/strata.db`.
    #[arg(long, value_name = "URL", value_parser = check_store)]
    pub store: Option<super::access::Secret>,
    /// Compute backend.
    #[arg(long, value_enum, default_value_t = BackendChoice::Auto)]
    pub backend: BackendChoice,
    /// Directory of the browser viewer served at `/`.
    #[arg(long, default_value = "web/dist")]
    pub web: PathBuf,
    /// Server admin token: may create worlds and acts as admin of every world. Read from
    /// `STRATA_ADMIN_TOKEN` when not given. Without one, anyone may create worlds.
    #[arg(long)]
    pub admin_token: Option<super::access::Secret>,
    /// An origin (`https://maps.example.org`) whose pages may call every route from a browser,
    /// worlds included; repeat it for several. Read from `STRATA_CORS_ORIGINS` (comma-separated)
    /// when not given. Without one, only the server's own origin may, besides the bare seeds'
    /// routes, which every origin may read.
    #[arg(long, value_name = "ORIGIN", value_parser = check_origin)]
    pub cors_origin: Vec<String>,
    /// Milliseconds a client may take to send a request's header, and may pause while sending
    /// its body, before the connection is closed.
    #[arg(long, value_name = "MS", default_value_t = super::HEADER_READ_TIMEOUT.as_millis() as u64,
          value_parser = clap::value_parser!(u64).range(1..=3_600_000))]
    pub read_timeout_ms: u64,
    /// Connections held at once, stream connections included; further ones are answered 503
    /// and closed.
    #[arg(long, value_name = "N", default_value_t = super::MAX_CONNECTIONS as u32,
          value_parser = clap::value_parser!(u32).range(1..))]
    pub max_connections: u32,
    /// Directory of the disk tier of the stage cache (finished tiles by input hash); memory
    /// only without it.
    #[arg(long)]
    pub cache_dir: Option<PathBuf>,
    /// Memory budget of all the caches together, MiB (split between them by fixed fractions:
    /// half for finished tiles, a quarter for encoded bodies, the rest for solved regions and
    /// world plans; see `server::budget`). Read from `STRATA_MEMORY_BUDGET` (MiB) when not
    /// given; default 512. The process holds a fixed overhead besides (`strata bench serve`
    /// measures the resident memory against it).
    #[arg(long, value_name = "MB", value_parser = clap::value_parser!(u64).range(0..=1 << 30))]
    pub memory_budget: Option<u64>,
    /// Archive bytes one world's export jobs may hold on disk, MiB: queued and running jobs
    /// count at the upper bound of their archive, finished ones at its size. An export whose
    /// bound exceeds it is refused (400 `export_too_large`); one that does not fit beside the
    /// world's other archives is refused until they expire (429 `export_quota_exceeded`).
    #[arg(long, value_name = "MIB", default_value_t = super::jobs::quota::DEFAULT_WORLD_BUDGET_MB,
          value_parser = clap::value_parser!(u64).range(1..=1 << 30))]
    pub export_world_budget: u64,
    /// Archive bytes all export jobs together may hold on disk, MiB (counted as for
    /// `--export-world-budget`).
    #[arg(long, value_name = "MIB", default_value_t = super::jobs::quota::DEFAULT_DISK_BUDGET_MB,
          value_parser = clap::value_parser!(u64).range(1..=1 << 30))]
    pub export_disk_budget: u64,
    /// Seconds an export archive is kept after its job is done; then it is deleted and its job
    /// answers `expired` (410 `job_expired` for the archive).
    #[arg(long, value_name = "SECONDS", default_value_t = super::jobs::quota::DEFAULT_MAX_AGE_S,
          value_parser = clap::value_parser!(u64).range(1..=10 * 365 * 86_400))]
    pub export_max_age: u64,
    /// Directory of the export archives, shared by the replicas of one store (a network file
    /// system or a shared volume) so that any replica serves any archive. Read from
    /// `STRATA_SHARED_DIR` when not given; default `<data>/exports`.
    #[arg(long, value_name = "DIR")]
    pub shared_dir: Option<PathBuf>,
    /// Seconds an export job's replica may go without renewing its hold on the job before
    /// another replica of the same store takes the job over and redoes it.
    #[arg(long, value_name = "SECONDS", default_value_t = super::jobs::ledger::DEFAULT_LEASE_S,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    pub export_lease: u64,
    /// Expensive requests (export creation, scatter, volume chunks, region PNGs and stats, volume meshes,
    /// tiles not yet cached) each client address and each token may make per minute, in a burst
    /// or spread out; further ones are refused (429 `rate_limited` with `Retry-After`).
    #[arg(long, value_name = "PER_MINUTE",
          default_value_t = super::rate_limit::DEFAULT_RATE_LIMIT_PER_MINUTE,
          value_parser = clap::value_parser!(u32).range(1..))]
    pub rate_limit: u32,
    /// Bytes of Ptex pages one stream session may hold (protocol v2, `api/stream_protocol_v2.md`),
    /// MiB: a vista page for each of its faces, detail pages sharing the rest.
    #[arg(long, value_name = "MIB", env = "STRATA_PTEX_SESSION_BUDGET",
          default_value_t = crate::stream::ptex::DEFAULT_SESSION_BUDGET_MB,
          value_parser = clap::value_parser!(u64).range(1..=1 << 20))]
    pub ptex_session_budget: u64,
    /// Bytes of Ptex pages all stream sessions together may hold, MiB; a session that would
    /// exceed it gets no pages (`ptex_unavailable`).
    #[arg(long, value_name = "MIB", env = "STRATA_PTEX_SERVER_BUDGET",
          default_value_t = crate::stream::ptex::DEFAULT_SERVER_BUDGET_MB,
          value_parser = clap::value_parser!(u64).range(1..=1 << 30))]
    pub ptex_server_budget: u64,
}

fn check_store(s: &str) -> Result<super::access::Secret, String> {
    if crate::store::is_postgres_url(s) {
        Ok(super::access::Secret::new(s))
    } else {
        Err(
            "the store must be a postgres:// or postgresql:// URL (without --store, worlds live \
             in <data>/strata.db)"
                .into(),
        )
    }
}

fn check_origin(s: &str) -> Result<String, String> {
    super::cors::parse_origin(s).map(|_| s.to_owned())
}

impl ServeArgs {
    /// `--memory-budget`, else `STRATA_MEMORY_BUDGET`, else
    /// [`super::budget::DEFAULT_MEMORY_BUDGET_MB`].
    ///
    /// # Errors
    /// `STRATA_MEMORY_BUDGET` is not a whole number of MiB.
    pub fn memory_budget_mb(&self) -> anyhow::Result<u64> {
        if let Some(mb) = self.memory_budget {
            return Ok(mb);
        }
        match std::env::var("STRATA_MEMORY_BUDGET") {
            Ok(v) => v
                .trim()
                .parse::<u64>()
                .ok()
                .filter(|mb| *mb <= 1 << 30)
                .ok_or_else(|| {
                    anyhow::anyhow!("STRATA_MEMORY_BUDGET: {v:?} is not a number of MiB")
                }),
            Err(_) => Ok(super::budget::DEFAULT_MEMORY_BUDGET_MB),
        }
    }

    /// The Ptex page budgets of the command line.
    pub fn ptex_settings(&self) -> crate::stream::ptex::PtexSettings {
        crate::stream::ptex::PtexSettings {
            session_bytes: self.ptex_session_budget << 20,
            server_bytes: self.ptex_server_budget << 20,
            ..crate::stream::ptex::PtexSettings::default()
        }
    }

    /// The export queue's limits with the disk budgets and archive age of the command line.
    pub fn job_limits(&self) -> super::jobs::JobLimits {
        super::jobs::JobLimits {
            world_budget_bytes: self.export_world_budget << 20,
            disk_budget_bytes: self.export_disk_budget << 20,
            max_age: std::time::Duration::from_secs(self.export_max_age),
            ..super::jobs::JobLimits::default()
        }
    }

    /// The PostgreSQL URL of `--store`, else of `STRATA_DATABASE_URL` (when set and not empty);
    /// `None` means the embedded SQLite store.
    ///
    /// # Errors
    /// `STRATA_DATABASE_URL` is not a PostgreSQL URL.
    pub fn database_url(&self) -> anyhow::Result<Option<super::access::Secret>> {
        if let Some(url) = &self.store {
            return Ok(Some(url.clone()));
        }
        match std::env::var("STRATA_DATABASE_URL") {
            Ok(v) if v.trim().is_empty() => Ok(None),
            Ok(v) => check_store(v.trim())
                .map(Some)
                .map_err(|e| anyhow::anyhow!("STRATA_DATABASE_URL: {e}")),
            Err(_) => Ok(None),
        }
    }

    /// The export archive directory: `--shared-dir`, else `STRATA_SHARED_DIR` (when set and not
    /// empty), else `<data>/exports`.
    pub fn shared_dir(&self) -> PathBuf {
        if let Some(dir) = &self.shared_dir {
            return dir.clone();
        }
        match std::env::var("STRATA_SHARED_DIR") {
            Ok(v) if !v.trim().is_empty() => PathBuf::from(v.trim()),
            _ => self.data.join("exports"),
        }
    }

    /// `--read-timeout-ms` as a duration.
    pub fn read_timeout(&self) -> std::time::Duration {
        std::time::Duration::from_millis(self.read_timeout_ms)
    }
}
