//! A volume region end to end: proxies → voxelization → normal diffusion → noise diffusion and
//! material propagation → surface propagation → Gaussian filter (Becher §4.1, stages 1–4 and the
//! filter of §4.5), with per-stage times for `strata bench volume`.
//!
//! **Warm start after an edit (§8).** [`regenerate`] takes the previous result: samples whose
//! constraints did not change keep their solution as the initial guess. The region re-solved is
//! the bounding box of the samples whose `Ω_N`/`Ω_R` membership or constraint values changed,
//! grown by `warm_margin` samples; inside it the cascade runs on the box with the previous
//! solution as fixed boundary values on its faces, outside it the previous `N`, `α`, `β` are
//! kept. The surface propagation and the filter (O(n), cheap) always run on the whole grid.
//! Deviation: outside the box the result is the previous one, not a fresh solve; the harmonic
//! influence of a local edit decays with distance, and `warm_margin` bounds what is ignored.

use super::curve::FeatureCurve;
use super::diffuse::{diffuse_normals, harmonic_fill, harmonic_fill_on, DiffuseParams};
use super::filter::gaussian_of;
use super::grid::Grid;
use super::propagate::{propagate_material, propagate_surface};
use super::proxy::{curve_proxy, heightfield_proxy, mesh_proxy, Heightfield, InputMesh};
use super::voxelize::{voxelize, Voxelized};
use super::PipelineError;
use crate::terrain::cancel::Cancel;
use crate::volume::offload::{CpuOnly, VolumeOffload};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Most feature curves in one scene.
pub const MAX_CURVES: usize = 4096;
/// Most input meshes in one scene.
pub const MAX_MESHES: usize = 256;

/// A box of samples `[lo, hi)` per axis.
pub type SampleBox = ([usize; 3], [usize; 3]);

/// The modelling primitives of a region.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Feature curves (highest priority).
    pub curves: Vec<FeatureCurve>,
    /// Input meshes (middle priority).
    pub meshes: Vec<InputMesh>,
    /// The world's heightfield around the region (lowest priority).
    pub heightfield: Option<Heightfield>,
}

/// Parameters of the pipeline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PipelineParams {
    /// Dead-zone radius around higher-priority inputs, metres (§4.2).
    pub dead_zone_m: f32,
    /// Length of a curve proxy segment, metres (`None`: half the grid spacing).
    pub curve_step_m: Option<f32>,
    /// Diffusion solver settings.
    pub diffuse: DiffuseParams,
    /// σ of the Gaussian filter on `S`, samples (0 disables it).
    pub gaussian_sigma: f32,
    /// Samples added around the changed box by [`regenerate`].
    pub warm_margin: usize,
    /// The optional feature-curve expansion of §5.1 ([`super::expand`]); `None` skips it.
    pub expand: Option<super::expand::ExpandParams>,
}

impl Default for PipelineParams {
    fn default() -> Self {
        Self {
            dead_zone_m: 3.0,
            curve_step_m: None,
            diffuse: DiffuseParams::default(),
            gaussian_sigma: 1.0,
            warm_margin: 12,
            expand: None,
        }
    }
}

/// Milliseconds of each stage of one run: wall-clock time ([`RegionFields::times`]) or CPU time
/// of all threads together ([`RegionFields::cpu_times`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StageTimes {
    /// Building proxy triangles.
    pub proxy_ms: f64,
    /// Voxelization (gather, dead zone, average).
    pub voxelize_ms: f64,
    /// Normal (guidance) field diffusion.
    pub normal_diffusion_ms: f64,
    /// Noise-parameter (`α`, `β`) diffusion.
    pub noise_diffusion_ms: f64,
    /// Material propagation with confidence. It runs on one worker concurrently with the normal
    /// diffusion ([`generate`]; with the surface propagation in [`regenerate`]), so it overlaps
    /// that stage.
    pub material_ms: f64,
    /// Surface propagation (on one worker beside the noise diffusion in [`generate`]).
    pub surface_propagation_ms: f64,
    /// Gaussian filter.
    pub filter_ms: f64,
    /// The whole run, end to end (less than the sum of the stages by the overlap).
    pub total_ms: f64,
}

/// Wall-clock and CPU times of a run being recorded.
#[derive(Clone, Copy, Default)]
struct Timing {
    wall: StageTimes,
    cpu: StageTimes,
}

