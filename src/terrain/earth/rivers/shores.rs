//! Lake shores of worlds with `lakes` 2 and later: the terrain shaped to meet each lake's level
//! along a curved shoreline, so a lake's water ends where its ground rises, never along a line
//! of the node lattice.
//!
//! The first lakes (`lakes: 1`, worlds stored before shores existed) flood a sample when one of
//! the four nodes around it holds a lake above its height ([`RiverJob::lake_level`]); where the
//! ground between a lake node and a dry one stays below the level, the water stops at the line
//! between two dry nodes, a straight side a kilometre long. Here instead:
//!
//! 1. **Lake field.** The nodes around a sample give bilinear weights on the unjittered lattice
//!    (the cell of [`RiverJob::lake_level`]), read at the sample displaced by a smooth warp (at
//!    most [`SHORE_WARP`]` · 1.5` spacings, wavelength [`SHORE_WARP_WAVE`] spacings, so within
//!    the job's window of nodes); `I` is the weight of the lake nodes (1 at a lake node, 0 on
//!    any edge between dry nodes) and `L` their weighted level. Bilinear weights along a cell
//!    edge depend on its two nodes only, so `I` and `L` are continuous across cells and every
//!    tile computes them alike.
//! 2. **Shoreline.** `t = I + n`, with `n` two octaves of value noise (wavelengths
//!    [`SHORE_NOISE_M`] and a third of it, at most [`SHORE_NOISE`] together; with `lakes: 7`
//!    each faded by the tile's vertex spacing, [`super::RiverPlan::shore_noise`]); the shore is
//!    `t = ½`, and `e = ½ − t` is negative in the lake and positive on land.
//! 3. **Ground.** The height is clamped between a floor and a ceiling that both pass through
//!    `L` at the shore: on land the floor rises gently (`L + SHORE_GENTLE_M·e`) and the ceiling
//!    steeply (`L + SHORE_STEEP_M·e`); in the lake the ceiling falls gently and the floor
//!    steeply. So the ground is dry above `L` just outside the shore and under water just
//!    inside it, while away from the shore the wedge between them opens and the terrain keeps
//!    its own shape. The change fades in with `I` from 0 to [`SHORE_FULL`] (below any shore,
//!    as `|n| ≤` [`SHORE_NOISE`] `< ½ − SHORE_FULL`), so it vanishes on edges between dry nodes;
//!    it is at most [`SHORE_MAX_M`] either way, the LOD bound of the LODs that skip it.
//!    **Sink** (`lakes: 8`, [`super::RiverPlan::sink`]): first, the height sinks towards `F`,
//!    the weighted height of the lake nodes around (the network's node heights, as `L` is
//!    their weighted level): `h − s·max(h − F, 0)` with `s` the smoothstep of
//!    `(I − `[`SINK_FROM`]`)·`[`SINK_SCALE`] (0 up to `I = SINK_FROM`, below any shore; 1 where
//!    every node around holds the lake), the change at most [`SINK_MAX_M`]. The nodes see the
//!    relief no finer than their spacing; the ground between them keeps its finer octaves,
//!    ridges up to hundreds of metres above both nodes of an edge (p90 about 450 m over the
//!    edges of either network in the default world), so inside a lake such a ridge stood above
//!    the level even after the wedge's 200 m, and cut pools off from the lake's outlet: closed
//!    depressions as deep as the ridge. Sunk, the ground between lake nodes follows their
//!    heights, which lie below the level; the ridges run down into the lake as spurs.
//! 4. **Water.** A sample is lake water where `e < 0` and its carved height is below `L`
//!    ([`RiverJob::shore_level`]).
//! 5. **Sill** (`lakes: 4`). The shores raise the land beside a lake above `L`, but the carve
//!    runs after them, and the floodplains and walls of rivers whose water is lower than the
//!    lake (the river that leaves a spilling lake, and those that join it near the outlet) cut
//!    that land below `L` right beside the water: dry ground below the lake's level, which a
//!    lake would flood, along a straight edge where the shore ends. So outside its channel a
//!    piece cuts the land no lower than `min(h, L)` (`h` the shaped height), blended in with
//!    `s = smoothstep(0, SILL_FULL, I) · smoothstep(−SILL_E, 0, e)` ([`Sill`]): in full on the
//!    land side of the shore wherever the lake weight is at least [`SILL_FULL`], fading to
//!    nothing where it reaches 0 (so the heights stay continuous across cells) and within
//!    [`SILL_E`] inside the shore (where the ground it leaves below `L` is lake water). The
//!    channels keep their cut, so the river that leaves the lake runs wet through its sill.
//!
//! The shores apply to the heights before the river carve (valleys of rivers flowing into the
//! lake cut through the raised land to their water levels, which are no lower than the lake's).
//! The WGSL twin is `shore` in `shaders/rivers.wgsl`, every operation in this order.

