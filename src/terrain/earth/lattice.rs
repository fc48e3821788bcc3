//! The lattice split of `earth-1`'s height sum: the large-scale part evaluated on coarse world
//! lattices and interpolated, the fine part at every sample.
//!
//! Most of a LOD-0 sample's cost is in fields that barely change across a tile: the macro fields
//! (warp, continents, belts, hills: eighteen octaves of wavelength 5 km and more) and the
//! relief and gully layers of wavelength hundreds of metres and more. With
//! `EarthParams::lattice_cells` set (new worlds: 16, 16 m at the default 1 m cell), a LOD whose vertex spacing `δ` is at most
//! half the lattice spacing `s` evaluates, at the world lattice's nodes `(a·s, b·s)`:
//! - the macro fields (elevation, relief amplitude, ridge mix), and
//! - the *prefix* of its layers: the longest run of leading layers whose wavelength (a gully
//!   layer's: its cell) is at least [`PREFIX_WAVES`] `· s`, summed with their gradient, each
//!   node with the climate's erosion and roughness at the node,
//!
//! and interpolates those six values at each sample with the uniform Catmull–Rom spline through
//! the 4 × 4 nodes around it, rows first: `v = Σ_b wz_b · (Σ_a wx_a · V[b][a])`, each sum taken
//! left to right from its first product. The layers after the prefix then add their detail at
//! the sample, steered and damped by the interpolated gradient, and the valley-floor
//! compression finishes the height as in [`super::kernel::heights`].
//!
//! **Seams and determinism.** A node's values are a function of its world lattice index, and a
//! sample's weights of its offset from the node (an exact fraction, the ratio being a power of
//! two), so every tile that holds a vertex computes it from the same nodes with the same
//! weights and gets the same bits; a job's nodes reach one node beyond its samples on each side
//! (the stencil's margin). At a node the weights are exactly `[0, 1, 0, 0]`, so a vertex that
//! lies on a node gets the node's own values.
//!
//! **The coarse lattice.** With `EarthParams::coarse_lattice_cells` too (new worlds: 256, 256 m),
//! the macro fields and the layers of wavelength at least [`COARSE_PREFIX_WAVES`] `· S` (the
//! default world's two longest, 24 and 12 km) are evaluated at the nodes of that lattice
//! (spacing `S`) instead, and interpolated the same way:
//! - at LODs with at least two vertices to `s` (LODs 0–3), at the nodes of the fine lattice,
//!   which then add the layers between the two prefixes ([`Lattice::outer`]);
//! - at LODs with fewer to `s` but at least two to `S` (LODs 4–7: 16 to 128 m), at their
//!   samples, which add the layers after the coarse prefix.
//!
//! A fine node and a sample of a coarser LOD at the same place read the same coarse nodes with
//! the same weights (the offsets are exact fractions with power-of-two denominators), so both
//! get the same bits for the coarse part, and the two LODs differ there only by the layers
//! after it, as without the coarse lattice.
//!
//! **Accuracy and LOD.** A prefix layer has at least [`PREFIX_WAVES`] nodes per wavelength, where
//! Catmull–Rom reproduces a sinusoid to within 0.2 % of its amplitude; the macro fields vary over
//! kilometres. The gully stripes turn sharply around the points where their blended phasor
//! vanishes, and there the interpolation rounds them off: against evaluating every layer at
//! every sample the heights differ by 0.8 m at the 99th percentile and 3.3 m at most
//! (`tests/earth_lattice.rs`); the coarse lattice adds at most 0.4 m in tiles of 100–200 m
//! relief. So the split is part of the world's definition, not an
//! approximation of another: a world either has `lattice_cells` (and `coarse_lattice_cells`)
//! or not, for good. LODs whose spacing is at least the coarse lattice's (or, without it, the
//! fine one's) evaluate every layer at every vertex (each of their vertices is a node, where
//! the interpolation gives the node's own values), so the LOD bound of [`super::EarthLod`]
//! stands between a coarse LOD and LOD 0 at their shared vertices.
//!
//! **Cost.** A LOD-0 job of 67² samples reads 7² nodes: the prefix (13 of the default world's 17
//! LOD-0 layers) is evaluated 49 times instead of 4 489, the macro fields' eighteen octaves at
//! the 4² or 5² coarse nodes around them, and each sample pays the interpolation (24
//! multiply-adds after the rows) and the layers after the prefix. A LOD-6 job reads 21² coarse
//! nodes instead of evaluating the macro fields at its 67² samples. The WGSL twin
//! (`shaders/earth.wgsl`) interpolates the nodes the host computes with [`nodes`], as it reads
//! the climate's weights from the host.