impl Timing {
    /// Records the time since `sw` into the field `f` of both.
    fn record(&mut self, sw: Stopwatch, f: fn(&mut StageTimes) -> &mut f64) {
        let (w, c) = sw.lap();
        *f(&mut self.wall) += w;
        *f(&mut self.cpu) += c;
    }
}

/// The fields of a region after the pipeline.
#[derive(Clone, Debug)]
pub struct RegionFields {
    /// The sample grid.
    pub grid: Grid,
    /// Dense unit normals `N`.
    pub normal: [Vec<f32>; 3],
    /// Voxelized bitangents `B` (sparse: zero where no curve was gathered).
    pub bitangent: [Vec<f32>; 3],
    /// Final signed distance `S`, metres, negative inside the solid.
    pub surface: Vec<f32>,
    /// `S` before the Gaussian filter.
    pub surface_raw: Vec<f32>,
    /// Layer in which the surface propagation set each sample (0 = `Ω_S`).
    pub surface_layer: Vec<u32>,
    /// Noise amplitude `α` per sample.
    pub alpha: Vec<f32>,
    /// Noise roughness `β` per sample.
    pub beta: Vec<f32>,
    /// Material id per sample.
    pub material: Vec<u16>,
    /// Confidence of the material, `[0, 1]`.
    pub confidence: Vec<f32>,
    /// The voxelization's constraints (kept for warm starts and tests).
    pub voxelized: Voxelized,
    /// Wall-clock stage times of the run that produced these fields.
    pub times: StageTimes,
    /// CPU time of each stage, all threads together (process CPU time; for the concurrent
    /// material and surface propagations, each one's thread CPU time).
    pub cpu_times: StageTimes,
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Runs `f` and returns its result with its wall-clock and thread CPU milliseconds.
fn timed_on_thread<T>(f: impl FnOnce() -> T) -> (T, f64, f64) {
    let (w, c) = (Instant::now(), crate::cpu_time::thread_ms());
    let r = f();
    (r, ms(w), crate::cpu_time::thread_ms() - c)
}

/// Wall-clock and process CPU time since a start.
#[derive(Clone, Copy)]
struct Stopwatch {
    wall: Instant,
    cpu: f64,
}

impl Stopwatch {
    fn start() -> Self {
        Self {
            wall: Instant::now(),
            cpu: crate::cpu_time::process_ms(),
        }
    }

