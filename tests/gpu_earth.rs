//! The WGSL twin of the `earth-1` height field (`shaders/earth.wgsl`, `strata::gpu::EarthKernels`)
//! against the CPU reference `terrain::earth::field`, on a software adapter (lavapipe or
//! llvmpipe). These tests REQUIRE an adapter: without one they fail with instructions, they never
//! skip.
//!
//! The biome weights are computed on the CPU on both paths, so they must be identical, bit for
//! bit. The heights: see [`height_tolerance`].

use std::sync::Arc;
use strata::compute::Compute;
use strata::gpu::{request_device, BackendChoice, EarthKernels};
use strata::terrain::tile::{field, FieldJob};
use strata::terrain::{TileKey, WorldParams, WorldPlan};

const SEED: u64 = 42;

fn plan() -> WorldPlan {
    let params = WorldParams::default();
    assert!(params.earth.is_some(), "the default world is earth-1");
    WorldPlan::new(SEED, params).expect("default world")
}

fn software_device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    match pollster::block_on(request_device(BackendChoice::Gpu)) {
        Ok(Some(d)) => d,
        Ok(None) => panic!("request_device(Gpu) returned no device"),
        Err(e) => panic!(
            "gpu_earth needs a wgpu adapter; install Mesa's lavapipe (apt-get install mesa-vulkan-drivers \
             libvulkan1) and set XDG_RUNTIME_DIR. Error: {e:#}"
        ),
    }
}

/// Slack on `|Δh|`: 1 cm plus 2⁻¹⁸ of the height (≈ 32 ULP; about 2 cm at 4 km).
///
/// The twin mirrors `kernel::heights` operation for operation: products pass the rounding barrier
/// `rn` (no fused multiply-add), `/` and `sqrt` are corrected to the correctly rounded result
/// (`div_rn`, `sqrt_rn`), `inv_sqrt` and `sincos_turns` are the CPU's own integer-and-multiply
/// sequences, and the constants are generated from the Rust ones. On lavapipe the heights are
/// then bit-identical: measured max |Δh| = 0 m on every job below (the test prints the counts).
///
/// The slack is deliberately small, as in `tests/gpu_twin.rs`. The chain amplifies last-bit
/// differences: the slope-dependent damping `1 / (1 + k_d |G|²)`, the gully direction `G / |G|`,
/// the gully fade-in and the normalised phasor sum of the gully stripes (which turns sharply
/// where the four phasors nearly cancel). On the CPU, one ULP of the sample positions moves the
/// heights of the LOD 6 mountain tile by up to ≈ 1.7 m (≈ 0.12 m without the gully layers;
/// `one_ulp_sensitivity` prints both). So a device that is not bit-exact (flushed subnormals, an
/// intermediate rounded differently) can fail this bound near such points, and should: the GPU
/// and CPU paths serve neighbouring tiles, which must meet without steps. A systematic error (a
/// wrong constant, a missed term, a layer out of order) is metres everywhere.
fn height_tolerance(h: f32) -> f32 {
    1e-2 + h.abs() / 262_144.0
}

struct Report {
    max_dh: f32,
    differing: usize,
    min_h: f32,
    max_h: f32,
}

fn compare(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    kernels: &EarthKernels,
    plan: &WorldPlan,
    key: TileKey,
) -> Report {
    let job = FieldJob::with_margin(key);
    let t = std::time::Instant::now();
    let cpu = field(plan, job);
    let cpu_ms = t.elapsed().as_secs_f64() * 1e3;
    let t = std::time::Instant::now();
    let gpu = kernels
        .field(device, queue, plan, job, None)
        .unwrap_or_else(|e| panic!("GPU earth field of {key:?}: {e:#}"));
    let gpu_ms = t.elapsed().as_secs_f64() * 1e3;
    assert_eq!((gpu.w, gpu.h), (cpu.w, cpu.h));
    assert_eq!(gpu.heights.len(), cpu.heights.len());
    // The weights are the CPU's climate on both paths.
    assert_eq!(gpu.weights.len(), cpu.weights.len());
    for (i, (c, g)) in cpu.weights.iter().zip(&gpu.weights).enumerate() {
        assert_eq!(
            c.to_bits(),
            g.to_bits(),
            "weight {i} of {key:?}: cpu {c} gpu {g}"
        );
    }
    let spacing = plan.lods[key.lod as usize].spacing_m;
    let mut rep = Report {
        max_dh: 0.0,
        differing: 0,
        min_h: f32::INFINITY,
        max_h: f32::NEG_INFINITY,
    };
    for (v, (&c, &g)) in cpu.heights.iter().zip(&gpu.heights).enumerate() {
        let (i, j) = (v % job.w, v / job.w);
        let (x, z) = (
            (job.gx0 + i as i64) as f32 * spacing,
            (job.gz0 + j as i64) as f32 * spacing,
        );
        let (dh, tol) = ((c - g).abs(), height_tolerance(c));
        assert!(
            dh <= tol,
            "height of {key:?} at vertex ({i}, {j}) = ({x} m, {z} m): cpu {c} gpu {g} (|Δ| {dh} > {tol})"
        );
        rep.max_dh = rep.max_dh.max(dh);
        rep.differing += usize::from(c.to_bits() != g.to_bits());
        rep.min_h = rep.min_h.min(c);
        rep.max_h = rep.max_h.max(c);
    }
    println!(
        "{key:?} ({} m spacing, x0 {:.0} m, z0 {:.0} m): heights {:.1}..{:.1} m; max |Δh| {:.3e} m; \
         not bit-identical: {} of {}; {} layers; CPU {cpu_ms:.1} ms, GPU {gpu_ms:.1} ms",
        spacing,
        job.gx0 as f32 * spacing,
        job.gz0 as f32 * spacing,
        rep.min_h,
        rep.max_h,
        rep.max_dh,
        rep.differing,
        cpu.heights.len(),
        plan.earth.as_ref().expect("earth").lods[key.lod as usize]
            .layers
            .len(),
    );
    rep
}

