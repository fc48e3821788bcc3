//! The `materials` and `decals` scene elements (issue 20, `api/scene.schema.json`): parsing,
//! their limits, and the [`MaterialSet`] a world's elements make.
//!
//! ```json
//! {"id": "wet-rock", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "rock",
//!  "base": [0.30, 0.30, 0.32], "roughness": [0.2, 0.4]}
//! {"id": "cobbles", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "cobbles",
//!  "texture": {"albedo": "<blake3 hex>", "repeat_m": 2}}
//! {"id": "puddle", "bbox": {"min": [90, 40], "max": [110, 60]}, "image": "<blake3 hex>",
//!  "center": [100, 50], "size_m": [12, 8], "rotation_deg": 30, "opacity": 0.9}
//! ```
//!
//! A material element names a material: the name of a default one (`seabed`, `sand`, `grass`,
//! `dirt`, `rock`, `snow`, `mud`) overrides the fields it gives and keeps the others; a new name
//! adds a material with the next id (7, 8, … in document order), its fields defaulting to
//! [`new_material`]'s. A material applies wherever a sample has its id, world-wide: its `bbox`
//! is not read, and an edit of `materials` dirties the whole world (`scene::dirty_region`).
//!
//! A decal element has effect inside its `bbox` only: the rotated rectangle must lie inside it,
//! so an edit of a decal dirties just the pages its box meets.
//!
//! Images are named by the blake3 of their PNG bytes (lowercase hex), uploaded to the world
//! beforehand (`POST /v1/worlds/{id}/images`); `Scene::image_refs` lists a scene's. Parsing
//! and the limits are pure; whether the images exist is the store's check.

use super::decal::Decal;
use super::image::{parse_hash, Image};
use super::material::{
    Material, MaterialSet, Texture, DEFAULT_GROUND, MAX_DECALS, MAX_MATERIALS, MAX_REPEAT_LOG2,
    MIN_REPEAT_LOG2,
};
use super::noise::{ANCHOR_M, MAX_FREQ_LOG2, MIN_FREQ_LOG2};
use crate::element::{Element, MAX_COORD_M};
use serde::Deserialize;
use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::Arc;

/// Materials in the default set.
const DEFAULT_COUNT: usize = 7;
/// Longest material name, bytes.
pub const MAX_NAME_LEN: usize = 32;
/// Most `materials` elements in a scene (the default set's 7 and the new ones fit
/// [`MAX_MATERIALS`]).
pub const MAX_MATERIAL_ELEMENTS: usize = MAX_MATERIALS - DEFAULT_COUNT;
/// Most `decals` elements in a scene.
pub const MAX_DECAL_ELEMENTS: usize = MAX_DECALS;
/// Largest decal side, metres.
pub const MAX_DECAL_M: f64 = 4096.0;
/// Largest relief or noise amplitude of a material, metres.
pub const MAX_AMPLITUDE_M: f32 = 100.0;
/// Most pattern octaves.
pub const MAX_OCTAVES: u32 = 8;

/// Why an element is refused: a JSON pointer relative to the element and the reason.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {message}")]
pub struct SpecError {
    /// E.g. `/texture/repeat_m`.
    pub pointer: String,
    /// Why, naming the limit.
    pub message: String,
}

fn err(pointer: impl Into<String>, message: impl Into<String>) -> SpecError {
    SpecError {
        pointer: pointer.into(),
        message: message.into(),
    }
}

fn fields<T: serde::de::DeserializeOwned>(e: &Element) -> Result<T, SpecError> {
    let v = serde_json::Value::Object(e.rest.clone());
    serde_path_to_error::deserialize(&v).map_err(|x| {
        err(
            crate::element::path_pointer(x.path()),
            x.inner().to_string(),
        )
    })
}

fn image_ref(at: &str, hex: &str) -> Result<[u8; 32], SpecError> {
    parse_hash(hex).ok_or_else(|| {
        err(
            at,
            "an image is named by the blake3 of its PNG bytes: 64 lowercase hex digits \
             (the `image` of POST /v1/worlds/{id}/images)",
        )
    })
}

