//! `strata bench volume` (issue 5): meshing throughput against `fast-surface-nets` ([`mesh`]) and
//! the complete volume-region pipeline beside the paper's Table 1 ([`pipeline`]).

pub mod mesh;
pub mod pipeline;

use crate::cli::BenchArgs;

/// Runs both parts of the volume benchmark.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    pipeline::run(args)?;
    mesh::run(args)
}
