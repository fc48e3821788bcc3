//! The WGSL twin of the `earth-1` height field (`shaders/earth.wgsl`, `strata::gpu::EarthKernels`)
//! against the CPU reference `terrain::earth::field`, on a software adapter (lavapipe or
//! llvmpipe). These tests REQUIRE an adapter: without one they fail with instructions, they never
//! skip.
//!
//! The biome weights are computed on the CPU on both paths, so they must be identical, bit for
//! bit. The heights: see [`height_tolerance`]. The river carve (`shaders/rivers.wgsl`, a second
//! pass over the heights) is compared on tiles that cross rivers in
//! [`gpu_river_carve_matches_cpu`]: the carved field within the same tolerance, and the carve of
//! the device's own heights bit for bit.

use std::sync::Arc;
use strata::compute::Compute;
use strata::gpu::{BackendChoice, EarthKernels};
use strata::terrain::earth::rivers;
use strata::terrain::tile::{field, FieldJob};
use strata::terrain::{TileKey, WorldParams, WorldPlan};

mod common;

const SEED: u64 = 42;

fn plan() -> WorldPlan {
    let params = WorldParams::default();
    assert!(params.earth.is_some(), "the default world is earth-1");
    WorldPlan::new(SEED, params).expect("default world")
}

fn software_device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    common::device::software_device("gpu_earth")
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
    /// The device's heights.
    gpu_heights: Vec<f32>,
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
        gpu_heights: gpu.heights.clone(),
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
        // LOD 3 (8 m, 512 m tiles), and in the range 115 km out, where the gullies' phasors
        // cancel (`gullies: 3` fades them there: tests/gullies.rs).
        key(3, -40, 25),
        key(3, 219, 231),
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
    // LODs 0 and 3 run the lattice split (`earth::lattice`) with the 16 m lattice, whose nodes
    // the host computes from the 256 m lattice's; LOD 6 with the 256 m lattice alone (four
    // samples a node); the host uploads the nodes and the kernel interpolates them before the
    // later layers. LODs 9 and 12 have no split.
    let lods = &plan.earth.as_ref().expect("earth").lods;
    assert!(lods[0].lattice.is_some_and(|l| l.outer.is_some()));
    assert!(lods[3].lattice.is_some_and(|l| l.outer.is_some()));
    assert!(lods[6]
        .lattice
        .is_some_and(|l| l.step == 4 && l.outer.is_none()));
    assert!(lods[9].lattice.is_none() && lods[12].lattice.is_none());
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

/// The default world without rivers: the heights `earth::field` has before the carve.
fn dry_plan() -> WorldPlan {
    let mut params = WorldParams::default();
    params.earth.as_mut().expect("earth-1").rivers = None;
    WorldPlan::new(SEED, params).expect("default world without rivers")
}

/// Every height the device carved (`gpu`) has the bits of the CPU carve (`expected`) of the
/// device's own uncarved height (`bare`), on a job `w` samples wide.
fn assert_same_carve(k: TileKey, w: usize, bare: &[f32], expected: &[f32], gpu: &[f32]) {
    for (v, (e, g)) in expected.iter().zip(gpu).enumerate() {
        assert_eq!(
            e.to_bits(),
            g.to_bits(),
            "{k:?}, vertex ({}, {}): the device carves its height {} to {g}, the CPU carve of \
             that height gives {e}",
            v % w,
            v / w,
            bare[v]
        );
    }
}

