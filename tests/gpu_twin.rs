//! The WGSL twin of tile synthesis against the CPU reference, on a software adapter (lavapipe or
//! llvmpipe). These tests REQUIRE an adapter: without one they fail with instructions, they never
//! skip.
//!
//! Tolerances (rationale in `src/gpu/mod.rs`): the kernels are built to reproduce the CPU's bits
//! (integer hashing, no contraction thanks to rounding barriers, correctly rounded `/` and `sqrt`),
//! and on lavapipe they do: every comparison below reports how many values are bit-identical. The
//! asserted tolerances are slack on top of that, for a device that flushes subnormals or rounds an
//! intermediate differently: weights within 2⁻²³ (one ULP of 1.0), heights within
//! 1 mm + 2⁻²⁰·|h|, biome ids identical but for at most two samples. The slack is deliberately
//! small: the warp feeds the accumulated height back into the sample position, so one ULP of
//! difference can grow from octave to octave (with the paper's literal rotation about the origin
//! and 400 m generators it reached metres a few kilometres out; `point_functions_match_cpu` prints
//! how far the CPU's own heights move when x moves by one ULP). A twin that is not bit-exact may
//! show it anywhere, and these tests should notice.

use std::sync::Arc;
use strata::compute::Compute;
use strata::gpu::BackendChoice;
use strata::gpu::TileKernels;
use strata::terrain::tile::{field, job_biome_ids, Field, FieldJob};
use strata::terrain::{synthesize, TileKey, WorldParams, WorldPlan};

mod common;

const SEED: u64 = 7;

/// The classic world: the tile kernels are its twin (`earth-1`, the default, has its own:
/// `tests/gpu_earth.rs`).
fn plan() -> WorldPlan {
    WorldPlan::new(SEED, WorldParams::classic()).expect("classic world")
}

fn software_device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    common::device::software_device("gpu_twin")
}

/// Slack on `|Δw|`: one ULP of 1.0. The weights are sums of kernel taps in tap order, products
/// rounded before they are added, and one correctly rounded division, exactly as on the CPU.
const WEIGHT_TOLERANCE: f32 = f32::EPSILON;

/// Slack on `|Δh|`: 1 mm plus 2⁻²⁰ of the height (≈ 8 ULP). Expected difference: none.
fn height_tolerance(h: f32) -> f32 {
    1e-3 + h.abs() / 1_048_576.0
}

/// The first tile of a row (scanning west from `x_start`) whose blurred weights are not all
/// one-hot, i.e. one that straddles a biome border.
fn border_tile(plan: &WorldPlan, lod: u32, x_start: i64, z: i64) -> TileKey {
    let lp = &plan.lods[lod as usize];
    let at = |gx: i64, gz: i64| {
        plan.biome_map
            .biome_at(gx as f32 * lp.spacing_m, gz as f32 * lp.spacing_m)
    };
    for x in (x_start - 400..=x_start).rev() {
        let (gx, gz) = (x * 64, z * 64);
        let probes = [
            at(gx, gz),
            at(gx + 64, gz),
            at(gx, gz + 64),
            at(gx + 64, gz + 64),
            at(gx + 32, gz + 32),
        ];
        if probes.iter().all(|b| *b == probes[0]) {
            continue;
        }
        let f = field(plan, FieldJob::new(lod, gx - 1, gz - 1, 67, 67));
        if f.weights.iter().any(|w| *w > 0.0 && *w < 1.0) {
            return TileKey { lod, x, z };
        }
    }
    panic!("no border tile at LOD {lod} in row {z} west of {x_start}");
}

struct Report {
    max_dw: f32,
    max_dh: f32,
    id_mismatches: usize,
    excluded: usize,
    weights_differing: usize,
    heights_differing: usize,
}

