// WGSL twin of `ptex::bake::texel` (Becher §4.7, texture baking): one invocation per interior
// texel of one face. See `src/ptex/bake.rs` for the steps (bilinear interpolation in the face's
// control grid, octave cut, noise and relief displacement, displaced normal by forward
// differences along the tangent frame, tri-planar blend with the displaced normal, quantisation)
// and `src/ptex/noise.rs` for the exact lattice coordinates (anchor times a power of two plus a
// local offset times a power of two). The per-face constants `kmax` and `step` come from the CPU
// (`ptex::bake::face_constants`), so both sides cut the same octaves.
//
// The integer hashing is the CPU's bit for bit; the float arithmetic follows the CPU's order, but
// a compiler may contract `a * b + c` and `sqrt`, `/` are a few ULP here, so texels may differ
// from the CPU by rounding (the tolerance is in `tests/gpu_ptex.rs`).
//
// `Params`, `Face`, `Sample` and `Mat` are `gpu::ptex`'s `GpuPtexParams`, `GpuFace`, `GpuSample`
// and `GpuMaterial`, field for field. Output: three words per texel (albedo and roughness bytes,
// normal and material bytes, the displacement's bits), texel `f·res² + j·res + i`.

struct Params {
    res: u32,
    faces: u32,
    noise_k0: i32,
    noise_octaves: u32,
    noise_seed: u32,
    materials: u32,
    pad0: u32,
    pad1: u32,
}

struct Face {
    ax: i32,
    ay: i32,
    az: i32,
    first: u32,
    n: u32,
    kmax: i32,
    step: f32,
    pad: u32,
}

struct Sample {
    px: f32,
    py: f32,
    pz: f32,
    material: u32,
    nx: f32,
    ny: f32,
    nz: f32,
    noise_m: f32,
}

