//! `strata bench` options.

/// `strata bench` options.
#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    /// Benchmark name: `tiles`, `serve`, `strata`, `poisson`, `volume`, `realism`, `abuse`,
    /// `scale` or `ptex`.
    pub name: String,
    /// Print one JSON object per line instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Tiles to synthesise per core.
    #[arg(long, default_value_t = 200)]
    pub tiles: usize,
    /// Seconds of each load run of `bench scale`.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=600))]
    pub seconds: u32,
}
