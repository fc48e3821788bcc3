//! Command-line interface.

use clap::{Parser, Subcommand, ValueEnum};
use std::net::SocketAddr;
use std::path::PathBuf;

/// strata: a terrain-generation server.
#[derive(Debug, Parser)]
#[command(name = "strata", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run the server.
    Serve(ServeArgs),
    /// Measure performance against the targets of the issues.
    Bench(BenchArgs),
    /// Export a region to a tar archive locally, optionally one shard of N.
    Export(ExportArgs),
}

/// `strata export` options.
#[derive(Debug, clap::Args)]
pub struct ExportArgs {
    /// World seed.
    #[arg(long)]
    pub seed: u64,
    /// World settings as JSON (a `WorldParams` document); the default world without it.
    #[arg(long)]
    pub world: Option<PathBuf>,
    /// Level of detail.
    #[arg(long, default_value_t = 0)]
    pub lod: u32,
    /// Tile rectangle `x0,z0,x1,z1` (x1 and z1 exclusive).
    #[arg(long, value_delimiter = ',', num_args = 4)]
    pub region: Vec<i64>,
    /// Products: `tiles`, `scatter`.
    #[arg(long, value_delimiter = ',', default_value = "tiles")]
    pub products: Vec<String>,
    /// Tile formats: `json`, `bin`, `png`, `glb`.
    #[arg(long, value_delimiter = ',', default_value = "bin")]
    pub formats: Vec<String>,
    /// Shard `i/N` (1-based); the default is the whole export.
    #[arg(long)]
    pub shard: Option<String>,
    /// Output archive.
    #[arg(long, short)]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// Which compute backend to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BackendChoice {
    /// A hardware GPU if there is one, else the CPU path.
    Auto,
    /// The CPU reference path only.
    Cpu,
    /// A wgpu device, software adapters (lavapipe, llvmpipe) included; fails without one.
    Gpu,
}

/// `strata serve` options.
#[derive(Debug, clap::Args)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub addr: SocketAddr,
    /// Data directory (scene store, caches).
    #[arg(long, default_value = "data")]
    pub data: PathBuf,
    /// Compute backend.
    #[arg(long, value_enum, default_value_t = BackendChoice::Auto)]
    pub backend: BackendChoice,
    /// Directory of the browser viewer served at `/`.
    #[arg(long, default_value = "web/dist")]
    pub web: PathBuf,
    /// Server admin token: may create worlds and acts as admin of every world. Read from
    /// `STRATA_ADMIN_TOKEN` when not given. Without one, anyone may create worlds.
    #[arg(long)]
    pub admin_token: Option<crate::server::access::Secret>,
    /// Directory of the disk tier of the stage cache (finished tiles by input hash); memory
    /// only without it.
    #[arg(long)]
    pub cache_dir: Option<PathBuf>,
}

/// `strata bench` options.
#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    /// Benchmark name: `tiles`, `serve`, `strata`, `poisson`, `volume` or `realism`.
    pub name: String,
    /// Print one JSON object per line instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Tiles to synthesise per core.
    #[arg(long, default_value_t = 200)]
    pub tiles: usize,
}

/// Runs a parsed command line.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    keep_freed_memory();
    match cli.command {
        Command::Serve(args) => {
            // Mesa's drivers complain on every adapter probe without it. Set before any thread
            // exists, so nothing reads the environment concurrently.
            if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
                std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
            }
            tracing_subscriber::fmt()
                .with_env_filter(
                    tracing_subscriber::EnvFilter::try_from_default_env()
                        .unwrap_or_else(|_| "strata=info,tower_http=info".into()),
                )
                .init();
            let rt = tokio::runtime::Builder::new_multi_thread()
                .enable_all()
                .build()?;
            rt.block_on(crate::server::serve(args))
        }
        Command::Bench(args) => crate::bench::run(&args),
        Command::Export(args) => crate::export::cli::run(&args),
    }
}

/// Heap bytes glibc may keep after frees instead of returning them to the system.
pub const MALLOC_TRIM_THRESHOLD: i32 = 256 << 20;
/// Allocations from this size up get their own mapping (smaller ones reuse the heap).
pub const MALLOC_MMAP_THRESHOLD: i32 = 32 << 20;

/// Tile synthesis allocates and frees a few hundred kilobytes per tile; glibc's default
/// thresholds hand that memory back to the kernel and fault it in again for the next tile (about
/// 3% of a tile's time in page faults, 5% in zeroing). Keeping it costs at most
/// [`MALLOC_TRIM_THRESHOLD`] of idle heap.
fn keep_freed_memory() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets allocator parameters; it is called before any other thread
    // exists.
    unsafe {
        libc::mallopt(libc::M_TRIM_THRESHOLD, MALLOC_TRIM_THRESHOLD);
        libc::mallopt(libc::M_MMAP_THRESHOLD, MALLOC_MMAP_THRESHOLD);
    }
}
