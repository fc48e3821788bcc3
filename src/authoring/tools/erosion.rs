//! §4.4 erosion brushes on the heights solved so far, keeping every fixed sample: `erosion`
//! (thermal, [`crate::authoring::erosion`]) and `hydraulic_erosion` (droplets,
//! [`crate::authoring::hydraulic`]).

use super::{Check, Raster, Tool};
use crate::authoring::erosion::MAX_EROSION_ITERATIONS;
use crate::authoring::hydraulic::{droplet_seed, Droplets};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use crate::authoring::spec_tools::{MAX_DROPLETS, MAX_DROPLET_STEPS};
use serde::{Deserialize, Serialize};

/// Erosion brush (§4.4): the heights solved so far are eroded inside the disc of
/// `radius_m` around `center` (thermal erosion: `iterations` steps moving material downhill
/// wherever the slope exceeds `talus_deg`, faded by the C² falloff), keeping every fixed
/// sample, and the eroded gradients replace the target there (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Erosion {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
    /// Talus angle, degrees (`0..=89`).
    #[serde(default = "default_talus")]
    pub talus_deg: f64,
    /// Erosion steps, `1..=500`.
    pub iterations: u32,
}

fn default_talus() -> f64 {
    30.0
}

impl Tool for Erosion {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.number("/talus_deg", self.talus_deg, 0.0, 89.0)?;
        if !(1..=MAX_EROSION_ITERATIONS).contains(&self.iterations) {
            return Err(c.refuse(
                "/iterations",
                format!("must be in 1..={MAX_EROSION_ITERATIONS}"),
            ));
        }
        Ok(())
    }

    fn reads_solution(&self) -> bool {
        true
    }

    fn grid_sweeps(&self) -> u64 {
        u64::from(self.iterations)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let cancel = r.cancel.clone();
        let (canvas, current) = r.solved()?;
        canvas.erode(
            self.center,
            self.radius_m,
            self.talus_deg,
            self.iterations,
            current,
            &cancel,
        )?;
        Ok(())
    }
}

/// Hydraulic erosion brush (§4.4, Fig. 14): the heights solved so far are eroded inside the
/// disc of `radius_m` around `center` by `droplets` water droplets (each starting at a
/// hashed point of the disc and running at most `steps` cells downhill, picking up and
/// dropping sediment), keeping every fixed sample; the erosion's gradient change joins the target
/// there (soft, added). See [`crate::authoring::hydraulic`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydraulicErosion {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
    /// Droplets, `1..=200000`.
    pub droplets: u32,
    /// Most cells a droplet runs, `1..=512`.
    #[serde(default = "default_steps")]
    pub steps: u32,
    /// Share of the missing sediment capacity picked up per step, `0..=1`.
    #[serde(default = "default_erosion_rate")]
    pub erosion_rate: f64,
    /// Droplet seed (hashed with the world seed).
    #[serde(default)]
    pub seed: u32,
}

fn default_steps() -> u32 {
    64
}

fn default_erosion_rate() -> f64 {
    0.3
}

impl Tool for HydraulicErosion {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        if !(1..=MAX_DROPLETS).contains(&self.droplets) {
            return Err(c.refuse("/droplets", format!("must be in 1..={MAX_DROPLETS}")));
        }
        if !(1..=MAX_DROPLET_STEPS).contains(&self.steps) {
            return Err(c.refuse("/steps", format!("must be in 1..={MAX_DROPLET_STEPS}")));
        }
        c.number("/erosion_rate", self.erosion_rate, 0.0, 1.0)
    }

    fn reads_solution(&self) -> bool {
        true
    }

    fn droplet_steps(&self) -> u64 {
        u64::from(self.droplets) * u64::from(self.steps)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let d = Droplets {
            count: self.droplets,
            steps: self.steps,
            erosion_rate: self.erosion_rate,
            seed: droplet_seed(r.plan.seed, self.seed),
        };
        let cancel = r.cancel.clone();
        let (canvas, current) = r.solved()?;
        canvas.hydraulic_erode(self.center, self.radius_m, &d, current, &cancel)?;
        Ok(())
    }
}
