//! The `strata.rivers.v1` JSON of a tile's river lines (`api/rivers_v1.md`): the centre lines of
//! the rivers that reach into the tile, from upstream to downstream, as
//! [`crate::terrain::earth::tile_rivers`] gives them.

use crate::terrain::earth::rivers::RiverLine;
use crate::terrain::TileKey;
use serde::Serialize;

/// Format identifier of the river lines.
pub const RIVERS_FORMAT: &str = "strata.rivers.v1";

/// The document; field order is the serialisation order.
#[derive(Serialize)]
struct RiversJson<'a> {
    /// Always [`RIVERS_FORMAT`].
    format: &'static str,
    /// Level of detail of the tile.
    lod: u32,
    /// Tile column.
    x: i64,
    /// Tile row.
    z: i64,
    /// Vertex spacing of the tile, metres (it spans 64 spacings).
    spacing_m: f32,
    /// The lines.
    lines: &'a [RiverLine],
}

/// Encodes the river lines of tile `key` (vertex spacing `spacing_m`).
pub fn encode(key: TileKey, spacing_m: f32, lines: &[RiverLine]) -> Vec<u8> {
    let doc = RiversJson {
        format: RIVERS_FORMAT,
        lod: key.lod,
        x: key.x,
        z: key.z,
        spacing_m,
        lines,
    };
    // Plain structs of finite numbers and strings serialise into a Vec without failing.
    serde_json::to_vec(&doc).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::earth::rivers::LineEnd;

    #[test]
    fn fields_in_order() {
        let line = RiverLine {
            points: vec![[1.0, 2.0, 30.0], [3.0, 4.0, 29.5]],
            width_m: vec![4.0, 4.5],
            discharge_m3s: vec![0.5, 0.6],
            from: [0, 1],
            to: [1, 1],
            ends: LineEnd::Continues,
        };
        let key = TileKey {
            lod: 6,
            x: -1,
            z: 2,
        };
        let text = String::from_utf8(encode(key, 64.0, &[line])).expect("UTF-8");
        assert_eq!(
            text,
            r#"{"format":"strata.rivers.v1","lod":6,"x":-1,"z":2,"spacing_m":64.0,"lines":[{"points":[[1.0,2.0,30.0],[3.0,4.0,29.5]],"width_m":[4.0,4.5],"discharge_m3s":[0.5,0.6],"from":[0,1],"to":[1,1],"ends":"continues"}]}"#
        );
        let empty = String::from_utf8(encode(key, 64.0, &[])).expect("UTF-8");
        assert!(empty.ends_with(r#""lines":[]}"#), "{empty}");
    }
}
