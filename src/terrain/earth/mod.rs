//! The `earth-1` generator: a world that reads as Earth from continents to the metre.
//!
//! Sources: Schneider et al., *Real-time rendering of infinite landscapes on the GPU* (value-noise
//! multifractals, §2.2 domain warping, §4.1 LOD octave counts), Choroś & Topolski (the extended
//! Voronoi biome map with latitude and dispersion), Musgrave's ridged multifractal, Quílez's
//! derivative-damped fBm, and the point-evaluable erosion filters of Clay John (2018), Felix
//! Westin (2023) and Rune Skovbo Johansen (2026), whose phasor-blended stripe noise the gully
//! layers follow (our own formulation, see [`kernel`]).
//!
//! Scales, largest first (defaults of [`EarthParams`]):
//! - **continents** (~1 400 km lattice, nine octaves down to 5 km, rotated per octave and warped
//!   by a bounded field): ocean floor at −4.2 km, shelf, coast, plains rising inland to 650 m; the
//!   origin is biased onto land;
//! - **mountain belts** (600 km lattice): sinuous bands where a belt noise crosses zero, with
//!   3.6 km of ridged relief; hill country (550 m) and plains (90 m) elsewhere;
//! - **relief layers**: up to 16 octaves from 24 km wavelength, each rotated by its own angle,
//!   ridged in belts, damped by the slope accumulated so far;
//! - **gully layers** (the erosion filter): six octaves from an 8 km lattice down to 250 m, the
//!   coarsest left out in new worlds (`gully_first`: its straight stripes cut canyons; the
//!   rivers carve that scale), interleaved with the relief octaves of similar amplitude;
//! - **climate** ([`climate`]): biome weights on a 4 km world lattice, colder with altitude.
//!
//! **LOD rule (§4.1, generalised).** Every layer has a reference amplitude `a_i · A_max` and a
//! wavelength `L_i`. At a vertex spacing `δ` it gets the weight
//! `w_i = clamp(min(ln(f a_i A_max / δ) / ln(1/q), log₂(L_i / 2δ)), 0, 1)`, where `q` is its
//! series' amplitude ratio (the paper's `λ − k`; `f` = 4 for relief layers (§4.1 has 1) and 8 for
//! gully layers, whose long low waves stay visible below the spacing; no wave shorter than two
//! spacings), then `w_i = min(w_i, w_{i−1})` so the kept
//! layers are a prefix of the evaluation order. The macro fields (continents, belts, hills,
//! warp) and the climate are evaluated in full at every LOD. Hence a vertex's height at LOD `k`
//! differs from LOD 0 only through the layers LOD `k` drops or weights less, and by at most
//! [`EarthLod::bound_m`] = `Σ_i (w_i⁰ − w_i^k) · a_i · A_max · S_i`, with `S_i` the layer's largest
//! value times the largest erosion or roughness factor.
//!
//! **Lattice split** ([`lattice`], worlds with `lattice_cells`): at LODs finer than the lattice, the
//! macro fields and the leading layers of long wavelength are evaluated at the nodes of a world
//! lattice and interpolated; the later layers at every sample. Worlds with `coarse_lattice_cells`
//! (new worlds) take the macro fields and the longest layers from a second lattice of 256 m, at
//! the first lattice's nodes and at the samples of LODs 4–7.
//!
//! Seams: every value is a function of the vertex's world position (its lattice index times the
//! spacing, exact in `f32`), so neighbouring tiles share edge vertices bit for bit, as with the
//! classic generator.

pub mod climate;
pub(crate) mod kernel;
pub mod lattice;
pub mod params;
pub mod rivers;
pub mod trig;

pub use kernel::LANES;
pub use params::{BiomeRelief, EarthParams, RiverParams};

use super::biome::BiomeMapPlan;
use super::hash::{purpose, stream, unit};
use super::plan::MAX_LOD;
use super::tile::{Field, FieldJob};
use super::world::WorldParams;

/// Most relief octaves a world may ask for.
pub const MAX_RELIEF_OCTAVES: usize = 20;
/// Most gully octaves a world may ask for.
pub const MAX_GULLY_OCTAVES: usize = 8;

