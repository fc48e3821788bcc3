//! The tools of an authored region: each tool is a parameter type implementing [`Tool`]
//! (validation naming a refused field by JSON pointer, its cost, its rasterisation on the
//! region's canvas), grouped one module per tool family, and registered once in [`Op`], the
//! `op`-tagged operation of the scene's `regions` element.
//!
//! # Families
//!
//! - [`elevation`]: hard elevation constraints (`elevation`, `freeze`) and their [`Shape`].
//! - [`brush`]: soft gradient brushes (`amplify`, `noise`).
//! - [`slope`]: §4.1 gradient constraints (`slope_point`, `slope_curve`).
//! - [`landform`]: Fig. 4 landforms and the Fig. 8 composites (`crest`, `cliff`, `river`,
//!   `free_crest`, `ravine`, `fault`, `mountain_range`, `mesa`).
//! - [`paste`]: §4.1 copy-paste (`copy_paste`).
//! - [`tensor`]: §4.3 tensor maps (`directional_tensor`, `skeleton_tensor`, `stroke_tensor`).
//! - [`erosion`]: §4.4 erosion brushes (`erosion`, `hydraulic_erosion`).
//! - [`fitting`]: §5.1 fitting and the §3 regularisation (`contours`, `network`, `regularize`).
//! - [`sketch`]: issue 17's coarse sketch (`sketch`).
//! - [`basis`]: Schneider §3 basis functions (`basis`).
//!
//! The algorithms behind them (the [`crate::authoring::raster::Canvas`] methods) live in the
//! modules of [`crate::authoring`] named in each family's documentation.
//!
//! # Adding a tool
//!
//! A new tool is one new file and one registration line:
//!
//! 1. `src/authoring/tools/<family>.rs`: a parameter struct named as the tool (`MyTool`)
//!    deriving `Clone, Debug, PartialEq, Serialize, Deserialize` with
//!    `#[serde(deny_unknown_fields)]`, whose fields are the operation's JSON fields, and
//!    `impl Tool` for it: [`Tool::check`] with the [`Check`] helpers, [`Tool::apply`] on the
//!    [`Raster`] (its canvas, the world plan, the heights solved so far), and
//!    [`Tool::droplet_steps`], [`Tool::grid_sweeps`], [`Tool::reads_solution`] (a tool that
//!    calls [`Raster::solved`]: its solve counts in the region's work budget) or
//!    [`Tool::keeps_solution`] where the defaults do not hold.
//! 2. One line at the end of the `tools!` list below: `mod my_family: MyTool,` declares the new
//!    file's module and registers the tool (a further tool of an existing family's file is
//!    `my_family: MyOtherTool,`, without `mod`). The tool's name in snake case is its `op` tag
//!    (`MyTool` is `"op": "my_tool"`). New tools go last, so the list of expected tags in serde's
//!    "unknown variant" message only grows.
//!
//! `api/scene.schema.json` describes the document and gets the new operation's fields.

pub use super::region::Raster;
pub use elevation::Shape;

use super::region::RegionError;
use super::spec::{err, finite_in, RegionSpec, SpecError, MAX_ELEVATION_M, MAX_POINTS};
use serde::{Deserialize, Serialize};

/// What every tool of a region does: check its parameters, state its cost, rasterise itself.
pub trait Tool {
    /// Checks the parameters of the operation at `c.index`, naming the first refused field by
    /// its JSON pointer below the element ([`Check::at`]).
    ///
    /// # Errors
    /// [`SpecError`] naming the field and the reason.
    fn check(&self, c: &Check) -> Result<(), SpecError>;

    /// Droplet steps (`droplets × steps`) the operation spends: each counts for
    /// [`super::spec_tools::DROPLET_STEP_CELLS`] cell steps of the region's budget,
    /// [`super::spec_tools::MAX_REGION_CELL_STEPS`], checked when a scene is accepted
    /// ([`RegionSpec::check_cost`], which names the operation's `droplets` field).
    fn droplet_steps(&self) -> u64 {
        0
    }

    /// Sweeps of the whole region grid the operation makes (thermal erosion: its iterations):
    /// `sweeps × samples²` cell steps of the region's budget,
    /// [`super::spec_tools::MAX_REGION_CELL_STEPS`], checked when a scene is accepted
    /// ([`RegionSpec::check_cost`], which names the operation's `iterations` field).
    fn grid_sweeps(&self) -> u64 {
        0
    }

    /// Whether the operation reads the heights solved before it (so that the region is
    /// reconstructed first, a solve counted in the region's budget,
    /// [`super::spec_tools::MAX_REGION_CELL_STEPS`]).
    fn reads_solution(&self) -> bool {
        false
    }

    /// Whether the heights solved before the operation still solve the problem after it (a
    /// freeze only fixes samples at those heights), so a later operation that reads the solved
    /// heights need not solve again.
    fn keeps_solution(&self) -> bool {
        false
    }

