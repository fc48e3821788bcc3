//! Proto-texturing (Schneider et al. §4.2): a surface material per vertex from a height/slope
//! weighting function, plus water depth below the sea level.
//!
//! Each candidate material gets a weight in [0, 1] from smooth steps of height and slope:
//! - `seabed` = under water;
//! - `rock` = slope above `rock_slope_deg` (blended over `rock_blend_deg`, the blend running on
//!   the cosine of the slope), on land;
//! - `snow` = above the biome-weighted snow line, where not rock;
//! - `sand` (beach) = less than `beach_height_m` above the sea, where not rock;
//! - in worlds with `alpine_fraction` `a > 0`, `rock` also takes the alpine share
//!   `α = smoothstep(−a·L, −a·L/4, h − line)` of what the three above leave, `L` the snow
//!   line's height above the sea: bare rock and scree above the tree line, from `(1 − a)·L`
//!   above the sea up to the snow;
//! - each biome's ground material gets `w_b · (1 − rock) · (1 − snow) · (1 − beach) · (1 − α)`.
//!
//! The vertex's material is the heaviest one (lowest id on ties). Steep rock thus suppresses
//! grass as in the paper's Fig. 8.

use super::world::{material, WorldParams, MATERIALS, MAX_BIOMES};

/// What the weighting function looks at.
#[derive(Clone, Copy, Debug)]
pub struct Surface<'a> {
    /// Ground height, metres.
    pub height_m: f32,
    /// Y component of the unit normal (`cos` of the slope angle).
    pub normal_y: f32,
    /// Biome weights.
    pub weights: &'a [f32],
}

fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Smoothstep with a precomputed `1 / (e1 − e0)`.
#[inline(always)]
fn smoothstep_inv(e0: f32, inv_width: f32, x: f32) -> f32 {
    let t = ((x - e0) * inv_width).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Per-world constants of the weighting function, resolved once.
#[derive(Clone, Debug, PartialEq)]
pub struct TexturePlan {
    sea_level_m: f32,
    height_blend_m: f32,
    beach_height_m: f32,
    /// `cos` of the slope where rock starts and where it is complete (the slope smoothstep runs
    /// in `cos` space, i.e. on the normal's y component, which avoids an `acos` per vertex).
    rock_cos: (f32, f32),
    ground: Vec<u8>,
    snow_line_m: Vec<f32>,
    /// `Texturing::alpine_fraction` (0: no alpine zone).
    alpine_fraction: f32,
}

/// The alpine zone's share of the ground (module docs) at `above_line` metres above a snow line
/// that lies `line_above_sea` metres above the sea: 0 below `(1 − fraction)` of the line's
/// height, 1 from a quarter of that band below the line up. 0 everywhere when `fraction` is 0.
#[inline(always)]
pub fn alpine_share(fraction: f32, line_above_sea: f32, above_line: f32) -> f32 {
    let band = fraction * line_above_sea.max(0.0);
    if band > 0.0 {
        smoothstep_inv(-band, 1.0 / (0.75 * band), above_line)
    } else {
        0.0
    }
}

impl TexturePlan {
    /// Resolves the settings.
    pub fn new(params: &WorldParams) -> Self {
        let t = &params.texturing;
        let lo = libm::cosf((t.rock_slope_deg - t.rock_blend_deg * 0.5).to_radians());
        let hi = libm::cosf((t.rock_slope_deg + t.rock_blend_deg * 0.5).to_radians());
        Self {
            sea_level_m: params.sea_level_m,
            height_blend_m: t.height_blend_m.max(1e-3),
            beach_height_m: t.beach_height_m,
            rock_cos: (lo, if hi == lo { lo - 1e-6 } else { hi }),
            ground: params
                .biomes
                .iter()
                .map(|b| WorldParams::material_id(&b.ground))
                .collect(),
            snow_line_m: params
                .biomes
                .iter()
                .map(|b| b.snow_line_m.clamp(-1e6, 1e6))
                .collect(),
            alpine_fraction: t.alpine_fraction,
        }
    }
}

/// Material weights, indexed like [`MATERIALS`].
pub fn material_weights(plan: &TexturePlan, s: &Surface) -> [f32; MATERIALS.len()] {
    let mut out = [0.0f32; MATERIALS.len()];
    let above = s.height_m - plan.sea_level_m;
    let blend = plan.height_blend_m;
    let inv_blend = 1.0 / blend;
    let wet = 1.0 - smoothstep_inv(-blend * 0.5, 2.0 * inv_blend, above);
    out[material::SEABED as usize] = wet;
    let rock = smoothstep(plan.rock_cos.0, plan.rock_cos.1, s.normal_y) * (1.0 - wet);
    out[material::ROCK as usize] = rock;
    let mut snow_line = 0.0f32;
    for (line, w) in plan.snow_line_m.iter().zip(s.weights) {
        snow_line += w * line;
    }
    let snow =
        smoothstep_inv(snow_line - blend, 0.5 * inv_blend, s.height_m) * (1.0 - rock) * (1.0 - wet);
    out[material::SNOW as usize] += snow;
    let beach =
        (1.0 - smoothstep_inv(plan.beach_height_m, inv_blend, above)) * (1.0 - wet) * (1.0 - rock);
    out[material::SAND as usize] += beach;
    let mut rest = (1.0 - wet) * (1.0 - rock) * (1.0 - snow) * (1.0 - beach);
    if plan.alpine_fraction > 0.0 {
        let alpine = alpine_share(
            plan.alpine_fraction,
            snow_line - plan.sea_level_m,
            s.height_m - snow_line,
        );
        out[material::ROCK as usize] += rest * alpine;
        rest *= 1.0 - alpine;
    }
    for (g, w) in plan.ground.iter().zip(s.weights) {
        out[*g as usize] += w * rest;
    }
    out
}

/// How many inputs of [`texel_weights`] a vertex carries ([`surface_inputs`]).
pub const SURFACE_INPUTS: usize = 2 + MATERIALS.len();

/// The inputs of [`texel_weights`] at a vertex: its height above the sea, its height above its
/// snow line (`snow_line_m` where the world gives one, else the biome-weighted line; moved by
/// `snow_shift_m`), both metres, then the share of
/// each material in [`MATERIALS`] order among the ground materials of the vertex's biomes (the
/// weights of the biomes whose ground it is, summed). Every input is what the weighting
/// function reads before its smooth steps, so a texel between vertices can take their bilinear
/// mix and evaluate the steps at its own place (`ptex_blend: 2`).
pub fn surface_inputs(
    plan: &TexturePlan,
    height_m: f32,
    weights: &[f32],
    snow_line_m: Option<f32>,
    snow_shift_m: f32,
) -> [f32; SURFACE_INPUTS] {
    let mut out = [0.0f32; SURFACE_INPUTS];
    let mut line = 0.0f32;
    for ((l, g), w) in plan.snow_line_m.iter().zip(&plan.ground).zip(weights) {
        line += w * l;
        out[2 + *g as usize] += w;
    }
    let line = snow_line_m.unwrap_or(line);
    out[0] = height_m - plan.sea_level_m;
    out[1] = height_m - (line + snow_shift_m);
    out
}

/// The thresholds [`texel_weights`] reads, from a world's [`TexturePlan`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexelRule {
    /// Width of the snow-line and beach transitions, metres.
    pub blend_m: f32,
    /// Beaches reach this high above the sea, metres.
    pub beach_height_m: f32,
    /// `cos` of the slope where rock starts and where it is complete.
    pub rock_cos: (f32, f32),
    /// `Texturing::alpine_fraction` (0: no alpine zone).
    pub alpine_fraction: f32,
}

impl TexturePlan {
    /// The thresholds of [`texel_weights`].
    pub fn texel_rule(&self) -> TexelRule {
        TexelRule {
            blend_m: self.height_blend_m,
            beach_height_m: self.beach_height_m,
            rock_cos: self.rock_cos,
            alpine_fraction: self.alpine_fraction,
        }
    }
}

