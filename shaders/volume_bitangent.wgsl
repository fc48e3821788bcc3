// WGSL twin of `volume::pipeline::expand::smooth_bitangents` (Becher §5.1): the smooth, dense,
// sign-free bitangent field.
//
// `seed` normalises the voxelized bitangents: a non-zero one is `Ω_B` (layer 0, fixed), the rest
// is unset. Then one `fill` dispatch per wavefront layer `L`: every unset sample with a neighbour
// of a lower layer folds those neighbours, in the fixed order −x, +x, −y, +y, −z, +z, with the
// sign-free pair-wise average `avg(a, b) = normalize(a + sign(a·b)·b)` (`avg(0, b) = b`), and
// takes layer `L`. Layers are atomics because a neighbour may be set in the same dispatch (it then
// reads as `L`, which is not below `L`), so every value is read only after its dispatch ended,
// exactly the CPU's breadth-first order. Finally `sweep` dispatches ping-pong Jacobi sweeps that
// re-average every filled sample with all six neighbours (`Ω_B` and unreached samples copied).
//
// The arithmetic is the CPU's, in its order: products and sums written out (no `dot`,
// `normalize` or `length` builtins, whose evaluation order is the implementation's).
//
// `Params` is `gpu::volume_bitangent::GpuBitangentParams` on the CPU, field for field.

struct Params {
    nx: u32,
    ny: u32,
    nz: u32,
    layer: u32,
}

const UNSET: u32 = 0xffffffffu;

@group(0) @binding(0) var<uniform> p: Params;
@group(0) @binding(1) var<storage, read_write> layer: array<atomic<u32>>;
@group(0) @binding(2) var<storage, read_write> src: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read_write> dst: array<vec4<f32>>;

fn dot3(a: vec3<f32>, b: vec3<f32>) -> f32 {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// `grid::normalize`: `a / |a|`, zero for a (near) zero vector.
fn unit(a: vec3<f32>) -> vec3<f32> {
    let l = sqrt(dot3(a, a));
    if (l > 1e-12) {
        let r = 1.0 / l;
        return vec3<f32>(a.x * r, a.y * r, a.z * r);
    }
    return vec3<f32>(0.0);
}

fn is_zero(a: vec3<f32>) -> bool {
    return a.x == 0.0 && a.y == 0.0 && a.z == 0.0;
}

// `expand::sign_free_average`.
fn avg(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    if (is_zero(a)) {
        return b;
    }
    if (is_zero(b)) {
        return a;
    }
    var s = 1.0;
    if (dot3(a, b) < 0.0) {
        s = -1.0;
    }
    let r = unit(vec3<f32>(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s));
    if (is_zero(r)) {
        return a;
    }
    return r;
}

fn index(gid: vec3<u32>, groups: vec3<u32>) -> u32 {
    return gid.x + gid.y * groups.x * 64u;
}

// The neighbour `k` (order −x, +x, −y, +y, −z, +z) of sample `i`, or `UNSET` outside the grid.
fn neighbour(i: u32, k: u32) -> u32 {
    let x = i % p.nx;
    let y = (i / p.nx) % p.ny;
    let z = i / (p.nx * p.ny);
    let sl = p.nx * p.ny;
    switch k {
        case 0u: { if (x > 0u) { return i - 1u; } }
        case 1u: { if (x + 1u < p.nx) { return i + 1u; } }
        case 2u: { if (y > 0u) { return i - p.nx; } }
        case 3u: { if (y + 1u < p.ny) { return i + p.nx; } }
        case 4u: { if (z > 0u) { return i - sl; } }
        default: { if (z + 1u < p.nz) { return i + sl; } }
    }
    return UNSET;
}

@compute @workgroup_size(64)
fn seed(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(gid, groups);
    if (i >= p.nx * p.ny * p.nz) {
        return;
    }
    let v = unit(src[i].xyz);
    src[i] = vec4<f32>(v, 0.0);
    if (is_zero(v)) {
        atomicStore(&layer[i], UNSET);
    } else {
        atomicStore(&layer[i], 0u);
    }
}

@compute @workgroup_size(64)
fn fill(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(gid, groups);
    if (i >= p.nx * p.ny * p.nz) {
        return;
    }
    if (atomicLoad(&layer[i]) != UNSET) {
        return;
    }
    var acc = vec3<f32>(0.0);
    var found = false;
    for (var k = 0u; k < 6u; k = k + 1u) {
        let j = neighbour(i, k);
        if (j == UNSET) {
            continue;
        }
        if (atomicLoad(&layer[j]) >= p.layer) {
            continue;
        }
        acc = avg(acc, src[j].xyz);
        found = true;
    }
    if (found) {
        src[i] = vec4<f32>(acc, 0.0);
        atomicStore(&layer[i], p.layer);
    }
}

@compute @workgroup_size(64)
fn sweep(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = index(gid, groups);
    if (i >= p.nx * p.ny * p.nz) {
        return;
    }
    let l = atomicLoad(&layer[i]);
    var acc = src[i].xyz;
    if (l != 0u && l != UNSET) {
        for (var k = 0u; k < 6u; k = k + 1u) {
            let j = neighbour(i, k);
            if (j != UNSET) {
                acc = avg(acc, src[j].xyz);
            }
        }
    }
    dst[i] = vec4<f32>(acc, 0.0);
}
