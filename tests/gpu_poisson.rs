//! The WGSL twin of the multigrid Poisson solver (`shaders/poisson.wgsl`, `strata::gpu::poisson`)
//! against the CPU reference (`strata::terrain::poisson`), on a software adapter (lavapipe or
//! llvmpipe). These tests REQUIRE an adapter: without one they fail with instructions, they never
//! skip.
//!
//! Tolerances:
//! - each kernel: the GPU evaluates the CPU's expression in the CPU's order but in `f32` (the CPU
//!   in `f64`, on the same `f32`-representable inputs), and may contract `a·b + c` into an FMA. A
//!   kernel output is at most five `f32` roundings of partial sums of magnitude up to `4M` (`M`
//!   the largest magnitude read; four neighbours), each off by at most half an ULP, `2⁻²⁴ · 4M`,
//!   hence `|Δ| ≤ 10 · 2⁻²⁴ · M`; we allow `16 · 2⁻²⁴ · M` (observed: up to 0.6 of the bound on
//!   the residual, the largest). A wrong index or weight exceeds it by orders of magnitude.
//! - the coarse levels' 9-point kernels: eight weighted terms instead of four, with weights up to
//!   3 in magnitude, so we allow `2 · 3` times the bound above (observed: under 1% of it).
//! - a solve: 20 V-cycles on the device from zero against the CPU solution at relative residual
//!   1e-10, on a problem with a fixed point and a fixed curve (Galerkin coarse levels with special
//!   stencils). The device iterate stalls at its `f32` floor: residuals of ~500 m heights are
//!   evaluated with ~`2⁻²⁴ · 2000` m rounding per sample, which `A⁻¹` turns into height errors of
//!   a few millimetres on a 129² grid (observed 1.3 mm, relative residual 6e-7); we allow 2 cm
//!   and a relative residual (recomputed on the CPU in `f64`) of 1e-5.

mod common;

use strata::gpu::poisson::{GpuField, GpuPoissonParams, Op, PoissonKernels, POISSON_WGSL};
use strata::terrain::poisson::level::Level;
use strata::terrain::poisson::ops::{
    prolong, residual, residual_restrict, smooth_colour, smooth_nine,
};
use strata::terrain::poisson::{Acceleration, GridSpec, OwnedProblem, SolveOptions, Solver, Start};

fn software_device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    common::device::software_device("gpu_poisson")
}

/// A terrain-like problem; with `constrained`, a fixed point and a fixed diagonal curve.
fn terrain(n: usize, constrained: bool) -> OwnedProblem {
    let grid = GridSpec::new(n, n, 2.0).expect("grid");
    let heights: Vec<f32> = (0..n * n)
        .map(|k| {
            let (x, z) = ((k % n) as f64 * 2.0, (k / n) as f64 * 2.0);
            (450.0
                + 60.0 * (x / 70.0).sin() * (z / 55.0 + 0.3).cos()
                + 4.0 * (x / 6.1 + z / 9.3).sin()) as f32
        })
        .collect();
    let mut p = OwnedProblem::from_heights(grid, heights);
    if constrained {
        p.fix(n / 3, n / 4, 400.0);
        for t in 0..n / 2 {
            p.fix(n / 4 + t, n / 2 + t / 2, 470.0);
        }
    }
    p
}

/// Rounds every value of a level to `f32`, so the CPU (f64) and the device (f32) read the same
/// inputs.
fn round_to_f32(level: &mut Level) {
    for a in level.h.iter_mut().chain(level.rhs.iter_mut()) {
        for v in a.iter_mut() {
            *v = f64::from(*v as f32);
        }
    }
}

