//! Hashed value noise for the Ptex bake: lattice values from [`crate::terrain::hash`], quintic
//! interpolation, octaves at power-of-two frequencies.
//!
//! # Exact lattice coordinates
//!
//! A face carries an integer anchor `A` (in units of [`ANCHOR_M`] = 256 m) and its sample
//! positions `p` relative to `A·256 m`, as `f32`. An octave of frequency `f = 2^k` cycles per
//! metre (`−8 ≤ k ≤ 8`) reads the lattice at `A·256·f + p·f`: the first term is an integer
//! (computed with wrapping `i32` arithmetic), the second a product by a power of two, exact in
//! `f32`. So the lattice cell and the fraction inside it are the same bits on every device, and
//! the WGSL twin (`shaders/ptex.wgsl`) differs from this reference only in the rounding of the
//! interpolation arithmetic.
//!
//! [`fbm3_lanes`] and [`fbm2_lanes`] take [`LANES`] points side by side (the bake's texels of a
//! row): each lane's bits are those of [`fbm3`] and [`fbm2`] at its point.

use crate::terrain::hash::{mix32, PRIME_X, PRIME_Z};

/// The unit of face anchors, metres (a power of two, so anchors times any octave frequency of
/// at least `1/256` cycles per metre are integers).
pub const ANCHOR_M: f64 = 256.0;
/// Odd multiplier that spreads the y lattice coordinate.
pub const PRIME_Y: u32 = 0x9e37_79b1;
/// Lowest octave exponent `k` (frequency `2^k` cycles per metre).
pub const MIN_FREQ_LOG2: i32 = -8;
/// Highest octave exponent.
pub const MAX_FREQ_LOG2: i32 = 8;

/// `2^k` as `f32` for `|k| ≤ 126`, built from its bits.
pub fn exp2i(k: i32) -> f32 {
    f32::from_bits(((k + 127) as u32) << 23)
}

/// Hash of a 3D lattice point.
#[inline(always)]
pub fn hash3(x: i32, y: i32, z: i32, seed: u32) -> u32 {
    mix32(
        (x as u32).wrapping_mul(PRIME_X)
            ^ (y as u32).wrapping_mul(PRIME_Y)
            ^ (z as u32).wrapping_mul(PRIME_Z)
            ^ seed,
    )
}

/// The lattice value of a hash, in `[−1, 1)`.
#[inline(always)]
fn value(h: u32) -> f32 {
    (h >> 8) as f32 * (1.0 / 8_388_608.0) - 1.0
}

/// Quintic fade `t³(6t² − 15t + 10)`.
#[inline(always)]
pub fn fade(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

#[inline(always)]
fn lerp(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

/// The integer lattice offset `A·256·2^k` of anchor component `a` (wrapping).
#[inline(always)]
pub fn anchor_lattice(a: i32, k: i32) -> i32 {
    // 256·2^k = 2^(8 + k) with 8 + k ≥ 0 for k ≥ MIN_FREQ_LOG2.
    a.wrapping_mul(1i32.wrapping_shl((8 + k) as u32))
}

/// Splits `x` into its lattice cell (plus `base`) and the fraction inside it.
#[inline(always)]
fn cell(base: i32, x: f32) -> (i32, f32) {
    let fl = x.floor();
    (base.wrapping_add(fl as i32), x - fl)
}

/// Most octaves of one sum: one per exponent `MIN_FREQ_LOG2..=MAX_FREQ_LOG2`.
pub const MAX_OCTAVES: usize = (MAX_FREQ_LOG2 - MIN_FREQ_LOG2 + 1) as usize;

/// The lattice values at the corners of the cell one octave of a 3D sum read last, with the
/// cell and seed they belong to. Neighbouring texels (and a texel's displaced points) mostly
/// read the same cell of an octave coarser than a texel, and take the corners from here instead
/// of hashing them again; the values are the hashes' own, so a sum through a cache has the same
/// bits as one without.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cell3 {
    key: Option<([i32; 3], u32)>,
    v: [f32; 8],
}

impl Cell3 {
    /// A cache holding no cell.
    pub const EMPTY: Self = Self {
        key: None,
        v: [0.0; 8],
    };
}

/// [`Cell3`] for a 2D sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cell2 {
    key: Option<([i32; 2], u32)>,
    v: [f32; 4],
}

impl Cell2 {
    /// A cache holding no cell.
    pub const EMPTY: Self = Self {
        key: None,
        v: [0.0; 4],
    };
}

