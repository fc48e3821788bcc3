//! `strata bench poisson` (issue 4).

use crate::cli::BenchArgs;

/// Runs the Poisson benchmark.
pub fn run(_args: &BenchArgs) -> anyhow::Result<()> {
    anyhow::bail!("not implemented yet")
}