/// Depth of a gully layer relative to the relief amplitude, at the coarsest gully octave.
const GULLY_DEPTH: f32 = 0.09;
/// A relief layer is kept in full while its amplitude is at least a quarter of the vertex
/// spacing (§4.1 keeps it down to the spacing; a quarter keeps the ridges of coarse tiles sharp).
const RELIEF_LOD_AMPLITUDE: f64 = 4.0;
/// A gully layer is kept in full while its amplitude is at least an eighth of the spacing: its
/// waves are long and low, and stay visible well below the §4.1 limit.
const GULLY_LOD_AMPLITUDE: f64 = 8.0;

/// Relief octaves mixed towards ridged in mountain belts.
pub const RIDGED_OCTAVES: usize = 3;
/// Sum of the relief octaves' reference amplitudes is about `RELIEF_NORM / (1 − gain)`.
const RELIEF_NORM: f32 = 0.55;
/// Largest magnitude of a relief layer's signal: smooth gradient noise is a convex blend of
/// corner values `g · d` with `|g|, |d| ≤ √2`, times [`kernel::GRADIENT_SCALE`]; ridged is at
/// most `2 · 0.6`.
const RELIEF_SIGNAL_MAX: f32 = 2.0 * kernel::GRADIENT_SCALE;

/// One octave of a noise: rotation, frequency, offset and amplitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseOctave {
    /// Lattice cells per metre.
    pub freq: f32,
    /// Weight of the octave (metres for the warp, plain numbers elsewhere).
    pub amp: f32,
    /// Stream seed of the octave's lattice.
    pub seed: u32,
    /// Cosine of the octave's rotation.
    pub cos: f32,
    /// Sine of the octave's rotation.
    pub sin: f32,
    /// Offset of the octave's lattice, cells.
    pub ox: f32,
    /// Offset of the octave's lattice, cells.
    pub oz: f32,
}

/// The LOD-independent fields: warp, continents, belts, hills.
#[derive(Clone, Debug, PartialEq)]
pub struct MacroPlan {
    /// Warp of the macro fields along x (amplitudes in metres).
    pub warp_x: Vec<NoiseOctave>,
    /// Warp along z.
    pub warp_z: Vec<NoiseOctave>,
    /// Continent octaves.
    pub continent: Vec<NoiseOctave>,
    /// Belt octaves.
    pub belt: Vec<NoiseOctave>,
    /// Hill-country octaves.
    pub hills: Vec<NoiseOctave>,
    /// `EarthParams::land_bias`.
    pub land_bias: f32,
    /// `EarthParams::origin_land`.
    pub origin_land: f32,
    /// `1 / origin_land_radius_m²`.
    pub inv_origin_r2: f32,
    /// `EarthParams::belt_width`.
    pub belt_width: f32,
    /// Relief of mountains, metres.
    pub mountain_relief_m: f32,
    /// Relief of hills, metres.
    pub hill_relief_m: f32,
    /// Relief of plains, metres.
    pub plain_relief_m: f32,
    /// Relief of the sea floor, metres.
    pub seafloor_relief_m: f32,
    /// Height of the interior plains, metres.
    pub interior_height_m: f32,
    /// Depth of the abyss, metres.
    pub ocean_depth_m: f32,
}

/// What a layer adds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LayerKind {
    /// One relief octave; `fine` ones (wavelength at most the coarsest gully spacing) are scaled
    /// by the biome's roughness.
    Relief {
        /// Scaled by the roughness.
        fine: bool,
        /// Mixed towards ridged by the belt mask (the first [`RIDGED_OCTAVES`]).
        ridged: bool,
    },
    /// One erosion-filter octave.
    Gully {
        /// Incised cross-section (`EarthParams::gullies` 2 and 3): V-shaped troughs, rounded
        /// crests.
        incised: bool,
        /// Square of the smallest magnitude the blended phasor is divided by
        /// (`EarthParams::gullies` 3: [`kernel::GULLY_PHASOR_FLOOR2`]; 0 before, which leaves
        /// every bit as it was).
        floor2: f32,
    },
}

/// One layer of the height sum at one LOD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    /// Relief or gully.
    pub kind: LayerKind,
    /// Its noise; `octave.amp` is unused.
    pub octave: NoiseOctave,
    /// Reference amplitude relative to the local relief `A`, times the LOD weight.
    pub amp: f32,
}

