// WGSL twin of the point functions of the world: `terrain::hash`, `terrain::noise`,
// `terrain::fractal` (Schneider et al., "Real-Time Editing, Synthesis, and Rendering of Infinite
// Landscapes on GPUs", Eq. 1 and §2.2) and `terrain::biome` (Choroś & Topolski, extended Voronoi
// biomes, Algorithms 1 and 2).
//
// Every function mirrors its Rust original operation for operation and in the same order. The
// integer arithmetic (wrapping u32 multiplies, xors, shifts) gives identical bits. For the float
// arithmetic WGSL is looser than Rust in two ways, and both are closed here:
//
// - a compiler may contract `a * b + c` into a fused multiply-add, or rewrite `a + (b - a) * t` as
//   a lerp; the CPU code does neither. Every product that feeds an addition goes through `rn`, a
//   rounding barrier (an integer xor with a runtime zero that no compiler can see through), so it
//   is rounded to f32 first, as on the CPU;
// - `/` and `sqrt` need only be accurate to 2.5 ULP. `div_rn` and `sqrt_rn` correct the hardware
//   result to the correctly rounded one (what Rust computes) with exact residuals (Dekker's exact
//   product; `fma` need not be fused in WGSL, and is not on lavapipe). The warp normalisation
//   uses no hardware operation of that kind: it mirrors the CPU's `inv_sqrt`.
//
// On a device with IEEE-754 `+`, `-`, `*` (which WGSL requires) the twin is then bit-exact. That
// matters more than it seems: the §2.2 warp feeds the accumulated height back into the sample
// position, so one ULP of difference can grow from octave to octave into a visible step between a
// GPU tile and its CPU neighbour.
//
// No transcendental function is evaluated here: octave frequencies and amplitudes, warp constants
// and scales come precomputed from `WorldPlan`.
//
// This file is a library with no bindings; `tile.wgsl` is appended to it at load time. Every
// entry point must set `rounding_key` from a runtime zero (a uniform) before calling anything here.

// Always 0 at run time, but unknown to the compiler.
var<private> rounding_key: u32;

// Rounding barrier: returns `x` unchanged, after it has been rounded to f32.
fn rn(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) ^ rounding_key);
}

// Next f32 above a non-negative finite `x`.
fn next_up(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) + 1u);
}

// Next f32 below a positive finite `x`.
fn next_down(x: f32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) - 1u);
}

// Veltkamp split of `a` into two 12-bit halves, hi + lo = a exactly.
fn split(a: f32) -> vec2<f32> {
    let c = rn(4097.0 * a);
    let hi = rn(c - rn(c - a));
    return vec2<f32>(hi, rn(a - hi));
}

// `a - q b` with a single rounding (exact whenever representable, which it is for q within an
// ULP of a / b), by Dekker's exact product: `fma` is not guaranteed to be fused in WGSL (and is
// not on lavapipe), so only correctly rounded `+`, `-`, `*` are used.
fn residual(a: f32, q: f32, b: f32) -> f32 {
    let p = rn(q * b);
    let qs = split(q);
    let bs = split(b);
    let e = rn(rn(rn(rn(rn(qs.x * bs.x) - p) + rn(qs.x * bs.y)) + rn(qs.y * bs.x)) + rn(qs.y * bs.y));
    return rn(a - p) - e;
}

// Correctly rounded |a| / |b| for finite a > 0, b > 0, from an estimate `q0` within a few ULP:
// q is first moved to the f32 at or below a / b, then the next f32 is taken iff a / b lies above
// their midpoint, i.e. iff 2 (a - q b) > d b (both sides exact: d is a power of two; no quotient
// of two f32 is a midpoint).
fn div_from(a: f32, b: f32, q0: f32) -> f32 {
    var q = q0;
    for (var i = 0; i < 4; i++) {
        if (residual(a, q, b) < 0.0) {
            q = next_down(q);
        } else if (residual(a, next_up(q), b) >= 0.0) {
            q = next_up(q);
        } else {
            break;
        }
    }
    let up = next_up(q);
    if (rn(2.0 * residual(a, q, b)) > rn(rn(up - q) * b)) {
        q = up;
    }
    return q;
}

