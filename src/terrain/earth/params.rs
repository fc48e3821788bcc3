//! Settings of the `earth-1` generator (scene units: metres and plain numbers) and their limits.

use super::super::world::ParamError;
use serde::{Deserialize, Serialize};

/// The tectonic and climatic structure of an `earth-1` world. Every length is in metres.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EarthParams {
    /// Lattice spacing of the first continent octave, metres: continents and oceans are about
    /// this wide.
    pub continent_scale_m: f32,
    /// Added to the continent value before the coast is placed at 0: more land when positive,
    /// in [-1, 1].
    pub land_bias: f32,
    /// Extra continent value at the origin, fading with the square of the distance over
    /// `origin_land_radius_m`: keeps the place where players start on land (0 turns it off).
    pub origin_land: f32,
    /// Radius of the origin's land bias, metres.
    pub origin_land_radius_m: f32,
    /// Depth of the abyssal ocean floor below sea level, metres.
    pub ocean_depth_m: f32,
    /// Height of inland plains far from the coast above sea level, metres.
    pub interior_height_m: f32,
    /// Lattice spacing of the mountain-belt pattern, metres (belts are a fraction of it wide).
    pub belt_scale_m: f32,
    /// Half-width of a belt in units of the belt noise (larger: wider belts), in (0, 1].
    pub belt_width: f32,
    /// Relief of the highest mountain belts, metres.
    pub mountain_relief_m: f32,
    /// Relief of hill country, metres.
    pub hill_relief_m: f32,
    /// Relief of plains, metres.
    pub plain_relief_m: f32,
    /// Relief of the ocean floor, metres.
    pub seafloor_relief_m: f32,
    /// Wavelength of the largest ridges, metres; each further octave halves it.
    pub ridge_scale_m: f32,
    /// Height octaves at the finest LOD (the §4.1 rule drops the ones a coarser spacing cannot
    /// resolve), in [1, 20].
    pub octaves: u32,
    /// Ratio of the amplitudes of successive height octaves, in (0, 1).
    pub gain: f32,
    /// Wavelength below which octaves fall off by `detail_gain` instead (hillslopes are
    /// smoother than the self-similar extrapolation of the large relief), metres.
    pub detail_scale_m: f32,
    /// Ratio of the amplitudes of successive octaves below `detail_scale_m`, in (0, 1).
    pub detail_gain: f32,
    /// Erosion filter: strength (0 turns it off), in [0, 2].
    pub erosion: f32,
    /// Erosion filter: spacing of the coarsest gully lattice, metres.
    pub gully_scale_m: f32,
    /// Erosion filter: gully octaves, each half the spacing of the previous, in [0, 8].
    pub gully_octaves: u32,
    /// Erosion filter: the gullies' cross-section, 1 to 3. `1`: a cosine, as high on its crests
    /// as it is deep in its troughs (worlds stored before `2` existed have no `gullies` and keep
    /// it, and their bytes); `2` (new worlds until `3`): incised, V-shaped troughs between broad
    /// rounded crests, so the stripes read as valleys cut into the slope ([`super::kernel`]);
    /// `3` (new worlds): the gullies of `2` faded out where the stripes of a cell's corners
    /// cancel, instead of flipping from crest to trough within a sample
    /// ([`super::kernel::GULLY_PHASOR_FLOOR2`]): no cliffs one sample wide.
    #[serde(
        default = "EarthParams::first_gullies",
        skip_serializing_if = "EarthParams::is_first_gullies"
    )]
    pub gullies: u32,
    /// Erosion filter: the first gully octave kept, in [0, `gully_octaves`]: octaves
    /// `0..gully_first` are left out, and the others keep the lattice spacing
    /// (`gully_scale_m / 2^g`), depth and lattice seeds they have without it. `0`: every octave
    /// (worlds stored before it existed have no `gully_first` and keep it, and their bytes).
    /// `1` (new worlds): the coarsest octave left out. Its stripes, straight across cells of
    /// `gully_scale_m` (8 km by default) and about 9 % of the relief deep, cut canyons a few
    /// hundred metres deep that run dead straight for kilometres (the range at (111.5 km,
    /// 119 km), with 0.17 % of its 8 m steps steeper than 63°); the rivers carve valleys at
    /// that scale.
    #[serde(default, skip_serializing_if = "EarthParams::is_zero")]
    pub gully_first: u32,
    /// Spacing of the world lattice on which the large-scale part of the height is evaluated and
    /// interpolated at finer LODs ([`super::lattice`]), in LOD-0 vertex spacings (`cell_m`): a
    /// power of two in [2, 256]. Absent in worlds stored before it existed, which evaluate every
    /// layer at every vertex and keep their bytes; new worlds: 16 (16 m at the default 1 m cell).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lattice_cells: Option<u32>,
    /// Spacing of a second, coarser world lattice, in LOD-0 vertex spacings: the macro fields
    /// and the leading layers of longest wavelength are evaluated at its nodes and interpolated
    /// at every LOD finer than it, at the samples of the LODs between the two lattices and at the
    /// nodes of `lattice_cells` below them ([`super::lattice`]). A power of two in [4, 4096], at
    /// least twice `lattice_cells`. Absent in worlds stored before it existed, which keep their
    /// bytes; new worlds: 256 (256 m at the default 1 m cell).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coarse_lattice_cells: Option<u32>,
    /// Whose snow lines a vertex reads, 1 or 2. `1`: the biomes' `snow_line_m` weighted by the
    /// vertex's biome weights, which the climate has made colder with altitude, so a mountain's
    /// upper slopes take the snow line of a colder biome (the tundra's 600 m on a range of the
    /// temperate latitudes) and snow reaches far down every range (worlds stored before `2`
    /// existed have no `snow_lines` and keep it, and their bytes). `2` (new worlds): the snow
    /// line of the climate at sea level, the altitude's cooling taken back ([`super::climate`]),
    /// so a biome's `snow_line_m` is the height where its own climate turns to snow.
    #[serde(
        default = "EarthParams::first_snow_lines",
        skip_serializing_if = "EarthParams::is_first_snow_lines"
    )]
    pub snow_lines: u32,
    /// Latitude of the origin as a distance from the pole, metres: the Voronoi map of
    /// Choroś & Topolski is read at `z + latitude_offset_m`, so the origin sits this far towards
    /// the equator.
    pub latitude_offset_m: f32,
    /// Height at which the climate is one biome colder, metres (the temperature lapse, in units
    /// of the pole-to-equator range: 10 000 m means a 2 km mountain is a fifth of the way to the
    /// pole).
    pub lapse_m: f32,
    /// Rivers and lakes ([`super::rivers`]); absent in worlds stored before rivers existed,
    /// which keep their river-free bytes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rivers: Option<RiverParams>,
}

