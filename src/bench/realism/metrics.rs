//! Terrain statistics on a plain height grid, each a pure function.
//!
//! A [`Grid`] is `w × h` heights in metres, row-major (`heights[j·w + i]`), with the same spacing
//! `spacing_m` along both axes; `i` grows east, `j` grows south (row 0 is the north edge). Where a
//! statistic speaks of *land*, it means the cells higher than the sea level passed to it (pass
//! `f64::NEG_INFINITY` for a grid without sea): the sea floor is not terrain a walker sees.
//!
//! - **Slope** ([`slopes`]): at every interior land cell, `atan(|∇h|)` in degrees, the gradient
//!   from central differences `((h[i+1] − h[i−1]) / 2s, (h[j+1] − h[j−1]) / 2s)`; the median and
//!   the 95th percentile (nearest rank) over those cells.
//! - **Closed depressions** ([`depressions`]): the grid filled by priority-flood (Barnes, Lehman
//!   & Mulla 2014, *Priority-flood: an optimal depression-filling and watershed-labeling
//!   algorithm*, algorithm 1, 8-neighbour): the grid border and every cell at or below sea level
//!   are outlets; every other cell is raised to the lowest level from which water could leave
//!   through outlets. The figure is the fraction of land cells raised by more than 2 m.
//! - **Peaks and pits** ([`extrema`]): interior land cells strictly higher (peaks) or strictly
//!   lower (pits) than all 8 neighbours, per km² of interior land (`cells · s² / 10⁶`).
//! - **Power-spectrum slope** ([`spectrum`]): the heights minus their least-squares plane, times
//!   a separable Hann window, 2-D FFT (`rustfft`); the power `|F|²` radially averaged in 12
//!   logarithmic wavenumber bins, and the least-squares slope of `log₁₀ P` against `log₁₀ k` over
//!   the band of wavelengths from 4 samples to a quarter of the grid's shorter side. For
//!   fractional Brownian surfaces with Hurst exponent `H` the slope is `−(2H + 2)`; real
//!   landscapes typically give −3 to −4 over this kind of band.
//! - **Hypsometry** ([`hypsometry`]): over land cells, the elevation exceeded by 10, 25, 50, 75
//!   and 90 % of the area (metres, and relative: `(z − min) / (max − min)`), and the hypsometric
//!   integral `(mean − min) / (max − min)`.
//! - **Gradient-direction anisotropy** ([`anisotropy`]): the direction of the central-difference
//!   gradient at interior land cells whose slope exceeds 1°, counted in 8 bins of 45° centred on
//!   east, south-east, south, … (`z` grows south; bin `round(θ / 45°) mod 8`,
//!   `θ = atan2(∂h/∂z, ∂h/∂x)`), and the largest count over the smallest (infinite when a bin is
//!   empty). 1 means no preferred direction.
//! - **Biome-border curvature ratio** ([`border_curvature`]): the mean of `|∇²h|` in 1/m, the
//!   5-point Laplacian `(h[i+1] + h[i−1] + h[j+1] + h[j−1] − 4h) / s²`, over interior cells marked
//!   as border (by the caller: a vertex whose largest biome weight is below 0.99), divided by the
//!   same mean over the other interior cells; `None` when either set is empty. Values near 1 mean
//!   the blend leaves no seam of extra curvature. [`land_border_curvature`] leaves out the cells
//!   whose stencil touches lake or river water: a shore's curvature is the water's, wherever a
//!   lake happens to lie, not the blend's.

use rustfft::{num_complex::Complex, FftPlanner};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// A square-spaced height grid (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// Columns (east).
    pub w: usize,
    /// Rows (south).
    pub h: usize,
    /// Sample spacing along both axes, metres.
    pub spacing_m: f64,
    /// Heights, metres, `heights[j·w + i]`.
    pub heights: Vec<f32>,
}

impl Grid {
    /// A grid; `heights.len()` must be `w · h`.
    pub fn new(w: usize, h: usize, spacing_m: f64, heights: Vec<f32>) -> Self {
        assert_eq!(heights.len(), w * h, "a {w}×{h} grid has {} heights", w * h);
        Self {
            w,
            h,
            spacing_m,
            heights,
        }
    }