// Correctly rounded `a / b` (finite, b != 0), as Rust computes it; WGSL only promises 2.5 ULP.
fn div_rn(a: f32, b: f32) -> f32 {
    if (a == 0.0) {
        return a / b;
    }
    let q = div_from(abs(a), abs(b), rn(abs(a) / abs(b)));
    return select(q, -q, (a < 0.0) != (b < 0.0));
}

// Correctly rounded sqrt(x) for finite x > 0 from an estimate `s0` within a few ULP, the same
// way: s at or below sqrt(x), then its successor iff x - s² > s d (exact: both sides are multiples
// of d², and the square root of an f32 is never a midpoint).
fn sqrt_from(x: f32, s0: f32) -> f32 {
    var s = s0;
    for (var i = 0; i < 4; i++) {
        if (residual(x, s, s) < 0.0) {
            s = next_down(s);
        } else if (residual(x, next_up(s), next_up(s)) >= 0.0) {
            s = next_up(s);
        } else {
            break;
        }
    }
    let up = next_up(s);
    if (residual(x, s, s) > rn(s * rn(up - s))) {
        s = up;
    }
    return s;
}

// Correctly rounded `sqrt(x)` for finite x > 0, as Rust computes it; WGSL only promises 2.5 ULP.
fn sqrt_rn(x: f32) -> f32 {
    return sqrt_from(x, rn(sqrt(x)));
}

const PRIME_X: u32 = 0x8da6b343u;
const PRIME_Z: u32 = 0xd8163841u;

// `terrain::hash::mix32`: Chris Wellons' lowbias32.
fn mix32(h0: u32) -> u32 {
    var h = h0;
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}

// `terrain::hash::hash2`.
fn hash2(x: i32, z: i32, seed: u32) -> u32 {
    return mix32((bitcast<u32>(x) * PRIME_X) ^ (bitcast<u32>(z) * PRIME_Z) ^ seed);
}

// `terrain::hash::unit`: 24 bits to [0, 1), exact in f32.
fn unit(h: u32) -> f32 {
    return f32(h >> 8u) * (1.0 / 16777216.0);
}

// `terrain::hash::signed_unit`.
fn signed_unit(h: u32) -> f32 {
    return rn(unit(h) * 2.0) - 1.0;
}

const BYTE_SUM_MEAN: i32 = 510;
// `terrain::noise::INV_BYTE_SUM_STD`, written as the exact decimal value of the Rust f32 constant
// so the conversion is exact (checked by a unit test in `src/gpu`).
const INV_BYTE_SUM_STD: f32 = 0.006765875034034252166748046875;

// `terrain::noise::gaussian`: byte sum of a hash, scaled to unit variance.
fn gaussian(h: u32) -> f32 {
    let sum = (h & 0xffu) + ((h >> 8u) & 0xffu) + ((h >> 16u) & 0xffu) + (h >> 24u);
    return rn(f32(i32(sum) - BYTE_SUM_MEAN) * INV_BYTE_SUM_STD);
}

// `terrain::noise::fade`: quintic fade 6t^5 - 15t^4 + 10t^3.
fn fade(t: f32) -> f32 {
    return t * t * t * (rn(t * (rn(t * 6.0) - 15.0)) + 10.0);
}

// `terrain::noise::lattice_hash`: the lattice's finaliser, one multiply between two xor-shifts.
fn lattice_hash(h0: u32) -> u32 {
    let h = (h0 ^ (h0 >> 16u)) * 0x7feb352du;
    return h ^ (h >> 15u);
}

// `terrain::fractal::lattice_index`: a floored coordinate as a lattice index, clamped to ±2^30
// first (inside the supported world the clamp never changes a value).
fn lattice_index(f: f32) -> u32 {
    return bitcast<u32>(i32(min(max(f, -1073741824.0), 1073741824.0)));
}

