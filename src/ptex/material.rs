//! Procedural ground materials for the Ptex bake (§4.7): each material is a handful of numbers,
//! so a world needs no image assets and every texel is a pure function of them.
//!
//! A material's pattern at a point of one projection plane is `t = ½ + ½·fbm2` (see
//! [`super::noise::fbm2`]: `octaves` octaves from `2^freq_log2` cycles per metre, `t` clamped to
//! `[0, 1]`). From `t`: albedo `base + (tint − base)·t` (sRGB-encoded components in `[0, 1]`,
//! blended in that encoding), roughness `roughness[0] + (roughness[1] − roughness[0])·t`, relief
//! `relief_m·(t − ½)` metres along the normal. `noise_m` is the amplitude of the world-space
//! noise displacement a vertex of this material carries (the paper's per-vertex noise
//! parameters).
//!
//! [`MaterialSet::default_ground`] is the set for the ground materials of
//! [`crate::terrain::world::MATERIALS`] (ids 0–5: seabed, sand, grass, dirt, rock, snow) plus mud (id 6,
//! for volume regions and scene elements to come). A world's `materials` scene element overrides
//! or extends it by name and its `decals` add decals ([`super::spec`]); the bake takes any set.
//!
//! An image material ([`Texture`]) reads its albedo, and optionally the `t` of its roughness and
//! relief, from uploaded images ([`super::image`]) tiled over the projection planes instead of
//! the pattern, and optionally a tangent-space normal map that tilts the baked normal.

use super::decal::Decal;
use super::image::Image;
use crate::terrain::hash::stream;
use std::borrow::Cow;
use std::sync::Arc;

/// One material: procedural, or with uploaded images in place of some of its patterns.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Name, e.g. `"rock"`.
    pub name: Cow<'static, str>,
    /// Albedo where the pattern is 0, sRGB-encoded, each in `[0, 1]`.
    pub base: [f32; 3],
    /// Albedo where the pattern is 1, sRGB-encoded.
    pub tint: [f32; 3],
    /// Roughness where the pattern is 0 and 1.
    pub roughness: [f32; 2],
    /// Relief amplitude of the pattern, metres (peak to peak).
    pub relief_m: f32,
    /// Amplitude of the world-space noise displacement of this material's vertices, metres.
    pub noise_m: f32,
    /// Lowest pattern octave: `2^freq_log2` cycles per metre.
    pub freq_log2: i32,
    /// Pattern octaves (before the per-face cut of octaves finer than half a texel).
    pub octaves: u32,
    /// Uploaded images that replace the pattern's albedo, roughness or relief; `None` for a
    /// procedural material.
    pub texture: Option<Texture>,
}

/// The images of an image material, tiled over each tri-planar projection plane: the plane's
/// coordinates in metres times `2^−repeat_log2` (wrapped to `[0, 1)`) are the image's `(u, v)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Texture {
    /// Albedo image (R, G, B sRGB-encoded; alpha ignored), an index into [`MaterialSet::images`].
    pub albedo: u32,
    /// Roughness image (its R channel `r` gives roughness `roughness[0] + (roughness[1] −
    /// roughness[0])·r`); `None`: the procedural pattern's.
    pub roughness: Option<u32>,
    /// Height image (its R channel `h` gives relief `relief_m·(h − ½)` metres); `None`: the
    /// procedural pattern's.
    pub height: Option<u32>,
    /// Tangent-space normal map (R, G, B = `x, y, z` of a unit normal times ½ plus ½, `z` out of
    /// the plane, `y` along the plane's second coordinate: the OpenGL convention), perturbing the
    /// displaced normal where the material lies ([`super::bake`], step 5); `None`: no map.
    pub normal: Option<u32>,
    /// One repeat is `2^repeat_log2` metres (`−2..=8`, so repeats line up with face anchors at
    /// multiples of 256 m).
    pub repeat_log2: i32,
}

/// The materials a bake reads, by id, and the world-space displacement noise.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialSet {
    /// Materials by id (a sample's material indexes this; ids past the end read the last).
    pub materials: Vec<Material>,
    /// Hash stream seed of each material's pattern (from the world seed).
    pub seeds: Vec<u32>,
    /// Hash stream seed of the displacement noise.
    pub noise_seed: u32,
    /// Lowest displacement-noise octave: `2^noise_freq_log2` cycles per metre.
    pub noise_freq_log2: i32,
    /// Displacement-noise octaves.
    pub noise_octaves: u32,
    /// Decoded images the materials' textures and the decals index.
    pub images: Vec<Arc<Image>>,
    /// Decals, applied in order over the blended materials.
    pub decals: Vec<Decal>,
}

/// Stream purpose of the Ptex patterns ([`crate::terrain::hash::stream`]); index = material id,
/// [`NOISE_INDEX`] for the displacement.
pub const PURPOSE_PTEX: u32 = 20;
/// Stream index of the displacement noise.
pub const NOISE_INDEX: u32 = 1000;
/// Most materials a set may hold (ids are bytes; the device buffer is sized by this).
pub const MAX_MATERIALS: usize = 64;
/// Most decals a set may hold (each texel tests every decal's footprint).
pub const MAX_DECALS: usize = 64;
/// Shortest repeat of an image material: `2^−2` = 0.25 m.
pub const MIN_REPEAT_LOG2: i32 = -2;
/// Longest repeat of an image material: `2^8` = 256 m (the face anchor unit).
pub const MAX_REPEAT_LOG2: i32 = 8;

