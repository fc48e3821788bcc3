//! The `regions` scene element: a `bbox`, a grid resolution and a list of tool operations.
//!
//! ```json
//! {"id": "valley", "bbox": {"min": [0, 0], "max": [512, 512]}, "samples": 257,
//!  "ops": [{"op": "elevation", "shape": {"point": [256, 256]}, "elevation_m": 80, "radius_m": 12},
//!          {"op": "amplify", "center": [100, 300], "radius_m": 60, "factor": 2.0}]}
//! ```
//!
//! Units: positions in world metres (`[x, z]`), radii and elevations in metres, slopes in
//! degrees. Every limit is a constant here ([`SAMPLE_CHOICES`], [`MAX_OPS`], [`MAX_POINTS`]).

use super::erosion::MAX_EROSION_ITERATIONS;
use super::spec_tools::{
    validate_contours, validate_heightmap, validate_network, Contour, Heightmap, NetworkEdge,
    NetworkNode, MAX_DROPLETS, MAX_DROPLET_STEPS, MAX_REGION_DROPLET_STEPS,
};
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

/// Where an elevation constraint applies.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Shape {
    /// One point `[x, z]`, metres.
    Point([f64; 2]),
    /// A polyline of points `[x, z]`, metres.
    Polyline(Vec<[f64; 2]>),
    /// A painted region: the polygon of points `[x, z]` (metres, at least 3, closed
    /// implicitly); every sample inside it, or within `radius_m` of its outline, is constrained.
    Region(Vec<[f64; 2]>),
}

