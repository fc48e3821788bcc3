//! The extended Voronoi biome map of Choroś & Topolski (Algorithms 1 and 2).
//!
//! Algorithm 1: the plane is divided into square cells of `cell_size_m`; cell `(i, j)` has a seed
//! at `(i + v₁, j + v₂)` with `v₁, v₂ ∈ [−1, 1)` hashed from `(seed, i, j)`. A point takes the seed
//! nearest to it (squared Euclidean distance) among the cells within `RANGE = 2` of its own, and
//! the Voronoi value is a hash of the seed's floored position, in `[0, 1)`.
//!
//! Algorithm 2: with latitude enabled the value is clamped to `[f − d, f + d] ∩ [0, 1]`, where
//! `f` is the triangle wave of Eq. 2 over the seed's floored `|z|` with period `2S` cells (0 at the
//! pole, 1 at the equator) and `d` the dispersion; without dispersion `d = 0`, which gives pure
//! latitude bands. The biome is `⌊value · K⌋` for `K` biomes, so biome 0 lies toward the poles.
//!
//! Sampling is on the world-anchored vertex lattice of a LOD. [`biome_grid`] fills a rectangle of
//! it; it evaluates the corners of world-anchored 8×8 blocks first and fills a block whose four
//! corners share one seed without testing its inner samples (Voronoi cells are convex). Because the
//! blocks are anchored to the world, every tile makes the same decision for the same sample, so
//! the map is a pure function of the global sample index.

use super::hash::{hash2, purpose, signed_unit, stream, unit};
use super::world::BiomeLayout;

/// Algorithm 1's search range, in cells.
pub const RANGE: i32 = 2;
/// Side of the world-anchored blocks of the corner shortcut, in samples (a power of two).
pub const BLOCK: i64 = 8;
/// Points of a grid row compared side by side by [`BiomeMapPlan::nearest_grid`].
pub const GRID_LANES: usize = 16;

/// Stream seeds of the Voronoi map of one world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VoronoiSeeds {
    /// Seed x offsets.
    pub x: u32,
    /// Seed z offsets.
    pub z: u32,
    /// Cell values.
    pub value: u32,
}

impl VoronoiSeeds {
    /// The Voronoi streams of a world seed.
    pub fn new(world_seed: u64) -> Self {
        Self {
            x: stream(world_seed, purpose::VORONOI, 0),
            z: stream(world_seed, purpose::VORONOI, 1),
            value: stream(world_seed, purpose::VORONOI, 2),
        }
    }
}

/// Biome-map constants in the form the kernels use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BiomeMapPlan {
    /// `1 / cell_size_m`.
    pub inv_cell: f32,
    /// Latitude speed `S`, cells.
    pub speed: f32,
    /// Whether latitude applies.
    pub latitude: bool,
    /// Dispersion `d` (0 when dispersion is off).
    pub dispersion: f32,
    /// Number of biomes `K`.
    pub count: u32,
    /// Stream seeds.
    pub seeds: VoronoiSeeds,
}

impl BiomeMapPlan {
    /// The plan of a layout with `count` biomes.
    pub fn new(layout: &BiomeLayout, count: usize, world_seed: u64) -> Self {
        Self {
            inv_cell: (1.0 / layout.cell_size_m as f64) as f32,
            speed: layout.latitude_speed_cells,
            latitude: layout.latitude,
            dispersion: if layout.dispersion {
                layout.dispersion_d
            } else {
                0.0
            },
            count: count as u32,
            seeds: VoronoiSeeds::new(world_seed),
        }
    }

    /// Algorithm 1: the winning seed's cell index and floored seed position, for a point in metres.
    pub fn nearest(&self, x_m: f32, z_m: f32) -> Nearest {
        self.nearest_with(x_m, z_m, |i, j| self.seed_pos(i, j))
    }

    /// Algorithm 1 with the seed positions from `seed_at(i, j)` (hashed or cached: the same values).
    #[inline(always)]
    fn nearest_with(
        &self,
        x_m: f32,
        z_m: f32,
        seed_at: impl Fn(i32, i32) -> (f32, f32),
    ) -> Nearest {
        let x = x_m * self.inv_cell;
        let z = z_m * self.inv_cell;
        let cx = x.floor() as i32;
        let cz = z.floor() as i32;
        let mut best = f32::INFINITY;
        let mut win = Nearest {
            cell: (0, 0),
            pos: (0.0, 0.0),
        };
        for j in cz - RANGE..=cz + RANGE {
            for i in cx - RANGE..=cx + RANGE {
                let (sx, sz) = seed_at(i, j);
                let dx = sx - x;
                let dz = sz - z;
                let d = dx * dx + dz * dz;
                if d < best {
                    best = d;
                    win = Nearest {
                        cell: (i, j),
                        pos: (sx, sz),
                    };
                }
            }
        }
        win
    }

