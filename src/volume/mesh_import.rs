//! Input meshes given as glTF 2.0 binaries (`.glb`): the triangles a volume region voxelizes as
//! its middle-priority input (Becher §3.3, "input meshes"; §4.2 assigns such meshes global noise
//! parameters and a material, which the element supplies).
//!
//! A small hand-written reader, not the `gltf` crate: a volume region needs only the positions and
//! indices of triangle primitives with the node transforms applied, and reading exactly that keeps
//! every limit explicit. What is read:
//!
//! - the GLB container (header, a JSON chunk, an optional BIN chunk; version 2 only);
//! - the scene `scene` (or the first of `scenes`; without scenes, every root node), its nodes and
//!   their children recursively (at most [`MAX_NODE_DEPTH`] deep and [`MAX_NODE_VISITS`] visits),
//!   each with its local `matrix` or `translation`/`rotation`/`scale`, composed parent first;
//!   at most [`MAX_PRIMITIVE_VISITS`] primitives and [`MAX_ACCESSOR_ELEMENTS`] accessor elements
//!   are read in one traversal;
//! - of each mesh primitive of mode 4 (triangles), 5 (strip) or 6 (fan): `POSITION` (`FLOAT`
//!   `VEC3`, no sparse storage) and the optional `indices` (`UNSIGNED_BYTE`, `_SHORT` or `_INT`),
//!   through buffer views of buffer 0, which must be the GLB's own BIN chunk (no external or
//!   data URIs). Primitives of other modes (points, lines) have no surface and are skipped.
//!
//! A node whose world matrix mirrors (negative determinant) has its triangles' winding reversed,
//! as the glTF specification prescribes, so the outward normals `(v1 − v0) × (v2 − v0)` the
//! pipeline uses stay outward. An optional element `transform` (a column-major 4×4 affine matrix,
//! glTF's convention) is applied after the node transforms, with the same winding rule.
//!
//! Everything else in the file (materials, textures, normals, animations, extensions) is ignored.
//! Bad input is an error saying what is wrong; nothing panics on user bytes.

use serde_json::Value;

/// Largest glb accepted, bytes (decoded). With base64's 4/3 it keeps one mesh well inside a
/// scene's size limit (`store::MAX_SCENE_BYTES`).
pub const MAX_GLB_BYTES: usize = 512 * 1024;
/// Deepest node hierarchy followed.
pub const MAX_NODE_DEPTH: usize = 32;
/// Most node visits in one scene traversal (a node reached twice counts twice).
pub const MAX_NODE_VISITS: usize = 4096;
/// Most mesh primitives visited in one scene traversal, of any mode (a primitive reached through
/// two nodes counts twice). Without it, a 512 KiB file of thousands of primitives under
/// thousands of node visits made the reader loop for minutes while producing no triangle.
pub const MAX_PRIMITIVE_VISITS: usize = 65_536;
/// Most accessor elements (positions and indices) read in one scene traversal, counted per
/// read: an accessor read again through another node or primitive counts again. It bounds the
/// work of primitives that read large accessors yet yield few triangles (an index count below 3,
/// points reused), which the triangle budget alone does not.
pub const MAX_ACCESSOR_ELEMENTS: usize = 524_288;

use crate::glb::{CHUNK_BIN, CHUNK_JSON, GLB_MAGIC};

/// Why a glb is refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct GlbError(pub String);

fn bad(message: impl Into<String>) -> GlbError {
    GlbError(message.into())
}

/// A column-major 4×4 matrix (glTF's layout: element `(row r, column c)` at `c·4 + r`).
pub type Mat4 = [f32; 16];

/// The identity.
pub const IDENTITY: Mat4 = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// `a · b`.
pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [0.0f32; 16];
    for c in 0..4 {
        for r in 0..4 {
            out[c * 4 + r] = (0..4).map(|k| a[k * 4 + r] * b[c * 4 + k]).sum();
        }
    }
    out
}

/// `m · (p, 1)` without the projective row (matrices here are affine).
pub fn apply(m: &Mat4, p: [f32; 3]) -> [f32; 3] {
    std::array::from_fn(|r| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r])
}

/// Determinant of the upper-left 3×3 block.
pub fn det3(m: &Mat4) -> f32 {
    let a = |r: usize, c: usize| m[c * 4 + r];
    a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
        - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
        + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0))
}