    /// A grid of `f(x, z)` at `x = i·s`, `z = j·s`.
    pub fn from_fn(w: usize, h: usize, spacing_m: f64, f: impl Fn(f64, f64) -> f64) -> Self {
        let heights = (0..w * h)
            .map(|k| f((k % w) as f64 * spacing_m, (k / w) as f64 * spacing_m) as f32)
            .collect();
        Self::new(w, h, spacing_m, heights)
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        self.heights[j * self.w + i] as f64
    }

    /// Central-difference gradient `(∂h/∂x, ∂h/∂z)` at an interior cell.
    #[inline]
    fn gradient(&self, i: usize, j: usize) -> (f64, f64) {
        let s2 = 2.0 * self.spacing_m;
        (
            (self.at(i + 1, j) - self.at(i - 1, j)) / s2,
            (self.at(i, j + 1) - self.at(i, j - 1)) / s2,
        )
    }

    /// Interior cells `(i, j)` whose height is above `sea_level_m`.
    fn interior_land(&self, sea_level_m: f64) -> impl Iterator<Item = (usize, usize)> + '_ {
        (1..self.h.saturating_sub(1))
            .flat_map(move |j| (1..self.w.saturating_sub(1)).map(move |i| (i, j)))
            .filter(move |&(i, j)| self.at(i, j) > sea_level_m)
    }

    /// Block average to `spacing_m` (coarser than the grid's): output cell `(a, b)` is the mean
    /// of the cells `(i, j)` with `⌊i·s / S⌋ = a`, `⌊j·s / S⌋ = b`; a last, incomplete block is
    /// dropped.
    pub fn block_average(&self, spacing_m: f64) -> Grid {
        let ratio = self.spacing_m / spacing_m;
        let w = (self.w as f64 * ratio).floor() as usize;
        let h = (self.h as f64 * ratio).floor() as usize;
        let mut sum = vec![0.0f64; w * h];
        let mut count = vec![0u32; w * h];
        for j in 0..self.h {
            let b = (j as f64 * ratio).floor() as usize;
            if b >= h {
                continue;
            }
            for i in 0..self.w {
                let a = (i as f64 * ratio).floor() as usize;
                if a < w {
                    sum[b * w + a] += self.at(i, j);
                    count[b * w + a] += 1;
                }
            }
        }
        let heights = sum
            .iter()
            .zip(&count)
            .map(|(s, c)| (s / (*c).max(1) as f64) as f32)
            .collect();
        Grid::new(w, h, spacing_m, heights)
    }

    /// Bilinear resampling to `spacing_m` over the same extent (`⌊(n − 1)·s / S⌋ + 1` samples a
    /// side).
    pub fn resample(&self, spacing_m: f64) -> Grid {
        resample_axes(
            &self.heights,
            self.w,
            self.h,
            self.spacing_m,
            self.spacing_m,
            spacing_m,
        )
    }
}

/// Bilinear resampling of a `w × h` row-major grid with spacings `dx_m` (along rows) and `dz_m`
/// (down columns) to a square grid of spacing `spacing_m` over the same extent.
pub fn resample_axes(
    heights: &[f32],
    w: usize,
    h: usize,
    dx_m: f64,
    dz_m: f64,
    spacing_m: f64,
) -> Grid {
    let nw = (((w - 1) as f64 * dx_m / spacing_m) + 1e-9).floor() as usize + 1;
    let nh = (((h - 1) as f64 * dz_m / spacing_m) + 1e-9).floor() as usize + 1;
    let mut out = Vec::with_capacity(nw * nh);
    for b in 0..nh {
        let z = (b as f64 * spacing_m / dz_m).min((h - 1) as f64);
        let j0 = (z.floor() as usize).min(h.saturating_sub(2));
        let fz = z - j0 as f64;
        let j1 = (j0 + 1).min(h - 1);
        for a in 0..nw {
            let x = (a as f64 * spacing_m / dx_m).min((w - 1) as f64);
            let i0 = (x.floor() as usize).min(w.saturating_sub(2));
            let fx = x - i0 as f64;
            let i1 = (i0 + 1).min(w - 1);
            let v = |i: usize, j: usize| heights[j * w + i] as f64;
            let top = v(i0, j0) * (1.0 - fx) + v(i1, j0) * fx;
            let bottom = v(i0, j1) * (1.0 - fx) + v(i1, j1) * fx;
            out.push((top * (1.0 - fz) + bottom * fz) as f32);
        }
    }
    Grid::new(nw, nh, spacing_m, out)
}

/// Nearest-rank percentile `q ∈ [0, 1]` of `v` (sorted in place); NaN when empty.
pub fn percentile(v: &mut [f64], q: f64) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let rank = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len());
    v[rank - 1]
}

