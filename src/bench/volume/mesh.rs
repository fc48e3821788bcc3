//! Part of `strata bench volume`.

use crate::cli::BenchArgs;

/// Runs this part of the benchmark.
pub fn run(_args: &BenchArgs) -> anyhow::Result<()> {
    anyhow::bail!("not implemented yet")
}