/// Checks an element `transform`: finite, affine (last row `0 0 0 1`), invertible.
///
/// # Errors
/// [`GlbError`] saying which.
pub fn check_transform(m: &Mat4) -> Result<(), GlbError> {
    if m.iter().any(|v| !v.is_finite()) {
        return Err(bad("transform values must be finite"));
    }
    if [m[3], m[7], m[11], m[15]] != [0.0, 0.0, 0.0, 1.0] {
        return Err(bad(
            "transform must be affine: a column-major 4x4 matrix whose last row is 0 0 0 1",
        ));
    }
    if det3(m).abs() < 1e-12 {
        return Err(bad("transform must be invertible"));
    }
    Ok(())
}

/// The local matrix of a node: `matrix`, or `T·R·S` from `translation`, `rotation` (unit
/// quaternion `[x, y, z, w]`) and `scale`.
fn node_matrix(node: &Value, at: &str) -> Result<Mat4, GlbError> {
    let floats = |key: &str, n: usize| -> Result<Option<Vec<f32>>, GlbError> {
        match node.get(key) {
            None => Ok(None),
            Some(v) => {
                let arr = v
                    .as_array()
                    .filter(|a| a.len() == n)
                    .ok_or_else(|| bad(format!("{at}.{key} must be {n} numbers")))?;
                let out: Option<Vec<f32>> = arr
                    .iter()
                    .map(|x| x.as_f64().map(|f| f as f32).filter(|f| f.is_finite()))
                    .collect();
                out.map(Some)
                    .ok_or_else(|| bad(format!("{at}.{key} must be finite numbers")))
            }
        }
    };
    if let Some(m) = floats("matrix", 16)? {
        let mut out = [0.0; 16];
        out.copy_from_slice(&m);
        return Ok(out);
    }
    let t = floats("translation", 3)?.unwrap_or_else(|| vec![0.0; 3]);
    let q = floats("rotation", 4)?.unwrap_or_else(|| vec![0.0, 0.0, 0.0, 1.0]);
    let s = floats("scale", 3)?.unwrap_or_else(|| vec![1.0; 3]);
    let len = q.iter().map(|v| v * v).sum::<f32>().sqrt();
    if len < 1e-6 {
        return Err(bad(format!("{at}.rotation must be a unit quaternion")));
    }
    let (x, y, z, w) = (q[0] / len, q[1] / len, q[2] / len, q[3] / len);
    // Rotation matrix of a unit quaternion, column-major.
    let r = [
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y + z * w),
        2.0 * (x * z - y * w),
        2.0 * (x * y - z * w),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z + x * w),
        2.0 * (x * z + y * w),
        2.0 * (y * z - x * w),
        1.0 - 2.0 * (x * x + y * y),
    ];
    let mut m = [0.0; 16];
    for c in 0..3 {
        for row in 0..3 {
            m[c * 4 + row] = r[c * 3 + row] * s[c];
        }
    }
    m[12] = t[0];
    m[13] = t[1];
    m[14] = t[2];
    m[15] = 1.0;
    Ok(m)
}

/// The parsed container: the JSON document and the BIN chunk, and the accessor elements read
/// from it so far (checked against [`MAX_ACCESSOR_ELEMENTS`]).
struct Glb<'a> {
    doc: Value,
    bin: &'a [u8],
    elements_read: std::cell::Cell<usize>,
}

fn u32_at(b: &[u8], at: usize) -> Option<u32> {
    let s = b.get(at..at.checked_add(4)?)?;
    Some(u32::from_le_bytes([s[0], s[1], s[2], s[3]]))
}

