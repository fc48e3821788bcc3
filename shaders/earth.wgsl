// requires: common.wgsl
// preamble: strata::gpu::earth::constants_wgsl()
//
// WGSL twin of `terrain::earth::kernel::heights` (the `earth-1` height function): one invocation
// per sample of a field job, evaluating the macro fields (warp, continents, belts, hills), then
// the LOD's relief layers (rotated gradient noise, ridged in belts, damped by the slope so far)
// and gully layers (the erosion filter steered by the slope so far), in the CPU's layer order.
//
// The biome weights (`earth::climate::weights`) and the per-sample erosion strength and
// roughness they give stay on the CPU: the host computes them and uploads `relief` (erosion,
// roughness) per sample, and the field's weights are the CPU's own.
//
// Every operation mirrors the Rust in the same order, as in `common.wgsl`: each product that can
// meet an addition passes the rounding barrier `rn` (no contraction into a fused multiply-add),
// `/` is `div_rn` and `sqrt` is `sqrt_rn` (correctly rounded, as on the CPU), the sine and cosine
// are `trig::sincos_turns` from adds, multiplies and `floor`.
//
// The kernel constants (DAMPING, RIDGE_EPS2, GULLY_SLOPE, GRADIENT_SCALE, LAND_EDGE_0/1,
// BELT_EPS2, BELT_LAND_0/1, HILLS_EDGE_0/1, RIDGE_EDGE_0/1, HILL_RIDGE, COAST_M, INTERIOR_C,
// SHELF_M, SHELF_C, ABYSS_C, UPLIFT) and the f32 constants of `sincos_turns` are not written
// here: the host prepends `const NAME: f32 = …;` lines generated from the Rust constants
// (`gpu::earth::constants_wgsl`), each the exact decimal of the f32, so WGSL reads the same value.
//
// `EarthParams` is `gpu::layout::GpuEarthParams` on the CPU, `EarthOctave` is `GpuEarthOctave`
// and `EarthLayer` is `GpuEarthLayer`, field for field.