/// One tool operation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Op {
    /// Hard elevation constraint: samples within `radius_m` of the shape take `elevation_m`
    /// (a polyline may give one elevation per point in `elevations_m`, interpolated along it).
    Elevation {
        /// Point or polyline.
        shape: Shape,
        /// Imposed elevation, metres (or per polyline point: `elevations_m`).
        #[serde(default)]
        elevation_m: Option<f64>,
        /// One elevation per polyline point, metres.
        #[serde(default)]
        elevations_m: Option<Vec<f64>>,
        /// Samples closer than this to the shape are constrained (at least the nearest), metres.
        #[serde(default)]
        radius_m: f64,
    },
    /// Freeze brush: samples within `radius_m` of `center` keep the procedural height (hard).
    Freeze {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
    },
    /// Gradient amplify (`factor > 1`) or suppress (`factor < 1`) brush with a C² falloff: the
    /// target gradient becomes `(1 + (factor − 1)·f(r)) · ∇h` (soft).
    Amplify {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
        /// Gradient scale at the centre, `0..=8`.
        factor: f64,
    },
    /// Crest: a ridge line at `elevation_m` along the polyline (hard), flanks falling at
    /// `slope_deg` on both sides over `width_m` (soft).
    Crest {
        /// The ridge line, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Elevation of the ridge, metres.
        elevation_m: f64,
        /// Flank slope, degrees (`0..90`).
        slope_deg: f64,
        /// Flank width on each side, metres.
        width_m: f64,
    },
    /// Noise brush: `g += ∇n` for a lattice noise `n` of `amplitude_m` and `wavelength_m`,
    /// faded out with a C² falloff (soft).
    Noise {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
        /// Noise amplitude, metres.
        amplitude_m: f64,
        /// Noise wavelength, metres.
        wavelength_m: f64,
        /// Noise seed (hashed with the world seed).
        #[serde(default)]
        seed: u32,
        /// Tensor modulation `μ` (§4.3): the noise's slopes along `angle_deg` are scaled by
        /// `1 + μ`, across it by `1 − μ` (`0..=1`; 0: isotropic noise).
        #[serde(default)]
        anisotropy: f64,
        /// Direction `θ` of the modulation, degrees from +x toward +z.
        #[serde(default)]
        angle_deg: f64,
    },

    /// Point gradient constraint (§4.1): the slope at `center` becomes `slope_deg` rising toward
    /// `direction_deg` (degrees from +x toward +z), faded out over `radius_m` by a curl-free
    /// field (soft, added; `Canvas::slope_point`).
    SlopePoint {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Reach, metres.
        radius_m: f64,
        /// Slope, degrees (`−89..=89`; negative falls toward the direction).
        slope_deg: f64,
        /// Direction of the rise, degrees from +x toward +z.
        direction_deg: f64,
    },
    /// Curve gradient constraint with a slope profile on each side (§4.1): out to `width_m`
    /// from the polyline the heights fall away from it at `slope_left_deg` on its left and
    /// `slope_right_deg` on its right (negative values rise), blended back over the last third
    /// of the width by a curl-free field (soft, added; `Canvas::slope_curve`).
    SlopeCurve {
        /// The curve, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Slope falling away on the left of the stroke, degrees (`−89..=89`).
        slope_left_deg: f64,
        /// Slope falling away on the right of the stroke, degrees (`−89..=89`).
        slope_right_deg: f64,
        /// Reach on each side, metres.
        width_m: f64,
    },

    /// Cliff (Fig. 4): the top edge at `top_elevation_m` along the polyline (hard) and, on the
    /// right of the stroke (looking along it, north up), a face falling at `slope_deg` away
    /// from the edge over `width_m` (soft). The foot lies near `top − width·tan(slope)`.
    Cliff {
        /// The top edge, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Elevation of the top edge, metres.
        top_elevation_m: f64,
        /// Slope of the face, degrees (`0..=89`).
        slope_deg: f64,
        /// Horizontal width of the face, metres.
        width_m: f64,
    },
    /// River (Fig. 4): the bed at `bed_elevation_m` within `bed_width_m / 2` of the polyline
    /// (hard) and banks rising gently at `bank_slope_deg` over `bank_width_m` on both sides
    /// (soft).
    River {
        /// The river's course, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Elevation of the bed, metres.
        bed_elevation_m: f64,
        /// Width of the bed, metres (at least one sample is fixed).
        #[serde(default)]
        bed_width_m: f64,
        /// Slope of the banks, degrees (`0..=30`: gentle).
        bank_slope_deg: f64,
        /// Width of each bank, metres.
        bank_width_m: f64,
    },
    /// Free crest (Fig. 4): a ridge made of gradients only (no elevation), the flanks falling at
    /// up to `slope_deg` (C² falloff) over `width_m`; added to the target, so crossings add.
    FreeCrest {
        /// The ridge line, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Flank slope at the line, degrees (`0..=89`).
        slope_deg: f64,
        /// Reach on each side, metres.
        width_m: f64,
    },
    /// Ravine (Fig. 4): a free crest upside down (gradients only; flanks rising away from the
    /// line at up to `slope_deg` over `width_m`).
    Ravine {
        /// The ravine's line, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Flank slope at the line, degrees (`0..=89`).
        slope_deg: f64,
        /// Reach on each side, metres.
        width_m: f64,
    },
    /// Fault (Fig. 4): a step of `throw_m` across the polyline, the right of the stroke
    /// dropping (negative: rising), spread over a band of `width_m` (gradients only, added, so
    /// crossing faults superpose). The step dies out beyond the polyline's ends.
    Fault {
        /// The fault line, `[x, z]` metres (at least 2 points).
        points: Vec<[f64; 2]>,
        /// Height of the step, metres.
        throw_m: f64,
        /// Width of the band the step is spread over, metres.
        width_m: f64,
    },
    /// Mountain-range brush (Fig. 8, left): one stroke gives a main free crest rising about
    /// `height_m` over `width_m` on each side, and side spurs every `width_m` along it.
    MountainRange {
        /// The stroke, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Rise of the main ridge above its surroundings, metres.
        height_m: f64,
        /// Reach of the main ridge on each side (and spur spacing), metres.
        width_m: f64,
        /// Spur jitter seed (hashed with the world seed).
        #[serde(default)]
        seed: u32,
    },
    /// Mesa (Fig. 8, right): a plateau at `elevation_m` within `radius_m` of `center` (hard)
    /// ringed by a cliff falling at `slope_deg` over `cliff_width_m` (soft).
    Mesa {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Plateau radius, metres.
        radius_m: f64,
        /// Plateau elevation, metres.
        elevation_m: f64,
        /// Cliff slope, degrees (`0..=89`).
        slope_deg: f64,
        /// Horizontal width of the cliff ring, metres.
        cliff_width_m: f64,
    },

    /// Copy-paste (§4.1): the gradients of the procedural world over the source rectangle
    /// `source_min..source_max` are pasted centred on `target`, rotated by `rotation_deg` (from
    /// +x toward +z: clockwise on a north-up map) and scaled horizontally by `scale` (heights
    /// are copied, so slopes scale by `1/scale`); they replace the target gradient (soft), and
    /// the reconstruction blends the copy into its surroundings. The source is this world, the
    /// world of seed `source_seed` (same settings), or an inline PNG16 `heightmap` (then the
    /// source rectangle is in metres from the image's west-north pixel); at most one of the two.
    CopyPaste {
        /// West-north corner of the source `[x, z]`, metres.
        source_min: [f64; 2],
        /// East-south corner of the source `[x, z]`, metres.
        source_max: [f64; 2],
        /// Centre of the pasted copy `[x, z]`, metres.
        target: [f64; 2],
        /// Rotation, degrees (`−360..=360`).
        #[serde(default)]
        rotation_deg: f64,
        /// Horizontal scale (`0.125..=8`).
        #[serde(default = "unit_scale")]
        scale: f64,
        /// Seed of another world to copy from (with this world's settings).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        source_seed: Option<u64>,
        /// An uploaded heightmap to copy from.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        heightmap: Option<Heightmap>,
        /// Warp amplitude, metres (`0..=1000`; 0: none): the footprint is displaced by a
        /// smooth noise field before the mapping ([`super::paste::Warp`]).
        #[serde(default)]
        warp_m: f64,
        /// Wavelength of the warp, metres (`1..=100000`).
        #[serde(default = "default_warp_wavelength")]
        warp_wavelength_m: f64,
        /// Warp noise seed (hashed with the world seed).
        #[serde(default)]
        warp_seed: u32,
    },

    /// Directional tensor (§4.3): inside the disc of `radius_m` around `center` the target
    /// gradient is multiplied by `D = I + μ·M(θ)`, which scales slopes along `angle_deg` by
    /// `1 + strength` and across it by `1 − strength`.
    DirectionalTensor {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
        /// Direction `θ`, degrees from +x toward +z.
        angle_deg: f64,
        /// `μ`, `0..=1`.
        strength: f64,
    },
    /// Skeleton tensor (§4.3): `I + μ·α(d/r)·M(θ)` around a point or polyline skeleton, `α`
    /// the C² falloff of the distance to it.
    SkeletonTensor {
        /// The skeleton: one point or a polyline, `[x, z]` metres.
        points: Vec<[f64; 2]>,
        /// Radius of influence, metres.
        radius_m: f64,
        /// Direction `θ`, degrees from +x toward +z.
        angle_deg: f64,
        /// `μ`, `0..=1`.
        strength: f64,
    },
    /// Stroke-aligned tensor brush (§4.3, Fig. 7): a skeleton tensor whose direction follows
    /// the stroke at the closest point, orienting slopes along the stroke.
    StrokeTensor {
        /// The stroke, `[x, z]` metres (at least 2 points).
        points: Vec<[f64; 2]>,
        /// Radius of influence, metres.
        radius_m: f64,
        /// `μ`, `0..=1`.
        strength: f64,
    },

    /// Erosion brush (§4.4): the heights solved so far are eroded inside the disc of
    /// `radius_m` around `center` (thermal erosion: `iterations` steps moving material downhill
    /// wherever the slope exceeds `talus_deg`, faded by the C² falloff), keeping every fixed
    /// sample, and the eroded gradients replace the target there (soft).
    Erosion {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
        /// Talus angle, degrees (`0..=89`).
        #[serde(default = "default_talus")]
        talus_deg: f64,
        /// Erosion steps, `1..=500`.
        iterations: u32,
    },
    /// Hydraulic erosion brush (§4.4, Fig. 14): the heights solved so far are eroded inside the
    /// disc of `radius_m` around `center` by `droplets` water droplets (each starting at a
    /// hashed point of the disc and running at most `steps` cells downhill, picking up and
    /// dropping sediment), keeping every fixed sample; the erosion's gradient change joins the target
    /// there (soft, added). See [`super::hydraulic`].
    HydraulicErosion {
        /// Centre `[x, z]`, metres.
        center: [f64; 2],
        /// Radius, metres.
        radius_m: f64,
        /// Droplets, `1..=200000`.
        droplets: u32,
        /// Most cells a droplet runs, `1..=512`.
        #[serde(default = "default_steps")]
        steps: u32,
        /// Share of the missing sediment capacity picked up per step, `0..=1`.
        #[serde(default = "default_erosion_rate")]
        erosion_rate: f64,
        /// Droplet seed (hashed with the world seed).
        #[serde(default)]
        seed: u32,
    },
    /// Fitting to contour lines (§5.1, Fig. 10): every line becomes an elevation constraint at
    /// its elevation (hard), and the target gradient of the heights over the whole region is
    /// scaled by `detail` (0: the null Laplacian, a membrane between the contours; 1: keep the
    /// relief, e.g. the procedural world's or a noise brush's, as detail).
    Contours {
        /// The contour lines.
        lines: Vec<Contour>,
        /// Share of the prior relief kept, `0..=1`.
        #[serde(default)]
        detail: f64,
    },
    /// Fitting to a ridge/river network (§5.1, Fig. 11): each edge is an elevation constraint
    /// along its polyline (hard), the elevation linear in arc length between its nodes' (so
    /// junctions agree), with flanks falling from ridges and banks rising from rivers at
    /// `slope_deg` over `width_m` (soft); the rest of the region's target gradient is scaled by
    /// `detail` as for contours.
    Network {
        /// The nodes (junctions, sources, mouths, peaks).
        nodes: Vec<NetworkNode>,
        /// The edges between nodes.
        edges: Vec<NetworkEdge>,
        /// Share of the prior relief kept, `0..=1`.
        #[serde(default)]
        detail: f64,
    },
    /// Two-pass regularisation (§3): the operations so far are reconstructed, the target
    /// gradient becomes the gradient of that reconstruction (curl-free), and the interior
    /// Dirichlet constraints are dropped (frozen samples stay), as they are now part of the
    /// gradient field. Later operations edit that field.
    Regularize {},
    /// The coarse sketch ([`super::sketch`]): a PNG16 base height field over the whole `bbox`
    /// (corner pixels on its corners) replacing the world's large-scale elevation there, tapered
    /// to the world's over `blend_m` inside the bbox edge; the world's detail stays (soft).
    Sketch {
        /// A 16-bit greyscale PNG of 2 to 1025 pixels a side, base64 (standard, padded).
        png_base64: String,
        /// Elevation of value 0, metres.
        min_m: f64,
        /// Elevation of value 65535, metres.
        max_m: f64,
        /// Width of the taper inside the bbox edge, metres.
        #[serde(default)]
        blend_m: f64,
    },
    /// A basis function ([`super::basis`], Schneider §3): a tileable 8- or 16-bit greyscale
    /// image, tiled with period `period_m` over world position and scaled to zero mean and RMS
    /// `amplitude_m`, replacing the world's relief texture below the period with convex weight
    /// `weight` (tapered over `blend_m` inside the bbox edge; several in a region are
    /// renormalised to sum to at most 1, the noise keeping the rest) (soft).
    Basis {
        /// An 8- or 16-bit greyscale PNG of 2 to 1024 pixels a side, base64 (standard, padded).
        png_base64: String,
        /// Period of the tiling, metres, at least 4 region sample spacings.
        period_m: f64,
        /// RMS of the image's texture, metres.
        amplitude_m: f64,
        /// Weight of the image against the world's texture, `0..=1`.
        #[serde(default = "default_weight")]
        weight: f64,
        /// Width of the taper inside the bbox edge, metres.
        #[serde(default)]
        blend_m: f64,
    },
}

