//! WGSL twins of the volume stages (`shaders/volume*.wgsl`).
