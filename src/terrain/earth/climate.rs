//! Climate-driven biome weights of `earth-1`, the same at every LOD.
//!
//! Choroś & Topolski's extended Voronoi (Algorithms 1 and 2: latitude speed `S`, dispersion `d`,
//! [`crate::terrain::biome`]) is evaluated at the nodes of a world-anchored lattice of
//! [`NODE_SPACING_M`] (4 km), read at `z + latitude_offset_m` so the origin lies at mid-latitude, and
//! made colder with altitude: the Voronoi value (0 at the pole, 1 at the equator) falls by
//! `e / lapse_m` where `e ≥ 0` is the large-scale elevation at the node (continent and mean
//! mountain relief, [`super::macro_elevation`]). The node's biome is `⌊value · K⌋`.
//!
//! The one-hot node biomes are blurred on the node lattice with a Gaussian of radius
//! `blur_radius_m` (`σ = radius / 3`, [`crate::terrain::blur`]) and each vertex takes the
//! bilinear interpolation of the four nodes around it. The node lattice is fixed in world
//! metres, so a world point gets the same weights at every LOD and in every tile (its node cell
//! and offsets are computed in `f64` from the vertex's lattice index), and the weights change
//! smoothly over kilometres, so no LOD sees a biome step that another does not.
//!
//! **Snow lines** (worlds with `EarthParams::snow_lines: 2`). The cooling moves a mountain's
//! upper slopes into colder biomes, whose `snow_line_m` was meant for the lowlands of their own
//! latitudes (the tundra's 600 m); read there, snow would reach as far down every range. So each
//! node also keeps the snow line of its climate at sea level ([`sea_snow_lines`]): its blurred
//! weights' mean biome index plus the `e · K / lapse_m` biomes the cooling took off, read in the
//! biomes' snow lines between their centres; a vertex takes the bilinear mix of its four nodes'.
//!
//! **Shared work.** At the LOD whose vertex spacing is the node spacing (LOD 12 at a 1 m cell)
//! every vertex is a node: the weights are the nodes' own (no interpolation), and the nodes'
//! macro fields ([`NodeMacro`], the bits the height function computes at the same positions)
//! are handed to the heights, which then skip their own macro fields (`super::field`).

use super::super::biome::BiomeMapPlan;
use super::super::blur::{blur_weights, kernel};
use super::super::tile::FieldJob;
use super::EarthPlan;
use std::sync::Arc;

/// Spacing of the climate lattice, metres.
pub const NODE_SPACING_M: f64 = 4096.0;

/// Climate constants of a world.
#[derive(Clone, Debug, PartialEq)]
pub struct ClimatePlan {
    /// The Voronoi map of Algorithms 1–2 (cell size, latitude speed, dispersion).
    pub map: BiomeMapPlan,
    /// Added to `z` before the map is read, metres.
    pub latitude_offset_m: f32,
    /// Elevation that makes the climate one pole-to-equator range colder, metres.
    pub lapse_m: f32,
    /// Blur kernel on the node lattice, `2r + 1` taps.
    pub kernel: Vec<f32>,
    /// Number of biomes `K`.
    pub count: usize,
    /// The biomes' snow lines (metres, clamped to ±10⁶) where the world reads the sea-level
    /// climate's snow line (`EarthParams::snow_lines: 2`, [`sea_snow_lines`]); `None` otherwise.
    pub sea_snow: Option<Vec<f32>>,
}

impl ClimatePlan {
    /// The climate of a layout with `count` biomes.
    pub fn new(
        map: BiomeMapPlan,
        blur_radius_m: f32,
        latitude_offset_m: f32,
        lapse_m: f32,
        count: usize,
        sea_snow: Option<Vec<f32>>,
    ) -> Self {
        let r = (blur_radius_m as f64 / NODE_SPACING_M).round() as usize;
        let sigma = (blur_radius_m as f64 / 3.0 / NODE_SPACING_M).max(1e-3) as f32;
        Self {
            map,
            latitude_offset_m,
            lapse_m,
            kernel: kernel(r, sigma),
            count,
            sea_snow,
        }
    }
}

