//! World settings: everything the procedural world function depends on besides the seed.
//!
//! Why one file of slightly over 600 lines: the settings types, their defaults and their validation
//! (every error naming its field) are the one schema of the `world` document.
//!
//! Units are in the field names' docs: metres, degrees, or plain numbers. `WorldParams::default()`
//! is the default scene's world: four biomes ordered from pole to equator, the paper's warping
//! constants and a 64 m biome blur (129 samples at LOD 0; `strata bench tiles` uses the paper's 35).

use super::earth::{BiomeRelief, EarthParams};
use super::fractal::{FractalParams, WarpParams};
use serde::{Deserialize, Serialize};

/// Surface materials of proto-texturing, in id order (the id is the index).
pub const MATERIALS: [&str; 6] = ["seabed", "sand", "grass", "dirt", "rock", "snow"];

/// Material ids, indices into [`MATERIALS`].
pub mod material {
    /// Ground below sea level.
    pub const SEABED: u8 = 0;
    /// Beaches and deserts.
    pub const SAND: u8 = 1;
    /// Grassland.
    pub const GRASS: u8 = 2;
    /// Bare soil of the tundra.
    pub const DIRT: u8 = 3;
    /// Steep slopes.
    pub const ROCK: u8 = 4;
    /// Above the snow line and in the arctic.
    pub const SNOW: u8 = 5;
}

/// One kind of object scattered over a biome.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScatterKind {
    /// Name given to clients (`"pine"`, `"boulder"`, `"deer"`).
    pub kind: String,
    /// Probability that a scatter candidate in this biome becomes this kind, in [0, 1]. A biome's
    /// densities sum to at most 1.
    pub density: f32,
    /// Steepest slope the object stands on, degrees.
    pub max_slope_deg: f32,
}

/// One biome: a Voronoi area type with its own height generator and ground.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Biome {
    /// Unique name.
    pub name: String,
    /// Height generator of this biome (the `classic` generator; absent with `earth-1`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub generator: Option<FractalParams>,
    /// Character of the relief in this biome (`earth-1`; absent means erosion and roughness 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relief: Option<BiomeRelief>,
    /// Material of flat ground below the snow line, one of [`MATERIALS`].
    pub ground: String,
    /// Height above which the ground is snow, metres.
    pub snow_line_m: f32,
    /// What grows and lives here.
    pub scatter: Vec<ScatterKind>,
}

/// The extended Voronoi biome layout of Choroś & Topolski §5.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BiomeLayout {
    /// Voronoi cell size ("biome size"), metres.
    pub cell_size_m: f32,
    /// Whether the biome follows latitude (Eq. 2 / Algorithm 2).
    pub latitude: bool,
    /// Latitude speed `S`: Voronoi cells from pole (value 0) to equator (value 1).
    pub latitude_speed_cells: f32,
    /// Whether dispersion is applied; without it (and with latitude) biomes form pure bands.
    pub dispersion: bool,
    /// Dispersion `d`: the Voronoi value is clamped to `[f − d, f + d]`, in [0, 1].
    pub dispersion_d: f32,
    /// Gaussian blur radius, metres; the kernel spans `2·round(radius/spacing) + 1` samples and
    /// `σ = radius / 3`.
    pub blur_radius_m: f32,
}

