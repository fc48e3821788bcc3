// requires: common.wgsl
//
// WGSL twin of `terrain::tile::field`: heights and biome weights of a rectangle of one LOD's
// vertex lattice, in four dispatches (each in its own compute pass, so each sees the previous
// one's writes):
//
// 1. `block_corners`: Algorithm 1 at the corners of the world-anchored 8×8 blocks that cover the
//    biome grid (`terrain::biome::biome_grid`), with the fill biome of each corner;
// 2. `biome_ids`: each sample of the biome grid (the rectangle plus the blur radius r on every
//    side) takes its block's fill biome when the block's four corners share one Voronoi cell, and
//    its own Algorithm 1 + 2 evaluation otherwise: the CPU's rule, so the ids agree;
// 3. `blur_h`: horizontal pass of `terrain::blur::blur_weights` with the exact one-hot rule;
// 4. `blur_v`: vertical pass with the one-hot rule, normalisation, then the height
//    h = Σ_b w_b · fbm_b over the biomes with w_b > 0, in biome order, from 0.0.
//
// `Params` is `gpu::layout::GpuParams` on the CPU, field for field.

struct Params {
    // Output rectangle: lattice origin and size.
    gx0: i32,
    gz0: i32,
    w: u32,
    h: u32,
    // Biome grid: the output rectangle grown by r = taps / 2 on every side.
    bgx0: i32,
    bgz0: i32,
    bw: u32,
    bh: u32,
    // Block corners: first block index and corner grid size (blocks + 1 per side).
    bx0: i32,
    bz0: i32,
    cw: u32,
    ch: u32,
    // Blur taps (2r + 1), number of biomes, vertex spacing in metres, and 0 (see `rn`).
    taps: u32,
    k: u32,
    spacing: f32,
    rounding_key: u32,
    map: BiomeMap,
}

// Most biomes a world may have (`terrain::world::MAX_BIOMES`).
const MAX_BIOMES: u32 = 8u;
// Tag of a horizontal blur result that is not one-hot (`terrain::blur::DENSE`).
const DENSE: u32 = 255u;
// `terrain::biome::BLOCK` = 2^3.
const BLOCK_SHIFT: u32 = 3u;
const WORKGROUP: u32 = 64u;

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> fractals: array<Fractal>;
@group(0) @binding(2) var<storage, read> kernel: array<f32>;
// Per block corner: winning cell (x, z), fill biome, unused.
@group(0) @binding(3) var<storage, read_write> corners: array<vec4<i32>>;
// Biome id per biome-grid sample, row-major (bw × bh).
@group(0) @binding(4) var<storage, read_write> ids: array<u32>;
// Horizontal pass (w × bh): tag (biome or DENSE) and k dense channel values.
@group(0) @binding(5) var<storage, read_write> htag: array<u32>;
@group(0) @binding(6) var<storage, read_write> hdense: array<f32>;
// Output: weights (w × h × k, vertex-major) and heights (w × h).
@group(0) @binding(7) var<storage, read_write> weights: array<f32>;
@group(0) @binding(8) var<storage, read_write> heights: array<f32>;

// Linear invocation index of a 2D dispatch of 1D workgroups (the x count is capped at 65535).
fn invocation(gid: vec3<u32>, nwg: vec3<u32>) -> u32 {
    return gid.y * nwg.x * WORKGROUP + gid.x;
}

// Every entry point starts here: the runtime zero of the rounding barrier (common.wgsl).
fn begin() {
    rounding_key = params.rounding_key;
}

// World position of a lattice index, `(g as f32) * spacing` as on the CPU.
fn pos(g: i32) -> f32 {
    return f32(g) * params.spacing;
}

@compute @workgroup_size(64)
fn block_corners(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    begin();
    let idx = invocation(gid, nwg);
    if (idx >= params.cw * params.ch) {
        return;
    }
    let cx = i32(idx % params.cw);
    let cz = i32(idx / params.cw);
    let gx = (params.bx0 + cx) << BLOCK_SHIFT;
    let gz = (params.bz0 + cz) << BLOCK_SHIFT;
    let n = nearest(params.map, pos(gx), pos(gz));
    corners[idx] = vec4<i32>(n.cell.x, n.cell.y, i32(biome_of(params.map, n.pos)), 0);
}