/// The macro fields (elevation, relief amplitude, ridge mix: [`super::kernel`]'s `macro_fields`)
/// of the climate nodes of a grid, row-major like the node biomes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NodeMacro {
    /// Node columns (the blur margin included).
    pub w: usize,
    /// Elevation `e(c)` at each node.
    pub elev: Vec<f32>,
    /// Relief amplitude `A` at each node.
    pub amp: Vec<f32>,
    /// Ridge mix `ρ` at each node.
    pub ridge: Vec<f32>,
}

/// The biomes of the climate nodes of a grid, `(cols[i], rows[j])` at `out[j·w + i]` (metres,
/// node multiples; `w = cols.len()`), and the nodes' macro fields they were read from.
fn node_biomes(plan: &EarthPlan, cols: &[f32], rows: &[f32], out: &mut [u8]) -> NodeMacro {
    let c = &plan.climate;
    let (mut xs, mut zs) = (Vec::with_capacity(out.len()), Vec::with_capacity(out.len()));
    for &z in rows {
        xs.extend_from_slice(cols);
        zs.extend(std::iter::repeat_n(z, cols.len()));
    }
    let mut m = NodeMacro {
        w: cols.len(),
        elev: vec![0.0f32; xs.len()],
        amp: vec![0.0f32; xs.len()],
        ridge: vec![0.0f32; xs.len()],
    };
    super::macro_fields_batch(plan, &xs, &zs, &mut m.elev, &mut m.amp, &mut m.ridge);
    let shifted: Vec<f32> = rows.iter().map(|z| z + c.latitude_offset_m).collect();
    let nearest = c.map.nearest_grid(cols, &shifted);
    for (n, id) in out.iter_mut().enumerate() {
        let elevation = super::macro_elevation(m.elev[n], m.amp[n], m.ridge[n]);
        let warmth = c.map.value_of(&nearest[n]);
        let v = (warmth - elevation.max(0.0) / c.lapse_m).clamp(0.0, 1.0);
        *id = ((v * c.count as f32) as usize).min(c.count - 1) as u8;
    }
    m
}

/// Biome weights of a job's samples, `out[v · K + b]`, vertex-major like `Field::weights`.
pub fn weights(plan: &EarthPlan, spacing_m: f32, job: FieldJob) -> Vec<f32> {
    weights_and_macro(plan, spacing_m, job).0
}

/// Whether every sample of a LOD with vertex spacing `spacing_m` is a climate node (the
/// spacing is the node spacing): then the weights need no interpolation and the nodes' macro
/// fields are the samples'.
pub fn samples_are_nodes(spacing_m: f32) -> bool {
    spacing_m as f64 == NODE_SPACING_M
}

/// Largest side, in nodes, of a window kept in [`WINDOWS`].
const WINDOW_MAX_NODES: usize = 3;
/// Byte budget of [`WINDOWS`].
const WINDOWS_BYTES: u64 = 16 << 20;

/// A node window of a job: the blurred biome weights of its nodes (the nodes around its
/// samples) and the macro fields of those nodes with the blur margin.
#[derive(Debug)]
pub struct NodeWindow {
    /// First node column (world node index).
    pub i0: i64,
    /// First node row.
    pub j0: i64,
    /// Node columns (the blur margin left out).
    pub nw: usize,
    /// Blurred weights, `K` per node, row-major.
    pub weights: Vec<f32>,
    /// The nodes' macro fields, the blur margin included.
    pub node_macro: NodeMacro,
    /// The sea-level climate's snow line at each node, metres, row-major like the weights
    /// ([`sea_snow_lines`]); empty unless the world reads it.
    pub sea_line: Vec<f32>,
}

type Window = Arc<NodeWindow>;

/// A window's key: the world's fingerprint, its first and last node column and row.
type WindowKey = (u64, i64, i64, i64, i64);

/// The node windows of small jobs, by the world's fingerprint ([`EarthPlan::fingerprint`]) and
/// the window's first and last node column and row: process-wide, bounded in bytes, like the
/// river network's block caches. A window is a pure function of its node indices and the world,
/// so the cache changes the time, never the bytes: it saves a LOD-0 tile the macro fields and
/// the Voronoi map at about a hundred nodes (`bench tiles`' LOD-0 figure fell by about 2 %).
static WINDOWS: std::sync::LazyLock<moka::sync::Cache<WindowKey, Window>> =
    std::sync::LazyLock::new(|| {
        moka::sync::Cache::builder()
            .max_capacity(WINDOWS_BYTES)
            .weigher(|_, w: &Window| {
                let m = &w.node_macro;
                let floats =
                    w.weights.len() + m.elev.len() + m.amp.len() + m.ridge.len() + w.sea_line.len();
                (64 + 4 * floats).min(u32::MAX as usize) as u32
            })
            .build()
    });

