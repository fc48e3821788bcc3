//! The input hash of a tile: what the stage cache (`cache`) keys a tile by.
//!
//! A tile's input hash is blake3 over a canonical encoding of everything the tile depends on, in
//! this order (integers little-endian):
//!
//! 1. the domain tag [`INPUTS_DOMAIN`] and [`TILE_CODE_VERSION`] (`u32`);
//! 2. the seed (`u64`);
//! 3. the world settings: blake3 of the canonical JSON of the [`WorldParams`];
//! 4. the key: `lod` (`u32`), `x`, `z` (`i64`);
//! 5. the seam flags `n, e, s, w` (one byte each, 0 or 1);
//! 6. the number of scene elements that [reach](tile_reach) the tile (`u64`), then for each of
//!    them, in [`super::ELEMENT_KINDS`] order and document order within an array: the index of
//!    its array (`u8`) and blake3 of the element's canonical JSON. Only the arrays that shape
//!    the surface count ([`super::shapes_surface`]): `materials` and `decals` change Ptex pages,
//!    never a tile's bytes, so they are not a tile's inputs.
//!
//! Canonical JSON: no whitespace, object keys sorted by their UTF-8 bytes, strings escaped as
//! serde_json escapes them, numbers as serde_json prints them (shortest round-trip form).
//! Hashing the hash of a document instead of the document itself costs no collision resistance
//! and keeps a version's [`SceneInputs`] small.
//!
//! **The margin.** An element is part of a tile's inputs when its `bbox` meets the tile's
//! footprint grown on every side by [`margin_m`] = 2 vertex spacings of the tile's LOD, plus the
//! biome blur radius with the classic generator. That bounds how far from its footprint a tile reads the world: the 67×67 field
//! reaches one vertex spacing beyond the footprint plus the blur kernel's half-width
//! (`round(radius / spacing)` spacings, at most radius + spacing / 2); the seam strips lie on the
//! tile's edges at the next coarser LOD and reach the kernel's half-width there (at most
//! radius + spacing). An element whose `bbox` stays outside this margin cannot change the tile,
//! provided element kinds only have effect inside their `bbox` (the scene's contract). A stage
//! that reads farther must grow the margin and bump [`TILE_CODE_VERSION`].
//!
//! So an edit whose dirty region ([`super::dirty_region`]) meets a tile's grown footprint changes
//! the tile's hash, and an edit elsewhere leaves it — and its cached result — untouched. A change
//! of the world settings changes every hash.

use super::{Element, Rect, Scene};
use crate::authoring::RegionSpec;
use crate::ptex::spec::PtexSpecs;
use crate::subsurface::{Geology, StrataSpec};
use crate::terrain::{Generator, TileKey, WorldParams};
use crate::volume::element::VolumeSpec;
use serde_json::Value;
use std::sync::Arc;

/// Domain tag at the start of every tile input encoding.
pub const INPUTS_DOMAIN: &[u8] = b"strata.tile-inputs\0";

/// Version of the code that turns inputs into tiles. Bump it whenever a change to the world
/// function (`src/terrain`, its WGSL twin, the seam snapping) or to the edits tiles take
/// (`src/authoring` tools and solver, `src/subsurface` breaches) changes any tile's bits, so
/// every cached result — in memory and on disk — is orphaned rather than served stale.
///
/// 2: the thermal erosion brush adds its change instead of replacing the target gradient, and
/// the Poisson solver loads its right-hand side without per-neighbour divisions.
/// 3: a warm Poisson re-solve between a region's operations may end with finishing sweeps
/// instead of a global cycle, and volume regions' harmonic fill runs on a Galerkin hierarchy
/// (the volume overrides tiles mark can move).
/// 4: the local Poisson re-solve smooths a wider band after its write-back and rounds its window
/// sweeps differently (warm re-solves between a region's operations change in the last bits), and
/// the Perona–Malik sweep of volume regions uses fused multiply-adds.
/// 5: the local Poisson re-solve stops its cycles at 0.4 of the tolerance instead of 0.25 (warm
/// re-solves between a region's operations may run one cycle fewer).
pub const TILE_CODE_VERSION: u32 = 5;

/// The vertex spacing of a LOD, metres.
fn spacing_m(world: &WorldParams, lod: u32) -> f64 {
    world.cell_m as f64 * (1u64 << lod.min(62)) as f64
}

