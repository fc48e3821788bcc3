//! The `earth-1` height kernel and river carve: `terrain::earth::field` on a wgpu device.
//!
//! [`EarthKernels`] holds the compute pipelines of `shaders/earth.wgsl` and `shaders/rivers.wgsl`.
//! The first runs one invocation per sample: the macro fields, the LOD's relief layers and gully
//! layers of `terrain::earth::kernel`. The biome weights (the climate: `earth::climate::weights`,
//! a Voronoi map on a 4 km lattice with an elevation lapse and a blur) stay on the CPU: the host
//! computes them, derives each sample's erosion strength and roughness from them exactly as
//! `earth::field` does, and uploads those two numbers per sample; the returned field's weights
//! are the CPU's, bit for bit. At LODs with a lattice split (`earth::lattice`) the host also
//! computes the nodes (`lattice::nodes`, one per 16² LOD-0 samples) and uploads them; the kernel
//! interpolates them and evaluates the layers after the split's prefix.
//!
//! Where the world has rivers and the LOD carves them (`rivers::MAX_CARVE_LOD`), the second
//! pipeline, `shaders/rivers.wgsl`, carves the heights in place in the same command encoder,
//! before they are copied out: the twin of `earth::carve` (`rivers::RiverJob::carve_one`, which the CPU reaches through
//! `RiverJob::pruned` bins), one
//! invocation per sample. The river job (the drainage network, its pieces and their bins) is
//! built on the CPU by `rivers::job_for`, as `earth::field` builds it, and uploaded: the pieces as
//! `rivers::Piece` itself, the bins in their CSR form, and the bin grid in
//! [`GpuCarveParams`].
//!
//! The kernel constants of `earth::kernel` and of the carve have one source of truth, the Rust
//! constants: the host prepends a preamble of `const NAME: f32 = …;` lines ([`constants_wgsl`])
//! to both shader sources, each literal the shortest decimal of the `f32` widened to `f64`, which
//! WGSL reads as that `f64` exactly and converts to the same `f32` without rounding. Retuning a
//! number (or the layer lists of `earth::EarthPlan`, which are uploaded per job) needs no change
//! here.
//!
//! Like [`super::tile::TileKernels`], every job runs inside error scopes, waits for its
//! submission with a timeout, checks the mapping, and reports any failure as an `Err`.

use super::kit::{bind_group, dispatch_linear, read_back, readback, storage, upload};
use super::kit::{Binding, Program};
use super::layout::{GpuCarveParams, GpuEarthLayer, GpuEarthOctave, GpuEarthParams, LAKE_NONE};
use super::scopes::Scopes;
use super::tile::{COMMON_WGSL, MAX_BUFFER_BYTES};
use crate::terrain::earth::rivers::{self, Piece, RiverJob};
use crate::terrain::earth::{climate, kernel, lattice, EarthPlan};
use crate::terrain::tile::{Field, FieldJob};
use crate::terrain::WorldPlan;
use anyhow::{anyhow, bail, Context};
use std::fmt::Write;
use std::time::Duration;

/// `shaders/earth.wgsl`: bindings and entry point of the `earth-1` heights (needs the constants
/// preamble and `common.wgsl`).
pub const EARTH_WGSL: &str = include_str!("../../shaders/earth.wgsl");

/// `shaders/rivers.wgsl`: bindings and entry point of the river carve (needs the constants
/// preamble and `common.wgsl`).
pub const RIVERS_WGSL: &str = include_str!("../../shaders/rivers.wgsl");

/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;