/// The weight of each material ([`MATERIALS`] order) at a point whose [`surface_inputs`] are `s`
/// (a texel's: the bilinear mix of its vertices') and whose unit normal has the y component
/// `normal_y`: the smooth steps of [`material_weights`], each taken at the point. The weights
/// sum to 1 where the ground shares do. `shaders/ptex.wgsl` (`surface_weights`) is its twin,
/// operation for operation. The same function as [`material_weights`], taken from the inputs
/// before the thresholds; that one keeps its own order of operations because
/// [`proto_texture_batch`] is pinned to its bits.
pub fn texel_weights(
    rule: &TexelRule,
    s: &[f32; SURFACE_INPUTS],
    normal_y: f32,
) -> [f32; MATERIALS.len()] {
    let blend = rule.blend_m;
    let inv_blend = 1.0 / blend;
    let above = s[0];
    let wet = 1.0 - smoothstep_inv(-blend * 0.5, 2.0 * inv_blend, above);
    let rock = smoothstep(rule.rock_cos.0, rule.rock_cos.1, normal_y) * (1.0 - wet);
    let snow = smoothstep_inv(-blend, 0.5 * inv_blend, s[1]) * (1.0 - rock) * (1.0 - wet);
    let beach =
        (1.0 - smoothstep_inv(rule.beach_height_m, inv_blend, above)) * (1.0 - wet) * (1.0 - rock);
    let rest = (1.0 - wet) * (1.0 - rock) * (1.0 - snow) * (1.0 - beach);
    // The alpine zone: `s[0] − s[1]` is the snow line's height above the sea. Where the world
    // has none the share is exactly 0, so `rest · 1` and `rock + 0` keep the bits of the
    // worlds stored before it.
    let alpine = alpine_share(rule.alpine_fraction, above - s[1], s[1]);
    let ground = rest * (1.0 - alpine);
    let mut out = [0.0f32; MATERIALS.len()];
    out[material::SEABED as usize] = wet;
    out[material::SAND as usize] = beach;
    out[material::ROCK as usize] = rock + rest * alpine;
    out[material::SNOW as usize] = snow;
    for (m, w) in out.iter_mut().enumerate() {
        *w += s[2 + m] * ground;
    }
    out
}

/// Vertices per block of [`proto_texture_batch`]: the per-block rows live on the stack.
const BLOCK: usize = 64;