fn default_weight() -> f64 {
    1.0
}

fn default_warp_wavelength() -> f64 {
    64.0
}

fn default_steps() -> u32 {
    64
}

fn default_erosion_rate() -> f64 {
    0.3
}

fn default_talus() -> f64 {
    30.0
}

fn unit_scale() -> f64 {
    1.0
}

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
    /// hydraulic-erosion brushes is at most [`MAX_REGION_DROPLET_STEPS`].
    pub fn check_cost(&self) -> Result<(), SpecError> {
        let mut droplet_steps = 0u64;
        for (i, op) in self.ops.iter().enumerate() {
            if let Op::HydraulicErosion {
                droplets, steps, ..
            } = op
            {
                droplet_steps += u64::from(*droplets) * u64::from(*steps);
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
        let big = crate::element::MAX_COORD_M;
        let pos = |p: String, v: [f64; 2]| -> Result<(), SpecError> {
            finite_in(format!("{p}/0"), v[0], -big, big)?;
            finite_in(format!("{p}/1"), v[1], -big, big)
        };
        let radius = |p: String, r: f64| finite_in(p, r, 0.0, 1.0e6);
        let elev = |p: String, v: f64| finite_in(p, v, -MAX_ELEVATION_M, MAX_ELEVATION_M);
        let polyline = |p: String, pts: &[[f64; 2]]| -> Result<(), SpecError> {
            if pts.is_empty() || pts.len() > MAX_POINTS {
                return Err(err(p, format!("needs 1 to {MAX_POINTS} points")));
            }
            for (i, q) in pts.iter().enumerate() {
                pos(format!("{p}/{i}"), *q)?;
            }
            Ok(())
        };
        for (i, op) in self.ops.iter().enumerate() {
            let at = |f: &str| format!("/ops/{i}{f}");
            match op {
                Op::Elevation {
                    shape,
                    elevation_m,
                    elevations_m,
                    radius_m,
                } => {
                    radius(at("/radius_m"), *radius_m)?;
                    let count = match shape {
                        Shape::Point(p) => {
                            pos(at("/shape/point"), *p)?;
                            1
                        }
                        Shape::Polyline(pts) => {
                            polyline(at("/shape/polyline"), pts)?;
                            pts.len()
                        }
                        Shape::Region(pts) => {
                            polyline(at("/shape/region"), pts)?;
                            if pts.len() < 3 {
                                return Err(err(
                                    at("/shape/region"),
                                    "a painted region needs at least 3 points",
                                ));
                            }
                            if elevations_m.is_some() {
                                return Err(err(
                                    at("/elevations_m"),
                                    "a painted region takes one elevation_m",
                                ));
                            }
                            1
                        }
                    };
                    match (elevation_m, elevations_m) {
                        (Some(e), None) => elev(at("/elevation_m"), *e)?,
                        (None, Some(es)) => {
                            if es.len() != count {
                                return Err(err(
                                    at("/elevations_m"),
                                    format!("needs one elevation per point ({count})"),
                                ));
                            }
                            for (k, e) in es.iter().enumerate() {
                                elev(at(&format!("/elevations_m/{k}")), *e)?;
                            }
                        }
                        _ => {
                            return Err(err(
                                at("/elevation_m"),
                                "give exactly one of elevation_m and elevations_m",
                            ))
                        }
                    }
                }
                Op::Freeze { center, radius_m } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                }
                Op::Amplify {
                    center,
                    radius_m,
                    factor,
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/factor"), *factor, 0.0, 8.0)?;
                }
                Op::Crest {
                    points,
                    elevation_m,
                    slope_deg,
                    width_m,
                } => {
                    polyline(at("/points"), points)?;
                    elev(at("/elevation_m"), *elevation_m)?;
                    finite_in(at("/slope_deg"), *slope_deg, 0.0, 89.0)?;
                    radius(at("/width_m"), *width_m)?;
                }
                Op::Noise {
                    center,
                    radius_m,
                    amplitude_m,
                    wavelength_m,
                    anisotropy,
                    angle_deg,
                    ..
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/amplitude_m"), *amplitude_m, 0.0, 1.0e4)?;
                    finite_in(at("/wavelength_m"), *wavelength_m, 1.0e-3, 1.0e6)?;
                    finite_in(at("/anisotropy"), *anisotropy, 0.0, 1.0)?;
                    finite_in(at("/angle_deg"), *angle_deg, -360.0, 360.0)?;
                }
                Op::SlopePoint {
                    center,
                    radius_m,
                    slope_deg,
                    direction_deg,
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/slope_deg"), *slope_deg, -89.0, 89.0)?;
                    finite_in(at("/direction_deg"), *direction_deg, -360.0, 360.0)?;
                }
                Op::SlopeCurve {
                    points,
                    slope_left_deg,
                    slope_right_deg,
                    width_m,
                } => {
                    polyline(at("/points"), points)?;
                    finite_in(at("/slope_left_deg"), *slope_left_deg, -89.0, 89.0)?;
                    finite_in(at("/slope_right_deg"), *slope_right_deg, -89.0, 89.0)?;
                    finite_in(at("/width_m"), *width_m, 1.0e-3, 1.0e6)?;
                }
                Op::Cliff {
                    points,
                    top_elevation_m,
                    slope_deg,
                    width_m,
                } => {
                    polyline(at("/points"), points)?;
                    elev(at("/top_elevation_m"), *top_elevation_m)?;
                    finite_in(at("/slope_deg"), *slope_deg, 0.0, 89.0)?;
                    finite_in(at("/width_m"), *width_m, 1.0e-3, 1.0e6)?;
                }
                Op::River {
                    points,
                    bed_elevation_m,
                    bed_width_m,
                    bank_slope_deg,
                    bank_width_m,
                } => {
                    polyline(at("/points"), points)?;
                    elev(at("/bed_elevation_m"), *bed_elevation_m)?;
                    radius(at("/bed_width_m"), *bed_width_m)?;
                    finite_in(at("/bank_slope_deg"), *bank_slope_deg, 0.0, 30.0)?;
                    finite_in(at("/bank_width_m"), *bank_width_m, 1.0e-3, 1.0e6)?;
                }
                Op::FreeCrest {
                    points,
                    slope_deg,
                    width_m,
                }
                | Op::Ravine {
                    points,
                    slope_deg,
                    width_m,
                } => {
                    polyline(at("/points"), points)?;
                    finite_in(at("/slope_deg"), *slope_deg, 0.0, 89.0)?;
                    finite_in(at("/width_m"), *width_m, 1.0e-3, 1.0e6)?;
                }
                Op::Fault {
                    points,
                    throw_m,
                    width_m,
                } => {
                    polyline(at("/points"), points)?;
                    if points.len() < 2 {
                        return Err(err(at("/points"), "a fault needs at least 2 points"));
                    }
                    elev(at("/throw_m"), *throw_m)?;
                    finite_in(at("/width_m"), *width_m, 1.0e-3, 1.0e6)?;
                }
                Op::MountainRange {
                    points,
                    height_m,
                    width_m,
                    ..
                } => {
                    polyline(at("/points"), points)?;
                    finite_in(at("/height_m"), *height_m, 0.0, MAX_ELEVATION_M)?;
                    finite_in(at("/width_m"), *width_m, 1.0e-3, 1.0e6)?;
                }
                Op::Mesa {
                    center,
                    radius_m,
                    elevation_m,
                    slope_deg,
                    cliff_width_m,
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    elev(at("/elevation_m"), *elevation_m)?;
                    finite_in(at("/slope_deg"), *slope_deg, 0.0, 89.0)?;
                    finite_in(at("/cliff_width_m"), *cliff_width_m, 1.0e-3, 1.0e6)?;
                }
                Op::CopyPaste {
                    source_min,
                    source_max,
                    target,
                    rotation_deg,
                    scale,
                    source_seed,
                    heightmap,
                    warp_m,
                    warp_wavelength_m,
                    ..
                } => {
                    finite_in(at("/warp_m"), *warp_m, 0.0, 1000.0)?;
                    finite_in(at("/warp_wavelength_m"), *warp_wavelength_m, 1.0, 1.0e5)?;
                    if let Some(h) = heightmap {
                        if source_seed.is_some() {
                            return Err(err(
                                at("/source_seed"),
                                "give at most one of source_seed and heightmap",
                            ));
                        }
                        validate_heightmap(&at("/heightmap"), h)?;
                    }
                    pos(at("/source_min"), *source_min)?;
                    pos(at("/source_max"), *source_max)?;
                    pos(at("/target"), *target)?;
                    for k in 0..2 {
                        let extent = source_max[k] - source_min[k];
                        if extent <= 0.0 || extent > MAX_PASTE_M {
                            return Err(err(
                                at(&format!("/source_max/{k}")),
                                format!(
                                    "the source needs a width and depth in (0, {MAX_PASTE_M}] m"
                                ),
                            ));
                        }
                    }
                    finite_in(at("/rotation_deg"), *rotation_deg, -360.0, 360.0)?;
                    finite_in(at("/scale"), *scale, 0.125, 8.0)?;
                }
                Op::DirectionalTensor {
                    center,
                    radius_m,
                    angle_deg,
                    strength,
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/angle_deg"), *angle_deg, -360.0, 360.0)?;
                    finite_in(at("/strength"), *strength, 0.0, 1.0)?;
                }
                Op::SkeletonTensor {
                    points,
                    radius_m,
                    angle_deg,
                    strength,
                } => {
                    polyline(at("/points"), points)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/angle_deg"), *angle_deg, -360.0, 360.0)?;
                    finite_in(at("/strength"), *strength, 0.0, 1.0)?;
                }
                Op::StrokeTensor {
                    points,
                    radius_m,
                    strength,
                } => {
                    polyline(at("/points"), points)?;
                    if points.len() < 2 {
                        return Err(err(at("/points"), "a stroke needs at least 2 points"));
                    }
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/strength"), *strength, 0.0, 1.0)?;
                }
                Op::Erosion {
                    center,
                    radius_m,
                    talus_deg,
                    iterations,
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    finite_in(at("/talus_deg"), *talus_deg, 0.0, 89.0)?;
                    if !(1..=MAX_EROSION_ITERATIONS).contains(iterations) {
                        return Err(err(
                            at("/iterations"),
                            format!("must be in 1..={MAX_EROSION_ITERATIONS}"),
                        ));
                    }
                }
                Op::HydraulicErosion {
                    center,
                    radius_m,
                    droplets,
                    steps,
                    erosion_rate,
                    ..
                } => {
                    pos(at("/center"), *center)?;
                    radius(at("/radius_m"), *radius_m)?;
                    if !(1..=MAX_DROPLETS).contains(droplets) {
                        return Err(err(
                            at("/droplets"),
                            format!("must be in 1..={MAX_DROPLETS}"),
                        ));
                    }
                    if !(1..=MAX_DROPLET_STEPS).contains(steps) {
                        return Err(err(
                            at("/steps"),
                            format!("must be in 1..={MAX_DROPLET_STEPS}"),
                        ));
                    }

                    finite_in(at("/erosion_rate"), *erosion_rate, 0.0, 1.0)?;
                }
                Op::Contours { lines, detail } => validate_contours(&at(""), lines, *detail)?,
                Op::Network {
                    nodes,
                    edges,
                    detail,
                } => validate_network(&at(""), nodes, edges, *detail)?,
                Op::Regularize {} => {}
                Op::Sketch {
                    png_base64,
                    min_m,
                    max_m,
                    blend_m,
                } => super::sketch::validate(
                    &at(""),
                    (png_base64, *min_m, *max_m, *blend_m),
                    self.min,
                    self.max,
                )?,
                Op::Basis { .. } => {
                    let spacing = (self.max[0] - self.min[0]).max(self.max[1] - self.min[1])
                        / (self.samples - 1) as f64;
                    let b = super::basis::BasisOp::of(op).expect("a basis op");
                    super::basis::validate(&at(""), &b, self.min, self.max, spacing)?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn parse(region: serde_json::Value) -> Result<RegionSpec, SpecError> {
        let element: Element = serde_json::from_value(region).expect("an element");
        RegionSpec::from_element(&element)
    }

    #[test]
    fn a_regions_droplet_steps_are_bounded_before_any_work() {
        // Issue 18, finding 4: 200,000 droplets × 512 steps took 21 s of CPU per tile request.
        let brush = |droplets: u64, steps: u64| {
            json!({"op": "hydraulic_erosion", "center": [50, 50], "radius_m": 20,
                "droplets": droplets, "steps": steps})
        };
        let region = |ops: Vec<serde_json::Value>| {
            parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "ops": ops}))
                .expect("a valid region")
                .check_cost()
        };
        let half = MAX_REGION_DROPLET_STEPS / 2 / 512;
        assert!(region(vec![brush(half, 512), brush(half, 512)]).is_ok());
        let e = region(vec![brush(200_000, 512)]).expect_err("the probe's brush");
        assert_eq!(e.pointer, "/ops/0/droplets");
        assert!(
            e.message.contains(&MAX_REGION_DROPLET_STEPS.to_string()),
            "{}",
            e.message
        );
        let e = region(vec![brush(half, 512), brush(half, 512), brush(1, 1)])
            .expect_err("the sum over brushes");
        assert_eq!(e.pointer, "/ops/2/droplets");
    }

    #[test]
    fn the_new_tools_parse_with_defaults() {
        let r = parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]},
            "ops": [{"op": "hydraulic_erosion", "center": [50, 50], "radius_m": 20, "droplets": 100},
                    {"op": "regularize"},
                    {"op": "contours", "lines": [{"points": [[1, 1], [9, 9]], "elevation_m": 3}]}]}))
        .expect("valid");
        assert!(matches!(
            r.ops[0],
            Op::HydraulicErosion { steps: 64, erosion_rate, seed: 0, .. } if erosion_rate == 0.3
        ));
        assert_eq!(r.ops[1], Op::Regularize {});
        assert!(matches!(&r.ops[2], Op::Contours { detail, .. } if *detail == 0.0));
        // A copy-paste without a heightmap or seed serialises as before.
        let p = parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]},
            "ops": [{"op": "copy_paste", "source_min": [0, 0], "source_max": [9, 9], "target": [5, 5]}]}))
        .expect("valid");
        let text = serde_json::to_string(&p.ops[0]).expect("json");
        assert!(
            !text.contains("heightmap") && !text.contains("source_seed"),
            "{text}"
        );
    }

    #[test]
    fn a_region_parses_with_defaults() {
        let r = parse(json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 50]},
            "ops": [{"op": "elevation", "shape": {"point": [10, 10]}, "elevation_m": 5}]}))
        .expect("valid");
        assert_eq!(r.samples, DEFAULT_SAMPLES);
        assert_eq!(r.ops.len(), 1);
    }

    #[test]
    fn bad_fields_are_named() {
        let base = |ops: serde_json::Value| json!({"id": "a", "bbox": {"min": [0, 0], "max": [100, 100]}, "ops": ops});
        let cases = [
            (
                json!({"id": "a", "bbox": {"min": [0, 0], "max": [1, 1]}, "samples": 100}),
                "/samples",
            ),
            (
                base(json!([{"op": "amplify", "center": [0, 0], "radius_m": 5, "factor": 9}])),
                "/ops/0/factor",
            ),
            (
                base(json!([{"op": "freeze", "center": [0, 0], "radius_m": -1}])),
                "/ops/0/radius_m",
            ),
            (
                base(json!([{"op": "elevation", "shape": {"point": [0, 0]}}])),
                "/ops/0/elevation_m",
            ),
            (
                base(
                    json!([{"op": "elevation", "shape": {"polyline": [[0, 0], [1, 1]]}, "elevations_m": [1]}]),
                ),
                "/ops/0/elevations_m",
            ),
            (
                base(
                    json!([{"op": "crest", "points": [], "elevation_m": 1, "slope_deg": 10, "width_m": 5}]),
                ),
                "/ops/0/points",
            ),
            (
                base(
                    json!([{"op": "cliff", "points": [[0, 0], [9, 0]], "top_elevation_m": 1, "slope_deg": 95, "width_m": 5}]),
                ),
                "/ops/0/slope_deg",
            ),
            (
                base(json!([{"op": "fault", "points": [[0, 0]], "throw_m": 3, "width_m": 5}])),
                "/ops/0/points",
            ),
            (
                base(
                    json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5], "scale": 20}]),
                ),
                "/ops/0/scale",
            ),
            (
                base(
                    json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 0], "target": [5, 5]}]),
                ),
                "/ops/0/source_max/1",
            ),
            (
                base(json!([{"op": "erosion", "center": [0, 0], "radius_m": 5, "iterations": 0}])),
                "/ops/0/iterations",
            ),
            (
                base(
                    json!([{"op": "directional_tensor", "center": [0, 0], "radius_m": 5, "angle_deg": 0, "strength": 2}]),
                ),
                "/ops/0/strength",
            ),
            (
                base(
                    json!([{"op": "river", "points": [[0, 0], [9, 0]], "bed_elevation_m": 1, "bank_slope_deg": 45, "bank_width_m": 5}]),
                ),
                "/ops/0/bank_slope_deg",
            ),
            (base(json!([{"op": "melt"}])), "/ops/0"),
            (
                base(
                    json!([{"op": "hydraulic_erosion", "center": [0, 0], "radius_m": 5, "droplets": 0}]),
                ),
                "/ops/0/droplets",
            ),
            (
                base(
                    json!([{"op": "hydraulic_erosion", "center": [0, 0], "radius_m": 5, "droplets": 9, "erosion_rate": 2}]),
                ),
                "/ops/0/erosion_rate",
            ),
            (
                base(json!([{"op": "contours", "lines": []}])),
                "/ops/0/lines",
            ),
            (
                base(
                    json!([{"op": "contours", "lines": [{"points": [[0, 0]], "elevation_m": 1e9}]}]),
                ),
                "/ops/0/lines/0/elevation_m",
            ),
            (
                base(json!([{"op": "network",
                    "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9], "elevation_m": 5}],
                    "edges": [{"from": 0, "to": 1, "kind": "river"}]}])),
                "/ops/0/edges/0/to",
            ),
            (
                base(json!([{"op": "network",
                    "nodes": [{"at": [0, 0], "elevation_m": 1}],
                    "edges": [{"from": 0, "to": 3, "kind": "ridge"}]}])),
                "/ops/0/edges/0/to",
            ),
            (
                base(
                    json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5],
                        "heightmap": {"png_base64": "not*base64", "lo_m": 0, "hi_m": 1, "spacing_m": 1}}]),
                ),
                "/ops/0/heightmap/png_base64",
            ),
            (
                base(
                    json!([{"op": "copy_paste", "source_min": [0, 0], "source_max": [10, 10], "target": [5, 5],
                        "source_seed": 4, "heightmap": {"png_base64": "", "lo_m": 0, "hi_m": 1, "spacing_m": 1}}]),
                ),
                "/ops/0/source_seed",
            ),
            (base(json!([{"op": "regularize", "x": 1}])), "/ops/0"),
            (
                base(json!([{"op": "network",
                    "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9]}],
                    "edges": [{"from": 0, "to": 1, "kind": "ridge"}]}])),
                "/ops/0/nodes/1/elevation_m",
            ),
            (
                base(json!([{"op": "network",
                    "nodes": [{"at": [0, 0], "elevation_m": 1}, {"at": [9, 9]}],
                    "edges": [{"from": 0, "to": 1, "kind": "river", "grade_deg": 5}]}])),
                "/ops/0/edges/0/to",
            ),
            (
                json!({"id": "a", "bbox": {"min": [0, 0], "max": [0, 10]}}),
                "/bbox",
            ),
        ];
        for (region, pointer) in cases {
            let e = parse(region.clone()).expect_err("refused");
            assert!(
                e.pointer.starts_with(pointer),
                "{region}: got {e}, want {pointer}"
            );
        }
    }
}