/// Proto-texturing thresholds (Schneider §4.2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Texturing {
    /// Slope at which rock takes over, degrees.
    pub rock_slope_deg: f32,
    /// Width of the rock transition, degrees.
    pub rock_blend_deg: f32,
    /// Beaches reach this high above sea level, metres.
    pub beach_height_m: f32,
    /// Width of the snow-line and beach transitions, metres.
    pub height_blend_m: f32,
    /// How the Ptex bake blends a height tile's ground materials, 1 or 2
    /// (`src/ptex/bake.rs`, step 1). `1`: each texel blends the dominant materials of the four
    /// vertices around it by their bilinear weights, so a material's border runs along the
    /// vertex lattice in steps one vertex spacing wide (64 m at LOD 6); worlds stored before `2`
    /// existed have no `ptex_blend` and keep it, and their pages' bytes. `2` (new worlds): each
    /// texel evaluates these thresholds at its own height and slope, from the height above the
    /// sea, the height above the snow line, the normal and the biomes' ground shares
    /// interpolated between the four vertices ([`crate::terrain::texture::texel_weights`]), so
    /// a border follows the terrain's contours and slope breaks at the texel's resolution.
    #[serde(
        default = "Texturing::first_ptex_blend",
        skip_serializing_if = "Texturing::is_first_ptex_blend"
    )]
    pub ptex_blend: u32,
    /// The alpine zone, a fraction of the snow line's height above the sea: bare rock and
    /// scree take over the ground from `(1 − alpine_fraction)` of that height up to a quarter
    /// of the band below the snow line (above the tree line, where the climate's cooled
    /// biomes would keep their grass and soil up to the summits;
    /// [`crate::terrain::texture`]). `0.25` in new worlds (a 2.8 km snow line: rock from
    /// 2.1 km, half the ground at 2.36 km, all of it from 2.63 km); worlds stored before it
    /// have none (`0`, absent) and keep their materials and pages.
    #[serde(default, skip_serializing_if = "Texturing::is_no_alpine")]
    pub alpine_fraction: f32,
}

impl Texturing {
    fn is_no_alpine(v: &f32) -> bool {
        *v == 0.0
    }

    fn first_ptex_blend() -> u32 {
        1
    }

    fn is_first_ptex_blend(v: &u32) -> bool {
        *v == 1
    }
}

/// Scatter placement (Choroś §5).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScatterParams {
    /// Spacing of the world-anchored candidate lattice at LOD 0, metres; a tile at LOD `l` keeps
    /// the candidates whose level is at least `l` (a quarter of them per level).
    pub spacing_m: f32,
    /// How candidates get their level; documents without it are [`ScatterLattice::Scan`].
    #[serde(default, skip_serializing_if = "ScatterLattice::is_scan")]
    pub lattice: ScatterLattice,
}

/// How a world's scatter candidates get their level ([`super::scatter`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ScatterLattice {
    /// One lattice of `spacing_m` whose candidates each hash a level: a tile visits every
    /// candidate of its area, so a tile one LOD coarser visits 4 times as many. Worlds stored
    /// before `levels` keep it, and their bytes.
    #[default]
    #[serde(rename = "scan")]
    Scan,
    /// One lattice per level `L` of spacing `spacing_m · 2^L` whose candidates have level `L`:
    /// a tile visits about the same number of candidates at every LOD.
    #[serde(rename = "levels")]
    Levels,
}

impl ScatterLattice {
    /// Whether this is the stored worlds' [`ScatterLattice::Scan`] (which documents leave out).
    pub fn is_scan(&self) -> bool {
        *self == ScatterLattice::Scan
    }
}

/// Which world function a world uses. Stored scenes name theirs, so a world keeps its bytes when
/// the default changes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Generator {
    /// The first wave's world: one warped multifractal per Voronoi biome, blended by a blur of
    /// the biome map. A world document without `generator` is classic.
    #[default]
    #[serde(rename = "classic")]
    Classic,
    /// Continents, mountain belts, relief and gully layers, climate biomes ([`super::earth`]).
    #[serde(rename = "earth-1")]
    Earth1,
}

impl Generator {
    /// Whether this is the classic generator (which documents leave unnamed).
    pub fn is_classic(&self) -> bool {
        *self == Generator::Classic
    }
}

