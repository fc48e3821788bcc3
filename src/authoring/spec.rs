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

use super::spec_tools::{
    DROPLET_STEP_CELLS, MAX_ACCEPTED_SAMPLES, MAX_REGION_CELL_STEPS, SOLVE_CELL_STEPS,
};
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

/// The cell steps an operation adds to a region of `cells` grid samples.
fn op_cell_steps(tool: &dyn super::tools::Tool, cells: u64) -> u64 {
    let solve = if tool.reads_solution() {
        cells.saturating_mul(SOLVE_CELL_STEPS)
    } else {
        0
    };
    solve
        .saturating_add(tool.grid_sweeps().saturating_mul(cells))
        .saturating_add(tool.droplet_steps().saturating_mul(DROPLET_STEP_CELLS))
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
    /// world accepted under older limits keeps loading): its work, [`Self::cell_steps`] (its
    /// solves, thermal sweeps and droplet steps), is at most [`MAX_REGION_CELL_STEPS`] (the
    /// operation that adds work and crosses it is named), and its `samples` at most
    /// [`MAX_ACCEPTED_SAMPLES`].
    pub fn check_cost(&self) -> Result<(), SpecError> {
        let cells = (self.samples as u64).saturating_mul(self.samples as u64);
        let mut work = cells.saturating_mul(SOLVE_CELL_STEPS);
        for (i, op) in self.ops.iter().enumerate() {
            let tool = op.tool();
            let added = op_cell_steps(tool, cells);
            work = work.saturating_add(added);
            // An operation that adds no work is not named: the region's own solve crossed the
            // budget, which only a grid beyond `MAX_ACCEPTED_SAMPLES` does (refused below).
            if work <= MAX_REGION_CELL_STEPS || added == 0 {
                continue;
            }
            let field = if tool.droplet_steps() > 0 {
                "/droplets"
            } else if tool.grid_sweeps() > 0 {
                "/iterations"
            } else {
                ""
            };
            return Err(err(
                format!("/ops/{i}{field}"),
                format!(
                    "a region's work is at most {MAX_REGION_CELL_STEPS} cell steps: \
                     {SOLVE_CELL_STEPS} × samples² for its solve and for each freeze, \
                     regularize, erosion and hydraulic_erosion operation, iterations × samples² \
                     for its erosion operations, {DROPLET_STEP_CELLS} × droplets × steps for its \
                     hydraulic_erosion operations ({} samples: {} erosion iterations or {} \
                     droplet steps besides the solves); with this one it reaches {work}",
                    self.samples,
                    MAX_REGION_CELL_STEPS / cells.max(1),
                    MAX_REGION_CELL_STEPS / DROPLET_STEP_CELLS,
                ),
            ));
        }
        if self.samples > MAX_ACCEPTED_SAMPLES {
            return Err(err(
                "/samples",
                format!(
                    "at most {MAX_ACCEPTED_SAMPLES} when a scene is accepted (a stored region of \
                     {} samples keeps loading)",
                    self.samples
                ),
            ));
        }
        Ok(())
    }

    /// The region's work in cell steps, as [`Self::check_cost`] counts it.
    pub fn cell_steps(&self) -> u64 {
        let cells = (self.samples as u64).saturating_mul(self.samples as u64);
        self.ops
            .iter()
            .fold(cells.saturating_mul(SOLVE_CELL_STEPS), |w, op| {
                w.saturating_add(op_cell_steps(op.tool(), cells))
            })
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