/// Dominant materials of many vertices: `out[v] = proto_texture(plan, vertex v)`. `weights` is
/// vertex-major with `k` biomes; `snow_line` (metres per vertex, or empty) replaces the
/// biome-weighted snow line, as `earth-1` worlds with `snow_lines: 2` give the sea-level
/// climate's; `snow_shift` (metres per vertex, or empty for none) moves each vertex's snow line,
/// as `earth-1` does by aspect and noise.
///
/// Works in blocks of [`BLOCK`] vertices: the biome-weighted snow line, the four smooth steps and
/// `rest` as fixed-length rows, then one compare-and-select row per material in id order, so every
/// loop vectorises and branches run once per block. Each material's weight is built from the same
/// operations in the same order as in [`material_weights`] (base value, then `+ w_b · rest` for
/// the biomes whose ground it is, in biome order), hence the same bits and the same argmax.
pub fn proto_texture_batch(
    plan: &TexturePlan,
    heights: &[f32],
    normal_y: &[f32],
    weights: &[f32],
    snow_line: &[f32],
    snow_shift: &[f32],
    out: &mut [u8],
) {
    let k = plan.ground.len();
    let n = heights.len();
    assert!(
        normal_y.len() == n
            && out.len() == n
            && weights.len() == n * k
            && (snow_line.is_empty() || snow_line.len() == n)
            && (snow_shift.is_empty() || snow_shift.len() == n)
            && k <= MAX_BIOMES,
        "proto_texture_batch: sizes"
    );
    // A tile inside one biome (weights exactly one-hot everywhere): `0 + 1·x` is `x` and `0·x`
    // terms add `±0`, so the block needs no weight rows at all.
    let single = (0..k).find(|&b| weights.chunks_exact(k).all(|wv| wv[b] == 1.0));
    let blend = plan.height_blend_m;
    let inv_blend = 1.0 / blend;
    for (blk, ((hc, nc), oc)) in heights
        .chunks(BLOCK)
        .zip(normal_y.chunks(BLOCK))
        .zip(out.chunks_mut(BLOCK))
        .enumerate()
    {
        // Fixed-length rows (the tail padded) let every loop below run without bounds checks.
        let len = hc.len();
        let mut hs = [0.0f32; BLOCK];
        let mut ns = [0.0f32; BLOCK];
        hs[..len].copy_from_slice(hc);
        ns[..len].copy_from_slice(nc);
        let mut wt = [[0.0f32; BLOCK]; MAX_BIOMES];
        let mut line = [0.0f32; BLOCK];
        match single {
            Some(b) => {
                wt[b] = [1.0; BLOCK];
                line = [0.0 + plan.snow_line_m[b]; BLOCK];
            }
            None => {
                let wv = &weights[blk * BLOCK * k..(blk * BLOCK + len) * k];
                for (v, cell) in wv.chunks_exact(k).enumerate() {
                    for (b, w) in cell.iter().enumerate() {
                        wt[b][v] = *w;
                    }
                }
                for (b, l) in plan.snow_line_m.iter().enumerate() {
                    for v in 0..BLOCK {
                        line[v] += wt[b][v] * l;
                    }
                }
            }
        }
        if !snow_line.is_empty() {
            line[..len].copy_from_slice(&snow_line[blk * BLOCK..blk * BLOCK + len]);
        }
        if !snow_shift.is_empty() {
            let shift = &snow_shift[blk * BLOCK..blk * BLOCK + len];
            for (l, d) in line.iter_mut().zip(shift) {
                *l += d;
            }
        }
        let mut wet = [0.0f32; BLOCK];
        let mut rock = [0.0f32; BLOCK];
        let mut snow = [0.0f32; BLOCK];
        let mut beach = [0.0f32; BLOCK];
        let mut rest = [0.0f32; BLOCK];
        let mut scree = [0.0f32; BLOCK];
        for v in 0..BLOCK {
            let h = hs[v];
            let above = h - plan.sea_level_m;
            let we = 1.0 - smoothstep_inv(-blend * 0.5, 2.0 * inv_blend, above);
            let ro = smoothstep(plan.rock_cos.0, plan.rock_cos.1, ns[v]) * (1.0 - we);
            let sn = smoothstep_inv(line[v] - blend, 0.5 * inv_blend, h) * (1.0 - ro) * (1.0 - we);
            let be = (1.0 - smoothstep_inv(plan.beach_height_m, inv_blend, above))
                * (1.0 - we)
                * (1.0 - ro);
            wet[v] = we;
            rock[v] = ro;
            snow[v] = sn;
            beach[v] = be;
            rest[v] = (1.0 - we) * (1.0 - ro) * (1.0 - sn) * (1.0 - be);
        }
        if plan.alpine_fraction > 0.0 {
            for v in 0..BLOCK {
                let line_above_sea = line[v] - plan.sea_level_m;
                let alpine = alpine_share(plan.alpine_fraction, line_above_sea, hs[v] - line[v]);
                scree[v] = rest[v] * alpine;
                rest[v] *= 1.0 - alpine;
            }
        }
        let mut top = [0.0f32; BLOCK];
        let mut best = [0u8; BLOCK];
        for id in 0..MATERIALS.len() as u8 {
            let mut row = match id {
                material::SEABED => wet,
                material::SAND => beach,
                material::ROCK => rock,
                material::SNOW => snow,
                _ => [0.0; BLOCK],
            };
            if id == material::ROCK && plan.alpine_fraction > 0.0 {
                for v in 0..BLOCK {
                    row[v] += scree[v];
                }
            }
            for (b, g) in plan.ground.iter().enumerate() {
                if *g != id || single.is_some_and(|s| s != b) {
                    continue;
                }
                let w = &wt[b];
                for v in 0..BLOCK {
                    row[v] += w[v] * rest[v];
                }
            }
            if id == 0 {
                top = row;
                continue;
            }
            for v in 0..BLOCK {
                let better = row[v] > top[v];
                top[v] = if better { row[v] } else { top[v] };
                best[v] = if better { id } else { best[v] };
            }
        }
        oc.copy_from_slice(&best[..len]);
    }
}

