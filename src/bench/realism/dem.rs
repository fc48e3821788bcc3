//! Real DEMs to compare with: the two that matplotlib ships in its sample data.
//!
//! - `jacksboro_fault_dem.npz`: `elevation` (int16, metres, 344 rows × 403 columns, row 0 north)
//!   on a 3 arc-second grid (`dx`, `dy` in degrees) over the Jacksboro fault, Tennessee
//!   (latitude ≈ 36.6° N). Metres per degree come from the WGS84 series at the grid's mean
//!   latitude φ: `111 132.92 − 559.82 cos 2φ + 1.175 cos 4φ` north–south and
//!   `111 412.84 cos φ − 93.5 cos 3φ` east–west, giving ≈ 92.5 m × 74.4 m. Land only (no sea).
//! - `topobathy.npz`: `topo` (float32, metres, 91 × 120, sea floor negative) with `latitude` and
//!   `longitude` vectors (the coast of British Columbia near 49° N; steps of 2′ of longitude and
//!   1.3′ of latitude, ≈ 2.44 km × 2.43 km). Rows are flipped so row 0 is north; sea level 0 m.
//!
//! Each is resampled bilinearly along its finer axis to a square grid at the spacing of its
//! coarser axis (nothing is upsampled), which is its "native" spacing here.
//!
//! Where the files come from, first found wins: `$STRATA_BENCH_REALISM_DEM_DIR` holding the two
//! `.npz`; a matplotlib wheel in `target/bench-data/`; the `sample_data` folder of a matplotlib
//! that `python3` or `target/bench-venv/bin/python` imports; else `pip download --no-deps
//! --only-binary=:all: matplotlib -d target/bench-data` (with `python3 -m pip`, or the bench
//! venv's pip). The wheel is read in place (it is a zip; an `.npz` is a zip of `.npy` files),
//! nothing is unpacked, and nothing is committed.

use super::metrics::{resample_axes, Grid};
use anyhow::{bail, Context};
use std::io::{Cursor, Read};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A real DEM on a square grid.
#[derive(Clone, Debug)]
pub struct Dem {
    /// Short name: `jacksboro`, `topobathy`.
    pub name: &'static str,
    /// What and where it is.
    pub about: String,
    /// Heights on a square grid at the native spacing (see the module docs).
    pub grid: Grid,
    /// Sea level, metres (`-∞` when the DEM has no sea).
    pub sea_level_m: f64,
}

/// The sample files' path inside matplotlib.
const SAMPLE_DIR: &str = "matplotlib/mpl-data/sample_data";

/// Where the `.npz` bytes come from.
#[derive(Debug)]
enum Source {
    Dir(PathBuf),
    Wheel(PathBuf),
}

impl Source {
    fn read(&self, file: &str) -> anyhow::Result<Vec<u8>> {
        match self {
            Source::Dir(d) => {
                let p = d.join(file);
                std::fs::read(&p).with_context(|| format!("reading {}", p.display()))
            }
            Source::Wheel(w) => {
                let bytes = std::fs::read(w).with_context(|| format!("reading {}", w.display()))?;
                let mut zip = zip::ZipArchive::new(Cursor::new(bytes))?;
                let mut entry = zip
                    .by_name(&format!("{SAMPLE_DIR}/{file}"))
                    .with_context(|| format!("{file} in {}", w.display()))?;
                let mut out = Vec::new();
                entry.read_to_end(&mut out)?;
                Ok(out)
            }
        }
    }

    fn describe(&self) -> String {
        match self {
            Source::Dir(d) => d.display().to_string(),
            Source::Wheel(w) => w.display().to_string(),
        }
    }
}

/// Loads both DEMs; `say` reports setup steps (a pip download). The error says why none could
/// be had.
pub fn load(say: &dyn Fn(String)) -> anyhow::Result<(Vec<Dem>, String)> {
    let source = locate(say)?;
    let dems = vec![
        jacksboro(&source.read("jacksboro_fault_dem.npz")?)?,
        topobathy(&source.read("topobathy.npz")?)?,
    ];
    Ok((dems, source.describe()))
}

