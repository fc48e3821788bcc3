//! The figures of one grid for `strata bench realism`: the terrain statistics of
//! [`super::metrics`] gathered per grid ([`Figures`]), their text in the report's table and JSON
//! lines (with the LOD-consistency check's and the border method's), and the printing of those
//! lines.

use super::metrics::{
    anisotropy, depressions, extrema, hypsometry, percentile, slopes, spectrum, water_fraction,
    Anisotropy, Depressions, Extrema, Grid, Hypsometry, Slopes, Spectrum, HYPSOMETRY_FRACTIONS,
};
use super::sample::LodCheck;
use super::{border, DEPRESSION_DEPTH_M, TARGET_LOD_RATIO};
use crate::bench::{emit, BenchArgs};
use serde_json::{json, Value};

/// The terrain statistics of one grid.
#[derive(Clone, Copy, Debug)]
pub(super) struct Figures {
    pub(super) slopes: Slopes,
    pub(super) depressions: Depressions,
    pub(super) extrema: Extrema,
    pub(super) spectrum: Spectrum,
    pub(super) hypsometry: Hypsometry,
    pub(super) anisotropy: Anisotropy,
    pub(super) land_fraction: f64,
    /// Share of the land under lake or river water (NaN for a real DEM, which records no water).
    pub(super) water_fraction: f64,
    pub(super) relief_m: f64,
}

/// The figures of `g` (heights of the surface, lakes and rivers at their level); `water`, one
/// water surface per cell (NaN where none), for a world's grid.
pub(super) fn figures(g: &Grid, sea: f64, water: Option<&[f32]>) -> Figures {
    let mut land: Vec<f64> = g
        .heights
        .iter()
        .map(|v| *v as f64)
        .filter(|v| *v > sea)
        .collect();
    let land_fraction = land.len() as f64 / g.heights.len() as f64;
    let relief_m = percentile(&mut land, 0.95) - percentile(&mut land, 0.05);
    Figures {
        slopes: slopes(g, sea),
        depressions: depressions(g, sea, DEPRESSION_DEPTH_M),
        extrema: extrema(g, sea),
        spectrum: spectrum(g),
        hypsometry: hypsometry(g, sea),
        anisotropy: anisotropy(g, sea),
        land_fraction,
        water_fraction: water.map_or(f64::NAN, |w| water_fraction(g, sea, w)),
        relief_m,
    }
}

pub(super) fn figures_json(f: &Figures, v: &mut Value) {
    let h = &f.hypsometry;
    let add = json!({
        "slope_median_deg": f.slopes.median_deg,
        "slope_p95_deg": f.slopes.p95_deg,
        "steepest_step_deg": f.slopes.steepest_step_deg,
        "cliff_step_fraction": f.slopes.cliff_fraction,
        "depression_fraction_deeper_than_2m": f.depressions.fraction,
        "peaks_per_km2": f.extrema.peaks_per_km2,
        "pits_per_km2": f.extrema.pits_per_km2,
        "spectrum_slope": f.spectrum.slope,
        "spectrum_min_wavelength_m": f.spectrum.min_wavelength_m,
        "spectrum_max_wavelength_m": f.spectrum.max_wavelength_m,
        "hypsometric_integral": h.integral,
        "hypsometric_area_fractions": HYPSOMETRY_FRACTIONS,
        "hypsometric_curve_m": h.elevations_m,
        "hypsometric_curve_relative": h.relative,
        "land_min_m": h.min_m,
        "land_max_m": h.max_m,
        "anisotropy_ratio": f.anisotropy.ratio,
        "aspect_counts_e_se_s_sw_w_nw_n_ne": f.anisotropy.counts,
        "land_fraction": f.land_fraction,
        "water_fraction_of_land": (!f.water_fraction.is_nan()).then_some(f.water_fraction),
        "relief_p5_p95_m": f.relief_m,
    });
    if let (Some(v), Value::Object(add)) = (v.as_object_mut(), add) {
        v.extend(add);
    }
}

/// A number for the table: `n/a` for NaN, `∞` for infinity.
pub(super) fn num(v: f64, digits: usize) -> String {
    if v.is_nan() {
        "n/a".into()
    } else if v.is_infinite() {
        "∞".into()
    } else {
        format!("{v:.digits$}")
    }
}

pub(super) fn mark(ok: bool) -> &'static str {
    if ok {
        "✓"
    } else {
        "✗"
    }
}

