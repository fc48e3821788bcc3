//! Parameter types and validation of the fitting, regularisation, hydraulic-erosion and import
//! tools (the newer half of [`super::spec::Op`]): contour lines, ridge/river networks, and the
//! heightmap source of a copy-paste.
//!
//! Units: positions in world metres (`[x, z]`), elevations and widths in metres, slopes in
//! degrees. Every limit is a constant here.

use super::spec::{err, finite_in, SpecError, MAX_ELEVATION_M, MAX_POINTS};
use serde::{Deserialize, Serialize};

/// Largest side of an inline heightmap, pixels (its decoded samples stay below 17 MB).
pub const MAX_HEIGHTMAP_SIDE: usize = 2049;
/// Most points of all the lines (or edges, nodes included) of one fitting operation together.
pub const MAX_FIT_POINTS: usize = 8192;
/// Most contour lines of one `contours` operation.
pub const MAX_CONTOURS: usize = 256;
/// Most nodes of one `network` operation.
pub const MAX_NETWORK_NODES: usize = 1024;
/// Most edges of one `network` operation.
pub const MAX_NETWORK_EDGES: usize = 1024;
/// Most droplets of one hydraulic-erosion brush.
pub const MAX_DROPLETS: u32 = 200_000;
/// Most steps of one droplet.
pub const MAX_DROPLET_STEPS: u32 = 512;
/// The work of a region's solve, in cell steps (about 10 ns of one core each: a thermal-erosion
/// step of one grid sample, measured at 1025² samples, release build, on 2 shared cores): each
/// reconstruction counts [`SOLVE_CELL_STEPS`] per grid sample (the final one, and one before
/// every operation that reads the solved heights: `freeze`, `regularize` and the erosion
/// brushes), each thermal `erosion` iteration one per sample, each hydraulic-erosion droplet
/// step [`DROPLET_STEP_CELLS`]. At most this much, about 0.7 s of one core, so with the 0.45 s
/// of sampling a region's procedural base (bounded by `grid::MAX_LATTICE_SAMPLES`) the first
/// tile over the heaviest region a scene may accept costs about 1.1 s of one core, within the
/// 2 s a request may take (`strata bench abuse`). Before it, thermal erosion (2²⁸ cell steps)
/// and hydraulic erosion (2²² droplet steps) had budgets of their own, solves had none, and a
/// region of 2049² samples could cost 4.5 s with both brushes, and more with many brushes.
pub const MAX_REGION_CELL_STEPS: u64 = 1 << 26;
/// Cell steps a reconstruction costs per grid sample: a cold solve took 105–130 ns a sample at
/// 1025² and 193 ns at 2049², a warm one after a brush 65–85 ns at 1025².
pub const SOLVE_CELL_STEPS: u64 = 16;
/// Cell steps one droplet step counts for: a droplet step took 112–171 ns (1025² and 2049²
/// samples).
pub const DROPLET_STEP_CELLS: u64 = 16;
/// Largest `samples` a region may have when a scene is accepted: its solve at 2049² alone took
/// 0.8 s of one core beside the 0.45 s of its procedural base. Stored scenes keep their 2049²
/// regions (see [`super::spec::RegionSpec::check_cost`]).
pub const MAX_ACCEPTED_SAMPLES: usize = 1025;
/// Longest inline heightmap (`png_base64`), characters: 512 KiB of base64 (384 KiB of PNG), so
/// a scene with one stays well below the store's 1 MiB scene limit.
pub const MAX_HEIGHTMAP_BASE64: usize = 512 * 1024;

/// One contour line: a polyline at one elevation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Contour {
    /// The line, `[x, z]` metres (repeat the first point to close it).
    pub points: Vec<[f64; 2]>,
    /// Its elevation, metres.
    pub elevation_m: f64,
}

/// A node of a ridge/river network.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NetworkNode {
    /// Position `[x, z]`, metres.
    pub at: [f64; 2],
    /// Elevation, metres; when absent, derived along an edge with a `grade_deg` from a node
    /// that has one ([`resolve_elevations`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub elevation_m: Option<f64>,
}

/// What an edge of a network is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeKind {
    /// A crest line: flanks fall away from it.
    Ridge,
    /// A river flowing from `from` to `to`: banks rise away from it, and it never rises.
    River,
}

/// An edge of a ridge/river network: a polyline from one node to another.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NetworkEdge {
    /// Index of the start node (for a river: upstream).
    pub from: usize,
    /// Index of the end node (for a river: downstream).
    pub to: usize,
    /// Ridge or river.
    pub kind: EdgeKind,
    /// Intermediate vertices `[x, z]`, metres, between the two nodes.
    #[serde(default)]
    pub points: Vec<[f64; 2]>,
    /// Reach of the flanks (ridge) or banks (river) on each side, metres (0: none).
    #[serde(default)]
    pub width_m: f64,
    /// Slope of the flanks or banks, degrees (`0..=89`).
    #[serde(default)]
    pub slope_deg: f64,
    /// Slope along the edge from `from` to `to`, degrees (`−89..=89`, negative descending):
    /// gives an end node without an elevation one (`e_to = e_from + length·tan(grade)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grade_deg: Option<f64>,
}

