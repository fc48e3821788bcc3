// requires: common.wgsl
// preamble: strata::gpu::earth::constants_wgsl()
//
// WGSL twin of the river carve of `earth-1` (`terrain::earth::rivers::RiverJob::carve_one`, with
// `rivers::profile`): one invocation per sample of a field job, run after `earth.wgsl` has
// written the heights and before they are read back. Each sample looks up the bin of its
// position, lowers its height to the lowest of the valley profiles of the bin's river pieces,
// and removes at most CARVE_MAX_M.
//
// The river job itself (the drainage network, its pieces and their binning) is built on the CPU
// (`rivers::job_for`) and uploaded: `pieces` is `rivers::Piece` (twenty-two f32), `bin_start` and
// `bin_pieces` are the job's bins in CSR form, `lakes` the levels of its lake window, and
// `CarveParams` is `gpu::layout::GpuCarveParams`, field for field. Before the carve, the lake
// shores shape each height (`shore`, the twin of `RiverJob::shore`).
//
// Every operation mirrors the Rust in the same order, as in `earth.wgsl`: each product that can
// meet an addition passes the rounding barrier `rn`, `/` is `div_rn` and `sqrt` is `sqrt_rn`,
// and `f32::clamp` is written out as Rust evaluates it. CARVE_MAX_M and PIECE_LEN2_EPS come from
// the preamble the host generates from the Rust constants (`gpu::earth::constants_wgsl`).

struct CarveParams {
    // Output rectangle: lattice origin and size (those of the heights).
    gx0: i32,
    gz0: i32,
    w: u32,
    h: u32,
    // Vertex spacing in metres, and 0 (see `rn`).
    spacing: f32,
    rounding_key: u32,
    // Bin grid of the river job: west and north edges and side in metres, bins per row and
    // rows (both 0 for a job without bins).
    x0: f32,
    z0: f32,
    bin_m: f32,
    bins_w: u32,
    bins_h: u32,
    // Amplitude and stream seed of the walls' width noise (`RiverJob::wall_noise`, 0: none).
    wall_noise: f32,
    wall_seed: u32,
    // The lake window (`RiverJob::lakes`): node spacing in metres, first node column and row,
    // columns and rows (both 0 when no lake is near), whether the lakes have shaped shores
    // (`RiverJob::shores`, 0 or 1).
    node_spacing: f32,
    li0: i32,
    lk0: i32,
    lakes_w: u32,
    lakes_h: u32,
    shores: u32,
    // The shores' noise octaves and the warp's x and z (`RiverJob::shore_seeds`), the warp's
    // scale in metres and its noise's frequency in 1/m.
    shore_seed0: u32,
    shore_seed1: u32,
    shore_seed2: u32,
    shore_seed3: u32,
    shore_warp_m: f32,
    shore_warp_inv_m: f32,
    // Whether the carve keeps sills beside the lakes (`RiverJob::sills`, 0 or 1), and the
    // scales of the shoreline's two noise octaves (`RiverJob::shore_n`).
    sills: u32,
    shore_n1: f32,
    shore_n2: f32,
    // Whether the shores sink the ground inside a lake towards its nodes' heights
    // (`RiverJob::sink`, 0 or 1): the heights follow the levels in `lakes`.
    sink: u32,
}

// `rivers::Piece`: one piece of a river's centre line (a cubic offset from its chord with end
// slopes `sa` and `sb`, straight where both are zero) and its valley.
struct Piece {
    ax: f32,
    az: f32,
    bx: f32,
    bz: f32,
    wa: f32,
    wb: f32,
    half_width: f32,
    depth: f32,
    valley: f32,
    wet: f32,
    reach: f32,
    inv_len2: f32,
    floodplain: f32,
    sax: f32,
    saz: f32,
    sbx: f32,
    sbz: f32,
    floodplain_b: f32,
    slope_a: f32,
    slope_b: f32,
    // The walls' spur value at the ends (`valleys: 5`; 0 before).
    spur_a: f32,
    spur_b: f32,
}

const WORKGROUP: u32 = 64u;