    /// Rasterises the operation: adds to or replaces the canvas's target gradient (soft), or
    /// fixes samples (hard).
    ///
    /// # Errors
    /// [`RegionError`] if a solve before it fails or an input cannot be used.
    fn apply(&self, r: &mut Raster) -> Result<(), RegionError>;
}

/// Registers the tools: declares each family's module (an entry with `mod`), and makes the
/// [`Op`] enum (one newtype variant per tool, named as its parameter type and tagged by `op`)
/// and its dispatch to [`Tool`], in the order of the list.
macro_rules! tools {
    (@munch [$($done:tt)*] mod $family:ident: $name:ident, $($rest:tt)*) => {
        pub mod $family;
        tools!(@munch [$($done)* $family::$name] $($rest)*);
    };
    (@munch [$($done:tt)*] $family:ident: $name:ident, $($rest:tt)*) => {
        tools!(@munch [$($done)* $family::$name] $($rest)*);
    };
    (@munch [$($family:ident::$name:ident)*]) => {
        /// One tool operation: `op` names the tool (the variant in snake case), the other fields
        /// are its parameters.
        #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
        #[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
        pub enum Op {
            $(
                #[doc = concat!("The tool of `", stringify!($family), "::", stringify!($name), "`.")]
                $name($family::$name),
            )*
        }

        impl Op {
            /// The operation's tool.
            pub fn tool(&self) -> &dyn Tool {
                match self {
                    $(Op::$name(params) => params,)*
                }
            }
        }
    };
    ($($entries:tt)*) => {
        tools!(@munch [] $($entries)*);
    };
}

tools! {
    mod elevation: Elevation,
    elevation: Freeze,
    mod brush: Amplify,
    mod landform: Crest,
    brush: Noise,
    mod slope: SlopePoint,
    slope: SlopeCurve,
    landform: Cliff,
    landform: River,
    landform: FreeCrest,
    landform: Ravine,
    landform: Fault,
    landform: MountainRange,
    landform: Mesa,
    mod paste: CopyPaste,
    mod tensor: DirectionalTensor,
    tensor: SkeletonTensor,
    tensor: StrokeTensor,
    mod erosion: Erosion,
    erosion: HydraulicErosion,
    mod fitting: Contours,
    fitting: Network,
    fitting: Regularize,
    mod sketch: Sketch,
    mod basis: Basis,
}

/// What a tool's [`Tool::check`] sees: the operation's index and the region, with the checks
/// tools share. Each takes a field as a pointer below the operation (`"/radius_m"`).
#[derive(Debug)]
pub struct Check<'a> {
    /// Index of the operation in the region's `ops`.
    pub index: usize,
    /// The region (its bbox and samples; the operations are not validated yet).
    pub spec: &'a RegionSpec,
}

impl Check<'_> {
    /// The JSON pointer of `field` of this operation (`/ops/2/radius_m`; `""` the operation).
    pub fn at(&self, field: &str) -> String {
        format!("/ops/{}{field}", self.index)
    }

    /// A refusal of `field` for `message`.
    pub fn refuse(&self, field: &str, message: impl Into<String>) -> SpecError {
        err(self.at(field), message)
    }

    /// `field` is a finite number in `lo..=hi`.
    pub fn number(&self, field: &str, v: f64, lo: f64, hi: f64) -> Result<(), SpecError> {
        finite_in(self.at(field), v, lo, hi)
    }

    /// `field` is a position `[x, z]` within the world's coordinates.
    pub fn position(&self, field: &str, v: [f64; 2]) -> Result<(), SpecError> {
        let big = crate::element::MAX_COORD_M;
        self.number(&format!("{field}/0"), v[0], -big, big)?;
        self.number(&format!("{field}/1"), v[1], -big, big)
    }

    /// `field` is a radius or width in `0..=1e6` metres.
    pub fn radius(&self, field: &str, r: f64) -> Result<(), SpecError> {
        self.number(field, r, 0.0, 1.0e6)
    }

    /// `field` is an elevation within [`MAX_ELEVATION_M`].
    pub fn elevation(&self, field: &str, v: f64) -> Result<(), SpecError> {
        self.number(field, v, -MAX_ELEVATION_M, MAX_ELEVATION_M)
    }

    /// `field` is a polyline of 1 to [`MAX_POINTS`] positions.
    pub fn polyline(&self, field: &str, pts: &[[f64; 2]]) -> Result<(), SpecError> {
        if pts.is_empty() || pts.len() > MAX_POINTS {
            return Err(self.refuse(field, format!("needs 1 to {MAX_POINTS} points")));
        }
        for (i, q) in pts.iter().enumerate() {
            self.position(&format!("{field}/{i}"), *q)?;
        }
        Ok(())
    }

    /// The region's sample spacing, metres.
    pub fn spacing_m(&self) -> f64 {
        let s = self.spec;
        (s.max[0] - s.min[0]).max(s.max[1] - s.min[1]) / (s.samples - 1) as f64
    }
}
