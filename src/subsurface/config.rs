//! Santamaría-Ibirika et al. §4.1: the designer's input — material data (basic data, layer
//! characteristics, affinities) and the general parameters — with validation that names the
//! offending field by JSON pointer, and the paper's Table 2 configurations A0–B3 as presets.
//!
//! The JSON schema of [`SubsurfaceConfig`] is `api/subsurface.schema.json`.

use serde::{Deserialize, Serialize};

/// Most materials a configuration may list (bounds the work of Eq. 1–2).
pub const MAX_MATERIALS: usize = 64;

/// A 0–1 range with an optimum: the value of an element is drawn in `[min, max]`, peaked at
/// `optimum` (triangular distribution).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Range {
    /// Smallest value.
    pub min: f32,
    /// Largest value.
    pub max: f32,
    /// Most likely value.
    pub optimum: f32,
}

impl Range {
    /// A range of one value.
    pub const fn fixed(v: f32) -> Range {
        Range {
            min: v,
            max: v,
            optimum: v,
        }
    }

    /// Triangular draw with `u` uniform in `[0, 1)`.
    pub fn draw(&self, u: f32) -> f32 {
        let (a, b, c) = (self.min, self.max, self.optimum);
        if b <= a {
            return a;
        }
        let f = (c - a) / (b - a);
        if u < f {
            a + (u * (b - a) * (c - a)).sqrt()
        } else {
            b - ((1.0 - u) * (b - a) * (b - c)).sqrt()
        }
    }
}

/// The special parameters of a material (§4.1.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Flags {
    /// Empty voxels (the air above the surface is the first void material).
    pub void: bool,
    /// Only in the bottom layer.
    pub base: bool,
    /// Never mixed with other materials in a layer.
    pub alone: bool,
    /// A resource structured into veins instead of layers.
    pub vein: bool,
    /// Fills caves; different cave materials are different kinds of caves.
    pub cave: bool,
}

/// One material (§4.1.1): basic data and layer characteristics, all characteristics on 0–1.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Material name.
    pub name: String,
    /// Unique numeric identifier.
    pub id: u32,
    /// RGB colour.
    pub color: [u8; 3],
    /// Path of the material's texture.
    #[serde(default)]
    pub texture: String,
    /// Special parameters.
    #[serde(default)]
    pub flags: Flags,
    /// Relative area of veins and caves of this material (ignored otherwise).
    #[serde(default = "one")]
    pub area: f32,
    /// Relative depth (0 the surface, 1 the bottom of the terrain) where the material occurs.
    pub depth: Range,
    /// Relative thickness of the layers, veins or caves formed with it.
    pub thickness: Range,
    /// Relative surface roughness (layers) or midpoint-displacement constants (veins, caves).
    pub roughness: Range,
    /// Similarity of a layer's shape to the layer below.
    pub similarity: f32,
    /// Suitability for blending with the layer below (fraction of the layer that is transition).
    pub blend: f32,
}

fn one() -> f32 {
    1.0
}

/// Affinities of a pair of materials (§4.1.1): 0–1, or −1 for incompatible. Pairs not listed
/// have affinity 0 (compatible, not prone to mix).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Affinity {
    /// Id of one material.
    pub a: u32,
    /// Id of the other material.
    pub b: u32,
    /// Affinity in the same layer.
    pub same_layer: f32,
    /// Affinity in consecutive layers.
    pub next_layer: f32,
}

/// The general parameters (§4.1.2), in voxels where they are lengths.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct General {
    /// Distance between the surface and the bottom layer, voxels.
    pub terrain_depth: f32,
    /// Absolute thickness of relative thickness 1, voxels.
    pub layer_thickness: f32,
    /// Largest side of a cave's bounding square, voxels (also the cave lattice's cell side).
    pub cave_area: f32,
    /// Largest side of a vein's bounding square, voxels (also the vein lattice's cell side).
    pub vein_area: f32,
    /// Probability that a cell of the cave lattice holds a cave, 0–1.
    pub cave_density: f32,
    /// Probability that a cell of the vein lattice holds a vein, 0–1.
    pub vein_density: f32,
    /// Absolute height of a cave of relative thickness 1, voxels.
    pub cave_thickness: f32,
    /// Absolute height of a vein of relative thickness 1, voxels.
    pub vein_thickness: f32,
    /// Amplitude of layer surfaces of relative roughness 1, voxels.
    pub roughness: f32,
    /// Multiplies every layer's similarity, 0–1.
    pub similarity: f32,
    /// Frequency of the layer-surface noise, per voxel.
    pub scale: f32,
}