/// Length of an edge's polyline (node, vertices, node), metres.
pub fn edge_length(nodes: &[NetworkNode], e: &NetworkEdge) -> f64 {
    let pts: Vec<[f64; 2]> = std::iter::once(nodes[e.from].at)
        .chain(e.points.iter().copied())
        .chain(std::iter::once(nodes[e.to].at))
        .collect();
    pts.windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

/// Every node's elevation, metres: the given ones, and the missing ones derived along edges
/// with a `grade_deg` from a node that has one, sweeping the edges in document order until
/// nothing changes (deterministic; a grade between two nodes that both have elevations is not
/// used). Node and edge indices must be valid.
///
/// # Errors
/// The index of a node no graded edge reaches.
pub fn resolve_elevations(nodes: &[NetworkNode], edges: &[NetworkEdge]) -> Result<Vec<f64>, usize> {
    let mut known: Vec<Option<f64>> = nodes.iter().map(|n| n.elevation_m).collect();
    loop {
        let mut changed = false;
        for e in edges {
            let Some(grade) = e.grade_deg else {
                continue;
            };
            let rise = edge_length(nodes, e) * grade.to_radians().tan();
            match (known[e.from], known[e.to]) {
                (Some(a), None) => known[e.to] = Some(a + rise),
                (None, Some(b)) => known[e.from] = Some(b - rise),
                _ => continue,
            }
            changed = true;
        }
        if !changed {
            break;
        }
    }
    known.iter().enumerate().map(|(k, e)| e.ok_or(k)).collect()
}

/// A PNG16 heightmap carried inline in the scene (the source of a copy-paste).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Heightmap {
    /// A 16-bit greyscale PNG, base64 (standard alphabet, padded), at most
    /// [`MAX_HEIGHTMAP_BASE64`] characters.
    pub png_base64: String,
    /// Elevation of sample value 0, metres.
    pub lo_m: f64,
    /// Elevation of sample value 65535, metres.
    pub hi_m: f64,
    /// Distance between the image's pixels on the ground, metres.
    pub spacing_m: f64,
}

fn position(pointer: &str, p: [f64; 2]) -> Result<(), SpecError> {
    let big = crate::element::MAX_COORD_M;
    finite_in(format!("{pointer}/0"), p[0], -big, big)?;
    finite_in(format!("{pointer}/1"), p[1], -big, big)
}

fn polyline(pointer: &str, pts: &[[f64; 2]], min: usize) -> Result<(), SpecError> {
    if pts.len() < min || pts.len() > MAX_POINTS {
        return Err(err(pointer, format!("needs {min} to {MAX_POINTS} points")));
    }
    for (i, q) in pts.iter().enumerate() {
        position(&format!("{pointer}/{i}"), *q)?;
    }
    Ok(())
}

/// Validates a `contours` operation at `at` (`/ops/3`).
pub fn validate_contours(at: &str, lines: &[Contour], detail: f64) -> Result<(), SpecError> {
    if lines.is_empty() || lines.len() > MAX_CONTOURS {
        return Err(err(
            format!("{at}/lines"),
            format!("needs 1 to {MAX_CONTOURS} lines"),
        ));
    }
    let total: usize = lines.iter().map(|c| c.points.len()).sum();
    if total > MAX_FIT_POINTS {
        return Err(err(
            format!("{at}/lines"),
            format!("at most {MAX_FIT_POINTS} points in all, got {total}"),
        ));
    }
    for (k, c) in lines.iter().enumerate() {
        polyline(&format!("{at}/lines/{k}/points"), &c.points, 1)?;
        finite_in(
            format!("{at}/lines/{k}/elevation_m"),
            c.elevation_m,
            -MAX_ELEVATION_M,
            MAX_ELEVATION_M,
        )?;
    }
    finite_in(format!("{at}/detail"), detail, 0.0, 1.0)
}

