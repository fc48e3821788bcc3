//! The water of a tile glb (`api/tile_format_v1.md` §glTF): a second node and mesh, one
//! triangle primitive at the water surface with a translucent blue material.
//!
//! Only tiles that carry water kinds (worlds with rivers) get it, so the glb of every world
//! stored before rivers keeps its bytes. A vertex is **wet** when its kind is not 0 (sea, lake or
//! river); every quad with a wet corner is covered, split as the terrain's quads are. A wet
//! vertex sits at its water surface height ([`super::water::surface`]); a dry corner of a
//! covered quad at the lowest water surface of the wet vertices around it (its 3×3
//! neighbourhood in the tile), so the sheet runs on flat into the bank and the ground hides it
//! there. Normals point up. Vertices are the covered quads' corners only, in vertex-index order.

use super::glb::{bounds, push_f32s, ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, UNSIGNED_SHORT};
use super::water;
use crate::terrain::{Tile, TILE_VERTEX_COUNT, TILE_VERTS};
use serde_json::{json, Value};

/// Base colour (linear RGBA) of the water material; alpha is its opacity.
pub const WATER_COLOR: [f32; 4] = [0.05, 0.25, 0.55, 0.6];

/// A tile's water surface mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct WaterMesh {
    /// Positions relative to the tile origin, metres.
    pub positions: Vec<[f32; 3]>,
    /// Triangles, counter-clockwise seen from above, indices into `positions`.
    pub indices: Vec<u16>,
}

/// The water mesh of `tile`, or `None` when it carries no kinds or has no wet vertex.
pub fn mesh(tile: &Tile) -> Option<WaterMesh> {
    if tile.water_kind.len() != TILE_VERTEX_COUNT {
        return None;
    }
    let n = TILE_VERTS;
    let wet: Vec<bool> = tile.water_kind.iter().map(|&k| k != 0).collect();
    if !wet.contains(&true) {
        return None;
    }
    let surface = water::surface(tile);
    let quads = n - 1;
    let covered = |i: usize, j: usize| {
        let v = j * n + i;
        wet[v] || wet[v + 1] || wet[v + n] || wet[v + n + 1]
    };
    let mut used = vec![false; TILE_VERTEX_COUNT];
    for j in 0..quads {
        for i in 0..quads {
            if covered(i, j) {
                let v = j * n + i;
                for c in [v, v + 1, v + n, v + n + 1] {
                    used[c] = true;
                }
            }
        }
    }
    // The level of a used vertex: its own surface when wet, else the lowest wet neighbour's.
    let level = |v: usize| {
        if wet[v] {
            return surface[v];
        }
        let (i, j) = ((v % n) as i64, (v / n) as i64);
        let mut low = f32::INFINITY;
        for dj in -1..=1 {
            for di in -1..=1 {
                let (a, b) = (i + di, j + dj);
                if a < 0 || b < 0 || a >= n as i64 || b >= n as i64 {
                    continue;
                }
                let u = b as usize * n + a as usize;
                if wet[u] {
                    low = low.min(surface[u]);
                }
            }
        }
        low
    };
    let s = tile.spacing_m;
    let mut index = vec![u16::MAX; TILE_VERTEX_COUNT];
    let mut positions = Vec::new();
    for v in (0..TILE_VERTEX_COUNT).filter(|&v| used[v]) {
        index[v] = positions.len() as u16;
        positions.push([(v % n) as f32 * s, level(v), (v / n) as f32 * s]);
    }
    let mut indices = Vec::new();
    for j in 0..quads {
        for i in 0..quads {
            if covered(i, j) {
                let v00 = j * n + i;
                let [a, b, c, d] = [v00, v00 + 1, v00 + n, v00 + n + 1].map(|v| index[v]);
                indices.extend_from_slice(&[a, c, b, b, c, d]);
            }
        }
    }
    Some(WaterMesh { positions, indices })
}

