//! §4.1 gradient constraints: `slope_point` (a slope and direction at a point) and
//! `slope_curve` (a slope profile on each side of a curve), both curl-free fields added to the
//! target (soft); rasterised by [`crate::authoring::landform`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use serde::{Deserialize, Serialize};

/// Point gradient constraint (§4.1): the slope at `center` becomes `slope_deg` rising toward
/// `direction_deg` (degrees from +x toward +z), faded out over `radius_m` by a curl-free
/// field (soft, added; `Canvas::slope_point`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SlopePoint {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Reach, metres.
    pub radius_m: f64,
    /// Slope, degrees (`−89..=89`; negative falls toward the direction).
    pub slope_deg: f64,
    /// Direction of the rise, degrees from +x toward +z.
    pub direction_deg: f64,
}

impl Tool for SlopePoint {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/slope_deg", self.slope_deg, -89.0, 89.0)?;
        c.number("/direction_deg", self.direction_deg, -360.0, 360.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.slope_point(
            self.center,
            self.radius_m,
            self.slope_deg,
            self.direction_deg,
        );
        Ok(())
    }
}

/// Curve gradient constraint with a slope profile on each side (§4.1): out to `width_m`
/// from the polyline the heights fall away from it at `slope_left_deg` on its left and
/// `slope_right_deg` on its right (negative values rise), blended back over the last third
/// of the width by a curl-free field (soft, added; `Canvas::slope_curve`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SlopeCurve {
    /// The curve, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Slope falling away on the left of the stroke, degrees (`−89..=89`).
    pub slope_left_deg: f64,
    /// Slope falling away on the right of the stroke, degrees (`−89..=89`).
    pub slope_right_deg: f64,
    /// Reach on each side, metres.
    pub width_m: f64,
}

impl Tool for SlopeCurve {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.number("/slope_left_deg", self.slope_left_deg, -89.0, 89.0)?;
        c.number("/slope_right_deg", self.slope_right_deg, -89.0, 89.0)?;
        c.number("/width_m", self.width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.slope_curve(
            &self.points,
            self.slope_left_deg,
            self.slope_right_deg,
            self.width_m,
        );
        Ok(())
    }
}
