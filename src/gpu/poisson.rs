//! WGSL twin of the multigrid Poisson solver (`shaders/poisson.wgsl`, issue 4).
//!
//! [`PoissonKernels`] compiles the kernels (red and black half-sweeps of the finest level's 5-point
//! operator, the four-colour passes of the coarse levels' Galerkin 9-point operators with their
//! special stencils, the residual of either, full-weighting restriction, bilinear prolongation,
//! zeroing) for a device. [`PoissonKernels::upload`] copies a
//! CPU hierarchy ([`crate::terrain::poisson::level::Level`]s, e.g. from
//! [`crate::terrain::poisson::Solver::levels`] after [`crate::terrain::poisson::Solver::load`])
//! to the device in `f32`, [`PoissonKernels::run`] records a list of [`Op`]s into one compute pass
//! (WebGPU makes each dispatch's storage writes visible to the next), and
//! [`PoissonKernels::solve`] runs finest-level V- or W-cycles exactly as the CPU's
//! `multigrid::Solver` does (residual, restriction, coarse recursion, prolongation, smoothing; the
//! coarsest level by `COARSEST_SWEEPS` sweeps). The host functions take the device and queue as
//! arguments, so tests inject a software adapter.
//!
//! # Precision and tolerance
//! The kernels evaluate the CPU's expressions in the CPU's order, but in `f32` (WGSL has no
//! portable `f64`) where the CPU uses `f64`, and a WGSL compiler may contract `a·b + c` into a
//! fused multiply-add (the residual's `Σ − 4h`, the restriction's `4 r + 2 e`). So one kernel
//! application agrees with the CPU to a few `f32` roundings of the magnitudes involved
//! (`tests/gpu_poisson.rs` checks `|Δ| ≤ 16 · 2⁻²⁴ · M`, `M` the largest magnitude the kernel
//! reads), and a solve reaches the `f32` floor of the relative residual (about `1e-6` to `1e-5`:
//! residuals of ~500 m heights are evaluated with `2⁻²⁴ · 500 m` rounding), not the CPU's `1e-6`
//! on large grids; the heights then agree with the CPU's within a few millimetres.

use super::kit::{bind_group, read_back, readback, upload, Binding, Program};
use super::scopes::Scopes;
use crate::terrain::poisson::level::Level;
use crate::terrain::poisson::multigrid::{Cycle, SolveOptions, COARSEST_SWEEPS};
use anyhow::{anyhow, bail, Context};
use bytemuck::{Pod, Zeroable};
use std::time::Duration;

/// `shaders/poisson.wgsl`.
pub const POISSON_WGSL: &str = include_str!("../../shaders/poisson.wgsl");
/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// Largest storage buffer the kernels may bind (WebGPU's default limit): 2 · len · 4 bytes per
/// field, so up to 4097² samples.
pub const MAX_BUFFER_BYTES: u64 = 128 << 20;
/// How long a job may wait for the device.
pub const JOB_TIMEOUT: Duration = Duration::from_secs(60);

/// WGSL `PoissonParams`: the sizes of a level and of its coarser neighbour.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct GpuPoissonParams {
    /// Samples along x.
    pub nx: u32,
    /// Samples along z.
    pub nz: u32,
    /// Slots per colour row, `(nx + 1) / 2`.
    pub stride: u32,
    /// Values per colour array, `nz · stride`.
    pub len: u32,
    /// Coarse samples along x (0 without a coarser level).
    pub cnx: u32,
    /// Coarse samples along z.
    pub cnz: u32,
    /// Coarse slots per colour row.
    pub cstride: u32,
    /// Coarse values per colour array.
    pub clen: u32,
}

impl GpuPoissonParams {
    /// Parameters of `level`, with `coarse` its coarser neighbour if any.
    pub fn of(level: &Level, coarse: Option<&Level>) -> Self {
        let s = level.split;
        let (cnx, cnz, cstride, clen) = coarse
            .map(|c| (c.split.nx, c.split.nz, c.split.stride, c.split.len()))
            .unwrap_or_default();
        Self {
            nx: s.nx as u32,
            nz: s.nz as u32,
            stride: s.stride as u32,
            len: s.len() as u32,
            cnx: cnx as u32,
            cnz: cnz as u32,
            cstride: cstride as u32,
            clen: clen as u32,
        }
    }
}