struct Mat {
    base_r: f32,
    base_g: f32,
    base_b: f32,
    relief_m: f32,
    tint_r: f32,
    tint_g: f32,
    tint_b: f32,
    rough0: f32,
    rough1: f32,
    freq_log2: i32,
    octaves: u32,
    seed: u32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
    pad3: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> faces: array<Face>;
@group(0) @binding(2) var<storage, read> samples: array<Sample>;
@group(0) @binding(3) var<storage, read> mats: array<Mat>;
@group(0) @binding(4) var<storage, read_write> out: array<u32>;

const PRIME_X: u32 = 0x8da6b343u;
const PRIME_Y: u32 = 0x9e3779b1u;
const PRIME_Z: u32 = 0xd8163841u;
const MAX_FREQ_LOG2: i32 = 8;

// `terrain::hash::mix32`.
fn mix32(x: u32) -> u32 {
    var h = x;
    h = h ^ (h >> 16u);
    h = h * 0x7feb352du;
    h = h ^ (h >> 15u);
    h = h * 0x846ca68bu;
    h = h ^ (h >> 16u);
    return h;
}

fn hash3(x: i32, y: i32, z: i32, seed: u32) -> u32 {
    return mix32((u32(x) * PRIME_X) ^ (u32(y) * PRIME_Y) ^ (u32(z) * PRIME_Z) ^ seed);
}

fn lattice_value(h: u32) -> f32 {
    return f32(h >> 8u) * (1.0 / 8388608.0) - 1.0;
}

fn fade(t: f32) -> f32 {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

fn lerp1(a: f32, b: f32, t: f32) -> f32 {
    return a + (b - a) * t;
}

fn exp2i(k: i32) -> f32 {
    return bitcast<f32>(u32(k + 127) << 23u);
}

fn anchor_lattice(a: i32, k: i32) -> i32 {
    return a * (1i << u32(8 + k));
}

fn value3(base: vec3<i32>, x: vec3<f32>, seed: u32) -> f32 {
    let fl = floor(x);
    let i = base + vec3<i32>(fl);
    let f = x - fl;
    let u = fade(f.x);
    let v = fade(f.y);
    let w = fade(f.z);
    let x00 = lerp1(lattice_value(hash3(i.x, i.y, i.z, seed)), lattice_value(hash3(i.x + 1, i.y, i.z, seed)), u);
    let x10 = lerp1(lattice_value(hash3(i.x, i.y + 1, i.z, seed)), lattice_value(hash3(i.x + 1, i.y + 1, i.z, seed)), u);
    let x01 = lerp1(lattice_value(hash3(i.x, i.y, i.z + 1, seed)), lattice_value(hash3(i.x + 1, i.y, i.z + 1, seed)), u);
    let x11 = lerp1(lattice_value(hash3(i.x, i.y + 1, i.z + 1, seed)), lattice_value(hash3(i.x + 1, i.y + 1, i.z + 1, seed)), u);
    return lerp1(lerp1(x00, x10, v), lerp1(x01, x11, v), w);
}

fn value2(base: vec2<i32>, x: vec2<f32>, seed: u32) -> f32 {
    let fl = floor(x);
    let i = base + vec2<i32>(fl);
    let f = x - fl;
    let u = fade(f.x);
    let v = fade(f.y);
    let a = lerp1(lattice_value(hash3(i.x, i.y, 0, seed)), lattice_value(hash3(i.x + 1, i.y, 0, seed)), u);
    let b = lerp1(lattice_value(hash3(i.x, i.y + 1, 0, seed)), lattice_value(hash3(i.x + 1, i.y + 1, 0, seed)), u);
    return lerp1(a, b, v);
}

// `noise::octave_count`.
fn octave_count(k0: i32, octaves: u32, kmax: i32) -> u32 {
    let room = u32(max(min(kmax, MAX_FREQ_LOG2) - k0 + 1, 0));
    return min(octaves, room);
}

fn fbm3(anchor: vec3<i32>, p: vec3<f32>, k0: i32, count: u32, seed: u32) -> f32 {
    var sum = 0.0;
    for (var o = 0u; o < count; o = o + 1u) {
        let k = k0 + i32(o);
        let f = exp2i(k);
        let base = vec3<i32>(anchor_lattice(anchor.x, k), anchor_lattice(anchor.y, k), anchor_lattice(anchor.z, k));
        sum = sum + exp2i(-i32(o)) * value3(base, p * f, seed + o);
    }
    return sum;
}

fn fbm2(anchor: vec2<i32>, p: vec2<f32>, k0: i32, count: u32, seed: u32) -> f32 {
    var sum = 0.0;
    for (var o = 0u; o < count; o = o + 1u) {
        let k = k0 + i32(o);
        let f = exp2i(k);
        let base = vec2<i32>(anchor_lattice(anchor.x, k), anchor_lattice(anchor.y, k));
        sum = sum + exp2i(-i32(o)) * value2(base, p * f, seed + o);
    }
    return sum;
}

fn dot3(a: vec3<f32>, b: vec3<f32>) -> f32 {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

fn cross3(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

fn normalize_or(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let l2 = dot3(v, v);
    if (l2 < 1e-20) {
        return fallback;
    }
    let inv = 1.0 / sqrt(l2);
    return v * inv;
}

fn triplanar(n: vec3<f32>) -> vec3<f32> {
    let c2 = n * n;
    let a = c2 * c2;
    let inv = 1.0 / (a.x + a.y + a.z);
    return a * inv;
}

// Projection plane `axis` of a point: (y, z), (z, x), (x, y).
fn plane_f(v: vec3<f32>, axis: u32) -> vec2<f32> {
    if (axis == 0u) {
        return vec2<f32>(v.y, v.z);
    }
    if (axis == 1u) {
        return vec2<f32>(v.z, v.x);
    }
    return vec2<f32>(v.x, v.y);
}

fn plane_i(v: vec3<i32>, axis: u32) -> vec2<i32> {
    if (axis == 0u) {
        return vec2<i32>(v.y, v.z);
    }
    if (axis == 1u) {
        return vec2<i32>(v.z, v.x);
    }
    return vec2<i32>(v.x, v.y);
}

fn pattern(m: u32, anchor: vec3<i32>, q: vec3<f32>, axis: u32, kmax: i32) -> f32 {
    let mat = mats[m];
    let count = octave_count(mat.freq_log2, mat.octaves, kmax);
    let seed = mat.seed + 256u * axis;
    let v = fbm2(plane_i(anchor, axis), plane_f(q, axis), mat.freq_log2, count, seed);
    return clamp(0.5 + 0.5 * v, 0.0, 1.0);
}

// The interpolated texel inputs (see `bake::interpolate`).
var<private> pt_p: vec3<f32>;
var<private> pt_n: vec3<f32>;
var<private> pt_amp: f32;
var<private> pt_ids: array<u32, 4>;
var<private> pt_w: array<f32, 4>;
var<private> pt_count: u32;

fn material_index(id: u32) -> u32 {
    return min(id, params.materials - 1u);
}

fn interpolate(face: Face, u: f32, v: f32) {
    let n = face.n;
    let last = f32(n - 2u);
    let gu = u * f32(n - 1u);
    let gv = v * f32(n - 1u);
    let cu = min(floor(gu), last);
    let cv = min(floor(gv), last);
    let fu = gu - cu;
    let fv = gv - cv;
    let base = face.first + u32(cv) * n + u32(cu);
    var idx = array<u32, 4>(base, base + 1u, base + n, base + n + 1u);
    var w = array<f32, 4>((1.0 - fu) * (1.0 - fv), fu * (1.0 - fv), (1.0 - fu) * fv, fu * fv);
    var p = vec3<f32>(0.0);
    var nn = vec3<f32>(0.0);
    var amp = 0.0;
    pt_count = 0u;
    for (var k = 0u; k < 4u; k = k + 1u) {
        let s = samples[idx[k]];
        // Written as the CPU's left-to-right sums `w0·a + w1·b + w2·c + w3·d`.
        p = p + vec3<f32>(w[k] * s.px, w[k] * s.py, w[k] * s.pz);
        nn = nn + vec3<f32>(w[k] * s.nx, w[k] * s.ny, w[k] * s.nz);
        amp = amp + w[k] * s.noise_m;
        let id = material_index(s.material);
        var found = false;
        for (var m = 0u; m < pt_count; m = m + 1u) {
            if (pt_ids[m] == id) {
                pt_w[m] = pt_w[m] + w[k];
                found = true;
            }
        }
        if (!found) {
            pt_ids[pt_count] = id;
            pt_w[pt_count] = w[k];
            pt_count = pt_count + 1u;
        }
    }
    pt_p = p;
    pt_n = normalize_or(nn, vec3<f32>(0.0, 1.0, 0.0));
    pt_amp = amp;
}

fn displacement(anchor: vec3<i32>, q: vec3<f32>, wg: vec3<f32>, kmax: i32) -> f32 {
    let count = octave_count(params.noise_k0, params.noise_octaves, kmax);
    var d = pt_amp * fbm3(anchor, q, params.noise_k0, count, params.noise_seed);
    for (var m = 0u; m < pt_count; m = m + 1u) {
        let id = pt_ids[m];
        let relief = mats[id].relief_m;
        var r = 0.0;
        r = r + wg.x * (pattern(id, anchor, q, 0u, kmax) - 0.5);
        r = r + wg.y * (pattern(id, anchor, q, 1u, kmax) - 0.5);
        r = r + wg.z * (pattern(id, anchor, q, 2u, kmax) - 0.5);
        d = d + pt_w[m] * (relief * r);
    }
    return d;
}

fn unorm8(x: f32) -> u32 {
    return u32(floor(clamp(x, 0.0, 1.0) * 255.0 + 0.5));
}

fn snorm8(x: f32) -> u32 {
    return u32(i32(floor(clamp(x, -1.0, 1.0) * 127.0 + 0.5))) & 0xffu;
}

@compute @workgroup_size(64)
fn bake(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let idx = gid.x + gid.y * groups.x * 64u;
    let per = params.res * params.res;
    if (idx >= params.faces * per) {
        return;
    }
    let f = idx / per;
    let rem = idx - f * per;
    let j = rem / params.res;
    let i = rem - j * params.res;
    let face = faces[f];
    let r = f32(params.res);
    interpolate(face, (f32(i) + 0.5) / r, (f32(j) + 0.5) / r);
    let n = pt_n;
    var helper = vec3<f32>(1.0, 0.0, 0.0);
    if (abs(n.y) < 0.9) {
        helper = vec3<f32>(0.0, 1.0, 0.0);
    }
    let t1 = normalize_or(cross3(helper, n), vec3<f32>(1.0, 0.0, 0.0));
    let t2 = cross3(n, t1);
    let wg = triplanar(n);
    let a = vec3<i32>(face.ax, face.ay, face.az);
    let kmax = face.kmax;
    let step = face.step;
    let d0 = displacement(a, pt_p, wg, kmax);
    let d1 = displacement(a, pt_p + step * t1, wg, kmax);
    let d2 = displacement(a, pt_p + step * t2, wg, kmax);
    let inv = 1.0 / step;
    let g1 = (d1 - d0) * inv;
    let g2 = (d2 - d0) * inv;
    let nd = normalize_or(n - g1 * t1 - g2 * t2, n);
    let wd = triplanar(nd);
    var albedo = vec3<f32>(0.0);
    var rough = 0.0;
    var dominant = 0u;
    for (var m = 0u; m < pt_count; m = m + 1u) {
        let id = pt_ids[m];
        let mat = mats[id];
        let base = vec3<f32>(mat.base_r, mat.base_g, mat.base_b);
        let tint = vec3<f32>(mat.tint_r, mat.tint_g, mat.tint_b);
        for (var axis = 0u; axis < 3u; axis = axis + 1u) {
            let t = pattern(id, a, pt_p, axis, kmax);
            let k = pt_w[m] * wd[axis];
            albedo = albedo + k * (base + (tint - base) * t);
            rough = rough + k * (mat.rough0 + (mat.rough1 - mat.rough0) * t);
        }
        let best = pt_w[dominant];
        if (pt_w[m] > best || (pt_w[m] == best && id < pt_ids[dominant])) {
            dominant = m;
        }
    }
    let o = 3u * idx;
    out[o] = unorm8(albedo.x) | (unorm8(albedo.y) << 8u) | (unorm8(albedo.z) << 16u) | (unorm8(rough) << 24u);
    out[o + 1u] = snorm8(nd.x) | (snorm8(nd.y) << 8u) | (snorm8(nd.z) << 16u) | ((pt_ids[dominant] & 0xffu) << 24u);
    out[o + 2u] = bitcast<u32>(d0);
}
