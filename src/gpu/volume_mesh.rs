//! WGSL twin of surface-nets meshing (`shaders/volume_mesh.wgsl`).
