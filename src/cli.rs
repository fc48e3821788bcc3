//! Command-line interface: the `strata` command and its subcommands. Each subcommand's options
//! belong to the module that runs it ([`ServeArgs`] to `server`, [`BenchArgs`] to `bench`,
//! [`ExportArgs`], [`JoinArgs`] and [`WorldSettingsArgs`] to `export`, [`HillshadeArgs`] to
//! `bench::realism::preview`), so no module imports this one; only `src/main.rs` does.

use crate::bench::realism::preview::HillshadeArgs;
use crate::bench::BenchArgs;
use crate::export::cli::ExportArgs;
use crate::export::cli::WorldSettingsArgs;
use crate::export::join::JoinArgs;
use crate::server::ServeArgs;
use clap::{Parser, Subcommand};

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
    /// Join the archives of an export's shards into the archive of the whole export.
    ExportJoin(JoinArgs),
    /// Write a hillshade PNG of a square of a world and print its terrain figures.
    Hillshade(HillshadeArgs),
    /// Print the settings of new worlds (or check and print a settings file) as JSON.
    WorldSettings(WorldSettingsArgs),
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
        Command::ExportJoin(args) => crate::export::join::run(&args),
        Command::Hillshade(args) => crate::bench::realism::preview::run(&args),
        Command::WorldSettings(args) => crate::export::cli::print_world_settings(&args),
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