/// How far beyond its footprint a tile at `lod` reads the world, metres: two vertex spacings of
/// that LOD, plus the biome blur radius with the classic generator (whose blur reads the biome
/// map of the tile's own lattice). The `earth-1` blur reads only the procedural climate lattice,
/// which no scene element changes, so it adds nothing.
pub fn margin_m(world: &WorldParams, lod: u32) -> f64 {
    let blur = match world.generator {
        Generator::Classic => world.layout.blur_radius_m as f64,
        Generator::Earth1 => 0.0,
    };
    blur + 2.0 * spacing_m(world, lod)
}

/// The closed world-space square a tile covers: `[x·64·δ, (x+1)·64·δ] × [z·64·δ, (z+1)·64·δ]`
/// with `δ = cell_m · 2^lod`.
pub fn tile_footprint(world: &WorldParams, key: TileKey) -> Rect {
    let size = 64.0 * spacing_m(world, key.lod);
    Rect {
        min: [key.x as f64 * size, key.z as f64 * size],
        max: [(key.x + 1) as f64 * size, (key.z + 1) as f64 * size],
    }
}

/// The tile's footprint grown by [`margin_m`] on every side: the elements whose `bbox` meets it
/// are inputs of the tile.
pub fn tile_reach(world: &WorldParams, key: TileKey) -> Rect {
    let f = tile_footprint(world, key);
    let m = margin_m(world, key.lod);
    Rect {
        min: [f.min[0] - m, f.min[1] - m],
        max: [f.max[0] + m, f.max[1] + m],
    }
}

/// Writes `v` as canonical JSON (see the module docs).
pub fn canonical_json(v: &Value, out: &mut Vec<u8>) {
    match v {
        Value::Null | Value::Bool(_) | Value::Number(_) | Value::String(_) => {
            // serde_json writes scalars without whitespace; a scalar cannot fail to serialise.
            out.extend_from_slice(serde_json::to_string(v).unwrap_or_default().as_bytes());
        }
        Value::Array(items) => {
            out.push(b'[');
            for (i, item) in items.iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                canonical_json(item, out);
            }
            out.push(b']');
        }
        Value::Object(map) => {
            let mut keys: Vec<&String> = map.keys().collect();
            keys.sort_unstable_by(|a, b| a.as_bytes().cmp(b.as_bytes()));
            out.push(b'{');
            for (i, k) in keys.into_iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                canonical_json(&Value::String(k.clone()), out);
                out.push(b':');
                canonical_json(&map[k], out);
            }
            out.push(b'}');
        }
    }
}

/// blake3 of the canonical JSON of a serialisable value.
fn digest<T: serde::Serialize>(value: &T) -> [u8; 32] {
    let mut bytes = Vec::new();
    canonical_json(
        &serde_json::to_value(value).unwrap_or(Value::Null),
        &mut bytes,
    );
    *blake3::hash(&bytes).as_bytes()
}

/// One element as a tile input: its array, its box, the digest of its canonical JSON.
#[derive(Clone, Debug, PartialEq)]
struct ElementInput {
    kind: u8,
    rect: Rect,
    digest: [u8; 32],
}

/// What the input hashes of one scene version's tiles are made of, precomputed once per version:
/// the digest of the world settings and, per element, its box and digest.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneInputs {
    world: WorldParams,
    world_digest: [u8; 32],
    elements: Vec<ElementInput>,
    surface_digest: [u8; 32],
    regions: Vec<RegionInput>,
    strata: Vec<StrataInput>,
    volumes: Vec<VolumeInput>,
    ptex: Arc<PtexSpecs>,
}

/// A volume region of the scene, parsed, with the digest that keys its solution.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeInput {
    /// Digest of the world settings and the element: equal digests, equal solutions (with the
    /// seed).
    pub digest: [u8; 32],
    /// The parsed element.
    pub spec: Arc<VolumeSpec>,
}

/// A `strata` element of the scene, parsed; bound to the world's seed on first use.
#[derive(Clone, Debug)]
pub struct StrataInput {
    /// The parsed element.
    pub spec: Arc<StrataSpec>,
    /// Digest of the element (its canonical JSON).
    pub digest: [u8; 32],
    bound: Arc<std::sync::OnceLock<(u64, Arc<Geology>)>>,
}

impl PartialEq for StrataInput {
    fn eq(&self, other: &Self) -> bool {
        self.spec == other.spec
    }
}