/// The device's river carve (`shaders/rivers.wgsl`) against `earth::carve`, on tiles of the
/// default world with `valleys: 4` and `5` that cross river valleys at LODs 0, 3, 6 and 8 (all carve:
/// `MAX_CARVE_LOD` is 8). Two comparisons:
///
/// - **Carved field, device vs CPU**, within [`height_tolerance`], the uncarved heights' own
///   slack (the carve reads the device's heights, which carry it); the test prints max |Δh|
///   (0 on lavapipe). The carve is metres to hundreds of metres deep, far beyond that slack:
///   each LOD's tiles must hold at least 1 000 samples that the CPU carve moves by more than
///   the tolerance, so a device that skipped or misplaced the carve fails here.
/// - **The carve alone, exactly**: the device's carved heights must equal, bit for bit, the CPU
///   carve applied to the device's own uncarved heights (the same tile of the world without
///   rivers). No tolerance: the carve is a pointwise function of the position and the uncarved
///   height with no feedback, mirrored operation for operation (products through `rn`, `/` and
///   `sqrt` correctly rounded, the CPU's `clamp` written out, `CARVE_MAX_M` and the piece
///   epsilon from the generated preamble), so on any device with IEEE `+ − ×` it gives the
///   CPU's bits. This is what catches a last-millimetre error the tolerance would let through,
///   such as a sample outside every valley that is not returned unchanged (the seams need those
///   bits).
#[test]
fn gpu_river_carve_matches_cpu() {
    // `valleys: 4`: its pieces' floodplains and slopes vary along them (those of `valleys: 3`
    // are the same code with equal ends); `valleys: 6`: those, the walls' spurs, read at each
    // sample's foot on every piece, and slopes scaled by the relief on the host (the shader's
    // code is that of `valleys: 5`, which stored worlds keep); `valleys: 7`: the pieces of the
    // larger rivers alone where the relief is high, chosen on the host; `valleys: 8`, the
    // default: floodplains and bends sized by the discharge and floodplains widened to the
    // tile's spacing, all on the host.
    // The carve's limit is compared where a valley is cut by the full CARVE_MAX_M: in these
    // tiles' mountains only the streams every kilometre of `valleys: 4` and `6` cut that deep.
    for valleys in [4, 6, 7, 8] {
        let clamped = river_carve_matches_cpu(valleys);
        assert!(
            valleys >= 7 || clamped > 0,
            "valleys {valleys}: some valley should be cut by the full CARVE_MAX_M, so that the \
             limit is compared too"
        );
    }
}

