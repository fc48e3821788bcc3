//! The Ptex pages pack (`api/ptex_pages_v1.md`): header, face table, then the albedo, normal and
//! displacement planes of [`crate::ptex::Pages`]. Little-endian.

use crate::ptex::face::NO_FACE;
use crate::ptex::{FaceSet, Pages, Span};

/// `Content-Type` of the pack.
pub const CONTENT_TYPE: &str = "application/vnd.strata.ptex.v1";
/// Magic bytes.
pub const MAGIC: &[u8; 4] = b"STPX";
/// Header bytes.
pub const HEADER_BYTES: usize = 64;
/// Face-table bytes per face.
pub const FACE_BYTES: usize = 40;
/// Neighbour value of a face in another pack.
pub const OTHER_PACK: u32 = 0xFFFF_FFFE;
/// Neighbour value of no face.
pub const NO_NEIGHBOUR: u32 = 0xFFFF_FFFF;

/// What the faces of a pack belong to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PackKind {
    /// A volume chunk's quads.
    Chunk = 0,
    /// A height tile's 4 × 4 faces.
    Tile = 1,
}

/// The header fields besides the pages' own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PackInfo {
    /// Chunk or tile.
    pub kind: PackKind,
    /// Level of detail.
    pub lod: u32,
    /// Key `x, y, z` (`y = 0` for tiles).
    pub key: [i64; 3],
    /// World seed.
    pub seed: u64,
}

/// Encodes the output faces of `set` (their baked `pages`, borders filled) with their `classes`
/// (one per output face).
pub fn encode(info: &PackInfo, set: &FaceSet, classes: &[u8], pages: &Pages) -> Vec<u8> {
    let f = pages.faces;
    let per = pages.texels_per_face();
    let mut out = Vec::with_capacity(HEADER_BYTES + f * (FACE_BYTES + 12 * per));
    out.extend_from_slice(MAGIC);
    for v in [1u32, info.kind as u32, info.lod] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in info.key {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&info.seed.to_le_bytes());
    for v in [pages.res, f as u32, pages.side() as u32, 0] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for (id, links) in set.links.iter().take(f).enumerate() {
        out.extend_from_slice(&(id as u32).to_le_bytes());
        out.extend_from_slice(&[classes.get(id).copied().unwrap_or(2), 0, 0, 0]);
        for l in links {
            let (n, rest) = if l.face == NO_FACE {
                (NO_NEIGHBOUR, [255, 255, 255, 0])
            } else {
                let span = match l.span {
                    Span::Whole => 0,
                    Span::FirstHalf => 1,
                    Span::SecondHalf => 2,
                };
                let n = if (l.face as usize) < f {
                    l.face
                } else {
                    OTHER_PACK
                };
                (n, [l.edge, l.transform, span, 0])
            };
            out.extend_from_slice(&n.to_le_bytes());
            out.extend_from_slice(&rest);
        }
    }
    for t in &pages.albedo {
        out.extend_from_slice(t);
    }
    for t in &pages.normal {
        out.extend_from_slice(t);
    }
    for d in &pages.displacement {
        out.extend_from_slice(&d.to_le_bytes());
    }
    out
}
