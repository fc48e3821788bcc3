//! The `strata` command: `serve` runs the server, `bench` measures.

use clap::Parser;

fn main() -> anyhow::Result<()> {
    strata::cli::run(strata::cli::Cli::parse())
}
