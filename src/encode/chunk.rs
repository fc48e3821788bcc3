//! Wire formats of volume chunks ([`crate::volume::chunk`]): `strata.chunk.v1` JSON and the `STCK`
//! v1 little-endian binary; the glb is [`super::chunk_glb`]. The normative description is
//! `api/chunk_format_v1.md`. Every encoder is a pure function of the chunk, so the same URL gives
//! the same bytes and a content hash is a valid `ETag`.

use crate::volume::chunk::{ChunkKey, ChunkMesh};
use crate::volume::mesh::NONE;
use serde_json::json;

/// Format identifier of the JSON product.
pub const CHUNK_FORMAT: &str = "strata.chunk.v1";
/// Magic of the binary product.
pub const BIN_MAGIC: [u8; 4] = *b"STCK";
/// Version of the binary product.
pub const BIN_VERSION: u32 = 1;
/// Bytes of the binary header.
pub const BIN_HEADER_BYTES: usize = 96;
/// Header flag (offset 12): a `u32 ×V` section of subsurface materials ends the body.
pub const FLAG_GEOLOGY: u32 = 1;
/// `Content-Type` of the binary product.
pub const BIN_CONTENT_TYPE: &str = "application/vnd.strata.chunk.v1";

/// What a chunk product says about where it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChunkInfo {
    /// World seed.
    pub seed: u64,
    /// Address.
    pub key: ChunkKey,
    /// Cell size, metres.
    pub spacing_m: f32,
}

impl ChunkInfo {
    /// World position of the chunk origin (its first cell's minimum corner), metres.
    pub fn origin_m(&self) -> [f64; 3] {
        self.key
            .first_cell()
            .map(|c| c as f64 * self.spacing_m as f64)
    }
}

/// `strata.chunk.v1` JSON.
pub fn encode_json(info: &ChunkInfo, m: &ChunkMesh) -> Vec<u8> {
    let flat3 = |v: &[[f32; 3]]| v.iter().flatten().copied().collect::<Vec<f32>>();
    let adjacency: Vec<i64> = m
        .adjacency
        .iter()
        .flatten()
        .flat_map(|n| {
            if n.quad == NONE {
                [-1, -1, -1]
            } else {
                [i64::from(n.quad), i64::from(n.edge), i64::from(n.transform)]
            }
        })
        .collect();
    let doc = json!({
        "format": CHUNK_FORMAT,
        "seed": info.seed.to_string(),
        "key": { "lod": info.key.lod, "x": info.key.x, "y": info.key.y, "z": info.key.z },
        "spacing_m": info.spacing_m,
        "origin_m": info.origin_m(),
        "vertex_count": m.positions.len(),
        "quad_count": m.quads.len(),
        "positions": flat3(&m.positions),
        "normals": flat3(&m.normals),
        "materials": m.materials,
        "quads": m.quads.iter().flatten().collect::<Vec<_>>(),
        "classes": m.classes.iter().map(|c| *c as u8).collect::<Vec<_>>(),
        "adjacency": adjacency,
        "edges": m.global_edges.iter().flatten().collect::<Vec<_>>(),
        "skirt": {
            "depth_m": m.skirt_depth_m,
            "positions": flat3(&m.skirt_positions),
            "quads": m.skirt_quads.iter().flatten().collect::<Vec<_>>(),
        },
    });
    let mut doc = doc;
    if !m.geology.is_empty() {
        doc["geology"] = json!(m.geology);
    }
    serde_json::to_vec(&doc).unwrap_or_default()
}

fn pad4(out: &mut Vec<u8>) {
    while !out.len().is_multiple_of(4) {
        out.push(0);
    }
}

/// `STCK` v1 binary (layout in `api/chunk_format_v1.md`).
pub fn encode_bin(info: &ChunkInfo, m: &ChunkMesh) -> Vec<u8> {
    let (v, q) = (m.positions.len(), m.quads.len());
    let mut out = Vec::with_capacity(BIN_HEADER_BYTES + v * 28 + q * 72);
    out.extend_from_slice(&BIN_MAGIC);
    out.extend_from_slice(&BIN_VERSION.to_le_bytes());
    out.extend_from_slice(&info.key.lod.to_le_bytes());
    let flags = if m.geology.is_empty() {
        0
    } else {
        FLAG_GEOLOGY
    };
    out.extend_from_slice(&flags.to_le_bytes());
    for c in [info.key.x, info.key.y, info.key.z] {
        out.extend_from_slice(&c.to_le_bytes());
    }
    out.extend_from_slice(&info.seed.to_le_bytes());
    for o in info.origin_m() {
        out.extend_from_slice(&o.to_le_bytes());
    }
    out.extend_from_slice(&info.spacing_m.to_le_bytes());
    out.extend_from_slice(&m.skirt_depth_m.to_le_bytes());
    for n in [v, q, m.skirt_positions.len(), m.skirt_quads.len()] {
        out.extend_from_slice(&(n as u32).to_le_bytes());
    }
    debug_assert_eq!(out.len(), BIN_HEADER_BYTES);
    for x in m.positions.iter().chain(&m.normals).flatten() {
        out.extend_from_slice(&x.to_le_bytes());
    }
    out.extend_from_slice(&m.materials);
    pad4(&mut out);
    for i in m.quads.iter().flatten() {
        out.extend_from_slice(&i.to_le_bytes());
    }
    out.extend(m.classes.iter().map(|c| *c as u8));
    pad4(&mut out);
    for n in m.adjacency.iter().flatten() {
        out.extend_from_slice(&n.quad.to_le_bytes());
        out.extend_from_slice(&[n.edge, n.transform, 0, 0]);
    }
    for e in m.global_edges.iter().flatten() {
        out.extend_from_slice(&e.to_le_bytes());
    }
    for x in m.skirt_positions.iter().flatten() {
        out.extend_from_slice(&x.to_le_bytes());
    }
    for i in m.skirt_quads.iter().flatten() {
        out.extend_from_slice(&i.to_le_bytes());
    }
    for g in &m.geology {
        out.extend_from_slice(&g.to_le_bytes());
    }
    out
}