@group(0) @binding(0) var<uniform> params: CarveParams;
@group(0) @binding(1) var<storage, read> pieces: array<Piece>;
// `bins_w · bins_h + 1` offsets into `bin_pieces`.
@group(0) @binding(2) var<storage, read> bin_start: array<u32>;
// Piece indices of each bin, in piece order.
@group(0) @binding(3) var<storage, read> bin_pieces: array<u32>;
// Heights (w × h, row-major), carved in place.
@group(0) @binding(4) var<storage, read_write> heights: array<f32>;
// Lake level of each node of the lake window (lakes_w × lakes_h, row-major), LAKE_NONE where
// the node holds no lake.
@group(0) @binding(5) var<storage, read> lakes: array<f32>;

// `f32::clamp(t, 0.0, 1.0)` as Rust evaluates it (WGSL's `clamp` may treat −0 differently).
fn clamp01(t: f32) -> f32 {
    var r = t;
    if (r < 0.0) {
        r = 0.0;
    }
    if (r > 1.0) {
        r = 1.0;
    }
    return r;
}

// `carve::smoothstep`.
fn smoothstep_rn(e0: f32, e1: f32, x: f32) -> f32 {
    let t = clamp01(div_rn(x - e0, e1 - e0));
    return rn(rn(t * t) * (3.0 - rn(2.0 * t)));
}

// Correctly rounded sqrt, also for 0.
fn sqrt0(x: f32) -> f32 {
    if (x > 0.0) {
        return sqrt_rn(x);
    }
    return sqrt(x);
}

// `RiverJob::wall_width`: the width added to the walls at `(x, z)`, metres, exactly 0 without
// wall noise.
fn wall_width(x: f32, z: f32) -> f32 {
    if (params.wall_noise == 0.0) {
        return 0.0;
    }
    let n = lattice(rn(x * WALL_NOISE_INV_M), rn(z * WALL_NOISE_INV_M), params.wall_seed);
    return params.wall_noise * (clamp_to(n, -WALL_NOISE_CLAMP, WALL_NOISE_CLAMP) + WALL_NOISE_CLAMP);
}

// `carve::spur_step`: the smoothstep from `e0` to `e1` at `x`, its place bent by the spur value
// `s` (with `s = 0` the bits of `smoothstep_rn`).
fn spur_step_rn(e0: f32, e1: f32, x: f32, s: f32) -> f32 {
    let t0 = clamp01(div_rn(x - e0, e1 - e0));
    let t = t0 + rn(s * rn(t0 * (1.0 - t0)));
    return rn(rn(t * t) * (3.0 - rn(2.0 * t)));
}

// `rivers::profile` (its height only, `carve::profile_at_foot` with the walls' added width
// `wall`, metres, and the lake sill's level and weight, `sill.x` and `sill.y`; weight 0: none):
// piece `p` applied to a sample at `(x, z)` of height `h`. Beyond the reach, or the widened
// valley, the height is returned unchanged, bit for bit.
fn profile(p: Piece, x: f32, z: f32, h: f32, wall: f32, sill: vec2<f32>) -> f32 {
    let abx = p.bx - p.ax;
    let abz = p.bz - p.az;
    let t = clamp01(rn((rn((x - p.ax) * abx) + rn((z - p.az) * abz)) * p.inv_len2));
    // `carve::foot`: the distance to the curve's point at `t`.
    let k = rn(t * (1.0 - t));
    let ka = rn(k * (1.0 - t));
    let kb = rn(k * t);
    let dx = x - ((p.ax + rn(t * abx)) + (rn(ka * p.sax) + rn(kb * p.sbx)));
    let dz = z - ((p.az + rn(t * abz)) + (rn(ka * p.saz) + rn(kb * p.sbz)));
    let d2 = rn(dx * dx) + rn(dz * dz);
    if (d2 >= rn(p.reach * p.reach)) {
        return h;
    }
    let d = sqrt0(d2);
    let w = p.wa + rn((p.wb - p.wa) * t);
    var c = h;
    if (h > w) {
        // `f32::max` of two finite numbers: the floodplain's edge, linear along the piece.
        let floodplain = p.floodplain + rn((p.floodplain_b - p.floodplain) * t);
        var floor = p.half_width;
        if (floodplain > floor) {
            floor = floodplain;
        }
        let slope = p.slope_a + rn((p.slope_b - p.slope_a) * t);
        let v = clamp_to(floor + div_rn(h - w, slope) + wall, p.valley, p.reach);
        if (d < v) {
            let spur = p.spur_a + rn((p.spur_b - p.spur_a) * t);
            let g = spur_step_rn(floor, v, d, spur);
            c = w + rn((h - w) * g);
        }
    }
    if (d < p.half_width) {
        let r = div_rn(d, p.half_width);
        c = min(c, w - rn(p.depth * (1.0 - rn(r * r))));
    } else if (sill.y > 0.0) {
        c = c + rn((max(c, min(h, sill.x)) - c) * sill.y);
    }
    return c;
}