/// Compares the GPU field of a rectangle with the CPU field; vertices whose blur window holds an
/// id mismatch (a Voronoi near-tie) are excluded from the value checks and counted.
fn compare(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    kernels: &TileKernels,
    plan: &WorldPlan,
    lod: u32,
    (gx0, gz0, w, h): (i64, i64, usize, usize),
) -> Report {
    let t = std::time::Instant::now();
    let job = FieldJob::new(lod, gx0, gz0, w, h);
    let cpu: Field = field(plan, job);
    let cpu_ms = t.elapsed().as_secs_f64() * 1e3;
    let t = std::time::Instant::now();
    let (gpu, gpu_ids) = kernels
        .field_with_ids(device, queue, plan, job, None)
        .unwrap_or_else(|e| panic!("GPU field at LOD {lod} ({gx0}, {gz0}) {w}×{h}: {e:#}"));
    let gpu_ms = t.elapsed().as_secs_f64() * 1e3;
    assert_eq!((gpu.w, gpu.h), (w, h));
    assert_eq!(gpu.heights.len(), cpu.heights.len());
    assert_eq!(gpu.weights.len(), cpu.weights.len());

    let lp = &plan.lods[lod as usize];
    let (k, r) = (plan.biome_count(), lp.kernel.len() / 2);
    let (cpu_ids, bw, bh) = job_biome_ids(plan, job);
    assert_eq!(gpu_ids.len(), cpu_ids.len());
    let bad: Vec<(usize, usize)> = (0..bw * bh)
        .filter(|&s| gpu_ids[s] != cpu_ids[s])
        .map(|s| (s % bw, s / bw))
        .collect();
    // A vertex (i, j) sees the biome-grid samples (i..=i+2r, j..=j+2r).
    let tainted = |i: usize, j: usize| {
        bad.iter()
            .any(|&(bx, bz)| (i..=i + 2 * r).contains(&bx) && (j..=j + 2 * r).contains(&bz))
    };

    let mut rep = Report {
        max_dw: 0.0,
        max_dh: 0.0,
        id_mismatches: bad.len(),
        excluded: 0,
        weights_differing: 0,
        heights_differing: 0,
    };
    for j in 0..h {
        for i in 0..w {
            let v = j * w + i;
            if !bad.is_empty() && tainted(i, j) {
                rep.excluded += 1;
                continue;
            }
            for b in 0..k {
                let (c, g) = (cpu.weights[v * k + b], gpu.weights[v * k + b]);
                // Exactly zero on one side means zero on both: zero weights are structural.
                assert_eq!(
                    c == 0.0,
                    g == 0.0,
                    "weight zero-ness at LOD {lod} vertex ({i}, {j}) biome {b}: cpu {c} gpu {g}"
                );
                let dw = (c - g).abs();
                assert!(
                    dw <= WEIGHT_TOLERANCE,
                    "weight at LOD {lod} vertex ({i}, {j}) biome {b}: cpu {c} gpu {g} (|Δ| {dw} > {WEIGHT_TOLERANCE})"
                );
                rep.max_dw = rep.max_dw.max(dw);
                rep.weights_differing += usize::from(c.to_bits() != g.to_bits());
            }
            let (x, z) = (
                (gx0 + i as i64) as f32 * lp.spacing_m,
                (gz0 + j as i64) as f32 * lp.spacing_m,
            );
            let (c, g) = (cpu.heights[v], gpu.heights[v]);
            let (dh, htol) = ((c - g).abs(), height_tolerance(c));
            assert!(dh <= htol, "height at LOD {lod} vertex ({i}, {j}) = ({x} m, {z} m): cpu {c} gpu {g} (|Δ| {dh} > {htol})");
            rep.max_dh = rep.max_dh.max(dh);
            rep.heights_differing += usize::from(c.to_bits() != g.to_bits());
        }
    }
    println!(
        "LOD {lod} rect ({gx0}, {gz0}) {w}×{h}: max |Δw| {:.3e}, max |Δh| {:.3e} m; not bit-identical: \
         {} of {} weights, {} of {} heights; id mismatches {} of {}; vertices excluded {}; \
         CPU {cpu_ms:.1} ms, GPU {gpu_ms:.1} ms",
        rep.max_dw,
        rep.max_dh,
        rep.weights_differing,
        w * h * k,
        rep.heights_differing,
        w * h,
        rep.id_mismatches,
        bw * bh,
        rep.excluded
    );
    rep
}

