// WGSL twin of `volume::pipeline::diffuse::sweep` (Becher §4.3): one Jacobi sweep of the
// discretised diffusion
//
//   N' = N + 1/6 (c_E (N_E − N) + c_W (N_W − N) + c_U (N_U − N) + c_D (N_D − N) + c_N (N_N − N) + c_S (N_S − N))
//
// over up to four channels packed in a vec4 per sample, with homogeneous Neumann borders (a
// missing neighbour is the sample itself), constrained samples (`fixed != 0`) kept, and either
// c ≡ 1 (`mode == 0`, Laplace) or Perona–Malik c = 1 / (1 + q²), q = |N_a − N_b|² · (1/4k)
// (`mode == 1`, the three channels xyz, the update `fma(acc, 1/6, v)`). The operations are the
// CPU's, in the CPU's order.
//
// `Params` is `gpu::volume::GpuDiffuseParams` on the CPU, field for field.

struct Params {
    nx: u32,
    ny: u32,
    nz: u32,
    mode: u32,
    // 0.25 / k.
    qk: f32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

@group(0) @binding(0) var<uniform> p: Params;
@group(0) @binding(1) var<storage, read> src: array<vec4<f32>>;
@group(0) @binding(2) var<storage, read> fixed: array<u32>;
@group(0) @binding(3) var<storage, read_write> dst: array<vec4<f32>>;

// As the CPU's `coefficient`: |d|² and 1 + q² each with fused multiply-adds.
fn coef(d: vec4<f32>) -> f32 {
    let q = fma(d.z, d.z, fma(d.y, d.y, d.x * d.x)) * p.qk;
    return 1.0 / fma(q, q, 1.0);
}

@compute @workgroup_size(64)
fn sweep(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let i = gid.x + gid.y * groups.x * 64u;
    let n = p.nx * p.ny * p.nz;
    if (i >= n) {
        return;
    }
    let x = i % p.nx;
    let y = (i / p.nx) % p.ny;
    let z = i / (p.nx * p.ny);
    let sl = p.nx * p.ny;
    let v = src[i];
    if (fixed[i] != 0u) {
        dst[i] = v;
        return;
    }
    var e = v;
    var w = v;
    var u = v;
    var d = v;
    var no = v;
    var so = v;
    if (x + 1u < p.nx) { e = src[i + 1u]; }
    if (x > 0u) { w = src[i - 1u]; }
    if (y + 1u < p.ny) { u = src[i + p.nx]; }
    if (y > 0u) { d = src[i - p.nx]; }
    if (z + 1u < p.nz) { no = src[i + sl]; }
    if (z > 0u) { so = src[i - sl]; }
    if (p.mode == 1u) {
        let ce = coef(e - v);
        let cw = coef(w - v);
        let cu = coef(u - v);
        let cd = coef(d - v);
        let cn = coef(no - v);
        let cs = coef(so - v);
        let acc = ce * (e - v) + cw * (w - v) + cu * (u - v) + cd * (d - v) + cn * (no - v) + cs * (so - v);
        dst[i] = fma(acc, vec4<f32>(1.0 / 6.0), v);
    } else {
        let acc = (e - v) + (w - v) + (u - v) + (d - v) + (no - v) + (so - v);
        dst[i] = v + acc * (1.0 / 6.0);
    }
}
