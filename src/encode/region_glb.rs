//! The glTF 2.0 binary (`.glb`) of a whole solved volume region: the naive surface-nets quad mesh
//! ([`crate::volume::mesh`], Becher §4.6) of the region's filtered signed distance `S`, each quad
//! split into two triangles.
//!
//! One scene, one node. The node's `translation` is the world position of the region's grid
//! sample `(0, 0, 0)` in metres, and `POSITION` is relative to it (so the placed mesh is in world
//! metres, with `f32` precision kept near the region); its `extras` carry the element id, seed,
//! version, grid dims, spacing and the vertex and quad counts. With at least one quad the node
//! has one mesh with one indexed triangle primitive:
//!
//! - `POSITION`: `f32` VEC3 with `min`/`max`, metres;
//! - `NORMAL`: unit `∇S / |∇S|`, pointing out of the solid;
//! - `_MATERIAL`: `f32` SCALAR, the material id of the sample nearest to the vertex (the same
//!   rule the mesher uses; ids are exact in `f32`);
//! - `_NOISE`: `f32` VEC2, the noise amplitude `α` (metres) and roughness `β` interpolated
//!   trilinearly at the vertex;
//! - indices: `u32`; quad `q = [a, b, c, d]` becomes triangles `[a, b, c]` and `[a, c, d]`
//!   (counter-clockwise seen from outside, as the quads).
//!
//! The chunk glb ([`super::chunk_glb`]) carries positions and normals only; the custom
//! attributes are this export's addition (custom attribute names start with `_` as glTF
//! requires). An empty region (no surface) is a node without a mesh (glTF forbids empty
//! accessors).

use crate::volume::element::SolvedVolume;
use crate::volume::mesh::{surface_nets_on, MeshError, MeshOptions, QuadMesh, SampleAttributes};
use crate::volume::mesh_import::write_glb;
use crate::volume::offload::VolumeOffload;
use serde_json::json;

/// Most quads in one exported region mesh (about 60 bytes each in the glb: 1.2 GB at most).
pub const MAX_EXPORT_QUADS: usize = 1 << 24;

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

/// Who the export belongs to (written into the node's `extras`).
#[derive(Clone, Copy, Debug)]
pub struct RegionInfo {
    /// The world's seed.
    pub seed: u64,
    /// The scene version the region was solved from.
    pub version: u64,
}

/// Why a region cannot be exported.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The mesher refused the grid.
    #[error("meshing failed: {0}")]
    Mesh(#[from] MeshError),
    /// More quads than [`MAX_EXPORT_QUADS`].
    #[error("the region's mesh has {0} quads; at most {MAX_EXPORT_QUADS} are exported")]
    TooLarge(usize),
}

/// The region's quad mesh (positions relative to grid sample `(0, 0, 0)`), with `noise` =
/// `[α, β, 0, 0]` per vertex, with the surface nets offered to `dev`.
pub fn region_mesh(v: &SolvedVolume, dev: &dyn VolumeOffload) -> Result<QuadMesh, MeshError> {
    let f = &v.fields;
    let noise: Vec<[f32; 4]> = f
        .alpha
        .iter()
        .zip(&f.beta)
        .map(|(&a, &b)| [a, b, 0.0, 0.0])
        .collect();
    let attrs = SampleAttributes {
        materials: None,
        noise: Some(&noise),
    };
    let mut m = QuadMesh::default();
    surface_nets_on(
        &f.surface,
        attrs,
        &MeshOptions::new(f.grid.dims, f.grid.spacing),
        &mut m,
        dev,
    )?;
    Ok(m)
}

/// The material id of the sample nearest to each vertex (`u16` ids, unlike the mesher's `u8`).
fn vertex_materials(v: &SolvedVolume, m: &QuadMesh) -> Vec<f32> {
    let g = &v.fields.grid;
    m.cells
        .iter()
        .zip(&m.offsets)
        .map(|(c, o)| {
            let s: [usize; 3] = std::array::from_fn(|k| {
                (c[k] as usize + usize::from(o[k] >= 0.5)).min(g.dims[k] - 1)
            });
            f32::from(v.fields.material[g.index(s[0], s[1], s[2])])
        })
        .collect()
}