/// The `f32` constants `earth.wgsl` and `rivers.wgsl` read, by WGSL name: the named constants of
/// `earth::kernel`, then the literals inside its functions and those of `earth::trig` (which
/// have no Rust name; they are repeated here, and the twin tests notice if they drift), then the
/// named constants of the river carve.
pub fn constants() -> Vec<(&'static str, f32)> {
    use kernel as k;
    vec![
        ("DAMPING", k::DAMPING),
        ("RIDGE_EPS2", k::RIDGE_EPS2),
        ("GULLY_SLOPE", k::GULLY_SLOPE),
        ("GRADIENT_SCALE", k::GRADIENT_SCALE),
        ("LAND_EDGE_0", k::LAND_EDGE.0),
        ("LAND_EDGE_1", k::LAND_EDGE.1),
        ("BELT_EPS2", k::BELT_EPS2),
        ("BELT_LAND_0", k::BELT_LAND.0),
        ("BELT_LAND_1", k::BELT_LAND.1),
        ("HILLS_EDGE_0", k::HILLS_EDGE.0),
        ("HILLS_EDGE_1", k::HILLS_EDGE.1),
        ("RIDGE_EDGE_0", k::RIDGE_EDGE.0),
        ("RIDGE_EDGE_1", k::RIDGE_EDGE.1),
        ("HILL_RIDGE", k::HILL_RIDGE),
        ("COAST_M", k::COAST_M),
        ("INTERIOR_C", k::INTERIOR_C),
        ("SHELF_M", k::SHELF_M),
        ("SHELF_C", k::SHELF_C),
        ("ABYSS_C", k::ABYSS_C),
        ("UPLIFT", k::UPLIFT),
        ("VALLEY_FLOOR", k::VALLEY_FLOOR),
        ("INCISE_EPS", k::INCISE_EPS),
        ("INCISE_MEAN", k::INCISE_MEAN),
        ("INCISE_NORM", k::INCISE_NORM),
        // `kernel::gullies`: `inv_sqrt(g2 + 1e-12)` and `inv_sqrt(max(c² + s², floor²) + 1e-6)`.
        ("GULLY_G_EPS", 1e-12),
        ("GULLY_N_EPS", 1e-6),
        // `trig::sincos_turns`.
        ("TAU", std::f32::consts::TAU),
        ("TRIG_S3", 1.0 / 6.0),
        ("TRIG_S5", 1.0 / 120.0),
        ("TRIG_S7", 1.0 / 5040.0),
        ("TRIG_C4", 1.0 / 24.0),
        ("TRIG_C6", 1.0 / 720.0),
        // `rivers::RiverJob::carve_one` and `rivers::profile`.
        ("CARVE_MAX_M", rivers::CARVE_MAX_M),
        ("PIECE_LEN2_EPS", rivers::PIECE_LEN2_EPS),
        ("WALL_NOISE_INV_M", rivers::WALL_NOISE_INV_M),
        ("WALL_NOISE_CLAMP", rivers::WALL_NOISE_CLAMP),
        // `rivers::RiverJob::shore` (`rivers::shores`).
        ("SHORE_NOISE_INV_M", rivers::SHORE_NOISE_INV_M),
        ("SHORE_NOISE2_INV_M", rivers::SHORE_NOISE2_INV_M),
        ("SHORE_NOISE_CLAMP", rivers::SHORE_NOISE_CLAMP),
        ("SHORE_GENTLE_M", rivers::SHORE_GENTLE_M),
        ("SHORE_STEEP_M", rivers::SHORE_STEEP_M),
        ("SHORE_FULL", rivers::SHORE_FULL),
        ("SHORE_MAX_M", rivers::SHORE_MAX_M),
        ("SILL_FULL", rivers::SILL_FULL),
        ("SILL_E", rivers::SILL_E),
        ("SINK_FROM", rivers::SINK_FROM),
        ("SINK_SCALE", rivers::SINK_SCALE),
        ("SINK_MAX_M", rivers::SINK_MAX_M),
        ("LAKE_NONE", LAKE_NONE),
    ]
}

/// The WGSL preamble of [`constants`]: one `const NAME: f32 = literal;` per constant. The
/// literal is the shortest decimal that reads back as the `f32` widened to `f64`: WGSL parses it
/// as that abstract float exactly, and the conversion to `f32` is then exact.
pub fn constants_wgsl() -> String {
    let mut s = String::from(
        "// Generated by strata::gpu::earth::constants_wgsl from the Rust constants.\n",
    );
    for (name, value) in constants() {
        // Writing to a String cannot fail.
        let _ = writeln!(s, "const {name}: f32 = {:e};", value as f64);
    }
    s
}

/// The WGSL source of the earth kernel: the constants preamble, `common.wgsl`, `earth.wgsl`.
pub fn earth_shader_source() -> String {
    format!("{}\n{COMMON_WGSL}\n{EARTH_WGSL}", constants_wgsl())
}