#[test]
fn gpu_earth_field_matches_cpu() {
    let plan = plan();
    let (adapter, device, queue) = software_device();
    let info = adapter.get_info();
    println!(
        "adapter: {} ({:?}, {:?})",
        info.name, info.backend, info.device_type
    );
    let kernels = EarthKernels::new(&device).expect("earth kernel compiles");
    let key = |lod, x, z| TileKey { lod, x, z };
    let cases = [
        // LOD 0 (1 m, tiles of 64 m): the origin, negative coordinates, and x ≈ 600 km.
        key(0, 0, 0),
        key(0, -3, -7),
        key(0, 9375, -40),
        // LOD 3 (8 m, 512 m tiles).
        key(3, -40, 25),
        // LOD 6 (64 m, 4 096 m tiles): the mountain belt around x = 110 km, z = 0, and x ≈ −600 km.
        key(6, 26, 0),
        key(6, 26, -1),
        key(6, -147, 12),
        // LOD 9 (512 m, 32 km tiles): x ≈ 590 km, and around the origin.
        key(9, 18, -3),
        key(9, -1, -1),
        // LOD 12 (4 096 m, 262 km tiles): continents.
        key(12, 0, 0),
        key(12, -1, -1),
        key(12, 2, -3),
    ];
    let (mut max_dh, mut differing, mut samples) = (0.0f32, 0, 0);
    let mut mountain_relief = 0.0f32;
    for k in cases {
        let rep = compare(&device, &queue, &kernels, &plan, k);
        max_dh = max_dh.max(rep.max_dh);
        differing += rep.differing;
        samples += 67 * 67;
        if k.lod == 6 && k.x == 26 {
            mountain_relief = mountain_relief.max(rep.max_h - rep.min_h);
        }
    }
    println!(
        "overall: max |Δh| {max_dh:.3e} m, {differing} of {samples} heights not bit-identical"
    );
    assert!(
        mountain_relief > 500.0,
        "the LOD 6 tiles at x = 110 km should be mountains ({mountain_relief} m of relief)"
    );
}

/// For scale: how far the CPU's own heights move when x moves by one ULP, on the mountain tile.
#[test]
fn one_ulp_sensitivity() {
    let plan = plan();
    let key = TileKey {
        lod: 6,
        x: 26,
        z: 0,
    };
    let job = FieldJob::with_margin(key);
    let spacing = plan.lods[6].spacing_m;
    let earth = plan.earth.as_ref().expect("earth");
    let worst = |earth: &strata::terrain::earth::EarthPlan| {
        let base = strata::terrain::earth::field(earth, spacing, job);
        // The next f32 spacing moves every sample position by about one ULP (relative 2⁻²³).
        let next = f32::from_bits(spacing.to_bits() + 1);
        let moved = strata::terrain::earth::field(earth, next, job);
        base.heights
            .iter()
            .zip(&moved.heights)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0f32, f32::max)
    };
    let mut dry = earth.clone();
    dry.erosion.iter_mut().for_each(|e| *e = 0.0);
    println!(
        "one ULP of the sample positions moves the CPU heights of {key:?} by up to {:.3e} m \
         ({:.3e} m without the gully layers)",
        worst(earth),
        worst(&dry)
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn compute_routes_earth_worlds_to_the_earth_kernels() {
    let plan = Arc::new(plan());
    let handle = match strata::gpu::open(BackendChoice::Gpu).await {
        Ok(Some(h)) => h,
        Ok(None) => panic!("open(Gpu) returned no device"),
        Err(e) => panic!("gpu_earth needs a wgpu adapter (lavapipe): {e:#}"),
    };
    let job = FieldJob::with_margin(TileKey {
        lod: 6,
        x: 26,
        z: 0,
    });
    let cpu = field(&plan, job);
    // The handle runs the job on the earth kernels (a classic tile kernel would refuse it).
    let direct = handle
        .field(plan.clone(), job)
        .await
        .expect("earth field via the device task");
    let compute = Compute::with_gpu(handle.clone());
    let via_compute = compute.field(plan.clone(), job).await;
    assert!(
        !handle.is_lost(),
        "the earth job must not fail on the device"
    );
    assert_eq!(compute.info().backend, "gpu");
    for f in [&direct, &via_compute] {
        assert_eq!(f.weights, cpu.weights);
        for (c, g) in cpu.heights.iter().zip(&f.heights) {
            assert!((c - g).abs() <= height_tolerance(*c), "cpu {c} gpu {g}");
        }
    }
    // Out-of-range jobs are refused before they reach the device, without marking it lost.
    assert!(handle
        .field(
            plan.clone(),
            FieldJob::new(6, i64::from(i32::MAX), 0, 67, 67)
        )
        .await
        .is_err());
    assert!(!handle.is_lost());
}