/// Compares the device's carve of `valleys` with the CPU's on the chosen tiles; the number of
/// heights cut by the full `CARVE_MAX_M`.
fn river_carve_matches_cpu(valleys: u32) -> usize {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").valleys = valleys;
    let plan = WorldPlan::new(SEED, params).expect("valleys world");
    let dry = dry_plan();
    let earth = plan.earth.as_ref().expect("earth-1");
    let (_adapter, device, queue) = software_device();
    let kernels = EarthKernels::new(&device).expect("earth kernels compile");
    let key = |lod, x, z| TileKey { lod, x, z };
    // Found from the CPU field with and without rivers: valley floors and walls, valley edges
    // (tiles the valley crosses in part: most of their samples keep their heights bit for bit,
    // the others move by millimetres) and mountain valleys cut by the full CARVE_MAX_M.
    let cases = [
        // LODs 9 and 10 (33 and 66 km tiles), carved by the coarse network (`coarse: 1`):
        // around the origin and the range east of it.
        key(9, 0, 0),
        key(9, 3, 3),
        key(10, 0, 0),
        key(10, 1, 1),
        // LOD 8 (16 km tiles): around the origin, south-west of it, mountains at x ≈ 60 km.
        key(8, 0, 0),
        key(8, -1, -1),
        key(8, 3, 2),
        // LOD 6 (4 km tiles): a mountain valley cut by CARVE_MAX_M, two valleys in hills.
        key(6, 15, 9),
        key(6, 5, 0),
        key(6, 6, -4),
        // LOD 3 (512 m tiles): a mountain valley cut by CARVE_MAX_M, a valley wall, a valley
        // edge.
        key(3, 121, 75),
        key(3, 49, -25),
        key(3, 71, 112),
        // LOD 0 (64 m tiles): a channel, a valley cut by CARVE_MAX_M, two valley edges (the
        // two sides of the valley of that channel).
        key(0, -43, 72),
        key(0, 968, 600),
        key(0, -47, 72),
        key(0, -38, 72),
        // The lake near (−440, −4,496) m, whose shores (`lakes: 2`) move the heights before the
        // carve: LOD 3 (the whole lake) and LOD 0 (its shore).
        key(3, -1, -9),
        key(0, -7, -71),
    ];
    let (mut max_dh, mut differing, mut samples, mut clamped) = (0.0f32, 0, 0, 0);
    let mut beyond_by_lod = std::collections::BTreeMap::new();
    for k in cases {
        let rp = earth
            .carve_plan(k.lod as usize)
            .unwrap_or_else(|| panic!("{k:?} must carve"));
        let job = FieldJob::with_margin(k);
        let spacing = plan.lods[k.lod as usize].spacing_m;
        let rj = rivers::job_for(earth, rp, spacing, job.gx0, job.gz0, job.w, job.h);
        let carve = |uncarved: &[f32]| {
            let mut h = uncarved.to_vec();
            strata::terrain::earth::carve(&rj, spacing, job, &mut h);
            h
        };
        let carved = field(&plan, job);
        let bare = field(&dry, job);
        // The world without rivers has the heights of the world with rivers before the carve.
        let recarved = carve(&bare.heights);
        assert!(
            recarved
                .iter()
                .zip(&carved.heights)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "{k:?}: carving the river-free field does not give the field with rivers"
        );
        let (mut changed, mut beyond, mut at_max) = (0, 0, 0);
        for (&c, &b) in carved.heights.iter().zip(&bare.heights) {
            changed += usize::from(c.to_bits() != b.to_bits());
            beyond += usize::from((c - b).abs() > height_tolerance(c));
            at_max += usize::from(c.to_bits() == (b - rivers::CARVE_MAX_M).to_bits());
        }
        println!(
            "{k:?}: the CPU carve changes {changed} of {} heights ({beyond} beyond the \
             tolerance, {at_max} by CARVE_MAX_M)",
            carved.heights.len()
        );
        assert!(changed > 0, "{k:?} should cross a river valley");
        *beyond_by_lod.entry(k.lod).or_insert(0) += beyond;
        clamped += at_max;

        let rep = compare(&device, &queue, &kernels, &plan, k);
        max_dh = max_dh.max(rep.max_dh);
        differing += rep.differing;
        samples += carved.heights.len();

        let gpu_bare = kernels
            .field(&device, &queue, &dry, job, None)
            .unwrap_or_else(|e| panic!("GPU earth field of {k:?} without rivers: {e:#}"));
        let expected = carve(&gpu_bare.heights);
        assert_same_carve(k, job.w, &gpu_bare.heights, &expected, &rep.gpu_heights);
    }
    println!(
        "river carve overall: max |Δh| {max_dh:.3e} m, {differing} of {samples} heights not \
         bit-identical; carved beyond the tolerance per LOD {beyond_by_lod:?}; {clamped} cut by \
         CARVE_MAX_M"
    );
    for (lod, beyond) in &beyond_by_lod {
        assert!(
            *beyond >= 1000,
            "LOD {lod}: only {beyond} samples carved beyond the tolerance; choose tiles on rivers"
        );
    }
    clamped
}

/// The lake sills of `lakes: 4` worlds (`rivers::shores`, step 5) on the device: at the outlet
/// of the spilling lake south of the origin, the device's carve of its own uncarved heights
/// equals the CPU carve of those heights bit for bit, and there the sills raise at least 1 000
/// heights that the same carve without sills (`lakes: 3`) cuts lower, none of them lowered.
#[test]
fn gpu_river_carve_keeps_the_lake_sills_bit_for_bit() {
    let (plan, without) = (lakes_world(4), lakes_world(3));
    let gpu = Gpu::new();
    let key = |lod, x, z| TileKey { lod, x, z };
    let mut raised = 0;
    // LOD 3: the outlet's valleys; LOD 0: a sill's edge, where it fades in.
    for k in [key(3, -1, 0), key(3, -1, 1), key(0, -7, 8)] {
        let (expected, before) = gpu.carve_against(&plan, &without, k);
        for (a, b) in expected.iter().zip(before) {
            assert!(*a >= b, "{k:?}: a sill lowered a height from {b} to {a}");
            raised += usize::from(a.to_bits() != b.to_bits());
        }
    }
    println!("lake sills: {raised} heights raised");
    assert!(raised >= 1000, "only {raised} heights under a sill");
}