/// The WGSL source of the river carve: the constants preamble, `common.wgsl`, `rivers.wgsl`.
pub fn rivers_shader_source() -> String {
    format!("{}\n{COMMON_WGSL}\n{RIVERS_WGSL}", constants_wgsl())
}

/// The earth plan of an `earth-1` world.
fn earth_plan(plan: &WorldPlan) -> anyhow::Result<&EarthPlan> {
    plan.earth
        .as_ref()
        .ok_or_else(|| anyhow!("not an earth-1 world: its field runs on the tile kernels"))
}

/// Geometry and constants of one field job, as uploaded to `EarthParams`.
///
/// # Errors
/// If the world is not `earth-1`, the LOD does not exist, the rectangle is empty or too large,
/// or a lattice index of the job does not fit in `i32` (within the supported world it does).
pub fn earth_params(plan: &WorldPlan, job: FieldJob) -> anyhow::Result<GpuEarthParams> {
    let earth = earth_plan(plan)?;
    let FieldJob {
        lod,
        gx0,
        gz0,
        w,
        h,
    } = job;
    let lp = plan
        .lods
        .get(lod as usize)
        .ok_or_else(|| anyhow!("LOD {lod} is not in the plan"))?;
    let el = earth
        .lods
        .get(lod as usize)
        .ok_or_else(|| anyhow!("LOD {lod} is not in the earth plan"))?;
    if w == 0 || h == 0 || w > 4096 || h > 4096 {
        bail!("field of {w}×{h} samples; each side must be in 1..=4096");
    }
    for g in [gx0, gz0, gx0 + w as i64 - 1, gz0 + h as i64 - 1] {
        if i32::try_from(g).is_err() {
            bail!("lattice index {g} does not fit in i32 (rectangle at {gx0}, {gz0} of LOD {lod})");
        }
    }
    let biggest = (w * h * 8) as u64;
    if biggest > MAX_BUFFER_BYTES {
        bail!("field of {w}×{h} needs a {biggest}-byte buffer; at most {MAX_BUFFER_BYTES} are allowed");
    }
    let m = &earth.macro_plan;
    let count = |v: &Vec<_>| v.len() as u32;
    let (lattice_step, prefix, node_i0, node_k0, nodes_w) = match el.lattice {
        Some(lat) => {
            let (i0, k0, nw, _) = lattice::node_window(job, lat.step);
            let int = |v: i64| {
                i32::try_from(v).map_err(|_| anyhow!("node index {v} does not fit in i32"))
            };
            (
                lat.step as u32,
                lat.prefix as u32,
                int(i0)?,
                int(k0)?,
                nw as u32,
            )
        }
        None => (0, 0, 0, 0, 0),
    };
    Ok(GpuEarthParams {
        gx0: gx0 as i32,
        gz0: gz0 as i32,
        w: w as u32,
        h: h as u32,
        spacing: lp.spacing_m,
        rounding_key: 0,
        layer_count: el.layers.len() as u32,
        warp_x_count: count(&m.warp_x),
        warp_z_count: count(&m.warp_z),
        continent_count: count(&m.continent),
        belt_count: count(&m.belt),
        hills_count: count(&m.hills),
        land_bias: m.land_bias,
        origin_land: m.origin_land,
        inv_origin_r2: m.inv_origin_r2,
        belt_width: m.belt_width,
        mountain_relief_m: m.mountain_relief_m,
        hill_relief_m: m.hill_relief_m,
        plain_relief_m: m.plain_relief_m,
        seafloor_relief_m: m.seafloor_relief_m,
        interior_height_m: m.interior_height_m,
        ocean_depth_m: m.ocean_depth_m,
        inv_relief_max: earth.inv_relief_max,
        lattice_step,
        prefix,
        node_i0,
        node_k0,
        nodes_w,
        _pad0: 0,
        _pad1: 0,
        _pad2: 0,
    })
}

