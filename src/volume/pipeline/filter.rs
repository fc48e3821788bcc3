//! The Gaussian filter applied to `S` after the surface propagation (Becher §4.5: it "suppresses
//! the noise" of the locally planar propagation).
//!
//! Separable: three 1-D passes (x, y, z) with the normalised kernel `exp(−d²/2σ²)`,
//! `|d| ≤ ⌈2σ⌉`, clamped to the grid at the borders (so a constant field stays constant to the
//! last bit of rounding). σ is in samples. Parallel over z-slabs (x and y passes) or rows (z).

use super::grid::par_slabs;

/// Most kernel radius in samples.
pub const MAX_RADIUS: usize = 16;

/// The normalised kernel for `sigma` samples (a single tap of 1 when `sigma ≤ 0`).
pub fn kernel(sigma: f32) -> Vec<f32> {
    if sigma.is_nan() || sigma <= 0.0 {
        return vec![1.0];
    }
    let r = ((2.0 * sigma).ceil() as usize).clamp(1, MAX_RADIUS) as i64;
    let w: Vec<f32> = (-r..=r)
        .map(|d| (-(d * d) as f32 / (2.0 * sigma * sigma)).exp())
        .collect();
    let sum: f32 = w.iter().sum();
    w.iter().map(|v| v / sum).collect()
}

/// Filters `field` (grid `dims`) in place with the Gaussian of `sigma` samples.
pub fn gaussian(dims: [usize; 3], field: &mut [f32], sigma: f32) {
    if kernel(sigma).len() == 1 {
        return;
    }
    let out = gaussian_of(dims, field, sigma);
    field.copy_from_slice(&out);
}

/// The Gaussian of `sigma` samples of `field` (grid `dims`) as a new field, leaving `field`
/// as it is (the same values as [`gaussian`] without its copies).
pub fn gaussian_of(dims: [usize; 3], field: &[f32], sigma: f32) -> Vec<f32> {
    let k = kernel(sigma);
    if k.len() == 1 {
        return field.to_vec();
    }
    let r = (k.len() / 2) as i64;
    let [nx, ny, _] = dims;
    let slice = nx * ny;
    // Every sample of both buffers is written by the passes below before it is read.
    let mut out = vec![0.0f32; field.len()];
    let mut tmp = vec![0.0f32; field.len()];
    // The pass along axis `a` reads `src` and writes `dst`: x field → out, y out → tmp,
    // z tmp → out.
    for axis in 0..3 {
        let (src, dst): (&[f32], &mut [f32]) = match axis {
            0 => (field, &mut out),
            1 => (&out, &mut tmp),
            _ => (&tmp, &mut out),
        };
        let n_axis = dims[axis] as i64;
        let stride = [1, nx, slice][axis];
        par_slabs(dst, slice, |z0, out| {
            let nzs = out.len() / slice;
            let mut pad: Vec<f32> = Vec::with_capacity(nx + 2 * r as usize);
            for zl in 0..nzs {
                let z = z0 + zl;
                for y in 0..ny {
                    let o = nx * (y + ny * z);
                    let dst = &mut out[zl * slice + y * nx..zl * slice + y * nx + nx];
                    let coord = [0, y as i64, z as i64][axis];
                    if axis == 0 {
                        // The row with its border samples repeated `r` times on each side, so
                        // every tap is a plain (vectorisable) shifted read.
                        let row = &src[o..o + nx];
                        let ru = r as usize;
                        pad.clear();
                        pad.extend(std::iter::repeat_n(row[0], ru));
                        pad.extend_from_slice(row);
                        pad.extend(std::iter::repeat_n(row[nx - 1], ru));
                        dst.fill(0.0);
                        for (t, w) in k.iter().enumerate() {
                            for (d, v) in dst.iter_mut().zip(&pad[t..t + nx]) {
                                *d += w * v;
                            }
                        }
                    } else {
                        dst.fill(0.0);
                        for (t, w) in k.iter().enumerate() {
                            let c = (coord + t as i64 - r).clamp(0, n_axis - 1);
                            let ro = (o as i64 + (c - coord) * stride as i64) as usize;
                            let row = &src[ro..ro + nx];
                            for (d, v) in dst.iter_mut().zip(row) {
                                *d += w * v;
                            }
                        }
                    }
                }
            }
        });
    }
    out
}
