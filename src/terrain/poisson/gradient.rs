//! Gradient extraction and the gradient-map image encoding of the paper (§3).
//!
//! The solver takes slopes on edges ([`super::problem`]): [`extract_edges`] is their exact
//! counterpart (forward differences), so reconstructing an unedited field gives back its heights.
//! The paper's own extraction, `g_ij = (h_{i+1,j} − h_{i−1,j}, h_{i,j+1} − h_{i,j−1}) / 2δ`
//! per sample, is [`extract_samples`]; [`edges_from_samples`] averages per-sample gradients onto
//! the edges (for fields that come as per-sample images), and [`encode_map`] / [`decode_map`] are
//! the two-channel encoding `(r, g) = 2^{p−1} (1 + g/m)`.

use super::grid::GridSpec;

/// Forward-difference slopes of `heights` (`nx · nz`, metres) on the edges: `gx` (`(nx − 1) ·
/// nz`) and `gz` (`nx · (nz − 1)`), computed in `f64` and rounded to `f32`.
///
/// # Panics
/// If a slice length does not match the grid (a programming error of the caller).
pub fn extract_edges(grid: GridSpec, heights: &[f32], gx: &mut [f32], gz: &mut [f32]) {
    let (nx, nz, d) = (grid.nx, grid.nz, grid.spacing_m);
    assert_eq!(heights.len(), grid.len(), "heights length");
    assert_eq!(gx.len(), grid.x_edges(), "gx length");
    assert_eq!(gz.len(), grid.z_edges(), "gz length");
    for j in 0..nz {
        for i in 0..nx - 1 {
            let n = j * nx + i;
            gx[j * (nx - 1) + i] = ((f64::from(heights[n + 1]) - f64::from(heights[n])) / d) as f32;
        }
    }
    for j in 0..nz - 1 {
        for i in 0..nx {
            let n = j * nx + i;
            gz[n] = ((f64::from(heights[n + nx]) - f64::from(heights[n])) / d) as f32;
        }
    }
}

/// The paper's per-sample gradient (central differences, one-sided on the border), `nx · nz`
/// each.
///
/// # Panics
/// If a slice length does not match the grid.
pub fn extract_samples(grid: GridSpec, heights: &[f32], sx: &mut [f32], sz: &mut [f32]) {
    let (nx, nz, d) = (grid.nx, grid.nz, grid.spacing_m);
    assert_eq!(heights.len(), grid.len(), "heights length");
    assert_eq!(sx.len(), grid.len(), "sx length");
    assert_eq!(sz.len(), grid.len(), "sz length");
    let h = |i: usize, j: usize| f64::from(heights[j * nx + i]);
    for j in 0..nz {
        for i in 0..nx {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(nx - 1));
            let (c, e) = (j.saturating_sub(1), (j + 1).min(nz - 1));
            sx[j * nx + i] = ((h(b, j) - h(a, j)) / ((b - a) as f64 * d)) as f32;
            sz[j * nx + i] = ((h(i, e) - h(i, c)) / ((e - c) as f64 * d)) as f32;
        }
    }
}

/// Edge slopes from per-sample gradients: the mean of the two samples of each edge.
///
/// # Panics
/// If a slice length does not match the grid.
pub fn edges_from_samples(grid: GridSpec, sx: &[f32], sz: &[f32], gx: &mut [f32], gz: &mut [f32]) {
    let (nx, nz) = (grid.nx, grid.nz);
    assert_eq!(sx.len(), grid.len(), "sx length");
    assert_eq!(sz.len(), grid.len(), "sz length");
    assert_eq!(gx.len(), grid.x_edges(), "gx length");
    assert_eq!(gz.len(), grid.z_edges(), "gz length");
    for j in 0..nz {
        for i in 0..nx - 1 {
            let n = j * nx + i;
            gx[j * (nx - 1) + i] = ((f64::from(sx[n]) + f64::from(sx[n + 1])) * 0.5) as f32;
        }
    }
    for j in 0..nz - 1 {
        for i in 0..nx {
            let n = j * nx + i;
            gz[n] = ((f64::from(sz[n]) + f64::from(sz[n + nx])) * 0.5) as f32;
        }
    }
}

/// Two-channel encoding of per-sample gradients with `bits` bits per channel (1..=16):
/// `(r, g) = 2^{p−1} (1 + (sx, sz) / m)`, rounded and clamped to `0..2^p − 1`, where `m` is the
/// largest absolute component (returned; 1 for a flat field).
pub fn encode_map(sx: &[f32], sz: &[f32], bits: u32) -> (Vec<u16>, Vec<u16>, f32) {
    let bits = bits.clamp(1, 16);
    let m = sx.iter().chain(sz).fold(0.0f32, |a, v| a.max(v.abs()));
    let m = if m > 0.0 { m } else { 1.0 };
    let half = f64::from(1u32 << (bits - 1));
    let top = f64::from((1u32 << bits) - 1);
    let enc = |v: f32| {
        (half * (1.0 + f64::from(v) / f64::from(m)))
            .round()
            .clamp(0.0, top) as u16
    };
    (
        sx.iter().map(|v| enc(*v)).collect(),
        sz.iter().map(|v| enc(*v)).collect(),
        m,
    )
}

/// Inverse of [`encode_map`]: `g = m (c / 2^{p−1} − 1)`.
pub fn decode_map(r: &[u16], g: &[u16], m: f32, bits: u32) -> (Vec<f32>, Vec<f32>) {
    let half = f64::from(1u32 << (bits.clamp(1, 16) - 1));
    let dec = |c: u16| (f64::from(m) * (f64::from(c) / half - 1.0)) as f32;
    (
        r.iter().map(|c| dec(*c)).collect(),
        g.iter().map(|c| dec(*c)).collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_extraction_and_encoding_round_trip() {
        let g = GridSpec::new(5, 3, 2.0).expect("grid");
        let h: Vec<f32> = (0..15).map(|n| (n * n) as f32).collect();
        let (mut gx, mut gz) = (vec![0.0; g.x_edges()], vec![0.0; g.z_edges()]);
        extract_edges(g, &h, &mut gx, &mut gz);
        assert_eq!(gx[0], 0.5); // (1 − 0) / 2
        assert_eq!(gz[1], (36.0 - 1.0) / 2.0);
        let (mut sx, mut sz) = (vec![0.0; 15], vec![0.0; 15]);
        extract_samples(g, &h, &mut sx, &mut sz);
        assert_eq!(sx[6], (49.0 - 25.0) / 4.0);
        let (r, gg, m) = encode_map(&sx, &sz, 16);
        let (dx, dz) = decode_map(&r, &gg, m, 16);
        for (a, b) in sx.iter().chain(&sz).zip(dx.iter().chain(&dz)) {
            assert!((a - b).abs() <= m / 32768.0, "{a} vs {b}");
        }
    }
}