/// A parsed `materials` element.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Which material: a default one's name overrides it, a new name adds one.
    pub name: String,
    /// Albedo where the pattern is 0, sRGB-encoded components in `[0, 1]`.
    #[serde(default)]
    pub base: Option<[f32; 3]>,
    /// Albedo where the pattern is 1.
    #[serde(default)]
    pub tint: Option<[f32; 3]>,
    /// Roughness where the pattern (or roughness image) is 0 and 1, each in `[0, 1]`.
    #[serde(default)]
    pub roughness: Option<[f32; 2]>,
    /// Relief amplitude, metres peak to peak, `0..=100`.
    #[serde(default)]
    pub relief_m: Option<f32>,
    /// Amplitude of the noise displacement of this material's vertices, metres, `0..=100`.
    #[serde(default)]
    pub noise_m: Option<f32>,
    /// Lowest pattern octave: `2^freq_log2` cycles per metre, `−8..=8`.
    #[serde(default)]
    pub freq_log2: Option<i32>,
    /// Pattern octaves, `0..=8`.
    #[serde(default)]
    pub octaves: Option<u32>,
    /// Uploaded images in place of the pattern.
    #[serde(default)]
    pub texture: Option<TextureSpec>,
}

/// The `texture` of a material element.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TextureSpec {
    /// Albedo image hash.
    pub albedo: String,
    /// Roughness image hash (R channel).
    #[serde(default)]
    pub roughness: Option<String>,
    /// Height image hash (R channel; relief `relief_m·(h − ½)`).
    #[serde(default)]
    pub height: Option<String>,
    /// Tangent-space normal map hash (RGB; [`crate::ptex::material::Texture::normal`]).
    #[serde(default)]
    pub normal: Option<String>,
    /// Metres per repeat: a power of two from 0.25 to 256.
    pub repeat_m: f64,
}

impl MaterialSpec {
    /// Parses and checks a `materials` element.
    ///
    /// # Errors
    /// The pointer (relative to the element) and limit of the first bad field.
    pub fn from_element(e: &Element) -> Result<Self, SpecError> {
        let s: MaterialSpec = fields(e)?;
        s.check()?;
        Ok(s)
    }

    fn check(&self) -> Result<(), SpecError> {
        let n = &self.name;
        if n.is_empty()
            || n.len() > MAX_NAME_LEN
            || !n
                .bytes()
                .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_' || b == b'-')
        {
            return Err(err(
                "/name",
                format!("1 to {MAX_NAME_LEN} characters of a-z 0-9 _ -"),
            ));
        }
        let unit = |at: &str, v: &[f32]| -> Result<(), SpecError> {
            for (i, x) in v.iter().enumerate() {
                if !(0.0..=1.0).contains(x) {
                    return Err(err(format!("{at}/{i}"), "must be in [0, 1]"));
                }
            }
            Ok(())
        };
        if let Some(b) = &self.base {
            unit("/base", b)?;
        }
        if let Some(t) = &self.tint {
            unit("/tint", t)?;
        }
        if let Some(r) = &self.roughness {
            unit("/roughness", r)?;
        }
        for (at, v) in [("/relief_m", self.relief_m), ("/noise_m", self.noise_m)] {
            if v.is_some_and(|v| !(0.0..=MAX_AMPLITUDE_M).contains(&v)) {
                return Err(err(at, format!("metres in [0, {MAX_AMPLITUDE_M}]")));
            }
        }
        if self
            .freq_log2
            .is_some_and(|k| !(MIN_FREQ_LOG2..=MAX_FREQ_LOG2).contains(&k))
        {
            return Err(err(
                "/freq_log2",
                format!("an integer in {MIN_FREQ_LOG2}..={MAX_FREQ_LOG2}"),
            ));
        }
        if self.octaves.is_some_and(|o| o > MAX_OCTAVES) {
            return Err(err("/octaves", format!("at most {MAX_OCTAVES}")));
        }
        if let Some(t) = &self.texture {
            image_ref("/texture/albedo", &t.albedo)?;
            if let Some(r) = &t.roughness {
                image_ref("/texture/roughness", r)?;
            }
            if let Some(h) = &t.height {
                image_ref("/texture/height", h)?;
            }
            if let Some(n) = &t.normal {
                image_ref("/texture/normal", n)?;
            }
            repeat_log2(t.repeat_m)?;
        }
        Ok(())
    }

    /// The image hashes the element names, with their pointers relative to the element.
    pub fn images(&self) -> Vec<(&'static str, [u8; 32])> {
        let Some(t) = &self.texture else {
            return Vec::new();
        };
        [
            ("/texture/albedo", Some(&t.albedo)),
            ("/texture/roughness", t.roughness.as_ref()),
            ("/texture/height", t.height.as_ref()),
            ("/texture/normal", t.normal.as_ref()),
        ]
        .into_iter()
        .filter_map(|(at, h)| Some((at, parse_hash(h?)?)))
        .collect()
    }
}