fn parse_container(bytes: &[u8]) -> Result<Glb<'_>, GlbError> {
    if bytes.len() > MAX_GLB_BYTES {
        return Err(bad(format!(
            "the glb is {} bytes; at most {MAX_GLB_BYTES} are accepted",
            bytes.len()
        )));
    }
    if u32_at(bytes, 0) != Some(GLB_MAGIC) {
        return Err(bad("not a glb: the file does not start with \"glTF\""));
    }
    if u32_at(bytes, 4) != Some(2) {
        return Err(bad("only glTF 2.0 binaries are accepted"));
    }
    let total = u32_at(bytes, 8).ok_or_else(|| bad("truncated glb header"))? as usize;
    if total > bytes.len() || total < 20 {
        return Err(bad(format!(
            "the glb header says {total} bytes but {} were given",
            bytes.len()
        )));
    }
    let body = &bytes[..total];
    let mut at = 12;
    let mut json: Option<&[u8]> = None;
    let mut bin: &[u8] = &[];
    while at + 8 <= body.len() {
        let len = u32_at(body, at).unwrap_or(0) as usize;
        let kind = u32_at(body, at + 4).unwrap_or(0);
        let data = body
            .get(at + 8..at + 8 + len)
            .ok_or_else(|| bad("a glb chunk runs past the end of the file"))?;
        match kind {
            CHUNK_JSON if json.is_none() && at == 12 => json = Some(data),
            CHUNK_BIN if json.is_some() && bin.is_empty() => bin = data,
            CHUNK_JSON | CHUNK_BIN => return Err(bad("the glb chunks are out of order")),
            // Unknown chunk types are skipped, as the specification requires.
            _ => {}
        }
        at += 8 + len;
    }
    let json = json.ok_or_else(|| bad("the glb has no JSON chunk"))?;
    let doc: Value =
        serde_json::from_slice(json).map_err(|e| bad(format!("the glb's JSON is invalid: {e}")))?;
    if !doc.is_object() {
        return Err(bad("the glb's JSON must be an object"));
    }
    Ok(Glb {
        doc,
        bin,
        elements_read: std::cell::Cell::new(0),
    })
}

fn index_of(v: &Value, key: &str, at: &str) -> Result<Option<usize>, GlbError> {
    match v.get(key) {
        None => Ok(None),
        Some(x) => x
            .as_u64()
            .map(|i| Some(i as usize))
            .ok_or_else(|| bad(format!("{at}.{key} must be an index"))),
    }
}

