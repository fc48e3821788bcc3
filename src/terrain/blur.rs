//! Per-vertex biome weights: a separable Gaussian blur of the one-hot biome map (Choroś & Topolski
//! §5), normalised so the weights sum to one.
//!
//! The map is computed with a margin of `r` samples on every side, so each output sample sees its
//! full kernel; because the lattice is world-anchored and each output is a fixed-order sum over its
//! own window, neighbouring tiles get identical weights on shared vertices.
//!
//! Definition (the WGSL twin `shaders/tile.wgsl` computes the same):
//! - horizontal pass: if all `2r+1` samples of the window hold biome `b`, the result is exactly
//!   one-hot `b`; otherwise `h_c = Σ_t k_t · [id_t = c]`, summed in `t` order;
//! - vertical pass over the horizontal results: if all are one-hot for the same `b`, the result is
//!   one-hot `b`; otherwise `v_c = Σ_t k_t · h_{t,c}` in `t` order;
//! - `w_c = v_c / Σ_c v_c`.
//!
//! The one-hot shortcut is what keeps interior vertices cheap and exactly one-hot.

/// Tag of a horizontal result that is not one-hot.
const DENSE: u8 = u8::MAX;

/// Normalised Gaussian kernel of radius `r` samples and standard deviation `sigma` samples.
pub fn kernel(r: usize, sigma: f32) -> Vec<f32> {
    if r == 0 {
        return vec![1.0];
    }
    let s = sigma as f64;
    let raw: Vec<f64> = (0..=2 * r)
        .map(|t| {
            let d = t as f64 - r as f64;
            libm::exp(-(d * d) / (2.0 * s * s))
        })
        .collect();
    let sum: f64 = raw.iter().sum();
    raw.iter().map(|v| (v / sum) as f32).collect()
}

/// Blur radius and kernel for a LOD's vertex spacing.
pub fn kernel_for(radius_m: f32, spacing_m: f32) -> Vec<f32> {
    let r = (radius_m / spacing_m).round() as usize;
    kernel(r, (radius_m / 3.0 / spacing_m).max(1e-3))
}

