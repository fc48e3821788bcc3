//! The carve of a whole job's samples, up to [`LANES`] at a time: the samples are grouped by bin, and
//! each bin's pruned pieces ([`RiverJob::pruned`]) are applied to its samples side by side, in
//! loops with no branch that depends on a lane, so LLVM vectorises them.
//!
//! Every lane performs [`RiverJob::carve_pruned`]'s operations in its order (Rust never
//! contracts `a * b + c` into a fused multiply-add), and a branch of the scalar code becomes a
//! select between the values both of its arms compute, so every sample gets
//! [`RiverJob::carve_pruned`]'s bits (tested against [`RiverJob::carve_one`] in
//! `tests/rivers.rs`). Samples in a bin no piece reaches, or outside the bins, keep their height,
//! which is what the scalar carve returns for them (`h.max(h − CARVE_MAX_M)` is `h`).

use super::super::super::fractal::lattice_n;
use super::carve::{foot, smoothstep, spur_step, Piece, RiverJob, SKIP_MARGIN_M};
use super::shores::LakeField;
use super::{CARVE_MAX_M, WALL_NOISE_CLAMP, WALL_NOISE_INV_M};

/// Samples carved side by side: a bin's 8 × 8 samples at once (LLVM vectorises a loop this long;
/// it unrolls a loop of eight and then does not).
pub const LANES: usize = 64;
/// Lanes of a bin of at most 4 × 4 samples.
const SMALL_LANES: usize = 16;

/// `x.clamp(lo, hi)` without the check that `lo ≤ hi` (which the scalar code makes only where it
/// uses the value): the same two comparisons in the same order, so the same bits.
#[inline(always)]
fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    let x = if x < lo { lo } else { x };
    if x > hi {
        hi
    } else {
        x
    }
}

impl RiverJob {
    /// Carves the grid of samples at `(xs[i], zs[j])` (metres) whose heights are
    /// `heights[j · xs.len() + i]`: each gets [`RiverJob::carve_pruned`] with the bins pruned
    /// for these heights ([`RiverJob::pruned`]), bit for bit (the lake shores shape every height
    /// first, as `carve_pruned` does).
    pub fn carve_grid(&self, xs: &[f32], zs: &[f32], heights: &mut [f32]) {
        self.carve_grid_fields(xs, zs, heights);
    }