struct EarthParams {
    // Output rectangle: lattice origin and size.
    gx0: i32,
    gz0: i32,
    w: u32,
    h: u32,
    // Vertex spacing in metres, and 0 (see `rn`).
    spacing: f32,
    rounding_key: u32,
    // Layers of the LOD in `layers`.
    layer_count: u32,
    // Macro octaves in `octaves`: warp_x, warp_z, continent, belt, hills, in that order.
    warp_x_count: u32,
    warp_z_count: u32,
    continent_count: u32,
    belt_count: u32,
    hills_count: u32,
    // `earth::MacroPlan`.
    land_bias: f32,
    origin_land: f32,
    inv_origin_r2: f32,
    belt_width: f32,
    mountain_relief_m: f32,
    hill_relief_m: f32,
    plain_relief_m: f32,
    seafloor_relief_m: f32,
    interior_height_m: f32,
    ocean_depth_m: f32,
    // `earth::EarthPlan::inv_relief_max`.
    inv_relief_max: f32,
    // The LOD's lattice split (`earth::lattice`): samples per lattice spacing (0: none), the
    // layers the nodes hold, and the uploaded nodes' first column, first row and columns.
    lattice_step: u32,
    prefix: u32,
    node_i0: i32,
    node_k0: i32,
    nodes_w: u32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

// `earth::NoiseOctave`.
struct EarthOctave {
    freq: f32,
    amp: f32,
    seed: u32,
    cos: f32,
    sin: f32,
    ox: f32,
    oz: f32,
    _pad: u32,
}

const LAYER_RELIEF: u32 = 0u;
const LAYER_GULLY: u32 = 1u;

// `earth::Layer`: kind (LAYER_RELIEF or LAYER_GULLY), the relief flags as 0/1 (`ridged` on a gully
// layer: incised), the amplitude, and a gully layer's squared phasor floor (0: none).
struct EarthLayer {
    kind: u32,
    fine: u32,
    ridged: u32,
    amp: f32,
    octave: EarthOctave,
    floor2: f32,
}

const WORKGROUP: u32 = 64u;

@group(0) @binding(0) var<uniform> params: EarthParams;
@group(0) @binding(1) var<storage, read> octaves: array<EarthOctave>;
@group(0) @binding(2) var<storage, read> layers: array<EarthLayer>;
// Per sample: (erosion strength, roughness) from the CPU's climate weights.
@group(0) @binding(3) var<storage, read> relief: array<vec2<f32>>;
// Output: heights (w × h, row-major).
@group(0) @binding(4) var<storage, read_write> heights: array<f32>;
// The lattice split's nodes, two per node: (elevation, amplitude, ridge mix, layer sum) and
// (gradient x, gradient z, 0, 0), row-major from (node_i0, node_k0); one unread node when the
// LOD has no split. The host computes them with the CPU reference (`earth::lattice::nodes`).
@group(0) @binding(5) var<storage, read> nodes: array<vec4<f32>>;

// `noise::corner_hashes`: the lattice hashes of the cell's corners
// [(ix, iz), (ix + 1, iz), (ix, iz + 1), (ix + 1, iz + 1)].
fn corner_hashes(ix: u32, iz: u32, seed: u32) -> vec4<u32> {
    let hx0 = ix * PRIME_X;
    let hx1 = hx0 + PRIME_X;
    let hz = iz * PRIME_Z;
    let hz0 = hz ^ seed;
    let hz1 = (hz + PRIME_Z) ^ seed;
    return vec4<u32>(
        lattice_hash(hx0 ^ hz0),
        lattice_hash(hx1 ^ hz0),
        lattice_hash(hx0 ^ hz1),
        lattice_hash(hx1 ^ hz1),
    );
}

// `trig::sincos_turns`: (sin 2πx, cos 2πx) for x in turns.
fn sincos_turns(x: f32) -> vec2<f32> {
    let q = floor(rn(x * 4.0) + 0.5);
    let t = rn(rn(x - rn(q * 0.25)) * TAU);
    let t2 = rn(t * t);
    let s = rn(t * rn(1.0 - rn(t2 * rn(TRIG_S3 - rn(t2 * rn(TRIG_S5 - rn(t2 * TRIG_S7)))))));
    let c = rn(1.0 - rn(t2 * rn(0.5 - rn(t2 * rn(TRIG_C4 - rn(t2 * TRIG_C6))))));
    let quarter = i32(q) & 3;
    var r = vec2<f32>(s, c);
    if ((quarter & 1) == 1) {
        r = vec2<f32>(c, -s);
    }
    if ((quarter & 2) == 2) {
        r = -r;
    }
    return r;
}

// `kernel::dfade`.
fn dfade(t: f32) -> f32 {
    let u = rn(t * (t - 1.0));
    return rn(rn(30.0 * u) * u);
}

// `kernel::smoothstep`.
fn smoothstep_rn(e0: f32, e1: f32, x: f32) -> f32 {
    let t = clamp(div_rn(x - e0, e1 - e0), 0.0, 1.0);
    return rn(rn(t * t) * (3.0 - rn(2.0 * t)));
}

// Correctly rounded sqrt, also for 0.
fn sqrt0(x: f32) -> f32 {
    if (x > 0.0) {
        return sqrt_rn(x);
    }
    return sqrt(x);
}

// `kernel::octave_coords`.
fn octave_coords(o: EarthOctave, x: f32, z: f32) -> vec2<f32> {
    let qx = rn(rn(rn(o.cos * x) - rn(o.sin * z)) * o.freq) + o.ox;
    let qz = rn(rn(rn(o.sin * x) + rn(o.cos * z)) * o.freq) + o.oz;
    return vec2<f32>(qx, qz);
}

// `kernel::value`: value noise at lattice coordinates.
fn value(q: vec2<f32>, seed: u32) -> f32 {
    let fx = floor(q.x);
    let fz = floor(q.y);
    let u = fade(q.x - fx);
    let v = fade(q.y - fz);
    let h = corner_hashes(lattice_index(fx), lattice_index(fz), seed);
    let a = gaussian(h.x);
    let b = gaussian(h.y);
    let c = gaussian(h.z);
    let d = gaussian(h.w);
    let k1 = b - a;
    let k2 = c - a;
    let k3 = ((a - b) - c) + d;
    return ((a + rn(k1 * u)) + rn(k2 * v)) + rn(rn(k3 * u) * v);
}

// `kernel::fbm_into` over `count` octaves from `first`, added to `acc`.
fn fbm_into(first: u32, count: u32, x: f32, z: f32, acc0: f32) -> f32 {
    var acc = acc0;
    for (var i = 0u; i < count; i++) {
        let o = octaves[first + i];
        acc += rn(o.amp * value(octave_coords(o, x, z), o.seed));
    }
    return acc;
}

// `kernel::corner_gradient`.
fn corner_gradient(h: u32) -> vec2<f32> {
    let gx = f32(h & 0xffffu) - 32767.5;
    let gz = f32(h >> 16u) - 32767.5;
    return vec2<f32>(rn(gx * (1.0 / 32767.5)), rn(gz * (1.0 / 32767.5)));
}

// `kernel::gradient_d`: gradient noise times GRADIENT_SCALE and its lattice derivative, as
// (value, d/dqx, d/dqz).
fn gradient_d(q: vec2<f32>, seed: u32) -> vec3<f32> {
    let fx = floor(q.x);
    let fz = floor(q.y);
    let tx = q.x - fx;
    let tz = q.y - fz;
    let u = fade(tx);
    let v = fade(tz);
    let du = dfade(tx);
    let dv = dfade(tz);
    let h = corner_hashes(lattice_index(fx), lattice_index(fz), seed);
    let ga = corner_gradient(h.x);
    let gb = corner_gradient(h.y);
    let gc = corner_gradient(h.z);
    let ge = corner_gradient(h.w);
    let va = rn(ga.x * tx) + rn(ga.y * tz);
    let vb = rn(gb.x * (tx - 1.0)) + rn(gb.y * tz);
    let vc = rn(gc.x * tx) + rn(gc.y * (tz - 1.0));
    let vd = rn(ge.x * (tx - 1.0)) + rn(ge.y * (tz - 1.0));
    let k1 = vb - va;
    let k2 = vc - va;
    let k3 = ((va - vb) - vc) + vd;
    let n = rn((((va + rn(k1 * u)) + rn(k2 * v)) + rn(rn(k3 * u) * v)) * GRADIENT_SCALE);
    let gx = ((ga.x + rn((gb.x - ga.x) * u)) + rn((gc.x - ga.x) * v))
        + rn(rn((((ga.x - gb.x) - gc.x) + ge.x) * u) * v);
    let gz = ((ga.y + rn((gb.y - ga.y) * u)) + rn((gc.y - ga.y) * v))
        + rn(rn((((ga.y - gb.y) - gc.y) + ge.y) * u) * v);
    let dx = rn((gx + rn(du * (k1 + rn(k3 * v)))) * GRADIENT_SCALE);
    let dz = rn((gz + rn(dv * (k2 + rn(k3 * u)))) * GRADIENT_SCALE);
    return vec3<f32>(n, dx, dz);
}

// `kernel::macro_fields` for one sample: (elevation e(c), relief amplitude A, ridge mix ρ).
fn macro_fields(x: f32, z: f32) -> vec3<f32> {
    let p = params;
    var first = 0u;
    let wx = fbm_into(first, p.warp_x_count, x, z, 0.0);
    first += p.warp_x_count;
    let wz = fbm_into(first, p.warp_z_count, x, z, 0.0);
    first += p.warp_z_count;
    let px = x + wx;
    let pz = z + wz;
    let c = fbm_into(first, p.continent_count, px, pz, 0.0);
    first += p.continent_count;
    let b = fbm_into(first, p.belt_count, px, pz, 0.0);
    first += p.belt_count;
    let hl = fbm_into(first, p.hills_count, x, z, 0.0);

    let r2 = rn(rn(rn(x * x) + rn(z * z)) * p.inv_origin_r2);
    let cv = (c + p.land_bias) + div_rn(p.origin_land, 1.0 + r2);
    let land = smoothstep_rn(LAND_EDGE_0, LAND_EDGE_1, cv);
    let belt_abs = sqrt0(rn(b * b) + BELT_EPS2);
    let belt = rn((1.0 - smoothstep_rn(0.0, p.belt_width, belt_abs))
        * smoothstep_rn(BELT_LAND_0, BELT_LAND_1, cv));
    let hills = smoothstep_rn(HILLS_EDGE_0, HILLS_EDGE_1, hl);
    let inner = (rn(p.mountain_relief_m * belt) + rn(rn(p.hill_relief_m * hills) * (1.0 - belt)))
        + p.plain_relief_m;
    let amp = rn(land * inner) + rn((1.0 - land) * p.seafloor_relief_m);
    let ridge = max(smoothstep_rn(RIDGE_EDGE_0, RIDGE_EDGE_1, belt), rn(HILL_RIDGE * hills));
    let elev = (((rn(p.interior_height_m * smoothstep_rn(0.0, INTERIOR_C, cv)) + COAST_M)
        - rn((COAST_M - SHELF_M) * smoothstep_rn(0.0, SHELF_C, cv)))
        - rn((p.ocean_depth_m + SHELF_M) * smoothstep_rn(SHELF_C, ABYSS_C, cv)))
        + rn(rn(rn(UPLIFT * p.mountain_relief_m) * belt) * land);
    return vec3<f32>(elev, amp, ridge);
}

// `kernel::gullies` for one sample: (stripe value, d/dx, d/dz) for stripes along g, the phasor
// divided by the larger of its magnitude and √floor2.
fn gullies(o: EarthOctave, floor2: f32, x: f32, z: f32, g: vec2<f32>) -> vec3<f32> {
    let q = octave_coords(o, x, z);
    let k = rn(TAU * o.freq);
    let g2 = rn(g.x * g.x) + rn(g.y * g.y);
    let inv = inv_sqrt(g2 + GULLY_G_EPS);
    let tx = rn(-g.y * inv);
    let tz = rn(g.x * inv);
    let rx = rn(o.cos * tx) - rn(o.sin * tz);
    let rz = rn(o.sin * tx) + rn(o.cos * tz);
    let fx = floor(q.x);
    let fz = floor(q.y);
    let ux = q.x - fx;
    let uz = q.y - fz;
    let wu = fade(ux);
    let wv = fade(uz);
    let h = corner_hashes(lattice_index(fx), lattice_index(fz), o.seed);
    let p00 = f32(mix32(h.x) >> 8u) * (1.0 / 16777216.0);
    let p10 = f32(mix32(h.y) >> 8u) * (1.0 / 16777216.0);
    let p01 = f32(mix32(h.z) >> 8u) * (1.0 / 16777216.0);
    let p11 = f32(mix32(h.w) >> 8u) * (1.0 / 16777216.0);
    let sc00 = sincos_turns((rn(ux * rx) + rn(uz * rz)) + rn(p00));
    let sc10 = sincos_turns((rn((ux - 1.0) * rx) + rn(uz * rz)) + rn(p10));
    let sc01 = sincos_turns((rn(ux * rx) + rn((uz - 1.0) * rz)) + rn(p01));
    let sc11 = sincos_turns((rn((ux - 1.0) * rx) + rn((uz - 1.0) * rz)) + rn(p11));
    let ca = sc00.y + rn((sc10.y - sc00.y) * wu);
    let cb = sc01.y + rn((sc11.y - sc01.y) * wu);
    let sa = sc00.x + rn((sc10.x - sc00.x) * wu);
    let sb = sc01.x + rn((sc11.x - sc01.x) * wu);
    let c = ca + rn((cb - ca) * wv);
    let s = sa + rn((sb - sa) * wv);
    let n = inv_sqrt(max(rn(c * c) + rn(s * s), floor2) + GULLY_N_EPS);
    let ds = rn(rn(-s * n) * k);
    return vec3<f32>(rn(c * n), rn(ds * tx), rn(ds * tz));
}

// `kernel::incise`: the incised cross-section of a gully octave (`ridged` set on a gully layer),
// `(2√(u + ε) − 1 − INCISE_MEAN) · INCISE_NORM` with `u = (1 + v)/2`, and its derivative.
fn incise(nd: vec3<f32>) -> vec3<f32> {
    let ue = (0.5 + rn(0.5 * nd.x)) + INCISE_EPS;
    let inv = inv_sqrt(ue);
    let r = rn(ue * inv);
    let v = rn(((rn(2.0 * r) - 1.0) - INCISE_MEAN) * INCISE_NORM);
    let dsig = rn(rn(0.5 * inv) * INCISE_NORM);
    return vec3<f32>(v, rn(nd.y * dsig), rn(nd.z * dsig));
}

// `rn` of each component.
fn rn_v4(x: vec4<f32>) -> vec4<f32> {
    return bitcast<vec4<f32>>(bitcast<vec4<u32>>(x) ^ vec4<u32>(rounding_key));
}

fn rn_v2(x: vec2<f32>) -> vec2<f32> {
    return bitcast<vec2<f32>>(bitcast<vec2<u32>>(x) ^ vec2<u32>(rounding_key));
}

// `lattice::weights`: the uniform Catmull–Rom weights at offset t.
fn cr_weights(t: f32) -> vec4<f32> {
    let t2 = rn(t * t);
    let t3 = rn(t2 * t);
    return vec4<f32>(
        rn(0.5 * (rn(rn(2.0 * t2) - t3) - t)),
        rn(0.5 * (rn(rn(3.0 * t3) - rn(5.0 * t2)) + 2.0)),
        rn(0.5 * (rn(rn(4.0 * t2) - rn(3.0 * t3)) + t)),
        rn(0.5 * (t3 - t2)),
    );
}

// `lattice::locate`: the node of sample g and its offset from it in [0, 1).
fn locate(g: i32, step: i32) -> vec2<f32> {
    var n = g / step;
    if (g - n * step < 0) {
        n -= 1;
    }
    return vec2<f32>(f32(n), div_rn(f32(g - n * step), f32(step)));
}

// One node's values: elevation, amplitude, ridge mix, layer sum, gradient x, gradient z.
struct NodeValues {
    a: vec4<f32>,
    b: vec2<f32>,
}

fn node_values(a: i32, b: i32) -> NodeValues {
    let i = u32((b - params.node_k0) * i32(params.nodes_w) + (a - params.node_i0)) * 2u;
    return NodeValues(nodes[i], nodes[i + 1u].xy);
}

// `lattice::Interpolated::at`: rows first, each sum left to right from its first product.
fn interpolate_nodes(gx: i32, gz: i32) -> NodeValues {
    let step = i32(params.lattice_step);
    let lx = locate(gx, step);
    let lz = locate(gz, step);
    let wx = cr_weights(lx.y);
    let wz = cr_weights(lz.y);
    let a0 = i32(lx.x) - 1;
    let b0 = i32(lz.x) - 1;
    var out = NodeValues(vec4<f32>(0.0), vec2<f32>(0.0));
    for (var b = 0; b < 4; b++) {
        var ra = rn_v4(wx[0] * node_values(a0, b0 + b).a);
        var rb = rn_v2(wx[0] * node_values(a0, b0 + b).b);
        for (var a = 1; a < 4; a++) {
            let v = node_values(a0 + a, b0 + b);
            ra = ra + rn_v4(wx[a] * v.a);
            rb = rb + rn_v2(wx[a] * v.b);
        }
        if (b == 0) {
            out = NodeValues(rn_v4(wz[0] * ra), rn_v2(wz[0] * rb));
        } else {
            out = NodeValues(out.a + rn_v4(wz[b] * ra), out.b + rn_v2(wz[b] * rb));
        }
    }
    return out;
}

// Linear invocation index of a 2D dispatch of 1D workgroups (the x count is capped at 65535).
fn invocation(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.y * nwg.x * WORKGROUP + gid.x;
}

// `kernel::heights` for one sample.
@compute @workgroup_size(64)
fn earth_heights(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    rounding_key = params.rounding_key;
    let idx = invocation(gid, nwg);
    if (idx >= params.w * params.h) {
        return;
    }
    // World position `(g as f32) * spacing`, as on the CPU.
    let x = rn(f32(params.gx0 + i32(idx % params.w)) * params.spacing);
    let z = rn(f32(params.gz0 + i32(idx / params.w)) * params.spacing);
    let er = relief[idx];
    let erosion = er.x;
    let rough = er.y;
    var elev = 0.0;
    var amp = 0.0;
    var ridge = 0.0;
    var h = 0.0;
    var gx = 0.0;
    var gz = 0.0;
    var first = 0u;
    if (params.lattice_step > 0u) {
        // The lattice split: the nodes' part interpolated, the later layers below.
        let v = interpolate_nodes(params.gx0 + i32(idx % params.w), params.gz0 + i32(idx / params.w));
        elev = v.a.x;
        amp = v.a.y;
        ridge = v.a.z;
        h = v.a.w;
        gx = v.b.x;
        gz = v.b.y;
        first = params.prefix;
    } else {
        let m = macro_fields(x, z);
        elev = m.x;
        amp = m.y;
        ridge = m.z;
    }
    for (var i = first; i < params.layer_count; i++) {
        let layer = layers[i];
        let o = layer.octave;
        if (layer.kind == LAYER_RELIEF) {
            let nd = gradient_d(octave_coords(o, x, z), o.seed);
            let n = nd.x;
            // Lattice derivative → world: d/dp = freq · Rᵀ · d/dq.
            let wdx = rn((rn(o.cos * nd.y) + rn(o.sin * nd.z)) * o.freq);
            let wdz = rn((rn(o.cos * nd.z) - rn(o.sin * nd.y)) * o.freq);
            let an = sqrt0(rn(n * n) + RIDGE_EPS2);
            let t = max(1.0 - an, 0.0);
            let dan = div_rn(n, an);
            var r = 0.0;
            if (layer.ridged != 0u) {
                r = ridge;
            }
            let sig = rn((1.0 - r) * n) + rn(rn(r * 2.0) * (rn(t * t) - 0.4));
            let dsig = (1.0 - r) - rn(rn(rn(r * 4.0) * t) * dan);
            let damp = div_rn(1.0, 1.0 + rn(DAMPING * (rn(gx * gx) + rn(gz * gz))));
            var rough_l = 1.0;
            if (layer.fine != 0u) {
                rough_l = rough;
            }
            let a = rn(rn(rn(amp * layer.amp) * damp) * rough_l);
            h += rn(a * sig);
            gx += rn(rn(a * dsig) * wdx);
            gz += rn(rn(a * dsig) * wdz);
        } else {
            var nd = gullies(o, layer.floor2, x, z, vec2<f32>(gx, gz));
            if (layer.ridged != 0u) {
                nd = incise(nd);
            }
            let slope = sqrt0(rn(gx * gx) + rn(gz * gz));
            // The slope relative to the local relief.
            let full = rn(rn(GULLY_SLOPE * amp) * params.inv_relief_max);
            let fadein = smoothstep_rn(0.0, full, slope);
            let a = rn(rn(rn(amp * layer.amp) * erosion) * fadein);
            h += rn(a * nd.x);
            gx += rn(a * nd.y);
            gz += rn(a * nd.z);
        }
    }
    // Valley floors: `f(r) = r / (1 − r / s)` below the base level (`kernel::heights`).
    let s = rn(VALLEY_FLOOR * amp) + 1e-3;
    var relief_h = h;
    if (h < 0.0) {
        relief_h = div_rn(h, 1.0 - div_rn(h, s));
    }
    heights[idx] = elev + relief_h;
}