/// Empties the cache of node windows (the results stay the same).
pub fn clear_cache() {
    WINDOWS.invalidate_all();
    // Removed at once, so they no longer count against the budget ([`super::clear_caches`]).
    WINDOWS.run_pending_tasks();
}

/// The climate node of lattice index `g` of a LOD with vertex spacing `spacing_m`, as a
/// fractional node coordinate (computed in `f64`, so every LOD gives a world point the same).
fn node_coord(spacing_m: f32, g: i64) -> f64 {
    g as f64 * spacing_m as f64 / NODE_SPACING_M
}

/// The node (counted from node `first`) and the offset from it of each of the `n` lattice
/// indices from `g0`.
fn node_offsets(spacing_m: f32, g0: i64, n: usize, first: i64) -> Vec<(usize, f32)> {
    (0..n as i64)
        .map(|i| {
            let f = node_coord(spacing_m, g0 + i);
            let n = f.floor();
            ((n as i64 - first) as usize, (f - n) as f32)
        })
        .collect()
}

/// The node window of `job`: the blurred weights, macro fields and sea-level snow lines of the
/// nodes around its samples (kept in [`WINDOWS`] when small).
pub fn node_window(plan: &EarthPlan, spacing_m: f32, job: FieldJob) -> Arc<NodeWindow> {
    let k = plan.climate.count;
    let r = plan.climate.kernel.len() / 2;
    let node = |g: i64| node_coord(spacing_m, g);
    let (i0, j0) = (node(job.gx0).floor() as i64, node(job.gz0).floor() as i64);
    let i1 = node(job.gx0 + job.w as i64 - 1).floor() as i64 + 1;
    let j1 = node(job.gz0 + job.h as i64 - 1).floor() as i64 + 1;
    // Node ids with the blur margin, then blurred weights of nodes i0..=i1, j0..=j1.
    let (bw, bh) = (
        (i1 - i0 + 1) as usize + 2 * r,
        (j1 - j0 + 1) as usize + 2 * r,
    );
    let (nw, nh) = (bw - 2 * r, bh - 2 * r);
    let nodes_of = || {
        let at = |g: i64| (g as f64 * NODE_SPACING_M) as f32;
        let cols: Vec<f32> = (0..bw as i64).map(|i| at(i0 - r as i64 + i)).collect();
        let rows: Vec<f32> = (0..bh as i64).map(|j| at(j0 - r as i64 + j)).collect();
        let mut ids = vec![0u8; bw * bh];
        let node_macro = node_biomes(plan, &cols, &rows, &mut ids);
        let mut weights = vec![0.0f32; nw * nh * k];
        blur_weights(&ids, bw, bh, &plan.climate.kernel, k, &mut weights);
        let sea_line = match &plan.climate.sea_snow {
            Some(lines) => node_sea_lines(plan, lines, &weights, &node_macro, (nw, nh, r)),
            None => Vec::new(),
        };
        Arc::new(NodeWindow {
            i0,
            j0,
            nw,
            weights,
            node_macro,
            sea_line,
        })
    };
    // A window of at most 3 × 3 nodes (every tile up to LOD 6, whose samples lie in one or two
    // node cells a side) is shared by the tiles in the same cells: 4,096 LOD-0 tiles a cell.
    if nw <= WINDOW_MAX_NODES && nh <= WINDOW_MAX_NODES {
        WINDOWS.get_with((plan.fingerprint, i0, j0, i1, j1), nodes_of)
    } else {
        nodes_of()
    }
}

