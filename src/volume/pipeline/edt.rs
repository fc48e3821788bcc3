//! Exact squared Euclidean distance transform of a sample set (Felzenszwalb & Huttenlocher,
//! *Distance Transforms of Sampled Functions*, ToC 2012): three separable passes of the lower
//! envelope of parabolas, O(n). The voxelization's dead zone (§4.2) is `d² ≤ r²` of it.

use super::grid::{par_slabs, threads};
use rayon::prelude::*;

const FAR: f32 = 1e20;

/// One line: `d[q] = min_p (q − p)² + f[p]`.
fn line(f: &[f32], d: &mut [f32], v: &mut [usize], z: &mut [f32]) {
    let n = f.len();
    let mut k = 0usize;
    v[0] = 0;
    z[0] = -FAR;
    z[1] = FAR;
    for q in 1..n {
        if f[q] >= FAR {
            continue;
        }
        if f[v[0]] >= FAR {
            v[0] = q;
            continue;
        }
        loop {
            let p = v[k];
            let s =
                ((f[q] + (q * q) as f32) - (f[p] + (p * p) as f32)) / (2.0 * (q as f32 - p as f32));
            // z[0] = −FAR lies below every finite intersection, so k never drops below 0.
            if s <= z[k] && k > 0 {
                k -= 1;
                continue;
            }
            k += 1;
            v[k] = q;
            z[k] = s;
            z[k + 1] = FAR;
            break;
        }
    }
    if f[v[0]] >= FAR {
        d.fill(FAR);
        return;
    }
    k = 0;
    for (q, dq) in d.iter_mut().enumerate() {
        while z[k + 1] < q as f32 {
            k += 1;
        }
        let p = v[k];
        let dx = q as f32 - p as f32;
        *dq = dx * dx + f[p];
    }
}

/// Squared distance (in samples²) from every sample to the nearest sample with `set[i] != 0`;
/// `1e20` everywhere when the set is empty.
pub fn squared_distance(dims: [usize; 3], set: &[u8]) -> Vec<f32> {
    let [nx, ny, nz] = dims;
    let slice = nx * ny;
    let m = nx.max(ny).max(nz);
    let mut a: Vec<f32> = set
        .iter()
        .map(|&s| if s != 0 { 0.0 } else { FAR })
        .collect();
    // x and y passes: lines inside one z-slice, parallel over slabs.
    let mut b = vec![0.0f32; a.len()];
    {
        let src = &a;
        par_slabs(&mut b, slice, |z0, out| {
            let (mut f, mut d) = (vec![0.0f32; m], vec![0.0f32; m]);
            let (mut v, mut zz) = (vec![0usize; m], vec![0.0f32; m + 1]);
            for zl in 0..out.len() / slice {
                let o = (z0 + zl) * slice;
                let so = zl * slice;
                for y in 0..ny {
                    line(
                        &src[o + y * nx..o + y * nx + nx],
                        &mut d[..nx],
                        &mut v,
                        &mut zz,
                    );
                    out[so + y * nx..so + y * nx + nx].copy_from_slice(&d[..nx]);
                }
                for x in 0..nx {
                    for y in 0..ny {
                        f[y] = out[so + y * nx + x];
                    }
                    line(&f[..ny], &mut d[..ny], &mut v, &mut zz);
                    for y in 0..ny {
                        out[so + y * nx + x] = d[y];
                    }
                }
            }
        });
    }
    // z pass: columns into a y-major buffer (`t[(y·nx + x)·nz + z]`, contiguous per y, so the
    // y-rows are distributed over threads without sharing), then transposed back into the
    // z-major layout, distributed over z-slabs.
    let mut t = vec![0.0f32; a.len()];
    {
        let src = &b;
        let band = nx * nz;
        let per = ny.div_ceil(2 * threads()).max(1);
        t.par_chunks_mut(per * band)
            .enumerate()
            .for_each(|(k, out)| {
                let (mut f, mut d) = (vec![0.0f32; nz], vec![0.0f32; nz]);
                let (mut v, mut zz) = (vec![0usize; nz], vec![0.0f32; nz + 1]);
                for (yl, rows) in out.chunks_mut(band).enumerate() {
                    let y = k * per + yl;
                    for (x, col) in rows.chunks_mut(nz).enumerate() {
                        for (z, fz) in f.iter_mut().enumerate() {
                            *fz = src[x + nx * (y + ny * z)];
                        }
                        line(&f, &mut d, &mut v, &mut zz);
                        col.copy_from_slice(&d);
                    }
                }
            });
    }
    let t = &t;
    par_slabs(&mut a, slice, |z0, out| {
        for (zl, sl) in out.chunks_mut(slice).enumerate() {
            let z = z0 + zl;
            for (i, o) in sl.iter_mut().enumerate() {
                *o = t[i * nz + z];
            }
        }
    });
    a
}
