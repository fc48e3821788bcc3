//! Voxelization (Becher §4.2): proxy triangles → sparse constraints in `N`, `B`, `S`, `R`.
//!
//! Every triangle is tested against the cells (cubes of side `spacing` centred on the samples)
//! its bounding box touches with the separating-axis triangle–box test of Akenine-Möller (*Fast
//! 3D triangle-box overlap testing*, JGT 2001). The hits are first gathered as `(sample,
//! triangle)` pairs and then averaged per sample — the paper's linked list, sorted instead of
//! linked, so the result does not depend on the gathering order:
//!
//! - `N`: the normalised sum of the triangles' outward normals (normals of both ribbons of a
//!   curve average along its spine, as the paper notes) → `Ω_N`;
//! - `B`: left and right bitangents are averaged separately to `b̂_l`, `b̂_r`, then combined into
//!   the `b_avg` maximising `|b̂_l·b_avg| + |b̂_r·b_avg|`: `b̂_l + b̂_r` if the angle between them is
//!   below 90°, `b̂_l − b̂_r` otherwise;
//! - `R`: mean `α`, `β`; the material is the most frequent one (ties: the smaller id) → `Ω_R`;
//! - `S`: for samples hit by seed triangles, the mean signed distance from the sample to those
//!   triangles' planes → `Ω_S`. Deviation: the paper stores 0 ("S_x = 0" for intersected
//!   cells); the plane distance is exact for planar input and keeps `|∇S| ≈ 1` at the seeds.
//!
//! Priority passes: the inputs come in passes of decreasing priority (feature curves, input
//! meshes, heightfield). A triangle of a later pass is not gathered into a sample if a sample
//! within `dead_zone_m` of it (Euclidean, in metres; the paper's user-defined object-space
//! radius) was hit by an earlier pass — Fig. 6's dead zone that lets curves carve into a
//! heightfield.

use super::edt::squared_distance;
use super::grid::{dot, normalize, sub, Grid};
use super::proxy::{ProxyTriangle, Side};
use rayon::prelude::*;

/// Triangles per parallel task of the gathering.
const GATHER_CHUNK: usize = 64;

/// The sparse fields after voxelization. Unconstrained samples hold zeros.
#[derive(Clone, Debug)]
pub struct Voxelized {
    /// `N` as three component arrays (unit vectors in `Ω_N`).
    pub normal: [Vec<f32>; 3],
    /// `B` as three component arrays (unit vectors where a curve was gathered).
    pub bitangent: [Vec<f32>; 3],
    /// `S` (metres) in `Ω_S`.
    pub surface: Vec<f32>,
    /// `α` in `Ω_R`.
    pub alpha: Vec<f32>,
    /// `β` in `Ω_R`.
    pub beta: Vec<f32>,
    /// Material in `Ω_R`, [`NO_MATERIAL`] elsewhere.
    pub material: Vec<u16>,
    /// `Ω_N` membership (1 = constrained).
    pub omega_n: Vec<u8>,
    /// `Ω_R` membership.
    pub omega_r: Vec<u8>,
    /// `Ω_S` membership.
    pub omega_s: Vec<u8>,
    /// How many triangles each pass gathered at least once, and how many were dropped entirely
    /// by the dead zone.
    pub pass_stats: Vec<PassStats>,
}

/// Counters of one priority pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PassStats {
    /// Triangles in the pass.
    pub triangles: usize,
    /// (sample, triangle) pairs gathered.
    pub gathered: usize,
    /// (sample, triangle) pairs dropped inside the dead zone of an earlier pass.
    pub dropped: usize,
}

/// Material id of a sample no material reached.
pub const NO_MATERIAL: u16 = u16::MAX;

/// Akenine-Möller's triangle–box overlap test: box centred at the origin with half side `h`,
/// triangle already translated by minus the box centre. The separating axes are tried cheapest
/// and most discriminating first (the box's faces, the triangle's plane, then the nine edge
/// cross products); the result is their conjunction, so the order changes no answer.
#[inline]
fn tri_box(h: f32, v: [[f32; 3]; 3]) -> bool {
    // The box's face normals.
    for k in 0..3 {
        let lo = v[0][k].min(v[1][k]).min(v[2][k]);
        let hi = v[0][k].max(v[1][k]).max(v[2][k]);
        if lo > h || hi < -h {
            return false;
        }
    }
    let e = [sub(v[1], v[0]), sub(v[2], v[1]), sub(v[0], v[2])];
    // The triangle's plane.
    let n = super::grid::cross(e[0], e[1]);
    let d = dot(n, v[0]);
    let r = h * (n[0].abs() + n[1].abs() + n[2].abs());
    if d.abs() > r {
        return false;
    }
    // Nine cross-product axes a × e_j for the unit axes a.
    for ej in &e {
        for axis in 0..3 {
            let a = match axis {
                0 => [0.0, -ej[2], ej[1]],
                1 => [ej[2], 0.0, -ej[0]],
                _ => [-ej[1], ej[0], 0.0],
            };
            let p: [f32; 3] = [dot(a, v[0]), dot(a, v[1]), dot(a, v[2])];
            let lo = p[0].min(p[1]).min(p[2]);
            let hi = p[0].max(p[1]).max(p[2]);
            let r = h * (a[0].abs() + a[1].abs() + a[2].abs());
            if lo > r || hi < -r {
                return false;
            }
        }
    }
    true
}