/// A whole configuration: materials, their affinities and the general parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubsurfaceConfig {
    /// The materials.
    pub materials: Vec<Material>,
    /// Affinity pairs.
    #[serde(default)]
    pub affinities: Vec<Affinity>,
    /// General parameters.
    pub general: General,
}

/// A configuration error: the JSON pointer of the offending field and what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct ConfigError {
    /// JSON pointer, e.g. `/materials/2/depth/min`.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

fn err(field: String, message: impl Into<String>) -> ConfigError {
    ConfigError {
        field,
        message: message.into(),
    }
}

fn unit(field: String, v: f32) -> Result<(), ConfigError> {
    if (0.0..=1.0).contains(&v) {
        Ok(())
    } else {
        Err(err(field, format!("{v} is not in [0, 1]")))
    }
}

fn range(field: &str, r: &Range) -> Result<(), ConfigError> {
    unit(format!("{field}/min"), r.min)?;
    unit(format!("{field}/max"), r.max)?;
    unit(format!("{field}/optimum"), r.optimum)?;
    if r.min > r.max {
        return Err(err(format!("{field}/min"), "min exceeds max"));
    }
    if r.optimum < r.min || r.optimum > r.max {
        return Err(err(
            format!("{field}/optimum"),
            "optimum is outside [min, max]",
        ));
    }
    Ok(())
}

fn positive(field: &str, v: f32, max: f32) -> Result<(), ConfigError> {
    if v.is_finite() && v > 0.0 && v <= max {
        Ok(())
    } else {
        Err(err(
            format!("/general/{field}"),
            format!("{v} is not in (0, {max}]"),
        ))
    }
}