/// Everything the procedural world function depends on besides the seed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WorldParams {
    /// The world function; `"classic"` when absent (every world stored before `earth-1`).
    #[serde(default, skip_serializing_if = "Generator::is_classic")]
    pub generator: Generator,
    /// Settings of the `earth-1` generator; required with it, absent with `classic`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub earth: Option<EarthParams>,
    /// LOD-0 vertex spacing, metres.
    pub cell_m: f32,
    /// Water level, metres.
    pub sea_level_m: f32,
    /// §2.2 domain-warping constants.
    pub warp: WarpParams,
    /// Biome placement.
    pub layout: BiomeLayout,
    /// Biomes from pole (Voronoi value 0) to equator (value 1); at most [`MAX_BIOMES`].
    pub biomes: Vec<Biome>,
    /// Proto-texturing.
    pub texturing: Texturing,
    /// Scatter.
    pub scatter: ScatterParams,
    /// How volume chunks find the subsurface material of their vertices (`subsurface::carve`),
    /// 1 or 2. `1`: a vertex's probe into the solid reads the ground from the chunk's padded
    /// columns, clamped to them, so two chunks sharing a vertex on their border can give it
    /// different materials; worlds stored before `2` existed have no `chunk_geology` and keep
    /// it, and their bytes. `2` (new worlds): the probe reads the ground from the columns of the
    /// chunk and its eight neighbours, which hold every probe, at world-anchored positions, so
    /// every chunk gives a vertex the same material.
    #[serde(
        default = "WorldParams::first_chunk_geology",
        skip_serializing_if = "WorldParams::is_first_chunk_geology"
    )]
    pub chunk_geology: u32,
}

/// Most biomes a world may have.
pub const MAX_BIOMES: usize = 8;

fn gen(base_m: f32, amplitude_m: f32, scale_m: f32, hurst: f32) -> Option<FractalParams> {
    Some(FractalParams {
        base_m,
        amplitude_m,
        scale_m,
        lacunarity: 2.0,
        hurst,
        first_octave: 0,
        octaves: 8,
        warp: true,
    })
}

fn kinds(list: &[(&str, f32, f32)]) -> Vec<ScatterKind> {
    list.iter()
        .map(|&(kind, density, max_slope_deg)| ScatterKind {
            kind: kind.into(),
            density,
            max_slope_deg,
        })
        .collect()
}

impl Default for WorldParams {
    /// The world of bare seeds and new worlds: [`WorldParams::earth`].
    fn default() -> Self {
        Self::earth()
    }
}

impl WorldParams {
    /// The `earth-1` world: continents, mountain belts, eroded relief and six climate biomes
    /// from pole to equator on Voronoi cells of 32 km, a pole-to-equator range of 2 048 km with
    /// the origin at mid-latitude, and an 8 km blur on the climate lattice.
    pub fn earth() -> Self {
        let biome = |name: &str, ground: &str, snow_line_m, erosion, roughness, scatter| Biome {
            name: name.into(),
            generator: None,
            relief: Some(BiomeRelief { erosion, roughness }),
            ground: ground.into(),
            snow_line_m,
            scatter,
        };
        Self {
            generator: Generator::Earth1,
            earth: Some(EarthParams::default()),
            cell_m: 1.0,
            sea_level_m: 0.0,
            warp: WarpParams::default(),
            layout: BiomeLayout {
                cell_size_m: 32_000.0,
                latitude: true,
                latitude_speed_cells: 64.0,
                dispersion: true,
                dispersion_d: 0.12,
                blur_radius_m: 8192.0,
            },
            biomes: vec![
                biome(
                    "ice",
                    "snow",
                    -1e9,
                    0.6,
                    0.7,
                    kinds(&[("ice_boulder", 0.01, 30.0), ("seal", 0.002, 10.0)]),
                ),
                biome(
                    "tundra",
                    "dirt",
                    600.0,
                    0.8,
                    0.9,
                    kinds(&[
                        ("lichen_rock", 0.03, 35.0),
                        ("shrub", 0.08, 30.0),
                        ("reindeer", 0.003, 20.0),
                    ]),
                ),
                biome(
                    "taiga",
                    "grass",
                    1600.0,
                    1.0,
                    1.0,
                    kinds(&[
                        ("pine", 0.12, 30.0),
                        ("boulder", 0.01, 40.0),
                        ("elk", 0.003, 20.0),
                    ]),
                ),
                biome(
                    "temperate",
                    "grass",
                    2600.0,
                    1.1,
                    1.0,
                    kinds(&[
                        ("oak", 0.05, 25.0),
                        ("bush", 0.10, 30.0),
                        ("deer", 0.004, 20.0),
                    ]),
                ),
                biome(
                    "steppe",
                    "dirt",
                    3800.0,
                    0.9,
                    0.8,
                    kinds(&[("shrub", 0.05, 30.0), ("horse", 0.002, 15.0)]),
                ),
                biome(
                    "desert",
                    "sand",
                    5200.0,
                    0.7,
                    0.6,
                    kinds(&[
                        ("cactus", 0.02, 20.0),
                        ("dry_rock", 0.01, 40.0),
                        ("camel", 0.002, 15.0),
                    ]),
                ),
            ],
            texturing: Texturing {
                rock_slope_deg: 38.0,
                rock_blend_deg: 8.0,
                beach_height_m: 2.0,
                height_blend_m: 6.0,
                ptex_blend: 2,
                alpine_fraction: 0.25,
            },
            scatter: ScatterParams {
                spacing_m: 4.0,
                lattice: ScatterLattice::Levels,
            },
            chunk_geology: 2,
        }
    }
}

