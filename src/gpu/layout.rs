//! Host-side images of the WGSL structs of `shaders/common.wgsl`, `shaders/tile.wgsl`,
//! `shaders/earth.wgsl` and `shaders/rivers.wgsl`.
//!
//! Each struct is `#[repr(C)]`, [`bytemuck::Pod`] and matches its WGSL struct field for field
//! (offsets are checked against the offsets naga computes, by `tests/shaders_naga.rs`). Only 4-byte
//! scalars, `vec2<f32>` (`[f32; 2]`, 8-byte aligned in WGSL, placed at multiples of 8 here) and
//! arrays of 16-byte structs are used, so the C layout and the WGSL layout coincide without hidden
//! padding. Every value is copied from [`crate::terrain::WorldPlan`] (which did the transcendental
//! arithmetic in `f64`) or, for the river carve, from the field's
//! [`crate::terrain::earth::rivers::RiverJob`], never recomputed.

use crate::terrain::biome::BiomeMapPlan;
use crate::terrain::earth::{Layer, LayerKind, NoiseOctave};
use crate::terrain::fractal::{FractalPlan, MAX_OCTAVES};
use bytemuck::{Pod, Zeroable};

/// WGSL `Octave`: one octave of Eq. 1 (`terrain::fractal::Octave`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuOctave {
    /// `r^k`.
    pub freq: f32,
    /// `r^{-kH}` (times the fractional weight of the last octave).
    pub amp: f32,
    /// Stream seed of the octave's lattice.
    pub seed: u32,
    /// Padding to 16 bytes.
    pub _pad: u32,
}

/// WGSL `Fractal`: one biome's generator at one LOD (`terrain::fractal::FractalPlan`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct GpuFractal {
    /// Metres to domain units.
    pub inv_scale: f32,
    /// Height where the fractal is zero, metres.
    pub base_m: f32,
    /// Metres per unit of the sum.
    pub amplitude_m: f32,
    /// Number of valid entries of `octaves`.
    pub octave_count: u32,
    /// 1 if §2.2 warping is applied.
    pub warp: u32,
    /// `R0`.
    pub rough0: f32,
    /// Lever of the rotation, domain units (`WarpConsts::lever`).
    pub lever: f32,
    /// 1 to rotate about the world origin (the paper's literal formula).
    pub about_origin: u32,
    /// `c1`.
    pub c1: [f32; 2],
    /// `c2`.
    pub c2: [f32; 2],
    /// Translation of every octave after the first.
    pub t: [f32; 2],
    /// Initial rotation.
    pub r0: [f32; 2],
    /// Initial translation.
    pub t0: [f32; 2],
    /// Padding (`octaves` starts at 80).
    pub _pad2: [f32; 2],
    /// Octave table.
    pub octaves: [GpuOctave; MAX_OCTAVES],
}

impl From<&FractalPlan> for GpuFractal {
    fn from(f: &FractalPlan) -> Self {
        let mut g = GpuFractal::zeroed();
        g.inv_scale = f.inv_scale;
        g.base_m = f.base_m;
        g.amplitude_m = f.amplitude_m;
        let n = f.octaves.len().min(MAX_OCTAVES);
        g.octave_count = n as u32;
        for (dst, src) in g.octaves.iter_mut().zip(&f.octaves[..n]) {
            *dst = GpuOctave {
                freq: src.freq,
                amp: src.amp,
                seed: src.seed,
                _pad: 0,
            };
        }
        if let Some(w) = &f.warp {
            g.warp = 1;
            g.rough0 = w.rough0;
            g.c1 = w.c1;
            g.c2 = w.c2;
            g.t = w.t;
            g.r0 = w.r0;
            g.t0 = w.t0;
            g.lever = w.lever;
            g.about_origin = w.about_origin as u32;
        }
        g
    }
}

/// WGSL `BiomeMap` (`terrain::biome::BiomeMapPlan`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuBiomeMap {
    /// `1 / cell_size_m`.
    pub inv_cell: f32,
    /// Latitude speed `S`, cells.
    pub speed: f32,
    /// Dispersion `d` (0 without dispersion).
    pub dispersion: f32,
    /// 1 if latitude applies.
    pub latitude: u32,
    /// Number of biomes `K`.
    pub count: u32,
    /// Voronoi stream of seed x offsets.
    pub seed_x: u32,
    /// Voronoi stream of seed z offsets.
    pub seed_z: u32,
    /// Voronoi stream of cell values.
    pub seed_value: u32,
}

impl From<&BiomeMapPlan> for GpuBiomeMap {
    fn from(m: &BiomeMapPlan) -> Self {
        Self {
            inv_cell: m.inv_cell,
            speed: m.speed,
            dispersion: m.dispersion,
            latitude: m.latitude as u32,
            count: m.count,
            seed_x: m.seeds.x,
            seed_z: m.seeds.z,
            seed_value: m.seeds.value,
        }
    }
}