/// The uniform of the river carve of a field job over its river job `rj`: the rectangle of
/// `params` (the job's [`earth_params`]) and the bin grid of `rj`, with no bins when `rj` has
/// none (`bin_start` empty, as in `RiverJob::default()`), so that no sample reads a bin.
///
/// # Errors
/// If `rj`'s bins are not `bins_w · bins_h` ranges in CSR form, or its pieces or bins need a
/// buffer larger than [`MAX_BUFFER_BYTES`] (the job then does not run on the device).
pub fn carve_params(params: &GpuEarthParams, rj: &RiverJob) -> anyhow::Result<GpuCarveParams> {
    for (what, bytes) in [
        ("pieces", std::mem::size_of_val(rj.pieces.as_slice())),
        (
            "bin offsets",
            std::mem::size_of_val(rj.bin_start.as_slice()),
        ),
        (
            "bin entries",
            std::mem::size_of_val(rj.bin_pieces.as_slice()),
        ),
    ] {
        if bytes as u64 > MAX_BUFFER_BYTES {
            bail!("the river {what} need a {bytes}-byte buffer; at most {MAX_BUFFER_BYTES} are allowed");
        }
    }
    let (bins_w, bins_h) = if rj.bin_start.is_empty() {
        (0, 0)
    } else {
        let bins = rj.bins_w.checked_mul(rj.bins_h);
        if bins.and_then(|b| b.checked_add(1)) != Some(rj.bin_start.len()) {
            bail!(
                "a river job of {}×{} bins has {} bin offsets",
                rj.bins_w,
                rj.bins_h,
                rj.bin_start.len()
            );
        }
        // Within MAX_BUFFER_BYTES of offsets, both counts and their product fit in u32.
        (rj.bins_w as u32, rj.bins_h as u32)
    };
    // The lake window, empty (0 × 0) when no lake is near.
    let (li0, lk0, lakes_w, lakes_h) = if rj.lakes.is_empty() {
        (0, 0, 0, 0)
    } else {
        let rows = rj.lakes.len() / rj.lakes_w.max(1);
        if rows * rj.lakes_w != rj.lakes.len() {
            bail!(
                "a lake window of {} columns has {} levels",
                rj.lakes_w,
                rj.lakes.len()
            );
        }
        let index = |v: i64| {
            i32::try_from(v)
                .map_err(|_| anyhow!("lake node index {v} is out of the device's range"))
        };
        let count = |v: usize| {
            u32::try_from(v).map_err(|_| anyhow!("a lake window of {v} nodes is too large"))
        };
        (
            index(rj.li0)?,
            index(rj.lk0)?,
            count(rj.lakes_w)?,
            count(rows)?,
        )
    };
    Ok(GpuCarveParams {
        gx0: params.gx0,
        gz0: params.gz0,
        w: params.w,
        h: params.h,
        spacing: params.spacing,
        rounding_key: 0,
        x0: rj.x0,
        z0: rj.z0,
        bin_m: rj.bin_m,
        bins_w,
        bins_h,
        wall_noise: rj.wall_noise,
        wall_seed: rj.wall_seed,
        node_spacing: rj.spacing_m,
        li0,
        lk0,
        lakes_w,
        lakes_h,
        shores: u32::from(rj.shores),
        shore_seed0: rj.shore_seeds[0],
        shore_seed1: rj.shore_seeds[1],
        shore_seed2: rj.shore_seeds[2],
        shore_seed3: rj.shore_seeds[3],
        shore_warp_m: rj.shore_warp_m,
        shore_warp_inv_m: rj.shore_warp_inv_m,
        sills: u32::from(rj.sills),
        shore_n1: rj.shore_n[0],
        shore_n2: rj.shore_n[1],
        sink: u32::from(rj.sink && lakes_w > 0),
    })
}

/// `v`, or `pad` when `v` is empty: a storage array binding must hold at least one element.
fn or_pad<'a, T>(v: &'a [T], pad: &'a [T; 1]) -> &'a [T] {
    if v.is_empty() {
        pad
    } else {
        v
    }
}

/// The macro octaves in the order `earth.wgsl` reads them: warp x, warp z, continent, belt, hills.
fn macro_octaves(earth: &EarthPlan) -> Vec<GpuEarthOctave> {
    let m = &earth.macro_plan;
    [&m.warp_x, &m.warp_z, &m.continent, &m.belt, &m.hills]
        .into_iter()
        .flatten()
        .map(GpuEarthOctave::from)
        .collect()
}

/// The compiled pipelines of `earth.wgsl` and `rivers.wgsl`, for one device.
#[derive(Debug)]
pub struct EarthKernels {
    layout: wgpu::BindGroupLayout,
    heights: wgpu::ComputePipeline,
    carve_layout: wgpu::BindGroupLayout,
    carve: wgpu::ComputePipeline,
}