/// The glb bytes of the whole region.
///
/// # Errors
/// [`ExportError`] when the mesher refuses the grid or the mesh has too many quads.
pub fn encode(
    v: &SolvedVolume,
    info: RegionInfo,
    dev: &dyn VolumeOffload,
) -> Result<Vec<u8>, ExportError> {
    let m = region_mesh(v, dev)?;
    if m.quad_count() > MAX_EXPORT_QUADS {
        return Err(ExportError::TooLarge(m.quad_count()));
    }
    let g = &v.fields.grid;
    let mut node = json!({
        "name": format!("volume {}", v.spec.id),
        "translation": g.origin.map(f64::from),
        "extras": {
            "volume": v.spec.id,
            "seed": info.seed.to_string(),
            "version": info.version,
            "dims": g.dims,
            "spacing_m": g.spacing,
            "origin_m": g.origin.map(f64::from),
            "vertex_count": m.vertex_count(),
            "quad_count": m.quad_count(),
        },
    });
    let mut doc = json!({
        "asset": { "version": "2.0", "generator": concat!("strata ", env!("CARGO_PKG_VERSION")) },
        "scene": 0,
        "scenes": [{ "nodes": [0] }],
    });
    let mut bin = Vec::new();
    if m.quad_count() > 0 {
        let (lo, hi) = super::glb::bounds(&m.positions);
        let mut views = Vec::new();
        let mut push =
            |bin: &mut Vec<u8>, values: &mut dyn Iterator<Item = [u8; 4]>, target: u32| {
                let start = bin.len();
                for b in values {
                    bin.extend_from_slice(&b);
                }
                views.push(json!({ "buffer": 0, "byteOffset": start,
                               "byteLength": bin.len() - start, "target": target }));
            };
        push(
            &mut bin,
            &mut m.positions.iter().flatten().map(|x| x.to_le_bytes()),
            ARRAY_BUFFER,
        );
        push(
            &mut bin,
            &mut m.normals.iter().flatten().map(|x| x.to_le_bytes()),
            ARRAY_BUFFER,
        );
        push(
            &mut bin,
            &mut vertex_materials(v, &m).into_iter().map(f32::to_le_bytes),
            ARRAY_BUFFER,
        );
        push(
            &mut bin,
            &mut m
                .noise
                .iter()
                .flat_map(|n| [n[0], n[1]])
                .map(f32::to_le_bytes),
            ARRAY_BUFFER,
        );
        push(
            &mut bin,
            &mut m
                .quads
                .iter()
                .flat_map(|&[a, b, c, d]| [a, b, c, a, c, d])
                .map(u32::to_le_bytes),
            ELEMENT_ARRAY_BUFFER,
        );
        let nv = m.vertex_count();
        node["mesh"] = json!(0);
        doc["meshes"] = json!([{ "name": v.spec.id, "primitives": [{
            "attributes": { "POSITION": 0, "NORMAL": 1, "_MATERIAL": 2, "_NOISE": 3 },
            "indices": 4, "mode": 4 }] }]);
        doc["accessors"] = json!([
            { "bufferView": 0, "componentType": FLOAT, "count": nv, "type": "VEC3",
              "min": lo.map(f64::from), "max": hi.map(f64::from) },
            { "bufferView": 1, "componentType": FLOAT, "count": nv, "type": "VEC3" },
            { "bufferView": 2, "componentType": FLOAT, "count": nv, "type": "SCALAR" },
            { "bufferView": 3, "componentType": FLOAT, "count": nv, "type": "VEC2" },
            { "bufferView": 4, "componentType": UNSIGNED_INT, "count": 6 * m.quad_count(),
              "type": "SCALAR" },
        ]);
        doc["bufferViews"] = json!(views);
        doc["buffers"] = json!([{ "byteLength": bin.len() }]);
    }
    doc["nodes"] = json!([node]);
    Ok(write_glb(&doc, &bin))
}
