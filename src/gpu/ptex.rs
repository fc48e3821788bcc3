//! The WGSL twin of the Ptex bake (Becher §4.7): `shaders/ptex.wgsl` run by
//! [`bake_interior_on_device`], the twin of [`crate::ptex::bake_interior`]. One invocation per
//! interior texel, one dispatch, one submission; the borders are then copied on the CPU
//! ([`crate::ptex::border::fill_borders`]: a copy, no arithmetic). The device and queue come
//! from the caller, so tests inject lavapipe.
//!
//! # Tolerance
//!
//! The hashing and the lattice coordinates are exact on both sides (`ptex::noise`), but WGSL
//! lets a compiler contract `a·b + c` and computes `sqrt` and `/` to a few ULP, so a texel's
//! floats may differ from the CPU's by rounding, and a quantised byte may land one step away
//! when the value sits near a rounding boundary; the normal, a difference quotient over half a
//! texel, amplifies that. `tests/gpu_ptex.rs` states the bound it allows.
//!
//! Image materials and decals read the set's images packed into one storage buffer of words
//! ([`pack_images`]: a header per image, then its mip levels' RGBA8 texels) and the decals from
//! another; the CPU reference ([`crate::ptex::image`], [`crate::ptex::decal`]) defines the
//! bytes, and the twin samples the same texels with the same bilinear weights.
//!
//! # Limits
//!
//! The packed images must fit the device's `max_storage_buffer_binding_size` too. The output
//! (12 bytes per texel) must fit the device's `max_storage_buffer_binding_size`; a
//! larger bake is an error, not a panic.

use super::kit::{bind_group, dispatch_linear, read_back, readback, upload, Binding, Program};
use super::scopes::Scopes;
use crate::ptex::bake::face_constants;
use crate::ptex::{FaceSet, MaterialSet, Pages};
use anyhow::{bail, Context};
use std::time::Duration;

/// `shaders/ptex.wgsl`.
pub const PTEX_WGSL: &str = include_str!("../../shaders/ptex.wgsl");
/// Invocations per workgroup (`@workgroup_size(64)`).
const WORKGROUP: u32 = 64;
/// How long one job may wait for the device.
const JOB_TIMEOUT: Duration = Duration::from_secs(120);

/// `Params` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuPtexParams {
    /// Texels per face side.
    pub res: u32,
    /// Faces.
    pub faces: u32,
    /// Lowest displacement-noise octave exponent.
    pub noise_k0: i32,
    /// Displacement-noise octaves.
    pub noise_octaves: u32,
    /// Displacement-noise hash seed.
    pub noise_seed: u32,
    /// Materials in the set.
    pub materials: u32,
    /// Decals in the set.
    pub decals: u32,
    /// 1 where the samples carry texel inputs (`FaceSet::surface`), else 0.
    pub surface: u32,
    /// `TexelRule::blend_m`, metres.
    pub blend_m: f32,
    /// `TexelRule::beach_height_m`, metres.
    pub beach_m: f32,
    /// `cos` of the slope where rock starts.
    pub rock_lo: f32,
    /// `cos` of the slope where rock is complete.
    pub rock_hi: f32,
    /// `TexelRule::alpine_fraction` (0: no alpine zone).
    pub alpine: f32,
    /// Padding to 16 bytes.
    pub pad: [u32; 3],
}

/// `Face` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuFace {
    /// Anchor, units of 256 m.
    pub anchor: [i32; 3],
    /// First sample.
    pub first: u32,
    /// Samples per side.
    pub n: u32,
    /// Finest octave exponent at this resolution.
    pub kmax: i32,
    /// Forward-difference step, metres.
    pub step: f32,
    /// Padding.
    pub pad: u32,
}

/// `Sample` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuSample {
    /// Position relative to the anchor, metres.
    pub position: [f32; 3],
    /// Material id.
    pub material: u32,
    /// Unit normal.
    pub normal: [f32; 3],
    /// Noise amplitude, metres.
    pub noise_m: f32,
}

/// `Mat` of `shaders/ptex.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    /// Albedo at pattern 0.
    pub base: [f32; 3],
    /// Relief, metres.
    pub relief_m: f32,
    /// Albedo at pattern 1.
    pub tint: [f32; 3],
    /// Roughness at pattern 0.
    pub rough0: f32,
    /// Roughness at pattern 1.
    pub rough1: f32,
    /// Lowest pattern octave exponent.
    pub freq_log2: i32,
    /// Pattern octaves.
    pub octaves: u32,
    /// Pattern hash seed.
    pub seed: u32,
    /// Header offset of the albedo image in the image words, or [`NONE`].
    pub tex_albedo: u32,
    /// Header offset of the roughness image, or [`NONE`].
    pub tex_rough: u32,
    /// Header offset of the height image, or [`NONE`].
    pub tex_height: u32,
    /// One repeat is `2^repeat_log2` metres.
    pub repeat_log2: i32,
    /// Header offset of the normal map, or [`NONE`].
    pub tex_normal: u32,
}