/// Biome weights of a job's samples, `out[v · K + b]`, vertex-major like `Field::weights`, and
/// the climate nodes' macro fields (the blur margin included): where [`samples_are_nodes`],
/// sample `(i, j)` is node `(i + r, j + r)` of them, `r` the blur kernel's radius, and its macro
/// fields are those of the height function at the sample, the same bits (a node at lattice
/// index `g` sits at `(g · 4096) as f32`, which is `g as f32 · 4096`, the sample's position).
pub fn weights_and_macro(
    plan: &EarthPlan,
    spacing_m: f32,
    job: FieldJob,
) -> (Vec<f32>, Arc<NodeWindow>) {
    let k = plan.climate.count;
    let window = node_window(plan, spacing_m, job);
    let (i0, j0, nw) = (window.i0, window.j0, window.nw);
    let nodes = &window.weights;
    let nh = nodes.len() / (nw * k).max(1);
    let mut out = vec![0.0f32; job.w * job.h * k];
    if samples_are_nodes(spacing_m) {
        // Sample `(i, j)` is node `(i, j)` and every offset is 0: the lerps below would add
        // `(b − a) · 0 = ±0` to `a` (which is never −0), giving `a`, so the weights are the
        // node's, clamped, the same bits.
        for j in 0..job.h {
            for i in 0..job.w {
                let (v, n) = ((j * job.w + i) * k, (j * nw + i) * k);
                for bi in 0..k {
                    out[v + bi] = nodes[n + bi].clamp(0.0, 1.0);
                }
            }
        }
        return (out, window);
    }
    // Each column's node and offset, computed once for all rows.
    let cols = node_offsets(spacing_m, job.gx0, job.w, i0);
    // A node cell whose four corners hold the same weights gives every sample in it those
    // weights: the lerps below add `(a − a) · t = +0` to `a` (never −0: blurred weights are sums
    // of non-negative products), so copying them is the same bits, and most tiles lie in one.
    let node_at = |n: usize| &nodes[n * k..(n + 1) * k];
    let uniform: Vec<bool> = (0..nw * nh)
        .map(|n| {
            let (ri, rj) = (n % nw, n / nw);
            ri + 1 < nw
                && rj + 1 < nh
                && [n + 1, n + nw, n + nw + 1].iter().all(|&m| {
                    node_at(n).iter().zip(node_at(m)).all(|(a, b)| {
                        a.to_bits() == b.to_bits() && a.to_bits() != (-0.0f32).to_bits()
                    })
                })
        })
        .collect();
    // Each column's lerps along x on the node row above and below it, computed once for all
    // rows in the same node row: `(top, bottom)` of biome `bi` at `[(i · k + bi) · 2]`.
    let mut lerps = vec![0.0f32; job.w * k * 2];
    let mut lerps_row = usize::MAX;
    for (j, (rj, tz)) in node_offsets(spacing_m, job.gz0, job.h, j0)
        .into_iter()
        .enumerate()
    {
        if rj != lerps_row {
            lerps_row = rj;
            for (i, &(ri, tx)) in cols.iter().enumerate() {
                let at = |di: usize, dj: usize| ((rj + dj) * nw + ri + di) * k;
                let (a, b, c, d) = (at(0, 0), at(1, 0), at(0, 1), at(1, 1));
                for bi in 0..k {
                    let top = nodes[a + bi] + (nodes[b + bi] - nodes[a + bi]) * tx;
                    let bottom = nodes[c + bi] + (nodes[d + bi] - nodes[c + bi]) * tx;
                    lerps[(i * k + bi) * 2] = top;
                    lerps[(i * k + bi) * 2 + 1] = bottom;
                }
            }
        }
        let row = &mut out[j * job.w * k..(j + 1) * job.w * k];
        for (i, &(ri, _)) in cols.iter().enumerate() {
            let v = i * k;
            if uniform[rj * nw + ri] {
                let a = (rj * nw + ri) * k;
                for bi in 0..k {
                    row[v + bi] = nodes[a + bi].clamp(0.0, 1.0);
                }
                continue;
            }
            for bi in 0..k {
                let (top, bottom) = (lerps[(v + bi) * 2], lerps[(v + bi) * 2 + 1]);
                // Clamped: a lerp of values in [0, 1] can round a last bit above 1.
                row[v + bi] = (top + (bottom - top) * tz).clamp(0.0, 1.0);
            }
        }
    }
    (out, window)
}

