//! The compute device: one thread owns the wgpu `Device` and `Queue` ([`device`]); stages send
//! jobs over a channel and await the results through a [`GpuHandle`].
//!
//! The kernels are WGSL twins of the CPU reference in [`crate::terrain`]:
//!
//! - `shaders/common.wgsl` mirrors the integer hashes, the Gaussian lattice noise and the warped
//!   multifractal of Schneider, Boldte & Westermann, *Real-Time Editing, Synthesis, and Rendering
//!   of Infinite Landscapes on GPUs* (VMV 2006; Eq. 1 and §2.2), and Algorithms 1 and 2 of the
//!   extended Voronoi biome map of Choroś & Topolski (*Procedural generation of biomes*);
//! - `shaders/tile.wgsl` runs [`crate::terrain::tile::field`] in four dispatches: block corners of
//!   the biome grid's corner shortcut, biome ids, horizontal blur, vertical blur plus heights;
//! - `shaders/earth.wgsl` ([`earth`]) computes the heights of an `earth-1` world
//!   ([`crate::terrain::earth::field`]) from its macro octaves and the LOD's layers, one
//!   invocation per sample, with the same rounding barriers and correctly rounded `/` and `sqrt`;
//!   its biome weights (the climate) are computed on the CPU, and so are the per-sample erosion
//!   and roughness the kernel reads. Where the world has rivers and the LOD carves them,
//!   `shaders/rivers.wgsl` then carves the heights in place in a second pass
//!   ([`crate::terrain::earth::carve`]), from the river job (pieces and bins) the CPU builds and
//!   uploads. [`GpuHandle::field`] routes each world to its kernels.
//!
//! All transcendental constants (octave frequencies and amplitudes, warp constants, scales, blur
//! taps) are taken from [`crate::terrain::WorldPlan`] and uploaded ([`layout`]), as are the river
//! pieces of the CPU's river job (channel widths and depths, valley widths); the GPU evaluates no
//! `pow`, `exp` or `log`.
//!
//! # Exactness and tolerance
//!
//! The kernels are built to reproduce the CPU's bits, not merely to come close:
//!
//! - the integer parts (hashes, lattice indices, block decisions, one-hot tests) are identical by
//!   construction (wrapping `u32` arithmetic, `i32` lattice indices that fit within
//!   `plan::WORLD_LIMIT_CELLS`, `f32(g) · spacing` positions exact below 2²⁴);
//! - WGSL lets a compiler contract `a * b + c` into a fused multiply-add and rewrite
//!   `a + (b − a) · t` as a lerp; the CPU code does neither (Rust never contracts). Every product
//!   that feeds an addition therefore passes a rounding barrier, `rn` in `common.wgsl`: an xor
//!   with a runtime zero, which no compiler can see through;
//! - WGSL's `/` and `sqrt` need only be accurate to 2.5 ULP; `div_rn` (blur normalisation,
//!   latitude gradient, the earth kernel's and the river carve's quotients) corrects the quotient
//!   to the correctly rounded one with exact residuals from Dekker's product (WGSL's `fma` need
//!   not be fused, and on lavapipe it is not). The warp normalisation needs no hardware square
//!   root: it mirrors the CPU's `inv_sqrt` (integer first guess, Newton steps in rounded
//!   multiplies). `sqrt_rn` corrects the hardware square root in the same way as `div_rn`, for
//!   the earth kernel (belts, ridges, slopes) and the river carve (distances to the river pieces).
//!
//! So on any device with IEEE-754 `+`, `-`, `*` (which WGSL requires) the GPU field equals the
//! CPU field bit for bit; `tests/gpu_twin.rs` observes exactly that on lavapipe, on tiles at LODs
//! 0–8 up to the corner of the supported world, and `tests/gpu_earth.rs` for the `earth-1`
//! heights and their river carve. Bit-exactness matters here because the §2.2 warp
//! feeds the accumulated height back into the sample position: a one-ULP difference can grow
//! through the octaves, and the GPU and CPU paths serve neighbouring tiles (after a fallback, or
//! for snap strips), which must meet without steps. The tests allow a little slack on top — weights
//! within 2⁻²³, heights within 1 mm + 2⁻²⁰·|h| (1 cm + 2⁻¹⁸·|h| for `earth-1`, whose gully
//! layers amplify a last-bit difference more), at most two differing biome ids — for a device
//! that flushes subnormals or rounds an intermediate differently; a systematic deviation would
//! exceed it.

pub mod device;
pub mod earth;
pub mod jobs;
mod kit;
pub mod layout;
pub mod poisson;
pub mod ptex;
mod scopes;
pub mod tile;
pub mod volume;
pub mod volume_bitangent;
pub mod volume_mesh;