/// The river network of an `earth-1` world.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RiverParams {
    /// Whether rivers and lakes are generated (false: the world stays river-free).
    pub enabled: bool,
    /// Spacing of the drainage nodes, metres: tributaries join about this far apart, in
    /// [256, 8192].
    pub spacing_m: f32,
    /// River density: channels hold water from a basin of `8 / density` nodes, in [0.1, 4].
    pub density: f32,
    /// Incision of the largest rivers below the surrounding land, metres, in [0, 300].
    pub incision_m: f32,
    /// The valleys' shape, 1 to 7 ([`super::rivers`], step 6). `1`: at least 250 m wide and
    /// more by discharge, so the land between rivers is pulled towards the planes of their water
    /// levels (straight facets); worlds stored before `2` existed have no `valleys` and keep it,
    /// and their bytes. `2`: a floodplain and walls as wide as the height they climb, along
    /// centre lines of eight straight pieces an edge instead of four; the land beyond keeps its
    /// shape. `3` (new worlds until `5`): the valleys of `2` along four bent pieces an edge, each a
    /// parabola through the curve's middle, so the walls follow the curve without facets. `4`
    /// (asked for by name): the valleys of `3` whose floodplain narrows and widens and whose
    /// walls steepen and ease along the river, so they read as eroded valleys instead of canals.
    /// `5` (new worlds until `6`): the valleys of `4` whose walls have spurs and hollows running
    /// down to the river ([`super::rivers::SPUR`]), so where two valleys' walls meet the crease
    /// wanders instead of running straight. `6` (new worlds until `7`): the valleys of `5` whose
    /// walls are gentler where the relief is lower ([`super::rivers::RELIEF_WALLS_MIN`]), so the
    /// rivers of a plain run in broad swales instead of a maze of trenches. `7` (new worlds until
    /// `8`): the valleys of `6`, where the relief is high only for the larger rivers and the streams out
    /// of and into lakes ([`super::rivers::RELIEF_SOURCE_Q`]): a mountain's small streams, one
    /// a kilometre, carved its whole surface into the bowls of their walls (a median 250 m cut
    /// in the range), and the relief and its gullies now stand between the larger valleys. `8`
    /// (new worlds): the valleys of `7` sized by their river ([`super::rivers::SIZED_Q`]): a
    /// small river's floodplain is narrower (a source's 8 m each side, where every dry valley of
    /// `7` had a flat floor 40 to 90 m wide, so the plains' brooks ran in canals) and its edge
    /// bends less ([`super::rivers::SMALL_BEND`]: the plains' small valleys wound as a maze of
    /// worm-like trenches), and each tile widens the floodplains to half its vertex spacing
    /// ([`super::rivers::LOD_FLOOR`]) so a coarse tile finds the narrow floors without pits.
    #[serde(
        default = "RiverParams::first_valleys",
        skip_serializing_if = "RiverParams::is_first_valleys"
    )]
    pub valleys: u32,
    /// The lakes, 1 to 8 ([`super::rivers`], step 5). `1`: a sample is lake water where one of the
    /// four nodes around it holds a lake above its height, so a lake's water can end along straight
    /// lines of the node lattice; worlds stored before `2` existed have no `lakes` and keep it, and
    /// their bytes. `2`: the ground is shaped to meet the lake's level along a curved shore
    /// ([`super::rivers`]' shores), where the water ends. `3` (asked for by name): the lakes of
    /// `2`, and a lake whose flood found an outlet spills there, so its river goes on to the sea or
    /// a lower lake through a valley cut in the rim down to the lake's level instead of ending in a
    /// basin closed by the finer relief; but the valleys of the rivers below the outlet are cut
    /// below the lake's level right beside its water. `4` (new worlds until `5`): the lakes of `3`
    /// held by a sill, where the carve cuts no floodplain or valley wall below the lake's level
    /// beside its water (the shores' step 5). `5` (new worlds until `6`): the lakes of `4` whose floods
    /// search 2048 instead of 256 nodes within 30 instead of 12 node spacings, so the basins that a
    /// mountain belt's ridges close, tens of kilometres across, fill to their outlets and spill,
    /// instead of holding a lake in their bottoms below a closed dry floor hundreds of metres deep
    /// (over 131 km of the range east of the origin at 64 m, the land in closed depressions deeper
    /// than 2 m falls from 12.7 % to 4.7 %); tiles too coarse to carve show the lakes over their
    /// uncarved heights. `6` (new worlds until `7`): the lakes of `5` in the hollows the network now sees
    /// (a node's height is at most the height of the LOD of one node spacing,
    /// [`super::rivers::HOLLOW_LODS`], where it stood up to 90 m above the bowls of a plain,
    /// which held neither river nor lake), and a flow ends at the first lake water it reaches
    /// and rests on that lake's level (a river that crossed a lake without meeting its pit, or
    /// ended in a pit submerged by a higher lake, was cut below the water the tiles show, a
    /// closed dry trench beside the lake); a spilling lake's river leaves from the saddle its
    /// outlet lies beyond, where the edge from its pit cut a trench kilometres long across the
    /// land beside the lake; and a river line is listed for a tile only where its curve
    /// reaches it. Over 33 km of the origin at 64 m the land in closed depressions deeper than
    /// 2 m falls from 5.3 % to 1.3 %. `7` (new worlds until `8`): the lakes of `6`, and a flood stopped by
    /// its limits keeps the lake it had filled before its level last rose, full to the rim that
    /// raised it (it kept the nodes it had reached beyond that rim, below the level beside dry
    /// neighbours as low: a flat closed floor tens of kilometres wide at 512 m); the coarse
    /// network's floods search 30 of its own spacings over at most
    /// [`super::rivers::COARSE_LAKE_MAX_NODES_7`] nodes and go on past their outlet over the
    /// nodes below their level that drain into the lake, and its spilling lakes leave from
    /// their saddles (its pits' edges, as long as the wider floods, cut arcs of trench 40 km and
    /// more across the land); and the shoreline's noise fades with the tile's vertex spacing,
    /// so no octave shorter than two spacings scatters lake vertices on the land beside a coarse
    /// tile's lakes. At 512 m the land in closed depressions deeper than 2 m falls from 10.7 to
    /// 3.3 % in the far area, 6.2 to 3.9 % in the range's. `8` (new worlds): the lakes of `7`
    /// whose shores sink the ground inside a lake towards its nodes' heights
    /// ([`super::rivers::RiverPlan::sink`]), so the ridges between the nodes, which the network
    /// does not see, no longer part a lake into pools that its outlet does not drain, and whose
    /// coarse network's floods visit up to [`super::rivers::COARSE_LAKE_MAX_NODES_8`] nodes,
    /// so the largest basins, about 150 km across, fill to their outlets. Over the 64
    /// world-wide areas of `bench realism` the land in closed depressions deeper than 2 m
    /// falls from 7.5 to 4.8 % at 512 m and from 2.2 to 1.5 % at 64 m.
    #[serde(
        default = "RiverParams::first_lakes",
        skip_serializing_if = "RiverParams::is_first_lakes"
    )]
    pub lakes: u32,
    /// The coarse network, 0 or 1 ([`super::rivers`], LODs). `0`: tiles coarser than
    /// [`super::rivers::MAX_CARVE_LOD`] are not carved; worlds stored before `1` existed have
    /// no `coarse` and keep it, and their bytes. `1` (new worlds): a second network of nodes
    /// [`super::rivers::COARSE_FACTOR`] times as far apart carves LODs
    /// `MAX_CARVE_LOD + 1 ..=` [`super::rivers::MAX_COARSE_LOD`], so the surface at 512 m and
    /// 1 km spacing has drainage: valleys of its larger rivers instead of the closed basins of
    /// the uncarved relief.
    #[serde(default, skip_serializing_if = "RiverParams::is_no_coarse")]
    pub coarse: u32,
    /// The river lines' centre lines, 1 or 2 ([`super::rivers`]' lines). `1`: a bent piece's
    /// ends and middle, a chord of which strays up to about 30 m from the curve the carve
    /// follows, so a client that draws the river along the line leaves the carved channel's
    /// water beside it; worlds stored before `2` existed have no `lines` and keep it, and their
    /// bytes. `2` (new worlds): each piece's curve in as many points as keep the chords within
    /// [`super::rivers::LINE_TOLERANCE_M`] of it, and the long edges of breached pits and
    /// spilling lakes (worlds with `coarse: 1`, which carve them) among the lines.
    #[serde(
        default = "RiverParams::first_lines",
        skip_serializing_if = "RiverParams::is_first_lines"
    )]
    pub lines: u32,
}