fn tile_rect(key: TileKey) -> (i64, i64, usize, usize) {
    (key.x * 64 - 1, key.z * 64 - 1, 67, 67)
}

#[test]
fn gpu_field_matches_cpu_on_sample_tiles() {
    let plan = plan();
    let (adapter, device, queue) = software_device();
    let info = adapter.get_info();
    println!(
        "adapter: {} ({:?}, {:?})",
        info.name, info.backend, info.device_type
    );
    let kernels = TileKernels::new(&device).expect("kernels compile");

    let border0 = border_tile(&plan, 0, -1, -3);
    let border2 = border_tile(&plan, 2, -1, -2);
    let border4 = border_tile(&plan, 4, -1, -1);
    println!("border tiles: {border0:?} {border2:?} {border4:?}");
    let cases = [
        (0, tile_rect(TileKey { lod: 0, x: 0, z: 0 })),
        (
            0,
            tile_rect(TileKey {
                lod: 0,
                x: -5,
                z: -9,
            }),
        ),
        (0, tile_rect(border0)),
        (2, tile_rect(border2)),
        (
            4,
            tile_rect(TileKey {
                lod: 4,
                x: -3,
                z: -2,
            }),
        ),
        (4, tile_rect(border4)),
        // A snap strip (33 × 1) of the next coarser LOD, as `Compute::tile` requests.
        (1, (-32, -64, 33, 1)),
        // The far corner of the supported world, where the warped fractal is most sensitive.
        (
            0,
            tile_rect(TileKey {
                lod: 0,
                x: plan.max_tile_coord(0),
                z: -plan.max_tile_coord(0) - 1,
            }),
        ),
        (
            8,
            tile_rect(TileKey {
                lod: 8,
                x: -plan.max_tile_coord(8) - 1,
                z: plan.max_tile_coord(8),
            }),
        ),
    ];
    let mut blended = 0;
    let (mut mismatches, mut samples) = (0, 0);
    let (mut max_dw, mut max_dh, mut differing) = (0.0f32, 0.0f32, 0);
    for (lod, rect) in cases {
        let rep = compare(&device, &queue, &kernels, &plan, lod, rect);
        differing += rep.weights_differing + rep.heights_differing;
        let r = plan.lods[lod as usize].kernel.len() / 2;
        samples += (rect.2 + 2 * r) * (rect.3 + 2 * r);
        mismatches += rep.id_mismatches;
        max_dw = max_dw.max(rep.max_dw);
        max_dh = max_dh.max(rep.max_dh);
        let cpu = field(&plan, FieldJob::new(lod, rect.0, rect.1, rect.2, rect.3));
        blended += usize::from(cpu.weights.iter().any(|w| *w > 0.0 && *w < 1.0));
    }
    println!(
        "overall: max |Δw| {max_dw:.3e}, max |Δh| {max_dh:.3e} m, {differing} values not bit-identical, \
         id mismatches {mismatches} of {samples}"
    );
    assert!(
        blended >= 3,
        "the border tiles must exercise the blur ({blended} blended)"
    );
    // The id rules are identical; only an exact Voronoi near-tie may flip (see src/gpu/mod.rs).
    assert!(
        mismatches <= 2,
        "{mismatches} biome-id mismatches in {samples} samples"
    );
}

#[test]
fn gpu_biome_ids_match_cpu_over_many_voronoi_cells() {
    // A 256×256 field at LOD 4 (16 m spacing) spans about 8×8 Voronoi cells around the origin,
    // with negative indices, latitude bands and many block shortcuts.
    let plan = plan();
    let (_, device, queue) = software_device();
    let kernels = TileKernels::new(&device).expect("kernels compile");
    let rep = compare(&device, &queue, &kernels, &plan, 4, (-128, -128, 256, 256));
    assert!(
        rep.id_mismatches <= 4,
        "{} biome-id mismatches",
        rep.id_mismatches
    );
}