    /// [`RiverJob::carve_grid`], returning the lake field of each sample that the shores read
    /// (row-major; empty where the world has no shaped shores or no lake is near the grid).
    pub fn carve_grid_fields(
        &self,
        xs: &[f32],
        zs: &[f32],
        heights: &mut [f32],
    ) -> Vec<Option<LakeField>> {
        assert_eq!(heights.len(), xs.len() * zs.len(), "a grid of heights");
        // The lake shores first: the carve reads the heights they shape (`carve_pruned`), and
        // with sills the lake level and sill weight of each sample (empty: none).
        let (mut sill_level, mut sill_s) = (Vec::new(), Vec::new());
        let mut fields = Vec::new();
        if self.shores && !self.lakes.is_empty() {
            if self.sills {
                sill_level = vec![0.0f32; heights.len()];
                sill_s = vec![0.0f32; heights.len()];
            }
            fields = vec![None; heights.len()];
            for (j, (row, row_fields)) in heights
                .chunks_mut(xs.len())
                .zip(fields.chunks_mut(xs.len()))
                .enumerate()
            {
                self.lake_field_row(xs, zs[j], row_fields);
                for (i, h) in row.iter_mut().enumerate() {
                    let sill;
                    (*h, sill) = self.shore_sill_of(row_fields[i], *h);
                    if self.sills {
                        let v = j * xs.len() + i;
                        (sill_level[v], sill_s[v]) = (sill.level, sill.s);
                    }
                }
            }
        }
        if self.bin_start.is_empty() {
            return fields;
        }
        // `bin_index` one axis at a time: a sample's bin is its row's bin row and its column's
        // bin column.
        let axis = |v: &[f32], origin: f32, n: usize| -> Vec<Option<usize>> {
            v.iter()
                .map(|&c| {
                    let b = ((c - origin) / self.bin_m).floor();
                    (b >= 0.0 && b < n as f32).then_some(b as usize)
                })
                .collect()
        };
        let cols = axis(xs, self.x0, self.bins_w);
        let rows = axis(zs, self.z0, self.bins_h);
        let bins = self.bin_start.len() - 1;
        let bin_of = |v: usize| -> Option<usize> {
            let (i, j) = (v % xs.len(), v / xs.len());
            Some(rows[j]? * self.bins_w + cols[i]?)
        };
        let mut h_max = vec![f32::NEG_INFINITY; bins];
        for (j, row) in heights.chunks(xs.len()).enumerate() {
            let Some(r) = rows[j] else { continue };
            for (i, &h) in row.iter().enumerate() {
                if let Some(c) = cols[i] {
                    let b = r * self.bins_w + c;
                    h_max[b] = h_max[b].max(h);
                }
            }
        }
        let pruned = self.pruned_for(&h_max);
        // The samples of each bin that some piece reaches, grouped by a counting sort.
        let reached = |b: usize| pruned.start[b] < pruned.start[b + 1];
        let mut first = vec![0u32; bins + 1];
        for v in 0..heights.len() {
            if let Some(b) = bin_of(v).filter(|&b| reached(b)) {
                first[b + 1] += 1;
            }
        }
        for b in 0..bins {
            first[b + 1] += first[b];
        }
        let mut next = first.clone();
        let mut order = vec![0u32; first[bins] as usize];
        for v in 0..heights.len() {
            if let Some(b) = bin_of(v).filter(|&b| reached(b)) {
                order[next[b] as usize] = v as u32;
                next[b] += 1;
            }
        }
        for b in (0..bins).filter(|&b| reached(b)) {
            let entries = &pruned.entries[pruned.start[b] as usize..pruned.start[b + 1] as usize];
            let sills = (&sill_level[..], &sill_s[..]);
            for group in order[first[b] as usize..first[b + 1] as usize].chunks(LANES) {
                // A bin of 4 × 4 samples or fewer (coarse LODs, whose bins are a node spacing)
                // in a quarter of the lanes.
                if group.len() <= SMALL_LANES {
                    self.carve_group::<SMALL_LANES>(entries, group, xs, zs, sills, heights);
                } else {
                    self.carve_group::<LANES>(entries, group, xs, zs, sills, heights);
                }
            }
        }
        fields
    }

    /// Carves the samples `group` (indices into the grid of `xs` × `zs`, at most `N`) of one bin
    /// whose pruned pieces are `entries`, `N` side by side; `sills` holds each sample's sill
    /// level and weight (empty: none).
    fn carve_group<const N: usize>(
        &self,
        entries: &[(u32, f32)],
        group: &[u32],
        xs: &[f32],
        zs: &[f32],
        sills: (&[f32], &[f32]),
        heights: &mut [f32],
    ) {
        let (mut x, mut z, mut h) = ([0.0; N], [0.0; N], [0.0; N]);
        let (mut sl, mut ss) = ([0.0; N], [0.0; N]);
        for (l, &v) in group.iter().enumerate() {
            let v = v as usize;
            (x[l], z[l]) = (xs[v % xs.len()], zs[v / xs.len()]);
            h[l] = heights[v];
            if !sills.1.is_empty() {
                (sl[l], ss[l]) = (sills.0[v], sills.1[v]);
            }
        }
        let c = self.carve_lanes(entries, &x, &z, &h, (&sl, &ss));
        for (l, &v) in group.iter().enumerate() {
            heights[v as usize] = c[l];
        }
    }

    /// [`RiverJob::wall_width`] of `N` samples.
    fn wall_lanes<const N: usize>(&self, x: &[f32; N], z: &[f32; N]) -> [f32; N] {
        if self.wall_noise == 0.0 {
            return [0.0; N];
        }
        let qx: [f32; N] = std::array::from_fn(|l| x[l] * WALL_NOISE_INV_M);
        let qz: [f32; N] = std::array::from_fn(|l| z[l] * WALL_NOISE_INV_M);
        let mut n = [0.0; N];
        lattice_n(&qx, &qz, self.wall_seed, &mut n);
        n.map(|v| {
            self.wall_noise * (v.clamp(-WALL_NOISE_CLAMP, WALL_NOISE_CLAMP) + WALL_NOISE_CLAMP)
        })
    }

