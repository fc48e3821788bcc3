//! The tile-synthesis kernels: `terrain::tile::field` on a wgpu device.
//!
//! [`TileKernels`] holds the four compute pipelines of `shaders/tile.wgsl` (block corners → biome
//! ids → horizontal blur → vertical blur and heights). [`TileKernels::field`] takes the device and
//! queue as arguments, so the device task and the tests (which inject their own device, like
//! wgpu's `hello_compute` example) run the same code. Every job runs inside error scopes, waits for
//! its submission with a timeout and checks the buffer mapping, and reports any failure as an
//! `Err`, never as a panic.

use super::kit::{
    bind_group, dispatch_linear, read_back, readback, storage, upload, Binding, Program,
};
use super::layout::{GpuBiomeMap, GpuFractal, GpuParams};
use super::scopes::Scopes;
use crate::terrain::biome::BLOCK;
use crate::terrain::tile::{Field, FieldJob};
use crate::terrain::world::MAX_BIOMES;
use crate::terrain::WorldPlan;
use anyhow::{anyhow, bail, Context};
use std::time::Duration;

/// `shaders/common.wgsl`: hashing, lattice noise, the warped fractal and the biome functions.
pub const COMMON_WGSL: &str = include_str!("../../shaders/common.wgsl");
/// `shaders/tile.wgsl`: bindings and entry points of tile synthesis (needs `common.wgsl`).
pub const TILE_WGSL: &str = include_str!("../../shaders/tile.wgsl");

/// Invocations per workgroup of every entry point (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// Largest buffer a job may need (WebGPU's default `max_storage_buffer_binding_size`).
pub const MAX_BUFFER_BYTES: u64 = 128 << 20;
/// How long one job may wait for the device before it counts as lost.
pub const DEFAULT_JOB_TIMEOUT: Duration = Duration::from_secs(5);

/// The WGSL source of the tile kernels: `common.wgsl` followed by `tile.wgsl`.
pub fn tile_shader_source() -> String {
    format!("{COMMON_WGSL}\n{TILE_WGSL}")
}

/// Geometry and constants of one field job, as uploaded to `Params`.
///
/// # Errors
/// If the world is `earth-1` (its field runs on [`super::earth::EarthKernels`]), the LOD does
/// not exist, the rectangle is empty or too large, the world has more than
/// [`MAX_BIOMES`] biomes, or a lattice index of the job (including the blur margin and the block
/// corners) does not fit in `i32`: within the supported world (`plan::WORLD_LIMIT_CELLS`) it always
/// does.
pub fn field_params(plan: &WorldPlan, job: FieldJob) -> anyhow::Result<GpuParams> {
    let FieldJob {
        lod,
        gx0,
        gz0,
        w,
        h,
    } = job;
    if plan.earth.is_some() {
        bail!("an earth-1 world: its field runs on the earth kernels, not the tile kernels");
    }
    let lp = plan
        .lods
        .get(lod as usize)
        .ok_or_else(|| anyhow!("LOD {lod} is not in the plan"))?;
    let k = plan.biome_count();
    if k == 0 || k > MAX_BIOMES {
        bail!("{k} biomes; the kernels support 1 to {MAX_BIOMES}");
    }
    if w == 0 || h == 0 || w > 4096 || h > 4096 {
        bail!("field of {w}×{h} samples; each side must be in 1..=4096");
    }
    let taps = lp.kernel.len();
    if taps % 2 != 1 {
        bail!("blur kernel of {taps} taps; expected 2r + 1");
    }
    let r = (taps / 2) as i64;
    let (bw, bh) = (w as i64 + 2 * r, h as i64 + 2 * r);
    let (bgx0, bgz0) = (gx0 - r, gz0 - r);
    let (bx0, bz0) = (bgx0.div_euclid(BLOCK), bgz0.div_euclid(BLOCK));
    let (bx1, bz1) = (
        (bgx0 + bw - 1).div_euclid(BLOCK),
        (bgz0 + bh - 1).div_euclid(BLOCK),
    );
    // The largest lattice index the kernels touch is the far block corner.
    let (cw, ch) = (bx1 - bx0 + 2, bz1 - bz0 + 2);
    for g in [
        bx0 * BLOCK,
        bz0 * BLOCK,
        (bx1 + 1) * BLOCK,
        (bz1 + 1) * BLOCK,
    ] {
        if i32::try_from(g).is_err() {
            bail!("lattice index {g} does not fit in i32 (rectangle at {gx0}, {gz0} of LOD {lod})");
        }
    }
    let biggest = (w as i64 * bh * k as i64)
        .max(bw * bh)
        .max(w as i64 * h as i64 * (k as i64 + 1))
        * 4;
    if biggest > MAX_BUFFER_BYTES as i64 {
        bail!("field of {w}×{h} needs a {biggest}-byte buffer; at most {MAX_BUFFER_BYTES} are allowed");
    }
    let i = |v: i64| v as i32;
    let u = |v: i64| v as u32;
    Ok(GpuParams {
        gx0: i(gx0),
        gz0: i(gz0),
        w: w as u32,
        h: h as u32,
        bgx0: i(bgx0),
        bgz0: i(bgz0),
        bw: u(bw),
        bh: u(bh),
        bx0: i(bx0),
        bz0: i(bz0),
        cw: u(cw),
        ch: u(ch),
        taps: taps as u32,
        k: k as u32,
        spacing: lp.spacing_m,
        rounding_key: 0,
        map: GpuBiomeMap::from(&plan.biome_map),
    })
}