/// The lattice values at the corners of cell `(ix, iy, iz)`, `x` fastest.
#[inline(always)]
fn corners3(ix: i32, iy: i32, iz: i32, seed: u32) -> [f32; 8] {
    let c = |dx: i32, dy: i32, dz: i32| {
        value(hash3(
            ix.wrapping_add(dx),
            iy.wrapping_add(dy),
            iz.wrapping_add(dz),
            seed,
        ))
    };
    [
        c(0, 0, 0),
        c(1, 0, 0),
        c(0, 1, 0),
        c(1, 1, 0),
        c(0, 0, 1),
        c(1, 0, 1),
        c(0, 1, 1),
        c(1, 1, 1),
    ]
}

/// The lattice values at the corners of 2D cell `(ix, iy)` (the 3D lattice at `z = 0`).
#[inline(always)]
fn corners2(ix: i32, iy: i32, seed: u32) -> [f32; 4] {
    let c = |dx: i32, dy: i32| value(hash3(ix.wrapping_add(dx), iy.wrapping_add(dy), 0, seed));
    [c(0, 0), c(1, 0), c(0, 1), c(1, 1)]
}

/// 3D value noise at `base + x` (lattice units), in `[−1, 1]`.
pub fn value3(base: [i32; 3], x: [f32; 3], seed: u32) -> f32 {
    let mut cache = Cell3::EMPTY;
    value3_in(&mut cache, base, x, seed)
}

/// [`value3`] reading the corners from `cache` when it holds the cell (and leaving the cell's
/// corners there).
#[inline(always)]
pub fn value3_in(cache: &mut Cell3, base: [i32; 3], x: [f32; 3], seed: u32) -> f32 {
    let (ix, fx) = cell(base[0], x[0]);
    let (iy, fy) = cell(base[1], x[1]);
    let (iz, fz) = cell(base[2], x[2]);
    let (u, v, w) = (fade(fx), fade(fy), fade(fz));
    let key = Some(([ix, iy, iz], seed));
    if cache.key != key {
        cache.v = corners3(ix, iy, iz, seed);
        cache.key = key;
    }
    let c = &cache.v;
    let x00 = lerp(c[0], c[1], u);
    let x10 = lerp(c[2], c[3], u);
    let x01 = lerp(c[4], c[5], u);
    let x11 = lerp(c[6], c[7], u);
    lerp(lerp(x00, x10, v), lerp(x01, x11, v), w)
}

/// 2D value noise at `base + x` (lattice units), in `[−1, 1]` (the 3D lattice at `z = 0`).
pub fn value2(base: [i32; 2], x: [f32; 2], seed: u32) -> f32 {
    let mut cache = Cell2::EMPTY;
    value2_in(&mut cache, base, x, seed)
}

/// [`value2`] through a [`Cell2`] cache.
#[inline(always)]
pub fn value2_in(cache: &mut Cell2, base: [i32; 2], x: [f32; 2], seed: u32) -> f32 {
    let (ix, fx) = cell(base[0], x[0]);
    let (iy, fy) = cell(base[1], x[1]);
    let (u, v) = (fade(fx), fade(fy));
    let key = Some(([ix, iy], seed));
    if cache.key != key {
        cache.v = corners2(ix, iy, seed);
        cache.key = key;
    }
    let c = &cache.v;
    lerp(lerp(c[0], c[1], u), lerp(c[2], c[3], u), v)
}

/// The octaves `k0, k0 + 1, …` of a sum, at most `octaves` of them and none above `kmax`.
pub fn octave_count(k0: i32, octaves: u32, kmax: i32) -> u32 {
    let room = (kmax.min(MAX_FREQ_LOG2) - k0 + 1).max(0) as u32;
    octaves.min(room)
}

/// Fractal sum of 3D value noise at `anchor·256 m + p`: octave `o` has frequency `2^(k0 + o)`
/// and amplitude `2^−o`, for `o < count`. Range `±(2 − 2^(1 − count))`.
pub fn fbm3(anchor: [i32; 3], p: [f32; 3], k0: i32, count: u32, seed: u32) -> f32 {
    fbm3_in(&mut [], anchor, p, k0, count, seed)
}

/// [`fbm3`] with octave `o` through `cells[o]` (octaves past the slice's end without a cache).
#[inline(always)]
pub fn fbm3_in(
    cells: &mut [Cell3],
    anchor: [i32; 3],
    p: [f32; 3],
    k0: i32,
    count: u32,
    seed: u32,
) -> f32 {
    let mut sum = 0.0f32;
    for o in 0..count {
        let k = k0 + o as i32;
        let f = exp2i(k);
        let base = anchor.map(|a| anchor_lattice(a, k));
        let x = p.map(|c| c * f);
        let mut spare = Cell3::EMPTY;
        let cache = cells.get_mut(o as usize).unwrap_or(&mut spare);
        sum += exp2i(-(o as i32)) * value3_in(cache, base, x, seed.wrapping_add(o));
    }
    sum
}