fn bench_dir(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("target")
        .join(name)
}

fn find_wheel(dir: &Path) -> Option<PathBuf> {
    let mut wheels: Vec<PathBuf> = std::fs::read_dir(dir)
        .ok()?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("matplotlib-") && n.ends_with(".whl"))
        })
        .collect();
    wheels.sort();
    wheels.pop()
}

fn python_sample_dir(python: &Path) -> Option<PathBuf> {
    let out = Command::new(python)
        .args([
            "-c",
            "import matplotlib, os; print(os.path.join(os.path.dirname(matplotlib.__file__), 'mpl-data', 'sample_data'))",
        ])
        .output()
        .ok()?;
    let dir = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    (out.status.success() && dir.join("topobathy.npz").exists()).then_some(dir)
}

fn locate(say: &dyn Fn(String)) -> anyhow::Result<Source> {
    if let Some(d) = std::env::var_os("STRATA_BENCH_REALISM_DEM_DIR") {
        return Ok(Source::Dir(PathBuf::from(d)));
    }
    let data = bench_dir("bench-data");
    if let Some(w) = find_wheel(&data) {
        return Ok(Source::Wheel(w));
    }
    let venv_python = bench_dir("bench-venv").join("bin/python");
    for python in [PathBuf::from("python3"), venv_python.clone()] {
        if let Some(d) = python_sample_dir(&python) {
            return Ok(Source::Dir(d));
        }
    }
    std::fs::create_dir_all(&data)?;
    say(format!(
        "downloading matplotlib's wheel for its sample DEMs: pip download --no-deps matplotlib -d {}",
        data.display()
    ));
    let pip_args = [
        "download",
        "--no-deps",
        "--only-binary=:all:",
        "-q",
        "matplotlib",
        "-d",
    ];
    let mut errors = Vec::new();
    let attempts: [(PathBuf, &[&str]); 2] = [
        (PathBuf::from("python3"), &["-m", "pip"]),
        (bench_dir("bench-venv").join("bin/pip"), &[]),
    ];
    for (program, pre) in attempts {
        match Command::new(&program)
            .args(pre)
            .args(pip_args)
            .arg(&data)
            .output()
        {
            Ok(o) if o.status.success() => {
                if let Some(w) = find_wheel(&data) {
                    return Ok(Source::Wheel(w));
                }
                errors.push(format!("{}: no wheel appeared", program.display()));
            }
            Ok(o) => errors.push(format!(
                "{} exited with {}: {}",
                program.display(),
                o.status,
                String::from_utf8_lossy(&o.stderr).trim()
            )),
            Err(e) => errors.push(format!("{}: {e}", program.display())),
        }
    }
    bail!("no matplotlib sample data: {}", errors.join("; "))
}

/// One array of an `.npy` file, as `f64`.
#[derive(Clone, Debug, PartialEq)]
pub struct Npy {
    /// Shape (C order).
    pub shape: Vec<usize>,
    /// Values, row-major.
    pub data: Vec<f64>,
}