    /// Seed position of lattice cell `(i, j)`, cells.
    #[inline(always)]
    pub fn seed_pos(&self, i: i32, j: i32) -> (f32, f32) {
        (
            i as f32 + signed_unit(hash2(i, j, self.seeds.x)),
            j as f32 + signed_unit(hash2(i, j, self.seeds.z)),
        )
    }

    /// Algorithms 1 and 2: the biome of a winning seed.
    pub fn biome_of(&self, n: &Nearest) -> u8 {
        let value = self.value_of(n);
        ((value * self.count as f32) as u32).min(self.count - 1) as u8
    }

    /// Algorithms 1 and 2: the Voronoi value of a winning seed in `[0, 1]`, clamped to the
    /// latitude band when latitude applies (0 towards the pole, 1 towards the equator).
    pub fn value_of(&self, n: &Nearest) -> f32 {
        let fx = n.pos.0.floor();
        let fz = n.pos.1.floor();
        let mut value = unit(hash2(fx as i32, fz as i32, self.seeds.value));
        if self.latitude {
            let period = self.speed * 2.0;
            let lat = fz.abs() % period;
            let grad = if lat <= self.speed {
                lat / self.speed
            } else {
                2.0 - lat / self.speed
            };
            value = value
                .clamp(grad - self.dispersion, grad + self.dispersion)
                .clamp(0.0, 1.0);
        }
        value
    }

    /// Algorithm 1 for the points of a grid (metres): point `(xs[i], zs[j])` at `out[j·w + i]`,
    /// `w = xs.len()`. The same winners as [`Self::nearest`]: each run of up to [`GRID_LANES`]
    /// points of a row in one lattice cell compares the cell's 25 candidates side by side, in
    /// [`Self::nearest`]'s order and with its arithmetic (the climate lattice of `earth-1` reads
    /// thousands of nodes a coarse tile, and the candidate scan was a third of its time).
    pub fn nearest_grid(&self, xs: &[f32], zs: &[f32]) -> Vec<Nearest> {
        let fold = |v: &[f32], f: fn(f32, f32) -> f32, init| v.iter().copied().fold(init, f);
        let (x0, x1) = (
            fold(xs, f32::min, f32::INFINITY),
            fold(xs, f32::max, f32::NEG_INFINITY),
        );
        let (z0, z1) = (
            fold(zs, f32::min, f32::INFINITY),
            fold(zs, f32::max, f32::NEG_INFINITY),
        );
        let cache = (x0 <= x1 && z0 <= z1)
            .then(|| SeedCache::new(self, x0, z0, x1, z1))
            .flatten();
        let mut out = Vec::with_capacity(xs.len() * zs.len());
        let Some(cache) = cache else {
            for &z in zs {
                out.extend(xs.iter().map(|&x| self.nearest(x, z)));
            }
            return out;
        };
        let cols: Vec<(f32, i32)> = xs
            .iter()
            .map(|&x_m| {
                let x = x_m * self.inv_cell;
                (x, x.floor() as i32)
            })
            .collect();
        for &z_m in zs {
            let z = z_m * self.inv_cell;
            let cz = z.floor() as i32;
            let mut a = 0;
            while a < cols.len() {
                let cx = cols[a].1;
                let mut b = a + 1;
                while b < cols.len() && cols[b].1 == cx && b - a < GRID_LANES {
                    b += 1;
                }
                let run = &cols[a..b];
                let mut best = [f32::INFINITY; GRID_LANES];
                let mut win = [0usize; GRID_LANES];
                let candidates = cache.candidates(cx, cz);
                for (c, cand) in candidates.iter().enumerate() {
                    let (sx, sz) = cand.pos;
                    for (l, &(x, _)) in run.iter().enumerate() {
                        let dx = sx - x;
                        let dz = sz - z;
                        let d = dx * dx + dz * dz;
                        if d < best[l] {
                            best[l] = d;
                            win[l] = c;
                        }
                    }
                }
                out.extend(win[..run.len()].iter().map(|&w| candidates[w]));
                a = b;
            }
        }
        out
    }

