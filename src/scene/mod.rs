//! The scene document: everything a world is besides its seed (`api/scene.schema.json`).
//!
//! A scene is a JSON object with the world settings (`world`, a [`WorldParams`]) and arrays of
//! elements (`regions`, `volumes`, `strata`, `materials`, `decals`). Every element has a string
//! `id`, unique within its array, and a world-space bounding box `bbox` in metres; its other
//! fields belong to the issues that give the element kind its meaning and are kept as they are.
//!
//! Pure code: no tokio, no axum, no I/O. The store keeps scenes as JSON values (edits are JSON
//! Patches applied to them); [`Scene::from_value`] is the one gate every stored version passes,
//! and [`dirty_region`] says what an edit changed, for incremental recompute and streaming
//! invalidation. [`SceneInputs`] / [`tile_inputs`] give a tile's input hash, the key of the stage
//! cache: the seed, settings, key, seams and the elements within reach of the tile.

mod dirty;
mod inputs;

pub(crate) use crate::element::path_pointer;
pub use crate::element::{escape_token, BBox, Element, Rect, MAX_COORD_M, MAX_ID_LEN};
pub use dirty::{dirty_region, Dirty};
pub use inputs::{
    canonical_json, margin_m, tile_footprint, tile_inputs, tile_reach, RegionInput, SceneInputs,
    StrataInput, VolumeInput, INPUTS_DOMAIN, TILE_CODE_VERSION,
};

use crate::ptex::spec::{MAX_DECAL_ELEMENTS, MAX_MATERIAL_ELEMENTS};
use crate::terrain::plan::WORLD_LIMIT_CELLS;
use crate::terrain::world::ParamError;
use crate::terrain::WorldParams;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The element arrays of a scene, in document order.
pub const ELEMENT_KINDS: [&str; 5] = ["regions", "volumes", "strata", "materials", "decals"];
/// The element arrays that only the Ptex bake reads (the last of [`ELEMENT_KINDS`]): tiles and
/// volume chunks do not depend on them.
pub const PTEX_KINDS: [&str; 2] = ["materials", "decals"];

/// Whether elements of the array `ELEMENT_KINDS[kind]` can change tiles and volume chunks (the
/// surface), not only Ptex pages.
pub fn shapes_surface(kind: usize) -> bool {
    ELEMENT_KINDS
        .get(kind)
        .is_some_and(|name| !PTEX_KINDS.contains(name))
}
/// A scene document.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// World settings; [`WorldParams::default()`] when absent.
    #[serde(default)]
    pub world: WorldParams,
    /// Authored (gradient-domain) regions.
    #[serde(default)]
    pub regions: Vec<Element>,
    /// Volume regions (feature curves, meshes).
    #[serde(default)]
    pub volumes: Vec<Element>,
    /// Subsurface layers, veins and caves.
    #[serde(default)]
    pub strata: Vec<Element>,
    /// Materials.
    #[serde(default)]
    pub materials: Vec<Element>,
    /// Decals.
    #[serde(default)]
    pub decals: Vec<Element>,
}

/// Why a scene document is refused: the JSON pointer (RFC 6901) of the offending value and
/// what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {message}")]
pub struct SceneError {
    /// E.g. `/world/biomes/2/generator/hurst`; `""` is the whole document.
    pub pointer: String,
    /// Human-readable reason.
    pub message: String,
}

impl SceneError {
    fn new(pointer: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            pointer: pointer.into(),
            message: message.into(),
        }
    }
}

/// Converts a [`ParamError`] field (`biomes[2].generator.hurst`) into a JSON pointer below
/// `prefix` (`/world/biomes/2/generator/hurst`).
pub fn param_pointer(prefix: &str, field: &str) -> String {
    let mut out = String::from(prefix);
    for part in field.split('.').filter(|p| !p.is_empty()) {
        let mut rest = part;
        // `name[1][2]` → `name`, `1`, `2`.
        let name_end = rest.find('[').unwrap_or(rest.len());
        out.push('/');
        out.push_str(&escape_token(&rest[..name_end]));
        rest = &rest[name_end..];
        while let Some(inner) = rest.strip_prefix('[') {
            let close = inner.find(']').unwrap_or(inner.len());
            out.push('/');
            out.push_str(&escape_token(&inner[..close]));
            rest = inner.get(close + 1..).unwrap_or("");
        }
    }
    out
}