/// One kernel dispatch on level `l` (restriction and prolongation go between `l` and `l + 1`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Red half-sweep on level `l` (5-point: the finest level).
    SmoothRed(usize),
    /// Black half-sweep on level `l` (5-point: the finest level).
    SmoothBlack(usize),
    /// Gauss–Seidel pass of a coarse level `l` (9-point) over colour array `c` (0 or 1) in the
    /// rows of parity `p` (0 or 1): the default stencil, then the special ones.
    SmoothNine(usize, usize, usize),
    /// Residual of level `l` into its residual buffer (5-point on the finest level, 9-point with
    /// the special stencils on coarse levels).
    Residual(usize),
    /// Full weighting of level `l`'s residual buffer into level `l + 1`'s right-hand side.
    Restrict(usize),
    /// Bilinear prolongation of level `l + 1`'s unknowns, added to level `l`'s free samples.
    Prolong(usize),
    /// Level `l`'s unknowns set to zero.
    Zero(usize),
}

/// A per-level array on the device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GpuField {
    /// Unknowns.
    H,
    /// Right-hand side.
    Rhs,
    /// Residual (written by [`Op::Residual`]).
    Residual,
}

/// The compiled kernels for one device.
#[derive(Debug)]
pub struct PoissonKernels {
    layout: wgpu::BindGroupLayout,
    smooth_red: wgpu::ComputePipeline,
    smooth_black: wgpu::ComputePipeline,
    smooth_nine: [wgpu::ComputePipeline; 4],
    smooth_special: [wgpu::ComputePipeline; 4],
    residual: wgpu::ComputePipeline,
    residual_nine: wgpu::ComputePipeline,
    residual_special: wgpu::ComputePipeline,
    restrict: wgpu::ComputePipeline,
    prolong: wgpu::ComputePipeline,
    zero: wgpu::ComputePipeline,
}

/// A hierarchy on the device: per level its parameters, unknowns, right-hand side, mask and
/// residual buffers, and the bind group that also binds the next coarser level.
#[derive(Debug)]
pub struct GpuHierarchy {
    params: Vec<GpuPoissonParams>,
    buffers: Vec<[wgpu::Buffer; 4]>,
    bind_groups: Vec<wgpu::BindGroup>,
    /// Special stencils per level (0 on the finest level).
    specials: Vec<u32>,
}

impl GpuHierarchy {
    /// Number of levels.
    pub fn level_count(&self) -> usize {
        self.params.len()
    }
}

impl PoissonKernels {
    /// Compiles `poisson.wgsl` and builds its pipelines.
    ///
    /// # Errors
    /// If shader compilation or pipeline creation reports an error.
    pub fn new(device: &wgpu::Device) -> anyhow::Result<Self> {
        let scopes = Scopes::push(device);
        let (r, w) = (Binding::Read, Binding::ReadWrite);
        let program = Program::new(
            device,
            "strata poisson.wgsl",
            POISSON_WGSL,
            &[Binding::Uniform, w, w, r, w, w, w, r, r],
        );
        let pipeline = |name: &str| program.pipeline(device, name);
        let kernels = Self {
            smooth_red: pipeline("smooth_red"),
            smooth_black: pipeline("smooth_black"),
            smooth_nine: ["00", "01", "10", "11"].map(|c| pipeline(&format!("smooth_nine_{c}"))),
            smooth_special: ["00", "01", "10", "11"]
                .map(|c| pipeline(&format!("smooth_special_{c}"))),
            residual: pipeline("residual"),
            residual_nine: pipeline("residual_nine"),
            residual_special: pipeline("residual_special"),
            restrict: pipeline("restrict_residual"),
            prolong: pipeline("prolong"),
            zero: pipeline("zero_h"),
            layout: program.layout,
        };
        scopes.pop().context("compiling shaders/poisson.wgsl")?;
        Ok(kernels)
    }

