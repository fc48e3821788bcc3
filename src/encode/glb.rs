//! The glTF 2.0 binary (`.glb`) mesh of a tile, skirts included.
//!
//! One scene, one node, one mesh with one indexed triangle primitive (plus, in worlds with
//! rivers, a second node and mesh for the water: [`super::water_glb`]):
//!
//! - **Vertices** `0..4225` are the surface, vertex `j·65 + i` at local
//!   `(i·spacing, h, j·spacing)`; vertices `4225 + e·65 + t` are the skirt bottoms, a copy of
//!   surface vertex `t` of edge `e` (edges `n, e, s, w`; `t` runs west→east on `n`/`s` and
//!   north→south on `e`/`w`) lowered by `skirt_depth_m`. Local coordinates are relative to the
//!   tile origin, which the node's `translation` carries (`[origin_x_m, 0, origin_z_m]`), so world
//!   = local + translation; the node's `extras` repeat the origin exactly (`origin_m`, `f64`) with
//!   the key and seed.
//! - **Attributes**: `POSITION` (`f32` VEC3 with `min`/`max`), `NORMAL` (unit, skirts copy their
//!   edge vertex's normal), `TEXCOORD_0` (`(i/64, j/64)`, skirts copy their edge vertex's).
//! - **Indices**: `u16` (4485 vertices), surface first (`64·64·2` triangles, quad `(i, j)` split
//!   as `[v00, v01, v10]`, `[v10, v01, v11]`), then skirts (`4·64·2` triangles). Every triangle is
//!   counter-clockwise seen from its front: surface triangles face +Y (up), skirt triangles face
//!   away from the tile.
//!
//! The file is a 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded with
//! zeros, both to 4 bytes; buffer views are 4-byte aligned.

use super::json::KeyJson;
use crate::glb::container;
use crate::terrain::tile::Edge;
use crate::terrain::{Tile, WorldPlan, TILE_VERTEX_COUNT, TILE_VERTS};
use serde_json::json;

/// Skirt vertices: one copy of each of the four edge rows.
pub const SKIRT_VERTEX_COUNT: usize = 4 * TILE_VERTS;
/// All vertices.
pub const VERTEX_COUNT: usize = TILE_VERTEX_COUNT + SKIRT_VERTEX_COUNT;
/// Surface triangles.
pub const SURFACE_TRIANGLES: usize = 2 * (TILE_VERTS - 1) * (TILE_VERTS - 1);
/// Skirt triangles.
pub const SKIRT_TRIANGLES: usize = 4 * 2 * (TILE_VERTS - 1);

/// glTF `bufferView.target` of vertex attributes.
pub(super) const ARRAY_BUFFER: u32 = 34962;
/// glTF `bufferView.target` of indices.
pub(super) const ELEMENT_ARRAY_BUFFER: u32 = 34963;
/// glTF `componentType` of `f32`.
pub(super) const FLOAT: u32 = 5126;
/// glTF `componentType` of `u16`.
pub(super) const UNSIGNED_SHORT: u32 = 5123;
const UNSIGNED_INT: u32 = 5125;

/// Triangle index list (surface, then skirts), counter-clockwise seen from the front.
pub fn triangles() -> Vec<u32> {
    let n = TILE_VERTS as u32;
    let mut idx = Vec::with_capacity(3 * (SURFACE_TRIANGLES + SKIRT_TRIANGLES));
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let v00 = j * n + i;
            let (v10, v01, v11) = (v00 + 1, v00 + n, v00 + n + 1);
            idx.extend_from_slice(&[v00, v01, v10, v10, v01, v11]);
        }
    }
    for (e, edge) in Edge::ALL.iter().enumerate() {
        // Along +X (north edge) or +Z (east edge) the pattern below faces -Z or +X, i.e. out
        // of the tile; the south and west edges run the same way but face the other side.
        let flip = matches!(edge, Edge::South | Edge::West);
        for t in 0..TILE_VERTS - 1 {
            let (t0, t1) = (edge.vertex(t) as u32, edge.vertex(t + 1) as u32);
            let b0 = (TILE_VERTEX_COUNT + e * TILE_VERTS + t) as u32;
            let b1 = b0 + 1;
            if flip {
                idx.extend_from_slice(&[t0, b0, t1, t1, b0, b1]);
            } else {
                idx.extend_from_slice(&[t0, t1, b0, t1, b1, b0]);
            }
        }
    }
    idx
}

