//! Exact squared Euclidean distance transform of a sample set (Felzenszwalb & Huttenlocher,
//! *Distance Transforms of Sampled Functions*, ToC 2012): three separable passes of the lower
//! envelope of parabolas, O(n). The voxelization's dead zone (§4.2) is `d² ≤ r²` of it.

use super::grid::{par_slabs, threads};

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
    // z pass: columns, parallel over ranges of rows y, each thread writing its own buffer.
    let t = threads().min(ny).max(1);
    let per = ny.div_ceil(t);
    let src = &b;
    let parts: Vec<(usize, Vec<f32>)> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..t)
            .map(|k| {
                s.spawn(move || {
                    let (y0, y1) = (k * per, ((k + 1) * per).min(ny));
                    let mut res = vec![0.0f32; (y1.saturating_sub(y0)) * nx * nz];
                    let (mut f, mut d) = (vec![0.0f32; nz], vec![0.0f32; nz]);
                    let (mut v, mut zz) = (vec![0usize; nz], vec![0.0f32; nz + 1]);
                    for y in y0..y1 {
                        for x in 0..nx {
                            for z in 0..nz {
                                f[z] = src[x + nx * (y + ny * z)];
                            }
                            line(&f, &mut d, &mut v, &mut zz);
                            let o = ((y - y0) * nx + x) * nz;
                            res[o..o + nz].copy_from_slice(&d);
                        }
                    }
                    (y0, res)
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("distance transform thread"))
            .collect()
    });
    for (y0, res) in parts {
        for (r, chunk) in res.chunks(nz).enumerate() {
            let (y, x) = (y0 + r / nx, r % nx);
            for (z, v) in chunk.iter().enumerate() {
                a[x + nx * (y + ny * z)] = *v;
            }
        }
    }
    a
}
