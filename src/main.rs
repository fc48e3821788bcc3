//! The `strata` command: `serve` runs the server, `bench` measures.

use clap::Parser;

/// mimalloc keeps freed pages for reuse instead of returning them to the system at once: a
/// volume region's fields (tens of MB, allocated and freed per run) then cost no page faults the
/// second time, about 15 % of a 128 × 64 × 128 run's CPU time with the system allocator.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> anyhow::Result<()> {
    strata::cli::run(strata::cli::Cli::parse())
}