/// Validates a `network` operation at `at`: node indices exist, rivers never rise.
pub fn validate_network(
    at: &str,
    nodes: &[NetworkNode],
    edges: &[NetworkEdge],
    detail: f64,
) -> Result<(), SpecError> {
    if nodes.is_empty() || nodes.len() > MAX_NETWORK_NODES {
        return Err(err(
            format!("{at}/nodes"),
            format!("needs 1 to {MAX_NETWORK_NODES} nodes"),
        ));
    }
    for (k, n) in nodes.iter().enumerate() {
        position(&format!("{at}/nodes/{k}/at"), n.at)?;
        if let Some(e) = n.elevation_m {
            finite_in(
                format!("{at}/nodes/{k}/elevation_m"),
                e,
                -MAX_ELEVATION_M,
                MAX_ELEVATION_M,
            )?;
        }
    }
    if edges.is_empty() || edges.len() > MAX_NETWORK_EDGES {
        return Err(err(
            format!("{at}/edges"),
            format!("needs 1 to {MAX_NETWORK_EDGES} edges"),
        ));
    }
    let total: usize = edges.iter().map(|e| e.points.len() + 2).sum();
    if total > MAX_FIT_POINTS {
        return Err(err(
            format!("{at}/edges"),
            format!("at most {MAX_FIT_POINTS} points in all (2 nodes per edge), got {total}"),
        ));
    }
    for (k, e) in edges.iter().enumerate() {
        let p = format!("{at}/edges/{k}");
        for (name, i) in [("from", e.from), ("to", e.to)] {
            if i >= nodes.len() {
                return Err(err(
                    format!("{p}/{name}"),
                    format!("names node {i}; there are {}", nodes.len()),
                ));
            }
        }
        if e.from == e.to {
            return Err(err(format!("{p}/to"), "an edge joins two different nodes"));
        }
        polyline(&format!("{p}/points"), &e.points, 0)?;
        finite_in(format!("{p}/width_m"), e.width_m, 0.0, 1.0e6)?;
        finite_in(format!("{p}/slope_deg"), e.slope_deg, 0.0, 89.0)?;
        if let Some(g) = e.grade_deg {
            finite_in(format!("{p}/grade_deg"), g, -89.0, 89.0)?;
        }
    }
    let elevations = resolve_elevations(nodes, edges).map_err(|k| {
        err(
            format!("{at}/nodes/{k}/elevation_m"),
            "needs an elevation, or an edge with grade_deg from a node that has one",
        )
    })?;
    for (k, (e, n)) in elevations.iter().zip(nodes).enumerate() {
        if n.elevation_m.is_none() {
            finite_in(
                format!("{at}/nodes/{k}/elevation_m"),
                *e,
                -MAX_ELEVATION_M,
                MAX_ELEVATION_M,
            )
            .map_err(|e| err(e.pointer, format!("derived from the grades: {}", e.message)))?;
        }
    }
    for (k, e) in edges.iter().enumerate() {
        if e.kind == EdgeKind::River && elevations[e.to] > elevations[e.from] {
            return Err(err(
                format!("{at}/edges/{k}/to"),
                "a river flows from `from` to `to` and cannot rise: its end node is higher",
            ));
        }
    }
    finite_in(format!("{at}/detail"), detail, 0.0, 1.0)
}

/// Validates an inline heightmap at `at` (`/ops/2/heightmap`) by decoding it.
pub fn validate_heightmap(at: &str, h: &Heightmap) -> Result<(), SpecError> {
    finite_in(
        format!("{at}/lo_m"),
        h.lo_m,
        -MAX_ELEVATION_M,
        MAX_ELEVATION_M,
    )?;
    finite_in(
        format!("{at}/hi_m"),
        h.hi_m,
        -MAX_ELEVATION_M,
        MAX_ELEVATION_M,
    )?;
    finite_in(format!("{at}/spacing_m"), h.spacing_m, 1.0e-3, 1.0e4)?;
    h.decode()
        .map(|_| ())
        .map_err(|e| err(format!("{at}/png_base64"), e))
}

impl Heightmap {
    /// The image's heights, metres.
    ///
    /// # Errors
    /// Why the text is not a base64 16-bit greyscale PNG within the limits.
    pub fn decode(&self) -> Result<super::exchange::Image<Vec<f32>>, String> {
        use base64::Engine;
        if self.png_base64.len() > MAX_HEIGHTMAP_BASE64 {
            return Err(format!(
                "at most {MAX_HEIGHTMAP_BASE64} base64 characters, got {}",
                self.png_base64.len()
            ));
        }
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(self.png_base64.as_bytes())
            .map_err(|e| format!("not base64: {e}"))?;
        // A PNG compresses a flat image well: read the size from the header before decoding.
        if bytes.len() >= 24 && &bytes[12..16] == b"IHDR" {
            let w = u32::from_be_bytes([bytes[16], bytes[17], bytes[18], bytes[19]]);
            let h = u32::from_be_bytes([bytes[20], bytes[21], bytes[22], bytes[23]]);
            if w as usize > MAX_HEIGHTMAP_SIDE || h as usize > MAX_HEIGHTMAP_SIDE {
                return Err(format!(
                    "at most {MAX_HEIGHTMAP_SIDE} pixels a side, got {w}×{h}"
                ));
            }
        }
        let img = super::exchange::import_png16(&bytes, self.lo_m, self.hi_m)
            .map_err(|e| e.to_string())?;
        if img.width < 2 || img.height < 2 {
            return Err("the image needs at least 2×2 pixels".into());
        }
        Ok(img)
    }

    /// The ground extent of the image `[width, depth]`, metres (pixel centres at the corners).
    pub fn extent_m(&self, width: usize, height: usize) -> [f64; 2] {
        [
            (width - 1) as f64 * self.spacing_m,
            (height - 1) as f64 * self.spacing_m,
        ]
    }
}
