//! Hard elevation constraints: `elevation` (a point, polyline or painted region held at an
//! elevation) and `freeze` (a disc keeping the heights solved so far); rasterised by
//! [`crate::authoring::raster`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use serde::{Deserialize, Serialize};

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

/// Hard elevation constraint: samples within `radius_m` of the shape take `elevation_m`
/// (a polyline may give one elevation per point in `elevations_m`, interpolated along it).
///
/// With `ring_m`, the constraint blends into the procedural ground over a ring of that width
/// around it with a C² profile (height and its first and second derivatives continuous at both
/// edges of the ring; [`crate::authoring::raster::Canvas::elevation_ring`]): the smooth hill of
/// the viewer. Without it (documents stored before it) the samples beyond `radius_m` are free
/// and the solve meets the constraint with a kink, as before.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Elevation {
    /// Point or polyline.
    pub shape: Shape,
    /// Imposed elevation, metres (or per polyline point: `elevations_m`).
    #[serde(default)]
    pub elevation_m: Option<f64>,
    /// One elevation per polyline point, metres.
    #[serde(default)]
    pub elevations_m: Option<Vec<f64>>,
    /// Samples closer than this to the shape are constrained (at least the nearest), metres.
    #[serde(default)]
    pub radius_m: f64,
    /// Width of the C² ring beyond `radius_m` over which the elevation blends into the
    /// procedural ground, metres (absent: no ring). At least [`MIN_RING_SAMPLES`] sample spacings
    /// of the region, and the ring lies inside the region's bbox.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ring_m: Option<f64>,
}

/// Fewest region sample spacings a ring spans: fewer cannot resolve its second derivative.
pub const MIN_RING_SAMPLES: f64 = 4.0;

impl Elevation {
    /// Checks `ring_m`: its width and that the ring, with the two spacings past it that keep the
    /// procedural ground, lies inside the bbox (its edge there would be a kink).
    fn check_ring(&self, c: &Check, ring: f64) -> Result<(), SpecError> {
        c.radius("/ring_m", ring)?;
        let spacing = c.spacing_m();
        let least = MIN_RING_SAMPLES * spacing;
        if ring < least {
            return Err(c.refuse(
                "/ring_m",
                format!(
                    "must be at least {MIN_RING_SAMPLES} sample spacings of the region ({least} m)"
                ),
            ));
        }
        let pts: &[[f64; 2]] = match &self.shape {
            Shape::Point(p) => std::slice::from_ref(p),
            Shape::Polyline(pts) | Shape::Region(pts) => pts,
        };
        let reach = self.radius_m + ring + 2.0 * spacing;
        let s = c.spec;
        let inside = pts.iter().all(|p| {
            p[0] - reach >= s.min[0]
                && p[0] + reach <= s.max[0]
                && p[1] - reach >= s.min[1]
                && p[1] + reach <= s.max[1]
        });
        if !inside {
            return Err(c.refuse(
                "/ring_m",
                format!(
                    "the ring reaches {reach} m from the shape (radius_m + ring_m + 2 sample \
                     spacings), beyond the region's bbox"
                ),
            ));
        }
        Ok(())
    }
}

impl Tool for Elevation {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.radius("/radius_m", self.radius_m)?;
        if let Some(ring) = self.ring_m {
            self.check_ring(c, ring)?;
        }
        let count = match &self.shape {
            Shape::Point(p) => {
                c.position("/shape/point", *p)?;
                1
            }
            Shape::Polyline(pts) => {
                c.polyline("/shape/polyline", pts)?;
                pts.len()
            }
            Shape::Region(pts) => {
                c.polyline("/shape/region", pts)?;
                if pts.len() < 3 {
                    return Err(
                        c.refuse("/shape/region", "a painted region needs at least 3 points")
                    );
                }
                if self.elevations_m.is_some() {
                    return Err(c.refuse("/elevations_m", "a painted region takes one elevation_m"));
                }
                1
            }
        };
        match (&self.elevation_m, &self.elevations_m) {
            (Some(e), None) => c.elevation("/elevation_m", *e),
            (None, Some(es)) => {
                if es.len() != count {
                    return Err(c.refuse(
                        "/elevations_m",
                        format!("needs one elevation per point ({count})"),
                    ));
                }
                for (k, e) in es.iter().enumerate() {
                    c.elevation(&format!("/elevations_m/{k}"), *e)?;
                }
                Ok(())
            }
            _ => Err(c.refuse(
                "/elevation_m",
                "give exactly one of elevation_m and elevations_m",
            )),
        }
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let es = match (&self.elevation_m, &self.elevations_m) {
            (_, Some(es)) => es.clone(),
            (Some(e), None) => vec![*e],
            (None, None) => vec![0.0],
        };
        match &self.shape {
            Shape::Point(p) => r.canvas.elevation(&[*p], &es, self.radius_m),
            Shape::Polyline(pts) => r.canvas.elevation(pts, &es, self.radius_m),
            Shape::Region(poly) => r.canvas.elevation_region(poly, es[0], self.radius_m),
        }
        if let Some(ring) = self.ring_m {
            match &self.shape {
                Shape::Point(p) => r.canvas.elevation_ring(&[*p], &es, self.radius_m, ring, None),
                Shape::Polyline(pts) => r.canvas.elevation_ring(pts, &es, self.radius_m, ring, None),
                Shape::Region(poly) => {
                    let mut outline = poly.clone();
                    outline.push(poly[0]);
                    r.canvas
                        .elevation_ring(&outline, &es[..1], self.radius_m, ring, Some(poly))
                }
            }
        }
        Ok(())
    }
}

/// Freeze brush: samples within `radius_m` of `center` keep the procedural height (hard).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Freeze {
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Radius, metres.
    pub radius_m: f64,
}

impl Tool for Freeze {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        c.position("/center", self.center)?;
        c.radius("/radius_m", self.radius_m)
    }

    fn reads_solution(&self) -> bool {
        true
    }

    fn keeps_solution(&self) -> bool {
        true
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let (canvas, current) = r.solved()?;
        canvas.freeze(self.center, self.radius_m, current);
        Ok(())
    }
}