/// The layers of one LOD.
#[derive(Clone, Debug, PartialEq)]
pub struct EarthLod {
    /// Layers in evaluation order (the last may be partial).
    pub layers: Vec<Layer>,
    /// Largest difference of a vertex's height from LOD 0, metres (module docs).
    pub bound_m: f32,
    /// How the LOD splits its sum between a coarse lattice and the samples ([`lattice`]); `None`
    /// evaluates every layer at every sample.
    pub lattice: Option<lattice::Lattice>,
}

/// Everything the `earth-1` kernels read, built once per world.
#[derive(Clone, Debug, PartialEq)]
pub struct EarthPlan {
    /// LOD-independent fields.
    pub macro_plan: MacroPlan,
    /// Per LOD, index = LOD.
    pub lods: Vec<EarthLod>,
    /// Biome weights.
    pub climate: climate::ClimatePlan,
    /// Erosion strength of each biome (the world's times the biome's).
    pub erosion: Vec<f32>,
    /// Roughness of each biome.
    pub roughness: Vec<f32>,
    /// `1 / A_max`: the inverse of the largest relief amplitude, 1/metres.
    pub inv_relief_max: f32,
    /// Stream seed of the snow line's noise.
    pub snow_seed: u32,
    /// Rivers and lakes, when the world has them enabled.
    pub rivers: Option<rivers::RiverPlan>,
    /// The coarse network that carves LODs `MAX_CARVE_LOD + 1 ..= MAX_COARSE_LOD`, in worlds
    /// with rivers and `coarse: 1` ([`EarthPlan::carve_plan`]).
    pub coarse_rivers: Option<rivers::RiverPlan>,
    /// Identifies the world function the climate nodes are computed from (the seed and the
    /// world settings): the key of [`climate`]'s process-wide cache of node windows.
    pub fingerprint: u64,
}

fn octaves(
    seed: u64,
    index: u32,
    count: usize,
    wavelength_m: f64,
    amp0: f64,
    gain: f64,
) -> Vec<NoiseOctave> {
    (0..count)
        .map(|k| {
            octave(
                seed,
                index + k as u32,
                wavelength_m / (1u64 << k) as f64,
                amp0 * libm::pow(gain, k as f64),
            )
        })
        .collect()
}

/// Octave `index` of the world's `earth-1` streams: its own rotation (a golden-angle sequence
/// plus a hashed turn) and lattice offset, so no two octaves share lattice directions or points.
fn octave(seed: u64, index: u32, wavelength_m: f64, amp: f64) -> NoiseOctave {
    let h = stream(seed, purpose::EARTH, index);
    let angle = index as f64 * 2.399_963_229_728_653 + unit(h) as f64 * std::f64::consts::TAU;
    NoiseOctave {
        freq: (1.0 / wavelength_m) as f32,
        amp: amp as f32,
        seed: h,
        cos: libm::cos(angle) as f32,
        sin: libm::sin(angle) as f32,
        ox: unit(h.rotate_left(11)) * 256.0,
        oz: unit(h.rotate_left(23)) * 256.0,
    }
}

impl EarthPlan {
    /// The network that carves tiles of `lod`: the world's network up to
    /// [`rivers::MAX_CARVE_LOD`], the coarse one up to [`rivers::MAX_COARSE_LOD`] where the
    /// world has it, else none (the tile keeps its uncarved heights).
    pub fn carve_plan(&self, lod: usize) -> Option<&rivers::RiverPlan> {
        if lod <= rivers::MAX_CARVE_LOD {
            self.rivers.as_ref()
        } else if lod <= rivers::MAX_COARSE_LOD {
            self.coarse_rivers.as_ref()
        } else {
            None
        }
    }

