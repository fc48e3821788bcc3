//! `strata export`: the export of the jobs API, run locally with a progress bar.

use super::{write_archive, ExportSpec, Product, Shard};
use crate::terrain::{WorldParams, WorldPlan, MAX_LOD};
use anyhow::Context;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::PathBuf;
use std::time::Instant;

/// `strata export` options.
#[derive(Debug, clap::Args)]
pub struct ExportArgs {
    /// World seed.
    #[arg(long)]
    pub seed: u64,
    /// World settings: a JSON file holding a scene's `world` object; the default world without
    /// it.
    #[arg(long, value_name = "FILE")]
    pub world: Option<PathBuf>,
    /// Level of detail, 0 (finest) to 12.
    #[arg(long, default_value_t = 0, value_parser = clap::value_parser!(u32).range(0..=i64::from(MAX_LOD)))]
    pub lod: u32,
    /// Tile rectangle: tiles x0 ≤ x < x1, z0 ≤ z < z1, e.g. `--region -2,-2,2,2`.
    #[arg(long, value_name = "X0,Z0,X1,Z1", allow_hyphen_values = true)]
    pub region: Region,
    /// Products, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "tiles")]
    pub products: Vec<ProductName>,
    /// Tile formats, comma-separated.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "bin")]
    pub formats: Vec<FormatName>,
    /// Write only part I of N of the export (I counted from 1); the parts of a region, in order,
    /// make the whole export.
    #[arg(long, value_name = "I/N", value_parser = Shard::parse)]
    pub shard: Option<Shard>,
    /// Texels per Ptex face side of the `ptex` product (a power of two in 8..=256).
    #[arg(long, default_value_t = 64)]
    pub ptex_res: u32,
    /// Output archive (tar).
    #[arg(long, short, value_name = "FILE")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
    pub threads: Option<u64>,
}

/// A tile rectangle `x0,z0,x1,z1`: tiles `x0 ≤ x < x1`, `z0 ≤ z < z1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    /// First column.
    pub x0: i64,
    /// First row.
    pub z0: i64,
    /// Column after the last.
    pub x1: i64,
    /// Row after the last.
    pub z1: i64,
}

impl std::str::FromStr for Region {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let values = s
            .split(',')
            .map(|v| {
                v.trim()
                    .parse::<i64>()
                    .map_err(|_| format!("{:?} is not an integer", v.trim()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let [x0, z0, x1, z1] = values[..] else {
            return Err(format!(
                "4 comma-separated integers x0,z0,x1,z1 required, got {}",
                values.len()
            ));
        };
        if x1 <= x0 || z1 <= z0 {
            return Err(format!(
                "the rectangle is empty: need x0 < x1 and z0 < z1, got {x0},{z0},{x1},{z1}"
            ));
        }
        Ok(Region { x0, z0, x1, z1 })
    }
}

/// A product of `--products`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ProductName {
    /// Height tiles, in each of `--formats`.
    Tiles,
    /// Scatter points (JSON).
    Scatter,
    /// Each tile's 4 × 4 Ptex faces as a `.ptx` file at `--ptex-res`.
    Ptex,
}

/// A tile format of `--formats`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FormatName {
    /// JSON.
    Json,
    /// Binary tile (`api/tile_format_v1.md`).
    Bin,
    /// 16-bit greyscale PNG of the heights.
    Png,
    /// glTF binary mesh.
    Glb,
}

impl FormatName {
    fn extension(self) -> &'static str {
        match self {
            FormatName::Json => "json",
            FormatName::Bin => "bin",
            FormatName::Png => "png",
            FormatName::Glb => "glb",
        }
    }
}

/// The world settings of a command's `--world` file (a scene's `world` object, `scene.world`
/// of `POST /v1/worlds`), or those of new worlds without one (`strata export`, `strata
/// hillshade`).
///
/// # Errors
/// The file cannot be read, or does not hold a world's settings (the message names the file).
pub fn world_settings(path: Option<&std::path::Path>) -> anyhow::Result<WorldParams> {
    let Some(path) = path else {
        return Ok(WorldParams::default());
    };
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    serde_json::from_str::<WorldParams>(&text)
        .with_context(|| format!("{} is not a world's settings", path.display()))
}

/// Options of `strata world-settings`.
#[derive(Debug, clap::Args)]
pub struct WorldSettingsArgs {
    /// A JSON file of world settings to check and print in full; the settings of new worlds
    /// when absent.
    #[arg(long)]
    pub world: Option<PathBuf>,
}

/// Runs `strata world-settings`: prints the settings of new worlds (or of the `--world` file,
/// checked as a world's settings are), every field spelled out, as pretty JSON: a file to edit
/// and give to `strata hillshade`, `strata export` or `POST /v1/worlds`. A file that leaves a
/// field out gets the value of worlds stored before that field existed, not of new worlds, so
/// start from this output.
pub fn print_world_settings(args: &WorldSettingsArgs) -> anyhow::Result<()> {
    let params = world_settings(args.world.as_deref())?;
    params.validate()?;
    println!("{}", serde_json::to_string_pretty(&params)?);
    Ok(())
}

/// Runs `strata export`.
pub fn run(args: &ExportArgs) -> anyhow::Result<()> {
    let params = world_settings(args.world.as_deref())?;
    let plan = WorldPlan::new(args.seed, params)?;
    let Region { x0, z0, x1, z1 } = args.region;
    let products = args
        .products
        .iter()
        .map(|p| match p {
            ProductName::Tiles => Product::Tiles,
            ProductName::Scatter => Product::Scatter,
            ProductName::Ptex => Product::Ptex,
        })
        .collect();
    let spec = ExportSpec {
        lod: args.lod,
        x0,
        z0,
        x1,
        z1,
        products,
        formats: args
            .formats
            .iter()
            .map(|f| f.extension().to_string())
            .collect(),
        ptex_res: args
            .products
            .contains(&ProductName::Ptex)
            .then_some(args.ptex_res),
    };
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let threads = args
        .threads
        .and_then(|n| usize::try_from(n).ok())
        .unwrap_or_else(|| {
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