/// Fractal sum of 2D value noise at `anchor·256 m + p` (the 2D analogue of [`fbm3`]).
pub fn fbm2(anchor: [i32; 2], p: [f32; 2], k0: i32, count: u32, seed: u32) -> f32 {
    fbm2_in(&mut [], anchor, p, k0, count, seed)
}

/// [`fbm2`] with octave `o` through `cells[o]` (octaves past the slice's end without a cache).
#[inline(always)]
pub fn fbm2_in(
    cells: &mut [Cell2],
    anchor: [i32; 2],
    p: [f32; 2],
    k0: i32,
    count: u32,
    seed: u32,
) -> f32 {
    let mut sum = 0.0f32;
    for o in 0..count {
        let k = k0 + o as i32;
        let f = exp2i(k);
        let base = anchor.map(|a| anchor_lattice(a, k));
        let x = p.map(|c| c * f);
        let mut spare = Cell2::EMPTY;
        let cache = cells.get_mut(o as usize).unwrap_or(&mut spare);
        sum += exp2i(-(o as i32)) * value2_in(cache, base, x, seed.wrapping_add(o));
    }
    sum
}

/// Points evaluated side by side by the lane sums ([`fbm3_lanes`], [`fbm2_lanes`]).
pub const LANES: usize = 8;
/// One `f32` per lane.
pub type Lanes = [f32; LANES];

/// [`cell`] in every lane.
#[inline(always)]
fn cell_lanes(base: i32, x: &Lanes) -> ([i32; LANES], Lanes) {
    let mut fl = [0.0f32; LANES];
    let mut f = [0.0f32; LANES];
    let mut within = true;
    for l in 0..LANES {
        fl[l] = x[l].floor();
        f[l] = x[l] - fl[l];
        within &= (-2_147_483_648.0..2_147_483_648.0).contains(&fl[l]);
    }
    let mut i = [0i32; LANES];
    if within {
        for l in 0..LANES {
            // SAFETY: `fl[l]` is an integer in the range of `i32` (checked above; NaN is not),
            // so the conversion is exact and equals `fl[l] as i32`.
            i[l] = base.wrapping_add(unsafe { fl[l].to_int_unchecked::<i32>() });
        }
    } else {
        for l in 0..LANES {
            i[l] = base.wrapping_add(fl[l] as i32);
        }
    }
    (i, f)
}

/// Whether every lane of each of `cells` holds lane 0's value.
#[inline(always)]
fn uniform<const D: usize>(cells: [&[i32; LANES]; D]) -> bool {
    let mut same = true;
    for c in cells {
        for l in 1..LANES {
            same &= c[l] == c[0];
        }
    }
    same
}

/// The lattice values at the corners of each lane's 3D cell, `[corner][lane]`, the corners of
/// `x` fastest; integer hashes lane by lane, so each is [`corners3`]'s value.
#[inline(always)]
fn corners3_lanes(
    ix: &[i32; LANES],
    iy: &[i32; LANES],
    iz: &[i32; LANES],
    seed: u32,
) -> [Lanes; 8] {
    let mut c = [[0.0f32; LANES]; 8];
    for l in 0..LANES {
        let x = [ix[l] as u32, ix[l].wrapping_add(1) as u32].map(|v| v.wrapping_mul(PRIME_X));
        let y = [iy[l] as u32, iy[l].wrapping_add(1) as u32].map(|v| v.wrapping_mul(PRIME_Y));
        let z = [iz[l] as u32, iz[l].wrapping_add(1) as u32].map(|v| v.wrapping_mul(PRIME_Z));
        for (k, corner) in c.iter_mut().enumerate() {
            corner[l] = value(mix32(x[k & 1] ^ y[(k >> 1) & 1] ^ z[k >> 2] ^ seed));
        }
    }
    c
}

/// [`corners3_lanes`] for 2D cells (the 3D lattice at `z = 0`, so the z term is `0`).
#[inline(always)]
fn corners2_lanes(ix: &[i32; LANES], iy: &[i32; LANES], seed: u32) -> [Lanes; 4] {
    let mut c = [[0.0f32; LANES]; 4];
    for l in 0..LANES {
        let x = [ix[l] as u32, ix[l].wrapping_add(1) as u32].map(|v| v.wrapping_mul(PRIME_X));
        let y = [iy[l] as u32, iy[l].wrapping_add(1) as u32].map(|v| v.wrapping_mul(PRIME_Y));
        for (k, corner) in c.iter_mut().enumerate() {
            corner[l] = value(mix32(x[k & 1] ^ y[k >> 1] ^ seed));
        }
    }
    c
}

