//! The `earth-1` height function, evaluated for [`LANES`] samples side by side.
//!
//! Every loop runs over fixed-length lane arrays with no branches that depend on a lane, so LLVM
//! vectorises it; the scalar reference is the same code with one lane in use. No fused
//! multiply-add is used (Rust never contracts `a * b + c`), so every build gives the same bits.
//! The WGSL twin `shaders/earth.wgsl` performs the same operations in the same order.
//!
//! The function, for a sample at world position `p` (metres) with climate weights giving the
//! erosion strength `E` and roughness `R`:
//!
//! ```text
//! w     = A_w · (Σ_k n_k(p) over two streams)             bounded warp of the macro fields
//! c     = Σ_k g_c^k · n_k(p + w) + bias + origin(p)        continent value, coast at c = 0
//! m     = Σ_k ½^k · n_k(p + w)                             belt noise; belts where |m| is small
//! belt  = (1 − smoothstep(0, width, √(m² + ε))) · land(c)
//! hills = smoothstep(−0.5, 0.5, Σ_k ½^k · n_k(p))
//! A     = land·(A_m·belt + A_h·hills·(1 − belt) + A_p) + (1 − land)·A_s     relief amplitude
//! h     = e(c) + 0.45·A_m·belt·land + Σ_layers A · a_i · layer_i(p, G)
//! ```
//!
//! `e(c)` places plains, shelf, slope and abyss; `G` is the gradient of the layers summed so far.
//! A *relief* layer is one octave of gradient noise `n` (rotated by its own angle so no lattice
//! direction is preferred), mixed between smooth `n` and ridged `(1 − |n|)²` by the belt mask,
//! damped by `1 / (1 + k_d |G|²)` (steep slopes get less detail, as erosion leaves them). A
//! *gully* layer is the erosion filter: stripes whose crests and troughs run along `G`, i.e.
//! downhill (see [`gullies`]), faded out where the slope is small so peaks and valley floors keep
//! their shape; because each gully octave steers by the gradient that includes the previous
//! ones, gullies branch off the flanks of larger ones.

use super::super::fractal::{gaussian_fast, inv_sqrt, lattice_index};
use super::super::hash::mix32;
use super::super::noise::{corner_hashes, fade};
use super::trig::sincos_turns;
use super::{EarthPlan, Layer, LayerKind, MacroPlan, NoiseOctave};

/// Samples evaluated together.
pub const LANES: usize = 64;

type L = [f32; LANES];

/// Derivative of the quintic fade.
#[inline(always)]
fn dfade(t: f32) -> f32 {
    let u = t * (t - 1.0);
    30.0 * u * u
}

#[inline(always)]
fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Octave coordinates: the world position rotated by the octave's angle, scaled by its
/// frequency and offset.
#[inline(always)]
fn octave_coords(o: &NoiseOctave, xs: &L, zs: &L, qx: &mut L, qz: &mut L) {
    for l in 0..LANES {
        qx[l] = (o.cos * xs[l] - o.sin * zs[l]) * o.freq + o.ox;
        qz[l] = (o.sin * xs[l] + o.cos * zs[l]) * o.freq + o.oz;
    }
}

/// Value noise at lattice coordinates, no derivative.
#[inline(always)]
fn value(qx: &L, qz: &L, seed: u32, out: &mut L) {
    for l in 0..LANES {
        let fx = qx[l].floor();
        let fz = qz[l].floor();
        let u = fade(qx[l] - fx);
        let v = fade(qz[l] - fz);
        let [h00, h10, h01, h11] = corner_hashes(lattice_index(fx), lattice_index(fz), seed);
        let a = gaussian_fast(h00);
        let b = gaussian_fast(h10);
        let c = gaussian_fast(h01);
        let d = gaussian_fast(h11);
        let k1 = b - a;
        let k2 = c - a;
        let k3 = a - b - c + d;
        out[l] = a + k1 * u + k2 * v + k3 * u * v;
    }
}