impl EarthKernels {
    /// Compiles the preamble + `common.wgsl` + `earth.wgsl`, and the preamble + `common.wgsl` +
    /// `rivers.wgsl`, and builds their pipelines.
    ///
    /// # Errors
    /// If shader compilation or pipeline creation reports an error.
    pub fn new(device: &wgpu::Device) -> anyhow::Result<Self> {
        let scopes = Scopes::push(device);
        // Both programs bind a uniform, three read-only arrays, the heights and one more
        // read-only array: the lattice split's nodes (earth) or the lake levels (carve).
        let bindings = [
            Binding::Uniform,
            Binding::Read,
            Binding::Read,
            Binding::Read,
            Binding::ReadWrite,
            Binding::Read,
        ];
        let program = Program::new(
            device,
            "strata earth.wgsl",
            &earth_shader_source(),
            &bindings,
        );
        let carve = Program::new(
            device,
            "strata rivers.wgsl",
            &rivers_shader_source(),
            &bindings,
        );
        let kernels = Self {
            heights: program.pipeline(device, "earth_heights"),
            layout: program.layout,
            carve: carve.pipeline(device, "river_carve"),
            carve_layout: carve.layout,
        };
        scopes
            .pop()
            .context("compiling shaders/earth.wgsl and shaders/rivers.wgsl")?;
        Ok(kernels)
    }

