//! The glTF 2.0 binary container (`.glb`): a 12-byte header, a JSON chunk and an optional BIN
//! chunk, every field little-endian. The one framing every glb writer uses (`encode`'s tiles,
//! chunks and region meshes, `volume::mesh_import`'s test meshes) and the constants its reader
//! (`volume::mesh_import`) checks. It sits at the bottom of the layers because both `volume`,
//! which reads glb input meshes, and `encode`, above it, frame glb files.

/// Magic of a glb header, `"glTF"` little-endian.
pub const GLB_MAGIC: u32 = 0x4654_6C67;
/// Type of the JSON chunk, `"JSON"`.
pub const CHUNK_JSON: u32 = 0x4E4F_534A;
/// Type of the binary chunk, `"BIN\0"`.
pub const CHUNK_BIN: u32 = 0x004E_4942;

/// Frames a glTF JSON document and its binary buffer as a glb (glTF 2.0 binary container,
/// every field little-endian): the header, the JSON chunk padded to 4 bytes with spaces, and
/// the BIN chunk padded with zeros (omitted when `bin` is empty).
pub fn container(doc: &serde_json::Value, bin: &[u8]) -> Vec<u8> {
    let mut json = serde_json::to_vec(doc).unwrap_or_default();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let pad = bin.len().next_multiple_of(4) - bin.len();
    let bin_len = if bin.is_empty() {
        0
    } else {
        8 + bin.len() + pad
    };
    let total = 12 + 8 + json.len() + bin_len;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(&GLB_MAGIC.to_le_bytes());
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(&CHUNK_JSON.to_le_bytes());
    out.extend_from_slice(&json);
    if !bin.is_empty() {
        out.extend_from_slice(&((bin.len() + pad) as u32).to_le_bytes());
        out.extend_from_slice(&CHUNK_BIN.to_le_bytes());
        out.extend_from_slice(bin);
        out.resize(out.len() + pad, 0);
    }
    out
}