    /// The plan of an `earth-1` world (`params.earth` must be set; `WorldParams::validate`
    /// checks it).
    pub fn new(seed: u64, params: &WorldParams, map: BiomeMapPlan) -> Self {
        let e = params.earth.clone().unwrap_or_default();
        let warp_len = e.continent_scale_m as f64 / 3.0;
        // Bounded warp: displacement 0.12 of its own wavelength, so the stretch it causes stays
        // below about 1.4 (no marble streaks), and it only moves the macro fields.
        let macro_plan = MacroPlan {
            warp_x: octaves(seed, 0, 2, warp_len, 0.12 * warp_len, 0.5),
            warp_z: octaves(seed, 2, 2, warp_len, 0.12 * warp_len, 0.5),
            continent: octaves(seed, 4, 9, e.continent_scale_m as f64, 0.5, 0.55),
            belt: octaves(seed, 13, 3, e.belt_scale_m as f64, 0.6, 0.5),
            hills: octaves(seed, 16, 2, 150_000.0, 0.8, 0.5),
            land_bias: e.land_bias,
            origin_land: e.origin_land,
            inv_origin_r2: (1.0 / (e.origin_land_radius_m as f64).powi(2)) as f32,
            belt_width: e.belt_width,
            mountain_relief_m: e.mountain_relief_m,
            hill_relief_m: e.hill_relief_m,
            plain_relief_m: e.plain_relief_m,
            seafloor_relief_m: e.seafloor_relief_m,
            interior_height_m: e.interior_height_m,
            ocean_depth_m: e.ocean_depth_m,
        };
        let relief = |b: &super::world::Biome| b.relief.clone().unwrap_or_default();
        let erosion: Vec<f32> = params
            .biomes
            .iter()
            .map(|b| e.erosion * relief(b).erosion)
            .collect();
        let roughness: Vec<f32> = params.biomes.iter().map(|b| relief(b).roughness).collect();
        let max_erosion = erosion.iter().fold(0.0f32, |a, &b| a.max(b));
        let max_rough = roughness.iter().fold(1.0f32, |a, &b| a.max(b));

        // The layers in evaluation order, each with its reference amplitude, the amplitude ratio
        // of its series and its largest signal.
        let mut all: Vec<(Layer, f64, f64, f64)> = Vec::new();
        let mut amp = RELIEF_NORM as f64;
        for k in 0..e.octaves as usize {
            let wavelength = e.ridge_scale_m as f64 / (1u64 << k) as f64;
            let o = octave(seed, 100 + k as u32, wavelength, 0.0);
            let fine = wavelength <= e.gully_scale_m as f64;
            // Hillslopes: below `detail_scale_m` the spectrum falls faster (`detail_gain`).
            let gain = if wavelength < e.detail_scale_m as f64 {
                e.detail_gain
            } else {
                e.gain
            } as f64;
            if k > 0 {
                amp *= gain;
            }
            let smax = RELIEF_SIGNAL_MAX as f64 * if fine { max_rough as f64 } else { 1.0 };
            let layer = Layer {
                kind: LayerKind::Relief {
                    fine,
                    ridged: k < RIDGED_OCTAVES,
                },
                octave: o,
                amp: amp as f32,
            };
            all.push((layer, 1.0 / gain, smax, RELIEF_LOD_AMPLITUDE));
        }
        for g in e.gully_first as usize..e.gully_octaves as usize {
            let cell = e.gully_scale_m as f64 / (1u64 << g) as f64;
            let o = octave(seed, 200 + g as u32, cell, 0.0);
            let amp = GULLY_DEPTH as f64 * libm::pow(0.5, g as f64);
            let layer = Layer {
                kind: LayerKind::Gully {
                    incised: e.gullies >= 2,
                    floor2: if e.gullies >= 3 {
                        kernel::GULLY_PHASOR_FLOOR2
                    } else {
                        0.0
                    },
                },
                octave: o,
                amp: amp as f32,
            };
            all.push((layer, 2.0, max_erosion as f64, GULLY_LOD_AMPLITUDE));
        }
        // Interleave by reference amplitude (stable: relief first at equal amplitude).
        all.sort_by(|a, b| b.0.amp.total_cmp(&a.0.amp));
        let a_max = ((e.mountain_relief_m.max(e.hill_relief_m) + e.plain_relief_m)
            .max(e.seafloor_relief_m)) as f64;
        let weights_at = |spacing: f64| -> Vec<f64> {
            let mut prev = 1.0f64;
            all.iter()
                .map(|(l, ratio, _, factor)| {
                    let by_amp =
                        libm::log(factor * l.amp as f64 * a_max / spacing) / libm::log(*ratio);
                    let by_len = libm::log2(1.0 / (l.octave.freq as f64 * 2.0 * spacing));
                    let w = by_amp.min(by_len).clamp(0.0, 1.0);
                    prev = prev.min(w);
                    prev
                })
                .collect()
        };
        let w0 = weights_at(params.cell_m as f64);
        let lods = (0..=MAX_LOD)
            .map(|lod| {
                let spacing = params.cell_m as f64 * (1u64 << lod) as f64;
                let w = weights_at(spacing);
                let mut bound = 0.0f64;
                let mut layers = Vec::new();
                for (i, (layer, _, smax, _)) in all.iter().enumerate() {
                    bound += (w0[i] - w[i]).max(0.0) * layer.amp as f64 * a_max * smax;
                    if w[i] > 0.0 {
                        layers.push(Layer {
                            amp: (layer.amp as f64 * w[i]) as f32,
                            ..*layer
                        });
                    }
                }
                let cells_m = |c: u32| c as f64 * params.cell_m as f64;
                let lattice = lattice::Lattice::for_lod(
                    &layers,
                    spacing,
                    e.lattice_cells.map(cells_m),
                    e.coarse_lattice_cells.map(cells_m),
                );
                EarthLod {
                    layers,
                    bound_m: bound as f32,
                    lattice,
                }
            })
            .collect();
        let climate = climate::ClimatePlan::new(
            map,
            params.layout.blur_radius_m,
            e.latitude_offset_m,
            e.lapse_m,
            params.biomes.len(),
            (e.snow_lines == 2).then(|| {
                params
                    .biomes
                    .iter()
                    .map(|b| b.snow_line_m.clamp(-1e6, 1e6))
                    .collect()
            }),
        );
        let mean_erosion = erosion.iter().sum::<f32>() / erosion.len().max(1) as f32;
        // The node heights read the whole world settings (edits are not in them), so worlds and
        // versions with equal settings share cached network blocks.
        let world = serde_json::to_vec(params).unwrap_or_default();
        let plan = |r: &params::RiverParams, coarse: bool| {
            rivers::RiverPlan::new(
                seed,
                r,
                params.cell_m,
                params.sea_level_m,
                mean_erosion,
                &world,
                coarse,
            )
        };
        let enabled = e.rivers.as_ref().filter(|r| r.enabled);
        let rivers = enabled.map(|r| plan(r, false));
        let coarse_rivers = enabled.filter(|r| r.coarse >= 1).map(|r| plan(r, true));
        let mut lods: Vec<EarthLod> = lods;
        if let Some(rp) = &rivers {
            // LODs that skip the carve (and the lake shores before it) differ from LOD 0 by at
            // most what they change; those the coarse network carves by twice that (its carve
            // and the fine one's each change a height by at most as much).
            // With `lakes: 8` the shores' sink lowers a height by up to `SINK_MAX_M` before
            // their wedge changes it.
            let shores = match rp.lakes {
                0 | 1 => 0.0,
                2..=7 => rivers::SHORE_MAX_M,
                _ => rivers::SHORE_MAX_M + rivers::SINK_MAX_M,
            };
            for (lod, l) in lods.iter_mut().enumerate().skip(rivers::MAX_CARVE_LOD + 1) {
                let coarse = coarse_rivers.is_some() && lod <= rivers::MAX_COARSE_LOD;
                let networks = if coarse { 2.0 } else { 1.0 };
                l.bound_m += networks * (rivers::CARVE_MAX_M + shores);
            }
            // `valleys: 8`: LODs that carve with floodplains widened to their spacing lower a
            // sample by at most what the walls climb over the added width.
            if rp.sized_valleys {
                for (lod, l) in lods.iter_mut().enumerate().take(rivers::MAX_CARVE_LOD + 1) {
                    let spacing_m = params.cell_m * (1u32 << lod) as f32;
                    l.bound_m += rivers::widened_floor_bound_m(spacing_m, rp.spacing_m);
                }
            }
        }
        Self {
            macro_plan,
            lods,
            climate,
            erosion,
            roughness,
            inv_relief_max: (1.0 / a_max) as f32,
            snow_seed: stream(seed, purpose::EARTH, 300),
            rivers,
            coarse_rivers,
            fingerprint: fingerprint(b"strata climate v1", seed, &world),
        }
    }
}