impl WorldParams {
    /// The first wave's world (the `classic` generator): four biomes ordered from pole to equator,
    /// each its own warped multifractal, Voronoi cells of 512 m.
    pub fn classic() -> Self {
        let biome = |name: &str, generator, ground: &str, snow_line_m, scatter| Biome {
            name: name.into(),
            generator,
            relief: None,
            ground: ground.into(),
            snow_line_m,
            scatter,
        };
        Self {
            generator: Generator::Classic,
            earth: None,
            cell_m: 1.0,
            sea_level_m: 0.0,
            warp: WarpParams::default(),
            layout: BiomeLayout {
                cell_size_m: 512.0,
                latitude: true,
                latitude_speed_cells: 8.0,
                dispersion: true,
                dispersion_d: 0.2,
                blur_radius_m: 64.0,
            },
            biomes: vec![
                biome(
                    "arctic",
                    gen(30.0, 190.0, 8000.0, 0.85),
                    "snow",
                    -1e9,
                    kinds(&[("ice_boulder", 0.01, 30.0), ("seal", 0.002, 10.0)]),
                ),
                biome(
                    "tundra",
                    gen(30.0, 175.0, 8000.0, 0.85),
                    "dirt",
                    90.0,
                    kinds(&[
                        ("lichen_rock", 0.03, 35.0),
                        ("shrub", 0.08, 30.0),
                        ("reindeer", 0.003, 20.0),
                    ]),
                ),
                biome(
                    "grassland",
                    gen(30.0, 170.0, 8000.0, 0.85),
                    "grass",
                    160.0,
                    kinds(&[
                        ("oak", 0.05, 25.0),
                        ("bush", 0.10, 30.0),
                        ("deer", 0.004, 20.0),
                    ]),
                ),
                biome(
                    "desert",
                    gen(30.0, 160.0, 8000.0, 0.85),
                    "sand",
                    1e9,
                    kinds(&[
                        ("cactus", 0.02, 20.0),
                        ("dry_rock", 0.01, 40.0),
                        ("camel", 0.002, 15.0),
                    ]),
                ),
            ],
            texturing: Texturing {
                rock_slope_deg: 38.0,
                rock_blend_deg: 8.0,
                beach_height_m: 2.0,
                height_blend_m: 6.0,
                ptex_blend: Texturing::first_ptex_blend(),
                alpine_fraction: 0.0,
            },
            scatter: ScatterParams {
                spacing_m: 4.0,
                lattice: ScatterLattice::Scan,
            },
            chunk_geology: WorldParams::first_chunk_geology(),
        }
    }
}