impl StrataInput {
    /// The element bound to `seed` (built once per scene version for the world's seed).
    pub fn geology(&self, seed: u64) -> Arc<Geology> {
        let (s, g) = self
            .bound
            .get_or_init(|| (seed, Arc::new(Geology::new(seed, (*self.spec).clone()))));
        if *s == seed {
            g.clone()
        } else {
            Arc::new(Geology::new(seed, (*self.spec).clone()))
        }
    }

    /// The element's bbox.
    pub fn rect(&self) -> Rect {
        Rect {
            min: self.spec.min,
            max: self.spec.max,
        }
    }
}

/// An authored region of the scene, parsed, with the digest that keys its solution.
#[derive(Clone, Debug, PartialEq)]
pub struct RegionInput {
    /// Digest of the world settings and the element: equal digests, equal solutions (with the
    /// seed).
    pub digest: [u8; 32],
    /// The parsed element.
    pub spec: Arc<RegionSpec>,
}

impl SceneInputs {
    /// The inputs of a scene.
    pub fn new(scene: &Scene) -> Self {
        let elements: Vec<ElementInput> = scene
            .kinds()
            .into_iter()
            .enumerate()
            .flat_map(|(kind, (_, elements))| {
                elements.iter().map(move |e: &Element| ElementInput {
                    kind: kind as u8,
                    rect: e.bbox.rect(),
                    digest: digest(e),
                })
            })
            .collect();
        let world_digest = digest(&scene.world);
        let surface_digest = surface_digest(&world_digest, &elements);
        let regions = scene
            .regions
            .iter()
            .filter_map(|e| {
                let spec = RegionSpec::from_element(e).ok()?;
                let mut h = blake3::Hasher::new();
                h.update(&world_digest);
                h.update(&digest(e));
                Some(RegionInput {
                    digest: *h.finalize().as_bytes(),
                    spec: Arc::new(spec),
                })
            })
            .collect();
        let strata = scene
            .strata
            .iter()
            .filter_map(|e| {
                Some(StrataInput {
                    spec: Arc::new(StrataSpec::from_element(e).ok()?),
                    digest: digest(e),
                    bound: Arc::default(),
                })
            })
            .collect();
        let volumes = scene
            .volumes
            .iter()
            .filter_map(|e| {
                let spec = VolumeSpec::from_element(e).ok()?;
                let mut h = blake3::Hasher::new();
                h.update(&world_digest);
                h.update(&digest(e));
                Some(VolumeInput {
                    digest: *h.finalize().as_bytes(),
                    spec: Arc::new(spec),
                })
            })
            .collect();
        Self {
            world: scene.world.clone(),
            world_digest,
            surface_digest,
            elements,
            regions,
            strata,
            volumes,
            ptex: Arc::new(PtexSpecs::new(&scene.materials, &scene.decals)),
        }
    }

    /// The parsed `materials` and `decals` elements the Ptex bake reads.
    pub fn ptex(&self) -> &Arc<PtexSpecs> {
        &self.ptex
    }

    /// The volume regions, in document order.
    pub fn volumes(&self) -> &[VolumeInput] {
        &self.volumes
    }

    /// The volume regions whose box meets the world-space box `[lo, hi]` (metres, `[x, y, z]`),
    /// in document order.
    pub fn volumes_meeting(&self, lo: [f64; 3], hi: [f64; 3]) -> Vec<VolumeInput> {
        self.volumes
            .iter()
            .filter(|v| v.spec.meets(lo, hi))
            .cloned()
            .collect()
    }

    /// The `strata` elements, in document order.
    pub fn strata(&self) -> &[StrataInput] {
        &self.strata
    }

    /// The `strata` elements whose bbox meets `rect`, bound to `seed`, in document order.
    pub fn strata_meeting(&self, seed: u64, rect: &Rect) -> Vec<Arc<Geology>> {
        self.strata
            .iter()
            .filter(|s| s.rect().intersects(rect))
            .map(|s| s.geology(seed))
            .collect()
    }

    /// The `strata` elements whose bbox meets what tile `key` reads, bound to `seed`.
    pub fn strata_touching(&self, seed: u64, key: TileKey) -> Vec<Arc<Geology>> {
        self.strata_meeting(seed, &tile_reach(&self.world, key))
    }

    /// The authored region with element id `id`.
    pub fn region(&self, id: &str) -> Option<&RegionInput> {
        self.regions.iter().find(|r| r.spec.id == id)
    }

    /// The authored regions whose bbox meets what tile `key` reads, in document order.
    pub fn regions_touching(&self, key: TileKey) -> Vec<RegionInput> {
        self.regions_meeting(&tile_reach(&self.world, key))
    }