/// Blurs `ids` (`w × h`, row-major, values below `k`) into `out` (`(w − 2r) × (h − 2r) × k`,
/// vertex-major: `out[v * k + c]`), where `kern.len() = 2r + 1`.
///
/// Returns `Some(b)` when every output is exactly one-hot `b`, which is the case exactly when the
/// whole grid is biome `b` (the windows of the outputs cover the grid).
pub fn blur_weights(
    ids: &[u8],
    w: usize,
    h: usize,
    kern: &[f32],
    k: usize,
    out: &mut [f32],
) -> Option<u8> {
    let taps = kern.len();
    let r = taps / 2;
    assert!(
        w > 2 * r && h > 2 * r,
        "blur_weights: grid smaller than the kernel"
    );
    let ow = w - 2 * r;
    let oh = h - 2 * r;
    assert_eq!(ids.len(), w * h, "blur_weights: input size");
    assert_eq!(out.len(), ow * oh * k, "blur_weights: output size");
    // Shortcut with the same result: when the whole grid is one biome every window is uniform.
    // (An or-reduction without early exit: it vectorises, `all` does not.)
    if ids.iter().fold(0u8, |acc, b| acc | (b ^ ids[0])) == 0 {
        out.fill(0.0);
        for cell in out.chunks_exact_mut(k) {
            cell[ids[0] as usize] = 1.0;
        }
        return Some(ids[0]);
    }

    // Horizontal pass over every row: tags and dense values.
    let mut tags = vec![0u8; h * ow];
    let mut dense = vec![0.0f32; h * ow * k];
    let mut run = vec![0usize; w];
    // One-hot rows, channel-major, for the rows that are not a single biome.
    let mut onehot = vec![0.0f32; k * w];
    let mut conv = vec![0.0f32; k * ow];
    for row in 0..h {
        let line = &ids[row * w..(row + 1) * w];
        run[w - 1] = 1;
        for i in (0..w - 1).rev() {
            run[i] = if line[i] == line[i + 1] {
                run[i + 1] + 1
            } else {
                1
            };
        }
        if run[0] == w {
            tags[row * ow..(row + 1) * ow].fill(line[0]);
            continue;
        }
        // Σ_t k_t · [id = c] as a convolution of each channel's 0/1 row: adding `k_t · 0 = +0`
        // leaves a sum unchanged, so this equals summing the matching taps in `t` order.
        onehot.fill(0.0);
        let mut present = [false; 256];
        for (i, b) in line.iter().enumerate() {
            onehot[*b as usize * w + i] = 1.0;
            present[*b as usize] = true;
        }
        conv.fill(0.0);
        // A channel absent from the row would only add `k_t · 0 = +0` to `+0`: skip it.
        for c in (0..k).filter(|c| present[*c]) {
            let src = &onehot[c * w..(c + 1) * w];
            let dst = &mut conv[c * ow..(c + 1) * ow];
            for (t, kt) in kern.iter().enumerate() {
                for (d, s) in dst.iter_mut().zip(&src[t..t + ow]) {
                    *d += kt * s;
                }
            }
        }
        for col in 0..ow {
            let o = row * ow + col;
            if run[col] >= taps {
                tags[o] = line[col];
            } else {
                tags[o] = DENSE;
                for c in 0..k {
                    dense[o * k + c] = conv[c * ow + col];
                }
            }
        }
    }

    // Vertical pass: expand the horizontal results to dense rows, sum whole rows per tap (the
    // same per-channel order as a per-vertex loop, but vectorisable), then apply the one-hot rule.
    let row_len = ow * k;
    let mut rows = vec![0.0f32; h * row_len];
    for (o, tag) in tags.iter().enumerate() {
        match *tag {
            DENSE => rows[o * k..(o + 1) * k].copy_from_slice(&dense[o * k..(o + 1) * k]),
            b => rows[o * k + b as usize] = 1.0,
        }
    }
    // Which outputs the one-hot rule covers: a run of 2r+1 equal one-hot tags below them.
    let mut vtag = vec![DENSE; oh * ow];
    let mut down = vec![0usize; h];
    for col in 0..ow {
        let tag = |row: usize| tags[row * ow + col];
        down[h - 1] = 1;
        for row in (0..h - 1).rev() {
            let same = tag(row) != DENSE && tag(row) == tag(row + 1);
            down[row] = if same { down[row + 1] + 1 } else { 1 };
        }
        for (orow, run) in down.iter().enumerate().take(oh) {
            if tag(orow) != DENSE && *run >= taps {
                vtag[orow * ow + col] = tag(orow);
            }
        }
    }
    for orow in 0..oh {
        let flags = &vtag[orow * ow..(orow + 1) * ow];
        let dst = &mut out[orow * row_len..(orow + 1) * row_len];
        dst.fill(0.0);
        // Dense sums only over the span of columns that need them, whole rows per tap.
        if let (Some(c0), Some(c1)) = (
            flags.iter().position(|t| *t == DENSE),
            flags.iter().rposition(|t| *t == DENSE),
        ) {
            let span = c0 * k..(c1 + 1) * k;
            let acc = &mut dst[span.clone()];
            for (t, kt) in kern.iter().enumerate() {
                let src = &rows[(orow + t) * row_len..(orow + t + 1) * row_len][span.clone()];
                for (d, s) in acc.iter_mut().zip(src) {
                    *d += kt * s;
                }
            }
            for cell in acc.chunks_exact_mut(k) {
                let sum: f32 = cell.iter().sum();
                for v in cell.iter_mut() {
                    *v /= sum;
                }
            }
        }
        for (col, t) in flags.iter().enumerate() {
            if *t != DENSE {
                let cell = &mut dst[col * k..(col + 1) * k];
                cell.fill(0.0);
                cell[*t as usize] = 1.0;
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The module's definition, literally, one output at a time.
    fn reference(ids: &[u8], w: usize, h: usize, kern: &[f32], k: usize) -> Vec<f32> {
        let taps = kern.len();
        let r = taps / 2;
        let (ow, oh) = (w - 2 * r, h - 2 * r);
        let horiz = |row: usize, col: usize| -> (Option<u8>, Vec<f32>) {
            let win = &ids[row * w + col..row * w + col + taps];
            if win.iter().all(|b| *b == win[0]) {
                return (Some(win[0]), vec![]);
            }
            let mut acc = vec![0.0f32; k];
            for t in 0..taps {
                acc[win[t] as usize] += kern[t];
            }
            (None, acc)
        };
        let mut out = vec![0.0f32; ow * oh * k];
        for orow in 0..oh {
            for col in 0..ow {
                let hs: Vec<_> = (0..taps).map(|t| horiz(orow + t, col)).collect();
                let dst = &mut out[(orow * ow + col) * k..(orow * ow + col + 1) * k];
                if let Some(b) = hs[0].0 {
                    if hs.iter().all(|x| x.0 == Some(b)) {
                        dst[b as usize] = 1.0;
                        continue;
                    }
                }
                let mut acc = vec![0.0f32; k];
                for (t, (tag, dense)) in hs.iter().enumerate() {
                    for c in 0..k {
                        let hv = match tag {
                            Some(b) => (*b as usize == c) as u8 as f32,
                            None => dense[c],
                        };
                        acc[c] += kern[t] * hv;
                    }
                }
                let sum: f32 = acc.iter().sum();
                for c in 0..k {
                    dst[c] = acc[c] / sum;
                }
            }
        }
        out
    }

    #[test]
    fn optimised_blur_equals_the_definition_bit_for_bit() {
        let (w, h, r, k) = (41usize, 37usize, 5usize, 4usize);
        let kern = kernel(r, r as f32 / 3.0);
        for seed in 0..6u32 {
            // Blobs of biomes with a few isolated samples.
            let ids: Vec<u8> = (0..w * h)
                .map(|i| {
                    let (x, y) = ((i % w) as u32, (i / w) as u32);
                    let hsh = crate::terrain::hash::hash2(x as i32 / 9, y as i32 / 7, seed);
                    if crate::terrain::hash::hash2(x as i32, y as i32, seed + 99).is_multiple_of(50)
                    {
                        (hsh % 4) as u8 ^ 1
                    } else {
                        (hsh % 4) as u8
                    }
                })
                .collect();
            let mut out = vec![0.0f32; (w - 2 * r) * (h - 2 * r) * k];
            let single = blur_weights(&ids, w, h, &kern, k, &mut out);
            assert_eq!(single, None, "a mixed grid is not one biome");
            let want = reference(&ids, w, h, &kern, k);
            for (a, b) in out.iter().zip(&want) {
                assert_eq!(a.to_bits(), b.to_bits());
            }
        }
        // A grid of one biome: the shortcut's answer is the definition's, and it says so.
        let ids = vec![2u8; w * h];
        let mut out = vec![0.5f32; (w - 2 * r) * (h - 2 * r) * k];
        assert_eq!(blur_weights(&ids, w, h, &kern, k, &mut out), Some(2));
        let want = reference(&ids, w, h, &kern, k);
        for (a, b) in out.iter().zip(&want) {
            assert_eq!(a.to_bits(), b.to_bits());
        }
    }

    #[test]
    fn kernel_is_normalised_and_symmetric() {
        let k = kernel(17, 17.0 / 3.0);
        assert_eq!(k.len(), 35);
        let s: f32 = k.iter().sum();
        assert!((s - 1.0).abs() < 1e-5);
        for t in 0..17 {
            assert_eq!(k[t], k[34 - t]);
        }
    }

    #[test]
    fn weights_sum_to_one_and_blend_across_a_border() {
        let (w, h, r) = (30usize, 20usize, 3usize);
        let ids: Vec<u8> = (0..w * h).map(|i| if i % w < 15 { 0 } else { 2 }).collect();
        let kern = kernel(r, 1.5);
        let (ow, oh) = (w - 2 * r, h - 2 * r);
        let mut out = vec![0.0; ow * oh * 3];
        blur_weights(&ids, w, h, &kern, 3, &mut out);
        for v in 0..ow * oh {
            let s: f32 = out[v * 3..v * 3 + 3].iter().sum();
            assert!((s - 1.0).abs() < 1e-6);
            assert_eq!(out[v * 3 + 1], 0.0);
        }
        // Far from the border: exactly one-hot. At the border: a blend.
        assert_eq!(out[0], 1.0);
        let at = |col: usize| out[(5 * ow + col) * 3 + 2];
        assert_eq!(at(ow - 1), 1.0);
        assert!(at(15 - r) > 0.3 && at(15 - r) < 0.7, "{}", at(15 - r));
        assert!(at(15 - r - 1) < at(15 - r));
    }
}
