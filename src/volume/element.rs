//! The `volumes` scene element (issue 5, "Volume chunks everywhere"): a box of the world whose
//! solid comes from the Becher pipeline ([`super::pipeline`]) — feature curves and meshes, with
//! the world's heightfield under the box as the lowest-priority input — and how volume chunks
//! take it.
//!
//! ```json
//! {"id": "arch", "bbox": {"min": [0, 0], "max": [64, 48]}, "y_m": [90, 130],
//!  "spacing_m": 1.0, "dead_zone_m": 6, "curves": [ … FeatureCurve … ], "meshes": [],
//!  "expand_curves": {"step_m": 0.5, "spacing_m": 4, "min_distance_m": 4, "max_length_m": 64}}
//! ```
//!
//! # Input meshes
//!
//! Each entry of `meshes` is either inline triangles or a glTF 2.0 binary, with the noise
//! parameters and material the pipeline assigns to the whole mesh (§4.2):
//!
//! - `{"triangles": [[[x, y, z], [x, y, z], [x, y, z]], …]}`: world metres, counter-clockwise
//!   seen from outside;
//! - `{"glb_base64": "Z2xURg…"}`: a standard-base64 `.glb` of at most
//!   [`MAX_GLB_BYTES`](super::mesh_import::MAX_GLB_BYTES) bytes, read by
//!   [`super::mesh_import`] (positions and indices of triangle primitives, node transforms
//!   applied; its units are taken as metres);
//!
//! both with the optional `"transform"` (16 numbers, a column-major affine 4×4 matrix as glTF
//! writes them, applied last), `"alpha"` (metres, default 0.3), `"beta"` (default 0.5) and
//! `"material"` (default 0). All meshes of an element hold at most [`MAX_VOLUME_TRIANGLES`]
//! triangles together. An uploaded glb (`POST …/volumes/{vid}/meshes`) becomes such a
//! `glb_base64` entry.
//!
//! # Curve expansion
//!
//! `expand_curves` (absent: off) turns on the optional §5.1 stage
//! ([`super::pipeline::expand`]) with its settings; `{}` takes the defaults.
//!
//! # Meeting the world without a gap
//!
//! A chunk sample `p` inside the box takes `S = w·S_v(p) + (1 − w)·S_h(p)`: `S_v` the region's
//! filtered signed distance (trilinear), `S_h` the heightfield solid the chunk has anyway, and
//! `w = smoothstep(0, band, d(p))` with `d(p)` the distance from `p` to the nearest face of the
//! box (x, z faces and the `y_m` bounds) and `band` = [`BLEND_CELLS`] region spacings. On the
//! box's faces and outside it `w = 0`, so the solid there is the heightfield's bit for bit and the
//! surface is continuous across the border; inside the band the two surfaces blend. `S` is a
//! function of the global sample position only, so same-LOD chunk seams stay exact.
//!
//! # Deviations
//!
//! # The heightfield input
//!
//! The heightfield input is the world's LOD-0 ground under the box as tiles have it: the
//! procedural heights plus the edits of the authored regions and the cave breaches of the
//! `strata` elements meeting [`ground_rect`] ([`GroundEdits`], which `edits::TileEdits`
//! implements), so a region
//! raised or a cave opened under the box shows inside it as outside. The server solves each
//! region once per `(seed, digest of the element and of those edits' elements)`.
//!
//! # Deviations
//!
//! - Vertex materials of chunks stay the tile materials; the region's per-sample material is
//!   not carried into chunks yet.

use super::mesh_import::{glb_triangles, Mat4, MAX_GLB_BYTES};
use super::pipeline::expand::ExpandParams;
use super::pipeline::{self, Grid, Heightfield, InputMesh, PipelineParams, RegionFields};
use crate::element::{Element, Rect};
use crate::terrain::lattice::Window;
use crate::terrain::WorldPlan;
use serde::Deserialize;

/// What the ground under a volume region takes on top of the procedural heights: the edits a
/// height tile applies (`edits::TileEdits`, which implements this trait one layer up).
pub trait GroundEdits {
    /// Applies the edits to the heights of a lattice `window` (row-major).
    fn apply(&self, window: Window, heights: &mut [f32]);
}

/// Most samples of a volume region's grid.
pub const MAX_VOLUME_SAMPLES: usize = 1 << 22;
/// Most feature curves of one element.
pub const MAX_VOLUME_CURVES: usize = 256;
/// Most triangles over all meshes of one element.
pub const MAX_VOLUME_TRIANGLES: usize = 65_536;
/// Width of the blend band inside the box, in region spacings.
pub const BLEND_CELLS: f32 = 4.0;
/// Smallest and largest grid spacing, metres.
pub const SPACING_RANGE_M: (f32, f32) = (0.25, 8.0);

