//! Hillshade images of a [`Grid`].
//!
//! The standard (Horn 1981) hillshade: slope and aspect from Horn's 3×3 weighted differences,
//! light from azimuth 315° (north-west) at 45° altitude, no vertical exaggeration,
//! `255 · (cos z cos s + sin z sin s cos(a − aspect))` clamped to 0–255, edge cells repeating
//! their neighbours. Land is grey; cells at or below the sea level are tinted blue (their shade
//! times (0.35, 0.55, 0.9) plus a constant (10, 30, 70)). Written as an 8-bit RGB PNG with the
//! `png` crate, one pixel per sample, row 0 north.

use super::metrics::{priority_flood, Grid};
use super::DEPRESSION_DEPTH_M;
use anyhow::Context;
use std::path::Path;

/// Shade `0..=255` of each cell.
pub fn shade(g: &Grid) -> Vec<u8> {
    let (w, h) = (g.w as i64, g.h as i64);
    let at =
        |i: i64, j: i64| g.heights[(j.clamp(0, h - 1) * w + i.clamp(0, w - 1)) as usize] as f64;
    let zenith = 45f64.to_radians();
    // Azimuth 315° (compass, clockwise from north) in the mathematical convention.
    let azimuth = (360.0f64 - 315.0 + 90.0).to_radians();
    let mut out = Vec::with_capacity(g.heights.len());
    for j in 0..h {
        for i in 0..w {
            let (a, b, c) = (at(i - 1, j - 1), at(i, j - 1), at(i + 1, j - 1));
            let (d, f) = (at(i - 1, j), at(i + 1, j));
            let (gg, hh, ii) = (at(i - 1, j + 1), at(i, j + 1), at(i + 1, j + 1));
            // dz/dx east, dz/dy south (row order), as in the usual ESRI formulation.
            let dzdx = ((c + 2.0 * f + ii) - (a + 2.0 * d + gg)) / (8.0 * g.spacing_m);
            let dzdy = ((gg + 2.0 * hh + ii) - (a + 2.0 * b + c)) / (8.0 * g.spacing_m);
            let slope = dzdx.hypot(dzdy).atan();
            let aspect = if dzdx != 0.0 {
                let mut asp = dzdy.atan2(-dzdx);
                if asp < 0.0 {
                    asp += std::f64::consts::TAU;
                }
                asp
            } else if dzdy > 0.0 {
                std::f64::consts::FRAC_PI_2
            } else if dzdy < 0.0 {
                std::f64::consts::TAU - std::f64::consts::FRAC_PI_2
            } else {
                0.0
            };
            let v = 255.0
                * (zenith.cos() * slope.cos()
                    + zenith.sin() * slope.sin() * (azimuth - aspect).cos());
            out.push(v.clamp(0.0, 255.0) as u8);
        }
    }
    out
}

/// RGB pixels: grey land, blue-tinted sea, and blue lakes and rivers where `water` (one flag
/// per pixel, when given) says so.
pub fn rgb(g: &Grid, sea_level_m: f64, water: Option<&[bool]>) -> Vec<u8> {
    let shades = shade(g);
    let mut out = Vec::with_capacity(shades.len() * 3);
    for (n, (s, z)) in shades.iter().zip(&g.heights).enumerate() {
        let s = *s as f64;
        if water.is_some_and(|w| w[n]) {
            out.extend([
                (20.0 + 0.2 * s) as u8,
                (70.0 + 0.35 * s) as u8,
                (140.0 + 0.45 * s).min(255.0) as u8,
            ]);
        } else if (*z as f64) <= sea_level_m {
            out.extend([
                (10.0 + 0.35 * s) as u8,
                (30.0 + 0.55 * s) as u8,
                (70.0 + 0.7 * s).min(255.0) as u8,
            ]);
        } else {
            out.extend([s as u8; 3]);
        }
    }
    out
}

/// Writes the hillshade of `g` to `path` (creating its folder), lakes and rivers where `water`
/// says.
pub fn write_png(
    path: &Path,
    g: &Grid,
    sea_level_m: f64,
    water: Option<&[bool]>,
) -> anyhow::Result<()> {
    write_rgb(path, g.w, g.h, &rgb(g, sea_level_m, water))
}

/// Writes `w × h` RGB pixels (rows from the north) to `path` as a PNG, creating its folder.
pub fn write_rgb(path: &Path, w: usize, h: usize, pixels: &[u8]) -> anyhow::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, w as u32, h as u32);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::High);
        let mut writer = enc.write_header()?;
        writer.write_image_data(pixels)?;
        writer.finish()?;
    }
    std::fs::write(path, bytes).with_context(|| format!("writing {}", path.display()))
}

/// Tints red the land pixels of `g` that the priority-flood fill raises by more than
/// [`DEPRESSION_DEPTH_M`] (the cells the closed-depression figure counts): each channel
/// halved, red then raised by 128.
pub fn tint_depressions(g: &Grid, sea_level_m: f64, pixels: &mut [u8]) {
    let filled = priority_flood(g, sea_level_m);
    for (n, (z, f)) in g.heights.iter().zip(&filled).enumerate() {
        if (*z as f64) > sea_level_m && (*f as f64 - *z as f64) > DEPRESSION_DEPTH_M {
            let p = &mut pixels[3 * n..3 * n + 3];
            p[0] = p[0] / 2 + 128;
            p[1] /= 2;
            p[2] /= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_is_cos_45_and_slopes_facing_the_light_are_brighter() {
        let flat = Grid::from_fn(8, 8, 10.0, |_, _| 5.0);
        assert!(shade(&flat).iter().all(|s| *s == 180));
        // Rising to the south-east (x east, z south) faces the north-west light; falling to the
        // south-east faces away from it.
        let toward = Grid::from_fn(8, 8, 10.0, |x, z| 0.5 * (x + z));
        let away = Grid::from_fn(8, 8, 10.0, |x, z| -0.5 * (x + z));
        assert!(shade(&away)[27] < 150, "{}", shade(&away)[27]);
        assert!(shade(&toward)[27] > 220, "{}", shade(&toward)[27]);
        let sea = rgb(&flat, 10.0, None);
        assert!(sea[2] > sea[0]);
    }

    #[test]
    fn only_the_closed_bowl_is_tinted() {
        // A bowl 10 m deep in a plane 100 m above the sea, beside a cone: the fill raises the
        // bowl's floor, not the cone's flanks nor the plane.
        let g = Grid::from_fn(32, 16, 10.0, |x, z| {
            let bowl = (x - 80.0).hypot(z - 80.0);
            let cone = (x - 240.0).hypot(z - 80.0);
            100.0 - 10.0 * (1.0 - bowl / 50.0).max(0.0) + 10.0 * (1.0 - cone / 50.0).max(0.0)
        });
        let plain = rgb(&g, 0.0, None);
        let mut tinted = plain.clone();
        tint_depressions(&g, 0.0, &mut tinted);
        let px = |p: &[u8], i: usize, j: usize| p[3 * (j * 32 + i)..3 * (j * 32 + i) + 3].to_vec();
        let floor = px(&tinted, 8, 8);
        assert!(
            floor[0] > floor[1] && floor[0] >= 128,
            "the bowl's floor is red: {floor:?}"
        );
        for (i, j) in [(24, 8), (0, 0), (31, 15)] {
            assert_eq!(px(&tinted, i, j), px(&plain, i, j), "({i}, {j}) untouched");
        }
    }
}
