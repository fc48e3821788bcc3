//! Authored regions (issue 4): rectangles of the world edited in the gradient domain after Guérin,
//! Peytavie, Masnou, Digne, Sauvage, Gain and Galin, *Gradient Terrain Authoring* (Computer
//! Graphics Forum 41(2), 2022; `../shared/papers/guerin-gradient-terrain-authoring.txt`): the heights are the Poisson reconstruction `Δh = ∇·g` of an edited gradient field `g`, with
//! hard elevation constraints as Dirichlet samples ([`crate::terrain::poisson`]).
//!
//! Pure code: no tokio, axum or wgpu.
//!
//! # The displacement formulation (how a region meets the infinite world)
//!
//! A region's grid is a square of `samples × samples` (`2^k + 1`) anchored at the west-north
//! corner of its `bbox`, spacing `δ = max(width, depth) / (samples − 1)`. Its starting gradient
//! field is the procedural world's own ([`grid::Procedural`] samples it), and its border takes the
//! procedural heights as Dirichlet values. Rather than reconstructing heights `h` and replacing the
//! world's, the region solves for the displacement `d = h − h_proc`:
//!
//! `Δd = ∇·(g − ∇h_proc)`, `d = 0` on the border and outside the `bbox`, `d = e − h_proc` where an
//! elevation constraint imposes `e`.
//!
//! This is the same linear system (the Laplacian is linear), but an unedited region gives `d = 0`
//! exactly, and a tile adds `d`, bilinearly interpolated at each vertex, to its own procedural
//! heights at its own LOD ([`Displacement::add_to_lattice`]). Hence:
//!
//! - the region's edge meets the procedural world with no step: `d` is 0 on the border and
//!   continuous inside;
//! - neighbouring tiles share edges bit for bit: a vertex's displacement is a pure function of its
//!   world position and the region;
//! - coarser LODs keep their fewer octaves and still show the edit.
//!
//! Tools ([`Op`]) are rasterised on the grid in document order ([`region::solve_region`]): each
//! either adds to the target gradient of `d` (soft: the least-squares target) or fixes samples
//! (hard). A hard constraint beats any conflicting soft one because fixed samples are not
//! unknowns.
//!
//! # Tools by module
//!
//! - [`tools`]: every tool's parameters, validation, cost and rasterisation behind the [`Tool`]
//!   trait, one module per family, registered in [`Op`]; how to add a tool is in its docs. The
//!   modules below are the algorithms the tools call.
//! - [`spec`]: the region element (bbox, samples, operations), parsed, validated and costed.
//! - [`region`]: the solve (the [`region::Raster`] the tools work on) and the displacement.
//! - [`raster`]: the canvas, and elevation, freeze, amplify, crest and noise (§4.1, §4.4).
//! - [`landform`]: the rest of Fig. 4 (cliff, river, free crest, ravine, fault) and the Fig. 8
//!   composites (mountain range, mesa).
//! - [`tensor`]: §4.3 tensor maps (directional, skeleton, stroke-aligned).
//! - [`paste`]: §4.1 copy-paste of gradients (from this world, another seed or an inline PNG16
//!   heightmap), rotated, scaled and warped.
//! - [`erosion`]: §4.4 an elevation-domain brush (thermal erosion) keeping the Dirichlet samples.
//! - [`hydraulic`]: §4.4 the hydraulic erosion brush (deterministic droplets) keeping them too.
//! - [`fitting`]: §5.1 fitting to contour lines and to ridge/river networks, and the §3
//!   two-pass regularisation.
//! - [`spec_tools`]: the parameter types and limits of the fitting and import tools.
//! - [`stats`]: readouts (elevation, slope) over a point, polyline or rectangle.
//! - [`sketch`]: issue 17's coarse sketch, a PNG16 base height field replacing the large-scale
//!   elevation over the bbox.
//! - [`basis`]: Schneider §3 basis functions, tileable greyscale images replacing the noise
//!   lattice in the relief texture below their period, composed by convex weights.
//! - [`exchange`]: PNG16 heightmaps and the §3 two-channel gradient-map encoding, in and out.

pub mod basis;
pub mod erosion;
pub mod exchange;
pub mod fitting;
pub mod grid;
pub mod hydraulic;
pub mod landform;
pub mod nearest;
pub mod paste;
pub mod raster;
pub mod region;
pub mod sketch;
pub mod spec;
pub mod spec_tools;
pub mod stats;
pub mod tensor;
pub mod tools;

pub use grid::{Procedural, RegionGrid};
pub use region::{solve_region, solve_region_on, Displacement, RegionError};
pub use spec::{RegionSpec, MAX_OPS, MAX_POINTS, SAMPLE_CHOICES};
pub use tools::{Op, Shape, Tool};
