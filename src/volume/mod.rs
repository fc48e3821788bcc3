//! Volume terrain (issue 5): Becher et al., *Feature-based volumetric terrain generation*.
//!
//! [`mesh`] turns a signed distance grid into a surface-nets quad mesh with quad classes and Ptex
//! adjacency; [`chunk`] meshes 32³-cell chunks of the world's solid for the chunk routes;
//! [`pipeline`] builds a volume region's fields from feature curves.

pub mod chunk;
pub mod element;
pub mod mesh;
pub mod mesh_import;
pub mod offload;
pub mod pipeline;