/// Scales gradient noise to about `[−1, 1]` (its corner gradients have components uniform in
/// `[−1, 1]`, mean square length ⅔).
pub const GRADIENT_SCALE: f32 = 1.7;

/// The gradient of a corner hash: the two 16-bit halves as a vector with components in
/// `[−1, 1]`. Not normalised (that would cost a reciprocal square root per corner); the square's
/// diagonal bias averages out over the octaves, each rotated by its own angle.
#[inline(always)]
fn corner_gradient(h: u32) -> (f32, f32) {
    let gx = (h & 0xffff) as f32 - 32767.5;
    let gz = (h >> 16) as f32 - 32767.5;
    (gx * (1.0 / 32767.5), gz * (1.0 / 32767.5))
}

/// Gradient (Perlin) noise times [`GRADIENT_SCALE`] and its derivative with respect to the
/// lattice coordinates: each corner carries a hashed gradient, blended with the quintic
/// fade. Zero at lattice points, less blocky than value noise, its zero set forms the connected
/// network of lines that ridged octaves turn into crests.
#[inline(always)]
fn gradient_d(qx: &L, qz: &L, seed: u32, out: &mut L, dx: &mut L, dz: &mut L) {
    for l in 0..LANES {
        let fx = qx[l].floor();
        let fz = qz[l].floor();
        let tx = qx[l] - fx;
        let tz = qz[l] - fz;
        let u = fade(tx);
        let v = fade(tz);
        let du = dfade(tx);
        let dv = dfade(tz);
        let [h00, h10, h01, h11] = corner_hashes(lattice_index(fx), lattice_index(fz), seed);
        let (ax, az) = corner_gradient(h00);
        let (bx, bz) = corner_gradient(h10);
        let (cx, cz) = corner_gradient(h01);
        let (ex, ez) = corner_gradient(h11);
        let va = ax * tx + az * tz;
        let vb = bx * (tx - 1.0) + bz * tz;
        let vc = cx * tx + cz * (tz - 1.0);
        let vd = ex * (tx - 1.0) + ez * (tz - 1.0);
        let k1 = vb - va;
        let k2 = vc - va;
        let k3 = va - vb - vc + vd;
        out[l] = (va + k1 * u + k2 * v + k3 * u * v) * GRADIENT_SCALE;
        let gx = ax + (bx - ax) * u + (cx - ax) * v + (ax - bx - cx + ex) * u * v;
        let gz = az + (bz - az) * u + (cz - az) * v + (az - bz - cz + ez) * u * v;
        dx[l] = (gx + du * (k1 + k3 * v)) * GRADIENT_SCALE;
        dz[l] = (gz + dv * (k2 + k3 * u)) * GRADIENT_SCALE;
    }
}

/// `Σ amp · n(octave coords)` over a list of octaves, added to `acc`.
#[inline(always)]
fn fbm_into(octaves: &[NoiseOctave], xs: &L, zs: &L, acc: &mut L) {
    let mut qx = [0.0; LANES];
    let mut qz = [0.0; LANES];
    let mut n = [0.0; LANES];
    for o in octaves {
        octave_coords(o, xs, zs, &mut qx, &mut qz);
        value(&qx, &qz, o.seed, &mut n);
        for l in 0..LANES {
            acc[l] += o.amp * n[l];
        }
    }
}

