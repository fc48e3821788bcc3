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
// `Params`, `Face`, `Sample`, `Mat` and `Decal` are `gpu::ptex`'s `GpuPtexParams`, `GpuFace`,
// `GpuSample`, `GpuMaterial` and `GpuDecal`, field for field. Image materials and decals sample
// the packed images of `tex` as `ptex::image::Image::sample` does (bytes times 1/255, bilinear,
// wrapped or clamped), at the mip level of `ptex::image::mip_level`. Output: three words per texel (albedo and roughness bytes,
// normal and material bytes, the displacement's bits), texel `f·res² + j·res + i`.

struct Params {
    res: u32,
    faces: u32,
    noise_k0: i32,
    noise_octaves: u32,
    noise_seed: u32,
    materials: u32,
    decals: u32,
    // 1 where the samples carry texel inputs (`surface`), weighed per texel by the thresholds below.
    surface: u32,
    blend_m: f32,
    beach_m: f32,
    rock_lo: f32,
    rock_hi: f32,
    // `TexelRule::alpine_fraction` (0: no alpine zone), then padding to 16 bytes.
    alpine: f32,
    pad0: u32,
    pad1: u32,
    pad2: u32,
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
    // Word offsets of the albedo, roughness and height images' headers in `tex` (NONE: none).
    tex_albedo: u32,
    tex_rough: u32,
    tex_height: u32,
    repeat_log2: i32,
    // Word offset of the normal map's header in `tex` (NONE: none).
    tex_normal: u32,
}