use super::super::super::fractal::lattice_n;
use super::super::super::noise::lattice;
use super::carve::{smoothstep, RiverJob};

/// Largest total of the shoreline's noise, in units of the lake weight `I`.
pub const SHORE_NOISE: f32 = 0.22;
/// Share of [`SHORE_NOISE`] in the first octave (the second has the rest).
pub const SHORE_NOISE_FIRST: f32 = 0.85;
/// Wavelength of the shoreline's first noise octave, metres (the second is a third of it).
pub const SHORE_NOISE_M: f32 = 384.0;
/// `1 / SHORE_NOISE_M`, 1/m.
pub const SHORE_NOISE_INV_M: f32 = 1.0 / SHORE_NOISE_M;
/// `3 / SHORE_NOISE_M`, 1/m: the second octave.
pub const SHORE_NOISE2_INV_M: f32 = 3.0 / SHORE_NOISE_M;
/// Largest magnitude of each octave's value before scaling.
pub const SHORE_NOISE_CLAMP: f32 = 1.5;
/// Gentle side of the shore's wedge, metres per unit of `e` (about 3° at the default 1 km node
/// spacing): the floor on land, the ceiling in the lake.
pub const SHORE_GENTLE_M: f32 = 48.0;
/// Steep side of the shore's wedge, metres per unit of `e` (about 13°): the ceiling on land,
/// the floor in the lake.
pub const SHORE_STEEP_M: f32 = 240.0;
/// Lake weight from which the shores apply in full.
pub const SHORE_FULL: f32 = 0.25;
/// Largest change of a height by the shores, metres.
pub const SHORE_MAX_M: f32 = 200.0;
/// Lake weight from which the sink applies (`lakes: 8`, step 3): below the shore, where
/// `I ≥ ½ − SHORE_NOISE`, so the shoreline keeps the ground's own shape where the lake ends.
pub const SINK_FROM: f32 = 0.25;
/// `1 / (1 − SINK_FROM)`: the sink's ramp reaches 1 where the lake weight does. A product,
/// not a quotient, so the WGSL twin rounds it as the CPU does.
pub const SINK_SCALE: f32 = 1.0 / (1.0 - SINK_FROM);
/// Largest lowering of a height by the sink, metres: with [`SHORE_MAX_M`] the LOD bound of the
/// LODs that skip the shores in `lakes: 8` worlds.
pub const SINK_MAX_M: f32 = 1000.0;

/// Lake weight from which the sill under the land beside a lake applies in full (step 5):
/// about 130 m from the edge where the weight vanishes at the default 1 km node spacing, wider
/// than a LOD-6 sample so no step of a 4-neighbour flood passes it. A power of two, as is
/// [`SILL_E`]: the smoothsteps divide by them, and lavapipe's division, which the WGSL twin
/// corrects to the rounded quotient from an estimate a few ULP off, was 4 ULP off after the
/// correction for a quotient by 0.05 (exact by a power of two).
pub const SILL_FULL: f32 = 0.125;
/// Depth inside the shore, in units of `e`, over which the sill fades out (step 5).
pub const SILL_E: f32 = 0.0625;

