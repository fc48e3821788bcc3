//! §5.1 fitting to contour lines (`contours`) and to ridge/river networks (`network`), and the
//! §3 two-pass regularisation (`regularize`); rasterised by [`crate::authoring::fitting`], their
//! parameter types and limits in [`crate::authoring::spec_tools`].

use super::{Check, Raster, Tool};
use crate::authoring::region::RegionError;
use crate::authoring::spec::SpecError;
use crate::authoring::spec_tools::{
    resolve_elevations, validate_contours, validate_network, Contour, NetworkEdge, NetworkNode,
};
use serde::{Deserialize, Serialize};

/// Fitting to contour lines (§5.1, Fig. 10): every line becomes an elevation constraint at
/// its elevation (hard), and the target gradient of the heights over the whole region is
/// scaled by `detail` (0: the null Laplacian, a membrane between the contours; 1: keep the
/// relief, e.g. the procedural world's or a noise brush's, as detail).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Contours {
    /// The contour lines.
    pub lines: Vec<Contour>,
    /// Share of the prior relief kept, `0..=1`.
    #[serde(default)]
    pub detail: f64,
}

impl Tool for Contours {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        validate_contours(&c.at(""), &self.lines, self.detail)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        r.canvas.contours(&self.lines, self.detail);
        Ok(())
    }
}

/// Fitting to a ridge/river network (§5.1, Fig. 11): each edge is an elevation constraint
/// along its polyline (hard), the elevation linear in arc length between its nodes' (so
/// junctions agree), with flanks falling from ridges and banks rising from rivers at
/// `slope_deg` over `width_m` (soft); the rest of the region's target gradient is scaled by
/// `detail` as for contours.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Network {
    /// The nodes (junctions, sources, mouths, peaks).
    pub nodes: Vec<NetworkNode>,
    /// The edges between nodes.
    pub edges: Vec<NetworkEdge>,
    /// Share of the prior relief kept, `0..=1`.
    #[serde(default)]
    pub detail: f64,
}

impl Tool for Network {
    fn check(&self, c: &Check) -> Result<(), SpecError> {
        validate_network(&c.at(""), &self.nodes, &self.edges, self.detail)
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let elevations = resolve_elevations(&self.nodes, &self.edges)
            .map_err(|k| r.refuse(format!("node {k} has no elevation")))?;
        r.canvas
            .network(&self.nodes, &elevations, &self.edges, self.detail);
        Ok(())
    }
}

/// Two-pass regularisation (§3): the operations so far are reconstructed, the target
/// gradient becomes the gradient of that reconstruction (curl-free), and the interior
/// Dirichlet constraints are dropped (frozen samples stay), as they are now part of the
/// gradient field. Later operations edit that field.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Regularize {}

impl Tool for Regularize {
    fn check(&self, _: &Check) -> Result<(), SpecError> {
        Ok(())
    }

    fn reads_solution(&self) -> bool {
        true
    }

    fn apply(&self, r: &mut Raster) -> Result<(), RegionError> {
        let (canvas, current) = r.solved()?;
        canvas.regularize(current);
        Ok(())
    }
}