/// [`value3_in`] at [`LANES`] points, lane by lane the same operations in the same order (so
/// the same bits): where every lane lies in one cell its corners come from `cache` (or are
/// hashed once and left there), else each lane's corners are hashed side by side.
#[inline(always)]
pub fn value3_lanes(cache: &mut Cell3, base: [i32; 3], x: [&Lanes; 3], seed: u32) -> Lanes {
    let (ix, fx) = cell_lanes(base[0], x[0]);
    let (iy, fy) = cell_lanes(base[1], x[1]);
    let (iz, fz) = cell_lanes(base[2], x[2]);
    let c = if uniform([&ix, &iy, &iz]) {
        let key = Some(([ix[0], iy[0], iz[0]], seed));
        if cache.key != key {
            cache.v = corners3(ix[0], iy[0], iz[0], seed);
            cache.key = key;
        }
        cache.v.map(|v| [v; LANES])
    } else {
        corners3_lanes(&ix, &iy, &iz, seed)
    };
    let mut out = [0.0f32; LANES];
    for l in 0..LANES {
        let (u, v, w) = (fade(fx[l]), fade(fy[l]), fade(fz[l]));
        let x00 = lerp(c[0][l], c[1][l], u);
        let x10 = lerp(c[2][l], c[3][l], u);
        let x01 = lerp(c[4][l], c[5][l], u);
        let x11 = lerp(c[6][l], c[7][l], u);
        out[l] = lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
    }
    out
}

/// [`value2_in`] at [`LANES`] points (as [`value3_lanes`]).
#[inline(always)]
pub fn value2_lanes(cache: &mut Cell2, base: [i32; 2], x: [&Lanes; 2], seed: u32) -> Lanes {
    let (ix, fx) = cell_lanes(base[0], x[0]);
    let (iy, fy) = cell_lanes(base[1], x[1]);
    let c = if uniform([&ix, &iy]) {
        let key = Some(([ix[0], iy[0]], seed));
        if cache.key != key {
            cache.v = corners2(ix[0], iy[0], seed);
            cache.key = key;
        }
        cache.v.map(|v| [v; LANES])
    } else {
        corners2_lanes(&ix, &iy, seed)
    };
    let mut out = [0.0f32; LANES];
    for l in 0..LANES {
        let (u, v) = (fade(fx[l]), fade(fy[l]));
        out[l] = lerp(lerp(c[0][l], c[1][l], u), lerp(c[2][l], c[3][l], u), v);
    }
    out
}

/// [`fbm3_in`] at [`LANES`] points `p` (`[axis][lane]`): each lane's bits are those of
/// [`fbm3`] at its point.
#[inline(always)]
pub fn fbm3_lanes(
    cells: &mut [Cell3],
    anchor: [i32; 3],
    p: &[Lanes; 3],
    k0: i32,
    count: u32,
    seed: u32,
) -> Lanes {
    let mut sum = [0.0f32; LANES];
    for o in 0..count {
        let k = k0 + o as i32;
        let f = exp2i(k);
        let base = anchor.map(|a| anchor_lattice(a, k));
        let x = p.map(|c| c.map(|v| v * f));
        let mut spare = Cell3::EMPTY;
        let cache = cells.get_mut(o as usize).unwrap_or(&mut spare);
        let v = value3_lanes(cache, base, [&x[0], &x[1], &x[2]], seed.wrapping_add(o));
        let amp = exp2i(-(o as i32));
        for l in 0..LANES {
            sum[l] += amp * v[l];
        }
    }
    sum
}