impl SubsurfaceConfig {
    /// Parses and validates a JSON configuration; errors name the field.
    pub fn from_json(text: &str) -> Result<SubsurfaceConfig, ConfigError> {
        let de = &mut serde_json::Deserializer::from_str(text);
        let config: SubsurfaceConfig = serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            let pointer = if path == "." {
                String::new()
            } else {
                path.split('.')
                    .map(|p| format!("/{}", p.trim_start_matches('[').trim_end_matches(']')))
                    .collect::<String>()
                    .replace("/[", "/")
                    .replace('[', "/")
                    .replace(']', "")
            };
            err(pointer, e.inner().to_string())
        })?;
        config.validate()?;
        Ok(config)
    }

    /// Checks every value; the error names the first offending field.
    pub fn validate(&self) -> Result<(), ConfigError> {
        if self.materials.is_empty() || self.materials.len() > MAX_MATERIALS {
            return Err(err(
                "/materials".into(),
                format!("between 1 and {MAX_MATERIALS} materials"),
            ));
        }
        for (i, m) in self.materials.iter().enumerate() {
            let p = format!("/materials/{i}");
            if m.name.is_empty() {
                return Err(err(format!("{p}/name"), "empty name"));
            }
            if self.materials[..i].iter().any(|o| o.id == m.id) {
                return Err(err(format!("{p}/id"), format!("duplicate id {}", m.id)));
            }
            let f = m.flags;
            let kinds = [f.void, f.base, f.vein, f.cave]
                .iter()
                .filter(|b| **b)
                .count();
            if kinds > 1 {
                return Err(err(
                    format!("{p}/flags"),
                    "at most one of void, base, vein, cave",
                ));
            }
            unit(format!("{p}/area"), m.area)?;
            range(&format!("{p}/depth"), &m.depth)?;
            range(&format!("{p}/thickness"), &m.thickness)?;
            range(&format!("{p}/roughness"), &m.roughness)?;
            unit(format!("{p}/similarity"), m.similarity)?;
            unit(format!("{p}/blend"), m.blend)?;
        }
        if !self.materials.iter().any(|m| m.flags.base) {
            return Err(err("/materials".into(), "no material has the base flag"));
        }
        if !self.materials.iter().any(|m| m.flags.void) {
            return Err(err("/materials".into(), "no material has the void flag"));
        }
        for (i, a) in self.affinities.iter().enumerate() {
            let p = format!("/affinities/{i}");
            for (key, id) in [("a", a.a), ("b", a.b)] {
                if !self.materials.iter().any(|m| m.id == id) {
                    return Err(err(format!("{p}/{key}"), format!("unknown material {id}")));
                }
            }
            for (key, v) in [("same_layer", a.same_layer), ("next_layer", a.next_layer)] {
                if v != -1.0 && !(0.0..=1.0).contains(&v) {
                    return Err(err(
                        format!("{p}/{key}"),
                        format!("{v} is neither in [0, 1] nor -1"),
                    ));
                }
            }
            let dup = self.affinities[..i]
                .iter()
                .any(|o| (o.a, o.b) == (a.a, a.b) || (o.a, o.b) == (a.b, a.a));
            if dup {
                return Err(err(p, "pair listed twice"));
            }
        }
        let g = &self.general;
        positive("terrain_depth", g.terrain_depth, 4096.0)?;
        positive("layer_thickness", g.layer_thickness, 4096.0)?;
        positive("cave_area", g.cave_area, 1024.0)?;
        positive("vein_area", g.vein_area, 1024.0)?;
        positive("cave_thickness", g.cave_thickness, 1024.0)?;
        positive("vein_thickness", g.vein_thickness, 1024.0)?;
        positive("scale", g.scale, 16.0)?;
        if !(g.roughness.is_finite() && (0.0..=1024.0).contains(&g.roughness)) {
            return Err(err(
                "/general/roughness".into(),
                "not in [0, 1024]".to_string(),
            ));
        }
        unit("/general/cave_density".into(), g.cave_density)?;
        unit("/general/vein_density".into(), g.vein_density)?;
        unit("/general/similarity".into(), g.similarity)?;
        Ok(())
    }

    /// The paper's Table 2 configuration by name (`A0`…`B3`).
    pub fn preset(name: &str) -> Option<SubsurfaceConfig> {
        let (regular, caves, veins, density) = match name {
            "A0" => (3, 0, 0, 0.0),
            "A1" => (3, 0, 1, 0.5),
            "A2" => (3, 1, 0, 0.5),
            "A3" => (3, 1, 1, 0.25),
            "B0" => (6, 0, 0, 0.0),
            "B1" => (6, 0, 2, 0.5),
            "B2" => (6, 1, 0, 0.5),
            "B3" => (6, 1, 2, 0.25),
            _ => return None,
        };
        Some(preset(regular, caves, veins, density))
    }
}

/// Names of the Table 2 presets.
pub const PRESETS: [&str; 8] = ["A0", "A1", "A2", "A3", "B0", "B1", "B2", "B3"];

fn material(name: &str, id: u32, color: [u8; 3], flags: Flags) -> Material {
    let h = crate::terrain::hash::mix32(id.wrapping_add(0x51ab));
    let t = |k: u32| (((h >> (8 * k)) & 0xff) as f32) / 255.0;
    Material {
        name: name.into(),
        id,
        color,
        texture: format!("textures/{name}.png"),
        flags,
        area: 0.6 + 0.4 * t(0),
        depth: Range {
            min: 0.0,
            max: 1.0,
            optimum: t(1),
        },
        thickness: Range {
            min: 0.3,
            max: 0.8,
            optimum: 0.4 + 0.3 * t(2),
        },
        roughness: Range {
            min: 0.2,
            max: 0.9,
            optimum: 0.5,
        },
        similarity: 0.3 + 0.5 * t(3),
        blend: 0.2 + 0.2 * t(0),
    }
}

