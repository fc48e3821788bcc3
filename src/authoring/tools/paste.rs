//! §4.1 copy-paste (`copy_paste`): gradients of this world, another seed's or an inline PNG16
//! heightmap, rotated, scaled and warped; rasterised by [`crate::authoring::paste`].

use super::{Check, Raster, Tool};
use crate::authoring::paste::{PasteSource, Placement, Warp};
use crate::authoring::region::RegionError;
use crate::authoring::spec::{SpecError, MAX_PASTE_M};
use crate::authoring::spec_tools::{validate_heightmap, Heightmap};
use crate::terrain::WorldPlan;
use serde::{Deserialize, Serialize};

/// Copy-paste (§4.1): the gradients of the procedural world over the source rectangle
/// `source_min..source_max` are pasted centred on `target`, rotated by `rotation_deg` (from
/// +x toward +z: clockwise on a north-up map) and scaled horizontally by `scale` (heights
/// are copied, so slopes scale by `1/scale`); they replace the target gradient (soft), and
/// the reconstruction blends the copy into its surroundings. The source is this world, the
/// world of seed `source_seed` (same settings), or an inline PNG16 `heightmap` (then the
/// source rectangle is in metres from the image's west-north pixel); at most one of the two.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CopyPaste {
    /// West-north corner of the source `[x, z]`, metres.
    pub source_min: [f64; 2],
    /// East-south corner of the source `[x, z]`, metres.
    pub source_max: [f64; 2],
    /// Centre of the pasted copy `[x, z]`, metres.
    pub target: [f64; 2],
    /// Rotation, degrees (`−360..=360`).
    #[serde(default)]
    pub rotation_deg: f64,
    /// Horizontal scale (`0.125..=8`).
    #[serde(default = "unit_scale")]
    pub scale: f64,
    /// Seed of another world to copy from (with this world's settings).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source_seed: Option<u64>,
    /// An uploaded heightmap to copy from.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heightmap: Option<Heightmap>,
    /// Warp amplitude, metres (`0..=1000`; 0: none): the footprint is displaced by a
    /// smooth noise field before the mapping ([`crate::authoring::paste::Warp`]).
    #[serde(default)]
    pub warp_m: f64,
    /// Wavelength of the warp, metres (`1..=100000`).
    #[serde(default = "default_warp_wavelength")]
    pub warp_wavelength_m: f64,
    /// Warp noise seed (hashed with the world seed).
    #[serde(default)]
    pub warp_seed: u32,
}

fn unit_scale() -> f64 {
    1.0
}

fn default_warp_wavelength() -> f64 {
    64.0
}

impl Tool for CopyPaste {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.number("/warp_m", self.warp_m, 0.0, 1000.0)?;
        c.number("/warp_wavelength_m", self.warp_wavelength_m, 1.0, 1.0e5)?;
        if let Some(h) = &self.heightmap {
            if self.source_seed.is_some() {
                return Err(c.refuse(
                    "/source_seed",
                    "give at most one of source_seed and heightmap",
                ));
            }
            validate_heightmap(&c.at("/heightmap"), h)?;
        }
        c.position("/source_min", self.source_min)?;
        c.position("/source_max", self.source_max)?;
        c.position("/target", self.target)?;
        for k in 0..2 {
            let extent = self.source_max[k] - self.source_min[k];
            if extent <= 0.0 || extent > MAX_PASTE_M {
                return Err(c.refuse(
                    &format!("/source_max/{k}"),
                    format!("the source needs a width and depth in (0, {MAX_PASTE_M}] m"),
                ));
            }
        }
        c.number("/rotation_deg", self.rotation_deg, -360.0, 360.0)?;
        c.number("/scale", self.scale, 0.125, 8.0)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let plan = r.plan;
        let spacing = r.canvas.grid.spacing_m / self.scale;
        let source_err = |message: String| r.refuse(format!("copy-paste source: {message}"));
        let src = match (&self.heightmap, &self.source_seed) {
            (Some(h), _) => {
                let img = h.decode().map_err(source_err)?;
                PasteSource::from_image(
                    &img,
                    h.spacing_m,
                    self.source_min,
                    self.source_max,
                    spacing,
                )
            }
            (None, Some(seed)) => {
                let other = WorldPlan::new(*seed, plan.params.clone())
                    .map_err(|e| source_err(e.to_string()))?;
                PasteSource::sample_on(
                    &other,
                    self.source_min,
                    self.source_max,
                    spacing,
                    &r.cancel,
                )?
            }
            (None, None) => PasteSource::sample_on(
                plan,
                self.source_min,
                self.source_max,
                spacing,
                &r.cancel,
            )?,
        };
        let at = Placement {
            target: self.target,
            rotation_deg: self.rotation_deg,
            scale: self.scale,
            warp: Warp::new(
                plan.seed,
                self.warp_seed,
                self.warp_m,
                self.warp_wavelength_m,
            ),
        };
        r.canvas.paste(&src, &at);
        Ok(())
    }
}
