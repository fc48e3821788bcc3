//! The auxiliary function `S(x)` of Schneider et al. §2.1: a lattice of N(0,1) values,
//! interpolated between lattice points.
//!
//! The paper stores a random Gaussian lattice in a texture and interpolates it bilinearly. Here the
//! lattice value at integer point `(i, j)` is a pure hash of `(i, j, stream seed)`
//! (`lattice_hash(i·PRIME_X ^ j·PRIME_Z ^ seed)`), made
//! approximately Gaussian as the sum of the hash's four bytes (Irwin–Hall with four terms, mean 510,
//! standard deviation √21845 = 147.8005), so no table and no global RNG exist and the lattice is infinite.
//! Interpolation uses the quintic fade `6t⁵ − 15t⁴ + 10t³`, which makes `S` C² (the paper asks for a
//! C¹ function; bilinear interpolation alone is only C⁰ and shows creases in the normals).
//!
//! Everything is `f32` with no fused multiply-add, in the same operation order as
//! `shaders/common.wgsl`, so the CPU reference is bit-reproducible on every x86-64 and ARM node.

use super::hash::{PRIME_X, PRIME_Z};

/// The lattice's hash finaliser: one multiply between two xor-shifts (half of `mix32`). The noise
/// evaluates four of these per octave per sample, and the multiply is the bottleneck of the
/// vectorised loop; the byte-sum Gaussian mixes the remaining bias out (see the tests).
#[inline(always)]
pub fn lattice_hash(h: u32) -> u32 {
    let h = (h ^ (h >> 16)).wrapping_mul(0x7feb_352d);
    h ^ (h >> 15)
}

/// Mean of the sum of four uniform bytes.
const BYTE_SUM_MEAN: i32 = 510;
/// `1 / sqrt(4 · (256² − 1) / 12)`: scales the byte sum to unit variance.
pub const INV_BYTE_SUM_STD: f32 = 0.006_765_875;

/// Largest magnitude of a lattice value (and so of `S` between lattice points, which interpolates
/// with weights in [0, 1]): the byte sum's extreme 510 from its mean, scaled.
pub const LATTICE_MAX: f32 = 510.0 * INV_BYTE_SUM_STD;

/// Approximately N(0,1) value of a lattice hash.
#[inline(always)]
pub fn gaussian(h: u32) -> f32 {
    let sum = (h & 0xff) + ((h >> 8) & 0xff) + ((h >> 16) & 0xff) + (h >> 24);
    (sum as i32 - BYTE_SUM_MEAN) as f32 * INV_BYTE_SUM_STD
}

/// Quintic fade curve; C² at the lattice points.
#[inline(always)]
pub fn fade(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// The lattice hashes of the four corners of the cell whose lowest corner is the lattice point
/// `(ix, iz)` (the integer coordinates as two's-complement `u32`), for one stream seed, in the
/// order `[(ix, iz), (ix + 1, iz), (ix, iz + 1), (ix + 1, iz + 1)]`: `lattice_hash(i·PRIME_X ^
/// j·PRIME_Z ^ seed)` with wrapping arithmetic, as `shaders/common.wgsl` computes them.
#[inline(always)]
pub fn corner_hashes(ix: u32, iz: u32, seed: u32) -> [u32; 4] {
    let hx0 = ix.wrapping_mul(PRIME_X);
    let hx1 = hx0.wrapping_add(PRIME_X);
    let hz = iz.wrapping_mul(PRIME_Z);
    let hz0 = hz ^ seed;
    let hz1 = hz.wrapping_add(PRIME_Z) ^ seed;
    [
        lattice_hash(hx0 ^ hz0),
        lattice_hash(hx1 ^ hz0),
        lattice_hash(hx0 ^ hz1),
        lattice_hash(hx1 ^ hz1),
    ]
}

/// The cell of the lattice around the point `(x, z)` (lattice units) for one stream seed: the
/// N(0,1) values at its four corners (in the order of [`corner_hashes`]) and the point's offsets
/// `(tx, tz)` in `[0, 1)` from the cell's lowest corner.
#[inline(always)]
pub fn lattice_cell(x: f32, z: f32, seed: u32) -> ([f32; 4], f32, f32) {
    let fx = x.floor();
    let fz = z.floor();
    let tx = x - fx;
    let tz = z - fz;
    let [h00, h10, h01, h11] = corner_hashes(fx as i32 as u32, fz as i32 as u32, seed);
    let corners = [gaussian(h00), gaussian(h10), gaussian(h01), gaussian(h11)];
    (corners, tx, tz)
}

/// Interpolates a cell's corner values `[v00, v10, v01, v11]` (order of [`corner_hashes`]) with
/// the fade weights `u = fade(tx)` along x and `v = fade(tz)` along z: first along x on both
/// z edges, then along z, in that order of operations (the shader's).
#[inline(always)]
pub fn interpolate([v00, v10, v01, v11]: [f32; 4], u: f32, v: f32) -> f32 {
    let a = v00 + (v10 - v00) * u;
    let b = v01 + (v11 - v01) * u;
    a + (b - a) * v
}

/// The auxiliary function at a point in lattice units, for one stream seed.
#[inline(always)]
pub fn lattice(x: f32, z: f32, seed: u32) -> f32 {
    let (corners, tx, tz) = lattice_cell(x, z, seed);
    interpolate(corners, fade(tx), fade(tz))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_values_are_standard_normal() {
        let n = 20_000;
        let (mut sum, mut sq) = (0.0f64, 0.0f64);
        for i in 0..n {
            let v = lattice((i % 200) as f32, (i / 200) as f32, 99) as f64;
            sum += v;
            sq += v * v;
        }
        let mean = sum / n as f64;
        let var = sq / n as f64 - mean * mean;
        assert!(mean.abs() < 0.03, "mean {mean}");
        assert!((var - 1.0).abs() < 0.05, "variance {var}");
    }

    #[test]
    fn lattice_is_continuous_across_cell_borders() {
        for k in -5..5 {
            let x = k as f32;
            let left = lattice(x - 1e-3, 0.37, 5);
            let right = lattice(x + 1e-3, 0.37, 5);
            assert!(
                (left - right).abs() < 1e-2,
                "jump at {x}: {left} vs {right}"
            );
        }
    }

    #[test]
    fn seeds_give_different_lattices() {
        assert_ne!(lattice(0.5, 0.5, 1), lattice(0.5, 0.5, 2));
    }
}
