//! WGSL twin of the multigrid Poisson solver (`shaders/poisson.wgsl`).