/// Material and noise parameters the heightfield input carries.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct GroundInput {
    /// Noise amplitude `α`, metres.
    #[serde(default = "default_alpha")]
    pub alpha: f32,
    /// Noise roughness `β`.
    #[serde(default = "default_beta")]
    pub beta: f32,
    /// Material id.
    #[serde(default)]
    pub material: u16,
}

fn default_alpha() -> f32 {
    0.3
}

fn default_beta() -> f32 {
    0.5
}

impl Default for GroundInput {
    fn default() -> Self {
        Self {
            alpha: default_alpha(),
            beta: default_beta(),
            material: 0,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Fields {
    y_m: [f32; 2],
    #[serde(default = "default_spacing")]
    spacing_m: f32,
    #[serde(default = "default_dead_zone")]
    dead_zone_m: f32,
    #[serde(default)]
    curves: Vec<pipeline::FeatureCurve>,
    #[serde(default)]
    meshes: Vec<MeshEntry>,
    #[serde(default)]
    ground: GroundInput,
    #[serde(default)]
    expand_curves: Option<ExpandParams>,
}

/// One entry of `meshes` (module docs): inline triangles or a base64 glb.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MeshEntry {
    #[serde(default)]
    triangles: Option<Vec<[[f32; 3]; 3]>>,
    #[serde(default)]
    glb_base64: Option<String>,
    #[serde(default)]
    transform: Option<Mat4>,
    #[serde(default = "default_alpha")]
    alpha: f32,
    #[serde(default = "default_beta")]
    beta: f32,
    #[serde(default)]
    material: u16,
}

/// The triangles of mesh entry `i` (transform applied), at most `budget` of them.
fn mesh_triangles(
    i: usize,
    m: &MeshEntry,
    budget: usize,
) -> Result<Vec<[[f32; 3]; 3]>, VolumeError> {
    use base64::Engine as _;
    let at = |f: &str| format!("/meshes/{i}{f}");
    if let Some(t) = &m.transform {
        super::mesh_import::check_transform(t).map_err(|e| err(at("/transform"), e.0))?;
    }
    let too_many = || {
        err(
            "/meshes",
            format!("at most {MAX_VOLUME_TRIANGLES} triangles in all"),
        )
    };
    match (&m.triangles, &m.glb_base64) {
        (Some(tris), None) => {
            if tris.len() > budget {
                return Err(too_many());
            }
            if let Some(k) = tris
                .iter()
                .position(|t| t.iter().flatten().any(|c| !c.is_finite()))
            {
                return Err(err(at(&format!("/triangles/{k}")), "must be finite"));
            }
            Ok(match &m.transform {
                None => tris.clone(),
                Some(t) => {
                    let flip = super::mesh_import::det3(t) < 0.0;
                    tris.iter()
                        .map(|v| {
                            let [a, b, c] = v.map(|p| super::mesh_import::apply(t, p));
                            if flip {
                                [a, c, b]
                            } else {
                                [a, b, c]
                            }
                        })
                        .collect()
                }
            })
        }
        (None, Some(text)) => {
            if text.len() > MAX_GLB_BYTES.div_ceil(3) * 4 {
                return Err(err(
                    at("/glb_base64"),
                    format!("the glb may be at most {MAX_GLB_BYTES} bytes"),
                ));
            }
            let bytes = base64::engine::general_purpose::STANDARD
                .decode(text)
                .map_err(|e| err(at("/glb_base64"), format!("not standard base64: {e}")))?;
            glb_triangles(&bytes, m.transform.as_ref(), budget)
                .map_err(|e| err(at("/glb_base64"), e.0))
        }
        _ => Err(err(at(""), "give exactly one of triangles and glb_base64")),
    }
}

fn default_spacing() -> f32 {
    1.0
}

fn default_dead_zone() -> f32 {
    3.0
}

/// A parsed `volumes` element.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeSpec {
    /// Element id.
    pub id: String,
    /// West-north corner `[x, z]` of the box, metres.
    pub min: [f64; 2],
    /// East-south corner `[x, z]` of the box, metres.
    pub max: [f64; 2],
    /// Bottom and top of the box, metres.
    pub y_m: [f32; 2],
    /// The region's grid.
    pub grid: Grid,
    /// Curves and meshes (the heightfield is added when solved).
    pub scene: pipeline::Scene,
    /// Dead-zone radius, metres.
    pub dead_zone_m: f32,
    /// The heightfield input's parameters.
    pub ground: GroundInput,
    /// The optional curve expansion (§5.1); `None` is off.
    pub expand: Option<ExpandParams>,
}

/// Why a `volumes` element is refused: a JSON pointer relative to the element and the reason.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {message}")]
pub struct VolumeError {
    /// Pointer relative to the element.
    pub pointer: String,
    /// Why.
    pub message: String,
}

fn err(pointer: impl Into<String>, message: impl Into<String>) -> VolumeError {
    VolumeError {
        pointer: pointer.into(),
        message: message.into(),
    }
}

/// `curves[2].constraints[0].b_l` → `/curves/2/constraints/0/b_l`.
fn pointer_of(field: &str) -> String {
    let mut out = String::new();
    for part in field.split('.') {
        let (name, rest) = part.split_once('[').unwrap_or((part, ""));
        out.push('/');
        out.push_str(name);
        for idx in rest.split('[') {
            let idx = idx.trim_end_matches(']');
            if !idx.is_empty() {
                out.push('/');
                out.push_str(idx);
            }
        }
    }
    out
}

impl VolumeSpec {
    /// Parses a `volumes` element.
    ///
    /// # Errors
    /// [`VolumeError`] naming the offending field.
    pub fn from_element(e: &Element) -> Result<VolumeSpec, VolumeError> {
        let value = serde_json::Value::Object(e.rest.clone());
        let f: Fields = serde_path_to_error::deserialize(&value).map_err(|x| {
            err(
                crate::element::path_pointer(x.path()),
                x.inner().to_string(),
            )
        })?;
        let (lo, hi) = SPACING_RANGE_M;
        if !(f.spacing_m.is_finite() && (lo..=hi).contains(&f.spacing_m)) {
            return Err(err("/spacing_m", format!("must be in [{lo}, {hi}] metres")));
        }
        let [y0, y1] = f.y_m;
        if !(y0.is_finite() && y1.is_finite() && y1 > y0 && y0.abs() < 1.0e5 && y1.abs() < 1.0e5) {
            return Err(err(
                "/y_m",
                "must be [bottom, top] metres with bottom < top",
            ));
        }
        if !(f.dead_zone_m.is_finite() && (0.0..=1000.0).contains(&f.dead_zone_m)) {
            return Err(err("/dead_zone_m", "must be in [0, 1000] metres"));
        }
        if f.curves.len() > MAX_VOLUME_CURVES {
            return Err(err(
                "/curves",
                format!("at most {MAX_VOLUME_CURVES} curves"),
            ));
        }
        let mut meshes = Vec::with_capacity(f.meshes.len());
        let mut used = 0;
        for (i, m) in f.meshes.iter().enumerate() {
            let triangles = mesh_triangles(i, m, MAX_VOLUME_TRIANGLES - used)?;
            used += triangles.len();
            meshes.push(InputMesh {
                triangles,
                alpha: m.alpha,
                beta: m.beta,
                material: m.material,
            });
            if !(m.alpha.is_finite() && m.beta.is_finite()) {
                return Err(err(
                    format!("/meshes/{i}/alpha"),
                    "alpha and beta must be finite",
                ));
            }
        }
        if let Some(e) = &f.expand_curves {
            e.validate().map_err(|x| match x {
                pipeline::PipelineError::Invalid { field, reason } => {
                    err(format!("/expand_curves/{field}"), reason)
                }
                other => err("/expand_curves", other.to_string()),
            })?;
        }
        for (i, c) in f.curves.iter().enumerate() {
            c.validate().map_err(|x| match x {
                pipeline::PipelineError::Invalid { field, reason } => {
                    err(format!("/curves/{i}{}", pointer_of(&field)), reason)
                }
                other => err(format!("/curves/{i}"), other.to_string()),
            })?;
        }
        let extent = [
            (e.bbox.max[0] - e.bbox.min[0]) as f32,
            y1 - y0,
            (e.bbox.max[1] - e.bbox.min[1]) as f32,
        ];
        let dims = extent.map(|x| (x / f.spacing_m).ceil() as usize + 1);
        if dims.iter().product::<usize>() > MAX_VOLUME_SAMPLES || dims.iter().any(|&d| d < 2) {
            return Err(err(
                "/spacing_m",
                format!(
                    "the box needs {dims:?} samples at this spacing; a region has 2 to {MAX_VOLUME_SAMPLES} in all and at least 2 per axis"
                ),
            ));
        }
        let grid = Grid::new(
            dims,
            [e.bbox.min[0] as f32, y0, e.bbox.min[1] as f32],
            f.spacing_m,
        )
        .map_err(|x| err("/spacing_m", x.to_string()))?;
        Ok(VolumeSpec {
            id: e.id.clone(),
            min: e.bbox.min,
            max: e.bbox.max,
            y_m: f.y_m,
            grid,
            scene: pipeline::Scene {
                curves: f.curves,
                meshes,
                heightfield: None,
            },
            dead_zone_m: f.dead_zone_m,
            ground: f.ground,
            expand: f.expand_curves,
        })
    }
}

impl VolumeSpec {
    /// Whether the region's box meets the world-space box `[lo, hi]` (metres, `[x, y, z]`).
    pub fn meets(&self, lo: [f64; 3], hi: [f64; 3]) -> bool {
        lo[0] < self.max[0]
            && hi[0] > self.min[0]
            && lo[2] < self.max[1]
            && hi[2] > self.min[1]
            && lo[1] < f64::from(self.y_m[1])
            && hi[1] > f64::from(self.y_m[0])
    }
}

/// A solved volume region.
#[derive(Clone, Debug)]
pub struct SolvedVolume {
    /// The element.
    pub spec: VolumeSpec,
    /// The pipeline's fields.
    pub fields: RegionFields,
}

/// Solves a volume region in the world `plan`: the procedural heights under the box (LOD 0,
/// one spacing beyond it) as the heightfield input, then the whole pipeline.
///
/// # Errors
/// [`pipeline::PipelineError`] from the pipeline.
pub fn solve_volume(
    plan: &WorldPlan,
    spec: &VolumeSpec,
    edits: &dyn GroundEdits,
) -> Result<SolvedVolume, pipeline::PipelineError> {
    solve_volume_on(
        plan,
        spec,
        edits,
        &super::offload::CpuOnly,
        &crate::terrain::cancel::Cancel::never(),
    )
}

/// [`solve_volume`] with the pipeline's twinned stages offered to `dev`
/// ([`super::offload`]), polling `cancel` before the ground is sampled, before the pipeline runs
/// and between its stages ([`pipeline::generate_on`]; not inside a stage).
///
/// # Errors
/// As [`solve_volume`], and [`pipeline::PipelineError::Cancelled`] once `cancel` is set.
pub fn solve_volume_on(
    plan: &WorldPlan,
    spec: &VolumeSpec,
    edits: &dyn GroundEdits,
    dev: &dyn super::offload::VolumeOffload,
    cancel: &crate::terrain::cancel::Cancel,
) -> Result<SolvedVolume, pipeline::PipelineError> {
    let cancelled = |_| pipeline::PipelineError::Cancelled;
    cancel.check().map_err(cancelled)?;
    let window = ground_window(plan, spec);
    let mut field = crate::terrain::tile::field(
        plan,
        crate::terrain::FieldJob::new(0, window.gx0, window.gz0, window.w, window.h),
    );
    edits.apply(window, &mut field.heights);
    let (s, gx0, gz0, w, h) = (
        f64::from(window.spacing_m),
        window.gx0,
        window.gz0,
        window.w,
        window.h,
    );
    let mut scene = spec.scene.clone();
    scene.heightfield = Some(Heightfield {
        origin: [(gx0 as f64 * s) as f32, (gz0 as f64 * s) as f32],
        spacing: s as f32,
        dims: [w, h],
        heights: field.heights,
        alpha: spec.ground.alpha,
        beta: spec.ground.beta,
        material: spec.ground.material,
    });
    let params = PipelineParams {
        dead_zone_m: spec.dead_zone_m,
        expand: spec.expand,
        ..PipelineParams::default()
    };
    cancel.check().map_err(cancelled)?;
    let fields = pipeline::generate_on(&spec.grid, &scene, &params, dev, cancel)?;
    Ok(SolvedVolume {
        spec: spec.clone(),
        fields,
    })
}

/// The LOD-0 lattice rectangle of the ground under a volume region's box (one vertex beyond it
/// on every side): the heightfield input of [`solve_volume`]. Its world rectangle,
/// [`ground_rect`], is what selects the edits that input takes.
pub fn ground_window(plan: &WorldPlan, spec: &VolumeSpec) -> Window {
    let s = f64::from(plan.lods[0].spacing_m);
    let gx0 = (spec.min[0] / s).floor() as i64 - 1;
    let gz0 = (spec.min[1] / s).floor() as i64 - 1;
    Window {
        spacing_m: plan.lods[0].spacing_m,
        gx0,
        gz0,
        w: ((spec.max[0] / s).ceil() as i64 + 1 - gx0 + 1) as usize,
        h: ((spec.max[1] / s).ceil() as i64 + 1 - gz0 + 1) as usize,
    }
}

/// The world rectangle of [`ground_window`], metres.
pub fn ground_rect(plan: &WorldPlan, spec: &VolumeSpec) -> Rect {
    let w = ground_window(plan, spec);
    let s = f64::from(w.spacing_m);
    Rect {
        min: [w.gx0 as f64 * s, w.gz0 as f64 * s],
        max: [
            (w.gx0 + w.w as i64 - 1) as f64 * s,
            (w.gz0 + w.h as i64 - 1) as f64 * s,
        ],
    }
}

impl SolvedVolume {
    /// Distance from world point `p` to the nearest face of the box, metres (negative outside).
    fn inset(&self, p: [f64; 3]) -> f64 {
        let sp = &self.spec;
        let dx = (p[0] - sp.min[0]).min(sp.max[0] - p[0]);
        let dz = (p[2] - sp.min[1]).min(sp.max[1] - p[2]);
        let dy = (p[1] - f64::from(sp.y_m[0])).min(f64::from(sp.y_m[1]) - p[1]);
        dx.min(dy).min(dz)
    }

