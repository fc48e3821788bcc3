//! The glTF 2.0 binary (`.glb`) of a volume chunk: surface quads and skirts triangulated.
//!
//! One scene, one node; the node's `translation` is the chunk origin (positions are relative to
//! it) and its `extras` carry the key, seed, spacing and counts. With at least one quad the node
//! has one mesh with one indexed triangle primitive: `POSITION` (`f32` VEC3 with `min`/`max`),
//! `NORMAL` (unit; skirt bottoms copy their top vertex's normal), `u32` indices. Surface quad `q`
//! `[a, b, c, d]` becomes triangles `2q = [a, b, c]` and `2q + 1 = [a, c, d]` (counter-clockwise
//! seen from outside, as the quads), then the skirt quads the same way. An empty chunk is a node
//! without a mesh (glTF forbids empty accessors).

use super::chunk::{ChunkInfo, CHUNK_FORMAT};
use super::glb::{bounds, push_f32s};
use crate::volume::chunk::ChunkMesh;
use serde_json::json;

const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

/// The triangle index list: surface quads, then skirt quads, two triangles each.
pub fn triangles(m: &ChunkMesh) -> Vec<u32> {
    let mut idx = Vec::with_capacity(6 * (m.quads.len() + m.skirt_quads.len()));
    for [a, b, c, d] in m.quads.iter().chain(&m.skirt_quads).copied() {
        idx.extend_from_slice(&[a, b, c, a, c, d]);
    }
    idx
}

/// The glb bytes.
pub fn encode(info: &ChunkInfo, m: &ChunkMesh) -> Vec<u8> {
    let origin = info.origin_m();
    let mut node = json!({
        "name": format!("chunk {}/{}/{}/{}", info.key.lod, info.key.x, info.key.y, info.key.z),
        "translation": origin,
        "extras": {
            "format": CHUNK_FORMAT,
            "key": { "lod": info.key.lod, "x": info.key.x, "y": info.key.y, "z": info.key.z },
            "seed": info.seed.to_string(),
            "origin_m": origin,
            "spacing_m": info.spacing_m,
            "skirt_depth_m": m.skirt_depth_m,
            "surface_vertex_count": m.positions.len(),
            "surface_quad_count": m.quads.len(),
            "skirt_vertex_count": m.skirt_positions.len(),
            "skirt_quad_count": m.skirt_quads.len(),
        },
    });
    let mut bin = Vec::new();
    let mut doc = json!({
        "asset": { "version": "2.0", "generator": concat!("strata ", env!("CARGO_PKG_VERSION")) },
        "scene": 0,
        "scenes": [{ "nodes": [0] }],
    });
    if !m.quads.is_empty() {
        let pos: Vec<[f32; 3]> = m
            .positions
            .iter()
            .chain(&m.skirt_positions)
            .copied()
            .collect();
        let mut nrm = m.normals.clone();
        // Skirt bottom i belongs to the top vertex of the first skirt quad that uses it.
        let mut skirt_nrm = vec![[0.0f32, 1.0, 0.0]; m.skirt_positions.len()];
        let v = m.positions.len();
        for [b, a, ba, bb] in m.skirt_quads.iter().copied() {
            skirt_nrm[ba as usize - v] = m.normals[a as usize];
            skirt_nrm[bb as usize - v] = m.normals[b as usize];
        }
        nrm.extend(skirt_nrm);
        let idx = triangles(m);
        let (min, max) = bounds(&pos);
        push_f32s(&mut bin, pos.iter().flatten());
        let nrm_start = bin.len();
        push_f32s(&mut bin, nrm.iter().flatten());
        let idx_start = bin.len();
        for i in &idx {
            bin.extend_from_slice(&i.to_le_bytes());
        }
        node["mesh"] = json!(0);
        doc["meshes"] = json!([{ "name": "chunk", "primitives": [{
            "attributes": { "POSITION": 0, "NORMAL": 1 }, "indices": 2, "mode": 4 }] }]);
        doc["accessors"] = json!([
            { "bufferView": 0, "componentType": FLOAT, "count": pos.len(), "type": "VEC3",
              "min": min.map(f64::from), "max": max.map(f64::from) },
            { "bufferView": 1, "componentType": FLOAT, "count": nrm.len(), "type": "VEC3" },
            { "bufferView": 2, "componentType": UNSIGNED_INT, "count": idx.len(), "type": "SCALAR" },
        ]);
        doc["bufferViews"] = json!([
            { "buffer": 0, "byteOffset": 0, "byteLength": nrm_start, "target": ARRAY_BUFFER },
            { "buffer": 0, "byteOffset": nrm_start, "byteLength": idx_start - nrm_start, "target": ARRAY_BUFFER },
            { "buffer": 0, "byteOffset": idx_start, "byteLength": bin.len() - idx_start, "target": ELEMENT_ARRAY_BUFFER },
        ]);
        doc["buffers"] = json!([{ "byteLength": bin.len() }]);
    }
    doc["nodes"] = json!([node]);
    crate::glb::container(&doc, &bin)
}