use super::kernel::{Partial, LANES};
use super::{climate, EarthPlan, Layer};
use crate::terrain::tile::FieldJob;

/// A prefix layer's wavelength is at least this many lattice spacings.
pub const PREFIX_WAVES: f64 = 12.0;
/// A prefix layer of the coarse lattice (`EarthParams::coarse_lattice_cells`) has a wavelength
/// of at least this many of its spacings. The layers' creases are sharper than their
/// wavelengths say: on a 256 m lattice, with twelve nodes a wavelength, the 6 km ridged layer
/// came out up to 9 m off and the 8 km gully layer up to 34 m (tiles of 100–200 m relief);
/// with forty, the two longest layers (24 and 12 km) are at most 0.4 m off.
pub const COARSE_PREFIX_WAVES: f64 = 40.0;
/// Values kept per node: elevation, relief amplitude, ridge mix, layer sum and its gradient
/// (x, z), then two zeros (eight `f32`, two `vec4` for the WGSL twin).
pub const NODE_FIELDS: usize = 8;

/// How one LOD splits its height sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lattice {
    /// Samples per lattice spacing (a power of two, at least 2).
    pub step: i64,
    /// Leading layers of the LOD evaluated at the nodes.
    pub prefix: usize,
    /// The coarser lattice the nodes' macro fields and first layers are interpolated from
    /// (`EarthParams::coarse_lattice_cells`), if the LOD is at least two samples to its spacing
    /// too; `None`: the nodes evaluate them.
    pub outer: Option<Level>,
}

/// One lattice of a split: its spacing in samples of the LOD and the layers its nodes hold.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Level {
    /// Samples of the LOD per lattice spacing (a power of two, at least 2).
    pub step: i64,
    /// Leading layers of the LOD evaluated at its nodes.
    pub prefix: usize,
}

impl Level {
    /// The level of a lattice of `lattice_m` for a LOD with vertex spacing `spacing_m` and
    /// `layers`, if its vertices are at least two to a lattice spacing: the prefix is the
    /// longest run of leading layers of wavelength at least `waves` lattice spacings.
    pub fn for_lod(layers: &[Layer], spacing_m: f64, lattice_m: f64, waves: f64) -> Option<Self> {
        let step = (lattice_m / spacing_m).round();
        if step < 2.0 {
            return None;
        }
        let prefix = layers
            .iter()
            .take_while(|l| 1.0 / l.octave.freq as f64 >= waves * lattice_m)
            .count();
        Some(Self {
            step: step as i64,
            prefix,
        })
    }
}

impl Lattice {
    /// The split of a LOD with vertex spacing `spacing_m` and `layers` between a lattice of
    /// `lattice_m` and one of `coarse_m` (each a power-of-two multiple of the spacing, either
    /// absent): the finer lattice that has at least two vertices to its spacing, its nodes
    /// reading the coarse one's where that has too; `None` when neither has.
    pub fn for_lod(
        layers: &[Layer],
        spacing_m: f64,
        lattice_m: Option<f64>,
        coarse_m: Option<f64>,
    ) -> Option<Self> {
        let fine = lattice_m.and_then(|m| Level::for_lod(layers, spacing_m, m, PREFIX_WAVES));
        let coarse =
            coarse_m.and_then(|m| Level::for_lod(layers, spacing_m, m, COARSE_PREFIX_WAVES));
        match (fine, coarse) {
            (Some(f), outer) => Some(Self {
                step: f.step,
                prefix: f.prefix,
                outer,
            }),
            (None, Some(c)) => Some(Self {
                step: c.step,
                prefix: c.prefix,
                outer: None,
            }),
            (None, None) => None,
        }
    }
}

/// The uniform Catmull–Rom weights of the four nodes around a point at offset `t` in `[0, 1)`
/// from the second: exactly `[0, 1, 0, 0]` at `t = 0`.
#[inline(always)]
pub fn weights(t: f32) -> [f32; 4] {
    let t2 = t * t;
    let t3 = t2 * t;
    [
        0.5 * (2.0 * t2 - t3 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (4.0 * t2 - 3.0 * t3 + t),
        0.5 * (t3 - t2),
    ]
}

/// The node values of a job: the nodes `(i0 + a, k0 + b)`, `a < w`, `b < h`, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Nodes {
    /// First node column (world lattice index).
    pub i0: i64,
    /// First node row.
    pub k0: i64,
    /// Node columns.
    pub w: usize,
    /// Node rows.
    pub h: usize,
    /// [`NODE_FIELDS`] values per node.
    pub values: Vec<[f32; NODE_FIELDS]>,
}