    /// Heights and biome weights of the lattice samples `(gx0 + i, gz0 + j)`, `i < w`, `j < h`, of
    /// LOD `lod` of an `earth-1` world: the twin of [`crate::terrain::earth::field`] (heights and
    /// their river carve on the device, weights and the river job on the CPU; tolerance in
    /// `tests/gpu_earth.rs`). `timeout` bounds the wait for the device (`None`: wait
    /// indefinitely).
    ///
    /// # Errors
    /// If the job is out of range ([`earth_params`]), its river job is too large
    /// ([`carve_params`]), or the device reports an error, times out, is lost or fails to map the
    /// result.
    pub fn field(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        plan: &WorldPlan,
        job: FieldJob,
        timeout: Option<Duration>,
    ) -> anyhow::Result<Field> {
        let params = earth_params(plan, job)?;
        let earth = earth_plan(plan)?;
        let spacing = plan.lods[job.lod as usize].spacing_m;
        let n = job.w * job.h;
        let (weights, window) = climate::weights_and_macro(earth, spacing, job);
        let snow_line = climate::sea_snow_lines(spacing, job, &window);
        let relief: Vec<[f32; 2]> = lattice::relief_of(earth, &weights)
            .into_iter()
            .map(|(e, r)| [e, r])
            .collect();
        // The nodes of the LOD's lattice split, computed here as the climate weights are (one
        // node per 16² samples at LOD 0), or one unread node.
        let nodes = match earth.lods[job.lod as usize].lattice {
            Some(lat) => lattice::nodes(earth, job.lod as usize, spacing, lat, job).values,
            None => vec![[0.0f32; lattice::NODE_FIELDS]],
        };
        let octaves = macro_octaves(earth);
        let mut layers: Vec<GpuEarthLayer> = earth.lods[job.lod as usize]
            .layers
            .iter()
            .map(GpuEarthLayer::from)
            .collect();
        // A storage array binding must hold at least one element; `layer_count` stays 0.
        if layers.is_empty() {
            layers.push(GpuEarthLayer::default());
        }
        // The river job of the carve, as `earth::field` builds it.
        let river = match earth.carve_plan(job.lod as usize) {
            Some(rp) => {
                let rj = rivers::job_for(earth, rp, spacing, job.gx0, job.gz0, job.w, job.h);
                let cp = carve_params(&params, &rj)?;
                Some((rj, cp))
            }
            None => None,
        };

        let scopes = Scopes::push(device);
        let init = |label: &str, contents: &[u8], usage: wgpu::BufferUsages| {
            upload(device, queue, label, contents, usage)
        };
        let storage_usage = wgpu::BufferUsages::STORAGE;
        let params_buf = init(
            "earth params",
            bytemuck::bytes_of(&params),
            wgpu::BufferUsages::UNIFORM,
        );
        let octave_buf = init(
            "earth octaves",
            bytemuck::cast_slice(&octaves),
            storage_usage,
        );
        let layer_buf = init("earth layers", bytemuck::cast_slice(&layers), storage_usage);
        let node_buf = init("earth nodes", bytemuck::cast_slice(&nodes), storage_usage);
        let relief_buf = init("earth relief", bytemuck::cast_slice(&relief), storage_usage);
        let bytes = n as u64 * 4;
        let heights = storage(device, "earth heights", bytes, wgpu::BufferUsages::COPY_SRC);
        let readback = readback(device, "earth readback", bytes);
        let carve_group = river.as_ref().map(|(rj, cp)| {
            // Empty arrays are uploaded as one element, which nothing reads: a job without
            // pieces has empty bins, and one without bins has `bins_w = bins_h = 0`.
            let (no_piece, no_index) = ([Piece::default()], [0u32]);
            let array = |label: &str, bytes: &[u8]| init(label, bytes, storage_usage);
            let carve_params_buf = init(
                "river carve params",
                bytemuck::bytes_of(cp),
                wgpu::BufferUsages::UNIFORM,
            );
            let piece_buf = array(
                "river pieces",
                bytemuck::cast_slice(or_pad(&rj.pieces, &no_piece)),
            );
            let start_buf = array(
                "river bin offsets",
                bytemuck::cast_slice(or_pad(&rj.bin_start, &no_index)),
            );
            let entry_buf = array(
                "river bin entries",
                bytemuck::cast_slice(or_pad(&rj.bin_pieces, &no_index)),
            );
            // The levels, then the lake nodes' heights where the shores sink the ground
            // (`lakes: 8`), in the same layout.
            let levels: Vec<f32> = rj
                .lakes
                .iter()
                .chain(if cp.sink != 0 { &rj.floors[..] } else { &[] })
                .map(|&l| if l.is_nan() { LAKE_NONE } else { l })
                .collect();
            let lake_buf = array(
                "river lake levels",
                bytemuck::cast_slice(or_pad(&levels, &[LAKE_NONE])),
            );
            bind_group(
                device,
                &self.carve_layout,
                "strata river carve job",
                &[
                    &carve_params_buf,
                    &piece_buf,
                    &start_buf,
                    &entry_buf,
                    &heights,
                    &lake_buf,
                ],
            )
        });
        let bind_group = bind_group(
            device,
            &self.layout,
            "strata earth job",
            &[
                &params_buf,
                &octave_buf,
                &layer_buf,
                &relief_buf,
                &heights,
                &node_buf,
            ],
        );
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("strata earth field"),
        });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: None,
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.heights);
            pass.set_bind_group(0, &bind_group, &[]);
            dispatch_linear(&mut pass, n as u32, WORKGROUP);
        }
        if let Some(carve_group) = &carve_group {
            // A pass of its own: it reads every height the first pass wrote.
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: None,
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.carve);
            pass.set_bind_group(0, carve_group, &[]);
            dispatch_linear(&mut pass, n as u32, WORKGROUP);
        }
        encoder.copy_buffer_to_buffer(&heights, 0, &readback, 0, bytes);
        let submission = queue.submit([encoder.finish()]);
        let data: Vec<u32> = read_back(device, &readback, submission, timeout, scopes)?;
        if data.len() < n {
            bail!("read back {} heights, expected {n}", data.len());
        }
        let heights: Vec<f32> = data[..n].iter().map(|&b| f32::from_bits(b)).collect();
        Ok(Field {
            w: job.w,
            h: job.h,
            heights,
            weights,
            snow_line,
            lake_fields: Vec::new(),
        })
    }
}

