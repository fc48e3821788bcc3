//! Landforms of Fig. 4 (`crest`, `cliff`, `river`, `free_crest`, `ravine`, `fault`) and the
//! Fig. 8 composites (`mountain_range`, `mesa`); rasterised by [`crate::authoring::landform`]
//! (the crest by [`crate::authoring::raster`]).

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::{SpecError, MAX_ELEVATION_M};
use serde::{Deserialize, Serialize};

/// Crest: a ridge line at `elevation_m` along the polyline (hard), flanks falling at
/// `slope_deg` on both sides over `width_m` (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Crest {
    /// The ridge line, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Elevation of the ridge, metres.
    pub elevation_m: f64,
    /// Flank slope, degrees (`0..90`).
    pub slope_deg: f64,
    /// Flank width on each side, metres.
    pub width_m: f64,
}

impl Tool for Crest {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.elevation("/elevation_m", self.elevation_m)?;
        c.number("/slope_deg", self.slope_deg, 0.0, 89.0)?;
        c.radius("/width_m", self.width_m)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .crest(&self.points, self.elevation_m, self.slope_deg, self.width_m);
        Ok(())
    }
}

/// Cliff (Fig. 4): the top edge at `top_elevation_m` along the polyline (hard) and, on the
/// right of the stroke (looking along it, north up), a face falling at `slope_deg` away
/// from the edge over `width_m` (soft). The foot lies near `top − width·tan(slope)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cliff {
    /// The top edge, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Elevation of the top edge, metres.
    pub top_elevation_m: f64,
    /// Slope of the face, degrees (`0..=89`).
    pub slope_deg: f64,
    /// Horizontal width of the face, metres.
    pub width_m: f64,
}

impl Tool for Cliff {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.elevation("/top_elevation_m", self.top_elevation_m)?;
        c.number("/slope_deg", self.slope_deg, 0.0, 89.0)?;
        c.number("/width_m", self.width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.cliff(
            &self.points,
            self.top_elevation_m,
            self.slope_deg,
            self.width_m,
        );
        Ok(())
    }
}

/// River (Fig. 4): the bed at `bed_elevation_m` within `bed_width_m / 2` of the polyline
/// (hard) and banks rising gently at `bank_slope_deg` over `bank_width_m` on both sides
/// (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct River {
    /// The river's course, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Elevation of the bed, metres.
    pub bed_elevation_m: f64,
    /// Width of the bed, metres (at least one sample is fixed).
    #[serde(default)]
    pub bed_width_m: f64,
    /// Slope of the banks, degrees (`0..=30`: gentle).
    pub bank_slope_deg: f64,
    /// Width of each bank, metres.
    pub bank_width_m: f64,
}

impl Tool for River {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.elevation("/bed_elevation_m", self.bed_elevation_m)?;
        c.radius("/bed_width_m", self.bed_width_m)?;
        c.number("/bank_slope_deg", self.bank_slope_deg, 0.0, 30.0)?;
        c.number("/bank_width_m", self.bank_width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.river(
            &self.points,
            self.bed_elevation_m,
            self.bed_width_m,
            self.bank_slope_deg,
            self.bank_width_m,
        );
        Ok(())
    }
}

/// Free crest (Fig. 4): a ridge made of gradients only (no elevation), the flanks falling at
/// up to `slope_deg` (C² falloff) over `width_m`; added to the target, so crossings add.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FreeCrest {
    /// The ridge line, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Flank slope at the line, degrees (`0..=89`).
    pub slope_deg: f64,
    /// Reach on each side, metres.
    pub width_m: f64,
}

/// The checks of a free crest and a ravine.
fn check_free_crest(
    c: &Check,
    points: &[[f64; 2]],
    slope_deg: f64,
    width_m: f64,
) -> Result<(), SpecError> {
    c.polyline("/points", points)?;
    c.number("/slope_deg", slope_deg, 0.0, 89.0)?;
    c.number("/width_m", width_m, 1.0e-3, 1.0e6)
}

impl Tool for FreeCrest {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        check_free_crest(c, &self.points, self.slope_deg, self.width_m)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .free_crest(&self.points, 1.0, self.slope_deg, self.width_m);
        Ok(())
    }
}

/// Ravine (Fig. 4): a free crest upside down (gradients only; flanks rising away from the
/// line at up to `slope_deg` over `width_m`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ravine {
    /// The ravine's line, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Flank slope at the line, degrees (`0..=89`).
    pub slope_deg: f64,
    /// Reach on each side, metres.
    pub width_m: f64,
}

impl Tool for Ravine {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        check_free_crest(c, &self.points, self.slope_deg, self.width_m)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas
            .free_crest(&self.points, -1.0, self.slope_deg, self.width_m);
        Ok(())
    }
}

/// Fault (Fig. 4): a step of `throw_m` across the polyline, the right of the stroke
/// dropping (negative: rising), spread over a band of `width_m` (gradients only, added, so
/// crossing faults superpose). The step dies out beyond the polyline's ends.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fault {
    /// The fault line, `[x, z]` metres (at least 2 points).
    pub points: Vec<[f64; 2]>,
    /// Height of the step, metres.
    pub throw_m: f64,
    /// Width of the band the step is spread over, metres.
    pub width_m: f64,
}

impl Tool for Fault {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        if self.points.len() < 2 {
            return Err(c.refuse("/points", "a fault needs at least 2 points"));
        }
        c.elevation("/throw_m", self.throw_m)?;
        c.number("/width_m", self.width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.fault(&self.points, self.throw_m, self.width_m);
        Ok(())
    }
}

/// Mountain-range brush (Fig. 8, left): one stroke gives a main free crest rising about
/// `height_m` over `width_m` on each side, and side spurs every `width_m` along it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MountainRange {
    /// The stroke, `[x, z]` metres.
    pub points: Vec<[f64; 2]>,
    /// Rise of the main ridge above its surroundings, metres.
    pub height_m: f64,
    /// Reach of the main ridge on each side (and spur spacing), metres.
    pub width_m: f64,
    /// Spur jitter seed (hashed with the world seed).
    #[serde(default)]
    pub seed: u32,
}

impl Tool for MountainRange {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.polyline("/points", &self.points)?;
        c.number("/height_m", self.height_m, 0.0, MAX_ELEVATION_M)?;
        c.number("/width_m", self.width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.mountain_range(
            &self.points,
            self.height_m,
            self.width_m,
            r.plan.seed,
            self.seed,
        );
        Ok(())
    }
}

/// Mesa (Fig. 8, right): a plateau at `elevation_m` within `radius_m` of `center` (hard)
/// ringed by a cliff falling at `slope_deg` over `cliff_width_m` (soft).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mesa {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Plateau radius, metres.
    pub radius_m: f64,
    /// Plateau elevation, metres.
    pub elevation_m: f64,
    /// Cliff slope, degrees (`0..=89`).
    pub slope_deg: f64,
    /// Horizontal width of the cliff ring, metres.
    pub cliff_width_m: f64,
}

impl Tool for Mesa {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)?;
        c.elevation("/elevation_m", self.elevation_m)?;
        c.number("/slope_deg", self.slope_deg, 0.0, 89.0)?;
        c.number("/cliff_width_m", self.cliff_width_m, 1.0e-3, 1.0e6)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.mesa(
            self.center,
            self.radius_m,
            self.elevation_m,
            self.slope_deg,
            self.cliff_width_m,
        );
        Ok(())
    }
}