// `f32::clamp` as Rust evaluates it (not WGSL's `clamp`, whose handling of −0 may differ).
fn clamp_to(x: f32, lo: f32, hi: f32) -> f32 {
    var r = x;
    if (r < lo) {
        r = lo;
    }
    if (r > hi) {
        r = hi;
    }
    return r;
}

// `RiverJob::bin`: the range of `bin_pieces` of the bin holding `(x, z)`, empty outside the
// grid (written, as on the CPU, so that a NaN index lands outside too).
fn bin_range(x: f32, z: f32) -> vec2<u32> {
    let bx = floor(div_rn(x - params.x0, params.bin_m));
    let bz = floor(div_rn(z - params.z0, params.bin_m));
    let inside_x = bx >= 0.0 && bx < f32(params.bins_w);
    let inside_z = bz >= 0.0 && bz < f32(params.bins_h);
    if (!(inside_x && inside_z)) {
        return vec2<u32>(0u, 0u);
    }
    let b = u32(bz) * params.bins_w + u32(bx);
    return vec2<u32>(bin_start[b], bin_start[b + 1u]);
}

// `RiverJob::node_lake`: the level of node `(i, k)` of the lake window, LAKE_NONE where it holds
// no lake or lies outside the window.
fn node_lake(i: i32, k: i32) -> f32 {
    let a = i - params.li0;
    let b = k - params.lk0;
    if (a < 0 || b < 0 || u32(a) >= params.lakes_w || u32(b) >= params.lakes_h) {
        return LAKE_NONE;
    }
    return lakes[u32(b) * params.lakes_w + u32(a)];
}

// `RiverJob::node_floor`: the height of lake node `(i, k)` of the window (a node `node_lake`
// found a lake at), stored after the window's levels.
fn node_floor(i: i32, k: i32) -> f32 {
    let a = u32(i - params.li0);
    let b = u32(k - params.lk0);
    return lakes[params.lakes_w * params.lakes_h + b * params.lakes_w + a];
}