@compute @workgroup_size(64)
fn biome_ids(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    begin();
    let idx = invocation(gid, nwg);
    if (idx >= params.bw * params.bh) {
        return;
    }
    let gx = params.bgx0 + i32(idx % params.bw);
    let gz = params.bgz0 + i32(idx / params.bw);
    // `div_euclid(BLOCK)`: an arithmetic shift floors negative indices too.
    let bx = gx >> BLOCK_SHIFT;
    let bz = gz >> BLOCK_SHIFT;
    let cw = params.cw;
    let ci = u32(bz - params.bz0) * cw + u32(bx - params.bx0);
    let c00 = corners[ci];
    let c10 = corners[ci + 1u];
    let c01 = corners[ci + cw];
    let c11 = corners[ci + cw + 1u];
    let uniform_block = all(c10.xy == c00.xy) && all(c01.xy == c00.xy) && all(c11.xy == c00.xy);
    if (uniform_block) {
        ids[idx] = u32(c00.z);
    } else {
        ids[idx] = biome_at(params.map, pos(gx), pos(gz));
    }
}

@compute @workgroup_size(64)
fn blur_h(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    begin();
    let idx = invocation(gid, nwg);
    let w = params.w;
    if (idx >= w * params.bh) {
        return;
    }
    let row = idx / w;
    let col = idx % w;
    let base = row * params.bw + col;
    let k = min(params.k, MAX_BIOMES);
    let first = ids[base];
    var same = true;
    for (var t = 1u; t < params.taps; t++) {
        if (ids[base + t] != first) {
            same = false;
            break;
        }
    }
    var acc: array<f32, 8>;
    if (same) {
        htag[idx] = first;
    } else {
        htag[idx] = DENSE;
        // Σ_t k_t · [id_t = c], in t order.
        for (var t = 0u; t < params.taps; t++) {
            let c = min(ids[base + t], MAX_BIOMES - 1u);
            acc[c] += kernel[t];
        }
    }
    for (var c = 0u; c < k; c++) {
        hdense[idx * k + c] = acc[c];
    }
}

@compute @workgroup_size(64)
fn blur_v(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>) {
    begin();
    let idx = invocation(gid, nwg);
    let w = params.w;
    if (idx >= w * params.h) {
        return;
    }
    let orow = idx / w;
    let col = idx % w;
    let k = min(params.k, MAX_BIOMES);
    let t0 = htag[orow * w + col];
    var one_hot = t0 != DENSE;
    for (var t = 1u; one_hot && t < params.taps; t++) {
        if (htag[(orow + t) * w + col] != t0) {
            one_hot = false;
        }
    }
    var wt: array<f32, 8>;
    if (one_hot) {
        wt[min(t0, MAX_BIOMES - 1u)] = 1.0;
    } else {
        var acc: array<f32, 8>;
        for (var t = 0u; t < params.taps; t++) {
            let kt = kernel[t];
            let src = (orow + t) * w + col;
            let tag = htag[src];
            if (tag == DENSE) {
                for (var c = 0u; c < k; c++) {
                    acc[c] += rn(kt * hdense[src * k + c]);
                }
            } else {
                acc[min(tag, MAX_BIOMES - 1u)] += kt;
            }
        }
        var sum = 0.0;
        for (var c = 0u; c < k; c++) {
            sum += acc[c];
        }
        for (var c = 0u; c < k; c++) {
            wt[c] = div_rn(acc[c], sum);
        }
    }
    let x = pos(params.gx0 + i32(col));
    let z = pos(params.gz0 + i32(orow));
    var height = 0.0;
    for (var b = 0u; b < k; b++) {
        weights[idx * k + b] = wt[b];
        if (wt[b] > 0.0) {
            height += rn(wt[b] * fbm(fractals[b], x, z));
        }
    }
    heights[idx] = height;
}