pub use device::{
    adapter_info_of, adapter_rank, open, open_with_timeout, request_device, AdapterInfo,
    BackendChoice, DeviceContext, GpuHandle,
};
pub use earth::{earth_field_on_device, earth_shader_source, rivers_shader_source, EarthKernels};
pub use tile::{
    field_on_device, field_params, tile_shader_source, TileKernels, DEFAULT_JOB_TIMEOUT,
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::FieldJob;
    use wgpu::{Backend, DeviceType};

    #[test]
    fn wgsl_constants_equal_the_rust_constants() {
        let line = tile::COMMON_WGSL
            .lines()
            .find(|l| l.starts_with("const INV_BYTE_SUM_STD: f32 = "))
            .expect("INV_BYTE_SUM_STD in common.wgsl");
        let lit = line
            .trim_start_matches("const INV_BYTE_SUM_STD: f32 = ")
            .trim_end_matches(';');
        // WGSL reads the literal as an abstract float (f64) and converts it to f32.
        let value = lit.parse::<f64>().expect("a float literal") as f32;
        assert_eq!(
            value.to_bits(),
            crate::terrain::noise::INV_BYTE_SUM_STD.to_bits()
        );
        assert!(tile::COMMON_WGSL.contains(&format!("0x{:08x}u", crate::terrain::hash::PRIME_X)));
        assert!(tile::COMMON_WGSL.contains(&format!("0x{:08x}u", crate::terrain::hash::PRIME_Z)));
        assert!(tile::COMMON_WGSL.contains(&format!(
            "const RANGE: i32 = {};",
            crate::terrain::biome::RANGE
        )));
        assert_eq!(crate::terrain::biome::BLOCK, 8, "tile.wgsl shifts by 3");
        for (name, v) in [
            ("DECAL_FACING_FROM", crate::ptex::decal::FACING_FROM),
            ("DECAL_FACING_FULL", crate::ptex::decal::FACING_FULL),
        ] {
            assert!(
                ptex::PTEX_WGSL.contains(&format!("const {name}: f32 = {v:?};")),
                "{name} = {v:?} in ptex.wgsl"
            );
        }
        assert_eq!(
            crate::terrain::world::MAX_BIOMES,
            8,
            "tile.wgsl holds 8 channels"
        );
    }

    #[test]
    fn adapter_choice() {
        use BackendChoice::*;
        assert_eq!(
            adapter_rank(Cpu, DeviceType::DiscreteGpu, Backend::Vulkan),
            None
        );
        assert_eq!(
            adapter_rank(Auto, DeviceType::Cpu, Backend::Vulkan),
            None,
            "auto skips lavapipe"
        );
        assert_eq!(adapter_rank(Auto, DeviceType::Other, Backend::Gl), None);
        assert!(adapter_rank(Auto, DeviceType::IntegratedGpu, Backend::Vulkan).is_some());
        let lavapipe =
            adapter_rank(Gpu, DeviceType::Cpu, Backend::Vulkan).expect("gpu takes software");
        let llvmpipe = adapter_rank(Gpu, DeviceType::Cpu, Backend::Gl).expect("gpu takes software");
        let igpu = adapter_rank(Gpu, DeviceType::IntegratedGpu, Backend::Gl).expect("hardware");
        assert!(igpu < lavapipe && lavapipe < llvmpipe);
    }

    #[test]
    fn params_cover_the_blur_margin_and_the_blocks() {
        let plan = crate::terrain::WorldPlan::new(3, crate::terrain::WorldParams::classic())
            .expect("plan");
        let p = field_params(&plan, FieldJob::new(0, -65, 63, 67, 67)).expect("params");
        let r = (plan.lods[0].kernel.len() / 2) as i32;
        assert_eq!(
            (p.bgx0, p.bgz0, p.bw, p.bh),
            (-65 - r, 63 - r, 67 + 2 * r as u32, 67 + 2 * r as u32)
        );
        assert_eq!(p.bx0, (-65 - r).div_euclid(8));
        assert_eq!(
            p.cw as i32,
            (p.bgx0 + p.bw as i32 - 1).div_euclid(8) - p.bx0 + 2
        );
        assert!(field_params(&plan, FieldJob::new(0, i64::from(i32::MAX), 0, 67, 67)).is_err());
        assert!(field_params(&plan, FieldJob::new(13, 0, 0, 67, 67)).is_err());
        assert!(field_params(&plan, FieldJob::new(0, 0, 0, 0, 67)).is_err());
    }
}
