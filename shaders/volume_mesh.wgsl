// Surface-nets meshing stage (Becher et al. §4.6), the WGSL twin of
// `strata::volume::mesh::nets::emit`: one invocation per cell computes the cell's corner sign
// mask, its vertex offset (mean of the zero crossings of its sign-changing edges, in cell units),
// the normal (gradient of the trilinear interpolant at the vertex) and which of the three grid
// edges leaving its minimum corner emit a quad (and with which sign). The host compacts the cells
// in index order into the same vertex and quad lists as the CPU and builds the Ptex adjacency.
//
// Grid convention: sample (x, y, z) at x + nx·(y + ny·z); cell c = x + (nx−1)·(y + (ny−1)·z).

struct MeshParams {
    nx: u32,
    ny: u32,
    nz: u32,
    spacing_m: f32,
    qmin_x: u32,
    qmin_y: u32,
    qmin_z: u32,
    _pad0: u32,
    qmax_x: u32,
    qmax_y: u32,
    qmax_z: u32,
    _pad1: u32,
};

@group(0) @binding(0) var<uniform> params: MeshParams;
@group(0) @binding(1) var<storage, read> sdf: array<f32>;
// Per cell: offset xyz (cell units) and w = 1 when the cell has a vertex.
@group(0) @binding(2) var<storage, read_write> vertex_out: array<vec4<f32>>;
// Per cell: unit normal xyz.
@group(0) @binding(3) var<storage, read_write> normal_out: array<vec4<f32>>;
// Per cell: bits 0–7 corner mask (bit i = corner i solid); bit 8 + 2a = the edge along axis a
// emits a quad, bit 9 + 2a = its lower sample is solid.
@group(0) @binding(4) var<storage, read_write> flags_out: array<u32>;

fn corner(i: u32) -> vec3<u32> {
    return vec3<u32>(i & 1u, (i >> 1u) & 1u, (i >> 2u) & 1u);
}

@compute @workgroup_size(64)
fn mesh_cells(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let cnx = params.nx - 1u;
    let cny = params.ny - 1u;
    let cnz = params.nz - 1u;
    let c = gid.x + gid.y * groups.x * 64u;
    if (c >= cnx * cny * cnz) {
        return;
    }
    let cx = c % cnx;
    let cy = (c / cnx) % cny;
    let cz = c / (cnx * cny);
    let sy = params.nx;
    let sz = params.nx * params.ny;
    let base = cx + sy * cy + sz * cz;
    var v: array<f32, 8>;
    var mask = 0u;
    for (var i = 0u; i < 8u; i++) {
        let k = corner(i);
        v[i] = sdf[base + k.x + sy * k.y + sz * k.z];
        if (v[i] < 0.0) {
            mask |= 1u << i;
        }
    }
    if (mask == 0u || mask == 255u) {
        vertex_out[c] = vec4<f32>(0.0);
        normal_out[c] = vec4<f32>(0.0);
        flags_out[c] = mask;
        return;
    }
    // Vertex: mean of the crossings, edges in the CPU's order (axis a, offsets o1, o2 along
    // (a+1)%3, (a+2)%3).
    var sum = vec3<f32>(0.0);
    var n = 0u;
    for (var a = 0u; a < 3u; a++) {
        let b = (a + 1u) % 3u;
        let cc = (a + 2u) % 3u;
        for (var o = 0u; o < 4u; o++) {
            let lo = ((o & 1u) << b) | (((o >> 1u) & 1u) << cc);
            let hi = lo | (1u << a);
            if ((((mask >> lo) ^ (mask >> hi)) & 1u) == 0u) {
                continue;
            }
            let t = v[lo] / (v[lo] - v[hi]);
            let ca = vec3<f32>(corner(lo));
            let cb = vec3<f32>(corner(hi));
            sum += ca + t * (cb - ca);
            n += 1u;
        }
    }
    let inv = 1.0 / f32(n);
    let f = clamp(sum * inv, vec3<f32>(0.0), vec3<f32>(1.0));
    let g = vec3<f32>(1.0) - f;
    let dx = g.y * g.z * (v[1] - v[0]) + f.y * g.z * (v[3] - v[2]) + g.y * f.z * (v[5] - v[4]) + f.y * f.z * (v[7] - v[6]);
    let dy = g.x * g.z * (v[2] - v[0]) + f.x * g.z * (v[3] - v[1]) + g.x * f.z * (v[6] - v[4]) + f.x * f.z * (v[7] - v[5]);
    let dz = g.x * g.y * (v[4] - v[0]) + f.x * g.y * (v[5] - v[1]) + g.x * f.y * (v[6] - v[2]) + f.x * f.y * (v[7] - v[3]);
    let len = sqrt(dx * dx + dy * dy + dz * dz);
    var nrm = vec3<f32>(0.0, 1.0, 0.0);
    if (len > 0.0) {
        nrm = vec3<f32>(dx, dy, dz) / len;
    }
    vertex_out[c] = vec4<f32>(f, 1.0);
    normal_out[c] = vec4<f32>(nrm, 0.0);
    // Quads of the edges leaving corner 0 (sample p = (cx, cy, cz)), as the CPU emits them.
    var flags = mask;
    let p = vec3<u32>(cx, cy, cz);
    let qmin = vec3<u32>(params.qmin_x, params.qmin_y, params.qmin_z);
    let qmax = vec3<u32>(params.qmax_x, params.qmax_y, params.qmax_z);
    if (all(p >= qmin) && all(p < qmax)) {
        let solid0 = (mask & 1u) != 0u;
        let sbit = select(0u, 1u, solid0);
        let pos = vec3<bool>(cy > 0u && cz > 0u, cz > 0u && cx > 0u, cx > 0u && cy > 0u);
        for (var a = 0u; a < 3u; a++) {
            let other = ((mask >> (1u << a)) & 1u) != 0u;
            if (pos[a] && other != solid0) {
                flags |= (1u | (sbit << 1u)) << (8u + 2u * a);
            }
        }
    }
    flags_out[c] = flags;
}
