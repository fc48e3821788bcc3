//! `strata bench`: performance figures against the issues' targets.

use crate::cli::BenchArgs;

/// Runs a benchmark by name.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    anyhow::bail!("unknown benchmark {:?}", args.name)
}