// `RiverJob::shore_sill` (`rivers::shores`, with `RiverJob::lake_field`): the height `h` at
// `(x, z)` clamped into the shore's wedge around the lake level, faded in with the lake weight
// (`h` itself where no lake node around has weight or the world has the first lakes), then the
// sill's level and weight (weight 0: none).
fn shore(x: f32, z: f32, h: f32) -> vec3<f32> {
    if (params.shores == 0u || params.lakes_w == 0u) {
        return vec3<f32>(h, 0.0, 0.0);
    }
    let qx = rn(x * params.shore_warp_inv_m);
    let qz = rn(z * params.shore_warp_inv_m);
    let wx = clamp_to(lattice(qx, qz, params.shore_seed2), -SHORE_NOISE_CLAMP, SHORE_NOISE_CLAMP);
    let wz = clamp_to(lattice(qx, qz, params.shore_seed3), -SHORE_NOISE_CLAMP, SHORE_NOISE_CLAMP);
    let u = div_rn(x + rn(params.shore_warp_m * wx), params.node_spacing) - 0.5;
    let v = div_rn(z + rn(params.shore_warp_m * wz), params.node_spacing) - 0.5;
    let fu = floor(u);
    let fv = floor(v);
    let a = u - fu;
    let b = v - fv;
    let i = i32(fu);
    let k = i32(fv);
    let ws = array<f32, 4>(
        rn((1.0 - a) * (1.0 - b)),
        rn(a * (1.0 - b)),
        rn((1.0 - a) * b),
        rn(a * b),
    );
    let ci = array<i32, 4>(i, i + 1, i, i + 1);
    let ck = array<i32, 4>(k, k, k + 1, k + 1);
    // The weights are at least 0, so no lake corner (or none with weight) leaves 0.
    var weight = 0.0;
    var sum = 0.0;
    var floor_sum = 0.0;
    for (var c = 0u; c < 4u; c++) {
        let l = node_lake(ci[c], ck[c]);
        if (l > LAKE_NONE) {
            weight = weight + ws[c];
            sum = sum + rn(ws[c] * l);
            if (params.sink != 0u) {
                floor_sum = floor_sum + rn(ws[c] * node_floor(ci[c], ck[c]));
            }
        }
    }
    if (weight <= 0.0) {
        return vec3<f32>(h, 0.0, 0.0);
    }
    let level = div_rn(sum, weight);
    let n1 = clamp_to(
        lattice(rn(x * SHORE_NOISE_INV_M), rn(z * SHORE_NOISE_INV_M), params.shore_seed0),
        -SHORE_NOISE_CLAMP,
        SHORE_NOISE_CLAMP,
    );
    let n2 = clamp_to(
        lattice(rn(x * SHORE_NOISE2_INV_M), rn(z * SHORE_NOISE2_INV_M), params.shore_seed1),
        -SHORE_NOISE_CLAMP,
        SHORE_NOISE_CLAMP,
    );
    let t = weight + (rn(params.shore_n1 * n1) + rn(params.shore_n2 * n2));
    let e = 0.5 - t;
    var sill_s = 0.0;
    if (params.sills != 0u) {
        sill_s = rn(smoothstep_rn(0.0, SILL_FULL, weight) * smoothstep_rn(-SILL_E, 0.0, e));
    }
    // The sink (`lakes: 8`, the shores' step 3): towards the lake nodes' height, with the ramp
    // of the lake weight.
    var hs = h;
    if (params.sink != 0u) {
        let lake_floor = div_rn(floor_sum, weight);
        let st = clamp01(rn(rn(weight - SINK_FROM) * SINK_SCALE));
        let s = rn(rn(st * st) * (3.0 - rn(2.0 * st)));
        hs = rn(h - min(rn(s * max(rn(h - lake_floor), 0.0)), SINK_MAX_M));
    }
    let gentle = rn(SHORE_GENTLE_M * e);
    let steep = rn(SHORE_STEEP_M * e);
    var lo = level + steep;
    var hi = level + gentle;
    if (e > 0.0) {
        lo = level + gentle;
        hi = level + steep;
    }
    var target_h = hs;
    if (hs < lo) {
        target_h = lo;
    } else if (hs > hi) {
        target_h = hi;
    } else {
        return vec3<f32>(hs, level, sill_s);
    }
    let g = smoothstep_rn(0.0, SHORE_FULL, weight);
    let change = clamp_to(rn((target_h - hs) * g), -SHORE_MAX_M, SHORE_MAX_M);
    return vec3<f32>(hs + change, level, sill_s);
}

// Linear invocation index of a 2D dispatch of 1D workgroups (the x count is capped at 65535).
fn invocation(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.y * nwg.x * WORKGROUP + gid.x;
}

// `RiverJob::carve_one` for one sample, in place.
@compute @workgroup_size(64)
fn river_carve(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    rounding_key = params.rounding_key;
    let idx = invocation(gid, nwg);
    if (idx >= params.w * params.h) {
        return;
    }
    // World position `(g as f32) * spacing`, as on the CPU.
    let x = rn(f32(params.gx0 + i32(idx % params.w)) * params.spacing);
    let z = rn(f32(params.gz0 + i32(idx / params.w)) * params.spacing);
    let shaped = shore(x, z, heights[idx]);
    let h = shaped.x;
    let sill = shaped.yz;
    var c = h;
    let range = bin_range(x, z);
    var wall = 0.0;
    if (range.x < range.y) {
        wall = wall_width(x, z);
    }
    for (var k = range.x; k < range.y; k++) {
        c = min(c, profile(pieces[bin_pieces[k]], x, z, h, wall, sill));
    }
    heights[idx] = max(c, h - CARVE_MAX_M);
}
