//! The volume-region pipeline of Becher, Krone, Reina & Ertl, *Feature-based Volumetric Terrain
//! Generation and Decoration* (IEEE TVCG 2019; extended from I3D 2017), §3–4.5 and §5.
//!
//! A volume region is a box of the world sampled on a [`Grid`]. Its surface is generated from
//! modelling primitives — feature curves ([`curve`], §3.1), input meshes and the world's
//! heightfield as proxy geometry ([`proxy`], §3.2–3.3) — by pure stage functions on the fields
//! `N` (normals), `B` (bitangents), `S` (signed distance) and `R` (noise parameters `α`, `β`,
//! material and its confidence):
//!
//! 1. [`voxelize`] (§4.2): triangle–cell intersection, gather then average, the bitangent
//!    averaging rule, priority passes curves > meshes > heightfield with a dead zone in metres;
//! 2. [`diffuse`] (§4.3): anisotropic Perona–Malik diffusion of `N`, `k = 0.01`, Neumann borders,
//!    constrained samples fixed — solved by a cascadic multigrid plus a few anisotropic sweeps
//!    instead of thousands of Jacobi sweeps (§8);
//! 3. [`diffuse::harmonic_fill`] of `α`, `β` and [`propagate::propagate_material`] with
//!    confidence (§4.4);
//! 4. [`propagate::propagate_surface`] (§4.5): the min rule, each value set once;
//! 5. [`filter::gaussian`] on `S` (§4.5).
//!
//! [`region::generate`] runs them in order; [`region::regenerate`] warm-starts from a previous
//! result after an edit; [`brick`] solves a region larger than one grid in bricks that exchange
//! borders (§5.2). The product — `S` with material, confidence and noise parameters per sample,
//! in the shared grid layout (`x + nx·(y + ny·z)`, y up, `S < 0` inside) — is what
//! [`crate::volume::mesh`] meshes. The optional feature-curve expansion (§5.1) is [`expand`],
//! run first by [`region::generate`] when [`PipelineParams::expand`] is set.
//!
//! `shaders/volume_diffuse.wgsl` and `shaders/volume_propagate.wgsl` are the GPU twins of the
//! diffusion sweep and the surface propagation (`gpu::volume`).

// Grid code indexes several parallel arrays by one sample index; index loops read clearer here.
#![allow(clippy::needless_range_loop)]

pub mod brick;
pub mod curve;
pub mod diffuse;
pub mod edt;
pub mod expand;
pub mod filter;
pub mod grid;
pub mod multigrid;
pub mod propagate;
pub mod proxy;
pub mod region;
pub mod scenes;
pub mod voxelize;

pub use curve::{ConstraintPoint, CurveSample, FeatureCurve};
pub use grid::Grid;
pub use proxy::{Heightfield, InputMesh, ProxyTriangle};
pub use region::{
    generate, generate_on, regenerate, PipelineParams, RegionFields, Scene, StageTimes,
};

/// Errors of the pipeline's public functions.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum PipelineError {
    /// Bad input: the field and what is wrong with it.
    #[error("invalid {field}: {reason}")]
    Invalid {
        /// The offending field (a path such as `curves[2].constraints[0].b_l`).
        field: String,
        /// What is wrong.
        reason: String,
    },
    /// No seed primitive touches the region, so `S` has nothing to propagate from.
    #[error("no seed primitive (seed curve, mesh or heightfield) intersects the region")]
    NoSurface,
    /// The solve's cancellation flag was set ([`crate::terrain::cancel::Cancel`]).
    #[error("cancelled")]
    Cancelled,
}

impl PipelineError {
    pub(crate) fn invalid(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Self::Invalid {
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// The same error with `prefix.` prepended to the field name.
    pub(crate) fn within(self, prefix: &str) -> Self {
        match self {
            Self::Invalid { field, reason } => Self::Invalid {
                field: format!("{prefix}.{field}"),
                reason,
            },
            other => other,
        }
    }
}