    /// `(wall ms, cpu ms)` since the start.
    fn lap(&self) -> (f64, f64) {
        (ms(self.wall), crate::cpu_time::process_ms() - self.cpu)
    }
}

fn build_voxels(
    grid: &Grid,
    scene: &Scene,
    params: &PipelineParams,
    times: &mut Timing,
) -> Result<Voxelized, PipelineError> {
    if scene.curves.len() > MAX_CURVES {
        return Err(PipelineError::invalid(
            "curves",
            format!("at most {MAX_CURVES} curves"),
        ));
    }
    if scene.meshes.len() > MAX_MESHES {
        return Err(PipelineError::invalid(
            "meshes",
            format!("at most {MAX_MESHES} meshes"),
        ));
    }
    if !(params.dead_zone_m.is_finite() && params.dead_zone_m >= 0.0) {
        return Err(PipelineError::invalid(
            "dead_zone_m",
            "must be a non-negative number of metres",
        ));
    }
    let step = params.curve_step_m.unwrap_or(0.5 * grid.spacing);
    if !(step.is_finite() && step > 0.0) {
        return Err(PipelineError::invalid("curve_step_m", "must be positive"));
    }
    let sw = Stopwatch::start();
    let mut curves = Vec::new();
    for (i, c) in scene.curves.iter().enumerate() {
        curves.extend(curve_proxy(c, step).map_err(|e| e.within(&format!("curves[{i}]")))?);
    }
    let mut meshes = Vec::new();
    for (i, m) in scene.meshes.iter().enumerate() {
        meshes.extend(mesh_proxy(m).map_err(|e| e.within(&format!("meshes[{i}]")))?);
    }
    let ground = match &scene.heightfield {
        Some(hf) => {
            let lo = [grid.origin[0], grid.origin[2]];
            let hi = [
                grid.origin[0] + grid.spacing * (grid.dims[0] - 1) as f32,
                grid.origin[2] + grid.spacing * (grid.dims[2] - 1) as f32,
            ];
            heightfield_proxy(hf, lo, hi).map_err(|e| e.within("heightfield"))?
        }
        None => Vec::new(),
    };
    times.record(sw, |t| &mut t.proxy_ms);
    let sw = Stopwatch::start();
    let v = voxelize(grid, &[&curves, &meshes, &ground], params.dead_zone_m);
    times.record(sw, |t| &mut t.voxelize_ms);
    if !v.omega_s.iter().any(|&s| s != 0) {
        return Err(PipelineError::NoSurface);
    }
    Ok(v)
}

/// Material propagation (§4.4) of the voxelized seeds: materials and confidences.
fn material_stage(grid: &Grid, v: &Voxelized) -> (Vec<u16>, Vec<f32>) {
    let mut material = v.material.clone();
    let confidence = propagate_material(grid.dims, &v.omega_r, &mut material);
    (material, confidence)
}

/// Surface propagation (§4.5) from the voxelized seeds along `normal`: `S` and its layers,
/// from `dev` when it answers.
fn surface_stage(
    grid: &Grid,
    v: &Voxelized,
    normal: &[Vec<f32>; 3],
    dev: &dyn VolumeOffload,
) -> (Vec<f32>, Vec<u32>) {
    if let Some(done) = dev.propagate_surface(grid, normal, &v.omega_s, &v.surface) {
        return done;
    }
    let mut s = v.surface.clone();
    let layer = propagate_surface(grid, normal, &v.omega_s, &mut s);
    (s, layer)
}

/// Runs the sequential wavefront `serial` on one worker beside the slab-parallel `parallel` on
/// the rest of the pool, and records both stages: `serial` by its thread's CPU time, `parallel`
/// by the process CPU time of the overlap minus that. Both wall times include the overlap.
fn overlapped<A: Send, B: Send>(
    times: &mut Timing,
    serial: (fn(&mut StageTimes) -> &mut f64, impl FnOnce() -> A + Send),
    parallel: (fn(&mut StageTimes) -> &mut f64, impl FnOnce() -> B + Send),
) -> (A, B) {
    let sw = Stopwatch::start();
    let ((a, aw, ac), (b, bw)) = rayon::join(
        || timed_on_thread(serial.1),
        || {
            let t = Instant::now();
            let b = (parallel.1)();
            (b, ms(t))
        },
    );
    let (_, cpu) = sw.lap();
    *(serial.0)(&mut times.wall) += aw;
    *(serial.0)(&mut times.cpu) += ac;
    *(parallel.0)(&mut times.wall) += bw;
    *(parallel.0)(&mut times.cpu) += (cpu - ac).max(0.0);
    (a, b)
}

/// The Gaussian filter (§4.5) and the assembled fields.
#[allow(clippy::too_many_arguments)]
fn finish(
    grid: &Grid,
    v: Voxelized,
    normal: [Vec<f32>; 3],
    (alpha, beta): (Vec<f32>, Vec<f32>),
    (material, confidence): (Vec<u16>, Vec<f32>),
    (s, surface_layer): (Vec<f32>, Vec<u32>),
    params: &PipelineParams,
    mut times: Timing,
    run: Stopwatch,
) -> RegionFields {
    let sw = Stopwatch::start();
    let surface = gaussian_of(grid.dims, &s, params.gaussian_sigma);
    times.record(sw, |t| &mut t.filter_ms);
    times.record(run, |t| &mut t.total_ms);
    RegionFields {
        grid: *grid,
        normal,
        bitangent: v.bitangent.clone(),
        surface,
        surface_raw: s,
        surface_layer,
        alpha,
        beta,
        material,
        confidence,
        voxelized: v,
        times: times.wall,
        cpu_times: times.cpu,
    }
}

/// Runs the whole pipeline on `grid` for `scene`.
///
/// # Errors
/// [`PipelineError::Invalid`] naming the offending input field; [`PipelineError::NoSurface`]
/// when no seed primitive touches the region.
pub fn generate(
    grid: &Grid,
    scene: &Scene,
    params: &PipelineParams,
) -> Result<RegionFields, PipelineError> {
    generate_on(grid, scene, params, &CpuOnly, &Cancel::never())
}

/// [`generate`] with the twinned stages (Perona–Malik sweeps, surface propagation, smooth
/// bitangents) offered to `dev` ([`crate::volume::offload`]), polling `cancel` between stages:
/// before the voxelization, after it, and after each of the two overlapped pairs of stages.
///
/// # Errors
/// As [`generate`], and [`PipelineError::Cancelled`] once `cancel` is set.
pub fn generate_on(
    grid: &Grid,
    scene: &Scene,
    params: &PipelineParams,
    dev: &dyn VolumeOffload,
    cancel: &Cancel,
) -> Result<RegionFields, PipelineError> {
    let check = || cancel.check().map_err(|_| PipelineError::Cancelled);
    check()?;
    if let Some(e) = &params.expand {
        // §5.1: expand the curves along a first guidance pass, then solve for the expanded ones.
        let expanded = super::expand::expand_scene_on(grid, scene, params, e, dev, cancel)?;
        let params = PipelineParams {
            expand: None,
            ..*params
        };
        return generate_on(grid, &expanded, &params, dev, cancel);
    }
    let run = Stopwatch::start();
    let grid = Grid::new(grid.dims, grid.origin, grid.spacing)?;
    let mut times = Timing::default();
    let v = build_voxels(&grid, scene, params, &mut times)?;
    check()?;

    // The stages after the voxelization form two chains: material propagation (§4.4) needs
    // only the voxelization, surface propagation (§4.5) needs the normals, the noise diffusion
    // (§4.4) only the voxelization. The critical path is voxelization → normal diffusion →
    // surface propagation → filter; the material wavefront and the noise diffusion fill the
    // cores beside it. Each sequential wavefront runs on one worker beside a slab-parallel
    // diffusion whose slabs the other workers (and the wavefront's worker, once done) take:
    // material beside the normal diffusion, surface beside the noise diffusion. On two cores
    // this keeps both busy to the end of each pair; starting the noise diffusion earlier
    // (beside the material) would leave the surface wavefront alone on one core.
    let (mat, n) = overlapped(
        &mut times,
        (|t| &mut t.material_ms, || material_stage(&grid, &v)),
        (
            |t| &mut t.normal_diffusion_ms,
            || {
                let mut n: Vec<Vec<f32>> = v.normal.to_vec();
                diffuse_normals(
                    grid.dims,
                    &mut n,
                    &v.omega_n,
                    &params.diffuse,
                    false,
                    dev,
                    cancel,
                );
                let [n0, n1, n2]: [Vec<f32>; 3] = n.try_into().expect("three components");
                [n0, n1, n2]
            },
        ),
    );
    check()?;
    let (surf, mut r) = overlapped(
        &mut times,
        (
            |t| &mut t.surface_propagation_ms,
            || surface_stage(&grid, &v, &n, dev),
        ),
        (
            |t| &mut t.noise_diffusion_ms,
            || {
                let mut r = vec![v.alpha.clone(), v.beta.clone()];
                harmonic_fill_on(grid.dims, &mut r, &v.omega_r, &params.diffuse, cancel);
                r
            },
        ),
    );
    check()?;
    let beta = r.pop().expect("beta");
    let alpha = r.pop().expect("alpha");
    Ok(finish(
        &grid,
        v,
        n,
        (alpha, beta),
        mat,
        surf,
        params,
        times,
        run,
    ))
}

/// The box `[lo, hi)` of samples whose constraints differ between `a` and `b`, or `None`.
fn changed_box(grid: &Grid, a: &Voxelized, b: &Voxelized) -> Option<SampleBox> {
    let mut lo = grid.dims;
    let mut hi = [0usize; 3];
    for i in 0..grid.len() {
        let differs = a.omega_n[i] != b.omega_n[i]
            || a.omega_r[i] != b.omega_r[i]
            || (0..3).any(|k| a.normal[k][i] != b.normal[k][i])
            || a.alpha[i] != b.alpha[i]
            || a.beta[i] != b.beta[i];
        if differs {
            let c = grid.coords(i);
            for k in 0..3 {
                lo[k] = lo[k].min(c[k]);
                hi[k] = hi[k].max(c[k] + 1);
            }
        }
    }
    (hi[0] > 0).then_some((lo, hi))
}

/// Re-solves `diffuse` for the channels inside the box, with the box's outermost layer (where
/// it is not the grid's border) fixed at the values already in `chans`.
fn solve_box(
    grid: &Grid,
    chans: &mut [Vec<f32>],
    fixed: &[u8],
    lo: [usize; 3],
    hi: [usize; 3],
    solve: impl Fn([usize; 3], &mut [Vec<f32>], &[u8]),
) {
    let dims = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    let n = dims[0] * dims[1] * dims[2];
    let mut sub: Vec<Vec<f32>> = chans.iter().map(|_| vec![0.0; n]).collect();
    let mut sfix = vec![0u8; n];
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                let (gx, gy, gz) = (x + lo[0], y + lo[1], z + lo[2]);
                let gi = grid.index(gx, gy, gz);
                let si = x + dims[0] * (y + dims[1] * z);
                let face = |c: usize, l: usize, h: usize, d: usize| {
                    (c == l && l > 0) || (c + 1 == h && h < d)
                };
                let on_face = face(gx, lo[0], hi[0], grid.dims[0])
                    || face(gy, lo[1], hi[1], grid.dims[1])
                    || face(gz, lo[2], hi[2], grid.dims[2]);
                sfix[si] = u8::from(fixed[gi] != 0 || on_face);
                for (s, c) in sub.iter_mut().zip(chans.iter()) {
                    s[si] = c[gi];
                }
            }
        }
    }
    solve(dims, &mut sub, &sfix);
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                let gi = grid.index(x + lo[0], y + lo[1], z + lo[2]);
                let si = x + dims[0] * (y + dims[1] * z);
                for (s, c) in sub.iter().zip(chans.iter_mut()) {
                    c[gi] = s[si];
                }
            }
        }
    }
}

