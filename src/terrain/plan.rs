//! A world's precomputed constants: octave tables, biome-map constants and blur kernels per LOD.
//!
//! Building a plan does all the transcendental arithmetic (`pow`, `exp`, `log`) once, in `f64`,
//! with the pure-Rust `libm` crate (not the platform's libm, whose last bits differ between
//! versions, which would break same-bytes-on-every-node), and rounds to `f32`; the kernels (CPU and WGSL) only read the tables, so both paths start from
//! identical constants.

use super::biome::BiomeMapPlan;
use super::blur::kernel_for;
use super::earth::EarthPlan;
use super::fractal::{FractalPlan, MAX_OCTAVES};
use super::hash::{purpose, stream};
use super::texture::TexturePlan;
use super::world::{Generator, ParamError, WorldParams};

/// Finest LOD.
pub const MIN_LOD: u32 = 0;
/// Coarsest LOD served: a tile at LOD 12 spans 262 144 vertex spacings.
pub const MAX_LOD: u32 = 12;
/// Vertices per tile side.
pub const TILE_VERTS: usize = 65;
/// Quads per tile side.
pub const TILE_QUADS: i64 = 64;
/// Vertices per tile.
pub const TILE_VERTEX_COUNT: usize = TILE_VERTS * TILE_VERTS;
/// The supported world is the square `|X|, |Z| ≤ WORLD_LIMIT_CELLS · cell_m` metres: beyond it
/// `f32` positions lose the precision the finest octaves need.
pub const WORLD_LIMIT_CELLS: f64 = 1_048_576.0;

/// Constants of one LOD.
#[derive(Clone, Debug)]
pub struct LodPlan {
    /// Vertex spacing, metres.
    pub spacing_m: f32,
    /// Biome blur kernel, `2r + 1` taps (classic; `[1]` with `earth-1`, whose blur runs on its
    /// climate lattice).
    pub kernel: Vec<f32>,
    /// Height generator of each biome (classic; empty with `earth-1`).
    pub fractals: Vec<FractalPlan>,
}

/// Everything needed to synthesise any tile of a world.
#[derive(Clone, Debug)]
pub struct WorldPlan {
    /// World seed.
    pub seed: u64,
    /// World settings.
    pub params: WorldParams,
    /// Biome map constants.
    pub biome_map: BiomeMapPlan,
    /// Per-LOD constants, index = LOD.
    pub lods: Vec<LodPlan>,
    /// Proto-texturing constants.
    pub texture: TexturePlan,
    /// The `earth-1` kernels' constants; `None` for a classic world.
    pub earth: Option<EarthPlan>,
}

impl WorldPlan {
    /// Validates the settings and builds the plan.
    pub fn new(seed: u64, params: WorldParams) -> Result<Self, ParamError> {
        params.validate()?;
        let biome_map = BiomeMapPlan::new(&params.layout, params.biomes.len(), seed);
        let classic = params.generator == Generator::Classic;
        let lods = (MIN_LOD..=MAX_LOD)
            .map(|lod| {
                let spacing = params.cell_m as f64 * (1u64 << lod) as f64;
                let fractals = params
                    .biomes
                    .iter()
                    .filter_map(|b| b.generator.as_ref())
                    .map(|generator| {
                        // Octave `k` of every biome reads the same lattice: where biomes share a
                        // scale their low octaves coincide, so mountains continue across biome
                        // borders and the blur only hides differences of amplitude and roughness.
                        let seeds: Vec<u32> = (0..MAX_OCTAVES as u32)
                            .map(|k| stream(seed, purpose::OCTAVE, k + generator.first_octave))
                            .collect();
                        FractalPlan::new(generator, &params.warp, spacing, &seeds)
                    })
                    .collect();
                LodPlan {
                    spacing_m: spacing as f32,
                    kernel: if classic {
                        kernel_for(params.layout.blur_radius_m, spacing as f32)
                    } else {
                        vec![1.0]
                    },
                    fractals,
                }
            })
            .collect();
        let texture = TexturePlan::new(&params);
        let earth = (!classic).then(|| EarthPlan::new(seed, &params, biome_map));
        Ok(Self {
            seed,
            params,
            biome_map,
            lods,
            texture,
            earth,
        })
    }

    /// Number of biomes.
    pub fn biome_count(&self) -> usize {
        self.params.biomes.len()
    }

    /// Bound on how far a vertex's height at `lod` may differ from its height at LOD 0, metres.
    /// With `earth-1`, [`super::earth::EarthLod::bound_m`]. Classic:
    /// the largest amplitude the §4.1 octave count drops at that spacing, over the biomes (the
    /// fractional octave counted by its missing part). An octave's amplitude is its weight times
    /// the generator's amplitude times the largest lattice value, [`noise::LATTICE_MAX`]. The
    /// biome weights are the same at every LOD for generators that compute them on a fixed
    /// lattice; for the classic generator the blur adds the difference of the biomes' fields
    /// where its kernel changes, which this bound does not cover.
    pub fn lod_error_bound_m(&self, lod: u32) -> f32 {
        let lod = lod.min(MAX_LOD) as usize;
        if let Some(e) = &self.earth {
            return e.lods[lod].bound_m;
        }
        let mut worst = 0.0f64;
        for (fine, coarse) in self.lods[0].fractals.iter().zip(&self.lods[lod].fractals) {
            let dropped: f64 = fine
                .octaves
                .iter()
                .enumerate()
                .map(|(k, o)| {
                    let kept = coarse.octaves.get(k).map_or(0.0, |c| c.amp as f64);
                    (o.amp as f64 - kept).max(0.0)
                })
                .sum();
            worst = worst.max(dropped * fine.amplitude_m as f64);
        }
        (worst * super::noise::LATTICE_MAX as f64) as f32
    }

    /// Largest tile coordinate magnitude at a LOD that stays inside the supported world.
    pub fn max_tile_coord(&self, lod: u32) -> i64 {
        let tile_cells = TILE_QUADS as f64 * (1u64 << lod) as f64;
        (WORLD_LIMIT_CELLS / tile_cells) as i64 - 1
    }
}