fn max_abs(a: &[Vec<f64>; 2]) -> f64 {
    a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// Compares a device array with the CPU's; returns the largest difference and how many values
/// are bit-identical after rounding the CPU's to f32.
fn compare(what: &str, gpu: &[Vec<f32>; 2], cpu: &[Vec<f64>; 2], bound: f64) -> f64 {
    let mut worst = 0.0f64;
    let (mut same, mut total) = (0usize, 0usize);
    for c in 0..2 {
        assert_eq!(gpu[c].len(), cpu[c].len(), "{what}: length");
        for (g, v) in gpu[c].iter().zip(&cpu[c]) {
            worst = worst.max((f64::from(*g) - v).abs());
            same += usize::from(g.to_bits() == (*v as f32).to_bits());
            total += 1;
        }
    }
    println!("{what}: max |Δ| = {worst:.3e} (bound {bound:.3e}), {same}/{total} bit-identical to the CPU rounded to f32");
    assert!(
        worst <= bound,
        "{what}: max |Δ| = {worst:e} exceeds {bound:e}"
    );
    worst
}

/// The two finest levels of a loaded 65² problem, with non-trivial unknowns on both.
fn two_levels() -> Vec<Level> {
    let p = terrain(65, true);
    let mut solver = Solver::new(p.grid, SolveOptions::default()).expect("solver");
    solver.load(&p.problem()).expect("load");
    let mut levels: Vec<Level> = solver.levels()[..2].to_vec();
    // Free unknowns of the finest level: the heights plus a deterministic ripple; coarse
    // unknowns: a smooth correction field.
    for (l, level) in levels.iter_mut().enumerate() {
        let g = level.grid;
        for j in 0..g.nz {
            for i in 0..g.nx {
                let (c, k) = level.split.locate(i, j);
                if level.free[c][k] != 0 {
                    level.h[c][k] = if l == 0 {
                        f64::from(p.heights[j * g.nx + i]) + ((i * 7 + j * 13) % 11) as f64 * 0.37
                    } else {
                        3.0 * (i as f64 * 0.4).sin() + (j as f64 * 0.3).cos()
                    };
                }
            }
        }
        round_to_f32(level);
    }
    levels
}

/// `16 · 2⁻²⁴ · M`: the per-kernel tolerance (see the module docs).
fn kernel_bound(m: f64) -> f64 {
    16.0 * m / 16_777_216.0
}

#[test]
fn each_kernel_matches_the_cpu_reference() {
    let (_adapter, device, queue) = software_device();
    let kernels = PoissonKernels::new(&device).expect("kernels");
    let levels = two_levels();
    let m0 = max_abs(&levels[0].h).max(max_abs(&levels[0].rhs));

    // Residual.
    let hier = kernels.upload(&device, &queue, &levels).expect("upload");
    kernels
        .run(&device, &queue, &hier, &[Op::Residual(0)])
        .expect("residual");
    let gpu = kernels
        .read(&device, &queue, &hier, 0, GpuField::Residual)
        .expect("read");
    let n = levels[0].split.len();
    let mut cpu = [vec![0.0; n], vec![0.0; n]];
    residual(&levels[0], &mut cpu);
    assert!(max_abs(&cpu) > 1.0, "the residual is not trivial");
    compare("residual", &gpu, &cpu, kernel_bound(m0));

    // Restriction of the residual (the device restricts its own residual; the CPU its own, which
    // agree within the bound above, amplified by the weights' sum 4).
    kernels
        .run(&device, &queue, &hier, &[Op::Restrict(0)])
        .expect("restrict");
    let gpu = kernels
        .read(&device, &queue, &hier, 1, GpuField::Rhs)
        .expect("read");
    let mut coarse = levels[1].clone();
    residual_restrict(&levels[0], &mut coarse);
    compare(
        "restriction",
        &gpu,
        &coarse.rhs,
        4.0 * kernel_bound(m0) + kernel_bound(4.0 * max_abs(&cpu)),
    );

    // Prolongation (added to the finest unknowns).
    let hier = kernels.upload(&device, &queue, &levels).expect("upload");
    kernels
        .run(&device, &queue, &hier, &[Op::Prolong(0)])
        .expect("prolong");
    let gpu = kernels
        .read(&device, &queue, &hier, 0, GpuField::H)
        .expect("read");
    let mut fine = levels[0].clone();
    prolong::<true>(&levels[1], &mut fine, &mut Vec::new());
    compare("prolongation", &gpu, &fine.h, kernel_bound(m0));

    // Red, then black half-sweep.
    for (op, c, name) in [
        (Op::SmoothRed(0), 0, "red half-sweep"),
        (Op::SmoothBlack(0), 1, "black half-sweep"),
    ] {
        let hier = kernels.upload(&device, &queue, &levels).expect("upload");
        kernels.run(&device, &queue, &hier, &[op]).expect("smooth");
        let gpu = kernels
            .read(&device, &queue, &hier, 0, GpuField::H)
            .expect("read");
        let mut fine = levels[0].clone();
        smooth_colour(&mut fine, c);
        compare(name, &gpu, &fine.h, kernel_bound(m0));
    }

    // Zeroing.
    let hier = kernels.upload(&device, &queue, &levels).expect("upload");
    kernels
        .run(&device, &queue, &hier, &[Op::Zero(1)])
        .expect("zero");
    let gpu = kernels
        .read(&device, &queue, &hier, 1, GpuField::H)
        .expect("read");
    assert!(gpu.iter().flatten().all(|v| *v == 0.0));

    // An op on a missing coarser level is an error, not a panic.
    assert!(kernels
        .run(&device, &queue, &hier, &[Op::Restrict(1)])
        .is_err());
}

#[test]
fn coarse_kernels_match_the_cpu_reference() {
    // Level 1 of a constrained problem: the Galerkin 9-point operator with special stencils
    // around the fixed point and curve.
    let (_adapter, device, queue) = software_device();
    let kernels = PoissonKernels::new(&device).expect("kernels");
    let mut levels = two_levels();
    let specials = levels[1].nine.as_ref().expect("9-point").special.len();
    assert!(specials > 10, "{specials} special stencils");
    // A right-hand side on level 1 too (the restricted residual).
    let mut coarse = levels[1].clone();
    residual_restrict(&levels[0], &mut coarse);
    levels[1].rhs = coarse.rhs;
    round_to_f32(&mut levels[1]);
    let m1 = max_abs(&levels[1].h).max(max_abs(&levels[1].rhs));
    // The 9-point sums have eight weighted terms (weights up to 3 in magnitude): twice the
    // 5-point kernel's bound, times the largest weight.
    let bound = 2.0 * 3.0 * kernel_bound(m1);

    let hier = kernels.upload(&device, &queue, &levels).expect("upload");
    kernels
        .run(&device, &queue, &hier, &[Op::Residual(1)])
        .expect("residual");
    let gpu = kernels
        .read(&device, &queue, &hier, 1, GpuField::Residual)
        .expect("read");
    let n = levels[1].split.len();
    let mut cpu = [vec![0.0; n], vec![0.0; n]];
    residual(&levels[1], &mut cpu);
    assert!(max_abs(&cpu) > 1e-3, "the residual is not trivial");
    compare("9-point residual", &gpu, &cpu, bound);

    for (c, par) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        let hier = kernels.upload(&device, &queue, &levels).expect("upload");
        kernels
            .run(&device, &queue, &hier, &[Op::SmoothNine(1, c, par)])
            .expect("smooth");
        let gpu = kernels
            .read(&device, &queue, &hier, 1, GpuField::H)
            .expect("read");
        let mut level = levels[1].clone();
        smooth_nine(&mut level, c, par);
        compare(&format!("9-point pass ({c}, {par})"), &gpu, &level.h, bound);
    }
    assert!(kernels
        .run(&device, &queue, &hier, &[Op::SmoothNine(0, 0, 0)])
        .is_err());
    assert!(kernels
        .run(&device, &queue, &hier, &[Op::SmoothRed(1)])
        .is_err());
}