/// A world setting that is out of range; `field` is a JSON pointer-like path.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct ParamError {
    /// Path of the offending field, e.g. `biomes[2].generator.hurst`.
    pub field: String,
    /// What is wrong with it.
    pub message: String,
}

fn check(ok: bool, field: impl Into<String>, message: &str) -> Result<(), ParamError> {
    if ok {
        Ok(())
    } else {
        Err(ParamError {
            field: field.into(),
            message: message.into(),
        })
    }
}

/// Checks a classic biome generator; `f` turns a field name into the biome's path.
fn check_fractal(
    g: &FractalParams,
    cell_m: f32,
    f: &dyn Fn(&str) -> String,
) -> Result<(), ParamError> {
    check(
        g.base_m.is_finite() && g.base_m.abs() <= 10_000.0,
        f("generator.base_m"),
        "must be in [-10000, 10000]",
    )?;
    check(
        g.amplitude_m.is_finite() && g.amplitude_m > 0.0 && g.amplitude_m <= 5_000.0,
        f("generator.amplitude_m"),
        "must be in (0, 5000]",
    )?;
    check(
        g.scale_m.is_finite() && g.scale_m >= 4.0 * cell_m && g.scale_m <= 1.0e6,
        f("generator.scale_m"),
        "must be in [4 vertex spacings, 1e6]",
    )?;
    check(
        g.lacunarity.is_finite() && (1.1..=4.0).contains(&g.lacunarity),
        f("generator.lacunarity"),
        "must be in [1.1, 4]",
    )?;
    check(
        g.hurst.is_finite() && g.hurst > 0.05 && g.hurst <= 1.0,
        f("generator.hurst"),
        "must be in (0.05, 1]",
    )?;
    check(
        g.octaves >= 1 && g.octaves as usize <= super::fractal::MAX_OCTAVES,
        f("generator.octaves"),
        "must be in [1, 16]",
    )?;
    check(
        g.first_octave <= 8,
        f("generator.first_octave"),
        "must be in [0, 8]",
    )?;
    Ok(())
}

impl WorldParams {
    fn first_chunk_geology() -> u32 {
        1
    }

    fn is_first_chunk_geology(v: &u32) -> bool {
        *v == 1
    }