/// The large-scale fields of a batch: continent elevation `e(c)`, relief amplitude `A` and ridge
/// mix `ρ`. Independent of the LOD.
#[inline(always)]
pub(super) fn macro_fields(
    m: &MacroPlan,
    xs: &L,
    zs: &L,
    elev: &mut L,
    amp: &mut L,
    ridge: &mut L,
) {
    let mut wx = [0.0; LANES];
    let mut wz = [0.0; LANES];
    fbm_into(&m.warp_x, xs, zs, &mut wx);
    fbm_into(&m.warp_z, xs, zs, &mut wz);
    let mut px = [0.0; LANES];
    let mut pz = [0.0; LANES];
    for l in 0..LANES {
        px[l] = xs[l] + wx[l];
        pz[l] = zs[l] + wz[l];
    }
    let mut c = [0.0; LANES];
    fbm_into(&m.continent, &px, &pz, &mut c);
    let mut b = [0.0; LANES];
    fbm_into(&m.belt, &px, &pz, &mut b);
    let mut hl = [0.0; LANES];
    fbm_into(&m.hills, xs, zs, &mut hl);
    for l in 0..LANES {
        // The origin's land bias: a rational bump, 1 at the origin, ¼ at two radii.
        let r2 = (xs[l] * xs[l] + zs[l] * zs[l]) * m.inv_origin_r2;
        let cv = c[l] + m.land_bias + m.origin_land / (1.0 + r2);
        let land = smoothstep(LAND_EDGE.0, LAND_EDGE.1, cv);
        let belt_abs = (b[l] * b[l] + BELT_EPS2).sqrt();
        let belt = (1.0 - smoothstep(0.0, m.belt_width, belt_abs))
            * smoothstep(BELT_LAND.0, BELT_LAND.1, cv);
        let hills = smoothstep(HILLS_EDGE.0, HILLS_EDGE.1, hl[l]);
        amp[l] = land
            * (m.mountain_relief_m * belt
                + m.hill_relief_m * hills * (1.0 - belt)
                + m.plain_relief_m)
            + (1.0 - land) * m.seafloor_relief_m;
        ridge[l] = smoothstep(RIDGE_EDGE.0, RIDGE_EDGE.1, belt).max(HILL_RIDGE * hills);
        elev[l] = m.interior_height_m * smoothstep(0.0, INTERIOR_C, cv) + COAST_M
            - (COAST_M - SHELF_M) * smoothstep(0.0, SHELF_C, cv)
            - (m.ocean_depth_m + SHELF_M) * smoothstep(SHELF_C, ABYSS_C, cv)
            + UPLIFT * m.mountain_relief_m * belt * land;
    }
}

/// Continent values over which land fades in (the relief amplitude's land mask).
pub const LAND_EDGE: (f32, f32) = (-0.06, 0.02);
/// `ε²` of the smooth `|m|` of the belt noise.
pub const BELT_EPS2: f32 = 1e-4;
/// Continent values over which belts fade in (few mountains out at sea).
pub const BELT_LAND: (f32, f32) = (-0.1, 0.15);
/// Hill-noise values over which hill country fades in.
pub const HILLS_EDGE: (f32, f32) = (-0.5, 0.5);
/// Belt mask values over which ridged octaves take over.
pub const RIDGE_EDGE: (f32, f32) = (0.05, 0.5);
/// Ridge mix of hill country.
pub const HILL_RIDGE: f32 = 0.35;
/// Plains at the coast, metres above sea level.
pub const COAST_M: f32 = 80.0;
/// Continent value where the plains reach the interior height.
pub const INTERIOR_C: f32 = 0.9;
/// The shelf edge: depth (metres below sea level, negative) and continent value.
pub const SHELF_M: f32 = -200.0;
/// Continent value of the shelf edge.
pub const SHELF_C: f32 = -0.05;
/// Continent value where the abyss begins.
pub const ABYSS_C: f32 = -0.3;
/// Uplift of mountain belts, in units of their relief: valleys stay above the plains.
pub const UPLIFT: f32 = 0.45;

/// Damping of the finer layers by the slope so far: `1 / (1 + k_d |G|²)`.
pub const DAMPING: f32 = 5.0;
/// `ε²` of the smooth absolute value of ridged octaves.
pub const RIDGE_EPS2: f32 = 0.12 * 0.12;
/// Slope (rise over run) at which gullies reach their full depth where the relief is the
/// largest (proportionally less where it is smaller); below it they fade in.
pub const GULLY_SLOPE: f32 = 0.35;