    /// The biome at a point in metres.
    pub fn biome_at(&self, x_m: f32, z_m: f32) -> u8 {
        self.biome_of(&self.nearest(x_m, z_m))
    }
}

/// The seed a point belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearest {
    /// Lattice cell of the seed.
    pub cell: (i32, i32),
    /// Seed position, cells.
    pub pos: (f32, f32),
}

/// Seed positions of a rectangle of cells, so a grid does not re-hash them for every sample.
struct SeedCache {
    i0: i32,
    j0: i32,
    w: usize,
    pos: Vec<(f32, f32)>,
}

/// Largest seed cache built; coarse LODs, whose samples are far apart, hash directly.
const MAX_CACHED_SEEDS: usize = 4096;

impl SeedCache {
    fn new(plan: &BiomeMapPlan, x0_m: f32, z0_m: f32, x1_m: f32, z1_m: f32) -> Option<Self> {
        let i0 = (x0_m * plan.inv_cell).floor() as i32 - RANGE;
        let j0 = (z0_m * plan.inv_cell).floor() as i32 - RANGE;
        let i1 = (x1_m * plan.inv_cell).floor() as i32 + RANGE;
        let j1 = (z1_m * plan.inv_cell).floor() as i32 + RANGE;
        let w = (i1 - i0 + 1) as usize;
        let h = (j1 - j0 + 1) as usize;
        if w * h > MAX_CACHED_SEEDS {
            return None;
        }
        let mut pos = Vec::with_capacity(w * h);
        for j in j0..=j1 {
            for i in i0..=i1 {
                pos.push(plan.seed_pos(i, j));
            }
        }
        Some(Self { i0, j0, w, pos })
    }

    /// The 25 candidate seeds of lattice cell `(cx, cz)`, in [`BiomeMapPlan::nearest`]'s order
    /// (rows, then columns).
    fn candidates(&self, cx: i32, cz: i32) -> [Nearest; 25] {
        let mut out = [Nearest {
            cell: (0, 0),
            pos: (0.0, 0.0),
        }; 25];
        let mut c = 0;
        for j in cz - RANGE..=cz + RANGE {
            let row = (j - self.j0) as usize * self.w;
            for i in cx - RANGE..=cx + RANGE {
                out[c] = Nearest {
                    cell: (i, j),
                    pos: self.pos[row + (i - self.i0) as usize],
                };
                c += 1;
            }
        }
        out
    }

    /// Same result as [`BiomeMapPlan::nearest`], with seeds from the cache.
    fn nearest(&self, plan: &BiomeMapPlan, x_m: f32, z_m: f32) -> Nearest {
        plan.nearest_with(x_m, z_m, |i, j| {
            self.pos[(j - self.j0) as usize * self.w + (i - self.i0) as usize]
        })
    }

    /// Evaluates the samples of one block whose samples all lie in the same lattice cell, lanes
    /// side by side: the same 25 candidates in the same order and the same comparisons as
    /// [`Self::nearest`], so the same winners. Returns false (doing nothing) when the samples span
    /// several cells.
    #[allow(clippy::too_many_arguments)]
    fn block(
        &self,
        plan: &BiomeMapPlan,
        spacing_m: f32,
        (xa, xb): (i64, i64),
        (za, zb): (i64, i64),
        gx0: i64,
        gz0: i64,
        w: usize,
        out: &mut [u8],
    ) -> bool {
        const MAX: usize = (BLOCK * BLOCK) as usize;
        let mut xs = [0.0f32; MAX];
        let mut zs = [0.0f32; MAX];
        let mut n = 0;
        for gz in za..zb {
            for gx in xa..xb {
                xs[n] = gx as f32 * spacing_m * plan.inv_cell;
                zs[n] = gz as f32 * spacing_m * plan.inv_cell;
                n += 1;
            }
        }
        let cx = xs[0].floor() as i32;
        let cz = zs[0].floor() as i32;
        if !(0..n).all(|l| xs[l].floor() as i32 == cx && zs[l].floor() as i32 == cz) {
            return false;
        }
        let mut best = [f32::INFINITY; MAX];
        let mut win = [0u8; MAX];
        let candidates = self.candidates(cx, cz);
        for (c, cand) in candidates.iter().enumerate() {
            let (sx, sz) = cand.pos;
            for l in 0..MAX {
                let dx = sx - xs[l];
                let dz = sz - zs[l];
                let d = dx * dx + dz * dz;
                let closer = d < best[l];
                best[l] = if closer { d } else { best[l] };
                win[l] = if closer { c as u8 } else { win[l] };
            }
        }
        let biomes = candidates.map(|cand| plan.biome_of(&cand));
        let mut l = 0;
        for gz in za..zb {
            let row = (gz - gz0) as usize * w;
            for gx in xa..xb {
                out[row + (gx - gx0) as usize] = biomes[win[l] as usize];
                l += 1;
            }
        }
        true
    }
}

