//! Integer hashing: the only source of randomness in strata.
//!
//! Every random choice is a pure function of `(seed, purpose, integer lattice coordinates)`. The
//! functions here use only wrapping `u32` multiplies, xors and shifts, so the WGSL twin
//! (`shaders/common.wgsl`) computes the same bits.

/// Odd multiplier that spreads the x lattice coordinate (from the PCG family).
pub const PRIME_X: u32 = 0x8da6_b343;
/// Odd multiplier that spreads the z lattice coordinate.
pub const PRIME_Z: u32 = 0xd816_3841;

/// Chris Wellons' `lowbias32` finaliser: a bijection on `u32` with good avalanche.
#[inline(always)]
pub fn mix32(mut h: u32) -> u32 {
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^= h >> 16;
    h
}

/// Hash of a 2D integer lattice point under a stream seed.
#[inline(always)]
pub fn hash2(x: i32, z: i32, seed: u32) -> u32 {
    mix32((x as u32).wrapping_mul(PRIME_X) ^ (z as u32).wrapping_mul(PRIME_Z) ^ seed)
}

/// Derives the stream seed for one purpose from the world seed.
///
/// `purpose` names what the stream is for (an octave of a biome generator, the Voronoi seeds,
/// scatter); `index` separates streams of the same purpose.
pub fn stream(world_seed: u64, purpose: u32, index: u32) -> u32 {
    let lo = world_seed as u32;
    let hi = (world_seed >> 32) as u32;
    mix32(mix32(mix32(lo ^ 0x9e37_79b9) ^ hi) ^ purpose.wrapping_mul(0x85eb_ca6b) ^ index)
}

/// Maps a hash to `[0, 1)` with 24 bits of resolution (exact in `f32`).
#[inline(always)]
pub fn unit(h: u32) -> f32 {
    (h >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// Maps a hash to `[-1, 1)`.
#[inline(always)]
pub fn signed_unit(h: u32) -> f32 {
    unit(h) * 2.0 - 1.0
}

/// Stream purposes. Each random stream of the world function has its own.
pub mod purpose {
    /// Octave `k` of the height generators (`index = k`, shared by all biomes).
    pub const OCTAVE: u32 = 1;
    /// Voronoi seed positions and cell values of the biome map.
    pub const VORONOI: u32 = 2;
    /// Scatter candidates.
    pub const SCATTER: u32 = 3;
    /// Octaves of the `earth-1` generator (`index` = the octave's number in its plan).
    pub const EARTH: u32 = 4;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hashes_spread_bits_evenly() {
        let mut ones = [0u32; 32];
        let n = 4096;
        for i in 0..n {
            let h = hash2(i % 64 - 32, i / 64 - 32, 7);
            for (b, count) in ones.iter_mut().enumerate() {
                *count += (h >> b) & 1;
            }
        }
        for count in ones {
            let frac = count as f64 / n as f64;
            assert!((frac - 0.5).abs() < 0.05, "bit frequency {frac}");
        }
    }

    #[test]
    fn streams_differ_by_seed_purpose_and_index() {
        let a = stream(1, purpose::OCTAVE, 0);
        assert_ne!(a, stream(2, purpose::OCTAVE, 0));
        assert_ne!(a, stream(1, purpose::VORONOI, 0));
        assert_ne!(a, stream(1, purpose::OCTAVE, 1));
        assert_ne!(
            stream(1 << 32, purpose::OCTAVE, 0),
            stream(0, purpose::OCTAVE, 0)
        );
    }
}