/// Square of the smallest magnitude of the blended phasor that [`gullies`] divides by in worlds
/// with `gullies: 3` (magnitude 1/√8 ≈ 0.35; the square is exact in `f32`, as the WGSL twin
/// receives it). Where the corners' phasors nearly cancel, the normalised stripe `c/|p|`
/// turns from crest to trough within a fraction of a sample: the full depth of the gully (up to
/// 320 m for the coarsest octave in a mountain belt) as a cliff one sample wide, seen in the
/// viewer as vertical walls with a comb of stripes and at 8 m as knife-edge lines. Dividing by
/// `max(|p|, 0.35)` keeps full stripes wherever the phasors agree and fades the stripe to 0
/// continuously where they cancel. Over 20 km of the range at 8 m (40 × 40 LOD-3 tiles from
/// (102 km, 102 km)) the neighbour pairs steeper than 63° fell from 0.081 % to 0.016 % and the
/// steepest from 87° to 79° (a floor of 0.2: 0.030 %; 0.5: 0.011 %).
pub const GULLY_PHASOR_FLOOR2: f32 = 0.125;

/// One erosion-filter octave: returns the stripe value in `[−1, 1]` and its gradient (per metre)
/// for stripes whose crests run along `(gx, gz)`, the blended phasor divided by the larger of its
/// magnitude and `√floor2` ([`GULLY_PHASOR_FLOOR2`] in `gullies: 3` worlds, else 0).
///
/// The four corners of the sample's cell each carry a wave `cos 2π(d·t' + φ_c)` through the
/// sample, where `d` is the offset from the corner in cells, `t'` the unit vector across the
/// slope (in the octave's rotated frame) and `φ_c` a hashed phase; their phasors are blended with
/// the bilinear fade weights and normalised, so the stripes keep unit amplitude and bend
/// smoothly as the slope direction turns. The gradient is the stripe's own (the change of the
/// weights and of the direction is neglected, as in the point-evaluable filters this follows).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn gullies(
    o: &NoiseOctave,
    floor2: f32,
    xs: &L,
    zs: &L,
    gx: &L,
    gz: &L,
    out: &mut L,
    dx: &mut L,
    dz: &mut L,
) {
    let mut qx = [0.0; LANES];
    let mut qz = [0.0; LANES];
    octave_coords(o, xs, zs, &mut qx, &mut qz);
    let k = std::f32::consts::TAU * o.freq;
    for l in 0..LANES {
        // Across-slope unit vector t = perp(G) / |G|, world frame, then rotated into the octave's.
        let g2 = gx[l] * gx[l] + gz[l] * gz[l];
        let inv = inv_sqrt(g2 + 1e-12);
        let tx = -gz[l] * inv;
        let tz = gx[l] * inv;
        let rx = o.cos * tx - o.sin * tz;
        let rz = o.sin * tx + o.cos * tz;
        let fx = qx[l].floor();
        let fz = qz[l].floor();
        let ux = qx[l] - fx;
        let uz = qz[l] - fz;
        let wu = fade(ux);
        let wv = fade(uz);
        let [h00, h10, h01, h11] = corner_hashes(lattice_index(fx), lattice_index(fz), o.seed);
        let phase = |h: u32| (mix32(h) >> 8) as f32 * (1.0 / 16_777_216.0);
        let (s00, c00) = sincos_turns(ux * rx + uz * rz + phase(h00));
        let (s10, c10) = sincos_turns((ux - 1.0) * rx + uz * rz + phase(h10));
        let (s01, c01) = sincos_turns(ux * rx + (uz - 1.0) * rz + phase(h01));
        let (s11, c11) = sincos_turns((ux - 1.0) * rx + (uz - 1.0) * rz + phase(h11));
        let ca = c00 + (c10 - c00) * wu;
        let cb = c01 + (c11 - c01) * wu;
        let sa = s00 + (s10 - s00) * wu;
        let sb = s01 + (s11 - s01) * wu;
        let c = ca + (cb - ca) * wv;
        let s = sa + (sb - sa) * wv;
        // `max(x, 0)` is `x` for the sum of squares: worlds before `gullies: 3` keep their bits.
        let n = inv_sqrt((c * c + s * s).max(floor2) + 1e-6);
        out[l] = c * n;
        // d/dp cos(θ) = −sin(θ) · 2π · freq · t (world frame).
        let ds = -s * n * k;
        dx[l] = ds * tx;
        dz[l] = ds * tz;
    }
}