/// `Decal` of `shaders/ptex.wgsl` ([`crate::ptex::decal::Decal`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuDecal {
    /// Centre's anchor, units of 256 m.
    pub anchor: [i32; 2],
    /// Centre relative to the anchor, metres.
    pub offset: [f32; 2],
    /// Reciprocal width and length, per metre.
    pub inv_size: [f32; 2],
    /// `cos θ`.
    pub cos: f32,
    /// `sin θ`.
    pub sin: f32,
    /// Opacity.
    pub opacity: f32,
    /// Roughness blended in (when `has_rough`).
    pub rough: f32,
    /// Whether the decal sets roughness.
    pub has_rough: u32,
    /// Header offset of the image.
    pub image: u32,
    /// Header offset of the mask image, or [`NONE`].
    pub mask: u32,
    /// `⌈log2⌉` of the image's pixels per metre.
    pub density_log2: i32,
    /// Likewise for the mask.
    pub mask_density_log2: i32,
    /// 1 when the decal fades with the surface's facing (`top_down_facing`), else 0.
    pub facing: u32,
}

/// "No image" in [`GpuMaterial`] and [`GpuDecal`].
pub const NONE: u32 = u32::MAX;

/// The images of a set packed as `shaders/ptex.wgsl` reads them: per image a header `[w, h,
/// levels, offset of each level…]` (word offsets), then its levels' texels as little-endian
/// RGBA8 words. Returns the words and each image's header offset.
pub fn pack_images(images: &[std::sync::Arc<crate::ptex::image::Image>]) -> (Vec<u32>, Vec<u32>) {
    let mut words = Vec::new();
    let mut headers = Vec::with_capacity(images.len());
    for img in images {
        let at = words.len();
        headers.push(at as u32);
        words.extend([img.width, img.height, img.levels.len() as u32]);
        words.resize(at + 3 + img.levels.len(), 0);
        for (l, level) in img.levels.iter().enumerate() {
            words[at + 3 + l] = words.len() as u32;
            words.extend(level.iter().map(|t| u32::from_le_bytes(*t)));
        }
    }
    (words, headers)
}