/// WGSL `Params` of `tile.wgsl` (a uniform buffer): the rectangle, the derived grids and the
/// biome map. `map` sits at offset 64, a multiple of 16 as the uniform address space requires.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuParams {
    /// Output rectangle origin, lattice index.
    pub gx0: i32,
    /// Output rectangle origin, lattice index.
    pub gz0: i32,
    /// Output columns.
    pub w: u32,
    /// Output rows.
    pub h: u32,
    /// Biome grid origin (`gx0 − r`).
    pub bgx0: i32,
    /// Biome grid origin (`gz0 − r`).
    pub bgz0: i32,
    /// Biome grid columns (`w + 2r`).
    pub bw: u32,
    /// Biome grid rows (`h + 2r`).
    pub bh: u32,
    /// First block column (`bgx0.div_euclid(8)`).
    pub bx0: i32,
    /// First block row.
    pub bz0: i32,
    /// Block-corner grid columns (blocks + 1).
    pub cw: u32,
    /// Block-corner grid rows.
    pub ch: u32,
    /// Blur taps `2r + 1`.
    pub taps: u32,
    /// Number of biomes.
    pub k: u32,
    /// Vertex spacing, metres.
    pub spacing: f32,
    /// Always 0: the runtime zero of the rounding barrier `rn` in `common.wgsl`.
    pub rounding_key: u32,
    /// Biome map constants.
    pub map: GpuBiomeMap,
}

/// WGSL `EarthOctave` of `earth.wgsl` (`terrain::earth::NoiseOctave`, padded to 32 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuEarthOctave {
    /// Lattice cells per metre.
    pub freq: f32,
    /// Weight of the octave.
    pub amp: f32,
    /// Stream seed of the octave's lattice.
    pub seed: u32,
    /// Cosine of the octave's rotation.
    pub cos: f32,
    /// Sine of the octave's rotation.
    pub sin: f32,
    /// Lattice offset, cells.
    pub ox: f32,
    /// Lattice offset, cells.
    pub oz: f32,
    /// Padding to 32 bytes.
    pub _pad: u32,
}

impl From<&NoiseOctave> for GpuEarthOctave {
    fn from(o: &NoiseOctave) -> Self {
        Self {
            freq: o.freq,
            amp: o.amp,
            seed: o.seed,
            cos: o.cos,
            sin: o.sin,
            ox: o.ox,
            oz: o.oz,
            _pad: 0,
        }
    }
}

/// WGSL `EarthLayer` of `earth.wgsl` (`terrain::earth::Layer`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuEarthLayer {
    /// 0: relief, 1: gully.
    pub kind: u32,
    /// 1 if a relief layer is scaled by the roughness.
    pub fine: u32,
    /// 1 if a relief layer is mixed towards ridged by the ridge mix, or a gully layer is
    /// incised.
    pub ridged: u32,
    /// Amplitude relative to the local relief, times the LOD weight.
    pub amp: f32,
    /// The layer's noise (`amp` unused).
    pub octave: GpuEarthOctave,
    /// A gully layer's squared phasor floor (`LayerKind::Gully::floor2`); 0 for relief.
    pub floor2: f32,
}

impl From<&Layer> for GpuEarthLayer {
    fn from(l: &Layer) -> Self {
        let (kind, fine, ridged, floor2) = match l.kind {
            LayerKind::Relief { fine, ridged } => (0, fine as u32, ridged as u32, 0.0),
            LayerKind::Gully { incised, floor2 } => (1, 0, incised as u32, floor2),
        };
        Self {
            kind,
            fine,
            ridged,
            amp: l.amp,
            octave: GpuEarthOctave::from(&l.octave),
            floor2,
        }
    }
}

/// WGSL `EarthParams` of `earth.wgsl` (a uniform buffer, 112 bytes): the rectangle, the counts
/// of the macro octaves and layers, and the scalars of `terrain::earth::MacroPlan`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuEarthParams {
    /// Output rectangle origin, lattice index.
    pub gx0: i32,
    /// Output rectangle origin, lattice index.
    pub gz0: i32,
    /// Output columns.
    pub w: u32,
    /// Output rows.
    pub h: u32,
    /// Vertex spacing, metres.
    pub spacing: f32,
    /// Always 0: the runtime zero of the rounding barrier `rn` in `common.wgsl`.
    pub rounding_key: u32,
    /// Layers of the LOD.
    pub layer_count: u32,
    /// Warp-x octaves (first in the octave buffer).
    pub warp_x_count: u32,
    /// Warp-z octaves.
    pub warp_z_count: u32,
    /// Continent octaves.
    pub continent_count: u32,
    /// Belt octaves.
    pub belt_count: u32,
    /// Hill-country octaves.
    pub hills_count: u32,
    /// `MacroPlan::land_bias`.
    pub land_bias: f32,
    /// `MacroPlan::origin_land`.
    pub origin_land: f32,
    /// `MacroPlan::inv_origin_r2`.
    pub inv_origin_r2: f32,
    /// `MacroPlan::belt_width`.
    pub belt_width: f32,
    /// `MacroPlan::mountain_relief_m`.
    pub mountain_relief_m: f32,
    /// `MacroPlan::hill_relief_m`.
    pub hill_relief_m: f32,
    /// `MacroPlan::plain_relief_m`.
    pub plain_relief_m: f32,
    /// `MacroPlan::seafloor_relief_m`.
    pub seafloor_relief_m: f32,
    /// `MacroPlan::interior_height_m`.
    pub interior_height_m: f32,
    /// `MacroPlan::ocean_depth_m`.
    pub ocean_depth_m: f32,
    /// `EarthPlan::inv_relief_max`.
    pub inv_relief_max: f32,
    /// Samples per lattice spacing of the LOD's split (`earth::lattice::Lattice::step`), or 0
    /// when every layer is evaluated at every sample.
    pub lattice_step: u32,
    /// Leading layers whose sum the nodes hold (`Lattice::prefix`).
    pub prefix: u32,
    /// First node column of the uploaded nodes (world lattice index).
    pub node_i0: i32,
    /// First node row of the uploaded nodes.
    pub node_k0: i32,
    /// Node columns of the uploaded nodes.
    pub nodes_w: u32,
    /// Padding to a multiple of 16 bytes.
    pub _pad0: u32,
    /// Padding.
    pub _pad1: u32,
    /// Padding.
    pub _pad2: u32,
}