/// Table 2: `regular` layer materials, `caves` cave materials, `veins` vein materials, plus one
/// void and one base material; "all materials have the maximum affinity between them"; the
/// density applies to caves and veins alike.
fn preset(regular: u32, caves: u32, veins: u32, density: f32) -> SubsurfaceConfig {
    let mut materials = vec![
        material(
            "air",
            0,
            [200, 230, 255],
            Flags {
                void: true,
                ..Flags::default()
            },
        ),
        material(
            "bedrock",
            1,
            [40, 40, 45],
            Flags {
                base: true,
                ..Flags::default()
            },
        ),
    ];
    let names = ["clay", "sand", "limestone", "granite", "shale", "marble"];
    for (i, name) in names.iter().take(regular as usize).enumerate() {
        let c = 90 + 25 * i as u8;
        materials.push(material(
            name,
            10 + i as u32,
            [c, c - 20, c - 50],
            Flags::default(),
        ));
    }
    for i in 0..caves {
        materials.push(material(
            "cave",
            30 + i,
            [10, 10, 20],
            Flags {
                cave: true,
                ..Flags::default()
            },
        ));
    }
    let ores = ["iron", "gold"];
    for (i, name) in ores.iter().take(veins as usize).enumerate() {
        materials.push(material(
            name,
            40 + i as u32,
            [180, 120 + 60 * i as u8, 40],
            Flags {
                vein: true,
                ..Flags::default()
            },
        ));
    }
    let mut affinities = Vec::new();
    for (i, a) in materials.iter().enumerate() {
        for b in &materials[i + 1..] {
            affinities.push(Affinity {
                a: a.id,
                b: b.id,
                same_layer: 1.0,
                next_layer: 1.0,
            });
        }
    }
    SubsurfaceConfig {
        materials,
        affinities,
        general: General {
            terrain_depth: 40.0,
            layer_thickness: 14.0,
            cave_area: 24.0,
            vein_area: 24.0,
            cave_density: density,
            vein_density: density,
            cave_thickness: 8.0,
            vein_thickness: 5.0,
            roughness: 3.0,
            similarity: 0.6,
            scale: 1.0 / 24.0,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_and_round_trip() {
        for name in PRESETS {
            let c = SubsurfaceConfig::preset(name).expect("preset");
            c.validate().expect("valid");
            let text = serde_json::to_string(&c).expect("json");
            assert_eq!(SubsurfaceConfig::from_json(&text).expect("parse"), c);
        }
        assert!(SubsurfaceConfig::preset("C0").is_none());
    }

    #[test]
    fn errors_name_the_field() {
        let mut c = SubsurfaceConfig::preset("A3").expect("preset");
        c.materials[2].depth.min = 1.5;
        assert_eq!(
            c.validate().expect_err("bad").field,
            "/materials/2/depth/min"
        );
        let mut c = SubsurfaceConfig::preset("A3").expect("preset");
        c.affinities[3].next_layer = -0.5;
        assert_eq!(
            c.validate().expect_err("bad").field,
            "/affinities/3/next_layer"
        );
        let mut c = SubsurfaceConfig::preset("A3").expect("preset");
        c.general.scale = 0.0;
        assert_eq!(c.validate().expect_err("bad").field, "/general/scale");
        let mut v =
            serde_json::to_value(SubsurfaceConfig::preset("A1").expect("preset")).expect("json");
        v["materials"][1]["colour"] = serde_json::json!([1, 2, 3]);
        let e = SubsurfaceConfig::from_json(&v.to_string()).expect_err("unknown field");
        assert_eq!(e.field, "/materials/1/colour");
        v["materials"][1]
            .as_object_mut()
            .expect("object")
            .remove("colour");
        v["general"]["scale"] = serde_json::json!("big");
        let e = SubsurfaceConfig::from_json(&v.to_string()).expect_err("type");
        assert_eq!(e.field, "/general/scale");
    }

    #[test]
    fn triangular_draw_stays_in_range() {
        let r = Range {
            min: 0.2,
            max: 0.9,
            optimum: 0.3,
        };
        for i in 0..100 {
            let v = r.draw(i as f32 / 100.0);
            assert!((0.2..=0.9).contains(&v), "{v}");
        }
    }
}