/// `lakes: 8` (the default): the shores sink the ground inside a lake towards its nodes' heights
/// before their wedge, and the device reads those heights after the lake window's levels. On a
/// tile of the crater lake near (−367 km, −534 km), whose ridges between the nodes stood above
/// its level with `lakes: 7`, the device carves a field as the CPU does, bit for bit, and the
/// sink lowers thousands of its heights below those of `lakes: 7`.
#[test]
fn gpu_river_carve_sinks_the_ground_inside_lakes_bit_for_bit() {
    let (plan, before) = (lakes_world(8), lakes_world(7));
    let k = TileKey {
        lod: 6,
        x: -90,
        z: -131,
    };
    let (expected, seven) = Gpu::new().carve_against(&plan, &before, k);
    let sunk = expected.iter().zip(seven).filter(|(a, b)| **a < *b).count();
    println!(
        "sunk lake floors: {sunk} of {} heights lower than with lakes 7",
        expected.len()
    );
    assert!(sunk >= 1000, "only {sunk} heights sunk");
}

/// The default world of seed [`SEED`] with `rivers.lakes` set to `lakes`.
fn lakes_world(lakes: u32) -> WorldPlan {
    let mut params = WorldParams::default();
    let earth = params.earth.as_mut().expect("earth-1");
    earth.rivers.as_mut().expect("rivers").lakes = lakes;
    WorldPlan::new(SEED, params).expect("a world with lakes")
}

/// The software device, its earth kernels and the river-free world they carve.
struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    kernels: EarthKernels,
    dry: WorldPlan,
}

impl Gpu {
    fn new() -> Self {
        let (_adapter, device, queue) = software_device();
        let kernels = EarthKernels::new(&device).expect("earth kernels compile");
        Self {
            device,
            queue,
            kernels,
            dry: dry_plan(),
        }
    }

    /// The device's field of tile `k` of `plan`, checked bit for bit against the CPU carve of
    /// its river-free heights; returns that carve and the CPU carve of the same heights with
    /// `other`'s rivers and lakes.
    fn carve_against(
        &self,
        plan: &WorldPlan,
        other: &WorldPlan,
        k: TileKey,
    ) -> (Vec<f32>, Vec<f32>) {
        let job = FieldJob::with_margin(k);
        let spacing = plan.lods[k.lod as usize].spacing_m;
        let carve = |plan: &WorldPlan, uncarved: &[f32]| {
            let earth = plan.earth.as_ref().expect("earth-1");
            let rp = earth.rivers.as_ref().expect("rivers");
            let rj = rivers::job_for(earth, rp, spacing, job.gx0, job.gz0, job.w, job.h);
            let mut h = uncarved.to_vec();
            strata::terrain::earth::carve(&rj, spacing, job, &mut h);
            h
        };
        let gpu_bare = self
            .kernels
            .field(&self.device, &self.queue, &self.dry, job, None)
            .unwrap_or_else(|e| panic!("GPU earth field of {k:?} without rivers: {e:#}"));
        let expected = carve(plan, &gpu_bare.heights);
        let rep = compare(&self.device, &self.queue, &self.kernels, plan, k);
        assert_same_carve(k, job.w, &gpu_bare.heights, &expected, &rep.gpu_heights);
        let before = carve(other, &gpu_bare.heights);
        (expected, before)
    }
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