/// Bakes the interior texels of every face of `set` at `res` on `device` into `out` (reset to
/// the set's faces; borders left zero), like [`crate::ptex::bake_interior`].
///
/// # Errors
/// An empty or invalid input, an output too large for the device, or a device error.
pub fn bake_interior_on_device(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    set: &FaceSet,
    mats: &MaterialSet,
    res: u32,
    out: &mut Pages,
) -> anyhow::Result<()> {
    if !crate::ptex::valid_res(res) {
        bail!("res {res} is not a power of two in 8..=256");
    }
    if let Err(e) = mats.validate() {
        bail!("materials: {e}");
    }
    let texels = set.faces.len() as u64 * u64::from(res) * u64::from(res);
    let bytes = 12 * texels;
    let limit = device.limits().max_storage_buffer_binding_size;
    if texels == 0 || bytes > limit || texels >= u64::from(u32::MAX) {
        bail!("{texels} texels need a {bytes}-byte buffer; the device allows {limit}");
    }
    let faces: Vec<GpuFace> = set
        .faces
        .iter()
        .map(|f| {
            let (kmax, step) = face_constants(f, res);
            GpuFace {
                anchor: f.anchor,
                first: f.first,
                n: f.n,
                kmax,
                step,
                pad: 0,
            }
        })
        .collect();
    let samples: Vec<GpuSample> = set
        .samples
        .iter()
        .map(|s| GpuSample {
            position: s.position,
            material: s.material,
            normal: s.normal,
            noise_m: s.noise_m,
        })
        .collect();
    // Two vec4 per sample where the set has texel inputs (one zero pair otherwise: storage
    // bindings may not be empty).
    let rule = set.texel_rule().copied();
    let mut surface: Vec<[f32; 4]> = Vec::with_capacity(2 * set.surface.len());
    if rule.is_some() {
        for s in &set.surface {
            surface.push([s[0], s[1], s[2], s[3]]);
            surface.push([s[4], s[5], s[6], s[7]]);
        }
    } else {
        surface.extend([[0.0; 4]; 2]);
    }
    let (mut image_words, headers) = pack_images(&mats.images);
    let header = |i: Option<u32>| i.map_or(NONE, |i| headers[i as usize]);
    let materials: Vec<GpuMaterial> = mats
        .materials
        .iter()
        .zip(&mats.seeds)
        .map(|(m, &seed)| GpuMaterial {
            base: m.base,
            relief_m: m.relief_m,
            tint: m.tint,
            rough0: m.roughness[0],
            rough1: m.roughness[1],
            freq_log2: m.freq_log2,
            octaves: m.octaves,
            seed,
            tex_albedo: header(m.texture.map(|t| t.albedo)),
            tex_rough: header(m.texture.and_then(|t| t.roughness)),
            tex_height: header(m.texture.and_then(|t| t.height)),
            repeat_log2: m.texture.map_or(0, |t| t.repeat_log2),
            tex_normal: header(m.texture.and_then(|t| t.normal)),
        })
        .collect();
    let mut decals: Vec<GpuDecal> = mats
        .decals
        .iter()
        .map(|d| GpuDecal {
            anchor: d.anchor,
            offset: d.offset,
            inv_size: d.inv_size,
            cos: d.cos,
            sin: d.sin,
            opacity: d.opacity,
            rough: d.roughness.unwrap_or(0.0),
            has_rough: u32::from(d.roughness.is_some()),
            image: headers[d.image as usize],
            mask: header(d.mask),
            density_log2: d.density_log2,
            mask_density_log2: d.mask_density_log2,
            facing: u32::from(d.facing),
        })
        .collect();
    let decal_count = decals.len() as u32;
    // Storage bindings may not be empty.
    if decals.is_empty() {
        decals.push(bytemuck::Zeroable::zeroed());
    }
    if image_words.is_empty() {
        image_words.push(0);
    }
    if 4 * image_words.len() as u64 > limit {
        bail!(
            "the images need a {}-byte buffer; the device allows {limit}",
            4 * image_words.len()
        );
    }
    let params = GpuPtexParams {
        res,
        faces: set.faces.len() as u32,
        noise_k0: mats.noise_freq_log2,
        noise_octaves: mats.noise_octaves,
        noise_seed: mats.noise_seed,
        materials: materials.len() as u32,
        decals: decal_count,
        surface: u32::from(rule.is_some()),
        blend_m: rule.map_or(0.0, |r| r.blend_m),
        beach_m: rule.map_or(0.0, |r| r.beach_height_m),
        rock_lo: rule.map_or(0.0, |r| r.rock_cos.0),
        rock_hi: rule.map_or(0.0, |r| r.rock_cos.1),
        alpine: rule.map_or(0.0, |r| r.alpine_fraction),
        pad: [0; 3],
    };
    let scopes = Scopes::push(device);
    let (u, r, w) = (Binding::Uniform, Binding::Read, Binding::ReadWrite);
    let program = Program::new(
        device,
        "strata ptex.wgsl",
        PTEX_WGSL,
        &[u, r, r, r, w, r, r, r],
    );
    let pipeline = program.pipeline(device, "bake");
    let storage = wgpu::BufferUsages::STORAGE;
    let ub = upload(
        device,
        queue,
        "ptex params",
        bytemuck::bytes_of(&params),
        wgpu::BufferUsages::UNIFORM,
    );
    let fb = upload(
        device,
        queue,
        "ptex faces",
        bytemuck::cast_slice(&faces),
        storage,
    );
    let sb = upload(
        device,
        queue,
        "ptex samples",
        bytemuck::cast_slice(&samples),
        storage,
    );
    let mb = upload(
        device,
        queue,
        "ptex materials",
        bytemuck::cast_slice(&materials),
        storage,
    );
    let ob = super::kit::storage(device, "ptex texels", bytes, wgpu::BufferUsages::COPY_SRC);
    let ib = upload(
        device,
        queue,
        "ptex images",
        bytemuck::cast_slice(&image_words),
        storage,
    );
    let db = upload(
        device,
        queue,
        "ptex decals",
        bytemuck::cast_slice(&decals),
        storage,
    );
    let tb = upload(
        device,
        queue,
        "ptex texel inputs",
        bytemuck::cast_slice(&surface),
        storage,
    );
    let group = bind_group(
        device,
        &program.layout,
        "ptex",
        &[&ub, &fb, &sb, &mb, &ob, &ib, &db, &tb],
    );
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("strata ptex bake"),
    });
    {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("strata ptex bake"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        dispatch_linear(&mut pass, texels as u32, WORKGROUP);
    }
    let rb = readback(device, "ptex readback", bytes);
    encoder.copy_buffer_to_buffer(&ob, 0, &rb, 0, bytes);
    let submission = queue.submit([encoder.finish()]);
    let words: Vec<u32> = read_back(device, &rb, submission, Some(JOB_TIMEOUT), scopes)
        .context("running shaders/ptex.wgsl")?;
    out.reset(res, set.faces.len());
    let rr = res as usize;
    for f in 0..set.faces.len() {
        for j in 0..rr {
            for i in 0..rr {
                let src = 3 * ((f * rr + j) * rr + i);
                let dst = out.at(f, i as i32, j as i32);
                out.albedo[dst] = words[src].to_le_bytes();
                out.normal[dst] = words[src + 1].to_le_bytes();
                out.displacement[dst] = f32::from_bits(words[src + 2]);
            }
        }
    }
    Ok(())
}