// `terrain::noise::lattice` / `fractal::lattice_lanes`: the auxiliary function S of
// Schneider et al. §2.1 at a point in lattice units.
fn lattice(x: f32, z: f32, seed: u32) -> f32 {
    let fx = floor(x);
    let fz = floor(z);
    let tx = x - fx;
    let tz = z - fz;
    let hx0 = lattice_index(fx) * PRIME_X;
    let hx1 = hx0 + PRIME_X;
    let hz = lattice_index(fz) * PRIME_Z;
    let hz0 = hz ^ seed;
    let hz1 = (hz + PRIME_Z) ^ seed;
    let v00 = gaussian(lattice_hash(hx0 ^ hz0));
    let v10 = gaussian(lattice_hash(hx1 ^ hz0));
    let v01 = gaussian(lattice_hash(hx0 ^ hz1));
    let v11 = gaussian(lattice_hash(hx1 ^ hz1));
    let u = fade(tx);
    let v = fade(tz);
    let a = v00 + rn((v10 - v00) * u);
    let b = v01 + rn((v11 - v01) * u);
    return a + rn((b - a) * v);
}

// `terrain::fractal::inv_sqrt`: 1 / sqrt(x) for normal positive x from Lomont's integer first
// guess and two Newton steps, in integer ops and rounded multiplies and subtractions only.
fn inv_sqrt(x: f32) -> f32 {
    let half = 0.5 * x;
    var y = bitcast<f32>(0x5f375a86u - (bitcast<u32>(x) >> 1u));
    y = y * (1.5 - rn(rn(half * y) * y));
    return y * (1.5 - rn(rn(half * y) * y));
}

// `terrain::fractal::Octave` (padded to 16 bytes).
struct Octave {
    freq: f32,
    amp: f32,
    seed: u32,
    _pad: u32,
}

const MAX_OCTAVES: u32 = 16u;

// `terrain::fractal::FractalPlan` of one biome at one LOD; `gpu::layout::GpuFractal` on the CPU.
struct Fractal {
    inv_scale: f32,
    base_m: f32,
    amplitude_m: f32,
    octave_count: u32,
    warp: u32,
    rough0: f32,
    lever: f32,
    about_origin: u32,
    c1: vec2<f32>,
    c2: vec2<f32>,
    t: vec2<f32>,
    r0: vec2<f32>,
    t0: vec2<f32>,
    _pad2: vec2<f32>,
    octaves: array<Octave, 16>,
}

// `terrain::fractal::fbm_lanes` for one lane: Eq. 1 with per-octave rotation and translation
// (§2.2), height in metres at a world position in metres.
fn fbm(f: Fractal, x_m: f32, z_m: f32) -> f32 {
    let px = rn(x_m * f.inv_scale);
    let pz = rn(z_m * f.inv_scale);
    var rx = 1.0;
    var rz = 0.0;
    var tx = 0.0;
    var tz = 0.0;
    if (f.warp != 0u) {
        rx = f.r0.x;
        rz = f.r0.y;
        tx = f.t0.x;
        tz = f.t0.y;
    }
    var lever = 0.0;
    var about_origin = false;
    if (f.warp != 0u) {
        lever = f.lever;
        about_origin = f.about_origin != 0u;
    }
    var octaves = f.octaves;
    var acc = 0.0;
    for (var o = 0u; o < min(f.octave_count, MAX_OCTAVES); o++) {
        let oct = octaves[o];
        var qx: f32;
        var qz: f32;
        if (about_origin) {
            // The paper's literal x'_k = [r_k ⊥r_k] · x + t_k.
            qx = rn((rn(rx * px) - rn(rz * pz) + tx) * oct.freq);
            qz = rn((rn(rz * px) + rn(rx * pz) + tz) * oct.freq);
        } else {
            // Rotation about the point at the lever from the sample: x + ([r ⊥r] − I) · L + t.
            qx = rn((px + (rn((rx - 1.0) * lever) + tx)) * oct.freq);
            qz = rn((pz + (rn(rz * lever) + tz)) * oct.freq);
        }
        let s = lattice(qx, qz, oct.seed);
        acc += rn(oct.amp * s);
        if (f.warp != 0u) {
            let rough = f.rough0 * acc;
            let vx = rn(f.c1.x * rough) + f.c2.x + rx;
            let vz = rn(f.c1.y * rough) + f.c2.y + rz;
            let len2 = rn(vx * vx) + rn(vz * vz);
            // `fractal::warp_lanes`: times the reciprocal length, unchanged where the vector has
            // (near) zero length.
            if (len2 > 1e-20) {
                let inv = inv_sqrt(len2);
                rx = rn(vx * inv);
                rz = rn(vz * inv);
            }
            tx = f.t.x;
            tz = f.t.y;
        }
    }
    return f.base_m + rn(f.amplitude_m * acc);
}