/// The sill the carve keeps under a sample ([`RiverJob::shore_sill`], step 5 of the module
/// docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sill {
    /// The lake level `L`, metres.
    pub level: f32,
    /// Its weight `s` in [0, 1]; 0: no sill.
    pub s: f32,
}

impl Sill {
    /// No sill: the carve as without one, bit for bit.
    pub const NONE: Sill = Sill { level: 0.0, s: 0.0 };
}

/// Largest displacement of the point at which the lake field is read, in node spacings
/// (`SHORE_WARP·1.5`, below one so the field reads only the job's window): a warp of wavelength
/// [`SHORE_WARP_WAVE`] spacings bends the shores that run between a row of lake nodes and a
/// row of dry ones, which the shore noise alone leaves straight over kilometres.
pub const SHORE_WARP: f32 = 0.25;
/// Wavelength of the warp, in node spacings.
pub const SHORE_WARP_WAVE: f32 = 2.5;

// `RiverJob::lake_field` and `Network::job` skip lakes farther than half a spacing beyond a
// sample's cell: the warp must stay below that.
const _: () = assert!(SHORE_WARP * SHORE_NOISE_CLAMP < 0.5);

/// Scale of the first octave's clamped value: `SHORE_NOISE·SHORE_NOISE_FIRST / SHORE_NOISE_CLAMP`.
pub const SHORE_N1: f32 = SHORE_NOISE * SHORE_NOISE_FIRST / SHORE_NOISE_CLAMP;
/// Scale of the second octave's clamped value.
pub const SHORE_N2: f32 = SHORE_NOISE * (1.0 - SHORE_NOISE_FIRST) / SHORE_NOISE_CLAMP;

/// Samples whose lake field [`RiverJob::lake_field_row`] computes side by side.
pub const FIELD_LANES: usize = 16;

/// The lake field at a sample (step 1 and 2 of the module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LakeField {
    /// Weighted level of the lake nodes around, metres.
    pub level: f32,
    /// Weight of the lake nodes, `I`, in (0, 1].
    pub weight: f32,
    /// Signed distance from the shore in lake-weight units, `e`: negative in the lake.
    pub e: f32,
    /// Weighted node height of the lake nodes around, `F`, metres (`lakes: 8`; else the
    /// level).
    pub floor: f32,
}

impl RiverJob {
    /// The level of node `(i, k)` of the window (absolute lattice indices), if it holds a lake.
    pub(super) fn node_lake(&self, i: i64, k: i64) -> Option<f32> {
        let (a, b) = (i - self.li0, k - self.lk0);
        if a < 0 || b < 0 || a as usize >= self.lakes_w {
            return None;
        }
        // Within a row, the index is past the end exactly when the row is below the window.
        let l = *self.lakes.get(b as usize * self.lakes_w + a as usize)?;
        (!l.is_nan()).then_some(l)
    }

    /// The height of lake node `(i, k)` of the window ([`RiverJob::floors`]; `lakes: 8`).
    fn node_floor(&self, i: i64, k: i64) -> f32 {
        let (a, b) = ((i - self.li0) as usize, (k - self.lk0) as usize);
        self.floors[b * self.lakes_w + a]
    }

    /// The lake field at `(x, z)`, if a lake node around it has weight there.
    pub fn lake_field(&self, x: f32, z: f32) -> Option<LakeField> {
        if self.lakes.is_empty() || !self.lake_near(x, z) {
            return None;
        }
        let (qx, qz) = (x * self.shore_warp_inv_m, z * self.shore_warp_inv_m);
        let wx = lattice(qx, qz, self.shore_seeds[2]);
        let wz = lattice(qx, qz, self.shore_seeds[3]);
        let n1 = lattice(
            x * SHORE_NOISE_INV_M,
            z * SHORE_NOISE_INV_M,
            self.shore_seeds[0],
        );
        let n2 = lattice(
            x * SHORE_NOISE2_INV_M,
            z * SHORE_NOISE2_INV_M,
            self.shore_seeds[1],
        );
        self.lake_field_of(x, z, [wx, wz, n1, n2])
    }

