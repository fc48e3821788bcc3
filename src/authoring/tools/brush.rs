//! Soft gradient brushes: `amplify` (scales the gradient) and `noise` (adds a lattice noise's
//! gradient, optionally stretched by a §4.3 tensor); rasterised by
//! [`crate::authoring::raster`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use crate::authoring::tensor::orientation;
use serde::{Deserialize, Serialize};

/// Gradient amplify (`factor > 1`) or suppress (`factor < 1`) brush with a C² falloff: the
/// target gradient becomes `(1 + (factor − 1)·f(r)) · ∇h` (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Amplify {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
    /// Gradient scale at the centre, `0..=8`.
    pub factor: f64,
}

impl Tool for Amplify {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/factor", self.factor, 0.0, 8.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.amplify(self.center, self.radius_m, self.factor);
        Ok(())
    }
}

/// Noise brush: `g += ∇n` for a lattice noise `n` of `amplitude_m` and `wavelength_m`,
/// faded out with a C² falloff (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Noise {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
    /// Noise amplitude, metres.
    pub amplitude_m: f64,
    /// Noise wavelength, metres.
    pub wavelength_m: f64,
    /// Noise seed (hashed with the world seed).
    #[serde(default)]
    pub seed: u32,
    /// Tensor modulation `μ` (§4.3): the noise's slopes along `angle_deg` are scaled by
    /// `1 + μ`, across it by `1 − μ` (`0..=1`; 0: isotropic noise).
    #[serde(default)]
    pub anisotropy: f64,
    /// Direction `θ` of the modulation, degrees from +x toward +z.
    #[serde(default)]
    pub angle_deg: f64,
}

impl Tool for Noise {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/amplitude_m", self.amplitude_m, 0.0, 1.0e4)?;
        c.number("/wavelength_m", self.wavelength_m, 1.0e-3, 1.0e6)?;
        c.number("/anisotropy", self.anisotropy, 0.0, 1.0)?;
        c.number("/angle_deg", self.angle_deg, -360.0, 360.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let m = orientation(self.angle_deg.to_radians());
        let k = self.anisotropy;
        r.canvas.noise(
            r.plan.seed,
            self.center,
            self.radius_m,
            self.amplitude_m,
            self.wavelength_m,
            self.seed,
            [[k * m[0][0], k * m[0][1]], [k * m[1][0], k * m[1][1]]],
        );
        Ok(())
    }
}