    /// The authored regions whose bbox meets `rect`, in document order.
    pub fn regions_meeting(&self, rect: &Rect) -> Vec<RegionInput> {
        self.regions
            .iter()
            .filter(|r| {
                Rect {
                    min: r.spec.min,
                    max: r.spec.max,
                }
                .intersects(rect)
            })
            .cloned()
            .collect()
    }

    /// The inputs of a world with these settings and no elements (a bare seed's world).
    pub fn bare(world: &WorldParams) -> Self {
        let world_digest = digest(world);
        Self {
            world: world.clone(),
            surface_digest: surface_digest(&world_digest, &[]),
            world_digest,
            elements: Vec::new(),
            regions: Vec::new(),
            strata: Vec::new(),
            volumes: Vec::new(),
            ptex: Arc::default(),
        }
    }

    /// The world settings.
    pub fn world(&self) -> &WorldParams {
        &self.world
    }

    /// Digest of everything tiles and volume chunks read: the world settings and the elements
    /// of the arrays that shape the surface ([`super::shapes_surface`]), in order. Two versions
    /// with equal digests have the same tiles and chunks; they may differ in their Ptex pages.
    pub fn surface_digest(&self) -> [u8; 32] {
        self.surface_digest
    }

    /// Number of elements of the scene.
    pub fn element_count(&self) -> usize {
        self.elements.len()
    }

    /// The input hash of tile `key` with seam flags `seams` (`n, e, s, w`) of the world `seed`.
    pub fn tile(&self, seed: u64, key: TileKey, seams: [bool; 4]) -> [u8; 32] {
        self.tile_with_version(TILE_CODE_VERSION, seed, key, seams)
    }

    fn tile_with_version(
        &self,
        code_version: u32,
        seed: u64,
        key: TileKey,
        seams: [bool; 4],
    ) -> [u8; 32] {
        let reach = tile_reach(&self.world, key);
        let touching: Vec<&ElementInput> = self
            .elements
            .iter()
            .filter(|e| super::shapes_surface(e.kind as usize) && e.rect.intersects(&reach))
            .collect();
        let mut h = blake3::Hasher::new();
        h.update(INPUTS_DOMAIN);
        h.update(&code_version.to_le_bytes());
        h.update(&seed.to_le_bytes());
        h.update(&self.world_digest);
        h.update(&key.lod.to_le_bytes());
        h.update(&key.x.to_le_bytes());
        h.update(&key.z.to_le_bytes());
        h.update(&seams.map(u8::from));
        h.update(&(touching.len() as u64).to_le_bytes());
        for e in touching {
            h.update(&[e.kind]);
            h.update(&e.digest);
        }
        *h.finalize().as_bytes()
    }
}

/// [`SceneInputs::surface_digest`] of a scene whose world digest is `world` and whose elements are
/// `elements`.
fn surface_digest(world: &[u8; 32], elements: &[ElementInput]) -> [u8; 32] {
    let mut h = blake3::Hasher::new();
    h.update(b"strata.surface\0");
    h.update(world);
    for e in elements
        .iter()
        .filter(|e| super::shapes_surface(e.kind as usize))
    {
        h.update(&[e.kind]);
        h.update(&e.digest);
    }
    *h.finalize().as_bytes()
}