    /// Whether a lake node can give weight at `(x, z)`: the warp moves the point by less than
    /// half a spacing, so no lake node among the 3 × 3 that the corners can reach gives none
    /// (a test that skips the noise, the same answer sooner).
    #[inline]
    fn lake_near(&self, x: f32, z: f32) -> bool {
        self.lake_near_cell(self.near_index(x), self.near_index(z))
    }

    /// The first of the three node indices along an axis whose lakes can give weight at
    /// coordinate `c` (metres).
    #[inline]
    fn near_index(&self, c: f32) -> i64 {
        (c / self.spacing_m - 0.5 - 0.5).floor() as i64
    }

    /// Whether a lake lies among the 3 × 3 nodes from `(i0, k0)`.
    fn lake_near_cell(&self, i0: i64, k0: i64) -> bool {
        (k0..k0 + 3).any(|k| (i0..i0 + 3).any(|i| self.node_lake(i, k).is_some()))
    }

    /// The lake field at `(x, z)` from its four noise values, unclamped: the warp's x and z,
    /// then the shoreline's two octaves.
    #[inline(always)]
    fn lake_field_of(&self, x: f32, z: f32, noise: [f32; 4]) -> Option<LakeField> {
        let [wx, wz, n1, n2] = noise.map(|v| v.clamp(-SHORE_NOISE_CLAMP, SHORE_NOISE_CLAMP));
        let u = (x + self.shore_warp_m * wx) / self.spacing_m - 0.5;
        let v = (z + self.shore_warp_m * wz) / self.spacing_m - 0.5;
        let (fu, fv) = (u.floor(), v.floor());
        let (a, b) = (u - fu, v - fv);
        let (i, k) = (fu as i64, fv as i64);
        let corners = [
            (i, k, (1.0 - a) * (1.0 - b)),
            (i + 1, k, a * (1.0 - b)),
            (i, k + 1, (1.0 - a) * b),
            (i + 1, k + 1, a * b),
        ];
        // The weights are at least 0, so no lake corner (or none with weight) leaves 0.
        let (mut weight, mut sum, mut floor) = (0.0f32, 0.0f32, 0.0f32);
        for (ci, ck, w) in corners {
            if let Some(l) = self.node_lake(ci, ck) {
                weight += w;
                sum += w * l;
                if self.sink {
                    floor += w * self.node_floor(ci, ck);
                }
            }
        }
        if weight <= 0.0 {
            return None;
        }
        let level = sum / weight;
        let floor = if self.sink { floor / weight } else { level };
        let t = weight + (self.shore_n[0] * n1 + self.shore_n[1] * n2);
        Some(LakeField {
            level,
            weight,
            e: 0.5 - t,
            floor,
        })
    }

    /// [`RiverJob::lake_field`] of the samples `(xs[i], z)`, into `out[i]`, bit for bit: the
    /// noise of [`FIELD_LANES`] samples side by side where a lake is near one of them.
    pub fn lake_field_row(&self, xs: &[f32], z: f32, out: &mut [Option<LakeField>]) {
        assert_eq!(xs.len(), out.len(), "a field per sample");
        if self.lakes.is_empty() {
            out.fill(None);
            return;
        }
        const N: usize = FIELD_LANES;
        // Neighbouring samples share their 3 × 3 nodes: each node column tested once.
        let k0 = self.near_index(z);
        let mut last: Option<(i64, bool)> = None;
        let mut near_at = |x: f32| {
            let i0 = self.near_index(x);
            match last {
                Some((i, near)) if i == i0 => near,
                _ => {
                    let near = self.lake_near_cell(i0, k0);
                    last = Some((i0, near));
                    near
                }
            }
        };
        for (xc, oc) in xs.chunks(N).zip(out.chunks_mut(N)) {
            let near: [bool; N] = std::array::from_fn(|l| xc.get(l).is_some_and(|&x| near_at(x)));
            if !near.contains(&true) {
                oc.fill(None);
                continue;
            }
            // Lanes past the row's end repeat its first sample (their values are unused).
            let x: [f32; N] = std::array::from_fn(|l| *xc.get(l).unwrap_or(&xc[0]));
            // The lattice noise of seed `seed` at the lanes' points scaled by `scale` (1/m).
            let noise = |scale: f32, seed: u32| {
                let mut out = [0.0; N];
                lattice_n(&x.map(|x| x * scale), &[z * scale; N], seed, &mut out);
                out
            };
            let wx = noise(self.shore_warp_inv_m, self.shore_seeds[2]);
            let wz = noise(self.shore_warp_inv_m, self.shore_seeds[3]);
            let n1 = noise(SHORE_NOISE_INV_M, self.shore_seeds[0]);
            let n2 = noise(SHORE_NOISE2_INV_M, self.shore_seeds[1]);
            for (l, o) in oc.iter_mut().enumerate() {
                *o = if near[l] {
                    self.lake_field_of(x[l], z, [wx[l], wz[l], n1[l], n2[l]])
                } else {
                    None
                };
            }
        }
    }

