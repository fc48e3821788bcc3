//! Sine and cosine of an angle in turns, from multiplies and adds only.
//!
//! The platform's `sinf`/`cosf` differ in their last bits between C libraries, and the erosion
//! filter evaluates twenty of them per sample, so strata uses its own: reduce to the nearest
//! quarter turn, evaluate Taylor polynomials on `[−π/4, π/4]` (absolute error below 4·10⁻⁶), and
//! rotate by the quarter. Every operation is a correctly rounded `f32` add, multiply or `floor`,
//! in the same order as `shaders/earth.wgsl`, so every CPU computes the same bits.

use std::f32::consts::TAU;

/// `(sin 2πx, cos 2πx)` for `x` in turns, `|x|` below 2²².
#[inline(always)]
pub fn sincos_turns(x: f32) -> (f32, f32) {
    let q = (x * 4.0 + 0.5).floor();
    let t = (x - q * 0.25) * TAU;
    let t2 = t * t;
    let s = t * (1.0 - t2 * (1.0 / 6.0 - t2 * (1.0 / 120.0 - t2 * (1.0 / 5040.0))));
    let c = 1.0 - t2 * (0.5 - t2 * (1.0 / 24.0 - t2 * (1.0 / 720.0)));
    // `q mod 4` as an integer in 0..4 (two's complement keeps negative quarters right).
    let quarter = (q as i32) & 3;
    let (s1, c1) = if quarter & 1 == 1 { (c, -s) } else { (s, c) };
    if quarter & 2 == 2 {
        (-s1, -c1)
    } else {
        (s1, c1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sincos_matches_the_library_within_four_millionths() {
        for i in -20_000..20_000 {
            let x = i as f32 * 0.000_731;
            let (s, c) = sincos_turns(x);
            let a = x as f64 * std::f64::consts::TAU;
            assert!((s as f64 - a.sin()).abs() < 4e-6, "sin at {x}: {s}");
            assert!((c as f64 - a.cos()).abs() < 4e-6, "cos at {x}: {c}");
        }
    }
}