/// Parses an `.npy` file (format versions 1–3; little-endian or byte-sized integers and floats,
/// C order).
pub fn parse_npy(bytes: &[u8]) -> anyhow::Result<Npy> {
    if bytes.len() < 10 || &bytes[..6] != b"\x93NUMPY" {
        bail!("not an .npy file");
    }
    let (len, start) = match bytes[6] {
        1 => (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10),
        2 | 3 => {
            let b: [u8; 4] = bytes.get(8..12).context("short header")?.try_into()?;
            (u32::from_le_bytes(b) as usize, 12)
        }
        v => bail!("unsupported .npy version {v}"),
    };
    let header = std::str::from_utf8(bytes.get(start..start + len).context("short header")?)?;
    let field = |key: &str| -> anyhow::Result<&str> {
        let at = header
            .find(&format!("'{key}':"))
            .with_context(|| format!("no {key} in {header:?}"))?;
        Ok(header[at + key.len() + 3..].trim_start())
    };
    if field("fortran_order")?.starts_with("True") {
        bail!("Fortran-order arrays are not supported");
    }
    let descr = field("descr")?;
    let descr = descr
        .strip_prefix('\'')
        .and_then(|d| d.split('\'').next())
        .context("descr")?;
    let shape_text = field("shape")?;
    let shape_text = shape_text
        .strip_prefix('(')
        .and_then(|s| s.split(')').next())
        .context("shape")?;
    let shape: Vec<usize> = shape_text
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse())
        .collect::<Result<_, _>>()?;
    let count: usize = shape.iter().product();
    let body = &bytes[start + len..];
    let (kind, size) = descr.split_at(2);
    let size: usize = size.parse().with_context(|| format!("dtype {descr}"))?;
    if !matches!(&kind[..1], "<" | "|") {
        bail!("unsupported byte order in dtype {descr}");
    }
    if body.len() < count * size {
        bail!("{} bytes of data for {count} × {size}", body.len());
    }
    let word = |k: usize| &body[k * size..(k + 1) * size];
    let data: Vec<f64> = (0..count)
        .map(|k| {
            let b = word(k);
            match (&kind[1..], size) {
                ("f", 4) => Ok(f32::from_le_bytes(b.try_into()?) as f64),
                ("f", 8) => Ok(f64::from_le_bytes(b.try_into()?)),
                ("i", 1) => Ok(b[0] as i8 as f64),
                ("i", 2) => Ok(i16::from_le_bytes(b.try_into()?) as f64),
                ("i", 4) => Ok(i32::from_le_bytes(b.try_into()?) as f64),
                ("i", 8) => Ok(i64::from_le_bytes(b.try_into()?) as f64),
                ("u", 1) => Ok(b[0] as f64),
                ("u", 2) => Ok(u16::from_le_bytes(b.try_into()?) as f64),
                _ => bail!("unsupported dtype {descr}"),
            }
        })
        .collect::<anyhow::Result<_>>()?;
    Ok(Npy { shape, data })
}

/// Reads one array of an `.npz`.
fn npz_array(npz: &[u8], name: &str) -> anyhow::Result<Npy> {
    let mut zip = zip::ZipArchive::new(Cursor::new(npz))?;
    let mut entry = zip
        .by_name(&format!("{name}.npy"))
        .with_context(|| format!("no {name} in the .npz"))?;
    let mut bytes = Vec::new();
    entry.read_to_end(&mut bytes)?;
    parse_npy(&bytes).with_context(|| format!("{name}.npy"))
}

fn scalar(npz: &[u8], name: &str) -> anyhow::Result<f64> {
    npz_array(npz, name)?
        .data
        .first()
        .copied()
        .with_context(|| format!("{name} is empty"))
}

/// Metres per degree of latitude and of longitude at latitude `lat_deg` (WGS84 series).
pub fn metres_per_degree(lat_deg: f64) -> (f64, f64) {
    let p = lat_deg.to_radians();
    (
        111_132.92 - 559.82 * (2.0 * p).cos() + 1.175 * (4.0 * p).cos(),
        111_412.84 * p.cos() - 93.5 * (3.0 * p).cos(),
    )
}

fn square(data: &[f64], w: usize, h: usize, dx_m: f64, dz_m: f64) -> Grid {
    let heights: Vec<f32> = data.iter().map(|v| *v as f32).collect();
    resample_axes(&heights, w, h, dx_m, dz_m, dx_m.max(dz_m))
}