/// Adds `water` to the glb document `doc` of a tile and its BIN chunk `bin` (4-byte aligned on
/// entry and on return): a material, a mesh, the accessors and buffer views, and a node named
/// `name` with `translation` in the scene.
pub fn append(
    doc: &mut Value,
    bin: &mut Vec<u8>,
    water: &WaterMesh,
    name: String,
    translation: [f64; 3],
) {
    let push = |doc: &mut Value, list: &str, item: Value| -> usize {
        match doc[list].as_array_mut() {
            Some(a) => {
                a.push(item);
                a.len() - 1
            }
            None => {
                doc[list] = json!([item]);
                0
            }
        }
    };
    let view = |doc: &mut Value, bin: &[u8], start: usize, target: u32| {
        push(
            doc,
            "bufferViews",
            json!({
                "buffer": 0,
                "byteOffset": start,
                "byteLength": bin.len() - start,
                "target": target,
            }),
        )
    };
    let start = bin.len();
    push_f32s(bin, water.positions.iter().flatten());
    let positions = view(doc, bin, start, ARRAY_BUFFER);
    let start = bin.len();
    let up = [0.0f32, 1.0, 0.0];
    push_f32s(bin, water.positions.iter().flat_map(|_| up.iter()));
    let normals = view(doc, bin, start, ARRAY_BUFFER);
    let start = bin.len();
    for i in &water.indices {
        bin.extend_from_slice(&i.to_le_bytes());
    }
    let indices = view(doc, bin, start, ELEMENT_ARRAY_BUFFER);
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }

    let (min, max) = bounds(&water.positions);
    let exact = |v: [f32; 3]| v.map(|x| x as f64);
    let count = water.positions.len();
    let pos = push(
        doc,
        "accessors",
        json!({ "bufferView": positions, "componentType": FLOAT, "count": count,
                "type": "VEC3", "min": exact(min), "max": exact(max) }),
    );
    let nrm = push(
        doc,
        "accessors",
        json!({ "bufferView": normals, "componentType": FLOAT, "count": count, "type": "VEC3" }),
    );
    let idx = push(
        doc,
        "accessors",
        json!({ "bufferView": indices, "componentType": UNSIGNED_SHORT,
                "count": water.indices.len(), "type": "SCALAR" }),
    );
    let material = push(
        doc,
        "materials",
        json!({
            "name": "water",
            "pbrMetallicRoughness": {
                "baseColorFactor": WATER_COLOR,
                "metallicFactor": 0.0,
                "roughnessFactor": 0.1,
            },
            "alphaMode": "BLEND",
            "doubleSided": true,
        }),
    );
    let mesh = push(
        doc,
        "meshes",
        json!({
            "name": "water",
            "primitives": [{
                "attributes": { "POSITION": pos, "NORMAL": nrm },
                "indices": idx,
                "material": material,
                "mode": 4,
            }],
        }),
    );
    let node = push(
        doc,
        "nodes",
        json!({ "name": name, "mesh": mesh, "translation": translation }),
    );
    if let Some(nodes) = doc["scenes"][0]["nodes"].as_array_mut() {
        nodes.push(json!(node));
    }
    doc["buffers"][0]["byteLength"] = json!(bin.len());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::tile;

    #[test]
    fn no_kinds_no_water_and_wet_quads_are_covered() {
        let mut t = tile(0, 0, 0);
        t.water_kind.clear();
        assert_eq!(mesh(&t), None, "a tile without kinds has no water mesh");
        t.water_kind = vec![0; TILE_VERTEX_COUNT];
        assert_eq!(mesh(&t), None, "nor one without wet vertices");
        // One wet vertex inside: its four quads, nine vertices.
        let v = 10 * TILE_VERTS + 20;
        t.water_kind[v] = 3;
        t.water_depth[v] = 2.0;
        let m = mesh(&t).expect("water");
        assert_eq!(m.positions.len(), 9);
        assert_eq!(m.indices.len(), 4 * 6);
        let level = t.heights[v] + 2.0;
        assert!(
            m.positions.iter().all(|p| p[1] == level),
            "dry corners take the wet level"
        );
        for tri in m.indices.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|k| m.positions[tri[k] as usize]);
            let (ux, uz, vx, vz) = (b[0] - a[0], b[2] - a[2], c[0] - a[0], c[2] - a[2]);
            // The y component of (b − a) × (c − a): positive means counter-clockwise from above.
            assert!(uz * vx - ux * vz > 0.0, "triangle {tri:?} faces up");
        }
    }
}