fn valid_id(id: &str) -> bool {
    !id.is_empty()
        && id.len() <= MAX_ID_LEN
        && id
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'_' | b':' | b'-'))
}

impl Scene {
    /// Parses and validates a scene document; the error names the offending value.
    pub fn from_value(value: &Value) -> Result<Self, SceneError> {
        if !value.is_object() {
            return Err(SceneError::new("", "a scene must be a JSON object"));
        }
        let scene: Scene = serde_path_to_error::deserialize(value)
            .map_err(|e| SceneError::new(path_pointer(e.path()), e.inner().to_string()))?;
        scene.validate()?;
        Ok(scene)
    }

    /// The document form of the scene (every field present).
    pub fn to_value(&self) -> Value {
        serde_json::to_value(self).unwrap_or(Value::Null)
    }

    /// The element arrays with their names, in [`ELEMENT_KINDS`] order.
    pub fn kinds(&self) -> [(&'static str, &[Element]); 5] {
        [
            ("regions", &self.regions),
            ("volumes", &self.volumes),
            ("strata", &self.strata),
            ("materials", &self.materials),
            ("decals", &self.decals),
        ]
    }

    /// The cost limits of issue 18 for the elements that are new or changed since `before` (all
    /// of them without it). Checked when a scene is written (a new world, an edit), not when a
    /// stored one is read, so a world accepted under older limits keeps loading and can still
    /// be edited:
    ///
    /// - a region's bbox lies within the world (|coordinate| ≤ `WORLD_LIMIT_CELLS · cell_m`),
    ///   since its procedural base is sampled over the whole bbox (finding 1: ±1e9 m grew the
    ///   process to 13 GB);
    /// - a region's work (its solves, thermal sweeps and droplet steps) is within its budget and
    ///   its `samples` within the accepted maximum
    ///   ([`crate::authoring::RegionSpec::check_cost`]).
    pub fn check_costs(&self, before: Option<&Scene>) -> Result<(), SceneError> {
        self.check_ptex(before)?;
        let limit = WORLD_LIMIT_CELLS * f64::from(self.world.cell_m);
        for (i, e) in self.regions.iter().enumerate() {
            if before.is_some_and(|b| b.regions.contains(e)) {
                continue;
            }
            let at = |f: &str| format!("/regions/{i}{f}");
            for axis in 0..2 {
                for (name, v) in [("min", e.bbox.min[axis]), ("max", e.bbox.max[axis])] {
                    if v.abs() > limit {
                        return Err(SceneError::new(
                            at(&format!("/bbox/{name}/{axis}")),
                            format!(
                                "a region lies within the world: within ±{limit} m \
                                 (world_limit_m of /v1/info)"
                            ),
                        ));
                    }
                }
            }
            crate::authoring::RegionSpec::from_element(e)
                .and_then(|r| r.check_cost())
                .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
        }
        Ok(())
    }

    /// The limits of the `materials` and `decals` elements ([`crate::ptex::spec`]) for those
    /// new or changed since `before`: each parses, material names are unique, and the arrays
    /// hold at most [`MAX_MATERIAL_ELEMENTS`] and [`MAX_DECAL_ELEMENTS`].
    fn check_ptex(&self, before: Option<&Scene>) -> Result<(), SceneError> {
        use crate::ptex::spec::{DecalSpec, MaterialSpec};
        for (kind, list, max) in [
            ("materials", &self.materials, MAX_MATERIAL_ELEMENTS),
            ("decals", &self.decals, MAX_DECAL_ELEMENTS),
        ] {
            let old = before.map(|b| {
                if kind == "materials" {
                    &b.materials
                } else {
                    &b.decals
                }
            });
            if list.len() > max && old.is_none_or(|o| o.len() < list.len()) {
                return Err(SceneError::new(
                    format!("/{kind}/{max}"),
                    format!("at most {max} {kind} elements"),
                ));
            }
            let mut names = std::collections::HashSet::new();
            for (i, e) in list.iter().enumerate() {
                let at = |f: &str| format!("/{kind}/{i}{f}");
                let fresh = old.is_none_or(|o| !o.contains(e));
                if kind == "decals" {
                    if fresh {
                        DecalSpec::from_element(e)
                            .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
                    }
                    continue;
                }
                let parsed = MaterialSpec::from_element(e);
                if fresh {
                    parsed
                        .clone()
                        .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
                }
                if let Ok(m) = parsed {
                    if !names.insert(m.name.clone()) && fresh {
                        return Err(SceneError::new(
                            at("/name"),
                            format!("material {:?} is named by an earlier element", m.name),
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// The images the scene's `materials` and `decals` elements name (those that parse), with
    /// the JSON pointer of each reference, in document order.
    pub fn image_refs(&self) -> Vec<(String, [u8; 32])> {
        use crate::ptex::spec::{DecalSpec, MaterialSpec};
        let mut out = Vec::new();
        for (i, e) in self.materials.iter().enumerate() {
            if let Ok(m) = MaterialSpec::from_element(e) {
                out.extend(
                    m.images()
                        .into_iter()
                        .map(|(p, h)| (format!("/materials/{i}{p}"), h)),
                );
            }
        }
        for (i, e) in self.decals.iter().enumerate() {
            if let Ok(d) = DecalSpec::from_element(e) {
                out.extend(
                    d.images()
                        .into_iter()
                        .map(|(p, h)| (format!("/decals/{i}{p}"), h)),
                );
            }
        }
        out
    }

    /// Checks the world settings and every element.
    pub fn validate(&self) -> Result<(), SceneError> {
        self.world.validate().map_err(|e: ParamError| {
            SceneError::new(param_pointer("/world", &e.field), e.message)
        })?;
        for (kind, elements) in self.kinds() {
            let mut seen = std::collections::HashSet::new();
            for (i, e) in elements.iter().enumerate() {
                let at = |f: &str| format!("/{kind}/{i}{f}");
                if !valid_id(&e.id) {
                    return Err(SceneError::new(
                        at("/id"),
                        format!("must be 1 to {MAX_ID_LEN} characters of A-Z a-z 0-9 . _ : -"),
                    ));
                }
                if !seen.insert(e.id.as_str()) {
                    return Err(SceneError::new(
                        at("/id"),
                        format!("duplicate id {:?} in {kind}", e.id),
                    ));
                }
                for axis in 0..2 {
                    for (name, v) in [("min", e.bbox.min[axis]), ("max", e.bbox.max[axis])] {
                        if !v.is_finite() || v.abs() > MAX_COORD_M {
                            return Err(SceneError::new(
                                at(&format!("/bbox/{name}/{axis}")),
                                format!("must be finite and within ±{MAX_COORD_M} m"),
                            ));
                        }
                    }
                    if e.bbox.min[axis] > e.bbox.max[axis] {
                        return Err(SceneError::new(
                            at(&format!("/bbox/max/{axis}")),
                            "must not be less than min",
                        ));
                    }
                }
                if kind == "regions" {
                    crate::authoring::RegionSpec::from_element(e)
                        .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
                }
                if kind == "volumes" {
                    crate::volume::element::VolumeSpec::from_element(e)
                        .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
                }
                if kind == "strata" {
                    if i >= crate::subsurface::spec::MAX_STRATA {
                        return Err(SceneError::new(
                            format!("/strata/{i}"),
                            format!(
                                "at most {} strata elements",
                                crate::subsurface::spec::MAX_STRATA
                            ),
                        ));
                    }
                    crate::subsurface::StrataSpec::from_element(e)
                        .map_err(|x| SceneError::new(at(&x.pointer), x.message))?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    /// An image hash (64 hex digits).
    const H: &str = "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef";

    fn refused(v: serde_json::Value) -> SceneError {
        let scene = Scene::from_value(&v).expect("a stored scene reads");
        let doc = v.to_string();
        scene.check_costs(None).expect_err(&doc)
    }

    fn decal(extra: serde_json::Value) -> serde_json::Value {
        let mut d = json!({"id": "d", "bbox": {"min": [-20, -20], "max": [20, 20]}, "image": H,
                           "center": [0, 0], "size_m": [10, 10]});
        for (k, v) in extra.as_object().expect("object") {
            d[k] = v.clone();
        }
        json!({"decals": [d]})
    }

    #[test]
    fn written_elements_are_refused_naming_the_field_and_the_limit() {
        let cases = [
            (
                decal(json!({"size_m": [10, 5000]})),
                "/decals/0/size_m/1",
                "4096",
            ),
            (
                decal(json!({"opacity": -0.5})),
                "/decals/0/opacity",
                "[0, 1]",
            ),
            (
                decal(json!({"image": "xyz"})),
                "/decals/0/image",
                "64 lowercase hex",
            ),
            (
                decal(json!({"projection": "side"})),
                "/decals/0/projection",
                "top_down",
            ),
            (
                decal(json!({"center": [18, 0]})),
                "/decals/0/bbox",
                "must contain",
            ),
            (
                decal(json!({"rotation_deg": 720})),
                "/decals/0/rotation_deg",
                "360",
            ),
            (decal(json!({"colour": 1})), "/decals/0", "unknown field"),
            (
                json!({"materials": [{"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]},
                       "name": "Rock"}]}),
                "/materials/0/name",
                "a-z",
            ),
            (
                json!({"materials": [{"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]},
                       "name": "rock", "octaves": 9}]}),
                "/materials/0/octaves",
                "8",
            ),
            (
                json!({"materials": [{"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]},
                       "name": "rock", "base": [0.5, 2.0, 0.5]}]}),
                "/materials/0/base/1",
                "[0, 1]",
            ),
            (
                json!({"materials": [{"id": "m", "bbox": {"min": [0, 0], "max": [0, 0]},
                       "name": "rock", "texture": {"albedo": H, "repeat_m": 512}}]}),
                "/materials/0/texture/repeat_m",
                "256",
            ),
            (
                json!({"materials": [
                    {"id": "a", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "moss"},
                    {"id": "b", "bbox": {"min": [0, 0], "max": [0, 0]}, "name": "moss"}]}),
                "/materials/1/name",
                "earlier element",
            ),
        ];
        for (v, pointer, limit) in cases {
            let e = refused(v);
            assert!(e.pointer.starts_with(pointer), "{pointer}: {e}");
            assert!(e.message.contains(limit), "{pointer}: {e}");
        }
        let many: Vec<_> = (0..=MAX_DECAL_ELEMENTS)
            .map(|i| {
                let mut d = decal(json!({}))["decals"][0].clone();
                d["id"] = json!(format!("d{i}"));
                d
            })
            .collect();
        let e = refused(json!({ "decals": many }));
        assert_eq!(e.pointer, format!("/decals/{MAX_DECAL_ELEMENTS}"));
    }

    #[test]
    fn a_stored_free_form_element_still_reads_and_leaves_the_default_set() {
        // Before these elements had a schema any fields were kept; such a world loads, its
        // pages bake with the default set, and an edit that leaves the element alone passes.
        let v = json!({"decals": [{"id": "d", "bbox": {"min": [0, 0], "max": [1, 1]},
                                   "anything": {"h": 3}}]});
        let scene = Scene::from_value(&v).expect("reads");
        assert_eq!(scene.check_costs(Some(&scene)), Ok(()));
        let specs = crate::ptex::spec::PtexSpecs::new(&scene.materials, &scene.decals);
        assert!(specs.is_empty());
        assert_eq!(
            specs.set(9, &std::collections::HashMap::new()),
            crate::ptex::MaterialSet::default_ground(9)
        );
    }

    #[test]
    fn default_round_trips() {
        let v = Scene::default().to_value();
        assert_eq!(Scene::from_value(&v).expect("valid"), Scene::default());
        assert_eq!(
            Scene::from_value(&json!({})).expect("empty is default"),
            Scene::default()
        );
    }

    #[test]
    fn a_region_beyond_the_world_is_refused_before_any_work() {
        let region = |m: f64| {
            let mut v = Scene::default().to_value();
            v["regions"] = json!([{"id": "r", "bbox": {"min": [-m, -m], "max": [m, m]},
                "samples": 33, "ops": []}]);
            v
        };
        let limit = WORLD_LIMIT_CELLS * f64::from(WorldParams::default().cell_m);
        let at_limit = Scene::from_value(&region(limit)).expect("a valid scene");
        assert_eq!(at_limit.check_costs(None), Ok(()));
        // A stored scene reads without the cost limits, so a world accepted before them loads.
        let huge = Scene::from_value(&region(1e9)).expect("it reads");
        let e = huge.check_costs(None).expect_err("±1e9 m");
        assert_eq!(e.pointer, "/regions/0/bbox/min/0");
        assert!(e.message.contains(&format!("±{limit} m")), "{}", e.message);
        // An edit that leaves the element as it was is accepted; one that adds it is not.
        assert_eq!(huge.check_costs(Some(&huge)), Ok(()));
        let e = huge
            .check_costs(Some(&Scene::default()))
            .expect_err("added by the edit");
        assert_eq!(e.pointer, "/regions/0/bbox/min/0");
    }

    #[test]
    fn a_stored_region_of_the_largest_grid_keeps_loading_and_editing() {
        let mut v = Scene::default().to_value();
        v["regions"] = json!([{"id": "r", "bbox": {"min": [0, 0], "max": [8192, 8192]},
            "samples": 2049, "ops": []}]);
        let stored = Scene::from_value(&v).expect("a stored 2049² region reads");
        assert_eq!(stored.check_costs(Some(&stored)), Ok(()));
        let e = stored
            .check_costs(Some(&Scene::default()))
            .expect_err("added by an edit");
        assert_eq!(e.pointer, "/regions/0/samples");
    }

    #[test]
    fn param_pointers() {
        assert_eq!(
            param_pointer("/world", "biomes[2].generator.hurst"),
            "/world/biomes/2/generator/hurst"
        );
        assert_eq!(
            param_pointer("/world", "biomes[0].scatter[3].density"),
            "/world/biomes/0/scatter/3/density"
        );
        assert_eq!(param_pointer("/world", "cell_m"), "/world/cell_m");
        assert_eq!(param_pointer("", "a/b~c"), "/a~1b~0c");
    }

    #[test]
    fn errors_are_pointers() {
        let mut v = Scene::default().to_value();
        v["world"]["earth"]["gain"] = json!(5.0);
        let e = Scene::from_value(&v).expect_err("gain");
        assert_eq!(e.pointer, "/world/earth/gain");

        let mut v = Scene::default().to_value();
        v["world"]["biomes"][2]["relief"]["erosion"] = json!(3.0);
        let e = Scene::from_value(&v).expect_err("erosion");
        assert_eq!(e.pointer, "/world/biomes/2/relief/erosion");

        let mut v = Scene::default().to_value();
        v["world"]["earth"]["octaves"] = json!("many");
        let e = Scene::from_value(&v).expect_err("type");
        assert_eq!(e.pointer, "/world/earth/octaves");

        // A classic world's biome generators, likewise.
        let mut v = Scene::default().to_value();
        v["world"] = serde_json::to_value(WorldParams::classic()).expect("classic");
        v["world"]["biomes"][2]["generator"]["hurst"] = json!(5.0);
        let e = Scene::from_value(&v).expect_err("hurst");
        assert_eq!(e.pointer, "/world/biomes/2/generator/hurst");

        let v = json!({"regions": [{"id": "a", "bbox": {"min": [0, 0], "max": [1, 1]}},
                                   {"id": "a", "bbox": {"min": [0, 0], "max": [1, 1]}}]});
        assert_eq!(
            Scene::from_value(&v).expect_err("dup").pointer,
            "/regions/1/id"
        );

        let v = json!({"decals": [{"id": "d", "bbox": {"min": [0, 5], "max": [1, 1]}}]});
        assert_eq!(
            Scene::from_value(&v).expect_err("bbox").pointer,
            "/decals/0/bbox/max/1"
        );
        let v = json!({"decals": [{"id": "", "bbox": {"min": [0, 0], "max": [1, 1]}}]});
        assert_eq!(
            Scene::from_value(&v).expect_err("id").pointer,
            "/decals/0/id"
        );
        assert_eq!(
            Scene::from_value(&json!([])).expect_err("array").pointer,
            ""
        );
    }

    #[test]
    fn scenes_refuse_bad_regions_naming_the_field() {
        let bad = json!({"regions": [{"id": "a", "bbox": {"min": [0, 0], "max": [9, 9]},
            "ops": [{"op": "freeze", "center": [0, 0], "radius_m": "wide"}]}]});
        let e = Scene::from_value(&bad).expect_err("refused");
        assert!(e.pointer.starts_with("/regions/0/ops/0"), "{e}");
    }

    #[test]
    fn elements_keep_their_other_fields() {
        let v = json!({"regions": [{"id": "r1", "bbox": {"min": [0.0, 0.5], "max": [10.0, 10.0]},
                                    "ops": [{"op": "freeze", "center": [1, 2], "radius_m": 3}]}],
                       "decals": [{"id": "d1", "bbox": {"min": [0.0, 0.5], "max": [10.0, 10.0]},
                                   "anything": {"tool": "raise", "h": 3}}]});
        let s = Scene::from_value(&v).expect("valid");
        assert_eq!(s.regions[0].rest["ops"][0]["radius_m"], json!(3));
        assert_eq!(s.decals[0].rest["anything"]["h"], json!(3));
        assert_eq!(s.to_value()["regions"], v["regions"]);
        assert_eq!(s.to_value()["decals"], v["decals"]);
    }
}