impl Default for RiverParams {
    fn default() -> Self {
        Self {
            enabled: true,
            spacing_m: 1024.0,
            density: 1.0,
            incision_m: 60.0,
            valleys: 8,
            lakes: 8,
            coarse: 1,
            lines: 2,
        }
    }
}

impl RiverParams {
    fn first_valleys() -> u32 {
        1
    }

    fn is_first_valleys(v: &u32) -> bool {
        *v == 1
    }

    fn first_lakes() -> u32 {
        1
    }

    fn is_first_lakes(v: &u32) -> bool {
        *v == 1
    }

    fn is_no_coarse(v: &u32) -> bool {
        *v == 0
    }

    fn first_lines() -> u32 {
        1
    }

    fn is_first_lines(v: &u32) -> bool {
        *v == 1
    }

    /// Checks every limit; `cell_m` is the world's LOD-0 spacing.
    pub fn validate(&self, cell_m: f32) -> Result<(), ParamError> {
        let m = "must be in";
        check(
            within(self.spacing_m, 256.0_f32.max(4.0 * cell_m), 8192.0),
            "rivers.spacing_m",
            &format!("{m} [max(256, 4 vertex spacings), 8192]"),
        )?;
        check(
            within(self.density, 0.1, 4.0),
            "rivers.density",
            &format!("{m} [0.1, 4]"),
        )?;
        check(
            within(self.incision_m, 0.0, 300.0),
            "rivers.incision_m",
            &format!("{m} [0, 300]"),
        )?;
        check(
            (1..=8).contains(&self.valleys),
            "rivers.valleys",
            "must be 1, 2, 3, 4, 5, 6, 7 or 8",
        )?;
        check(
            (1..=8).contains(&self.lakes),
            "rivers.lakes",
            "must be 1, 2, 3, 4, 5, 6, 7 or 8",
        )?;
        check(self.coarse <= 1, "rivers.coarse", "must be 0 or 1")?;
        check(
            (1..=2).contains(&self.lines),
            "rivers.lines",
            "must be 1 or 2",
        )
    }
}