    /// Copies `levels` (finest first, each the coarsening of the previous) to the device, in
    /// `f32`.
    ///
    /// # Errors
    /// If there are no levels, a buffer would exceed [`MAX_BUFFER_BYTES`], or the device reports
    /// an error.
    pub fn upload(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        levels: &[Level],
    ) -> anyhow::Result<GpuHierarchy> {
        if levels.is_empty() {
            bail!("no levels to upload");
        }
        let bytes = 2 * levels[0].split.len() as u64 * 4;
        if bytes > MAX_BUFFER_BYTES {
            bail!(
                "a {}×{} level needs {bytes}-byte buffers; at most {MAX_BUFFER_BYTES} are allowed",
                levels[0].grid.nx,
                levels[0].grid.nz
            );
        }
        let scopes = Scopes::push(device);
        let make = |label: &str, contents: &[u8], usage: wgpu::BufferUsages| {
            upload(device, queue, label, contents, usage)
        };
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC;
        let f32s = |a: &[Vec<f64>; 2]| -> Vec<f32> {
            a[0].iter().chain(&a[1]).map(|v| *v as f32).collect()
        };
        let mut params = Vec::new();
        let mut buffers = Vec::new();
        let mut uniforms = Vec::new();
        let mut stencils = Vec::new();
        let mut specials = Vec::new();
        for (l, level) in levels.iter().enumerate() {
            let p = GpuPoissonParams::of(level, levels.get(l + 1));
            let free: Vec<u32> = level.free[0]
                .iter()
                .chain(&level.free[1])
                .map(|f| u32::from(*f))
                .collect();
            let zeros = vec![0.0f32; 2 * level.split.len()];
            buffers.push([
                make("poisson h", bytemuck::cast_slice(&f32s(&level.h)), storage),
                make(
                    "poisson rhs",
                    bytemuck::cast_slice(&f32s(&level.rhs)),
                    storage,
                ),
                make("poisson free", bytemuck::cast_slice(&free), storage),
                make("poisson residual", bytemuck::cast_slice(&zeros), storage),
            ]);
            let words = stencil_words(level);
            specials.push(((words.len() - 10) / 11) as u32);
            stencils.push(make(
                "poisson stencils",
                bytemuck::cast_slice(&words),
                storage,
            ));
            uniforms.push(make(
                "poisson params",
                bytemuck::bytes_of(&p),
                wgpu::BufferUsages::UNIFORM,
            ));
            params.push(p);
        }
        // The coarsest level binds small dummies in the coarse slots (a buffer may not be bound
        // twice as writable storage).
        let dummies: [wgpu::Buffer; 3] =
            std::array::from_fn(|_| make("poisson dummy", &[0u8; 16], storage));
        let bind_groups = (0..levels.len())
            .map(|l| {
                let [h, rhs, free, res] = &buffers[l];
                let (hc, rhsc, freec) = match buffers.get(l + 1) {
                    Some([h, r, f, _]) => (h, r, f),
                    None => (&dummies[0], &dummies[1], &dummies[2]),
                };
                let list = [
                    &uniforms[l],
                    h,
                    rhs,
                    free,
                    res,
                    hc,
                    rhsc,
                    freec,
                    &stencils[l],
                ];
                bind_group(device, &self.layout, "strata poisson level", &list)
            })
            .collect();
        scopes.pop().context("uploading the Poisson hierarchy")?;
        Ok(GpuHierarchy {
            params,
            buffers,
            bind_groups,
            specials,
        })
    }