    /// Checks every limit; the server calls this before accepting a scene.
    pub fn validate(&self) -> Result<(), ParamError> {
        check(
            self.cell_m.is_finite() && (0.01..=1000.0).contains(&self.cell_m),
            "cell_m",
            "must be in [0.01, 1000]",
        )?;
        check(
            self.sea_level_m.is_finite(),
            "sea_level_m",
            "must be finite",
        )?;
        let w = &self.warp;
        let finite = [w.c1, w.c2, w.c3, w.r0, w.t0]
            .iter()
            .flatten()
            .all(|v| v.is_finite() && v.abs() <= 100.0);
        check(
            finite,
            "warp",
            "c1, c2, c3, r0 and t0 must be finite and within ±100",
        )?;
        check(
            (w.r0[0] * w.r0[0] + w.r0[1] * w.r0[1] - 1.0).abs() < 1e-3,
            "warp.r0",
            "must be a unit vector",
        )?;
        check(
            w.lever.is_finite() && (0.0..=100.0).contains(&w.lever),
            "warp.lever",
            "must be in [0, 100]",
        )?;
        let l = &self.layout;
        check(
            l.cell_size_m.is_finite() && l.cell_size_m >= 16.0 * self.cell_m,
            "layout.cell_size_m",
            "must be at least 16 vertex spacings",
        )?;
        check(
            l.latitude_speed_cells.is_finite() && l.latitude_speed_cells >= 1.0,
            "layout.latitude_speed_cells",
            "must be at least 1",
        )?;
        check(
            (0.0..=1.0).contains(&l.dispersion_d),
            "layout.dispersion_d",
            "must be in [0, 1]",
        )?;
        match self.generator {
            // The classic blur runs on each LOD's vertex lattice: at most 129 taps at LOD 0.
            Generator::Classic => check(
                l.blur_radius_m.is_finite()
                    && (0.0..=64.0 * self.cell_m).contains(&l.blur_radius_m),
                "layout.blur_radius_m",
                "must be in [0, 64 vertex spacings]",
            )?,
            // The earth-1 blur runs on the 4 km climate lattice: at most 17 taps.
            Generator::Earth1 => check(
                l.blur_radius_m.is_finite() && (0.0..=32_768.0).contains(&l.blur_radius_m),
                "layout.blur_radius_m",
                "must be in [0, 32768] with the earth-1 generator",
            )?,
        }
        match (&self.generator, &self.earth) {
            (Generator::Classic, Some(_)) => check(
                false,
                "earth",
                "applies to the earth-1 generator only; remove it or set generator to earth-1",
            )?,
            (Generator::Earth1, None) => {
                check(false, "earth", "is required with the earth-1 generator")?
            }
            (Generator::Earth1, Some(e)) => e.validate(self.cell_m)?,
            (Generator::Classic, None) => {}
        }
        check(
            !self.biomes.is_empty() && self.biomes.len() <= MAX_BIOMES,
            "biomes",
            "must have 1 to 8 biomes",
        )?;
        for (i, b) in self.biomes.iter().enumerate() {
            let f = |name: &str| format!("biomes[{i}].{name}");
            check(
                !b.name.is_empty() && self.biomes.iter().filter(|o| o.name == b.name).count() == 1,
                f("name"),
                "must be non-empty and unique",
            )?;
            check(
                MATERIALS.contains(&b.ground.as_str()),
                f("ground"),
                "must name a material",
            )?;
            if let Some(r) = &b.relief {
                check(
                    self.generator == Generator::Earth1,
                    f("relief"),
                    "applies to the earth-1 generator only",
                )?;
                r.validate(&format!("biomes[{i}]"))?;
            }
            match (&self.generator, &b.generator) {
                (Generator::Classic, Some(g)) => check_fractal(g, self.cell_m, &f)?,
                (Generator::Earth1, None) => {}
                (Generator::Classic, None) => check(
                    false,
                    f("generator"),
                    "is required with the classic generator",
                )?,
                (Generator::Earth1, Some(_)) => check(
                    false,
                    f("generator"),
                    "applies to the classic generator only",
                )?,
            }
            let mut total = 0.0;
            for (k, s) in b.scatter.iter().enumerate() {
                check(
                    (0.0..=1.0).contains(&s.density),
                    format!("biomes[{i}].scatter[{k}].density"),
                    "must be in [0, 1]",
                )?;
                total += s.density;
            }
            check(
                total <= 1.0 + 1e-6,
                f("scatter"),
                "densities must sum to at most 1",
            )?;
        }
        check(
            self.scatter.spacing_m.is_finite() && self.scatter.spacing_m >= self.cell_m,
            "scatter.spacing_m",
            "must be at least cell_m",
        )?;
        check(
            (1..=2).contains(&self.chunk_geology),
            "chunk_geology",
            "must be 1 or 2",
        )?;
        check(
            (1..=2).contains(&self.texturing.ptex_blend),
            "texturing.ptex_blend",
            "must be 1 or 2",
        )?;
        check(
            (0.0..=0.9).contains(&self.texturing.alpine_fraction),
            "texturing.alpine_fraction",
            "must be in [0, 0.9]",
        )?;
        Ok(())
    }

    /// Index of a material name in [`MATERIALS`].
    pub fn material_id(name: &str) -> u8 {
        MATERIALS.iter().position(|m| *m == name).unwrap_or(0) as u8
    }
}