    /// The region's filtered signed distance at `p` (trilinear; clamped to the grid).
    fn surface_at(&self, p: [f64; 3]) -> f64 {
        let g = &self.fields.grid;
        let f: [f64; 3] = std::array::from_fn(|a| {
            ((p[a] - f64::from(g.origin[a])) / f64::from(g.spacing))
                .clamp(0.0, (g.dims[a] - 1) as f64)
        });
        let i: [usize; 3] = std::array::from_fn(|a| (f[a] as usize).min(g.dims[a] - 2));
        let t: [f64; 3] = std::array::from_fn(|a| f[a] - i[a] as f64);
        let s = &self.fields.surface;
        let mut acc = 0.0;
        for dz in 0..2 {
            for dy in 0..2 {
                for dx in 0..2 {
                    let wgt = (if dx == 1 { t[0] } else { 1.0 - t[0] })
                        * (if dy == 1 { t[1] } else { 1.0 - t[1] })
                        * (if dz == 1 { t[2] } else { 1.0 - t[2] });
                    acc += wgt * f64::from(s[g.index(i[0] + dx, i[1] + dy, i[2] + dz)]);
                }
            }
        }
        acc
    }

    /// Blends the region into a value `s_h` of the heightfield solid at world point `p`
    /// (module docs); `s_h` itself outside the box and on its faces.
    pub fn blend(&self, p: [f64; 3], s_h: f32) -> f32 {
        let d = self.inset(p);
        if d <= 0.0 {
            return s_h;
        }
        let band = f64::from(BLEND_CELLS * self.fields.grid.spacing);
        let x = (d / band).min(1.0);
        let w = x * x * (3.0 - 2.0 * x);
        (w * self.surface_at(p) + (1.0 - w) * f64::from(s_h)) as f32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn element(rest: serde_json::Value) -> Element {
        let mut v = json!({"id": "v", "bbox": {"min": [0, 0], "max": [64, 48]}});
        if let (Some(o), Some(r)) = (v.as_object_mut(), rest.as_object()) {
            o.extend(r.clone());
        }
        serde_json::from_value(v).expect("element")
    }

    #[test]
    fn errors_name_the_field() {
        let at = |rest: serde_json::Value| {
            VolumeSpec::from_element(&element(rest))
                .expect_err("refused")
                .pointer
        };
        assert_eq!(at(json!({})), "");
        assert_eq!(at(json!({"y_m": [5, 1]})), "/y_m");
        assert_eq!(at(json!({"y_m": [0, 10], "spacing_m": 0})), "/spacing_m");
        assert_eq!(at(json!({"y_m": [0, 40], "spacing_m": 0.25})), "/spacing_m");
        assert_eq!(
            at(json!({"y_m": [0, 10], "dead_zone_m": -1})),
            "/dead_zone_m"
        );
        let (_, scene, _) = pipeline::scenes::arch([32, 16, 24]);
        let mut curves = serde_json::to_value(&scene.curves).expect("curves");
        curves[1]["constraints"][0]["t"] = json!(0.5);
        assert!(at(json!({"y_m": [0, 10], "curves": curves})).starts_with("/curves/1"));
        let ok = VolumeSpec::from_element(&element(json!({"y_m": [0, 32], "spacing_m": 2})))
            .expect("valid");
        assert_eq!(ok.grid.dims, [33, 17, 25]);
    }
}