fn repeat_log2(repeat_m: f64) -> Result<i32, SpecError> {
    let k = repeat_m.log2();
    let lo = 2f64.powi(MIN_REPEAT_LOG2);
    let hi = 2f64.powi(MAX_REPEAT_LOG2);
    if !repeat_m.is_finite() || k.fract() != 0.0 || !(lo..=hi).contains(&repeat_m) {
        return Err(err(
            "/texture/repeat_m",
            format!("metres per repeat: a power of two from {lo} to {hi}"),
        ));
    }
    Ok(k as i32)
}

/// The fields of a new material that its element leaves out: a mid-grey, untextured, flat,
/// rough material with no noise displacement, 4 octaves from 1 cycle per metre.
pub fn new_material(name: &str) -> Material {
    Material {
        name: Cow::Owned(name.to_owned()),
        base: [0.5, 0.5, 0.5],
        tint: [0.5, 0.5, 0.5],
        roughness: [0.8, 0.8],
        relief_m: 0.0,
        noise_m: 0.0,
        freq_log2: 0,
        octaves: 4,
        texture: None,
    }
}

/// A parsed `decals` element.
#[derive(Clone, Debug, PartialEq)]
pub struct DecalSpec {
    /// The image (R, G, B albedo; A the mask unless `mask` is given).
    pub image: [u8; 32],
    /// A separate mask image (R channel).
    pub mask: Option<[u8; 32]>,
    /// Centre `[x, z]`, metres.
    pub center: [f64; 2],
    /// Width (along the image's u) and length (along v), metres.
    pub size_m: [f64; 2],
    /// Turn about the vertical, degrees clockwise seen from above.
    pub rotation_deg: f64,
    /// Opacity in `[0, 1]`.
    pub opacity: f64,
    /// Roughness blended in, if any.
    pub roughness: Option<f64>,
    /// `projection: top_down_facing`: the decal fades on steep and downward faces
    /// ([`crate::ptex::decal::facing_weight`]).
    pub facing: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DecalFields {
    image: String,
    #[serde(default)]
    mask: Option<String>,
    center: [f64; 2],
    size_m: [f64; 2],
    #[serde(default)]
    rotation_deg: f64,
    #[serde(default = "one")]
    opacity: f64,
    #[serde(default)]
    roughness: Option<f64>,
    #[serde(default = "top_down")]
    projection: String,
}

fn one() -> f64 {
    1.0
}

fn top_down() -> String {
    "top_down".into()
}

impl DecalSpec {
    /// Parses and checks a `decals` element, its rectangle inside its `bbox`.
    ///
    /// # Errors
    /// The pointer (relative to the element) and limit of the first bad field.
    pub fn from_element(e: &Element) -> Result<Self, SpecError> {
        let f: DecalFields = fields(e)?;
        let facing = match f.projection.as_str() {
            "top_down" => false,
            "top_down_facing" => true,
            _ => return Err(err("/projection", "\"top_down\" or \"top_down_facing\"")),
        };
        let image = image_ref("/image", &f.image)?;
        let mask = f
            .mask
            .as_deref()
            .map(|m| image_ref("/mask", m))
            .transpose()?;
        for k in 0..2 {
            if !f.center[k].is_finite() || f.center[k].abs() > MAX_COORD_M {
                return Err(err(
                    format!("/center/{k}"),
                    format!("metres within ±{MAX_COORD_M}"),
                ));
            }
            if !(f.size_m[k] > 0.0 && f.size_m[k] <= MAX_DECAL_M) {
                return Err(err(
                    format!("/size_m/{k}"),
                    format!("metres in (0, {MAX_DECAL_M}]"),
                ));
            }
        }
        if !f.rotation_deg.is_finite() || f.rotation_deg.abs() > 360.0 {
            return Err(err("/rotation_deg", "degrees in [-360, 360]"));
        }
        if !(0.0..=1.0).contains(&f.opacity) {
            return Err(err("/opacity", "must be in [0, 1]"));
        }
        if f.roughness.is_some_and(|r| !(0.0..=1.0).contains(&r)) {
            return Err(err("/roughness", "must be in [0, 1]"));
        }
        let spec = DecalSpec {
            image,
            mask,
            center: f.center,
            size_m: f.size_m,
            rotation_deg: f.rotation_deg,
            opacity: f.opacity,
            roughness: f.roughness,
            facing,
        };
        let (lo, hi) = spec.extent();
        for k in 0..2 {
            if lo[k] < e.bbox.min[k] || hi[k] > e.bbox.max[k] {
                return Err(err(
                    "/bbox",
                    format!(
                        "must contain the decal's rectangle, [{}, {}] × [{}, {}] m",
                        lo[0], hi[0], lo[1], hi[1]
                    ),
                ));
            }
        }
        Ok(spec)
    }