/// The first eight bytes of the blake3 of `domain`, the seed and the serialised world settings
/// `world`: the key under which the process-wide caches keep a world's blocks, so worlds and
/// versions with equal settings share them.
pub(crate) fn fingerprint(domain: &[u8], seed: u64, world: &[u8]) -> u64 {
    let mut hasher = blake3::Hasher::new();
    hasher.update(domain);
    hasher.update(&seed.to_le_bytes());
    hasher.update(world);
    let mut first = [0u8; 8];
    first.copy_from_slice(&hasher.finalize().as_bytes()[..8]);
    u64::from_le_bytes(first)
}

/// Empties the process-wide caches of every world (the river network's blocks and the climate's
/// node windows); the results stay the same: tests use it to compute a tile from nothing, and
/// `bench tiles` to time a cold pass.
pub fn clear_caches() {
    rivers::clear_caches();
    climate::clear_cache();
}

/// The sea-level climate's snow line (metres) at each vertex of tile `key` (vertex order), as
/// [`field`] gives it to the tile's samples ([`climate::sea_snow_lines`]); empty when the world
/// does not read it. The Ptex inputs of a tile read it here, from the tile alone.
pub fn tile_sea_snow_lines(
    plan: &EarthPlan,
    key: super::tile::TileKey,
    spacing_m: f32,
) -> Vec<f32> {
    if plan.climate.sea_snow.is_none() {
        return Vec::new();
    }
    let n = super::plan::TILE_VERTS;
    let q = super::plan::TILE_QUADS;
    let job = FieldJob::new(key.lod, key.x * q, key.z * q, n, n);
    climate::sea_snow_lines(spacing_m, job, &climate::node_window(plan, spacing_m, job))
}