#[test]
fn a_device_solve_matches_the_cpu_solve() {
    let (_adapter, device, queue) = software_device();
    let kernels = PoissonKernels::new(&device).expect("kernels");
    // The device runs plain V-cycles (the Galerkin coarse operators keep their reduction steady
    // with interior constraints), compared with the CPU's plain V-cycles on a problem with a
    // fixed point and a fixed curve.
    let p = terrain(129, true);
    let opts = SolveOptions {
        tolerance: 1e-10,
        acceleration: Acceleration::None,
        ..SolveOptions::default()
    };
    let mut cpu = Solver::new(p.grid, opts).expect("solver");
    let report = cpu.solve(&p.problem(), Start::Cold).expect("cpu solve");
    println!(
        "CPU, plain V-cycles: {} cycles, factors {:?}",
        report.cycles,
        report.factors()
    );
    assert!(report.converged, "{report:?}");
    let mut want = vec![0.0f64; p.grid.len()];
    cpu.heights_f64_into(&mut want).expect("heights");

    let mut fresh = Solver::new(p.grid, opts).expect("solver");
    let bnorm = fresh.load(&p.problem()).expect("load");
    let levels = fresh.levels();
    let gpu = kernels
        .solve(&device, &queue, levels, 20, &opts)
        .expect("device solve");

    // Residual of the device's iterate, in f64 on the CPU.
    let mut finest = levels[0].clone();
    for (hc, gc) in finest.h.iter_mut().zip(&gpu) {
        for (h, g) in hc.iter_mut().zip(gc) {
            *h = f64::from(*g);
        }
    }
    let n = finest.split.len();
    let mut r = [vec![0.0; n], vec![0.0; n]];
    let rel = residual(&finest, &mut r).sqrt() / bnorm;
    let mut worst = 0.0f64;
    let g = finest.grid;
    for j in 0..g.nz {
        for i in 0..g.nx {
            worst = worst.max((finest.value(i, j) - want[j * g.nx + i]).abs());
        }
    }
    println!("device solve, 20 V-cycles on {}×{}: relative residual {rel:.2e}, max |h_gpu − h_cpu| = {worst:.3e} m", g.nx, g.nz);
    assert!(rel <= 1e-5, "relative residual {rel:e} of the device solve");
    assert!(worst <= 0.02, "device and CPU heights differ by {worst} m");
    // Fixed samples are untouched by every kernel.
    for j in 0..g.nz {
        for i in 0..g.nx {
            if !finest.is_free(i, j) {
                assert_eq!(
                    finest.value(i, j),
                    f64::from(p.heights[j * g.nx + i]),
                    "({i}, {j})"
                );
            }
        }
    }
}