#[test]
fn a_destroyed_device_gives_an_error_not_a_panic() {
    let plan = plan();
    let (_, device, queue) = software_device();
    let kernels = TileKernels::new(&device).expect("kernels compile");
    assert!(kernels
        .field(
            &device,
            &queue,
            &plan,
            FieldJob::new(0, -1, -1, 67, 67),
            None
        )
        .is_ok());
    device.destroy();
    let r = kernels.field(
        &device,
        &queue,
        &plan,
        FieldJob::new(0, -1, -1, 67, 67),
        None,
    );
    assert!(r.is_err(), "a job on a destroyed device must fail");
    println!(
        "job on a destroyed device: {:#}",
        r.err().map(|e| format!("{e:#}")).unwrap_or_default()
    );
}

#[tokio::test]
async fn backend_choices_cpu_and_auto() {
    assert!(strata::gpu::open(BackendChoice::Cpu)
        .await
        .expect("cpu")
        .is_none());
    // Auto takes hardware only: on this machine (lavapipe) that is no device; elsewhere it must be
    // a hardware adapter.
    match strata::gpu::open(BackendChoice::Auto)
        .await
        .expect("auto never fails for lack of a GPU")
    {
        None => println!("auto: no hardware adapter, CPU path"),
        Some(h) => {
            let t = h.adapter_info().device_type;
            assert!(
                ["DiscreteGpu", "IntegratedGpu", "VirtualGpu"].contains(&t.as_str()),
                "auto chose {t}"
            );
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn device_loss_falls_back_to_the_cpu() {
    let plan = Arc::new(plan());
    let handle = common::device::handle("device_loss_falls_back_to_the_cpu").await;
    let compute = Compute::with_gpu(handle.clone());
    let info = compute.info();
    assert_eq!(info.backend, "gpu");
    assert!(!info.device_lost);
    println!("adapter: {:?}", info.adapter);

    // The handle path works before the loss.
    let key = TileKey {
        lod: 0,
        x: -2,
        z: 1,
    };
    let (gx0, gz0, w, h) = tile_rect(key);
    let f = handle
        .field(plan.clone(), FieldJob::new(0, gx0, gz0, w, h))
        .await
        .expect("GPU field before the loss");
    let cpu = field(&plan, FieldJob::new(0, gx0, gz0, w, h));
    let dh = f
        .heights
        .iter()
        .zip(&cpu.heights)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(dh < 0.01, "GPU field via the handle: max |Δh| {dh}");

    handle.simulate_device_loss();
    let tile = compute
        .tile(plan.clone(), key, [true, false, true, false])
        .await;
    let mut expected = synthesize(&plan, key);
    strata::terrain::tile::snap_edges(&plan, &mut expected, [true, false, true, false]);
    assert!(
        tile == expected,
        "after a device loss the tile must be the CPU tile, bit for bit"
    );
    // Only a failing job sets the flag (the lost callback ignores our own destroy()), so this
    // shows the job on the destroyed device really failed.
    assert!(handle.is_lost(), "the failed job must mark the device lost");
    let info = compute.info();
    assert!(info.device_lost);
    assert_eq!(info.backend, "cpu");
    assert!(handle
        .field(plan.clone(), FieldJob::new(0, gx0, gz0, w, h))
        .await
        .is_err());
}

/// Probe of the point functions of `common.wgsl` (hash, lattice noise, one biome's fractal, the
/// biome map) at scattered points, against their Rust originals.
const PROBE_WGSL: &str = r#"
@group(0) @binding(0) var<storage, read> points: array<vec2<f32>>;
@group(0) @binding(1) var<storage, read> probe_fractals: array<Fractal>;
@group(0) @binding(2) var<uniform> probe_map: BiomeMap;
@group(0) @binding(3) var<storage, read_write> probe_out: array<vec4<f32>>;

@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) gid: vec3<u32>) {
    rounding_key = gid.z;
    let i = gid.x;
    if (i >= arrayLength(&points)) {
        return;
    }
    let p = points[i];
    probe_out[i] = vec4<f32>(
        bitcast<f32>(hash2(i32(floor(p.x)), i32(floor(p.y)), 0x9e3779b9u)),
        lattice(p.x * 0.037, p.y * 0.037, 12345u),
        fbm(probe_fractals[i % arrayLength(&probe_fractals)], p.x, p.y),
        f32(biome_at(probe_map, p.x, p.y)),
    );
}

// The division and square-root corrections, from estimates off by -3..=3 ULP.
@compute @workgroup_size(64)
fn probe_rounding(@builtin(global_invocation_id) gid: vec3<u32>) {
    rounding_key = gid.z;
    let i = gid.x;
    if (i >= arrayLength(&points)) {
        return;
    }
    let p = abs(points[i]);
    let off = i32(i % 7u) - 3;
    let q0 = bitcast<f32>(bitcast<i32>(p.x / p.y) + off);
    let s0 = bitcast<f32>(bitcast<i32>(sqrt(p.x)) + off);
    probe_out[i] = vec4<f32>(div_from(p.x, p.y, q0), sqrt_from(p.x, s0), div_rn(points[i].x, points[i].y), sqrt_rn(p.x));
}
"#;

fn run_probe(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    plan: &WorldPlan,
    lod: u32,
    entry: &str,
    points: &[[f32; 2]],
) -> Vec<[f32; 4]> {
    use strata::gpu::layout::{GpuBiomeMap, GpuFractal};
    use wgpu::util::DeviceExt;
    let source = format!("{}\n{PROBE_WGSL}", strata::gpu::tile::COMMON_WGSL);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("probe"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let entry_of = |binding: u32, ty: wgpu::BufferBindingType| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let read_only = wgpu::BufferBindingType::Storage { read_only: true };
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[
            entry_of(0, read_only),
            entry_of(1, read_only),
            entry_of(2, wgpu::BufferBindingType::Uniform),
            entry_of(3, wgpu::BufferBindingType::Storage { read_only: false }),
        ],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(entry),
        layout: Some(&pipeline_layout),
        module: &module,
        entry_point: Some(entry),
        compilation_options: Default::default(),
        cache: None,
    });
    let fractals: Vec<GpuFractal> = plan.lods[lod as usize]
        .fractals
        .iter()
        .map(GpuFractal::from)
        .collect();
    let map = GpuBiomeMap::from(&plan.biome_map);
    let storage = wgpu::BufferUsages::STORAGE;
    let init = |contents: &[u8], usage| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage,
        })
    };
    let pts = init(bytemuck::cast_slice(points), storage);
    let frs = init(bytemuck::cast_slice(&fractals), storage);
    let mp = init(bytemuck::bytes_of(&map), wgpu::BufferUsages::UNIFORM);
    let size = (points.len() * 16) as u64;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: storage | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let read = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &[&pts, &frs, &mp, &out]
            .iter()
            .enumerate()
            .map(|(i, b)| wgpu::BindGroupEntry {
                binding: i as u32,
                resource: b.as_entire_binding(),
            })
            .collect::<Vec<_>>(),
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups((points.len() as u32).div_ceil(64), 1, 1);
    }
    enc.copy_buffer_to_buffer(&out, 0, &read, 0, size);
    queue.submit([enc.finish()]);
    read.slice(..)
        .map_async(wgpu::MapMode::Read, |r| r.expect("map probe output"));
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("poll");
    let view = read.slice(..).get_mapped_range().expect("mapped");
    bytemuck::pod_collect_to_vec(&view)
}