const fn m(
    name: &'static str,
    base: [f32; 3],
    tint: [f32; 3],
    roughness: [f32; 2],
    relief_m: f32,
    noise_m: f32,
    freq_log2: i32,
) -> Material {
    Material {
        name: Cow::Borrowed(name),
        base,
        tint,
        roughness,
        relief_m,
        noise_m,
        freq_log2,
        octaves: 4,
        texture: None,
    }
}

/// The default ground materials, by id.
pub const DEFAULT_GROUND: [Material; 7] = [
    m(
        "seabed",
        [0.40, 0.37, 0.30],
        [0.27, 0.29, 0.24],
        [0.55, 0.75],
        0.06,
        0.03,
        -1,
    ),
    m(
        "sand",
        [0.84, 0.76, 0.57],
        [0.71, 0.62, 0.44],
        [0.70, 0.90],
        0.03,
        0.02,
        1,
    ),
    m(
        "grass",
        [0.35, 0.47, 0.19],
        [0.21, 0.33, 0.11],
        [0.75, 0.95],
        0.04,
        0.05,
        2,
    ),
    m(
        "dirt",
        [0.47, 0.38, 0.27],
        [0.34, 0.26, 0.18],
        [0.80, 0.95],
        0.05,
        0.06,
        1,
    ),
    m(
        "rock",
        [0.52, 0.51, 0.49],
        [0.33, 0.32, 0.31],
        [0.50, 0.80],
        0.30,
        0.20,
        -2,
    ),
    m(
        "snow",
        [0.93, 0.94, 0.96],
        [0.80, 0.85, 0.92],
        [0.35, 0.60],
        0.04,
        0.04,
        -1,
    ),
    m(
        "mud",
        [0.31, 0.25, 0.18],
        [0.22, 0.17, 0.12],
        [0.30, 0.60],
        0.02,
        0.03,
        0,
    ),
];

impl MaterialSet {
    /// `materials` with the hash streams of world `seed`.
    pub fn new(seed: u64, materials: Vec<Material>) -> Self {
        let seeds = (0..materials.len() as u32)
            .map(|i| stream(seed, PURPOSE_PTEX, i))
            .collect();
        Self {
            materials,
            seeds,
            noise_seed: stream(seed, PURPOSE_PTEX, NOISE_INDEX),
            noise_freq_log2: -3,
            noise_octaves: 5,
            images: Vec::new(),
            decals: Vec::new(),
        }
    }

    /// [`DEFAULT_GROUND`] for world `seed`.
    pub fn default_ground(seed: u64) -> Self {
        Self::new(seed, DEFAULT_GROUND.to_vec())
    }

    /// The index of material `id` (ids past the end read the last material).
    pub fn index(&self, id: u32) -> usize {
        (id as usize).min(self.materials.len().saturating_sub(1))
    }

    /// Checks the parameters the bake relies on.
    ///
    /// # Errors
    /// A message naming the first bad material parameter.
    pub fn validate(&self) -> Result<(), String> {
        use super::noise::{MAX_FREQ_LOG2, MIN_FREQ_LOG2};
        if self.materials.is_empty() || self.materials.len() > MAX_MATERIALS {
            return Err(format!("1..={MAX_MATERIALS} materials"));
        }
        let freq = MIN_FREQ_LOG2..=MAX_FREQ_LOG2;
        if !freq.contains(&self.noise_freq_log2) || self.noise_octaves > 8 {
            return Err("noise frequency or octaves out of range".into());
        }
        for (i, m) in self.materials.iter().enumerate() {
            let unit = |v: f32| (0.0..=1.0).contains(&v);
            let ok = m
                .base
                .iter()
                .chain(&m.tint)
                .chain(&m.roughness)
                .all(|&v| unit(v))
                && m.relief_m.is_finite()
                && (0.0..=100.0).contains(&m.relief_m)
                && (0.0..=100.0).contains(&m.noise_m)
                && freq.contains(&m.freq_log2)
                && m.octaves <= 8
                && m.texture.is_none_or(|t| {
                    let known = |i: u32| (i as usize) < self.images.len();
                    known(t.albedo)
                        && t.roughness.is_none_or(known)
                        && t.height.is_none_or(known)
                        && (MIN_REPEAT_LOG2..=MAX_REPEAT_LOG2).contains(&t.repeat_log2)
                });
            if !ok {
                return Err(format!(
                    "material {i} ({}) has a parameter out of range",
                    m.name
                ));
            }
        }
        if self.decals.len() > MAX_DECALS {
            return Err(format!("at most {MAX_DECALS} decals"));
        }
        for (i, d) in self.decals.iter().enumerate() {
            let known = |k: u32| (k as usize) < self.images.len();
            if !known(d.image) || !d.mask.is_none_or(known) {
                return Err(format!("decal {i} names an image the set lacks"));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_set_covers_the_world_materials_and_validates() {
        let set = MaterialSet::default_ground(7);
        assert_eq!(set.validate(), Ok(()));
        for (id, name) in crate::terrain::world::MATERIALS.iter().enumerate() {
            assert_eq!(set.materials[id].name, *name);
        }
        let other = MaterialSet::default_ground(8);
        assert_ne!(set.seeds, other.seeds, "patterns follow the world seed");
        assert_eq!(set.index(200), set.materials.len() - 1);
    }
}