/// The compiled pipelines of `tile.wgsl`, for one device.
#[derive(Debug)]
pub struct TileKernels {
    layout: wgpu::BindGroupLayout,
    block_corners: wgpu::ComputePipeline,
    biome_ids: wgpu::ComputePipeline,
    blur_h: wgpu::ComputePipeline,
    blur_v: wgpu::ComputePipeline,
}

impl TileKernels {
    /// Compiles `common.wgsl` + `tile.wgsl` and builds the four pipelines.
    ///
    /// # Errors
    /// If shader compilation or pipeline creation reports an error.
    pub fn new(device: &wgpu::Device) -> anyhow::Result<Self> {
        let scopes = Scopes::push(device);
        let mut bindings = vec![Binding::Uniform, Binding::Read, Binding::Read];
        bindings.extend([Binding::ReadWrite; 6]);
        let program = Program::new(device, "strata tile.wgsl", &tile_shader_source(), &bindings);
        let pipeline = |entry: &str| program.pipeline(device, entry);
        let kernels = Self {
            block_corners: pipeline("block_corners"),
            biome_ids: pipeline("biome_ids"),
            blur_h: pipeline("blur_h"),
            blur_v: pipeline("blur_v"),
            layout: program.layout,
        };
        scopes.pop().context("compiling shaders/tile.wgsl")?;
        Ok(kernels)
    }

    /// Heights and biome weights of the lattice samples `(gx0 + i, gz0 + j)`, `i < w`, `j < h`, of
    /// LOD `lod`: the twin of [`crate::terrain::tile::field`], within the tolerance stated in
    /// [`crate::gpu`]. `timeout` bounds the wait for the device (`None`: wait indefinitely).
    ///
    /// # Errors
    /// If the job is out of range ([`field_params`]), or the device reports an error, times out,
    /// is lost or fails to map the result.
    #[allow(clippy::too_many_arguments)]
    pub fn field(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        plan: &WorldPlan,
        job: FieldJob,
        timeout: Option<Duration>,
    ) -> anyhow::Result<Field> {
        self.run(device, queue, plan, job, timeout, false)
            .map(|(f, _)| f)
    }

    /// [`Self::field`], plus the biome ids of the job's biome grid: the rectangle grown by the
    /// blur radius `r = kernel.len() / 2` on every side, `(w + 2r) × (h + 2r)` row-major, the
    /// twin of [`crate::terrain::biome::biome_grid`] over that grid. For tests and diagnostics.
    ///
    /// # Errors
    /// As [`Self::field`].
    #[allow(clippy::too_many_arguments)]
    pub fn field_with_ids(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        plan: &WorldPlan,
        job: FieldJob,
        timeout: Option<Duration>,
    ) -> anyhow::Result<(Field, Vec<u8>)> {
        let (f, ids) = self.run(device, queue, plan, job, timeout, true)?;
        Ok((f, ids.unwrap_or_default()))
    }