/// The node and the offset in `[0, 1)` from it of sample `g` (a lattice index of the LOD).
#[inline(always)]
pub fn locate(g: i64, step: i64) -> (i64, f32) {
    let n = g.div_euclid(step);
    (n, (g - n * step) as f32 / step as f32)
}

/// The nodes a job's samples read: one beyond the nodes around its first and last samples.
pub fn node_window(job: FieldJob, step: i64) -> (i64, i64, usize, usize) {
    let (i0, i1) = (
        locate(job.gx0, step).0 - 1,
        locate(job.gx0 + job.w as i64 - 1, step).0 + 2,
    );
    let (k0, k1) = (
        locate(job.gz0, step).0 - 1,
        locate(job.gz0 + job.h as i64 - 1, step).0 + 2,
    );
    (i0, k0, (i1 - i0 + 1) as usize, (k1 - k0 + 1) as usize)
}

/// The climate's erosion strength and roughness at each point of a weight grid (`k` biomes
/// per point), summed over the biomes in order from 0.0.
pub fn relief_of(plan: &EarthPlan, weights: &[f32]) -> Vec<(f32, f32)> {
    weights
        .chunks_exact(plan.climate.count.max(1))
        .map(|wv| {
            let (mut e, mut r) = (0.0f32, 0.0f32);
            for ((w, eb), rb) in wv.iter().zip(&plan.erosion).zip(&plan.roughness) {
                e += w * eb;
                r += w * rb;
            }
            (e, r)
        })
        .collect()
}

/// The node values of `job` at LOD `lod` (vertex spacing `spacing_m`) split by `lat`. Without
/// an outer level a node starts from the macro fields at its position and adds the prefix; with
/// one it starts from the outer nodes' values interpolated at it (as a sample of the LOD at the
/// node would, bit for bit: the same nodes, the same weights) and adds the layers between the
/// two prefixes.
pub fn nodes(plan: &EarthPlan, lod: usize, spacing_m: f32, lat: Lattice, job: FieldJob) -> Nodes {
    let (i0, k0, w, h) = node_window(job, lat.step);
    let node_job = FieldJob {
        lod: job.lod,
        gx0: i0,
        gz0: k0,
        w,
        h,
    };
    let lattice_m = lat.step as f32 * spacing_m;
    let relief = relief_of(plan, &climate::weights(plan, lattice_m, node_job));
    // The outer level in units of this level's nodes.
    let outer = lat.outer.map(|o| {
        let inner = Lattice {
            step: o.step / lat.step,
            prefix: o.prefix,
            outer: None,
        };
        let coarse = nodes(plan, lod, lattice_m, inner, node_job);
        (Interpolated::new(&coarse, inner, node_job), o.prefix)
    });
    let first = outer.as_ref().map_or(0, |(_, p)| *p);
    let layers = &plan.lods[lod].layers[first..lat.prefix];
    let n = w * h;
    let mut values = vec![[0.0f32; NODE_FIELDS]; n];
    let (mut x, mut z) = ([0.0f32; LANES], [0.0f32; LANES]);
    let (mut ero, mut rough) = ([0.0f32; LANES], [0.0f32; LANES]);
    let mut p = Partial::zero();
    for start in (0..n).step_by(LANES) {
        let m = (n - start).min(LANES);
        for l in 0..LANES {
            // Lanes past the job repeat its last node, so every lane holds finite values.
            let v = start + l.min(m - 1);
            let (a, b) = (v % w, v / w);
            // A node's position as a sample of the LOD at it computes it.
            x[l] = ((i0 + a as i64) * lat.step) as f32 * spacing_m;
            z[l] = ((k0 + b as i64) * lat.step) as f32 * spacing_m;
            (ero[l], rough[l]) = relief[v];
            if let Some((base, _)) = &outer {
                let [e, am, r, hs, gx, gz] = base.at(a, b);
                (p.elev[l], p.amp[l], p.ridge[l]) = (e, am, r);
                (p.h[l], p.gx[l], p.gz[l]) = (hs, gx, gz);
            }
        }
        if outer.is_none() {
            p = Partial::start(plan, &x, &z);
        }
        p.add_layers(plan, layers, &x, &z, &ero, &rough);
        for l in 0..m {
            values[start + l] = [
                p.elev[l], p.amp[l], p.ridge[l], p.h[l], p.gx[l], p.gz[l], 0.0, 0.0,
            ];
        }
    }
    Nodes {
        i0,
        k0,
        w,
        h,
        values,
    }
}