/// [`fbm2_in`] at [`LANES`] points (as [`fbm3_lanes`]).
#[inline(always)]
pub fn fbm2_lanes(
    cells: &mut [Cell2],
    anchor: [i32; 2],
    p: [&Lanes; 2],
    k0: i32,
    count: u32,
    seed: u32,
) -> Lanes {
    let mut sum = [0.0f32; LANES];
    for o in 0..count {
        let k = k0 + o as i32;
        let f = exp2i(k);
        let base = anchor.map(|a| anchor_lattice(a, k));
        let x = p.map(|c| c.map(|v| v * f));
        let mut spare = Cell2::EMPTY;
        let cache = cells.get_mut(o as usize).unwrap_or(&mut spare);
        let v = value2_lanes(cache, base, [&x[0], &x[1]], seed.wrapping_add(o));
        let amp = exp2i(-(o as i32));
        for l in 0..LANES {
            sum[l] += amp * v[l];
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_anchor_shift_reads_the_same_lattice_as_the_local_offset() {
        // The same world point, once as anchor 1 + p and once as anchor 0 + (p + 256 m).
        for k in [-3, 0, 2] {
            let count = 3;
            let p = [3.25f32, 1.5, -7.75];
            let a = fbm3([1, 0, 0], p, k, count, 9);
            let b = fbm3([0, 0, 0], [p[0] + 256.0, p[1], p[2]], k, count, 9);
            assert_eq!(a.to_bits(), b.to_bits(), "k = {k}");
        }
    }

    #[test]
    fn sums_through_a_cache_have_the_bits_of_sums_without() {
        // A walk of small and large steps, so the cells are hit, missed and hit again, under
        // seeds and first octaves that change along it (a cache holding another seed's cell
        // must not answer).
        let mut c3 = [Cell3::EMPTY; MAX_OCTAVES];
        let mut c2 = [Cell2::EMPTY; MAX_OCTAVES];
        let mut x = [0.3f32, -1.7, 5.1];
        for i in 0..4000u32 {
            let step = if i % 97 == 0 { 3.7 } else { 0.013 };
            x = [x[0] + step, x[1] + step * 0.5, x[2] - step * 0.25];
            let (seed, k0, anchor) = (i / 50 % 2 * 11, (i / 75 % 3) as i32 - 2, [1, -2, 3]);
            let a = fbm3(anchor, x, k0, 5, seed);
            let b = fbm3_in(&mut c3, anchor, x, k0, 5, seed);
            assert_eq!(a.to_bits(), b.to_bits(), "fbm3 at {x:?}");
            let a = fbm2([4, -1], [x[0], x[2]], k0, 4, seed);
            let b = fbm2_in(&mut c2, [4, -1], [x[0], x[2]], k0, 4, seed);
            assert_eq!(a.to_bits(), b.to_bits(), "fbm2 at {x:?}");
        }
    }

    #[test]
    fn noise_is_continuous_and_bounded() {
        let mut prev = value3([0; 3], [0.0, 0.3, 0.7], 4);
        for i in 1..2000 {
            let x = i as f32 * 0.001;
            let v = value3([0; 3], [x, 0.3, 0.7], 4);
            assert!(v.abs() <= 1.0);
            assert!((v - prev).abs() < 0.01, "step at {x}");
            prev = v;
        }
        assert_eq!(octave_count(-2, 4, 0), 3);
        assert_eq!(octave_count(2, 4, 0), 0);
        assert_eq!(exp2i(-3), 0.125);
    }

    #[test]
    fn lane_sums_have_the_bits_of_sums_one_point_at_a_time() {
        // Lanes spread over one cell, over a few and over many (so both the shared-cell and the
        // lane-by-lane corners are taken), through caches and without.
        let mut c3 = [Cell3::EMPTY; MAX_OCTAVES];
        let mut c2 = [Cell2::EMPTY; MAX_OCTAVES];
        for i in 0..600u32 {
            let spread = [0.001f32, 0.07, 1.3][i as usize % 3];
            let start = [
                0.3 + i as f32 * 0.11,
                -1.7 + i as f32 * 0.05,
                5.1 - i as f32 * 0.02,
            ];
            let p: [Lanes; 3] = std::array::from_fn(|c| {
                std::array::from_fn(|l| start[c] + spread * (l * (c + 1)) as f32)
            });
            let (seed, k0, anchor) = (i / 50 % 2 * 11, (i / 75 % 4) as i32 - 3, [1, -2, 3]);
            let none: &mut [Cell3] = &mut [];
            for cells in [&mut c3[..], none] {
                let got = fbm3_lanes(cells, anchor, &p, k0, 5, seed);
                for l in 0..LANES {
                    let want = fbm3(anchor, [p[0][l], p[1][l], p[2][l]], k0, 5, seed);
                    assert_eq!(got[l].to_bits(), want.to_bits(), "fbm3 lane {l} of {i}");
                }
            }
            let none: &mut [Cell2] = &mut [];
            for cells in [&mut c2[..], none] {
                let got = fbm2_lanes(cells, [4, -1], [&p[0], &p[2]], k0, 4, seed);
                for l in 0..LANES {
                    let want = fbm2([4, -1], [p[0][l], p[2][l]], k0, 4, seed);
                    assert_eq!(got[l].to_bits(), want.to_bits(), "fbm2 lane {l} of {i}");
                }
            }
        }
    }
}
