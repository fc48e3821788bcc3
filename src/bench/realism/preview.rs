//! `strata hillshade`: a hillshade PNG and the terrain figures of any square of any world, to
//! look at what a world setting makes before serving it.
//!
//! `strata bench realism` shades five fixed areas of the default world; this command shades the
//! `tiles × tiles` tiles of one LOD around any centre, of the default world or of the world
//! settings in a JSON file (a scene's `world` object, `scene.world` of `POST /v1/worlds`,
//! [`crate::terrain::WorldParams`], read by [`crate::export::cli::world_settings`] as `strata
//! export` reads it), and prints the figures the bench prints for a grid ([`super::figures`]):
//! slopes, steepest step, closed depressions, relief. The grid is the one the bench samples
//! ([`super::sample::sample`]): the surface a DEM would record, lakes and rivers flat at their
//! level and drawn blue.

use super::figures::{figures, figures_json, num};
use super::hillshade;
use super::sample::{first_tile, sample};
use crate::terrain::plan::MAX_LOD;
use crate::terrain::WorldPlan;
use anyhow::Context;
use serde_json::json;
use std::path::PathBuf;
use std::time::Instant;

/// Most tiles per side: 32 × 32 tiles of 65² vertices is a 2048² picture and about a second of
/// CPU at LOD 0.
pub const MAX_TILES: usize = 32;

/// Options of `strata hillshade`.
#[derive(Debug, clap::Args)]
pub struct HillshadeArgs {
    /// World seed.
    #[arg(long, default_value_t = 42)]
    pub seed: u64,
    /// LOD of the tiles: vertex spacing `cell_m · 2^lod` (1 m at LOD 0 in the default world).
    #[arg(long, default_value_t = 3)]
    pub lod: u32,
    /// Centre of the square, metres east (negative: west).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub x: f64,
    /// Centre of the square, metres south (negative: north).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub z: f64,
    /// Tiles per side of the square, 1 to 32 (each 64 vertex spacings).
    #[arg(long, default_value_t = 8)]
    pub tiles: usize,
    /// A JSON file of world settings (a scene's `world` object); the settings of
    /// new worlds when absent.
    #[arg(long)]
    pub world: Option<PathBuf>,
    /// Where to write the PNG (RGB, one pixel a vertex, north up).
    #[arg(long)]
    pub out: PathBuf,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    /// Tint red the land in closed depressions deeper than 2 m (the cells the figures'
    /// priority-flood fill raises by more than that), to see where the figure comes from.
    #[arg(long)]
    pub depressions: bool,
}

/// Runs `strata hillshade`.
pub fn run(args: &HillshadeArgs) -> anyhow::Result<()> {
    anyhow::ensure!(
        (1..=MAX_TILES).contains(&args.tiles),
        "--tiles must be 1 to {MAX_TILES}, got {}",
        args.tiles
    );
    anyhow::ensure!(
        args.lod <= MAX_LOD,
        "--lod must be 0 to {MAX_LOD}, got {}",
        args.lod
    );
    anyhow::ensure!(
        args.x.is_finite() && args.z.is_finite() && args.x.abs() <= 1e9 && args.z.abs() <= 1e9,
        "--x and --z must be finite metres within ±1e9"
    );
    let params = crate::export::cli::world_settings(args.world.as_deref())?;
    let start = Instant::now();
    let plan = WorldPlan::new(args.seed, params)?;
    let sea = plan.params.sea_level_m as f64;
    let n = args.tiles;
    let s = sample(
        &plan,
        args.lod,
        first_tile(&plan, args.lod, args.x, n),
        first_tile(&plan, args.lod, args.z, n),
        n,
        n,
    );
    let g = s.surface();
    let water: Vec<bool> = s.water.iter().map(|w| !w.is_nan()).collect();
    let mut pixels = hillshade::rgb(&g, sea, Some(&water));
    if args.depressions {
        hillshade::tint_depressions(&g, sea, &mut pixels);
    }
    hillshade::write_rgb(&args.out, g.w, g.h, &pixels)
        .with_context(|| format!("writing {}", args.out.display()))?;
    let f = figures(&g, sea, Some(&s.water));
    let side_km = g.w as f64 * g.spacing_m / 1e3;
    if args.json {
        let mut v = json!({"png":args.out.display().to_string(),"seed":args.seed,"lod":args.lod,
            "center_x_m":args.x,"center_z_m":args.z,"spacing_m":g.spacing_m,
            "samples_w":g.w,"samples_h":g.h,"seconds":start.elapsed().as_secs_f64()});
        figures_json(&f, &mut v);
        println!("{v}");
    } else {
        println!(
            "{}: {}×{} vertices at {} m ({side_km:.1} km square) around ({:.1} km, {:.1} km), seed {}, {:.1} s",
            args.out.display(),
            g.w,
            g.h,
            g.spacing_m,
            args.x / 1e3,
            args.z / 1e3,
            args.seed,
            start.elapsed().as_secs_f64()
        );
        println!(
            "  land {:.0} %, relief p5–p95 {} m; slope median {}°, p95 {}°; steepest step {}°, steps steeper than 63° {} %; closed depressions deeper than 2 m {} % of the land; lakes and rivers {} % of the land",
            100.0 * f.land_fraction,
            num(f.relief_m, 0),
            num(f.slopes.median_deg, 1),
            num(f.slopes.p95_deg, 1),
            num(f.slopes.steepest_step_deg, 1),
            num(100.0 * f.slopes.cliff_fraction, 3),
            num(100.0 * f.depressions.fraction, 2),
            num(100.0 * f.water_fraction, 1),
        );
    }
    Ok(())
}