// `terrain::biome::BiomeMapPlan` (all 4-byte scalars, 32 bytes).
struct BiomeMap {
    inv_cell: f32,
    speed: f32,
    dispersion: f32,
    latitude: u32,
    count: u32,
    seed_x: u32,
    seed_z: u32,
    seed_value: u32,
}

// `terrain::biome::RANGE`.
const RANGE: i32 = 2;

// `terrain::biome::Nearest`.
struct Nearest {
    cell: vec2<i32>,
    pos: vec2<f32>,
}

// Algorithm 1 (`BiomeMapPlan::nearest`): the nearest Voronoi seed among the cells within RANGE.
// The first strictly smaller distance wins, in the same j-major scan order as the CPU.
fn nearest(m: BiomeMap, x_m: f32, z_m: f32) -> Nearest {
    let x = rn(x_m * m.inv_cell);
    let z = rn(z_m * m.inv_cell);
    let cx = i32(floor(x));
    let cz = i32(floor(z));
    // The CPU starts from +inf; every distance here is below 50, so any larger start is equivalent.
    var best = 3.0e38;
    var win = Nearest(vec2<i32>(0, 0), vec2<f32>(0.0, 0.0));
    for (var j = cz - RANGE; j <= cz + RANGE; j++) {
        for (var i = cx - RANGE; i <= cx + RANGE; i++) {
            let sx = f32(i) + signed_unit(hash2(i, j, m.seed_x));
            let sz = f32(j) + signed_unit(hash2(i, j, m.seed_z));
            let dx = sx - x;
            let dz = sz - z;
            let d = rn(dx * dx) + rn(dz * dz);
            if (d < best) {
                best = d;
                win = Nearest(vec2<i32>(i, j), vec2<f32>(sx, sz));
            }
        }
    }
    return win;
}

// Rust's `a % b` (exact fmod) for finite a >= 0 and b > 0: `a - n b` for the integer n that puts it
// in [0, b), from the exact residual, corrected if the quotient rounded across n.
fn fmod_pos(a: f32, b: f32) -> f32 {
    var r = residual(a, trunc(div_rn(a, b)), b);
    if (r < 0.0) {
        r += b;
    }
    if (r >= b) {
        r -= b;
    }
    return r;
}

// Algorithms 1 and 2 (`BiomeMapPlan::biome_of`): the biome of a winning seed, with the latitude
// triangle wave of Eq. 2 and the dispersion clamp.
fn biome_of(m: BiomeMap, pos: vec2<f32>) -> u32 {
    let fx = floor(pos.x);
    let fz = floor(pos.y);
    var value = unit(hash2(i32(fx), i32(fz), m.seed_value));
    if (m.latitude != 0u) {
        let period = m.speed * 2.0;
        let lat = fmod_pos(abs(fz), period);
        var grad: f32;
        if (lat <= m.speed) {
            grad = div_rn(lat, m.speed);
        } else {
            grad = 2.0 - div_rn(lat, m.speed);
        }
        value = clamp(clamp(value, grad - m.dispersion, grad + m.dispersion), 0.0, 1.0);
    }
    return min(u32(value * f32(m.count)), m.count - 1u);
}

// `BiomeMapPlan::biome_at`.
fn biome_at(m: BiomeMap, x_m: f32, z_m: f32) -> u32 {
    return biome_of(m, nearest(m, x_m, z_m).pos);
}
