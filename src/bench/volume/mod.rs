//! `strata bench volume` (issue 5): meshing throughput against `fast-surface-nets` ([`mesh`]) and
//! the complete volume-region pipeline beside the paper's Table 1 ([`pipeline`]).

pub mod mesh;
pub mod pipeline;

use crate::bench::BenchArgs;

/// Runs both parts of the volume benchmark; a failing part is reported and the other still runs.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let pipeline = pipeline::run(args);
    if let Err(e) = &pipeline {
        eprintln!("bench volume: the pipeline part failed: {e}");
    }
    mesh::run(args)?;
    pipeline
}