/// The input hash of tile `key` (seam flags `seams`) of the world `(seed, scene)`; see the module
/// docs for what goes in. For many tiles of one version, build [`SceneInputs`] once.
pub fn tile_inputs(scene: &Scene, seed: u64, key: TileKey, seams: [bool; 4]) -> [u8; 32] {
    SceneInputs::new(scene).tile(seed, key, seams)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    const KEY: TileKey = TileKey { lod: 0, x: 1, z: 1 };

    fn with_regions(regions: Value) -> Scene {
        Scene::from_value(&json!({ "regions": regions })).expect("valid scene")
    }

    fn region(id: &str, min: [f64; 2], max: [f64; 2], h: i64) -> Value {
        json!({"id": id, "bbox": {"min": min, "max": max},
               "ops": [{"op": "elevation", "shape": {"point": min}, "elevation_m": h, "radius_m": 1}]})
    }

    #[test]
    fn canonical_json_sorts_keys_and_has_no_whitespace() {
        let mut a = Vec::new();
        canonical_json(
            &json!({"b": [1, 2.5, {"z": null, "a": "x\"y"}], "a": true}),
            &mut a,
        );
        assert_eq!(
            String::from_utf8(a).expect("utf8"),
            r#"{"a":true,"b":[1,2.5,{"a":"x\"y","z":null}]}"#
        );
    }

    #[test]
    fn earth_reach_is_footprint_plus_two_spacings() {
        let w = WorldParams::default();
        assert_eq!(w.generator, Generator::Earth1);
        assert_eq!(margin_m(&w, 0), 2.0 * w.cell_m as f64);
        assert_eq!(margin_m(&w, 5), 64.0 * w.cell_m as f64);
    }

    #[test]
    fn reach_is_footprint_plus_blur_radius_and_two_spacings() {
        let w = WorldParams::classic();
        let f = tile_footprint(&w, KEY);
        let size = 64.0 * w.cell_m as f64;
        assert_eq!(f.min, [size, size]);
        assert_eq!(f.max, [2.0 * size, 2.0 * size]);
        let m = w.layout.blur_radius_m as f64 + 2.0 * w.cell_m as f64;
        assert_eq!(margin_m(&w, 0), m);
        let r = tile_reach(&w, KEY);
        assert_eq!(r.min, [size - m, size - m]);
        assert_eq!(r.max, [2.0 * size + m, 2.0 * size + m]);
        // Coarser LODs: twice the spacing, the same blur radius.
        assert_eq!(
            margin_m(&w, 3),
            w.layout.blur_radius_m as f64 + 16.0 * w.cell_m as f64
        );
    }

    #[test]
    fn the_hash_changes_with_every_input() {
        let base_scene = with_regions(json!([region("r", [90.0, 90.0], [100.0, 100.0], 1)]));
        let base = SceneInputs::new(&base_scene);
        let h0 = base.tile(7, KEY, [false; 4]);
        assert_eq!(h0, tile_inputs(&base_scene, 7, KEY, [false; 4]), "pure");
        let mut seen = vec![h0];
        let mut differs = |what: &str, h: [u8; 32]| {
            assert!(!seen.contains(&h), "{what} does not change the hash");
            seen.push(h);
        };
        differs("seed", base.tile(8, KEY, [false; 4]));
        differs(
            "code version",
            base.tile_with_version(TILE_CODE_VERSION + 1, 7, KEY, [false; 4]),
        );
        differs("lod", base.tile(7, TileKey { lod: 1, ..KEY }, [false; 4]));
        differs("x", base.tile(7, TileKey { x: 2, ..KEY }, [false; 4]));
        differs("z", base.tile(7, TileKey { z: 2, ..KEY }, [false; 4]));
        for i in 0..4 {
            let mut seams = [false; 4];
            seams[i] = true;
            differs(&format!("seam {i}"), base.tile(7, KEY, seams));
        }
        // Every kind of world setting.
        type Edit = fn(&mut WorldParams);
        let edits: [(&str, Edit); 6] = [
            ("sea level", |w| w.sea_level_m += 1.0),
            ("blur radius", |w| w.layout.blur_radius_m += 1.0),
            ("generator", |w| w.generator = Generator::Classic),
            ("erosion", |w| {
                if let Some(e) = w.earth.as_mut() {
                    e.erosion *= 0.9
                }
            }),
            ("biome name", |w| w.biomes[1].name.push('x')),
            ("texturing", |w| w.texturing.rock_slope_deg += 1.0),
        ];
        for (what, edit) in edits {
            let mut s = base_scene.clone();
            edit(&mut s.world);
            differs(what, SceneInputs::new(&s).tile(7, KEY, [false; 4]));
        }
        // An element in reach: changed field, moved box, another array, added, removed.
        let variants = [
            (
                "element field",
                json!({"regions": [region("r", [90.0, 90.0], [100.0, 100.0], 2)]}),
            ),
            (
                "element box",
                json!({"regions": [region("r", [90.0, 90.0], [101.0, 100.0], 1)]}),
            ),
            (
                "element id",
                json!({"regions": [region("q", [90.0, 90.0], [100.0, 100.0], 1)]}),
            ),
            (
                "element array",
                json!({"strata": [{"id": "r", "bbox": {"min": [90.0, 90.0], "max": [100.0, 100.0]},
                                   "preset": "A3"}]}),
            ),
            (
                "element added",
                json!({"regions": [region("r", [90.0, 90.0], [100.0, 100.0], 1),
                                                 region("s", [120.0, 60.0], [130.0, 62.0], 1)]}),
            ),
            ("element removed", json!({})),
        ];
        for (what, doc) in variants {
            let s = Scene::from_value(&doc).expect("valid");
            differs(what, SceneInputs::new(&s).tile(7, KEY, [false; 4]));
        }
        // Order among elements in reach.
        let ab = with_regions(json!([
            region("a", [90.0, 90.0], [91.0, 91.0], 1),
            region("b", [95.0, 95.0], [96.0, 96.0], 1)
        ]));
        let ba = with_regions(json!([
            region("b", [95.0, 95.0], [96.0, 96.0], 1),
            region("a", [90.0, 90.0], [91.0, 91.0], 1)
        ]));
        assert_ne!(
            SceneInputs::new(&ab).tile(7, KEY, [false; 4]),
            SceneInputs::new(&ba).tile(7, KEY, [false; 4]),
            "order"
        );
    }

    #[test]
    fn materials_and_decals_are_not_a_tiles_inputs_nor_its_surface() {
        let base_scene = with_regions(json!([region("r", [90.0, 90.0], [100.0, 100.0], 1)]));
        let base = SceneInputs::new(&base_scene);
        let mut ptex = base_scene.to_value();
        ptex["decals"] = json!([region("d", [90.0, 90.0], [100.0, 100.0], 1)]);
        ptex["materials"] = json!([region("m", [0.0, 0.0], [0.0, 0.0], 1)]);
        let with_ptex = SceneInputs::new(&Scene::from_value(&ptex).expect("valid"));
        assert_eq!(
            with_ptex.tile(7, KEY, [false; 4]),
            base.tile(7, KEY, [false; 4])
        );
        assert_eq!(with_ptex.surface_digest(), base.surface_digest());
        // A region in reach changes both; the world settings change the surface.
        let other = with_regions(json!([region("r", [90.0, 90.0], [100.0, 100.0], 2)]));
        let other = SceneInputs::new(&other);
        assert_ne!(
            other.tile(7, KEY, [false; 4]),
            base.tile(7, KEY, [false; 4])
        );
        assert_ne!(other.surface_digest(), base.surface_digest());
        let mut sea = base_scene.clone();
        sea.world.sea_level_m += 1.0;
        assert_ne!(
            SceneInputs::new(&sea).surface_digest(),
            base.surface_digest()
        );
        assert_eq!(
            SceneInputs::bare(&base_scene.world).surface_digest(),
            SceneInputs::new(&Scene::default()).surface_digest()
        );
    }

    #[test]
    fn elements_outside_the_margin_do_not_change_the_hash() {
        let w = WorldParams::default();
        let reach = tile_reach(&w, KEY);
        let base_scene = with_regions(json!([region("r", [90.0, 90.0], [100.0, 100.0], 1)]));
        let h0 = SceneInputs::new(&base_scene).tile(7, KEY, [false; 4]);
        // Just outside the grown footprint on each side, and far away.
        let eps = 1e-6;
        let outside = [
            ([reach.max[0] + eps, 90.0], [reach.max[0] + 5.0, 100.0]),
            ([reach.min[0] - 5.0, 90.0], [reach.min[0] - eps, 100.0]),
            ([90.0, reach.max[1] + eps], [100.0, reach.max[1] + 5.0]),
            ([90.0, reach.min[1] - 5.0], [100.0, reach.min[1] - eps]),
            ([1.0e6, 1.0e6], [1.0e6 + 1.0, 1.0e6 + 1.0]),
        ];
        for (i, (min, max)) in outside.into_iter().enumerate() {
            for variant in 0..2 {
                let s = with_regions(json!([
                    region(&format!("far{i}"), min, max, variant),
                    region("r", [90.0, 90.0], [100.0, 100.0], 1)
                ]));
                assert_eq!(
                    SceneInputs::new(&s).tile(7, KEY, [false; 4]),
                    h0,
                    "element {i} outside the margin changed the hash"
                );
            }
        }
        // Touching the grown footprint's edge counts (closed rectangles).
        let s = with_regions(json!([
            region("edge", [reach.max[0], 90.0], [reach.max[0] + 5.0, 100.0], 0),
            region("r", [90.0, 90.0], [100.0, 100.0], 1)
        ]));
        assert_ne!(SceneInputs::new(&s).tile(7, KEY, [false; 4]), h0);
        // A bare seed's world equals the default scene's.
        assert_eq!(
            SceneInputs::bare(&w).tile(7, KEY, [true, false, false, true]),
            SceneInputs::new(&Scene::default()).tile(7, KEY, [true, false, false, true])
        );
    }
}