/// Softening of the incised gullies' troughs, in units of `u` (below): the V is rounded over
/// about `√ε` of the stripe's half-period.
pub const INCISE_EPS: f32 = 0.02;
/// Mean of `2√u − 1` over a stripe's phase, `4/π − 1`: subtracted so incised gullies add no
/// height on average.
pub const INCISE_MEAN: f32 = 0.273_239_55;
/// `1 / (1 + INCISE_MEAN) = π/4`: keeps the incised stripe within `[−1, 1]` (its deepest trough
/// is −0.78, its crests 0.59), so the LOD bound's largest gully signal stands.
pub const INCISE_NORM: f32 = std::f32::consts::FRAC_PI_4;

/// The incised cross-section of a gully octave (`EarthParams::gullies` 2), in place: with the
/// stripe `v` (1 on its crests, −1 in its troughs) and `u = (1 + v)/2 = cos²(θ/2)`, the
/// section is `(2√(u + ε) − 1 − INCISE_MEAN) · INCISE_NORM`, i.e. `|cos(θ/2)|` rescaled: a
/// V-shaped trough between broad rounded crests, as water cuts gullies into a slope and leaves
/// the spurs between them. Its derivative is the stripe's times `INCISE_NORM / (2√(u + ε))`.
#[inline(always)]
fn incise(v: &mut L, dx: &mut L, dz: &mut L) {
    for l in 0..LANES {
        let ue = 0.5 + 0.5 * v[l] + INCISE_EPS;
        let inv = inv_sqrt(ue);
        let r = ue * inv;
        v[l] = (2.0 * r - 1.0 - INCISE_MEAN) * INCISE_NORM;
        let dsig = 0.5 * inv * INCISE_NORM;
        dx[l] *= dsig;
        dz[l] *= dsig;
    }
}

/// The state of a batch part-way through the height sum: the macro fields and the layers summed
/// so far with their gradient. [`heights`] is [`Partial::start`], [`Partial::add_layers`] over
/// the LOD's layers and [`Partial::finish`]; the lattice split ([`super::lattice`]) builds the
/// first part at the nodes of a world lattice and interpolates it instead.
#[derive(Clone, Debug)]
pub(crate) struct Partial {
    /// Continent elevation `e(c)`, metres.
    pub elev: L,
    /// Relief amplitude `A`, metres.
    pub amp: L,
    /// Ridge mix `ρ`.
    pub ridge: L,
    /// Layers summed so far, metres.
    pub h: L,
    /// Their gradient along x (rise over run).
    pub gx: L,
    /// Their gradient along z.
    pub gz: L,
}

impl Partial {
    /// All zeros.
    pub(crate) fn zero() -> Self {
        Self {
            elev: [0.0; LANES],
            amp: [0.0; LANES],
            ridge: [0.0; LANES],
            h: [0.0; LANES],
            gx: [0.0; LANES],
            gz: [0.0; LANES],
        }
    }

    /// The macro fields of a batch and no layers yet.
    #[inline(always)]
    pub(crate) fn start(plan: &EarthPlan, xs: &L, zs: &L) -> Self {
        let mut p = Self::zero();
        macro_fields(
            &plan.macro_plan,
            xs,
            zs,
            &mut p.elev,
            &mut p.amp,
            &mut p.ridge,
        );
        p
    }