impl Glb<'_> {
    fn item(&self, array: &str, i: usize) -> Result<&Value, GlbError> {
        self.doc
            .get(array)
            .and_then(|a| a.get(i))
            .ok_or_else(|| bad(format!("{array}[{i}] does not exist")))
    }

    /// The bytes of accessor `a`'s elements: `(view bytes, offset of element 0, stride, count)`.
    fn accessor(
        &self,
        a: usize,
        want_type: &str,
        component_types: &[u64],
    ) -> Result<(&[u8], usize, usize, usize, u64), GlbError> {
        let at = format!("accessors[{a}]");
        let acc = self.item("accessors", a)?;
        if acc.get("sparse").is_some() {
            return Err(bad(format!("{at}: sparse accessors are not supported")));
        }
        if acc.get("type").and_then(Value::as_str) != Some(want_type) {
            return Err(bad(format!("{at}.type must be {want_type}")));
        }
        let ct = acc
            .get("componentType")
            .and_then(Value::as_u64)
            .unwrap_or(0);
        if !component_types.contains(&ct) {
            return Err(bad(format!(
                "{at}.componentType must be one of {component_types:?}, got {ct}"
            )));
        }
        if acc.get("normalized").and_then(Value::as_bool) == Some(true) {
            return Err(bad(format!("{at}: normalized accessors are not supported")));
        }
        let count =
            acc.get("count")
                .and_then(Value::as_u64)
                .ok_or_else(|| bad(format!("{at}.count must be a number")))? as usize;
        let read = self.elements_read.get().saturating_add(count);
        if read > MAX_ACCESSOR_ELEMENTS {
            return Err(bad(format!(
                "{at}: reading its {count} elements would read more than {MAX_ACCESSOR_ELEMENTS} accessor elements in all"
            )));
        }
        self.elements_read.set(read);
        let comp = match ct {
            5121 => 1,
            5123 => 2,
            _ => 4,
        };
        let elem = comp * if want_type == "VEC3" { 3 } else { 1 };
        let bv = index_of(acc, "bufferView", &at)?
            .ok_or_else(|| bad(format!("{at} has no bufferView")))?;
        let offset = index_of(acc, "byteOffset", &at)?.unwrap_or(0);
        let vat = format!("bufferViews[{bv}]");
        let view = self.item("bufferViews", bv)?;
        let buffer = index_of(view, "buffer", &vat)?.unwrap_or(usize::MAX);
        if buffer != 0 {
            return Err(bad(format!(
                "{vat}.buffer must be 0, the glb's own binary chunk"
            )));
        }
        let buf = self.item("buffers", 0)?;
        if buf.get("uri").is_some() {
            return Err(bad(
                "buffers[0] must be the glb's binary chunk; external and data URIs are not read",
            ));
        }
        let v_off = index_of(view, "byteOffset", &vat)?.unwrap_or(0);
        let v_len = index_of(view, "byteLength", &vat)?
            .ok_or_else(|| bad(format!("{vat}.byteLength is required")))?;
        let bytes = v_off
            .checked_add(v_len)
            .and_then(|end| self.bin.get(v_off..end))
            .ok_or_else(|| bad(format!("{vat} runs past the end of the binary chunk")))?;
        let stride = index_of(view, "byteStride", &vat)?.unwrap_or(elem);
        if stride < elem {
            return Err(bad(format!("{vat}.byteStride is smaller than an element")));
        }
        if count > 0 {
            let end = (count - 1)
                .checked_mul(stride)
                .and_then(|x| x.checked_add(offset))
                .and_then(|x| x.checked_add(elem));
            if end.is_none_or(|e| e > bytes.len()) {
                return Err(bad(format!("{at} runs past the end of {vat}")));
            }
        }
        Ok((bytes, offset, stride, count, ct))
    }

    fn positions(&self, a: usize) -> Result<Vec<[f32; 3]>, GlbError> {
        let (bytes, offset, stride, count, _) = self.accessor(a, "VEC3", &[5126])?;
        let mut out = Vec::with_capacity(count);
        for i in 0..count {
            let at = offset + i * stride;
            let p: [f32; 3] = std::array::from_fn(|k| {
                let s = &bytes[at + 4 * k..at + 4 * k + 4];
                f32::from_le_bytes([s[0], s[1], s[2], s[3]])
            });
            if p.iter().any(|c| !c.is_finite()) {
                return Err(bad(format!("accessors[{a}]: position {i} is not finite")));
            }
            out.push(p);
        }
        Ok(out)
    }

    fn indices(&self, a: usize) -> Result<Vec<u32>, GlbError> {
        let (bytes, offset, stride, count, ct) = self.accessor(a, "SCALAR", &[5121, 5123, 5125])?;
        Ok((0..count)
            .map(|i| {
                let at = offset + i * stride;
                match ct {
                    5121 => u32::from(bytes[at]),
                    5123 => u32::from(u16::from_le_bytes([bytes[at], bytes[at + 1]])),
                    _ => {
                        u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
                    }
                }
            })
            .collect())
    }

    /// The root nodes of the scene to read.
    fn roots(&self) -> Result<Vec<usize>, GlbError> {
        let scenes = self.doc.get("scenes").and_then(Value::as_array);
        if let Some(scenes) = scenes.filter(|s| !s.is_empty()) {
            let s = index_of(&self.doc, "scene", "glTF")?.unwrap_or(0);
            let scene = scenes
                .get(s)
                .ok_or_else(|| bad(format!("scene {s} does not exist")))?;
            return match scene.get("nodes") {
                None => Ok(Vec::new()),
                Some(n) => n
                    .as_array()
                    .and_then(|a| a.iter().map(|x| x.as_u64().map(|i| i as usize)).collect())
                    .ok_or_else(|| bad(format!("scenes[{s}].nodes must be indices"))),
            };
        }
        let nodes = self
            .doc
            .get("nodes")
            .and_then(Value::as_array)
            .map_or(&[][..], Vec::as_slice);
        let mut child = vec![false; nodes.len()];
        for n in nodes {
            for c in n
                .get("children")
                .and_then(Value::as_array)
                .map_or(&[][..], Vec::as_slice)
            {
                if let Some(i) = c.as_u64().and_then(|i| child.get_mut(i as usize)) {
                    *i = true;
                }
            }
        }
        Ok((0..nodes.len()).filter(|&i| !child[i]).collect())
    }
}

/// Triangles of one primitive's vertex list by its mode.
fn assemble(mode: u64, idx: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        4 => idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        // Strip: odd triangles swap their first two vertices to keep the winding.
        5 => (2..idx.len())
            .map(|i| {
                if i % 2 == 0 {
                    [idx[i - 2], idx[i - 1], idx[i]]
                } else {
                    [idx[i - 1], idx[i - 2], idx[i]]
                }
            })
            .collect(),
        6 => (2..idx.len())
            .map(|i| [idx[0], idx[i - 1], idx[i]])
            .collect(),
        _ => Vec::new(),
    }
}

