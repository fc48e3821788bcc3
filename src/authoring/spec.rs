//! The `regions` scene element: a `bbox`, a grid resolution and a list of tool operations
//! ([`Op`], each checked by its [`super::tools`] tool), parsed, validated and costed.
//!
//! ```json
//! {"id": "valley", "bbox": {"min": [0, 0], "max": [512, 512]}, "samples": 257,
//!  "ops": [{"op": "elevation", "shape": {"point": [256, 256]}, "elevation_m": 80, "radius_m": 12},
//!          {"op": "amplify", "center": [100, 300], "radius_m": 60, "factor": 2.0}]}
//! ```
//!
//! Units: positions in world metres (`[x, z]`), radii and elevations in metres, slopes in
//! degrees. Every limit is a constant here ([`SAMPLE_CHOICES`], [`MAX_OPS`], [`MAX_POINTS`]).

pub use super::tools::{Op, Shape};

use super::spec_tools::{MAX_REGION_DROPLET_STEPS, MAX_REGION_EROSION_CELL_STEPS};
use super::tools::Check;
use crate::element::Element;
use serde::{Deserialize, Serialize};

/// Allowed grid resolutions, samples per side (`2^k + 1`).
pub const SAMPLE_CHOICES: [usize; 7] = [33, 65, 129, 257, 513, 1025, 2049];
/// Default grid resolution.
pub const DEFAULT_SAMPLES: usize = 257;
/// Most operations per region.
pub const MAX_OPS: usize = 256;
/// Most points of one polyline.
pub const MAX_POINTS: usize = 1024;
/// Largest magnitude of an elevation, metres.
pub const MAX_ELEVATION_M: f64 = 20_000.0;
/// Largest width or depth of a copy-paste source, metres.
pub const MAX_PASTE_M: f64 = 8192.0;

/// A region element, parsed and validated.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegionSpec {
    /// Element id.
    #[serde(skip)]
    pub id: String,
    /// West-north corner `[x, z]`, metres.
    #[serde(skip)]
    pub min: [f64; 2],
    /// East-south corner `[x, z]`, metres.
    #[serde(skip)]
    pub max: [f64; 2],
    /// Grid samples per side, one of [`SAMPLE_CHOICES`].
    #[serde(default = "default_samples")]
    pub samples: usize,
    /// Tool operations, applied in order.
    #[serde(default)]
    pub ops: Vec<Op>,
}

fn default_samples() -> usize {
    DEFAULT_SAMPLES
}

/// A refused region: the JSON pointer below the element (`/ops/2/radius_m`) and the reason.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {message}")]
pub struct SpecError {
    /// Pointer relative to the element.
    pub pointer: String,
    /// Why.
    pub message: String,
}

pub(super) fn err(pointer: impl Into<String>, message: impl Into<String>) -> SpecError {
    SpecError {
        pointer: pointer.into(),
        message: message.into(),
    }
}

pub(super) fn finite_in(pointer: String, v: f64, lo: f64, hi: f64) -> Result<(), SpecError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(err(pointer, format!("must be a number in [{lo}, {hi}]")))
    }
}

impl RegionSpec {
    /// Parses a `regions` element.
    ///
    /// # Errors
    /// [`SpecError`] naming the offending field.
    pub fn from_element(e: &Element) -> Result<Self, SpecError> {
        let value = serde_json::Value::Object(e.rest.clone());
        let mut spec: RegionSpec = serde_path_to_error::deserialize(&value).map_err(|x| {
            err(
                crate::element::path_pointer(x.path()),
                x.inner().to_string(),
            )
        })?;
        spec.id = e.id.clone();
        spec.min = e.bbox.min;
        spec.max = e.bbox.max;
        spec.validate()?;
        Ok(spec)
    }

    /// The cost limits a region meets when it is accepted (not when a stored scene is read, so a
    /// world accepted under older limits keeps loading): `droplets × steps` summed over its
    /// hydraulic-erosion brushes is at most [`MAX_REGION_DROPLET_STEPS`], and
    /// `iterations × samples²` summed over its thermal-erosion brushes at most
    /// [`MAX_REGION_EROSION_CELL_STEPS`].
    pub fn check_cost(&self) -> Result<(), SpecError> {
        let cells = (self.samples as u64).saturating_mul(self.samples as u64);
        let (mut droplet_steps, mut cell_steps) = (0u64, 0u64);
        for (i, op) in self.ops.iter().enumerate() {
            let tool = op.tool();
            let steps = tool.droplet_steps();
            if steps > 0 {
                droplet_steps = droplet_steps.saturating_add(steps);
                if droplet_steps > MAX_REGION_DROPLET_STEPS {
                    return Err(err(
                        format!("/ops/{i}/droplets"),
                        format!(
                            "droplets × steps over a region's hydraulic_erosion operations \
                             total at most {MAX_REGION_DROPLET_STEPS}; with this one they reach \
                             {droplet_steps}"
                        ),
                    ));
                }
            }
            let sweeps = tool.grid_sweeps();
            if sweeps > 0 {
                cell_steps = cell_steps.saturating_add(sweeps.saturating_mul(cells));
                if cell_steps > MAX_REGION_EROSION_CELL_STEPS {
                    return Err(err(
                        format!("/ops/{i}/iterations"),
                        format!(
                            "iterations × samples² over a region's erosion operations total at \
                             most {MAX_REGION_EROSION_CELL_STEPS} ({} iterations at {} samples); \
                             with this one they reach {cell_steps}",
                            MAX_REGION_EROSION_CELL_STEPS / cells.max(1),
                            self.samples
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    fn validate(&self) -> Result<(), SpecError> {
        if !SAMPLE_CHOICES.contains(&self.samples) {
            return Err(err(
                "/samples",
                format!("must be one of {SAMPLE_CHOICES:?} (2^k + 1)"),
            ));
        }
        if self.max[0] - self.min[0] <= 0.0 || self.max[1] - self.min[1] <= 0.0 {
            return Err(err("/bbox", "a region needs a positive width and depth"));
        }
        if self.ops.len() > MAX_OPS {
            return Err(err("/ops", format!("at most {MAX_OPS} operations")));
        }
        for (index, op) in self.ops.iter().enumerate() {
            op.tool().check(&Check { index, spec: self })?;
        }
        Ok(())
    }
}
