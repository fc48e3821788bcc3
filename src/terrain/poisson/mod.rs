//! Poisson reconstruction of heights from a gradient field by geometric multigrid (issue 4).
//!
//! Guérin et al., *Gradient Terrain Authoring*: `Δh = ∇·g` with Dirichlet constraints.
