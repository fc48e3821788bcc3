//! Issue 17's coarse sketch (`sketch`): a PNG16 base height field over the bbox replacing the
//! world's large-scale elevation; decoded, checked and rasterised by [`crate::authoring::sketch`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::sketch::{decode, validate};
use crate::authoring::spec::SpecError;
use serde::{Deserialize, Serialize};

/// The coarse sketch ([`crate::authoring::sketch`]): a PNG16 base height field over the whole
/// `bbox` (corner pixels on its corners) replacing the world's large-scale elevation there,
/// tapered to the world's over `blend_m` inside the bbox edge; the world's detail stays (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sketch {
    /// A 16-bit greyscale PNG of 2 to 1025 pixels a side, base64 (standard, padded).
    pub png_base64: String,
    /// Elevation of value 0, metres.
    pub min_m: f64,
    /// Elevation of value 65535, metres.
    pub max_m: f64,
    /// Width of the taper inside the bbox edge, metres.
    #[serde(default)]
    pub blend_m: f64,
}

impl Tool for Sketch {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        validate(
            &c.at(""),
            (&self.png_base64, self.min_m, self.max_m, self.blend_m),
            c.spec.min,
            c.spec.max,
        )
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let img = decode(&self.png_base64, self.min_m, self.max_m)
            .map_err(|message| r.refuse(format!("sketch: {message}")))?;
        r.canvas.sketch(r.plan, &img, self.blend_m);
        Ok(())
    }
}