    /// Records `ops` into one compute pass and waits for them.
    ///
    /// # Errors
    /// If an op names a level out of range (or a coarser level that does not exist), or the
    /// device reports an error or times out.
    pub fn run(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        hier: &GpuHierarchy,
        ops: &[Op],
    ) -> anyhow::Result<()> {
        let n = hier.level_count();
        for op in ops {
            let (l, needs_coarse) = match *op {
                Op::SmoothRed(l)
                | Op::SmoothBlack(l)
                | Op::SmoothNine(l, _, _)
                | Op::Residual(l)
                | Op::Zero(l) => (l, false),
                Op::Restrict(l) | Op::Prolong(l) => (l, true),
            };
            if l >= n || (needs_coarse && l + 1 >= n) {
                bail!("{op:?} is out of range for a hierarchy of {n} levels");
            }
            let nine = l > 0;
            match *op {
                Op::SmoothRed(_) | Op::SmoothBlack(_) if nine => {
                    bail!("{op:?}: level {l} has a 9-point operator (use SmoothNine)")
                }
                Op::SmoothNine(_, c, p) if !nine || c > 1 || p > 1 => {
                    bail!("{op:?}: needs a coarse level and colour, parity in 0..=1")
                }
                _ => {}
            }
        }
        let scopes = Scopes::push(device);
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("strata poisson"),
        });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("strata poisson ops"),
                timestamp_writes: None,
            });
            for op in ops {
                let l = match *op {
                    Op::SmoothRed(l)
                    | Op::SmoothBlack(l)
                    | Op::SmoothNine(l, _, _)
                    | Op::Residual(l)
                    | Op::Restrict(l)
                    | Op::Prolong(l)
                    | Op::Zero(l) => l,
                };
                let p = hier.params[l];
                let specials = hier.specials[l];
                // (pipeline, x groups, y groups) of each dispatch of the op.
                let mut dispatches: Vec<(&wgpu::ComputePipeline, u32, u32)> = Vec::new();
                let grid = p.stride.div_ceil(WORKGROUP);
                match *op {
                    Op::SmoothRed(_) => dispatches.push((&self.smooth_red, grid, p.nz)),
                    Op::SmoothBlack(_) => dispatches.push((&self.smooth_black, grid, p.nz)),
                    Op::SmoothNine(_, c, par) => {
                        dispatches.push((&self.smooth_nine[2 * c + par], grid, p.nz.div_ceil(2)));
                        if specials > 0 {
                            dispatches.push((
                                &self.smooth_special[2 * c + par],
                                specials.div_ceil(WORKGROUP),
                                1,
                            ));
                        }
                    }
                    Op::Residual(_) if l > 0 => {
                        dispatches.push((&self.residual_nine, grid, p.nz));
                        if specials > 0 {
                            dispatches.push((
                                &self.residual_special,
                                specials.div_ceil(WORKGROUP),
                                1,
                            ));
                        }
                    }
                    Op::Residual(_) => dispatches.push((&self.residual, grid, p.nz)),
                    Op::Restrict(_) => {
                        dispatches.push((&self.restrict, p.cnx.div_ceil(WORKGROUP), p.cnz))
                    }
                    Op::Prolong(_) => dispatches.push((&self.prolong, grid, p.nz)),
                    Op::Zero(_) => dispatches.push((&self.zero, grid, p.nz)),
                }
                for (pipeline, x, y) in dispatches {
                    pass.set_pipeline(pipeline);
                    pass.set_bind_group(0, &hier.bind_groups[l], &[]);
                    pass.dispatch_workgroups(x, y, 1);
                }
            }
        }
        let submission = queue.submit([encoder.finish()]);
        let polled = device.poll(wgpu::PollType::Wait {
            submission_index: Some(submission),
            timeout: Some(JOB_TIMEOUT),
        });
        let scoped = scopes.pop();
        polled.map_err(|e| anyhow!("waiting for the device: {e}"))?;
        scoped
    }

    /// Reads one array of level `level` back as two colour arrays.
    ///
    /// # Errors
    /// If the level is out of range, or the device reports an error, times out or fails to map.
    pub fn read(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        hier: &GpuHierarchy,
        level: usize,
        field: GpuField,
    ) -> anyhow::Result<[Vec<f32>; 2]> {
        let bufs = hier
            .buffers
            .get(level)
            .ok_or_else(|| anyhow!("level {level} of {}", hier.level_count()))?;
        let src = match field {
            GpuField::H => &bufs[0],
            GpuField::Rhs => &bufs[1],
            GpuField::Residual => &bufs[3],
        };
        let len = hier.params[level].len as usize;
        let size = (2 * len * 4) as u64;
        let scopes = Scopes::push(device);
        let readback = readback(device, "poisson readback", size);
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("strata poisson read"),
        });
        encoder.copy_buffer_to_buffer(src, 0, &readback, 0, size);
        let submission = queue.submit([encoder.finish()]);
        let data: Vec<f32> = read_back(device, &readback, submission, Some(JOB_TIMEOUT), scopes)?;
        let (a, b) = data.split_at(len);
        Ok([a.to_vec(), b.to_vec()])
    }

    /// The ops of one finest-level cycle on a hierarchy of `levels` levels, as the CPU's
    /// `multigrid::Solver` runs it: residual and restriction, zeroed coarse unknowns, the coarse
    /// cycle(s), prolongation, `pre_smooth + post_smooth` sweeps.
    pub fn cycle_ops(levels: usize, options: &SolveOptions) -> Vec<Op> {
        let mut ops = Vec::new();
        let sweep = |ops: &mut Vec<Op>, l: usize, n: usize| {
            for _ in 0..n {
                ops.push(Op::SmoothRed(l));
                ops.push(Op::SmoothBlack(l));
            }
        };
        if levels == 1 {
            sweep(&mut ops, 0, options.pre_smooth + options.post_smooth);
            return ops;
        }
        fn coarse(ops: &mut Vec<Op>, l: usize, levels: usize, o: &SolveOptions) {
            let sweep = |ops: &mut Vec<Op>, n: usize| {
                for _ in 0..n {
                    for (c, p) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                        ops.push(Op::SmoothNine(l, c, p));
                    }
                }
            };
            if l + 1 == levels {
                sweep(ops, COARSEST_SWEEPS);
                return;
            }
            sweep(ops, o.pre_smooth);
            ops.extend([Op::Residual(l), Op::Restrict(l), Op::Zero(l + 1)]);
            for _ in 0..gamma(o.cycle) {
                coarse(ops, l + 1, levels, o);
            }
            ops.push(Op::Prolong(l));
            sweep(ops, o.post_smooth);
        }
        ops.extend([Op::Residual(0), Op::Restrict(0), Op::Zero(1)]);
        for _ in 0..gamma(options.cycle) {
            coarse(&mut ops, 1, levels, options);
        }
        ops.push(Op::Prolong(0));
        sweep(&mut ops, 0, options.pre_smooth + options.post_smooth);
        ops
    }

    /// Runs `cycles` finest-level cycles on the device from the state of `levels` (the finest
    /// level's unknowns are the start, its fixed samples the constraints) and returns the finest
    /// unknowns as two colour arrays.
    ///
    /// # Errors
    /// As [`Self::upload`], [`Self::run`] and [`Self::read`].
    pub fn solve(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        levels: &[Level],
        cycles: usize,
        options: &SolveOptions,
    ) -> anyhow::Result<[Vec<f32>; 2]> {
        let hier = self.upload(device, queue, levels)?;
        let one = Self::cycle_ops(levels.len(), options);
        for _ in 0..cycles {
            self.run(device, queue, &hier, &one)?;
        }
        self.read(device, queue, &hier, 0, GpuField::H)
    }
}

/// The words of a level's `stencils` buffer (see `shaders/poisson.wgsl`): the default stencil and
/// its inverse centre, then per special sample its two-colour index, stencil and inverse centre,
/// as `f32` bits. The finest level (5-point) gets a zero default.
pub fn stencil_words(level: &Level) -> Vec<u32> {
    let bits = |v: f64| (v as f32).to_bits();
    let mut words = vec![0u32; 10];
    if let Some(op) = &level.nine {
        for (w, v) in words.iter_mut().zip(op.default) {
            *w = bits(v);
        }
        words[9] = bits(op.inv_default);
        for sp in &op.special {
            words.push((sp.colour * level.split.len() + sp.slot) as u32);
            words.extend(sp.stencil.iter().map(|v| bits(*v)));
            words.push(bits(sp.inv_centre));
        }
    }
    words
}

fn gamma(c: Cycle) -> usize {
    match c {
        Cycle::V => 1,
        Cycle::W => 2,
    }
}