/// Fills `out` (row-major, `w × h`, row = z) with the biomes of the samples `(gx0 + i, gz0 + j)` of
/// the lattice with spacing `spacing_m`.
pub fn biome_grid(
    plan: &BiomeMapPlan,
    spacing_m: f32,
    gx0: i64,
    gz0: i64,
    w: usize,
    h: usize,
    out: &mut [u8],
) {
    assert_eq!(out.len(), w * h, "biome_grid: output size");
    let pos = |g: i64| g as f32 * spacing_m;
    let bx0 = gx0.div_euclid(BLOCK);
    let bz0 = gz0.div_euclid(BLOCK);
    let bx1 = (gx0 + w as i64 - 1).div_euclid(BLOCK);
    let bz1 = (gz0 + h as i64 - 1).div_euclid(BLOCK);
    let cw = (bx1 - bx0 + 2) as usize;
    let ch = (bz1 - bz0 + 2) as usize;
    let cache = SeedCache::new(
        plan,
        pos(bx0 * BLOCK),
        pos(bz0 * BLOCK),
        pos((bx1 + 1) * BLOCK),
        pos((bz1 + 1) * BLOCK),
    );
    let nearest = |x: f32, z: f32| match &cache {
        Some(c) => c.nearest(plan, x, z),
        None => plan.nearest(x, z),
    };
    let mut corners = Vec::with_capacity(cw * ch);
    for cz in 0..ch {
        for cx in 0..cw {
            let gx = (bx0 + cx as i64) * BLOCK;
            let gz = (bz0 + cz as i64) * BLOCK;
            corners.push(nearest(pos(gx), pos(gz)));
        }
    }
    let mut memo: Option<((i32, i32), u8)> = None;
    for bz in bz0..=bz1 {
        for bx in bx0..=bx1 {
            let ci = ((bz - bz0) as usize) * cw + (bx - bx0) as usize;
            let c = [
                corners[ci],
                corners[ci + 1],
                corners[ci + cw],
                corners[ci + cw + 1],
            ];
            let uniform = c.iter().all(|n| n.cell == c[0].cell);
            // Neighbouring blocks mostly share their seed: look its biome up once.
            let fill = match memo {
                Some((cell, b)) if cell == c[0].cell => b,
                _ => {
                    let b = plan.biome_of(&c[0]);
                    memo = Some((c[0].cell, b));
                    b
                }
            };
            let xa = (bx * BLOCK).max(gx0);
            let xb = ((bx + 1) * BLOCK).min(gx0 + w as i64);
            let za = (bz * BLOCK).max(gz0);
            let zb = ((bz + 1) * BLOCK).min(gz0 + h as i64);
            if uniform {
                for gz in za..zb {
                    let row = (gz - gz0) as usize * w;
                    out[row + (xa - gx0) as usize..row + (xb - gx0) as usize].fill(fill);
                }
                continue;
            }
            let done = match &cache {
                Some(c) => c.block(plan, spacing_m, (xa, xb), (za, zb), gx0, gz0, w, out),
                None => false,
            };
            if !done {
                for gz in za..zb {
                    let row = (gz - gz0) as usize * w;
                    for gx in xa..xb {
                        out[row + (gx - gx0) as usize] = plan.biome_of(&nearest(pos(gx), pos(gz)));
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::world::WorldParams;

    fn plan() -> BiomeMapPlan {
        let w = WorldParams::classic();
        BiomeMapPlan::new(&w.layout, w.biomes.len(), 42)
    }

    #[test]
    fn nearest_grid_picks_the_pointwise_winners() {
        let p = plan();
        // Node-like grids: spacings below, near and above the cell, negative coordinates, a
        // grid too wide for the seed cache (pointwise fallback).
        for (step, x0, z0, n) in [
            (97.0f32, -3000.0f32, 1200.0f32, 40usize),
            (512.0, -20_000.0, -9000.0, 30),
            (4096.0, -150_000.0, 40_000.0, 24),
            (4096.0, -4e6, -4e6, 300),
        ] {
            let xs: Vec<f32> = (0..n).map(|i| x0 + i as f32 * step).collect();
            let zs: Vec<f32> = (0..n / 2).map(|j| z0 + j as f32 * step * 1.3).collect();
            let grid = p.nearest_grid(&xs, &zs);
            assert_eq!(grid.len(), xs.len() * zs.len());
            for (j, &z) in zs.iter().enumerate() {
                for (i, &x) in xs.iter().enumerate() {
                    assert_eq!(grid[j * xs.len() + i], p.nearest(x, z), "({x}, {z}) m");
                }
            }
        }
    }

    #[test]
    fn grid_equals_pointwise_where_blocks_are_uniform_and_is_window_independent() {
        let p = plan();
        let mut a = vec![0u8; 40 * 40];
        biome_grid(&p, 16.0, -20, -20, 40, 40, &mut a);
        let mut b = vec![0u8; 20 * 20];
        biome_grid(&p, 16.0, -7, -3, 20, 20, &mut b);
        for j in 0..20 {
            for i in 0..20 {
                assert_eq!(b[j * 20 + i], a[(j + 17) * 40 + i + 13]);
            }
        }
        let differing = a
            .iter()
            .enumerate()
            .filter(|(k, v)| {
                let (i, j) = ((k % 40) as i64 - 20, (k / 40) as i64 - 20);
                **v != p.biome_at(i as f32 * 16.0, j as f32 * 16.0)
            })
            .count();
        assert!(
            differing <= 4,
            "{differing} samples differ from pointwise evaluation"
        );
    }

    #[test]
    fn cached_seeds_give_the_same_map_as_direct_hashing() {
        let p = plan();
        for (spacing, gx0, gz0) in [
            (1.0f32, -300i64, 1000i64),
            (8.0, -40, -40),
            (8.0, 300, 500),
            (64.0, -50, 20),
            (4096.0, -30, -30),
        ] {
            let mut a = vec![0u8; 67 * 67];
            biome_grid(&p, spacing, gx0, gz0, 67, 67, &mut a);
            for (k, v) in a.iter().enumerate() {
                let (gx, gz) = (gx0 + (k % 67) as i64, gz0 + (k / 67) as i64);
                let (x, z) = (gx as f32 * spacing, gz as f32 * spacing);
                let bx = gx.div_euclid(BLOCK) * BLOCK;
                let bz = gz.div_euclid(BLOCK) * BLOCK;
                let corner = |dx: i64, dz: i64| {
                    p.nearest((bx + dx) as f32 * spacing, (bz + dz) as f32 * spacing)
                };
                let c = [
                    corner(0, 0),
                    corner(BLOCK, 0),
                    corner(0, BLOCK),
                    corner(BLOCK, BLOCK),
                ];
                let want = if c.iter().all(|n| n.cell == c[0].cell) {
                    p.biome_of(&c[0])
                } else {
                    p.biome_at(x, z)
                };
                assert_eq!(*v, want, "sample {gx},{gz} at spacing {spacing}");
            }
        }
    }

    #[test]
    fn without_dispersion_biomes_are_latitude_bands() {
        let w = WorldParams::classic();
        let mut layout = w.layout.clone();
        layout.dispersion = false;
        let p = BiomeMapPlan::new(&layout, 4, 9);
        // Near the pole (value 0) every sample is biome 0; near the equator, biome 3.
        for i in -20..20 {
            let x = i as f32 * 300.0;
            let n = p.nearest(x, 0.3 * 512.0);
            if n.pos.1.floor().abs() < 1.0 {
                assert_eq!(p.biome_of(&n), 0);
            }
        }
        let mut seen = [0usize; 4];
        for i in 0..400 {
            seen[p.biome_at(i as f32 * 97.0, 8.0 * 512.0 + (i % 7) as f32) as usize] += 1;
        }
        assert!(seen[3] > seen[0] * 5, "equator should be desert: {seen:?}");
    }
}