/// The sea-level climate's snow line at each node of a window (`EarthParams::snow_lines: 2`),
/// metres: the node's climate before the altitude's cooling, as a fractional biome index, read
/// in the biomes' snow lines `lines`.
///
/// The blurred weights give the node's climate as a mean biome index `m = Σ_b (b + ½)·w_b`; the
/// cooling moved it down by `e · K / lapse_m` biomes, `e ≥ 0` the node's large-scale elevation
/// (the one its biome was read at), so the sea-level index is `m + e · K / lapse_m`. Its snow
/// line is the piecewise-linear interpolation of `lines` between the biomes' centres (the
/// first's below the first centre, the last's above the last). `dims` = `(nw, nh, r)`: the window's nodes and
/// the blur margin of `node_macro`. A function of the node's blurred weights and macro fields,
/// so of its lattice index alone: every window gives a node the same bits.
fn node_sea_lines(
    plan: &EarthPlan,
    lines: &[f32],
    weights: &[f32],
    node_macro: &NodeMacro,
    (nw, nh, r): (usize, usize, usize),
) -> Vec<f32> {
    let c = &plan.climate;
    let k = c.count;
    // Biomes per metre of elevation, and each biome's centre.
    let per_m = k as f32 / c.lapse_m;
    let centres: Vec<f32> = (0..k).map(|b| b as f32 + 0.5).collect();
    let mut out = vec![0.0f32; nw * nh];
    for (j, row) in out.chunks_exact_mut(nw).enumerate() {
        let wrow = &weights[j * nw * k..(j + 1) * nw * k];
        let n0 = (j + r) * node_macro.w + r;
        let (elev, amp, ridge) = (
            &node_macro.elev[n0..n0 + nw],
            &node_macro.amp[n0..n0 + nw],
            &node_macro.ridge[n0..n0 + nw],
        );
        for (i, (o, wv)) in row.iter_mut().zip(wrow.chunks_exact(k)).enumerate() {
            let mut m = 0.0f32;
            for (w, centre) in wv.iter().zip(&centres) {
                m += centre * w;
            }
            let e = super::macro_elevation(elev[i], amp[i], ridge[i]);
            *o = m + e.max(0.0) * per_m;
        }
    }
    for x in &mut out {
        *x = snow_line_at_index(lines, *x);
    }
    out
}

/// The snow line at fractional biome index `x` (biome `b`'s centre at `b + ½`): linear between
/// neighbouring centres, the end biomes' lines beyond the end centres.
pub fn snow_line_at_index(lines: &[f32], x: f32) -> f32 {
    let last = lines.len().saturating_sub(1);
    if last == 0 {
        return lines.first().copied().unwrap_or(0.0);
    }
    let t = (x - 0.5).clamp(0.0, last as f32);
    // `t ≥ 0`, so the cast truncates to its floor (without a call to `floorf`).
    let b = (t as usize).min(last - 1);
    let f = t - b as f32;
    lines[b] + (lines[b + 1] - lines[b]) * f
}

/// The sea-level climate's snow line (metres) at each sample of `job`, bilinear between the
/// nodes of its node window ([`node_window`]) with the weights' node offsets; empty when the
/// world does not read it. A function of the sample's lattice index.
pub fn sea_snow_lines(spacing_m: f32, job: FieldJob, window: &NodeWindow) -> Vec<f32> {
    if window.sea_line.is_empty() {
        return Vec::new();
    }
    let (i0, j0, nw) = (window.i0, window.j0, window.nw);
    let cols = node_offsets(spacing_m, job.gx0, job.w, i0);
    let rows = node_offsets(spacing_m, job.gz0, job.h, j0);
    let mut out = Vec::with_capacity(job.w * job.h);
    // Each column's lerps along x on the node rows above and below it, once per node row.
    let (mut top, mut bottom) = (vec![0.0f32; job.w], vec![0.0f32; job.w]);
    let mut lerps_row = usize::MAX;
    for &(rj, tz) in &rows {
        if rj != lerps_row {
            lerps_row = rj;
            for (i, &(ri, tx)) in cols.iter().enumerate() {
                let v = |di: usize, dj: usize| window.sea_line[(rj + dj) * nw + ri + di];
                top[i] = v(0, 0) + (v(1, 0) - v(0, 0)) * tx;
                bottom[i] = v(0, 1) + (v(1, 1) - v(0, 1)) * tx;
            }
        }
        out.extend(top.iter().zip(&bottom).map(|(t, b)| t + (b - t) * tz));
    }
    out
}
