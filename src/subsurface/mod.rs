//! The layered subsurface: strata of mixed materials, mineral veins and caves, after
//! Santamaría-Ibirika, Cantero, Huerta, Salaberria and Lazcano, *Procedural approach to volumetric
//! terrain generation* (The Visual Computer, 2014; `../shared/papers/santamaria-procedural-volumetric-terrain.txt`).
//!
//! Pure, like [`crate::terrain`]: no tokio, axum or wgpu, and the only randomness is
//! [`crate::terrain::hash`] (purposes in [`plan::purpose`]) and the world-anchored lattice noise
//! [`crate::terrain::noise::lattice`].
//!
//! - [`config`] — §4.1's input: materials (name, id, colour, texture, the void/base/alone/vein/cave
//!   flags, area, depth/thickness/roughness ranges with an optimum, similarity, blend), affinity
//!   pairs (same layer, next layer, −1 incompatible) and the general parameters; validation names
//!   the offending field by JSON pointer; Table 2's configurations A0–B3 as presets. Schema:
//!   `api/subsurface.schema.json`.
//! - [`plan`] — §4.2: the layer stack from the base up (Eq. 1–2 over the materials not
//!   incompatible with the layer below, extra materials with probability 0.5, halving; main
//!   concentration 0.5–0.9, the others random, summing to 1), the layer properties (Eq. 3), the
//!   layer surfaces (Eq. 4), and veins and caves: bounding square of side `area/2…area` times the
//!   Eq. 3 relative area, the midpoint-displacement outline of depth 5 (Eq. 5), the circular
//!   height profile (Eq. 6) on top of the host layer.
//! - [`chunk`] — §3: chunks of `size × size` columns of stacked limits (at least the bottom and
//!   top voxel, at most `size`), a voxel's composition and flow by interpolation between the
//!   limits around it; §4.3's blend zones (blend × local thickness at a layer's bottom, mixing linearly from the
//!   layer below).
//! - [`openings`] — the caves that breach the ground or may come near it, from the elements'
//!   bounded data (the sites a stream streams volume chunks for).
//!
//! # Faithful, and where it deviates
//!
//! Faithful: the input data, Eq. 1–6, the probability-0.5-halving extra materials, the 0.5–0.9
//! main concentration, depth-5 outlines, blend zones, and the chunk/column/limit representation
//! with interpolation between limits.
//!
//! Deviations, and why:
//! - **Order independence instead of §4.2.4's online extension.** The paper extends a terrain plot
//!   by plot, drawing the number of veins and caves from the first plot's and interleaving them
//!   in a stack, so a plot depends on what was generated before. Here the layer stack is a
//!   function of the world seed alone (the whole world shares it: layers are infinite sheets
//!   whose surfaces come from world-anchored noise), and veins and caves live on world lattices
//!   (cell side = `vein_area` / `cave_area`): a cell holds an element with probability
//!   `vein_density` / `cave_density`, decided by hashing the seed and the cell, and its bounding
//!   square lies inside the cell. Any chunk is generated alone, in any order, on any thread, with
//!   identical bytes. Densities are therefore per lattice cell, and an element's host layer is
//!   drawn uniformly among all but the top layer rather than from the paper's stacking chance.
//! - Layer surfaces use strata's quintic-interpolated Gaussian lattice noise (the paper's Perlin
//!   noise) with `scale` as frequency; a layer whose surface would dip below the one underneath
//!   pinches out (zero thickness) — the paper does not say what happens there.
//! - Range-valued properties (thickness, roughness) are drawn per material from a triangular
//!   distribution on `[min, max]` peaked at the optimum before Eq. 3; the depth range filters the
//!   candidates of a layer by its relative depth (0 surface, 1 bottom), ignored when it leaves
//!   none. The paper names these ranges without saying how they are sampled.
//! - Eq. 5's constants come from the element's roughness `r`: `d₀ = 0.2·r` (unit square) and
//!   `SmoothConstant = 2 − r`; outline points are clamped to the bounding square. Eq. 6's distance
//!   is normalised by the distance from the square's centre to the outline, capped at 1.
//! - Limits sit at voxel centres and store a mixture of two palette entries (layer, blend pair,
//!   vein, cave or void); a column keeps the fewest limits that reproduce every voxel by
//!   interpolation (within 1e-5).
//! - Veins and caves override the layers they intrude into (the layers above are not pushed
//!   up), and caves override veins.
//! - Material flow (§4.2.1's last step): the unit tangent of the layer's surface (analytic
//!   gradient of Eq. 4 through the noise's derivative) whose horizontal direction turns about the
//!   y axis by `π·noise`; veins and caves take their host layer's flow (the paper regenerates it
//!   "using the same process"); the void has none. Limits store it, voxels interpolate it.
//! - In a world (the `strata` scene element, [`spec`], [`world`], [`carve`]) the stack is
//!   anchored to the ground: local height is `y − ground`, the top layer reaches the ground, the
//!   ground truncates the layers it cuts, and all at or above it is air. The paper's terrain has a
//!   flat top; a world's ground has relief, and without the anchor the noisy stack would leave
//!   void below the ground and rock above it. Caves carve the world's solid and open the height
//!   tiles where they reach the ground; veins do not carve.
//!
//! # The paper's evaluation criteria (§2.1), for this generator
//!
//! (Also in `docs/subsurface.md`.)
//!
//! Our own assessment against the paper's Table 1 requirements; the scores in brackets are on
//! the paper's scales, and only speed and memory are measured (`strata bench strata`).
//! - Innovation (2): stacks, compositions, veins and caves are probabilistic (Eq. 1–2); new
//!   seeds give unexpected combinations.
//! - Structure (2): layers couple to the layer below by affinity and similarity (Eq. 4), veins
//!   and caves to their host layer.
//! - Interest (2, not measured): veins and caves below the surface invite digging. Whether they
//!   do is a playtest question.
//! - Speed (2): online. A 5×5×5-chunk terrain takes a few milliseconds on one core, against the
//!   paper's 310–355 ms. Any chunk can be generated on demand and alone.
//! - Usability (2): the parameters are geological (depth, thickness, similarity, blend) and on
//!   0–1 scales. Two are technical and have no geological reading: the noise `scale` and the
//!   outline constants derived from roughness.
//! - Control (2): the designer sets materials, affinities and densities; edit-and-regenerate
//!   iteration (3): a `strata` element is part of the scene, edited by JSON Patch like any
//!   element, and the tiles, chunks, columns and queries of the new version follow at once.
//! - Ampliability (2): other terrains come from other configurations (Table 2 presets) without
//!   code changes.
//! - Scalability (1): `scale`, the thicknesses and the areas rescale the result; chunk size is
//!   a parameter, up to 64. There is no level of detail.
//! - Realism (2): plausible but not simulated. There is no erosion, tectonics or deposition.

pub mod carve;
pub mod chunk;
pub mod config;
pub mod openings;
pub mod plan;
pub mod spec;
pub mod world;

pub use chunk::{Chunk, ChunkKey, ElementMemo, Limit, Mix};
pub use config::{ConfigError, SubsurfaceConfig, PRESETS};
pub use plan::{Composition, Element, ElementKind, Layer, SubsurfacePlan};
pub use spec::{StrataError, StrataSpec};
pub use world::Geology;