    /// The field of `job` as [`Self::field`] computes it, and with `want_ids` also the biome ids
    /// of its biome grid as [`Self::field_with_ids`] returns them (`None` without).
    ///
    /// # Errors
    /// As [`Self::field`].
    fn run(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        plan: &WorldPlan,
        job: FieldJob,
        timeout: Option<Duration>,
        want_ids: bool,
    ) -> anyhow::Result<(Field, Option<Vec<u8>>)> {
        let params = field_params(plan, job)?;
        let lp = &plan.lods[job.lod as usize];
        let k = params.k as u64;
        let n = (job.w * job.h) as u64;

        let scopes = Scopes::push(device);
        let fractals: Vec<GpuFractal> = lp.fractals.iter().map(GpuFractal::from).collect();
        let init = |label: &str, contents: &[u8], usage: wgpu::BufferUsages| {
            upload(device, queue, label, contents, usage)
        };
        let scratch = |label: &str, words: u64, extra: wgpu::BufferUsages| {
            storage(device, label, words * 4, extra)
        };
        let params_buf = init(
            "params",
            bytemuck::bytes_of(&params),
            wgpu::BufferUsages::UNIFORM,
        );
        let fractal_buf = init(
            "fractals",
            bytemuck::cast_slice(&fractals),
            wgpu::BufferUsages::STORAGE,
        );
        let kernel_buf = init(
            "kernel",
            bytemuck::cast_slice(&lp.kernel),
            wgpu::BufferUsages::STORAGE,
        );
        let none = wgpu::BufferUsages::empty();
        let corners = scratch("corners", 4 * params.cw as u64 * params.ch as u64, none);
        let id_count = params.bw as u64 * params.bh as u64;
        let id_words = if want_ids { id_count } else { 0 };
        let ids = scratch(
            "ids",
            id_count,
            if want_ids {
                wgpu::BufferUsages::COPY_SRC
            } else {
                none
            },
        );
        let htag = scratch("htag", params.w as u64 * params.bh as u64, none);
        let hdense = scratch("hdense", params.w as u64 * params.bh as u64 * k, none);
        let weights = scratch("weights", n * k, wgpu::BufferUsages::COPY_SRC);
        let heights = scratch("heights", n, wgpu::BufferUsages::COPY_SRC);
        let readback = readback(device, "readback", (n * k + n + id_words) * 4);
        let bind_group = bind_group(
            device,
            &self.layout,
            "strata tile job",
            &[
                &params_buf,
                &fractal_buf,
                &kernel_buf,
                &corners,
                &ids,
                &htag,
                &hdense,
                &weights,
                &heights,
            ],
        );

        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("strata field"),
        });
        let passes = [
            (&self.block_corners, params.cw * params.ch),
            (&self.biome_ids, params.bw * params.bh),
            (&self.blur_h, params.w * params.bh),
            (&self.blur_v, params.w * params.h),
        ];
        // One pass per stage: each dispatch sees the storage writes of the previous one.
        for (pipeline, invocations) in passes {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: None,
                timestamp_writes: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            dispatch_linear(&mut pass, invocations, WORKGROUP);
        }
        encoder.copy_buffer_to_buffer(&weights, 0, &readback, 0, n * k * 4);
        encoder.copy_buffer_to_buffer(&heights, 0, &readback, n * k * 4, n * 4);
        if want_ids {
            encoder.copy_buffer_to_buffer(&ids, 0, &readback, (n * k + n) * 4, id_words * 4);
        }
        let submission = queue.submit([encoder.finish()]);
        let data: Vec<u32> = read_back(device, &readback, submission, timeout, scopes)?;
        let (nk, n) = ((n * k) as usize, n as usize);
        let float = |words: &[u32]| {
            words
                .iter()
                .map(|&b| f32::from_bits(b))
                .collect::<Vec<f32>>()
        };
        let field = Field {
            w: job.w,
            h: job.h,
            heights: float(&data[nk..nk + n]),
            weights: float(&data[..nk]),
            snow_line: Vec::new(),
            lake_fields: Vec::new(),
        };
        let ids = want_ids.then(|| data[nk + n..].iter().map(|&b| b as u8).collect());
        Ok((field, ids))
    }
}

/// Convenience for tests and tools: compiles the kernels on `device` and computes one field (no
/// timeout). The device task keeps one [`TileKernels`] instead.
///
/// # Errors
/// As [`TileKernels::new`] and [`TileKernels::field`].
#[allow(clippy::too_many_arguments)]
pub fn field_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    plan: &WorldPlan,
    job: FieldJob,
) -> anyhow::Result<Field> {
    TileKernels::new(device)?.field(device, queue, plan, job, None)
}