/// Warm start after an edit: runs the pipeline for `scene` reusing `prev` (same grid) as the
/// module docs describe. Returns the new fields and the re-solved box (`None` if nothing
/// changed).
///
/// # Errors
/// As [`generate`].
pub fn regenerate(
    prev: &RegionFields,
    scene: &Scene,
    params: &PipelineParams,
) -> Result<(RegionFields, Option<SampleBox>), PipelineError> {
    if params.expand.is_some() {
        // An edit can change every expanded curve: no warm start with expansion.
        let fields = generate(&prev.grid, scene, params)?;
        return Ok((fields, Some(([0; 3], prev.grid.dims))));
    }
    let run = Stopwatch::start();
    let grid = prev.grid;
    let mut times = Timing::default();
    let v = build_voxels(&grid, scene, params, &mut times)?;
    let changed = changed_box(&grid, &prev.voxelized, &v).map(|(lo, hi)| {
        let m = params.warm_margin;
        let lo = lo.map(|c| c.saturating_sub(m));
        let hi = [0, 1, 2].map(|k| (hi[k] + m).min(grid.dims[k]));
        (lo, hi)
    });

    let sw = Stopwatch::start();
    let mut n: Vec<Vec<f32>> = prev.normal.to_vec();
    // New constraints replace the previous values everywhere they apply.
    for i in 0..grid.len() {
        if v.omega_n[i] != 0 {
            for k in 0..3 {
                n[k][i] = v.normal[k][i];
            }
        }
    }
    let mut r = vec![prev.alpha.clone(), prev.beta.clone()];
    for i in 0..grid.len() {
        if v.omega_r[i] != 0 {
            r[0][i] = v.alpha[i];
            r[1][i] = v.beta[i];
        }
    }
    let dp = params.diffuse;
    if let Some((lo, hi)) = changed {
        solve_box(&grid, &mut n, &v.omega_n, lo, hi, |d, c, f| {
            diffuse_normals(d, c, f, &dp, false, &CpuOnly, &Cancel::never())
        });
        times.record(sw, |t| &mut t.normal_diffusion_ms);
        let sw = Stopwatch::start();
        solve_box(&grid, &mut r, &v.omega_r, lo, hi, |d, c, f| {
            harmonic_fill(d, c, f, &dp)
        });
        times.record(sw, |t| &mut t.noise_diffusion_ms);
    }
    let [n0, n1, n2]: [Vec<f32>; 3] = n.try_into().expect("three components");
    let normal = [n0, n1, n2];
    let beta = r.pop().expect("beta");
    let alpha = r.pop().expect("alpha");
    // Material and surface propagation are independent sequential wavefronts: one thread each.
    let (mat, surf) = overlapped(
        &mut times,
        (|t| &mut t.material_ms, || material_stage(&grid, &v)),
        (
            |t| &mut t.surface_propagation_ms,
            || surface_stage(&grid, &v, &normal, &CpuOnly),
        ),
    );
    Ok((
        finish(
            &grid,
            v,
            normal,
            (alpha, beta),
            mat,
            surf,
            params,
            times,
            run,
        ),
        changed,
    ))
}