/// The vertex attributes of a tile mesh (surface, then skirts).
#[derive(Clone, Debug, PartialEq)]
pub struct Vertices {
    /// Positions relative to the tile origin, metres.
    pub positions: Vec<[f32; 3]>,
    /// Unit normals, y up.
    pub normals: Vec<[f32; 3]>,
    /// Texture coordinates `(i/64, j/64)`.
    pub uvs: Vec<[f32; 2]>,
}

/// Vertex positions relative to the tile origin, normals and texture coordinates (surface, then
/// skirts).
pub fn vertices(tile: &Tile) -> Vertices {
    let s = tile.spacing_m;
    let last = (TILE_VERTS - 1) as f32;
    let mut pos = Vec::with_capacity(VERTEX_COUNT);
    let mut nrm = Vec::with_capacity(VERTEX_COUNT);
    let mut uv = Vec::with_capacity(VERTEX_COUNT);
    for v in 0..TILE_VERTEX_COUNT {
        let (i, j) = ((v % TILE_VERTS) as f32, (v / TILE_VERTS) as f32);
        let h = tile.heights.get(v).copied().unwrap_or(0.0);
        pos.push([i * s, h, j * s]);
        nrm.push(tile.normals.get(v).copied().unwrap_or([0.0, 1.0, 0.0]));
        uv.push([i / last, j / last]);
    }
    for edge in Edge::ALL {
        for t in 0..TILE_VERTS {
            let v = edge.vertex(t);
            let [x, y, z] = pos[v];
            pos.push([x, y - tile.skirt_depth_m, z]);
            nrm.push(nrm[v]);
            uv.push(uv[v]);
        }
    }
    Vertices {
        positions: pos,
        normals: nrm,
        uvs: uv,
    }
}

/// Appends `values` to `bin` as little-endian `f32`s.
pub(super) fn push_f32s<'a>(bin: &mut Vec<u8>, values: impl IntoIterator<Item = &'a f32>) {
    for x in values {
        bin.extend_from_slice(&x.to_le_bytes());
    }
}

/// The axis-aligned bounds `(min, max)` of `positions` per coordinate, in their units (glTF's
/// `POSITION` accessor needs them). The points are visited in order, so the result is the same as
/// any loop of `f32::min` and `f32::max` over them in that order; empty input gives
/// `([∞; 3], [−∞; 3])`.
pub(super) fn bounds(positions: &[[f32; 3]]) -> ([f32; 3], [f32; 3]) {
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for p in positions {
        for c in 0..3 {
            min[c] = min[c].min(p[c]);
            max[c] = max[c].max(p[c]);
        }
    }
    (min, max)
}

