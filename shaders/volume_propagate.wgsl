// WGSL twin of `volume::pipeline::propagate::propagate_surface` (Becher §4.5): one dispatch per
// wavefront layer. In the dispatch for layer `L`, every sample not yet set (`layer == UNSET`)
// with a neighbour of a lower layer takes
//
//   S_i = min over neighbours x with layer(x) < L of  S_x + ((i − x) · (N_i + N_x) / 2)
//
// (the offset is ±spacing along one axis) and `layer = L`: each value is set once, from values
// set in earlier dispatches only, exactly the CPU's breadth-first order. Layers are atomics
// because a neighbour may be set in the same dispatch (it then reads as L, which is not < L).
//
// `Params` is `gpu::volume::GpuPropagateParams` on the CPU, field for field.

struct Params {
    nx: u32,
    ny: u32,
    nz: u32,
    layer: u32,
    spacing: f32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

const UNSET: u32 = 0xffffffffu;

@group(0) @binding(0) var<uniform> p: Params;
@group(0) @binding(1) var<storage, read> normal: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read_write> layer: array<atomic<u32>>;
@group(0) @binding(3) var<storage, read_write> s: array<f32>;

@compute @workgroup_size(64)
fn propagate(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = gid.x + gid.y * groups.x * 64u;
    let n = p.nx * p.ny * p.nz;
    if (i >= n) {
        return;
    }
    if (atomicLoad(&layer[i]) != UNSET) {
        return;
    }
    let x = i % p.nx;
    let y = (i / p.nx) % p.ny;
    let z = i / (p.nx * p.ny);
    let sl = p.nx * p.ny;
    let ni = normal[i];
    let h = p.spacing;
    var best = 0.0;
    var found = false;
    // E, W, U, D, N, S as on the CPU; `off` is the sign of (i − x) along the axis times h.
    for (var k = 0u; k < 6u; k = k + 1u) {
        var j = i;
        var ok = false;
        var off = 0.0;
        var a = 0u;
        switch k {
            case 0u: { ok = x + 1u < p.nx; j = i + 1u; off = -h; a = 0u; }
            case 1u: { ok = x > 0u; j = i - 1u; off = h; a = 0u; }
            case 2u: { ok = y + 1u < p.ny; j = i + p.nx; off = -h; a = 1u; }
            case 3u: { ok = y > 0u; j = i - p.nx; off = h; a = 1u; }
            case 4u: { ok = z + 1u < p.nz; j = i + sl; off = -h; a = 2u; }
            default: { ok = z > 0u; j = i - sl; off = h; a = 2u; }
        }
        if (!ok) {
            continue;
        }
        if (atomicLoad(&layer[j]) >= p.layer) {
            continue;
        }
        let nj = normal[j];
        let v = s[j] + off * ((ni[a] + nj[a]) * 0.5);
        if (!found || v < best) {
            best = v;
        }
        found = true;
    }
    if (found) {
        s[i] = best;
        atomicStore(&layer[i], p.layer);
    }
}
