//! `strata export`: the export of the jobs API, run locally with a progress bar.

use super::{write_archive, ExportSpec, Product, Shard};
use crate::terrain::{WorldParams, WorldPlan};
use anyhow::{bail, Context};
use std::io::{BufWriter, IsTerminal, Write};
use std::path::PathBuf;
use std::time::Instant;

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

/// Runs `strata export`.
pub fn run(args: &ExportArgs) -> anyhow::Result<()> {
    let params = match &args.world {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("reading {}", path.display()))?;
            serde_json::from_str::<WorldParams>(&text)
                .with_context(|| format!("parsing {}", path.display()))?
        }
        None => WorldParams::default(),
    };
    let plan = WorldPlan::new(args.seed, params)?;
    let [x0, z0, x1, z1] = args.region[..] else {
        bail!("--region needs x0,z0,x1,z1")
    };
    let products = args
        .products
        .iter()
        .map(|p| match p.as_str() {
            "tiles" => Ok(Product::Tiles),
            "scatter" => Ok(Product::Scatter),
            other => bail!("unknown product {other:?}; known: tiles, scatter"),
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let spec = ExportSpec {
        lod: args.lod,
        x0,
        z0,
        x1,
        z1,
        products,
        formats: args.formats.clone(),
    };
    let shard = match &args.shard {
        Some(s) => Shard::parse(s).map_err(anyhow::Error::msg)?,
        None => Shard::WHOLE,
    };
    let threads = args.threads.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    });
    let file = std::fs::File::create(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let mut out = BufWriter::new(file);
    let start = Instant::now();
    let tty = std::io::stderr().is_terminal();
    let mut last = 0.0f64;
    let manifest = write_archive(
        &plan,
        &Default::default(),
        &spec,
        shard,
        threads,
        &mut out,
        |done, total| {
            let t = start.elapsed().as_secs_f64();
            if done == total || t - last >= 0.2 {
                last = t;
                let width = 30;
                let filled = (done * width).checked_div(total).unwrap_or(width);
                let bar = format!("[{}{}]", "#".repeat(filled), " ".repeat(width - filled));
                let line = format!("{bar} {done}/{total} tiles  {t:.1} s");
                if tty {
                    eprint!("\r{line}");
                } else {
                    eprintln!("{line}");
                }
            }
        },
    )?;
    out.flush()?;
    if tty {
        eprintln!();
    }
    eprintln!(
        "wrote {} ({} members, shard {}/{})",
        args.out.display(),
        manifest.members.len(),
        shard.index + 1,
        shard.count
    );
    Ok(())
}