    /// The axis-aligned box of the turned rectangle, `([x, z] min, [x, z] max)`, metres.
    pub fn extent(&self) -> ([f64; 2], [f64; 2]) {
        let (s, c) = self.rotation_deg.to_radians().sin_cos();
        let (hw, hl) = (self.size_m[0] * 0.5, self.size_m[1] * 0.5);
        let e = [c.abs() * hw + s.abs() * hl, s.abs() * hw + c.abs() * hl];
        (
            [self.center[0] - e[0], self.center[1] - e[1]],
            [self.center[0] + e[0], self.center[1] + e[1]],
        )
    }

    /// The image hashes the element names, with their pointers relative to the element.
    pub fn images(&self) -> Vec<(&'static str, [u8; 32])> {
        let mut out = vec![("/image", self.image)];
        out.extend(self.mask.map(|m| ("/mask", m)));
        out
    }

    /// The decal ready to bake, its image and mask at `image` and `mask` of the set's images.
    pub fn decal(&self, image: (u32, &Image), mask: Option<(u32, &Image)>) -> Decal {
        let (s, c) = self.rotation_deg.to_radians().sin_cos();
        let density = |img: &Image| -> i32 {
            let d =
                (f64::from(img.width) / self.size_m[0]).max(f64::from(img.height) / self.size_m[1]);
            d.log2().ceil() as i32
        };
        let anchor = self.center.map(|c| (c / ANCHOR_M).floor());
        Decal {
            anchor: anchor.map(|a| a as i32),
            offset: [
                (self.center[0] - anchor[0] * ANCHOR_M) as f32,
                (self.center[1] - anchor[1] * ANCHOR_M) as f32,
            ],
            inv_size: self.size_m.map(|s| (1.0 / s) as f32),
            cos: c as f32,
            sin: s as f32,
            opacity: self.opacity as f32,
            roughness: self.roughness.map(|r| r as f32),
            image: image.0,
            mask: mask.map(|m| m.0),
            density_log2: density(image.1),
            mask_density_log2: mask.map_or(0, |m| density(m.1)),
            facing: self.facing,
        }
    }
}

/// The images a set takes, each once, in the order first named.
struct Interned<'a> {
    /// What there is to take, by hash.
    images: &'a HashMap<[u8; 32], Arc<Image>>,
    /// Taken, by index.
    list: Vec<Arc<Image>>,
    /// Index of each taken hash.
    index: HashMap<[u8; 32], u32>,
}

impl Interned<'_> {
    /// The index and image of `hash`, taken if new; `None` if there is no such image.
    fn get(&mut self, hash: &[u8; 32]) -> Option<(u32, Arc<Image>)> {
        let img = self.images.get(hash)?.clone();
        let list = &mut self.list;
        let i = *self.index.entry(*hash).or_insert_with(|| {
            list.push(img.clone());
            list.len() as u32 - 1
        });
        Some((i, img))
    }

    /// The index of the image a hex hash names.
    fn index_of(&mut self, hex: &str) -> Option<u32> {
        self.get(&parse_hash(hex)?).map(|x| x.0)
    }
}

/// The parsed `materials` and `decals` of a scene (elements that do not parse are left out:
/// they were refused when written, or stored before these elements had a schema).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PtexSpecs {
    /// Material elements, in document order.
    pub materials: Vec<MaterialSpec>,
    /// Decal elements, in document order.
    pub decals: Vec<DecalSpec>,
}

impl PtexSpecs {
    /// The elements of `materials` and `decals` that parse.
    pub fn new(materials: &[Element], decals: &[Element]) -> Self {
        Self {
            materials: materials
                .iter()
                .filter_map(|e| MaterialSpec::from_element(e).ok())
                .collect(),
            decals: decals
                .iter()
                .filter_map(|e| DecalSpec::from_element(e).ok())
                .collect(),
        }
    }

    /// Whether the world's set is the default one.
    pub fn is_empty(&self) -> bool {
        self.materials.is_empty() && self.decals.is_empty()
    }

    /// Every image hash the elements name (repeats included), in document order.
    pub fn images(&self) -> Vec<[u8; 32]> {
        let m = self.materials.iter().flat_map(|s| s.images());
        let d = self.decals.iter().flat_map(|s| s.images());
        m.chain(d).map(|(_, h)| h).collect()
    }