/// How far north-facing slopes pull the snow line down (and south-facing ones push it up), per
/// unit of the normal's horizontal z component, metres.
pub const SNOW_ASPECT_M: f32 = 350.0;
/// Amplitude of the snow line's noise, metres (value noise on a 300 m lattice).
pub const SNOW_NOISE_M: f32 = 120.0;
/// Lattice spacing of the snow line's noise, metres.
const SNOW_NOISE_SCALE_M: f32 = 300.0;

/// Per-vertex shift of the snow line (metres) of tile `key`: lower on slopes facing north
/// (−z, where the normal's z component is negative) and higher facing south, by
/// [`SNOW_ASPECT_M`] times that component, plus value noise of [`SNOW_NOISE_M`] so the snow
/// edge is ragged. A function of the vertex's world position and normal, so tiles agree on
/// shared vertices. (Steep slopes already shed snow: rock wins over snow in the texturing.)
pub fn snow_shift(
    plan: &EarthPlan,
    key: super::tile::TileKey,
    spacing_m: f32,
    normals: &[[f32; 3]],
) -> Vec<f32> {
    use super::fractal::{gaussian_fast, lattice_index};
    use super::noise::{corner_hashes, fade, interpolate};
    let n = super::plan::TILE_VERTS;
    let seed = plan.snow_seed;
    // The noise of `fractal::lattice_n`, the same bits, with its per-axis parts computed once a
    // column and once a row and each lattice cell's corners once a run of vertices in it (a
    // cell is 300 m: a LOD-0 tile lies in at most four).
    let axis = |t0: i64| -> Vec<(u32, f32)> {
        (0..n as i64)
            .map(|i| {
                let c = (t0 * super::plan::TILE_QUADS + i) as f32 * spacing_m / SNOW_NOISE_SCALE_M;
                let f = c.floor();
                (lattice_index(f), fade(c - f))
            })
            .collect()
    };
    let (cols, rows) = (axis(key.x), axis(key.z));
    let mut cell: Option<((u32, u32), [f32; 4])> = None;
    normals
        .iter()
        .enumerate()
        .map(|(v, nrm)| {
            let v = v.min(n * n - 1);
            let ((ix, u), (iz, w)) = (cols[v % n], rows[v / n]);
            let corners = match cell {
                Some((at, c)) if at == (ix, iz) => c,
                _ => {
                    let c = corner_hashes(ix, iz, seed).map(gaussian_fast);
                    cell = Some(((ix, iz), c));
                    c
                }
            };
            SNOW_ASPECT_M * nrm[2] + SNOW_NOISE_M * interpolate(corners, u, w)
        })
        .collect()
}

