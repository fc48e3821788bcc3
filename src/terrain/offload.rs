//! Offload hooks: how the pure modules let a caller run a kernel's WGSL twin on a device.
//!
//! The terrain, authoring and volume code computes on the CPU and never imports a device (see
//! ARCHITECTURE.md's layers). Where a heavy kernel has a twin, its caller passes an offload: a
//! value whose methods may compute that kernel elsewhere and answer `Some`, or answer `None`, on
//! which the CPU reference runs. [`CpuOnly`] answers `None` to everything;
//! `compute::Offload` sends the work to the device task. The offload runs the kernel on the same
//! inputs the CPU would, so a `None` at any point (no device, a lost one, a grid beyond its
//! limits) changes the result only within the twin's stated tolerance.
//!
//! This module holds the terrain's hook ([`PoissonOffload`], for the multigrid cycles of an
//! authored region's solve); the volume module's `offload` holds the volume pipeline's.

use super::poisson::level::Level;
use super::poisson::SolveOptions;

/// The offload that runs nothing: every kernel on the CPU.
#[derive(Clone, Copy, Debug, Default)]
pub struct CpuOnly;

/// Where the finest-level cycles of a Poisson solve may run (the twin in
/// `shaders/poisson.wgsl`), used by [`super::poisson::Solver::solve_on`].
pub trait PoissonOffload: Sync {
    /// Whether [`Self::poisson_cycles`] may answer at all: without a device the solver takes its
    /// CPU path untouched, bit for bit.
    fn has_device(&self) -> bool {
        false
    }

    /// `cycles` finest-level cycles (`options.cycle`, plain, no Krylov acceleration) from the
    /// state of `levels`, a loaded solver's hierarchy: the finest unknowns as the two colour
    /// arrays of `levels[0].split`, in `f32`; `None` to leave the solve to the CPU.
    fn poisson_cycles(
        &self,
        levels: &[Level],
        cycles: usize,
        options: &SolveOptions,
    ) -> Option<[Vec<f32>; 2]> {
        let _ = (levels, cycles, options);
        None
    }
}

impl PoissonOffload for CpuOnly {}
