//! Schneider §3 basis functions (`basis`): a tileable greyscale image replacing the world's
//! relief texture below its period by convex weight; decoded, checked and rasterised by
//! [`crate::authoring::basis`].

use super::{Check, Raster, Tool};
use crate::authoring::basis::{decode, total_weight, validate};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use serde::{Deserialize, Serialize};

/// A basis function ([`crate::authoring::basis`], Schneider §3): a tileable 8- or 16-bit
/// greyscale image, tiled with period `period_m` over world position and scaled to zero mean
/// and RMS `amplitude_m`, replacing the world's relief texture below the period with convex
/// weight `weight` (tapered over `blend_m` inside the bbox edge; several in a region are
/// renormalised to sum to at most 1, the noise keeping the rest) (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Basis {
    /// An 8- or 16-bit greyscale PNG of 2 to 1024 pixels a side, base64 (standard, padded).
    pub png_base64: String,
    /// Period of the tiling, metres, at least 4 region sample spacings.
    pub period_m: f64,
    /// RMS of the image's texture, metres.
    pub amplitude_m: f64,
    /// Weight of the image against the world's texture, `0..=1`.
    #[serde(default = "default_weight")]
    pub weight: f64,
    /// Width of the taper inside the bbox edge, metres.
    #[serde(default)]
    pub blend_m: f64,
}

fn default_weight() -> f64 {
    1.0
}

impl Tool for Basis {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        validate(&c.at(""), self, c.spec.min, c.spec.max, c.spacing_m())
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let img =
            decode(&self.png_base64).map_err(|message| r.refuse(format!("basis: {message}")))?;
        let (spec, grid) = (r.spec, r.canvas.grid);
        let total = r
            .basis_total
            .get_or_insert_with(|| total_weight(&spec.ops, &grid).expect("a basis op"));
        r.canvas.basis(r.plan, &img, self, total);
        Ok(())
    }
}