impl Default for EarthParams {
    fn default() -> Self {
        Self {
            continent_scale_m: 1_400_000.0,
            land_bias: 0.05,
            origin_land: 0.45,
            origin_land_radius_m: 350_000.0,
            ocean_depth_m: 4200.0,
            interior_height_m: 650.0,
            belt_scale_m: 400_000.0,
            belt_width: 0.25,
            mountain_relief_m: 3300.0,
            hill_relief_m: 700.0,
            plain_relief_m: 150.0,
            seafloor_relief_m: 250.0,
            ridge_scale_m: 24_000.0,
            octaves: 16,
            gain: 0.5,
            detail_scale_m: 700.0,
            detail_gain: 0.4,
            erosion: 1.0,
            gully_scale_m: 8000.0,
            gully_octaves: 6,
            gullies: 3,
            gully_first: 1,
            lattice_cells: Some(16),
            coarse_lattice_cells: Some(256),
            snow_lines: 2,
            latitude_offset_m: 1_024_000.0,
            lapse_m: 10_000.0,
            rivers: Some(RiverParams::default()),
        }
    }
}

/// Per-biome character of an `earth-1` world's relief.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BiomeRelief {
    /// Multiplies the erosion filter's strength in this biome, in [0, 2].
    pub erosion: f32,
    /// Multiplies the amplitude of the octaves finer than the gullies, in [0, 2].
    pub roughness: f32,
}