pub(super) fn in_range(v: f64, (lo, hi): (f64, f64)) -> bool {
    v >= lo && v <= hi
}

/// `✓`/`✗` after a target, or `(n/a)` when the figure is undefined (no land, no border).
pub(super) fn check(v: f64, ok: bool) -> &'static str {
    if v.is_nan() {
        "(n/a)"
    } else {
        mark(ok)
    }
}

pub(super) fn curve(h: &Hypsometry) -> String {
    h.relative
        .iter()
        .map(|r| num(*r, 2))
        .collect::<Vec<_>>()
        .join("/")
}

/// The rows every grid has: label and value text (`mod.rs` attaches the targets by position: new
/// rows go last).
pub(super) fn rows(f: &Figures) -> Vec<(&'static str, String)> {
    vec![
        ("slope median, °", num(f.slopes.median_deg, 1)),
        ("slope 95th percentile, °", num(f.slopes.p95_deg, 1)),
        (
            "closed depressions > 2 m, % of land",
            num(100.0 * f.depressions.fraction, 2),
        ),
        ("peaks per km²", num(f.extrema.peaks_per_km2, 3)),
        ("pits per km²", num(f.extrema.pits_per_km2, 3)),
        ("power-spectrum slope", num(f.spectrum.slope, 2)),
        ("hypsometric integral", num(f.hypsometry.integral, 3)),
        ("hypsometric curve (10/25/50/75/90 %)", curve(&f.hypsometry)),
        ("gradient-direction anisotropy", num(f.anisotropy.ratio, 2)),
        ("land, %", num(100.0 * f.land_fraction, 1)),
        (
            "lakes and rivers, % of land",
            num(100.0 * f.water_fraction, 1),
        ),
        ("relief p5–p95, m", num(f.relief_m, 0)),
        (
            "steepest step between neighbours, °",
            num(f.slopes.steepest_step_deg, 1),
        ),
        (
            "neighbour steps steeper than 63°, %",
            num(100.0 * f.slopes.cliff_fraction, 3),
        ),
    ]
}

pub(super) const LABEL: usize = 40;
pub(super) const COL: usize = 26;

pub(super) fn spacing_text(m: f64) -> String {
    if m >= 1000.0 {
        format!("{:.2} km", m / 1e3)
    } else if (m - m.round()).abs() < 0.05 {
        format!("{m:.0} m")
    } else {
        format!("{m:.1} m")
    }
}

/// The LOD-consistency ratio, and the target with `p99 |Δh|` and the bound.
pub(super) fn lod_text(c: &Option<LodCheck>) -> (String, String) {
    match c {
        None => ("—".into(), "(LOD 0 is the reference)".into()),
        Some(c) => (
            num(c.p99_ratio, 3),
            format!(
                "≤ 1 {} (p99 |Δh| {} m, bound {} m, {} vertices)",
                check(c.p99_ratio, c.p99_ratio <= TARGET_LOD_RATIO),
                num(c.p99_diff_m, 2),
                num(c.bound_m, 2),
                c.vertices
            ),
        ),
    }
}

pub(super) fn lod_json(c: &Option<LodCheck>, v: &mut Value) {
    if let Some(c) = c {
        v["lod_consistency_p99_ratio"] = json!(c.p99_ratio);
        v["lod_diff_p99_m"] = json!(c.p99_diff_m);
        v["lod_diff_max_m"] = json!(c.max_diff_m);
        v["lod_error_bound_m"] = json!(c.bound_m);
        v["lod_vertices_compared"] = json!(c.vertices);
        v["lod0_tiles_sampled"] = json!(c.tiles);
        v["meets_lod_target"] = json!(c.p99_ratio <= TARGET_LOD_RATIO);
    }
}

/// Prints a line of the table (nothing with `--json`).
pub(super) fn table_line(args: &BenchArgs, line: String) {
    if !args.json {
        emit(args, Value::Null, line);
    }
}

/// Prints a JSON object (nothing without `--json`).
pub(super) fn json_line(args: &BenchArgs, v: Value) {
    if args.json {
        emit(args, v, String::new());
    }
}

/// How a border ratio was measured, for the table and the JSON.
pub(super) fn method_name(m: border::Method) -> &'static str {
    match m {
        border::Method::Within => "within the middle window",
        border::Method::Across => "middle window over the biomes alone",
    }
}