/// The dominant material id of a vertex.
pub fn proto_texture(plan: &TexturePlan, s: &Surface) -> u8 {
    let w = material_weights(plan, s);
    let mut best = 0;
    for (m, &v) in w.iter().enumerate() {
        if v > w[best] {
            best = m;
        }
    }
    best as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steep_slopes_are_rock_and_water_is_seabed() {
        let p = TexturePlan::new(&WorldParams::classic());
        let grass = [0.0, 0.0, 1.0, 0.0];
        let flat = Surface {
            height_m: 30.0,
            normal_y: 1.0,
            weights: &grass,
        };
        assert_eq!(proto_texture(&p, &flat), material::GRASS);
        let steep = Surface {
            normal_y: 60f32.to_radians().cos(),
            ..flat
        };
        assert_eq!(proto_texture(&p, &steep), material::ROCK);
        let under = Surface {
            height_m: -5.0,
            ..flat
        };
        assert_eq!(proto_texture(&p, &under), material::SEABED);
        let beach = Surface {
            height_m: 0.5,
            ..flat
        };
        assert_eq!(proto_texture(&p, &beach), material::SAND);
        let high = Surface {
            height_m: 400.0,
            ..flat
        };
        assert_eq!(proto_texture(&p, &high), material::SNOW);
    }

    /// Materials of [`proto_texture_batch`] over the vertices (four biome weights each), after
    /// asserting that each equals [`proto_texture`] of that vertex alone; `case` names the inputs
    /// in the failure message.
    fn batch_matching_per_vertex(
        p: &TexturePlan,
        heights: &[f32],
        ny: &[f32],
        weights: &[f32],
        case: &str,
    ) -> Vec<u8> {
        let mut out = vec![0u8; heights.len()];
        proto_texture_batch(p, heights, ny, weights, &[], &[], &mut out);
        for v in 0..heights.len() {
            let s = Surface {
                height_m: heights[v],
                normal_y: ny[v],
                weights: &weights[v * 4..v * 4 + 4],
            };
            assert_eq!(out[v], proto_texture(p, &s), "{case}: vertex {v}");
        }
        out
    }

    #[test]
    fn single_biome_path_equals_the_general_one() {
        let params = WorldParams::classic();
        let p = TexturePlan::new(&params);
        let n = 400;
        let heights: Vec<f32> = (0..n).map(|i| i as f32 * 1.3 - 60.0).collect();
        let ny: Vec<f32> = (0..n).map(|i| 0.3 + (i % 17) as f32 * 0.04).collect();
        let mut seen = std::collections::BTreeSet::new();
        for b in 0..params.biomes.len() {
            let weights: Vec<f32> = (0..n * 4)
                .map(|i| if i % 4 == b { 1.0 } else { 0.0 })
                .collect();
            let fast =
                batch_matching_per_vertex(&p, &heights, &ny, &weights, &format!("biome {b}"));
            seen.extend(fast);
        }
        // The inputs must reach every branch: water, beach, ground, rock and snow.
        assert!(seen.len() >= 5, "materials reached: {seen:?}");
    }

    #[test]
    fn the_alpine_zone_is_rock_below_the_snow_line_alike_in_batch_and_alone() {
        // The classic world's grassland has its snow line at 160 m: with an alpine fraction
        // of ¼ its gentle ground is grass below 120 m and rock from 150 m up to the snow.
        let mut params = WorldParams::classic();
        params.texturing.alpine_fraction = 0.25;
        let (alpine, bare) = (
            TexturePlan::new(&params),
            TexturePlan::new(&WorldParams::classic()),
        );
        let n = 800;
        let heights: Vec<f32> = (0..n).map(|i| i as f32 * 0.25).collect();
        let flat = vec![1.0f32; n];
        let grass: Vec<f32> = (0..n * 4)
            .map(|i| if i % 4 == 2 { 1.0 } else { 0.0 })
            .collect();
        let with = batch_matching_per_vertex(&alpine, &heights, &flat, &grass, "alpine");
        let without = batch_matching_per_vertex(&bare, &heights, &flat, &grass, "no alpine");
        let mut rock = 0;
        for (v, h) in heights.iter().enumerate() {
            if *h > 10.0 && *h < 119.5 {
                assert_eq!(with[v], material::GRASS, "{h} m, below the band");
            }
            if *h > 150.5 && *h < 153.5 {
                assert_eq!(
                    (with[v], without[v]),
                    (material::ROCK, material::GRASS),
                    "{h} m"
                );
                rock += 1;
            }
        }
        assert!(rock > 5, "{rock} vertices in the band's upper quarter");
        // Mixed weights take the general path of the batch.
        let mixed: Vec<f32> = (0..n * 4)
            .map(|i| if i % 4 == (i / 40) % 4 { 0.7 } else { 0.1 })
            .collect();
        batch_matching_per_vertex(&alpine, &heights, &flat, &mixed, "alpine, mixed weights");
    }

    #[test]
    fn batch_equals_per_vertex() {
        let p = TexturePlan::new(&WorldParams::classic());
        let n = 300;
        let heights: Vec<f32> = (0..n).map(|i| i as f32 * 1.7 - 40.0).collect();
        let ny: Vec<f32> = (0..n).map(|i| 0.4 + (i % 13) as f32 * 0.05).collect();
        let weights: Vec<f32> = (0..n * 4)
            .map(|i| if i % 4 == (i / 40) % 4 { 0.7 } else { 0.1 })
            .collect();
        batch_matching_per_vertex(&p, &heights, &ny, &weights, "mixed weights");
    }
}