/// Encodes a tile as glTF 2.0 binary.
pub fn encode(plan: &WorldPlan, tile: &Tile) -> Vec<u8> {
    let Vertices {
        positions: pos,
        normals: nrm,
        uvs: uv,
    } = vertices(tile);
    let idx = triangles();
    let (min, max) = bounds(&pos);

    let mut bin = Vec::new();
    let mut views = Vec::new();
    let mut view = |bin: &mut Vec<u8>, start: usize, target: u32| {
        views.push(json!({
            "buffer": 0,
            "byteOffset": start,
            "byteLength": bin.len() - start,
            "target": target,
        }));
    };
    let start = bin.len();
    push_f32s(&mut bin, pos.iter().flatten());
    view(&mut bin, start, ARRAY_BUFFER);
    let start = bin.len();
    push_f32s(&mut bin, nrm.iter().flatten());
    view(&mut bin, start, ARRAY_BUFFER);
    let start = bin.len();
    push_f32s(&mut bin, uv.iter().flatten());
    view(&mut bin, start, ARRAY_BUFFER);
    let start = bin.len();
    let index_type = if VERTEX_COUNT <= u16::MAX as usize {
        for &i in &idx {
            bin.extend_from_slice(&(i as u16).to_le_bytes());
        }
        UNSIGNED_SHORT
    } else {
        for &i in &idx {
            bin.extend_from_slice(&i.to_le_bytes());
        }
        UNSIGNED_INT
    };
    view(&mut bin, start, ELEMENT_ARRAY_BUFFER);
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }

    // f32 → f64 is exact, so min/max match the stored floats bit for bit.
    let exact = |v: [f32; 3]| v.map(|x| x as f64);
    let key = tile.key;
    let (ox, oz) = (tile.origin_x_m(), tile.origin_z_m());
    let mut doc = json!({
        "asset": {
            "version": "2.0",
            "generator": concat!("strata ", env!("CARGO_PKG_VERSION")),
        },
        "scene": 0,
        "scenes": [{ "nodes": [0] }],
        "nodes": [{
            "name": format!("tile {}/{}/{}", key.lod, key.x, key.z),
            "mesh": 0,
            "translation": [ox, 0.0, oz],
            "extras": {
                "format": super::TILE_FORMAT,
                "key": KeyJson::from(key),
                "seed": plan.seed.to_string(),
                "origin_m": [ox, oz],
                "spacing_m": tile.spacing_m,
                "skirt_depth_m": tile.skirt_depth_m,
                "surface_vertex_count": TILE_VERTEX_COUNT,
                "skirt_vertex_count": SKIRT_VERTEX_COUNT,
            },
        }],
        "meshes": [{
            "name": "terrain",
            "primitives": [{
                "attributes": { "POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2 },
                "indices": 3,
                "mode": 4,
            }],
        }],
        "accessors": [
            { "bufferView": 0, "componentType": FLOAT, "count": pos.len(), "type": "VEC3",
              "min": exact(min), "max": exact(max) },
            { "bufferView": 1, "componentType": FLOAT, "count": nrm.len(), "type": "VEC3" },
            { "bufferView": 2, "componentType": FLOAT, "count": uv.len(), "type": "VEC2" },
            { "bufferView": 3, "componentType": index_type, "count": idx.len(), "type": "SCALAR" },
        ],
        "bufferViews": views,
        "buffers": [{ "byteLength": bin.len() }],
    });
    if let Some(water) = super::water_glb::mesh(tile) {
        let name = format!("water {}/{}/{}", key.lod, key.x, key.z);
        super::water_glb::append(&mut doc, &mut bin, &water, name, [ox, 0.0, oz]);
    }
    container(&doc, &bin)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::test_util::{plan, tile};

    fn sub(a: [f32; 3], b: [f32; 3]) -> [f64; 3] {
        [
            (a[0] - b[0]) as f64,
            (a[1] - b[1]) as f64,
            (a[2] - b[2]) as f64,
        ]
    }

    fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }

    #[test]
    fn winding_faces_up_and_out() {
        let t = tile(3, -2, 1);
        let pos = vertices(&t).positions;
        let idx = triangles();
        assert_eq!(idx.len(), 3 * (SURFACE_TRIANGLES + SKIRT_TRIANGLES));
        let centre = [32.0 * t.spacing_m, 32.0 * t.spacing_m];
        for (n, tri) in idx.chunks(3).enumerate() {
            let [a, b, c] = [
                pos[tri[0] as usize],
                pos[tri[1] as usize],
                pos[tri[2] as usize],
            ];
            let nrm = cross(sub(b, a), sub(c, a));
            if n < SURFACE_TRIANGLES {
                assert!(nrm[1] > 0.0, "surface triangle {n} faces down");
            } else {
                // Outward: the normal points from the tile centre towards the triangle.
                let out = [(a[0] - centre[0]) as f64, (a[2] - centre[1]) as f64];
                assert!(
                    nrm[0] * out[0] + nrm[2] * out[1] > 0.0,
                    "skirt triangle {n} faces in"
                );
                assert!(nrm[1].abs() < 1e-9, "skirts are vertical");
            }
        }
    }

    #[test]
    fn glb_container() {
        let t = tile(0, 0, 0);
        let b = encode(plan(), &t);
        assert_eq!(b, encode(plan(), &t), "deterministic");
        assert_eq!(&b[0..4], b"glTF");
        assert_eq!(
            u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize,
            b.len()
        );
        let json_len = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
        assert_eq!(json_len % 4, 0);
        let doc: serde_json::Value =
            serde_json::from_slice(&b[20..20 + json_len]).expect("json chunk");
        assert_eq!(doc["accessors"][0]["count"], VERTEX_COUNT);
        assert_eq!(doc["nodes"][0]["extras"]["key"]["lod"], 0);
    }

    /// The JSON chunk and the BIN chunk's length of a glb.
    fn chunks(b: &[u8]) -> (serde_json::Value, usize) {
        let json_len = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
        let doc = serde_json::from_slice(&b[20..20 + json_len]).expect("json chunk");
        let at = 20 + json_len;
        let bin_len = u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]]) as usize;
        (doc, bin_len)
    }

    #[test]
    fn water_is_a_second_node_only_where_the_tile_has_kinds_and_water() {
        let mut t = tile(1, 2, -1);
        t.water_kind.clear();
        let (dry, _) = chunks(&encode(plan(), &t));
        assert_eq!(dry["nodes"].as_array().map(Vec::len), Some(1));
        assert_eq!(dry["meshes"].as_array().map(Vec::len), Some(1));
        assert_eq!(dry["scenes"][0]["nodes"], serde_json::json!([0]));
        assert!(dry.get("materials").is_none(), "no material without kinds");
        assert_eq!(dry["bufferViews"].as_array().map(Vec::len), Some(4));

        t.water_kind = vec![0; TILE_VERTEX_COUNT];
        for v in [0, 1, 65, 66, 2000] {
            t.water_kind[v] = 2;
            t.water_depth[v] = 3.0;
        }
        let b = encode(plan(), &t);
        let (wet, bin_len) = chunks(&b);
        assert_eq!(wet["scenes"][0]["nodes"], serde_json::json!([0, 1]));
        assert_eq!(wet["nodes"][1]["mesh"], 1);
        assert_eq!(
            wet["nodes"][1]["translation"],
            wet["nodes"][0]["translation"]
        );
        assert_eq!(wet["materials"][0]["alphaMode"], "BLEND");
        let prim = &wet["meshes"][1]["primitives"][0];
        assert_eq!(prim["material"], 0);
        let water = super::super::water_glb::mesh(&t).expect("water");
        let pos = prim["attributes"]["POSITION"].as_u64().expect("accessor") as usize;
        assert_eq!(wet["accessors"][pos]["count"], water.positions.len());
        let idx = prim["indices"].as_u64().expect("accessor") as usize;
        assert_eq!(wet["accessors"][idx]["count"], water.indices.len());
        assert_eq!(wet["buffers"][0]["byteLength"], bin_len);
        for view in wet["bufferViews"].as_array().expect("views") {
            let offset = view["byteOffset"].as_u64().expect("offset") as usize;
            let len = view["byteLength"].as_u64().expect("length") as usize;
            assert_eq!(offset % 4, 0);
            assert!(offset + len <= bin_len);
        }
        // The wet 2×2 block at the corner touches the quads (0..2, 0..2), and the wet vertex
        // (50, 30) its four quads.
        assert_eq!(water.indices.len(), 6 * (4 + 4));
    }
}