/// Samples whose cells the triangle intersects, in index order.
pub fn cells_of(grid: &Grid, t: &ProxyTriangle, out: &mut Vec<usize>) {
    out.clear();
    let g = t.v.map(|p| grid.to_grid(p));
    let mut lo = [0usize; 3];
    let mut hi = [0usize; 3];
    for k in 0..3 {
        let mn = g[0][k].min(g[1][k]).min(g[2][k]);
        let mx = g[0][k].max(g[1][k]).max(g[2][k]);
        let n = grid.dims[k] as f32;
        if mx < -0.5 || mn > n - 0.5 {
            return;
        }
        lo[k] = (mn + 0.5).floor().max(0.0) as usize;
        hi[k] = ((mx + 0.5).floor().max(0.0) as usize).min(grid.dims[k] - 1);
    }
    for z in lo[2]..=hi[2] {
        for y in lo[1]..=hi[1] {
            for x in lo[0]..=hi[0] {
                let c = [x as f32, y as f32, z as f32];
                let v = [sub(g[0], c), sub(g[1], c), sub(g[2], c)];
                // A hair over half a cell so that a triangle on a cell face counts for both.
                if tri_box(0.5 + 1e-5, v) {
                    out.push(grid.index(x, y, z));
                }
            }
        }
    }
}

/// Which of the `candidates` (sample indices) lie within `r` samples (Euclidean) of an
/// `occupied` sample. Only candidates inside the occupied samples' bounding box grown by
/// `g = ⌊r⌋ + 1` samples can be; for those, the exact distance transform
/// ([`squared_distance`]) is computed on their bounding box grown by `g`, which contains every
/// occupied sample within `r` of them, so the answer equals the whole grid's transform.
fn in_dead_zone(grid: &Grid, occupied: &[u32], candidates: &[u32], r: f32) -> Vec<bool> {
    let grow = r.floor() as usize + 1;
    let bbox = |set: &mut dyn Iterator<Item = [usize; 3]>| {
        let (mut lo, mut hi) = (grid.dims, [0usize; 3]);
        for p in set {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k] + 1);
            }
        }
        let lo = lo.map(|l| l.saturating_sub(grow));
        let hi = [0, 1, 2].map(|k| (hi[k] + grow).min(grid.dims[k]));
        (lo, hi)
    };
    let inside = |p: [usize; 3], (lo, hi): ([usize; 3], [usize; 3])| {
        (0..3).all(|k| p[k] >= lo[k] && p[k] < hi[k])
    };
    let near = bbox(&mut occupied.iter().map(|&o| grid.coords(o as usize)));
    let mut relevant = candidates
        .iter()
        .map(|&c| grid.coords(c as usize))
        .filter(|&p| inside(p, near))
        .peekable();
    if relevant.peek().is_none() {
        return vec![false; candidates.len()];
    }
    let (lo, hi) = bbox(&mut relevant);
    let bd = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    let local = |p: [usize; 3]| (p[0] - lo[0]) + bd[0] * ((p[1] - lo[1]) + bd[1] * (p[2] - lo[2]));
    let mut set = vec![0u8; bd[0] * bd[1] * bd[2]];
    for &o in occupied {
        let p = grid.coords(o as usize);
        if inside(p, (lo, hi)) {
            set[local(p)] = 1;
        }
    }
    let d2 = squared_distance(bd, &set);
    candidates
        .iter()
        .map(|&c| {
            let p = grid.coords(c as usize);
            inside(p, near) && d2[local(p)] <= r * r
        })
        .collect()
}