/// Convenience for tests and tools: compiles the kernel on `device` and computes one `earth-1`
/// field (no timeout). The device task keeps one [`EarthKernels`] instead.
///
/// # Errors
/// As [`EarthKernels::new`] and [`EarthKernels::field`].
pub fn earth_field_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    plan: &WorldPlan,
    job: FieldJob,
) -> anyhow::Result<Field> {
    EarthKernels::new(device)?.field(device, queue, plan, job, None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_preamble_reads_back_as_the_rust_constants() {
        let pre = constants_wgsl();
        for (name, value) in constants() {
            let head = format!("const {name}: f32 = ");
            let line = pre
                .lines()
                .find(|l| l.starts_with(&head))
                .unwrap_or_else(|| panic!("{name} in the preamble"));
            let lit = line[head.len()..].trim_end_matches(';');
            // WGSL reads the literal as an abstract float (f64), then converts it to f32.
            let wide = lit.parse::<f64>().expect("a float literal");
            assert_eq!(wide, value as f64, "{name}: {lit} is not exactly the f32");
            assert_eq!((wide as f32).to_bits(), value.to_bits(), "{name}");
        }
    }

    #[test]
    fn carve_params_follow_the_river_job() {
        let plan = WorldPlan::new(1, crate::terrain::WorldParams::default()).expect("plan");
        let job = FieldJob::new(6, -33, -33, 67, 67);
        let params = earth_params(&plan, job).expect("params");
        let earth = plan.earth.as_ref().expect("earth");
        let rp = earth.rivers.as_ref().expect("the default world has rivers");
        let spacing = plan.lods[6].spacing_m;
        let rj = rivers::job_for(earth, rp, spacing, job.gx0, job.gz0, job.w, job.h);
        let cp = carve_params(&params, &rj).expect("carve params");
        assert_eq!(
            (cp.gx0, cp.gz0, cp.w, cp.h),
            (params.gx0, params.gz0, params.w, params.h)
        );
        assert_eq!(cp.spacing.to_bits(), spacing.to_bits());
        assert_eq!(cp.rounding_key, 0);
        assert_eq!(
            (cp.x0.to_bits(), cp.z0.to_bits(), cp.bin_m.to_bits()),
            (rj.x0.to_bits(), rj.z0.to_bits(), rj.bin_m.to_bits())
        );
        assert!(cp.bins_w > 0 && cp.bins_h > 0);
        assert_eq!(
            (cp.bins_w as usize, cp.bins_h as usize),
            (rj.bins_w, rj.bins_h)
        );
        // A job without bins reads none: its grid has no bins; without lakes, no lake window.
        let empty = carve_params(&params, &RiverJob::default()).expect("an empty job");
        assert_eq!((empty.bins_w, empty.bins_h), (0, 0));
        assert_eq!((empty.lakes_w, empty.lakes_h), (0, 0));
        // A lake window goes up whole, with the world's shores.
        let mut lake = rj.clone();
        (lake.li0, lake.lk0, lake.lakes_w, lake.lakes) = (-3, 5, 2, vec![f32::NAN, 1.0, 2.0, 3.0]);
        let cp = carve_params(&params, &lake).expect("a lake window");
        assert_eq!(
            (cp.li0, cp.lk0, cp.lakes_w, cp.lakes_h, cp.shores),
            (-3, 5, 2, 2, u32::from(rp.lakes >= 2))
        );
        lake.lakes.pop();
        assert!(
            carve_params(&params, &lake).is_err(),
            "a ragged lake window"
        );
        // Offsets that do not cover the grid would send the device out of the job.
        let mut short = rj.clone();
        short.bin_start.pop();
        assert!(carve_params(&params, &short).is_err());
    }

    #[test]
    fn empty_arrays_are_padded_to_one_element() {
        assert_eq!(or_pad(&[] as &[u32], &[7]), &[7]);
        assert_eq!(or_pad(&[1u32, 2], &[7]), &[1, 2]);
    }

    #[test]
    fn tile_plans_are_refused() {
        let plan = WorldPlan::new(1, crate::terrain::WorldParams::classic()).expect("plan");
        assert!(earth_params(&plan, FieldJob::new(0, 0, 0, 4, 4)).is_err());
        let plan = WorldPlan::new(1, crate::terrain::WorldParams::default()).expect("plan");
        assert!(earth_params(&plan, FieldJob::new(0, 0, 0, 4, 4)).is_ok());
        assert!(earth_params(&plan, FieldJob::new(0, 0, 0, 0, 4)).is_err());
        assert!(earth_params(&plan, FieldJob::new(99, 0, 0, 4, 4)).is_err());
        assert!(earth_params(&plan, FieldJob::new(0, i64::from(i32::MAX), 0, 4, 4)).is_err());
    }
}