/// The triangles of a glb's scene in world metres (node transforms, then `transform`), wound
/// counter-clockwise seen from outside as the file's front faces are; at most `max_triangles`.
///
/// # Errors
/// [`GlbError`] saying what is wrong with the file (module docs), or that it has more than
/// `max_triangles` triangles.
pub fn glb_triangles(
    bytes: &[u8],
    transform: Option<&Mat4>,
    max_triangles: usize,
) -> Result<Vec<[[f32; 3]; 3]>, GlbError> {
    if let Some(t) = transform {
        check_transform(t)?;
    }
    let glb = parse_container(bytes)?;
    let mut out = Vec::new();
    let mut stack: Vec<(usize, Mat4, usize)> = glb
        .roots()?
        .into_iter()
        .rev()
        .map(|n| (n, *transform.unwrap_or(&IDENTITY), 0))
        .collect();
    let too_many = || {
        bad(format!(
            "the node hierarchy is deeper than {MAX_NODE_DEPTH} or has more than {MAX_NODE_VISITS} node visits (a cycle?)"
        ))
    };
    let mut visits = 0;
    let mut primitive_visits = 0usize;
    // Every node on the stack will be visited, so a stack longer than the visits left is refused
    // before it grows: a node listing itself as its child thousands of times would otherwise
    // push millions of entries before the depth limit ends the walk.
    if stack.len() > MAX_NODE_VISITS {
        return Err(too_many());
    }
    while let Some((n, parent, depth)) = stack.pop() {
        visits += 1;
        if visits > MAX_NODE_VISITS || depth >= MAX_NODE_DEPTH {
            return Err(too_many());
        }
        let at = format!("nodes[{n}]");
        let node = glb.item("nodes", n)?;
        let world = mul(&parent, &node_matrix(node, &at)?);
        if let Some(c) = node.get("children") {
            let kids: Vec<usize> = c
                .as_array()
                .and_then(|a| a.iter().map(|x| x.as_u64().map(|i| i as usize)).collect())
                .ok_or_else(|| bad(format!("{at}.children must be indices")))?;
            if visits + stack.len() + kids.len() > MAX_NODE_VISITS {
                return Err(too_many());
            }
            stack.extend(kids.into_iter().rev().map(|k| (k, world, depth + 1)));
        }
        let Some(m) = index_of(node, "mesh", &at)? else {
            continue;
        };
        let mirrored = det3(&world) < 0.0;
        let mesh = glb.item("meshes", m)?;
        let prims = mesh
            .get("primitives")
            .and_then(Value::as_array)
            .ok_or_else(|| bad(format!("meshes[{m}].primitives must be an array")))?;
        primitive_visits = primitive_visits.saturating_add(prims.len());
        if primitive_visits > MAX_PRIMITIVE_VISITS {
            return Err(bad(format!(
                "the scene visits more than {MAX_PRIMITIVE_VISITS} mesh primitives"
            )));
        }
        for (pi, p) in prims.iter().enumerate() {
            let pat = format!("meshes[{m}].primitives[{pi}]");
            let mode = p.get("mode").and_then(Value::as_u64).unwrap_or(4);
            if !(4..=6).contains(&mode) {
                continue;
            }
            let pos_at = p
                .get("attributes")
                .and_then(|a| a.get("POSITION"))
                .and_then(Value::as_u64)
                .ok_or_else(|| bad(format!("{pat} has no POSITION attribute")))?;
            let pos = glb.positions(pos_at as usize)?;
            let idx = match index_of(p, "indices", &pat)? {
                Some(i) => glb.indices(i)?,
                None => (0..pos.len() as u32).collect(),
            };
            let tris = assemble(mode, &idx);
            if out.len() + tris.len() > max_triangles {
                return Err(bad(format!(
                    "the glb has more than {max_triangles} triangles (the element's remaining budget)"
                )));
            }
            let world_pos: Vec<[f32; 3]> = pos.iter().map(|&q| apply(&world, q)).collect();
            for t in tris {
                let v = t.map(|i| world_pos.get(i as usize).copied());
                let [Some(a), Some(b), Some(c)] = v else {
                    return Err(bad(format!(
                        "{pat}: an index is beyond the {} positions",
                        pos.len()
                    )));
                };
                if [a, b, c].iter().flatten().any(|x| !x.is_finite()) {
                    return Err(bad(format!("{pat}: a transformed position is not finite")));
                }
                out.push(if mirrored { [a, c, b] } else { [a, b, c] });
            }
        }
    }
    Ok(out)
}

