//! The `strata` scene element (issue 6, "Integration"): which subsurface configuration a part of
//! the world has, at what voxel size, and whether its caves carve the world's solid.
//!
//! ```json
//! {"id": "geology", "bbox": {"min": [-5000, -5000], "max": [5000, 5000]},
//!  "preset": "B2", "voxel_m": 1.0, "carve": true}
//! ```
//!
//! Exactly one of `preset` (a Table 2 name, [`super::PRESETS`]) and `config` (a whole
//! configuration, `api/subsurface.schema.json`) gives the configuration. The element has effect
//! inside its `bbox` only: where several elements cover a point, the last one in document order
//! is in force there, and a vein or cave belongs to an element only when its bounding square lies
//! inside the element's `bbox` (so no cave is cut by a bbox edge).

use super::config::SubsurfaceConfig;
use crate::element::Element;
use serde::Deserialize;

/// Smallest voxel side, metres.
pub const MIN_VOXEL_M: f64 = 0.25;
/// Largest voxel side, metres (bounds the tiles a column chunk reads).
pub const MAX_VOXEL_M: f64 = 4.0;
/// Most `strata` elements in a scene.
pub const MAX_STRATA: usize = 16;

/// A parsed `strata` element.
#[derive(Clone, Debug, PartialEq)]
pub struct StrataSpec {
    /// Element id.
    pub id: String,
    /// `[x, z]` of the west-north corner of the bbox, metres.
    pub min: [f64; 2],
    /// `[x, z]` of the east-south corner of the bbox, metres.
    pub max: [f64; 2],
    /// The configuration (a preset's or the element's own), validated.
    pub config: SubsurfaceConfig,
    /// Side of a subsurface voxel, metres.
    pub voxel_m: f64,
    /// Whether caves carve the world's solid (volume chunks, height tiles where they breach).
    pub carve: bool,
    /// Whether height tiles of LOD 0–3 mark the vertices where its caves breach the ground as
    /// overridden by volume chunks (`volume_override`), so stream clients draw the chunks there.
    /// Off unless the element says so: tiles of elements stored before keep their bytes.
    pub mark_openings: bool,
}

/// Why a `strata` element is refused: a JSON pointer relative to the element and the reason.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {message}")]
pub struct StrataError {
    /// Pointer relative to the element, e.g. `/config/general/cave_density`.
    pub pointer: String,
    /// Why.
    pub message: String,
}

fn err(pointer: impl Into<String>, message: impl Into<String>) -> StrataError {
    StrataError {
        pointer: pointer.into(),
        message: message.into(),
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Fields {
    #[serde(default)]
    preset: Option<String>,
    #[serde(default)]
    config: Option<serde_json::Value>,
    #[serde(default = "default_voxel_m")]
    voxel_m: f64,
    #[serde(default = "default_carve")]
    carve: bool,
    #[serde(default)]
    mark_openings: bool,
}

fn default_voxel_m() -> f64 {
    1.0
}

fn default_carve() -> bool {
    true
}

impl StrataSpec {
    /// Parses a `strata` element.
    ///
    /// # Errors
    /// [`StrataError`] naming the offending field.
    pub fn from_element(e: &Element) -> Result<StrataSpec, StrataError> {
        let value = serde_json::Value::Object(e.rest.clone());
        let f: Fields = serde_path_to_error::deserialize(&value).map_err(|x| {
            err(
                crate::element::path_pointer(x.path()),
                x.inner().to_string(),
            )
        })?;
        let config = match (f.preset, f.config) {
            (Some(_), Some(_)) => {
                return Err(err("/config", "give either preset or config, not both"));
            }
            (None, None) => {
                return Err(err(
                    "/preset",
                    format!(
                        "a strata element needs a preset (one of {:?}) or a config",
                        super::PRESETS
                    ),
                ));
            }
            (Some(name), None) => SubsurfaceConfig::preset(&name).ok_or_else(|| {
                err(
                    "/preset",
                    format!("unknown preset {name:?}; one of {:?}", super::PRESETS),
                )
            })?,
            (None, Some(c)) => {
                let text = serde_json::to_string(&c).unwrap_or_default();
                SubsurfaceConfig::from_json(&text)
                    .map_err(|x| err(format!("/config{}", x.field), x.message))?
            }
        };
        if !(f.voxel_m.is_finite() && (MIN_VOXEL_M..=MAX_VOXEL_M).contains(&f.voxel_m)) {
            return Err(err(
                "/voxel_m",
                format!("must be a number of metres in [{MIN_VOXEL_M}, {MAX_VOXEL_M}]"),
            ));
        }
        Ok(StrataSpec {
            id: e.id.clone(),
            min: e.bbox.min,
            max: e.bbox.max,
            config,
            voxel_m: f.voxel_m,
            carve: f.carve,
            mark_openings: f.mark_openings,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn element(rest: serde_json::Value) -> Element {
        let mut v = json!({"id": "g", "bbox": {"min": [0, 0], "max": [100, 100]}});
        if let (Some(o), Some(r)) = (v.as_object_mut(), rest.as_object()) {
            o.extend(r.clone());
        }
        serde_json::from_value(v).expect("element")
    }

    #[test]
    fn presets_and_configs_parse() {
        let s = StrataSpec::from_element(&element(json!({"preset": "B2"}))).expect("preset");
        assert_eq!(s.config, SubsurfaceConfig::preset("B2").expect("B2"));
        assert_eq!((s.voxel_m, s.carve, s.mark_openings), (1.0, true, false));
        let config =
            serde_json::to_value(SubsurfaceConfig::preset("A3").expect("A3")).expect("config json");
        let s = StrataSpec::from_element(&element(
            json!({"config": config, "voxel_m": 2, "carve": false}),
        ))
        .expect("config");
        assert_eq!((s.voxel_m, s.carve), (2.0, false));
    }

    #[test]
    fn errors_name_the_field() {
        let at = |rest: serde_json::Value| {
            StrataSpec::from_element(&element(rest))
                .expect_err("refused")
                .pointer
        };
        assert_eq!(at(json!({})), "/preset");
        assert_eq!(at(json!({"preset": "C9"})), "/preset");
        assert_eq!(at(json!({"preset": "A0", "voxel_m": 0})), "/voxel_m");
        assert_eq!(at(json!({"preset": "A0", "carve": 3})), "/carve");
        assert_eq!(at(json!({"preset": "A0", "depth": 3})), "/depth");
        let mut config =
            serde_json::to_value(SubsurfaceConfig::preset("A3").expect("A3")).expect("config json");
        config["general"]["cave_density"] = json!(1.5);
        assert_eq!(
            at(json!({ "config": config })),
            "/config/general/cave_density"
        );
    }
}