impl Default for BiomeRelief {
    fn default() -> Self {
        Self {
            erosion: 1.0,
            roughness: 1.0,
        }
    }
}

fn check(ok: bool, field: &str, message: &str) -> Result<(), ParamError> {
    if ok {
        Ok(())
    } else {
        Err(ParamError {
            field: format!("earth.{field}"),
            message: message.into(),
        })
    }
}

fn within(v: f32, lo: f32, hi: f32) -> bool {
    v.is_finite() && (lo..=hi).contains(&v)
}

impl EarthParams {
    fn first_gullies() -> u32 {
        1
    }

    fn first_snow_lines() -> u32 {
        1
    }

    fn is_first_snow_lines(v: &u32) -> bool {
        *v == 1
    }

    fn is_first_gullies(v: &u32) -> bool {
        *v == 1
    }

    fn is_zero(v: &u32) -> bool {
        *v == 0
    }

    /// Checks every limit; `cell_m` is the world's LOD-0 spacing.
    pub fn validate(&self, cell_m: f32) -> Result<(), ParamError> {
        let m = "must be in";
        check(
            (1..=3).contains(&self.gullies),
            "gullies",
            "must be 1, 2 or 3",
        )?;
        check(
            (1..=2).contains(&self.snow_lines),
            "snow_lines",
            "must be 1 or 2",
        )?;
        check(
            within(self.continent_scale_m, 10_000.0, 1.0e8),
            "continent_scale_m",
            &format!("{m} [1e4, 1e8]"),
        )?;
        check(
            within(self.land_bias, -1.0, 1.0),
            "land_bias",
            &format!("{m} [-1, 1]"),
        )?;
        check(
            within(self.origin_land, 0.0, 2.0),
            "origin_land",
            &format!("{m} [0, 2]"),
        )?;
        check(
            within(self.origin_land_radius_m, 1.0, 1.0e8),
            "origin_land_radius_m",
            &format!("{m} [1, 1e8]"),
        )?;
        for (name, v) in [
            ("ocean_depth_m", self.ocean_depth_m),
            ("interior_height_m", self.interior_height_m),
            ("mountain_relief_m", self.mountain_relief_m),
            ("hill_relief_m", self.hill_relief_m),
            ("plain_relief_m", self.plain_relief_m),
            ("seafloor_relief_m", self.seafloor_relief_m),
        ] {
            check(within(v, 0.0, 10_000.0), name, &format!("{m} [0, 10000]"))?;
        }
        check(
            within(self.belt_scale_m, 10_000.0, 1.0e8),
            "belt_scale_m",
            &format!("{m} [1e4, 1e8]"),
        )?;
        check(
            self.belt_width.is_finite() && self.belt_width > 0.0 && self.belt_width <= 1.0,
            "belt_width",
            &format!("{m} (0, 1]"),
        )?;
        check(
            within(self.ridge_scale_m, 64.0 * cell_m, 1.0e6),
            "ridge_scale_m",
            &format!("{m} [64 vertex spacings, 1e6]"),
        )?;
        check(
            (1..=super::MAX_RELIEF_OCTAVES as u32).contains(&self.octaves),
            "octaves",
            &format!("{m} [1, {}]", super::MAX_RELIEF_OCTAVES),
        )?;
        for (name, v) in [("gain", self.gain), ("detail_gain", self.detail_gain)] {
            check(
                v.is_finite() && v > 0.0 && v < 1.0,
                name,
                &format!("{m} (0, 1)"),
            )?;
        }
        check(
            within(self.detail_scale_m, 0.0, 1.0e6),
            "detail_scale_m",
            &format!("{m} [0, 1e6]"),
        )?;
        check(
            within(self.erosion, 0.0, 2.0),
            "erosion",
            &format!("{m} [0, 2]"),
        )?;
        check(
            within(self.gully_scale_m, 16.0 * cell_m, 1.0e6),
            "gully_scale_m",
            &format!("{m} [16 vertex spacings, 1e6]"),
        )?;
        check(
            self.gully_octaves as usize <= super::MAX_GULLY_OCTAVES,
            "gully_octaves",
            &format!("{m} [0, {}]", super::MAX_GULLY_OCTAVES),
        )?;
        check(
            self.gully_first <= self.gully_octaves,
            "gully_first",
            &format!("{m} [0, gully_octaves ({})]", self.gully_octaves),
        )?;
        check(
            within(self.latitude_offset_m, -1.0e8, 1.0e8),
            "latitude_offset_m",
            &format!("{m} [-1e8, 1e8]"),
        )?;
        check(
            within(self.lapse_m, 100.0, 1.0e6),
            "lapse_m",
            &format!("{m} [100, 1e6]"),
        )?;
        if let Some(c) = self.lattice_cells {
            check(
                (2..=256).contains(&c) && c.is_power_of_two(),
                "lattice_cells",
                "must be a power of two in [2, 256]",
            )?;
        }
        if let Some(c) = self.coarse_lattice_cells {
            check(
                (4..=4096).contains(&c)
                    && c.is_power_of_two()
                    && self.lattice_cells.is_none_or(|f| c >= 2 * f),
                "coarse_lattice_cells",
                "must be a power of two in [4, 4096], at least twice lattice_cells",
            )?;
        }
        if let Some(r) = &self.rivers {
            r.validate(cell_m)?;
        }
        Ok(())
    }
}

impl BiomeRelief {
    /// Checks the limits; `field` is the biome's path (`biomes[2]`).
    pub fn validate(&self, field: &str) -> Result<(), ParamError> {
        for (name, v) in [("erosion", self.erosion), ("roughness", self.roughness)] {
            if !within(v, 0.0, 2.0) {
                return Err(ParamError {
                    field: format!("{field}.relief.{name}"),
                    message: "must be in [0, 2]".into(),
                });
            }
        }
        Ok(())
    }
}