/// Slope percentiles, degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slopes {
    /// Median slope, degrees.
    pub median_deg: f64,
    /// 95th percentile, degrees.
    pub p95_deg: f64,
    /// Steepest step between two neighbouring cells (along a row or a column), degrees.
    pub steepest_step_deg: f64,
    /// Share of the neighbour pairs whose step is steeper than [`CLIFF_RISE`] (63.4°).
    pub cliff_fraction: f64,
}

/// Rise over run between neighbouring cells above which a step counts as a cliff (63.4°): a
/// face that steep over a whole cell is rare in real terrain at 8 m and more, and a run of such
/// steps one cell wide is the mark of a discontinuity in the height function (the gullies of
/// `gullies: 2` made them).
pub const CLIFF_RISE: f64 = 2.0;

/// Slope median and 95th percentile over interior land cells, degrees; the steepest step and
/// the share of cliff steps between each interior land cell and its next cell along the row and
/// the column.
pub fn slopes(g: &Grid, sea_level_m: f64) -> Slopes {
    let mut deg: Vec<f64> = g
        .interior_land(sea_level_m)
        .map(|(i, j)| {
            let (gx, gz) = g.gradient(i, j);
            gx.hypot(gz).atan().to_degrees()
        })
        .collect();
    let (mut steepest, mut cliffs, mut pairs) = (0.0f64, 0usize, 0usize);
    for (i, j) in g.interior_land(sea_level_m) {
        for (a, b) in [(i + 1, j), (i, j + 1)] {
            let rise = (g.at(a, b) - g.at(i, j)).abs() / g.spacing_m;
            steepest = steepest.max(rise);
            cliffs += usize::from(rise > CLIFF_RISE);
            pairs += 1;
        }
    }
    Slopes {
        median_deg: percentile(&mut deg, 0.5),
        p95_deg: percentile(&mut deg, 0.95),
        steepest_step_deg: steepest.atan().to_degrees(),
        cliff_fraction: cliffs as f64 / pairs.max(1) as f64,
    }
}

/// Orders `f32` like `total_cmp` as an unsigned key.
fn order_key(v: f32) -> u32 {
    let b = v.to_bits();
    if b >> 31 == 1 {
        !b
    } else {
        b | 0x8000_0000
    }
}

/// Priority-flood fill (Barnes et al. 2014, algorithm 1, 8-neighbour): the border and the cells
/// at or below `sea_level_m` are outlets; returns the filled heights.
pub fn priority_flood(g: &Grid, sea_level_m: f64) -> Vec<f32> {
    let (w, h) = (g.w, g.h);
    let mut filled = g.heights.clone();
    let mut closed = vec![false; w * h];
    let mut open = BinaryHeap::new();
    for j in 0..h {
        for i in 0..w {
            let k = j * w + i;
            if i == 0 || j == 0 || i + 1 == w || j + 1 == h || g.at(i, j) <= sea_level_m {
                closed[k] = true;
                open.push(Reverse((order_key(filled[k]), k)));
            }
        }
    }
    while let Some(Reverse((_, k))) = open.pop() {
        let (i, j) = ((k % w) as i64, (k / w) as i64);
        for (di, dj) in NEIGHBOURS {
            let (ni, nj) = (i + di, j + dj);
            if ni < 0 || nj < 0 || ni >= w as i64 || nj >= h as i64 {
                continue;
            }
            let n = nj as usize * w + ni as usize;
            if !closed[n] {
                closed[n] = true;
                filled[n] = filled[n].max(filled[k]);
                open.push(Reverse((order_key(filled[n]), n)));
            }
        }
    }
    filled
}

const NEIGHBOURS: [(i64, i64); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

/// Share of the land cells of `g` (above `sea_level_m`) that hold lake or river water, 0–1:
/// `water` has one water surface per cell, NaN where there is none (same layout as `g`). NaN
/// when no cell is land.
pub fn water_fraction(g: &Grid, sea_level_m: f64, water: &[f32]) -> f64 {
    assert_eq!(water.len(), g.heights.len());
    let (land, wet) = g
        .heights
        .iter()
        .zip(water)
        .filter(|(z, _)| **z as f64 > sea_level_m)
        .fold((0usize, 0usize), |(l, n), (_, w)| {
            (l + 1, n + usize::from(!w.is_nan()))
        });
    wet as f64 / land as f64
}

/// Closed depressions after a priority-flood fill.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Depressions {
    /// Fraction of land cells the fill raises by more than `min_depth_m` (0–1).
    pub fraction: f64,
    /// The depth threshold, metres.
    pub min_depth_m: f64,
    /// Land cells.
    pub land_cells: usize,
}