/// The macro fields (elevation `e(c)`, relief amplitude `A`, ridge mix `ρ`) at world positions,
/// each the bits the height function computes at that position.
pub fn macro_fields_batch(
    plan: &EarthPlan,
    xs: &[f32],
    zs: &[f32],
    elev: &mut [f32],
    amp: &mut [f32],
    ridge: &mut [f32],
) {
    let mut x = [0.0f32; LANES];
    let mut z = [0.0f32; LANES];
    let (mut e, mut a, mut r) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
    for start in (0..xs.len()).step_by(LANES) {
        let n = (xs.len() - start).min(LANES);
        x[..n].copy_from_slice(&xs[start..start + n]);
        z[..n].copy_from_slice(&zs[start..start + n]);
        kernel::macro_fields(&plan.macro_plan, &x, &z, &mut e, &mut a, &mut r);
        elev[start..start + n].copy_from_slice(&e[..n]);
        amp[start..start + n].copy_from_slice(&a[..n]);
        ridge[start..start + n].copy_from_slice(&r[..n]);
    }
}

/// Large-scale elevation (continent and mean mountain relief, metres) of the macro fields at a
/// position, for the climate: `e(c) + 0.33 · A · ρ`.
#[inline]
pub fn macro_elevation(elev: f32, amp: f32, ridge: f32) -> f32 {
    elev + 0.33 * amp * ridge
}

/// Heights and biome weights of a job's lattice samples: the CPU reference of `earth-1` (the
/// WGSL twin is `shaders/earth.wgsl`).
pub fn field(plan: &EarthPlan, spacing_m: f32, job: FieldJob) -> Field {
    let FieldJob {
        lod,
        gx0,
        gz0,
        w,
        h,
    } = job;
    let (weights, window) = climate::weights_and_macro(plan, spacing_m, job);
    let snow_line = climate::sea_snow_lines(spacing_m, job, &window);
    let node_macro = &window.node_macro;
    let relief = lattice::relief_of(plan, &weights);
    let n = w * h;
    let mut heights = vec![0.0f32; n];
    if let Some(lat) = plan.lods[lod as usize].lattice {
        lattice::heights(
            plan,
            lod as usize,
            spacing_m,
            lat,
            job,
            &relief,
            &mut heights,
        );
    } else if climate::samples_are_nodes(spacing_m) {
        // Every sample is a climate node, whose macro fields the climate computed.
        let r = plan.climate.kernel.len() / 2;
        let layers = &plan.lods[lod as usize].layers;
        let (mut x, mut z) = ([0.0f32; LANES], [0.0f32; LANES]);
        let (mut ero, mut rough, mut out) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
        let mut p = kernel::Partial::zero();
        for start in (0..n).step_by(LANES) {
            let m = (n - start).min(LANES);
            for l in 0..m {
                let v = start + l;
                let (i, j) = (v % w, v / w);
                x[l] = (gx0 + i as i64) as f32 * spacing_m;
                z[l] = (gz0 + j as i64) as f32 * spacing_m;
                (ero[l], rough[l]) = relief[v];
                let node = (j + r) * node_macro.w + i + r;
                p.elev[l] = node_macro.elev[node];
                p.amp[l] = node_macro.amp[node];
                p.ridge[l] = node_macro.ridge[node];
                (p.h[l], p.gx[l], p.gz[l]) = (0.0, 0.0, 0.0);
            }
            p.add_layers(plan, layers, &x, &z, &ero, &rough);
            p.finish(&mut out);
            heights[start..start + m].copy_from_slice(&out[..m]);
        }
    } else {
        let (mut x, mut z) = ([0.0f32; LANES], [0.0f32; LANES]);
        let (mut ero, mut rough, mut out) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
        for start in (0..n).step_by(LANES) {
            let m = (n - start).min(LANES);
            for l in 0..m {
                let v = start + l;
                x[l] = (gx0 + (v % w) as i64) as f32 * spacing_m;
                z[l] = (gz0 + (v / w) as i64) as f32 * spacing_m;
                (ero[l], rough[l]) = relief[v];
            }
            kernel::heights(plan, lod as usize, &x, &z, &ero, &rough, &mut out);
            heights[start..start + m].copy_from_slice(&out[..m]);
        }
    }
    let mut lake_fields = Vec::new();
    if let Some(rp) = plan.carve_plan(lod as usize) {
        let rj = rivers::job_for(plan, rp, spacing_m, gx0, gz0, w, h);
        lake_fields = carve(&rj, spacing_m, job, &mut heights);
    }
    Field {
        w,
        h,
        heights,
        weights,
        snow_line,
        lake_fields,
    }
}

