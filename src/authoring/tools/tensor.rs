//! §4.3 tensor maps: `directional_tensor`, `skeleton_tensor` and `stroke_tensor` multiply the
//! target gradient by `I + μ·M(θ)`; rasterised by [`crate::authoring::tensor`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use serde::{Deserialize, Serialize};

/// Directional tensor (§4.3): inside the disc of `radius_m` around `center` the target
/// gradient is multiplied by `D = I + μ·M(θ)`, which scales slopes along `angle_deg` by
/// `1 + strength` and across it by `1 − strength`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DirectionalTensor {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
    /// Direction `θ`, degrees from +x toward +z.
    pub angle_deg: f64,
    /// `μ`, `0..=1`.
    pub strength: f64,
}

impl Tool for DirectionalTensor {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/angle_deg", self.angle_deg, -360.0, 360.0)?;
        c.number("/strength", self.strength, 0.0, 1.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .directional_tensor(self.center, self.radius_m, self.angle_deg, self.strength);
        Ok(())
    }
}

/// Skeleton tensor (§4.3): `I + μ·α(d/r)·M(θ)` around a point or polyline skeleton, `α`
/// the C² falloff of the distance to it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SkeletonTensor {
    /// The skeleton: one point or a polyline, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Radius of influence, metres.
    pub radius_m: f64,
    /// Direction `θ`, degrees from +x toward +z.
    pub angle_deg: f64,
    /// `μ`, `0..=1`.
    pub strength: f64,
}

impl Tool for SkeletonTensor {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/angle_deg", self.angle_deg, -360.0, 360.0)?;
        c.number("/strength", self.strength, 0.0, 1.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .skeleton_tensor(&self.points, self.radius_m, self.angle_deg, self.strength);
        Ok(())
    }
}

/// Stroke-aligned tensor brush (§4.3, Fig. 7): a skeleton tensor whose direction follows
/// the stroke at the closest point, orienting slopes along the stroke.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrokeTensor {
    /// The stroke, `[x, z]` metres (at least 2 points).
    pub points: Vec<[f64; 2]>,
    /// Radius of influence, metres.
    pub radius_m: f64,
    /// `μ`, `0..=1`.
    pub strength: f64,
}

impl Tool for StrokeTensor {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        if self.points.len() < 2 {
            return Err(c.refuse("/points", "a stroke needs at least 2 points"));
        }
        c.radius("/radius_m", self.radius_m)?;
        c.number("/strength", self.strength, 0.0, 1.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .stroke_tensor(&self.points, self.radius_m, self.strength);
        Ok(())
    }
}