/// Fraction of land cells in closed depressions deeper than `min_depth_m` (see the module docs).
pub fn depressions(g: &Grid, sea_level_m: f64, min_depth_m: f64) -> Depressions {
    let filled = priority_flood(g, sea_level_m);
    let (mut land, mut deep) = (0usize, 0usize);
    for (z, f) in g.heights.iter().zip(&filled) {
        if (*z as f64) > sea_level_m {
            land += 1;
            if (*f as f64 - *z as f64) > min_depth_m {
                deep += 1;
            }
        }
    }
    Depressions {
        fraction: if land == 0 {
            f64::NAN
        } else {
            deep as f64 / land as f64
        },
        min_depth_m,
        land_cells: land,
    }
}

/// Strict 8-neighbour extrema per km² of interior land.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extrema {
    /// Peaks per km².
    pub peaks_per_km2: f64,
    /// Pits per km².
    pub pits_per_km2: f64,
}

/// Peaks and pits per km² (see the module docs).
pub fn extrema(g: &Grid, sea_level_m: f64) -> Extrema {
    let (mut cells, mut peaks, mut pits) = (0usize, 0usize, 0usize);
    for (i, j) in g.interior_land(sea_level_m) {
        cells += 1;
        let c = g.at(i, j);
        let (mut higher, mut lower) = (true, true);
        for (di, dj) in NEIGHBOURS {
            let n = g.at((i as i64 + di) as usize, (j as i64 + dj) as usize);
            higher &= c > n;
            lower &= c < n;
        }
        peaks += usize::from(higher);
        pits += usize::from(lower);
    }
    let km2 = cells as f64 * g.spacing_m * g.spacing_m / 1e6;
    Extrema {
        peaks_per_km2: peaks as f64 / km2,
        pits_per_km2: pits as f64 / km2,
    }
}

/// Radially averaged power-spectrum fit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spectrum {
    /// Slope of `log₁₀ P` against `log₁₀ k` (negative for terrain).
    pub slope: f64,
    /// Shortest wavelength of the band, metres.
    pub min_wavelength_m: f64,
    /// Longest wavelength of the band, metres.
    pub max_wavelength_m: f64,
    /// Bins that held samples (at least 3 for a slope).
    pub bins: usize,
}

/// The power-spectrum slope (see the module docs). NaN when the grid is too small for three
/// bins.
pub fn spectrum(g: &Grid) -> Spectrum {
    let (w, h, s) = (g.w, g.h, g.spacing_m);
    let min_wavelength_m = 4.0 * s;
    let max_wavelength_m = w.min(h) as f64 * s / 4.0;
    let nan = Spectrum {
        slope: f64::NAN,
        min_wavelength_m,
        max_wavelength_m,
        bins: 0,
    };
    if w < 16 || h < 16 {
        return nan;
    }
    // Least-squares plane: with centred coordinates on a full grid the normal equations decouple.
    let (cx, cz) = ((w - 1) as f64 / 2.0, (h - 1) as f64 / 2.0);
    let n = (w * h) as f64;
    let mean = g.heights.iter().map(|v| *v as f64).sum::<f64>() / n;
    let (mut sxh, mut sxx, mut szh, mut szz) = (0.0, 0.0, 0.0, 0.0);
    for j in 0..h {
        for i in 0..w {
            let (x, z, v) = (i as f64 - cx, j as f64 - cz, g.at(i, j) - mean);
            sxh += x * v;
            sxx += x * x;
            szh += z * v;
            szz += z * z;
        }
    }
    let (bx, bz) = (sxh / sxx, szh / szz);
    let hann = |k: usize, n: usize| {
        0.5 * (1.0 - (2.0 * std::f64::consts::PI * k as f64 / (n - 1) as f64).cos())
    };
    let wx: Vec<f64> = (0..w).map(|i| hann(i, w)).collect();
    let wz: Vec<f64> = (0..h).map(|j| hann(j, h)).collect();
    let mut data: Vec<Complex<f64>> = (0..w * h)
        .map(|k| {
            let (i, j) = (k % w, k / w);
            let v = g.at(i, j) - mean - bx * (i as f64 - cx) - bz * (j as f64 - cz);
            Complex::new(v * wx[i] * wz[j], 0.0)
        })
        .collect();
    fft2(&mut data, w, h, false);

    const BINS: usize = 12;
    let (k_lo, k_hi) = (1.0 / max_wavelength_m, 1.0 / min_wavelength_m);
    let (l_lo, l_hi) = (k_lo.log10(), k_hi.log10());
    let mut sum_p = [0.0f64; BINS];
    let mut sum_lk = [0.0f64; BINS];
    let mut count = [0usize; BINS];
    for fj in 0..h {
        let kz = signed(fj, h) / (h as f64 * s);
        for fi in 0..w {
            let kx = signed(fi, w) / (w as f64 * s);
            let k = kx.hypot(kz);
            if k < k_lo || k > k_hi {
                continue;
            }
            let lk = k.log10();
            let b = (((lk - l_lo) / (l_hi - l_lo) * BINS as f64) as usize).min(BINS - 1);
            sum_p[b] += data[fj * w + fi].norm_sqr();
            sum_lk[b] += lk;
            count[b] += 1;
        }
    }
    let points: Vec<(f64, f64)> = (0..BINS)
        .filter(|b| count[*b] > 0 && sum_p[*b] > 0.0)
        .map(|b| {
            (
                sum_lk[b] / count[b] as f64,
                (sum_p[b] / count[b] as f64).log10(),
            )
        })
        .collect();
    if points.len() < 3 {
        return nan;
    }
    Spectrum {
        slope: fit_slope(&points),
        bins: points.len(),
        ..nan
    }
}