#[test]
fn params_match_the_wgsl_struct() {
    let module = naga::front::wgsl::parse_str(POISSON_WGSL).expect("poisson.wgsl parses");
    let (members, span) = module
        .types
        .iter()
        .find_map(|(_, ty)| match (&ty.name, &ty.inner) {
            (Some(name), naga::TypeInner::Struct { members, span }) if name == "PoissonParams" => {
                Some((members.clone(), *span))
            }
            _ => None,
        })
        .expect("struct PoissonParams");
    assert_eq!(span as usize, std::mem::size_of::<GpuPoissonParams>());
    let rust = [
        ("nx", std::mem::offset_of!(GpuPoissonParams, nx)),
        ("nz", std::mem::offset_of!(GpuPoissonParams, nz)),
        ("stride", std::mem::offset_of!(GpuPoissonParams, stride)),
        ("len", std::mem::offset_of!(GpuPoissonParams, len)),
        ("cnx", std::mem::offset_of!(GpuPoissonParams, cnx)),
        ("cnz", std::mem::offset_of!(GpuPoissonParams, cnz)),
        ("cstride", std::mem::offset_of!(GpuPoissonParams, cstride)),
        ("clen", std::mem::offset_of!(GpuPoissonParams, clen)),
    ];
    assert_eq!(members.len(), rust.len());
    for (m, (name, offset)) in members.iter().zip(rust) {
        assert_eq!(m.name.as_deref(), Some(name));
        assert_eq!(m.offset as usize, offset, "offset of {name}");
    }
}