/// A job's node rows interpolated at each of its sample columns, and the rows and weights each
/// sample row reads: [`Interpolated::at`] finishes the interpolation of one sample.
#[derive(Clone, Debug)]
pub struct Interpolated {
    /// Sample columns.
    w: usize,
    /// Node row `b` at sample column `i`, at `b · w + i`.
    rows: Vec<[f32; 6]>,
    /// Per sample row: the first of its four node rows and their weights.
    zs: Vec<(usize, [f32; 4])>,
}

impl Interpolated {
    /// Interpolates the rows of `nodes` at every sample column of `job`.
    pub fn new(nodes: &Nodes, lat: Lattice, job: FieldJob) -> Self {
        let cols: Vec<(usize, [f32; 4])> = (0..job.w as i64)
            .map(|i| {
                let (n, t) = locate(job.gx0 + i, lat.step);
                ((n - 1 - nodes.i0) as usize, weights(t))
            })
            .collect();
        let mut rows = vec![[0.0f32; 6]; nodes.h * job.w];
        for b in 0..nodes.h {
            let row = &nodes.values[b * nodes.w..(b + 1) * nodes.w];
            for (i, (a0, wx)) in cols.iter().enumerate() {
                let out = &mut rows[b * job.w + i];
                for (f, o) in out.iter_mut().enumerate() {
                    let mut s = wx[0] * row[*a0][f];
                    for (a, wa) in wx.iter().enumerate().skip(1) {
                        s += wa * row[a0 + a][f];
                    }
                    *o = s;
                }
            }
        }
        let zs = (0..job.h as i64)
            .map(|j| {
                let (n, t) = locate(job.gz0 + j, lat.step);
                ((n - 1 - nodes.k0) as usize, weights(t))
            })
            .collect();
        Self { w: job.w, rows, zs }
    }

    /// The six values at sample `(i, j)` of the job.
    #[inline(always)]
    pub fn at(&self, i: usize, j: usize) -> [f32; 6] {
        let (b0, wz) = self.zs[j];
        let mut out = [0.0f32; 6];
        for (f, of) in out.iter_mut().enumerate() {
            let mut s = wz[0] * self.rows[b0 * self.w + i][f];
            for (b, wb) in wz.iter().enumerate().skip(1) {
                s += wb * self.rows[(b0 + b) * self.w + i][f];
            }
            *of = s;
        }
        out
    }
}

/// Heights (metres) of `job`'s samples at LOD `lod` split by `lat`: the nodes' part
/// interpolated, then the layers after the prefix at each sample. `relief` holds each sample's
/// erosion strength and roughness.
pub fn heights(
    plan: &EarthPlan,
    lod: usize,
    spacing_m: f32,
    lat: Lattice,
    job: FieldJob,
    relief: &[(f32, f32)],
    out: &mut [f32],
) {
    let nodes = nodes(plan, lod, spacing_m, lat, job);
    let base = Interpolated::new(&nodes, lat, job);
    let rest = &plan.lods[lod].layers[lat.prefix..];
    let n = job.w * job.h;
    let (mut x, mut z) = ([0.0f32; LANES], [0.0f32; LANES]);
    let (mut ero, mut rough, mut hs) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
    let mut p = Partial::zero();
    for start in (0..n).step_by(LANES) {
        let m = (n - start).min(LANES);
        for l in 0..LANES {
            // Lanes past the job repeat its last sample, so every lane holds finite values.
            let v = start + l.min(m - 1);
            let (i, j) = ((v % job.w) as i64, (v / job.w) as i64);
            x[l] = (job.gx0 + i) as f32 * spacing_m;
            z[l] = (job.gz0 + j) as f32 * spacing_m;
            (ero[l], rough[l]) = relief[v];
            let [e, a, r, h, gx, gz] = base.at(i as usize, j as usize);
            (p.elev[l], p.amp[l], p.ridge[l]) = (e, a, r);
            (p.h[l], p.gx[l], p.gz[l]) = (h, gx, gz);
        }
        p.add_layers(plan, rest, &x, &z, &ero, &rough);
        p.finish(&mut hs);
        out[start..start + m].copy_from_slice(&hs[..m]);
    }
}