// `gpu::ptex::GpuDecal`; `ptex::decal::Decal`.
struct Decal {
    ax: i32,
    az: i32,
    ox: f32,
    oz: f32,
    inv_w: f32,
    inv_l: f32,
    cos_t: f32,
    sin_t: f32,
    opacity: f32,
    rough: f32,
    has_rough: u32,
    image: u32,
    mask: u32,
    density_log2: i32,
    mask_density_log2: i32,
    // 1: fades with the facing (`decal::facing_weight`), else 0.
    facing: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> faces: array<Face>;
@group(0) @binding(2) var<storage, read> samples: array<Sample>;
@group(0) @binding(3) var<storage, read> mats: array<Mat>;
@group(0) @binding(4) var<storage, read_write> out: array<u32>;
// Images: per image a header `[w, h, levels, offset of level 0, …]` (word offsets into this
// array) and its levels' texels, one packed RGBA8 word each, rows top to bottom.
@group(0) @binding(5) var<storage, read> tex: array<u32>;
@group(0) @binding(6) var<storage, read> decals: array<Decal>;
// Texel inputs (`terrain::texture::surface_inputs`), two vec4 per sample: height above the sea,
// height above the snow line, then the ground shares of the six proto-texturing materials.
@group(0) @binding(7) var<storage, read> surface: array<vec4<f32>>;

const NONE: u32 = 0xffffffffu;

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

// `ptex::image::mip_level`.
fn mip_level(density_log2: i32, kmax: i32, levels: u32) -> u32 {
    return u32(clamp(density_log2 - (kmax + 1), 0, i32(levels) - 1));
}

// Channel `c` of a packed texel, its byte as a float.
fn channel(word: u32, c: u32) -> f32 {
    return f32((word >> (8u * c)) & 0xffu);
}

fn texel_word(off: u32, w: u32, h: u32, x: i32, y: i32, wrap: bool) -> u32 {
    var xi: i32;
    var yi: i32;
    if (wrap) {
        xi = ((x % i32(w)) + i32(w)) % i32(w);
        yi = ((y % i32(h)) + i32(h)) % i32(h);
    } else {
        xi = clamp(x, 0, i32(w) - 1);
        yi = clamp(y, 0, i32(h) - 1);
    }
    return tex[off + u32(yi) * w + u32(xi)];
}

// `ptex::image::Image::sample`: bilinear at (u, v) of level `level` of the image at header `hd`.
fn sample_image(hd: u32, level: u32, u: f32, v: f32, wrap: bool) -> vec4<f32> {
    let l = min(level, tex[hd + 2u] - 1u);
    let w = max(tex[hd] >> l, 1u);
    let h = max(tex[hd + 1u] >> l, 1u);
    let off = tex[hd + 3u + l];
    let x = u * f32(w) - 0.5;
    let y = v * f32(h) - 0.5;
    let x0 = floor(x);
    let y0 = floor(y);
    let fx = x - x0;
    let fy = y - y0;
    let xi = i32(x0);
    let yi = i32(y0);
    let t00 = texel_word(off, w, h, xi, yi, wrap);
    let t10 = texel_word(off, w, h, xi + 1, yi, wrap);
    let t01 = texel_word(off, w, h, xi, yi + 1, wrap);
    let t11 = texel_word(off, w, h, xi + 1, yi + 1, wrap);
    var res = vec4<f32>(0.0);
    for (var c = 0u; c < 4u; c = c + 1u) {
        let top = channel(t00, c) + (channel(t10, c) - channel(t00, c)) * fx;
        let bottom = channel(t01, c) + (channel(t11, c) - channel(t01, c)) * fx;
        res[c] = (top + (bottom - top) * fy) * (1.0 / 255.0);
    }
    return res;
}

// `bake::image_sample`: an image material's image tiled on plane `axis`.
fn material_image(hd: u32, repeat_log2: i32, q: vec3<f32>, axis: u32, kmax: i32) -> vec4<f32> {
    let scale = exp2i(-repeat_log2);
    let x = plane_f(q, axis) * scale;
    let a = x - floor(x);
    let side = i32(countTrailingZeros(max(tex[hd], tex[hd + 1u])));
    let level = mip_level(side - repeat_log2, kmax, tex[hd + 2u]);
    return sample_image(hd, level, a.x, a.y, true);
}

// `bake::relief_t`: the height image's R channel, or the pattern.
fn relief_t(m: u32, anchor: vec3<i32>, q: vec3<f32>, axis: u32, kmax: i32) -> f32 {
    let mat = mats[m];
    if (mat.tex_height != NONE) {
        return material_image(mat.tex_height, mat.repeat_log2, q, axis, kmax).x;
    }
    return pattern(m, anchor, q, axis, kmax);
}

// `ptex::decal::apply`: the decals over `albedo` and `rough` (private, written back).
var<private> dec_albedo: vec3<f32>;
var<private> dec_rough: f32;

fn apply_decals(anchor: vec3<i32>, p: vec3<f32>, ny: f32, kmax: i32) {
    for (var k = 0u; k < params.decals; k = k + 1u) {
        let d = decals[k];
        let cx = f32(d.ax - anchor.x) * 256.0 + d.ox;
        let cz = f32(d.az - anchor.z) * 256.0 + d.oz;
        let dx = p.x - cx;
        let dz = p.z - cz;
        let s = dx * d.cos_t + dz * d.sin_t;
        let t = dz * d.cos_t - dx * d.sin_t;
        let u = s * d.inv_w + 0.5;
        let v = t * d.inv_l + 0.5;
        if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) {
            continue;
        }
        let level = mip_level(d.density_log2, kmax, tex[d.image + 2u]);
        let c = sample_image(d.image, level, u, v, false);
        var mask = c.w;
        if (d.mask != NONE) {
            let mask_level = mip_level(d.mask_density_log2, kmax, tex[d.mask + 2u]);
            mask = sample_image(d.mask, mask_level, u, v, false).x;
        }
        var a = d.opacity * mask;
        if (d.facing != 0u) {
            a = a * smoothstep_edges(DECAL_FACING_FROM, DECAL_FACING_FULL, ny);
        }
        dec_albedo = vec3<f32>(
            dec_albedo.x + (c.x - dec_albedo.x) * a,
            dec_albedo.y + (c.y - dec_albedo.y) * a,
            dec_albedo.z + (c.z - dec_albedo.z) * a,
        );
        if (d.has_rough != 0u) {
            dec_rough = dec_rough + (d.rough - dec_rough) * a;
        }
    }
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

// Adds weight `w` of material index `id` to the texel's slots: to its slot if it has one (equal
// ids merged), else to a new slot.
fn add_slot(id: u32, w: f32) {
    for (var m = 0u; m < pt_count; m = m + 1u) {
        if (pt_ids[m] == id) {
            pt_w[m] = pt_w[m] + w;
            return;
        }
    }
    pt_ids[pt_count] = id;
    pt_w[pt_count] = w;
    pt_count = pt_count + 1u;
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
        add_slot(material_index(s.material), w[k]);
    }
    pt_p = p;
    pt_n = normalize_or(nn, vec3<f32>(0.0, 1.0, 0.0));
    pt_amp = amp;
    if (params.surface == 1u) {
        var s = array<f32, 8>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        for (var k = 0u; k < 4u; k = k + 1u) {
            let lo = surface[2u * idx[k]];
            let hi = surface[2u * idx[k] + 1u];
            s[0] = s[0] + w[k] * lo.x;
            s[1] = s[1] + w[k] * lo.y;
            s[2] = s[2] + w[k] * lo.z;
            s[3] = s[3] + w[k] * lo.w;
            s[4] = s[4] + w[k] * hi.x;
            s[5] = s[5] + w[k] * hi.y;
            s[6] = s[6] + w[k] * hi.z;
            s[7] = s[7] + w[k] * hi.w;
        }
        surface_slots(surface_weights(s, pt_n.y));
    }
}