/// Voxelizes `passes` (highest priority first) into `grid` with a dead zone of `dead_zone_m`
/// metres around every earlier pass.
pub fn voxelize(grid: &Grid, passes: &[&[ProxyTriangle]], dead_zone_m: f32) -> Voxelized {
    let n = grid.len();
    let r = (dead_zone_m.max(0.0) / grid.spacing).max(0.0);
    let mut hits: Vec<(u32, u32, u32)> = Vec::new();
    let mut pass_stats = Vec::with_capacity(passes.len());
    for (p, tris) in passes.iter().enumerate() {
        let mut st = PassStats {
            triangles: tris.len(),
            ..Default::default()
        };
        // The triangle–cell tests run in parallel over chunks of triangles; the chunks' hits
        // are concatenated in triangle order, so the gathered list does not depend on the
        // thread count.
        let chunks: Vec<Vec<(u32, u32)>> = tris
            .par_chunks(GATHER_CHUNK)
            .enumerate()
            .map(|(k, chunk)| {
                let mut cells = Vec::new();
                let mut out = Vec::new();
                for (i, t) in chunk.iter().enumerate() {
                    cells_of(grid, t, &mut cells);
                    let ti = (k * GATHER_CHUNK + i) as u32;
                    out.extend(cells.iter().map(|&c| (c as u32, ti)));
                }
                out
            })
            .collect();
        let found: Vec<(u32, u32)> = chunks.into_iter().flatten().collect();
        // Dead zone: a pair is dropped when its sample lies within r of a sample gathered by an
        // earlier pass (exact Euclidean distance).
        let blocked = if p > 0 && !hits.is_empty() {
            let occupied: Vec<u32> = hits.iter().map(|h| h.0).collect();
            let cand: Vec<u32> = found.iter().map(|f| f.0).collect();
            in_dead_zone(grid, &occupied, &cand, r)
        } else {
            vec![false; found.len()]
        };
        for ((c, ti), b) in found.into_iter().zip(blocked) {
            if b {
                st.dropped += 1;
            } else {
                st.gathered += 1;
                hits.push((c, p as u32, ti));
            }
        }
        pass_stats.push(st);
    }
    // The keys are distinct, so the (parallel, unstable) sort is deterministic.
    hits.par_sort_unstable();

    let mut v = Voxelized {
        normal: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
        bitangent: [vec![0.0; n], vec![0.0; n], vec![0.0; n]],
        surface: vec![0.0; n],
        alpha: vec![0.0; n],
        beta: vec![0.0; n],
        material: vec![NO_MATERIAL; n],
        omega_n: vec![0; n],
        omega_r: vec![0; n],
        omega_s: vec![0; n],
        pass_stats,
    };
    let mut materials: Vec<u16> = Vec::new();
    let mut i = 0;
    while i < hits.len() {
        let c = hits[i].0 as usize;
        let mut j = i;
        let mut nsum = [0.0f32; 3];
        let (mut bl, mut br) = ([0.0f32; 3], [0.0f32; 3]);
        let (mut asum, mut bsum, mut count) = (0.0f32, 0.0f32, 0usize);
        let (mut ssum, mut scount) = (0.0f32, 0usize);
        materials.clear();
        let [x, y, z] = grid.coords(c);
        let pos = grid.position(x, y, z);
        while j < hits.len() && hits[j].0 as usize == c {
            let t = &passes[hits[j].1 as usize][hits[j].2 as usize];
            for k in 0..3 {
                nsum[k] += t.normal[k];
                match t.side {
                    Side::Left => bl[k] += t.bitangent[k],
                    Side::Right => br[k] += t.bitangent[k],
                    Side::None => {}
                }
            }
            asum += t.alpha;
            bsum += t.beta;
            count += 1;
            materials.push(t.material);
            if t.seed {
                ssum += dot(sub(pos, t.v[0]), t.normal);
                scount += 1;
            }
            j += 1;
        }
        let nn = normalize(nsum);
        if nn != [0.0; 3] {
            for k in 0..3 {
                v.normal[k][c] = nn[k];
            }
            v.omega_n[c] = 1;
        }
        let (hl, hr) = (normalize(bl), normalize(br));
        let b = if dot(hl, hr) >= 0.0 {
            normalize(super::grid::add(hl, hr))
        } else {
            normalize(sub(hl, hr))
        };
        for k in 0..3 {
            v.bitangent[k][c] = b[k];
        }
        v.alpha[c] = asum / count as f32;
        v.beta[c] = bsum / count as f32;
        materials.sort_unstable();
        let (mut best, mut best_n, mut k) = (materials[0], 0, 0);
        while k < materials.len() {
            let mut e = k;
            while e < materials.len() && materials[e] == materials[k] {
                e += 1;
            }
            if e - k > best_n {
                best = materials[k];
                best_n = e - k;
            }
            k = e;
        }
        v.material[c] = best;
        v.omega_r[c] = 1;
        if scount > 0 {
            v.surface[c] = ssum / scount as f32;
            v.omega_s[c] = 1;
        }
        i = j;
    }
    v
}