    /// Adds `layers` in order: `erosion[l]` and `rough[l]` are the climate's erosion strength
    /// and roughness at each sample.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn add_layers(
        &mut self,
        plan: &EarthPlan,
        layers: &[Layer],
        xs: &L,
        zs: &L,
        erosion: &L,
        rough: &L,
    ) {
        let (amp, ridge) = (&self.amp, &self.ridge);
        let (h, gx, gz) = (&mut self.h, &mut self.gx, &mut self.gz);
        let mut qx = [0.0; LANES];
        let mut qz = [0.0; LANES];
        let mut n = [0.0; LANES];
        let mut dx = [0.0; LANES];
        let mut dz = [0.0; LANES];
        for layer in layers {
            let o = &layer.octave;
            match layer.kind {
                LayerKind::Relief { fine, ridged } => {
                    octave_coords(o, xs, zs, &mut qx, &mut qz);
                    gradient_d(&qx, &qz, o.seed, &mut n, &mut dx, &mut dz);
                    for l in 0..LANES {
                        // Lattice derivative → world: d/dp = freq · Rᵀ · d/dq.
                        let wdx = (o.cos * dx[l] + o.sin * dz[l]) * o.freq;
                        let wdz = (o.cos * dz[l] - o.sin * dx[l]) * o.freq;
                        // Ridged: t = 1 − |n|_ε with a smooth absolute value, so crests are
                        // rounded over about ε of the octave's wavelength instead of one-sample
                        // creases.
                        let an = (n[l] * n[l] + RIDGE_EPS2).sqrt();
                        let t = (1.0 - an).max(0.0);
                        let dan = n[l] / an;
                        let r = if ridged { ridge[l] } else { 0.0 };
                        // (1 − ρ)·n + ρ·2(t² − 0.4), and its derivative.
                        let sig = (1.0 - r) * n[l] + r * 2.0 * (t * t - 0.4);
                        let dsig = (1.0 - r) - r * 4.0 * t * dan;
                        let damp = 1.0 / (1.0 + DAMPING * (gx[l] * gx[l] + gz[l] * gz[l]));
                        let rough_l = if fine { rough[l] } else { 1.0 };
                        let a = amp[l] * layer.amp * damp * rough_l;
                        h[l] += a * sig;
                        gx[l] += a * dsig * wdx;
                        gz[l] += a * dsig * wdz;
                    }
                }
                LayerKind::Gully { incised, floor2 } => {
                    gullies(o, floor2, xs, zs, gx, gz, &mut n, &mut dx, &mut dz);
                    if incised {
                        incise(&mut n, &mut dx, &mut dz);
                    }
                    for l in 0..LANES {
                        // The slope relative to the local relief: plains get valleys on their
                        // gentle slopes as mountains do on their steep ones.
                        let slope = (gx[l] * gx[l] + gz[l] * gz[l]).sqrt();
                        let fadein =
                            smoothstep(0.0, GULLY_SLOPE * amp[l] * plan.inv_relief_max, slope);
                        let a = amp[l] * layer.amp * erosion[l] * fadein;
                        h[l] += a * n[l];
                        gx[l] += a * dx[l];
                        gz[l] += a * dz[l];
                    }
                }
            }
        }
    }

    /// The heights (metres): the continent elevation plus the layers' sum, whose part below the
    /// base level is compressed towards the valley floor.
    #[inline(always)]
    pub(crate) fn finish(&self, out: &mut L) {
        for (l, o) in out.iter_mut().enumerate() {
            // Valley floors: below the base level the relief is compressed towards a floor at
            // `−VALLEY_FLOOR · A` (`f(r) = r / (1 − r / s)`, C¹ and 1-Lipschitz), as sediment
            // fills basins; closed hollows keep at most a fraction of their depth.
            let s = VALLEY_FLOOR * self.amp[l] + 1e-3;
            let r = self.h[l];
            let floor = r / (1.0 - r / s);
            *o = self.elev[l] + if r < 0.0 { floor } else { r };
        }
    }
}

/// Heights (metres) of a batch at one LOD, every layer evaluated at every sample: `erosion[l]`
/// and `rough[l]` are the climate's erosion strength and roughness at each sample.
pub(super) fn heights(
    plan: &EarthPlan,
    lod: usize,
    xs: &L,
    zs: &L,
    erosion: &L,
    rough: &L,
    out: &mut L,
) {
    let mut p = Partial::start(plan, xs, zs);
    p.add_layers(plan, &plan.lods[lod].layers, xs, zs, erosion, rough);
    p.finish(out);
}

/// Depth of the valley floors below the base level, in units of the local relief.
pub const VALLEY_FLOOR: f32 = 0.04;