    /// The world's set for `seed`: [`MaterialSet::default_ground`] with the material elements
    /// applied by name and the decals added, the images taken from `images` (by hash; an image
    /// it lacks leaves its material procedural and drops its decal, which the store's check
    /// before every write rules out).
    pub fn set(&self, seed: u64, images: &HashMap<[u8; 32], Arc<Image>>) -> MaterialSet {
        if self.is_empty() {
            return MaterialSet::default_ground(seed);
        }
        let mut interned = Interned {
            images,
            list: Vec::new(),
            index: HashMap::new(),
        };
        let mut materials = DEFAULT_GROUND.to_vec();
        for s in &self.materials {
            let at = match materials.iter().position(|m| m.name == s.name) {
                Some(at) => at,
                None if materials.len() < MAX_MATERIALS => {
                    materials.push(new_material(&s.name));
                    materials.len() - 1
                }
                None => continue,
            };
            let m = &mut materials[at];
            m.base = s.base.unwrap_or(m.base);
            m.tint = s.tint.unwrap_or(m.tint);
            m.roughness = s.roughness.unwrap_or(m.roughness);
            m.relief_m = s.relief_m.unwrap_or(m.relief_m);
            m.noise_m = s.noise_m.unwrap_or(m.noise_m);
            m.freq_log2 = s.freq_log2.unwrap_or(m.freq_log2);
            m.octaves = s.octaves.unwrap_or(m.octaves);
            if let Some(t) = &s.texture {
                if let (Some(albedo), Ok(repeat_log2)) =
                    (interned.index_of(&t.albedo), repeat_log2(t.repeat_m))
                {
                    m.texture = Some(Texture {
                        albedo,
                        roughness: t.roughness.as_ref().and_then(|h| interned.index_of(h)),
                        height: t.height.as_ref().and_then(|h| interned.index_of(h)),
                        normal: t.normal.as_ref().and_then(|h| interned.index_of(h)),
                        repeat_log2,
                    });
                }
            }
        }
        let mut decals = Vec::new();
        for d in &self.decals {
            let Some(image) = interned.get(&d.image) else {
                continue;
            };
            let mask = match &d.mask {
                Some(h) => match interned.get(h) {
                    Some(m) => Some(m),
                    None => continue,
                },
                None => None,
            };
            decals.push(d.decal(
                (image.0, &image.1),
                mask.as_ref().map(|m| (m.0, m.1.as_ref())),
            ));
        }
        let mut set = MaterialSet::new(seed, materials);
        set.images = interned.list;
        set.decals = decals;
        set
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn the_default_count_is_the_default_sets() {
        assert_eq!(DEFAULT_COUNT, DEFAULT_GROUND.len());
    }

    #[test]
    fn overrides_keep_unnamed_fields_and_new_names_take_the_next_ids() {
        let el = |v: serde_json::Value| -> Element { serde_json::from_value(v).expect("element") };
        let zero = json!({"min": [0, 0], "max": [0, 0]});
        let specs = PtexSpecs {
            materials: vec![
                MaterialSpec::from_element(&el(json!({"id": "a", "bbox": zero, "name": "moss",
                    "base": [0.1, 0.4, 0.1]})))
                .expect("moss"),
                MaterialSpec::from_element(&el(json!({"id": "b", "bbox": zero, "name": "rock",
                    "roughness": [0.2, 0.3]})))
                .expect("rock"),
            ],
            decals: Vec::new(),
        };
        let set = specs.set(4, &HashMap::new());
        let default = MaterialSet::default_ground(4);
        assert_eq!(set.materials.len(), 8);
        assert_eq!(set.materials[7].name, "moss");
        assert_eq!(set.materials[7].base, [0.1, 0.4, 0.1]);
        assert_eq!(set.materials[4].roughness, [0.2, 0.3]);
        assert_eq!(set.materials[4].base, default.materials[4].base);
        assert_eq!(
            set.seeds[..7],
            default.seeds[..],
            "the default materials keep their patterns"
        );
        assert_eq!(set.validate(), Ok(()));
    }

    #[test]
    fn a_decal_is_projected_top_down_or_top_down_facing() {
        let decal = |projection: &str| {
            let e: Element = serde_json::from_value(json!({"id": "d",
                "bbox": {"min": [-10, -10], "max": [10, 10]}, "image": "ab".repeat(32),
                "center": [0, 0], "size_m": [8, 8], "projection": projection}))
            .expect("element");
            DecalSpec::from_element(&e)
        };
        assert!(!decal("top_down").expect("top_down").facing);
        assert!(decal("top_down_facing").expect("facing").facing);
        let e = decal("sideways").expect_err("refused");
        assert_eq!(e.pointer, "/projection");
        assert!(e.message.contains("top_down_facing"), "{}", e.message);
    }
}