/// The level uploaded for a node of the lake window that holds no lake (the CPU's NaN: a shader
/// may assume no NaN exists, so none is uploaded).
pub const LAKE_NONE: f32 = -3.0e38;

/// WGSL `CarveParams` of `rivers.wgsl` (a uniform buffer, 112 bytes): the rectangle of the
/// heights, the bin grid of `terrain::earth::rivers::RiverJob`, its walls' width noise and its
/// lake window (the levels are uploaded beside it, [`LAKE_NONE`] for a node without a lake, and after
/// them the lake nodes' heights where `sink` is 1). The pieces are uploaded as
/// `rivers::Piece` itself, whose `#[repr(C)]` layout is the WGSL `Piece`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuCarveParams {
    /// Output rectangle origin, lattice index.
    pub gx0: i32,
    /// Output rectangle origin, lattice index.
    pub gz0: i32,
    /// Output columns.
    pub w: u32,
    /// Output rows.
    pub h: u32,
    /// Vertex spacing, metres.
    pub spacing: f32,
    /// Always 0: the runtime zero of the rounding barrier `rn` in `common.wgsl`.
    pub rounding_key: u32,
    /// `RiverJob::x0`: west edge of the bin grid, metres.
    pub x0: f32,
    /// `RiverJob::z0`: north edge of the bin grid, metres.
    pub z0: f32,
    /// `RiverJob::bin_m`: bin side, metres.
    pub bin_m: f32,
    /// `RiverJob::bins_w`, or 0 when the job has no bins (`bin_start` empty).
    pub bins_w: u32,
    /// `RiverJob::bins_h`, or 0 when the job has no bins.
    pub bins_h: u32,
    /// `RiverJob::wall_noise`: amplitude of the walls' width noise (0: none).
    pub wall_noise: f32,
    /// `RiverJob::wall_seed`.
    pub wall_seed: u32,
    /// `RiverJob::spacing_m`: the river node spacing, metres.
    pub node_spacing: f32,
    /// `RiverJob::li0`: first node column of the lake window.
    pub li0: i32,
    /// `RiverJob::lk0`: first node row of the lake window.
    pub lk0: i32,
    /// `RiverJob::lakes_w`: node columns of the lake window (0: no lake near).
    pub lakes_w: u32,
    /// Node rows of the lake window (0: no lake near).
    pub lakes_h: u32,
    /// 1 where the lakes have shaped shores (`RiverJob::shores`), else 0.
    pub shores: u32,
    /// `RiverJob::shore_seeds[0]`: the shores' first noise octave.
    pub shore_seed0: u32,
    /// `RiverJob::shore_seeds[1]`: the shores' second noise octave.
    pub shore_seed1: u32,
    /// `RiverJob::shore_seeds[2]`: the warp's x.
    pub shore_seed2: u32,
    /// `RiverJob::shore_seeds[3]`: the warp's z.
    pub shore_seed3: u32,
    /// `RiverJob::shore_warp_m`.
    pub shore_warp_m: f32,
    /// `RiverJob::shore_warp_inv_m`.
    pub shore_warp_inv_m: f32,
    /// `RiverJob::sills` (0 or 1).
    pub sills: u32,
    /// `RiverJob::shore_n[0]`: scale of the shoreline's first noise octave.
    pub shore_n1: f32,
    /// `RiverJob::shore_n[1]`: scale of its second octave.
    pub shore_n2: f32,
    /// 1 where the shores sink the ground inside a lake towards its nodes' heights
    /// (`RiverJob::sink`, `lakes: 8`; the heights follow the levels in the lake buffer), else 0.
    pub sink: u32,
}