/// Signed frequency index of FFT bin `f` of `n`.
fn signed(f: usize, n: usize) -> f64 {
    if f <= n / 2 {
        f as f64
    } else {
        f as f64 - n as f64
    }
}

/// Least-squares slope of `y` against `x`.
fn fit_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    sxy / sxx
}

/// In-place 2-D FFT of a `w × h` row-major array (inverse when `inverse`, unnormalised).
pub fn fft2(data: &mut [Complex<f64>], w: usize, h: usize, inverse: bool) {
    let mut planner = FftPlanner::<f64>::new();
    let (row, col) = if inverse {
        (planner.plan_fft_inverse(w), planner.plan_fft_inverse(h))
    } else {
        (planner.plan_fft_forward(w), planner.plan_fft_forward(h))
    };
    row.process(data);
    let mut column = vec![Complex::new(0.0, 0.0); h];
    for i in 0..w {
        for j in 0..h {
            column[j] = data[j * w + i];
        }
        col.process(&mut column);
        for j in 0..h {
            data[j * w + i] = column[j];
        }
    }
}

/// Area fractions of the hypsometric curve.
pub const HYPSOMETRY_FRACTIONS: [f64; 5] = [0.1, 0.25, 0.5, 0.75, 0.9];

/// Hypsometric curve and integral over land cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hypsometry {
    /// Elevation exceeded by each of [`HYPSOMETRY_FRACTIONS`] of the land area, metres.
    pub elevations_m: [f64; 5],
    /// The same relative to the land's range: `(z − min) / (max − min)`.
    pub relative: [f64; 5],
    /// `(mean − min) / (max − min)`.
    pub integral: f64,
    /// Lowest land height, metres.
    pub min_m: f64,
    /// Highest land height, metres.
    pub max_m: f64,
}

/// The hypsometric curve (see the module docs).
pub fn hypsometry(g: &Grid, sea_level_m: f64) -> Hypsometry {
    let mut land: Vec<f64> = g
        .heights
        .iter()
        .map(|v| *v as f64)
        .filter(|v| *v > sea_level_m)
        .collect();
    land.sort_by(f64::total_cmp);
    let (min, max) = (
        land.first().copied().unwrap_or(f64::NAN),
        land.last().copied().unwrap_or(f64::NAN),
    );
    let mean = land.iter().sum::<f64>() / land.len() as f64;
    let range = max - min;
    let elevations_m = HYPSOMETRY_FRACTIONS.map(|a| percentile(&mut land, 1.0 - a));
    Hypsometry {
        elevations_m,
        relative: elevations_m.map(|z| (z - min) / range),
        integral: (mean - min) / range,
        min_m: min,
        max_m: max,
    }
}

/// Gradient-direction counts in 8 bins of 45°.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Anisotropy {
    /// Largest count over smallest (infinite when a bin is empty, NaN when all are).
    pub ratio: f64,
    /// Counts per bin: east, south-east, south, … (`θ` grows from +x towards +z, south).
    pub counts: [u64; 8],
}