/// A minimal glb holding `triangles` as one non-indexed triangle primitive under one node with
/// the local `matrix` (tests and tools build inputs with it).
pub fn triangles_to_glb(triangles: &[[[f32; 3]; 3]], matrix: Option<&Mat4>) -> Vec<u8> {
    let mut bin: Vec<u8> = Vec::with_capacity(36 * triangles.len());
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for p in triangles.iter().flatten() {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
            bin.extend_from_slice(&p[k].to_le_bytes());
        }
    }
    let mut node = serde_json::json!({ "mesh": 0 });
    if let Some(m) = matrix {
        node["matrix"] = serde_json::json!(m.map(f64::from));
    }
    let doc = serde_json::json!({
        "asset": { "version": "2.0", "generator": "strata" },
        "scene": 0,
        "scenes": [{ "nodes": [0] }],
        "nodes": [node],
        "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "mode": 4 }] }],
        "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 3 * triangles.len(),
                        "type": "VEC3", "min": lo.map(f64::from), "max": hi.map(f64::from) }],
        "bufferViews": [{ "buffer": 0, "byteOffset": 0, "byteLength": bin.len() }],
        "buffers": [{ "byteLength": bin.len() }],
    });
    write_glb(&doc, &bin)
}

/// Frames a JSON document and a binary chunk as a glb ([`crate::glb::container`]).
pub use crate::glb::container as write_glb;

#[cfg(test)]
mod tests {
    use super::*;

    const TRI: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];

    #[test]
    fn round_trip_with_node_and_element_transforms() {
        let glb = triangles_to_glb(&[TRI], None);
        assert_eq!(glb_triangles(&glb, None, 10).expect("read"), vec![TRI]);
        // Node: translate by (10, 0, 0); element: scale by 2 → (20 + 2x, 2y, 2z).
        let mut node = IDENTITY;
        node[12] = 10.0;
        let mut el = IDENTITY;
        el[0] = 2.0;
        el[5] = 2.0;
        el[10] = 2.0;
        let glb = triangles_to_glb(&[TRI], Some(&node));
        let got = glb_triangles(&glb, Some(&el), 10).expect("read");
        assert_eq!(
            got,
            vec![[[20.0, 0.0, 0.0], [22.0, 0.0, 0.0], [20.0, 2.0, 0.0]]]
        );
        // The mirror z → −z keeps this triangle's positions (it lies in z = 0) but reverses its
        // winding, so the front face stays the mirrored front face.
        let mut mirror = IDENTITY;
        mirror[10] = -1.0;
        let got = glb_triangles(&glb_plain(), Some(&mirror), 10).expect("read");
        assert_eq!(got, vec![[TRI[0], TRI[2], TRI[1]]]);
    }

    fn glb_plain() -> Vec<u8> {
        triangles_to_glb(&[TRI], None)
    }

    #[test]
    fn strips_fans_and_limits() {
        assert_eq!(assemble(5, &[0, 1, 2, 3]), vec![[0, 1, 2], [2, 1, 3]]);
        assert_eq!(assemble(6, &[0, 1, 2, 3]), vec![[0, 1, 2], [0, 2, 3]]);
        assert!(assemble(1, &[0, 1, 2, 3]).is_empty());
        let glb = triangles_to_glb(&[TRI, TRI, TRI], None);
        let e = glb_triangles(&glb, None, 2).expect_err("budget");
        assert!(e.0.contains("more than 2"), "{e}");
        assert!(glb_triangles(b"not a glb at all", None, 10).is_err());
        let mut short = glb.clone();
        short.truncate(glb.len() - 8);
        assert!(glb_triangles(&short, None, 10).is_err());
        let mut singular = IDENTITY;
        singular[0] = 0.0;
        assert!(glb_triangles(&glb, Some(&singular), 10).is_err());
        assert!(glb_triangles(&vec![0u8; MAX_GLB_BYTES + 1], None, 10).is_err());
    }
}