/// Carves the rivers of `rj` into a job's heights: the CPU reference of the carve (the WGSL twin
/// is `shaders/rivers.wgsl`). Returns the lake field of each sample that the shores read
/// ([`rivers::RiverJob::carve_grid_fields`]; empty where none is near).
pub fn carve(
    rj: &rivers::RiverJob,
    spacing_m: f32,
    job: FieldJob,
    heights: &mut [f32],
) -> Vec<Option<rivers::LakeField>> {
    let xs: Vec<f32> = (0..job.w as i64)
        .map(|i| (job.gx0 + i) as f32 * spacing_m)
        .collect();
    let zs: Vec<f32> = (0..job.h as i64)
        .map(|j| (job.gz0 + j) as f32 * spacing_m)
        .collect();
    // Only the pieces that can reach each bin at its highest sample, a bin's samples side by
    // side (the same result, faster).
    rj.carve_grid_fields(&xs, &zs, heights)
}

/// Water surface (metres) and kind ([`rivers::kind`]) of tile `key`'s vertices, from their
/// final heights; empty when the world has no rivers (the water is the sea's, from the height).
/// `lake_fields` are the vertices' lake fields as the carve computed them (empty: computed
/// here).
pub fn tile_water(
    plan: &EarthPlan,
    key: super::tile::TileKey,
    spacing_m: f32,
    sea_level_m: f32,
    heights: &[f32],
    lake_fields: &[Option<rivers::LakeField>],
) -> (Vec<f32>, Vec<u8>) {
    let Some(rp) = &plan.rivers else {
        return (Vec::new(), Vec::new());
    };
    let n = super::plan::TILE_VERTS;
    let (gx0, gz0) = (
        key.x * super::plan::TILE_QUADS,
        key.z * super::plan::TILE_QUADS,
    );
    let rj = if let Some(cp) = plan.carve_plan(key.lod as usize) {
        rivers::water_job_for(plan, cp, spacing_m, gx0, gz0, n, n)
    } else if rp.lakes >= 5 {
        // The coarse network's lakes where the world has it: the fine network's floods over a
        // tile of 131 km and more cost tens of milliseconds cold.
        let lp = plan.coarse_rivers.as_ref().unwrap_or(rp);
        rivers::lake_job_for(plan, lp, spacing_m, gx0, gz0, n, n)
    } else {
        rivers::RiverJob::default()
    };
    let xs: Vec<f32> = (0..n as i64)
        .map(|i| (gx0 + i) as f32 * spacing_m)
        .collect();
    let zs: Vec<f32> = (0..n as i64)
        .map(|j| (gz0 + j) as f32 * spacing_m)
        .collect();
    let (mut surface, mut kinds) = (Vec::new(), Vec::new());
    rj.water_grid_fields(
        sea_level_m,
        (&xs, &zs),
        heights,
        lake_fields,
        &mut surface,
        &mut kinds,
    );
    (surface, kinds)
}

/// The river lines of tile `key` ([`rivers::RiverLine`]); empty when the world has no rivers.
pub fn tile_rivers(
    plan: &EarthPlan,
    key: super::tile::TileKey,
    spacing_m: f32,
) -> Vec<rivers::RiverLine> {
    let Some(rp) = &plan.rivers else {
        return Vec::new();
    };
    let span = super::plan::TILE_QUADS as f32 * spacing_m;
    let x0 = key.x as f32 * span;
    let z0 = key.z as f32 * span;
    rivers::Network::new(plan, rp).lines(x0, z0, x0 + span, z0 + span)
}