/// Gradient-direction anisotropy (see the module docs).
pub fn anisotropy(g: &Grid, sea_level_m: f64) -> Anisotropy {
    let min_gradient = 1.0f64.to_radians().tan();
    let mut counts = [0u64; 8];
    for (i, j) in g.interior_land(sea_level_m) {
        let (gx, gz) = g.gradient(i, j);
        if gx.hypot(gz) <= min_gradient {
            continue;
        }
        let bin = (gz.atan2(gx).to_degrees() / 45.0).round().rem_euclid(8.0) as usize % 8;
        counts[bin] += 1;
    }
    let max = *counts.iter().max().unwrap_or(&0) as f64;
    let min = *counts.iter().min().unwrap_or(&0) as f64;
    Anisotropy {
        ratio: if max == 0.0 { f64::NAN } else { max / min },
        counts,
    }
}

/// Mean `|∇²h|` on and off biome borders.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BorderCurvature {
    /// Sum of `|∇²h|` over border cells, 1/m.
    pub border_sum: f64,
    /// Border cells.
    pub border_cells: usize,
    /// Sum of `|∇²h|` over the other cells, 1/m.
    pub other_sum: f64,
    /// Other cells.
    pub other_cells: usize,
}

impl BorderCurvature {
    /// Mean `|∇²h|` on borders over the mean elsewhere; `None` when either set is empty.
    pub fn ratio(&self) -> Option<f64> {
        (self.border_cells > 0 && self.other_cells > 0 && self.other_sum > 0.0).then(|| {
            (self.border_sum / self.border_cells as f64)
                / (self.other_sum / self.other_cells as f64)
        })
    }

    /// Whether both sides are marked but one holds less than `min_side` of all the cells, too
    /// few for its mean to be compared.
    pub fn one_side_only(&self, min_side: f64) -> bool {
        let cells = (self.border_cells + self.other_cells) as f64;
        self.border_cells > 0 && (self.border_cells.min(self.other_cells) as f64) < min_side * cells
    }

    /// [`BorderCurvature::ratio`] where each side holds at least `min_side` of all the cells.
    pub fn two_sided_ratio(&self, min_side: f64) -> Option<f64> {
        self.ratio().filter(|_| !self.one_side_only(min_side))
    }

    /// Pools two measurements.
    pub fn add(&mut self, other: &BorderCurvature) {
        self.border_sum += other.border_sum;
        self.border_cells += other.border_cells;
        self.other_sum += other.other_sum;
        self.other_cells += other.other_cells;
    }
}

/// `|∇²h|` sums on and off the cells marked in `border` (same layout as the grid), interior
/// cells only.
pub fn border_curvature(g: &Grid, border: &[bool]) -> BorderCurvature {
    curvature_where(g, border, |_, _| true)
}

/// [`border_curvature`] over the interior cells whose five-point stencil holds no lake or river
/// water (`water`: the water surface over each cell, NaN where there is none; same layout).
pub fn land_border_curvature(g: &Grid, border: &[bool], water: &[f32]) -> BorderCurvature {
    assert_eq!(water.len(), g.heights.len());
    let dry = |i: usize, j: usize| water[j * g.w + i].is_nan();
    curvature_where(g, border, |i, j| {
        dry(i, j) && dry(i + 1, j) && dry(i - 1, j) && dry(i, j + 1) && dry(i, j - 1)
    })
}

/// [`border_curvature`] over the interior cells `(i, j)` where `keep(i, j)`.
fn curvature_where(
    g: &Grid,
    border: &[bool],
    keep: impl Fn(usize, usize) -> bool,
) -> BorderCurvature {
    assert_eq!(border.len(), g.heights.len());
    let s2 = g.spacing_m * g.spacing_m;
    let mut out = BorderCurvature::default();
    for j in 1..g.h.saturating_sub(1) {
        for i in 1..g.w.saturating_sub(1) {
            if !keep(i, j) {
                continue;
            }
            let lap = (g.at(i + 1, j) + g.at(i - 1, j) + g.at(i, j + 1) + g.at(i, j - 1)
                - 4.0 * g.at(i, j))
                / s2;
            if border[j * g.w + i] {
                out.border_sum += lap.abs();
                out.border_cells += 1;
            } else {
                out.other_sum += lap.abs();
                out.other_cells += 1;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests;