fn jacksboro(npz: &[u8]) -> anyhow::Result<Dem> {
    let e = npz_array(npz, "elevation")?;
    let [h, w] = e.shape[..] else {
        bail!("elevation has shape {:?}", e.shape)
    };
    let (dx, dy) = (scalar(npz, "dx")?, scalar(npz, "dy")?);
    let lat = (scalar(npz, "ymin")? + scalar(npz, "ymax")?) / 2.0;
    let (m_lat, m_lon) = metres_per_degree(lat);
    let (dx_m, dz_m) = (dx * m_lon, dy * m_lat);
    let grid = square(&e.data, w, h, dx_m, dz_m);
    Ok(Dem {
        name: "jacksboro",
        about: format!(
            "matplotlib jacksboro_fault_dem.npz: Jacksboro fault, Tennessee, {w}×{h} at {:.1}″ ({dx_m:.1} m E–W × {dz_m:.1} m N–S at {lat:.2}° N), resampled to {}×{} at {:.1} m",
            dy * 3600.0,
            grid.w,
            grid.h,
            grid.spacing_m
        ),
        grid,
        sea_level_m: f64::NEG_INFINITY,
    })
}

fn topobathy(npz: &[u8]) -> anyhow::Result<Dem> {
    let t = npz_array(npz, "topo")?;
    let [h, w] = t.shape[..] else {
        bail!("topo has shape {:?}", t.shape)
    };
    let lat = npz_array(npz, "latitude")?.data;
    let lon = npz_array(npz, "longitude")?.data;
    if lat.len() != h || lon.len() != w || h < 2 || w < 2 {
        bail!("latitude/longitude do not match topo's shape {:?}", t.shape);
    }
    let dlat = (lat[h - 1] - lat[0]) / (h - 1) as f64;
    let dlon = (lon[w - 1] - lon[0]) / (w - 1) as f64;
    let mid = (lat[0] + lat[h - 1]) / 2.0;
    let (m_lat, m_lon) = metres_per_degree(mid);
    let mut data = t.data;
    if dlat > 0.0 {
        // Row 0 is the south edge: flip so it is the north one.
        data = (0..h)
            .rev()
            .flat_map(|j| data[j * w..(j + 1) * w].to_vec())
            .collect();
    }
    let (dx_m, dz_m) = (dlon.abs() * m_lon, dlat.abs() * m_lat);
    let grid = square(&data, w, h, dx_m, dz_m);
    Ok(Dem {
        name: "topobathy",
        about: format!(
            "matplotlib topobathy.npz: British Columbia coast and shelf, {w}×{h} at {:.1}′ ({:.2} km E–W × {:.2} km N–S at {mid:.1}° N), resampled to {}×{} at {:.2} km, sea level 0 m",
            dlat.abs() * 60.0,
            dx_m / 1e3,
            dz_m / 1e3,
            grid.w,
            grid.h,
            grid.spacing_m / 1e3
        ),
        grid,
        sea_level_m: 0.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_npy_v1_int16() {
        let header = "{'descr': '<i2', 'fortran_order': False, 'shape': (2, 3), }";
        let mut header = header.to_string();
        while !(10 + header.len() + 1).is_multiple_of(64) {
            header.push(' ');
        }
        header.push('\n');
        let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
        bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
        bytes.extend_from_slice(header.as_bytes());
        for v in [1i16, -2, 3, 400, 5, -600] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        let a = parse_npy(&bytes).expect("parses");
        assert_eq!(a.shape, vec![2, 3]);
        assert_eq!(a.data, vec![1.0, -2.0, 3.0, 400.0, 5.0, -600.0]);
        let scalar_header = "{'descr': '<f8', 'fortran_order': False, 'shape': (), }\n";
        let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
        bytes.extend_from_slice(&(scalar_header.len() as u16).to_le_bytes());
        bytes.extend_from_slice(scalar_header.as_bytes());
        bytes.extend_from_slice(&0.25f64.to_le_bytes());
        assert_eq!(parse_npy(&bytes).expect("parses").data, vec![0.25]);
    }

    #[test]
    fn three_arc_seconds_at_jacksboro() {
        let (m_lat, m_lon) = metres_per_degree(36.59);
        assert!((m_lat * 3.0 / 3600.0 - 92.5).abs() < 0.2);
        assert!((m_lon * 3.0 / 3600.0 - 74.5).abs() < 0.3);
    }
}