    /// [`RiverJob::carve_pruned`] of `N` samples of one bin, whose pruned pieces are
    /// `entries`, with the sills' levels and weights `sill` (weight 0: none): the lowest of the
    /// pieces' profiles, each applied where the scalar code applies it, at most
    /// [`CARVE_MAX_M`] below the height.
    fn carve_lanes<const N: usize>(
        &self,
        entries: &[(u32, f32)],
        x: &[f32; N],
        z: &[f32; N],
        h: &[f32; N],
        sill: (&[f32; N], &[f32; N]),
    ) -> [f32; N] {
        let wall = self.wall_lanes(x, z);
        let mut c = *h;
        for &(i, r2) in entries {
            // A copy: LLVM does not vectorise the loop below while it reads the piece through a
            // reference it cannot prove unaliased with `c`.
            let p = &{ self.pieces[i as usize] };
            if p.spur_a == 0.0 && p.spur_b == 0.0 {
                piece_lanes::<false, N>(p, r2, x, z, h, &wall, sill, &mut c);
            } else {
                piece_lanes::<true, N>(p, r2, x, z, h, &wall, sill, &mut c);
            }
        }
        for l in 0..N {
            c[l] = c[l].max(h[l] - CARVE_MAX_M);
        }
        c
    }
}

/// Piece `p`'s profile ([`super::carve::profile`] with the walls' added width `wall`, the
/// piece's spurs where `SPURS`, and the sills `sill`) applied to `N` samples of heights `h`
/// whose carve so far is `c`, where [`RiverJob::carve_pruned`] applies it (`r2`: the piece's
/// pruned squared radius). Without spurs (both ends' values 0) the wall's step is the plain
/// smoothstep, which the spur step with `s = 0` equals bit for bit; the two loops differ only
/// in cost.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn piece_lanes<const SPURS: bool, const N: usize>(
    p: &Piece,
    r2: f32,
    x: &[f32; N],
    z: &[f32; N],
    h: &[f32; N],
    wall: &[f32; N],
    sill: (&[f32; N], &[f32; N]),
    c: &mut [f32; N],
) {
    let (sill_level, sill_s) = sill;
    let reach2 = p.reach * p.reach;
    let channel2 = p.half_width * p.half_width * 1.001;
    let floor_w = p.wa.min(p.wb) - SKIP_MARGIN_M;
    for l in 0..N {
        let (t, d2) = foot(p, x[l], z[l]);
        let (hl, cl) = (h[l], c[l]);
        // `profile_at_foot`, both arms of each branch computed.
        let d = d2.sqrt();
        let w = p.wa + (p.wb - p.wa) * t;
        let floor = p
            .half_width
            .max(p.floodplain + (p.floodplain_b - p.floodplain) * t);
        let slope = p.slope_a + (p.slope_b - p.slope_a) * t;
        let v = clamp(floor + (hl - w) / slope + wall[l], p.valley, p.reach);
        let g = if SPURS {
            spur_step(floor, v, d, p.spur_a + (p.spur_b - p.spur_a) * t)
        } else {
            smoothstep(floor, v, d)
        };
        let walled = if (hl > w) & (d < v) {
            w + (hl - w) * g
        } else {
            hl
        };
        let r = d / p.half_width;
        let silled = walled + (walled.max(hl.min(sill_level[l])) - walled) * sill_s[l];
        let cut = if d < p.half_width {
            walled.min(w - p.depth * (1.0 - r * r))
        } else if sill_s[l] > 0.0 {
            silled
        } else {
            walled
        };
        let profile = if d2 >= reach2 { hl } else { cut };
        // `carve_pruned`'s test of whether the piece can lower the sample.
        let applies = (d2 < r2) & ((d2 <= channel2) | (cl > floor_w));
        c[l] = if applies { cl.min(profile) } else { cl };
    }
}