    /// A height `h` at `(x, z)` shaped by the lake shores (step 3 of the module docs); `h`
    /// itself, bit for bit, where no lake is near or the world has the first lakes.
    #[inline]
    pub fn shore(&self, x: f32, z: f32, h: f32) -> f32 {
        self.shore_sill(x, z, h).0
    }

    /// [`RiverJob::shore`] and the sill the carve keeps under the sample (step 5 of the module
    /// docs; [`Sill::NONE`] without one or before `lakes: 4`).
    #[inline]
    pub fn shore_sill(&self, x: f32, z: f32, h: f32) -> (f32, Sill) {
        if !self.shores {
            return (h, Sill::NONE);
        }
        self.shore_sill_of(self.lake_field(x, z), h)
    }

    /// [`RiverJob::shore_sill`] of a sample whose lake field is `field` (a world with shaped
    /// shores).
    #[inline]
    pub fn shore_sill_of(&self, field: Option<LakeField>, h: f32) -> (f32, Sill) {
        let Some(f) = field else {
            return (h, Sill::NONE);
        };
        let sill = if self.sills {
            Sill {
                level: f.level,
                s: smoothstep(0.0, SILL_FULL, f.weight) * smoothstep(-SILL_E, 0.0, f.e),
            }
        } else {
            Sill::NONE
        };
        let h = if self.sink { sink(h, f) } else { h };
        let (gentle, steep) = (SHORE_GENTLE_M * f.e, SHORE_STEEP_M * f.e);
        let (lo, hi) = if f.e > 0.0 {
            (f.level + gentle, f.level + steep)
        } else {
            (f.level + steep, f.level + gentle)
        };
        let target = if h < lo {
            lo
        } else if h > hi {
            hi
        } else {
            return (h, sill);
        };
        let g = smoothstep(0.0, SHORE_FULL, f.weight);
        let change = ((target - h) * g).clamp(-SHORE_MAX_M, SHORE_MAX_M);
        (h + change, sill)
    }

    /// The lake level over a sample at `(x, z)` of a world with shaped shores: the lake field's level
    /// inside its shore (`e < 0`).
    pub fn shore_level(&self, x: f32, z: f32) -> Option<f32> {
        self.lake_field(x, z).filter(|f| f.e < 0.0).map(|f| f.level)
    }

    /// The lake level over `(x, z)` as the world's lakes define it: [`RiverJob::shore_level`]
    /// with shores, [`RiverJob::lake_level`] without.
    pub fn lake_surface(&self, x: f32, z: f32) -> Option<f32> {
        if self.shores {
            self.shore_level(x, z)
        } else {
            self.lake_level(x, z)
        }
    }
}

/// The sink of step 3 (`lakes: 8`): `h` lowered towards the lake nodes' height `F` with the
/// ramp of the lake weight, by at most [`SINK_MAX_M`].
#[inline(always)]
fn sink(h: f32, f: LakeField) -> f32 {
    let t = ((f.weight - SINK_FROM) * SINK_SCALE).clamp(0.0, 1.0);
    let s = t * t * (3.0 - 2.0 * t);
    h - (s * (h - f.floor).max(0.0)).min(SINK_MAX_M)
}