fn probe_points() -> Vec<[f32; 2]> {
    (0..4096)
        .map(|i| {
            let t = i as f32;
            [
                (t * 7.31).sin() * 3000.0 + t * 0.37,
                (t * 3.17).cos() * 2500.0 - t * 0.51,
            ]
        })
        .collect()
}

/// The classic world, the same with the paper's literal rotation about the origin, and the same
/// without warping: the three branches of the fractal.
fn world_variants() -> Vec<(&'static str, WorldPlan)> {
    let literal = WorldParams {
        warp: strata::terrain::fractal::WarpParams {
            about_origin: true,
            ..Default::default()
        },
        ..WorldParams::classic()
    };
    let mut unwarped = WorldParams::classic();
    for b in &mut unwarped.biomes {
        if let Some(g) = &mut b.generator {
            g.warp = false;
        }
    }
    vec![
        ("classic", plan()),
        (
            "about_origin",
            WorldPlan::new(SEED, literal).expect("literal warp world"),
        ),
        (
            "unwarped",
            WorldPlan::new(SEED, unwarped).expect("unwarped world"),
        ),
    ]
}

#[test]
fn point_functions_match_cpu() {
    use strata::terrain::hash::hash2;
    use strata::terrain::noise::lattice;
    let (_, device, queue) = software_device();
    let points = probe_points();
    for (name, plan) in world_variants() {
        for lod in [0, 3] {
            let got = run_probe(&device, &queue, &plan, lod, "probe", &points);
            let fractals = &plan.lods[lod as usize].fractals;
            let (mut lattice_bits, mut fbm_bits, mut biome_mismatch) = (0, 0, 0);
            let (mut max_dl, mut max_dh, mut max_sensitivity) = (0.0f32, 0.0f32, 0.0f32);
            for (i, (p, g)) in points.iter().zip(&got).enumerate() {
                let h = hash2(p[0].floor() as i32, p[1].floor() as i32, 0x9e37_79b9);
                assert_eq!(g[0].to_bits(), h, "hash2 at {p:?}");
                let l = lattice(p[0] * 0.037, p[1] * 0.037, 12345);
                lattice_bits += usize::from(l.to_bits() != g[1].to_bits());
                max_dl = max_dl.max((l - g[1]).abs());
                let f = &fractals[i % fractals.len()];
                let cpu = f.height(p[0], p[1]);
                fbm_bits += usize::from(cpu.to_bits() != g[2].to_bits());
                let dh = (cpu - g[2]).abs();
                let tol = height_tolerance(cpu);
                assert!(
                    dh <= tol,
                    "{name} LOD {lod}: fbm of biome {} at {p:?}: cpu {cpu} gpu {} (|Δ| {dh} > {tol})",
                    i % fractals.len(),
                    g[2]
                );
                max_dh = max_dh.max(dh);
                let x_next = f32::from_bits(p[0].to_bits() + 1);
                max_sensitivity = max_sensitivity.max((f.height(x_next, p[1]) - cpu).abs());
                biome_mismatch += usize::from(plan.biome_map.biome_at(p[0], p[1]) as f32 != g[3]);
            }
            println!(
                "{name} LOD {lod}, {} points within 5 km of the origin: not bit-identical: lattice \
                 {lattice_bits} (max |Δ| {max_dl:.3e}), fbm {fbm_bits} (max |Δ| {max_dh:.3e} m); biome \
                 mismatches {biome_mismatch}; for scale, one ULP of x moves the CPU's own fbm by up to \
                 {max_sensitivity:.3e} m",
                points.len()
            );
            // Lattice noise: values of magnitude ≤ 4; 8 ULP of slack.
            assert!(
                max_dl <= 4.0 * 8.0 * f32::EPSILON,
                "lattice noise differs by {max_dl}"
            );
            assert!(biome_mismatch <= 1, "{biome_mismatch} biome mismatches");
        }
    }
}

#[test]
fn division_and_sqrt_are_corrected_to_the_correctly_rounded_result() {
    let plan = plan();
    let (_, device, queue) = software_device();
    let points = probe_points();
    let got = run_probe(&device, &queue, &plan, 0, "probe_rounding", &points);
    for (p, g) in points.iter().zip(&got).filter(|(p, _)| p[0] != 0.0) {
        let (a, b) = (p[0].abs(), p[1].abs());
        assert_eq!(
            g[0].to_bits(),
            (a / b).to_bits(),
            "div_from({a}, {b}) from an estimate a few ULP off"
        );
        assert_eq!(
            g[1].to_bits(),
            a.sqrt().to_bits(),
            "sqrt_from({a}) from an estimate a few ULP off"
        );
        assert_eq!(
            g[2].to_bits(),
            (p[0] / p[1]).to_bits(),
            "div_rn({}, {})",
            p[0],
            p[1]
        );
        assert_eq!(g[3].to_bits(), a.sqrt().to_bits(), "sqrt_rn({a})");
    }
}