fn smoothstep_inv(e0: f32, inv_width: f32, x: f32) -> f32 {
    let t = clamp((x - e0) * inv_width, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

fn smoothstep_edges(e0: f32, e1: f32, x: f32) -> f32 {
    let t = clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Twin of `terrain::texture::texel_weights`: the weight of each proto-texturing material (seabed,
// sand, grass, dirt, rock, snow) at a texel with inputs `s` and normal y component `ny`.
fn surface_weights(s: array<f32, 8>, ny: f32) -> array<f32, 6> {
    let blend = params.blend_m;
    let inv_blend = 1.0 / blend;
    let above = s[0];
    let wet = 1.0 - smoothstep_inv(-blend * 0.5, 2.0 * inv_blend, above);
    let rock = smoothstep_edges(params.rock_lo, params.rock_hi, ny) * (1.0 - wet);
    let snow = smoothstep_inv(-blend, 0.5 * inv_blend, s[1]) * (1.0 - rock) * (1.0 - wet);
    let beach = (1.0 - smoothstep_inv(params.beach_m, inv_blend, above)) * (1.0 - wet) * (1.0 - rock);
    let rest = (1.0 - wet) * (1.0 - rock) * (1.0 - snow) * (1.0 - beach);
    let alpine = alpine_share(params.alpine, above - s[1], s[1]);
    let ground = rest * (1.0 - alpine);
    var out = array<f32, 6>(wet, beach, 0.0, 0.0, rock + rest * alpine, snow);
    for (var m = 0u; m < 6u; m = m + 1u) {
        out[m] = out[m] + s[2u + m] * ground;
    }
    return out;
}

// Twin of `terrain::texture::alpine_share`: the alpine zone's share of the ground at
// `above_line` metres above a snow line `line_above_sea` metres above the sea.
fn alpine_share(fraction: f32, line_above_sea: f32, above_line: f32) -> f32 {
    let band = fraction * max(line_above_sea, 0.0);
    if band > 0.0 {
        return smoothstep_inv(-band, 1.0 / (0.75 * band), above_line);
    }
    return 0.0;
}

// Twin of `ptex::bake::surface_slots`: the materials of weight at least MIN_SURFACE_WEIGHT in id
// order, at most four (the lightest left out, the higher id first on a tie), divided by their sum
// and merged by material index; the samples' materials stay where none has weight.
const MIN_SURFACE_WEIGHT: f32 = 1.0 / 512.0;
// `ptex::decal::FACING_FROM` and `FACING_FULL`.
const DECAL_FACING_FROM: f32 = 0.25;
const DECAL_FACING_FULL: f32 = 0.5;

fn surface_slots(weights: array<f32, 6>) {
    var ids = array<u32, 6>(0u, 0u, 0u, 0u, 0u, 0u);
    var ws = array<f32, 6>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    var count = 0u;
    for (var id = 0u; id < 6u; id = id + 1u) {
        if (weights[id] >= MIN_SURFACE_WEIGHT) {
            ids[count] = id;
            ws[count] = weights[id];
            count = count + 1u;
        }
    }
    while (count > 4u) {
        var lightest = 0u;
        for (var k = 1u; k < count; k = k + 1u) {
            if (ws[k] <= ws[lightest]) {
                lightest = k;
            }
        }
        for (var k = lightest; k + 1u < count; k = k + 1u) {
            ids[k] = ids[k + 1u];
            ws[k] = ws[k + 1u];
        }
        count = count - 1u;
    }
    if (count == 0u) {
        return;
    }
    var total = 0.0;
    for (var k = 0u; k < count; k = k + 1u) {
        total = total + ws[k];
    }
    pt_count = 0u;
    for (var k = 0u; k < count; k = k + 1u) {
        add_slot(material_index(ids[k]), ws[k] / total);
    }
}

fn displacement(anchor: vec3<i32>, q: vec3<f32>, wg: vec3<f32>, kmax: i32) -> f32 {
    let count = octave_count(params.noise_k0, params.noise_octaves, kmax);
    var d = pt_amp * fbm3(anchor, q, params.noise_k0, count, params.noise_seed);
    for (var m = 0u; m < pt_count; m = m + 1u) {
        let id = pt_ids[m];
        let relief = mats[id].relief_m;
        var r = 0.0;
        r = r + wg.x * (relief_t(id, anchor, q, 0u, kmax) - 0.5);
        r = r + wg.y * (relief_t(id, anchor, q, 1u, kmax) - 0.5);
        r = r + wg.z * (relief_t(id, anchor, q, 2u, kmax) - 0.5);
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
            let k = pt_w[m] * wd[axis];
            if (mat.tex_albedo == NONE) {
                let t = pattern(id, a, pt_p, axis, kmax);
                albedo = albedo + k * (base + (tint - base) * t);
                rough = rough + k * (mat.rough0 + (mat.rough1 - mat.rough0) * t);
                continue;
            }
            let rgb = material_image(mat.tex_albedo, mat.repeat_log2, pt_p, axis, kmax);
            albedo = albedo + k * rgb.xyz;
            var t: f32;
            if (mat.tex_rough != NONE) {
                t = material_image(mat.tex_rough, mat.repeat_log2, pt_p, axis, kmax).x;
            } else {
                t = pattern(id, a, pt_p, axis, kmax);
            }
            rough = rough + k * (mat.rough0 + (mat.rough1 - mat.rough0) * t);
        }
        let best = pt_w[dominant];
        if (pt_w[m] > best || (pt_w[m] == best && id < pt_ids[dominant])) {
            dominant = m;
        }
    }
    dec_albedo = albedo;
    dec_rough = rough;
    apply_decals(a, pt_p, nd.y, kmax);
    albedo = dec_albedo;
    rough = dec_rough;
    // `bake::normal_maps`: each material's normal map tilts `nd` on each plane (a whiteout
    // blend), weighted as the blend is.
    var tilt = vec3<f32>(0.0);
    var mapped = false;
    for (var m = 0u; m < pt_count; m = m + 1u) {
        let mat = mats[pt_ids[m]];
        if (mat.tex_normal == NONE) {
            continue;
        }
        mapped = true;
        for (var axis = 0u; axis < 3u; axis = axis + 1u) {
            let k = pt_w[m] * wd[axis];
            let s = material_image(mat.tex_normal, mat.repeat_log2, pt_p, axis, kmax);
            let a1 = (axis + 1u) % 3u;
            let a2 = (axis + 2u) % 3u;
            var v = vec3<f32>(0.0);
            v[a1] = (2.0 * s.x - 1.0) + nd[a1];
            v[a2] = (2.0 * s.y - 1.0) + nd[a2];
            v[axis] = abs(2.0 * s.z - 1.0) * nd[axis];
            tilt = tilt + k * (normalize_or(v, nd) - nd);
        }
    }
    var nm = nd;
    if (mapped) {
        nm = normalize_or(nd + tilt, nd);
    }
    let o = 3u * idx;
    out[o] = unorm8(albedo.x) | (unorm8(albedo.y) << 8u) | (unorm8(albedo.z) << 16u) | (unorm8(rough) << 24u);
    out[o + 1u] = snorm8(nm.x) | (snorm8(nm.y) << 8u) | (snorm8(nm.z) << 16u) | ((pt_ids[dominant] & 0xffu) << 24u);
    out[o + 2u] = bitcast<u32>(d0);
}
