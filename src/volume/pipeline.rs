//! The volume-region pipeline of Becher §4: voxelization, diffusions, surface propagation.
