//! Frames of kind 3 (protocol v2): Ptex pages of a stream session's faces, one detail level a
//! frame (`api/stream_protocol_v2.md`, "Ptex pages"). Little-endian.
//!
//! The 44-byte header of the other frames with `lod` = the level (0 vista … 5), `x` = the pages'
//! resolution, `z` = the page count, then the world version, the faces' kind (`u32`: 0 height-tile
//! faces, 1 volume-chunk faces) and the payload length. The payload: one 48-byte record per page
//! — a tile face's: face LOD `u32`, slot `u32`, face column `fx` `i64`, face row `fz` `i64`, the
//! tile's seam flags `u32`, the face's bounding sphere as centre x, y, z and radius `f32` metres,
//! `u32` 0; a chunk face's the same with the chunk's LOD, `x` and `z` for the face's, the chunk's
//! `y` (`i32`) for the seam flags and the quad's index (`u32`) for the last 0 — then each page's
//! three planes in the layout of
//! `api/ptex_pages_v1.md` (albedo `S²×4`, normal `S²×4`, displacement `S²` `f32`,
//! `S = res + 2`).

use super::protocol::{format_code, FRAME_HEADER_BYTES, FRAME_MAGIC, FRAME_VERSION};
use crate::encode::Format;
use crate::ptex::budget::FaceBounds;
use crate::ptex::face::{ChunkFaceKey, TileFaceKey};
use crate::volume::chunk::ChunkKey;

use super::ptex::PageFace;
use crate::ptex::Pages;

/// Frame kind of Ptex pages.
pub const KIND_PTEX: u8 = 3;
/// Bytes of a page record.
pub const PAGE_RECORD_BYTES: usize = 48;
/// The faces' kind at header offset 36: height-tile faces.
pub const FACES_TILE: u32 = 0;
/// The faces' kind at header offset 36: volume-chunk faces.
pub const FACES_CHUNK: u32 = 1;

/// One page of a frame: which face, which slot of its level's texture array.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PageRecord {
    /// The face: a height tile's or a volume chunk's (a frame holds one kind).
    pub face: PageFace,
    /// A tile face's seam flags `n, e, s, w` (bit `i` for flag `i`) the page was baked with (0
    /// for a chunk face).
    pub seams: u8,
    /// Layer in the level's texture array.
    pub slot: u32,
    /// The face's bounding sphere (what the budget classifies it by).
    pub bounds: FaceBounds,
}

/// A decoded Ptex frame (the client side, for tests and tools).
#[derive(Clone, Debug, PartialEq)]
pub struct PtexFrame {
    /// Detail level, 0 (vista) … 5.
    pub level: u8,
    /// World version the pages are of.
    pub version: u64,
    /// The pages' records.
    pub records: Vec<PageRecord>,
    /// The pages' texels, face `k` being `records[k]`.
    pub pages: Pages,
}

/// Bytes of a frame of `count` pages of resolution `res`.
pub fn frame_bytes(res: u32, count: usize) -> usize {
    let s = res as usize + 2;
    FRAME_HEADER_BYTES + count * (PAGE_RECORD_BYTES + s * s * 12)
}

/// The frame of `pages` (face `k` being `records[k]`) at `level` of world `version`.
pub fn encode(level: u8, version: u64, records: &[PageRecord], pages: &Pages) -> Vec<u8> {
    let count = records.len().min(pages.faces);
    let mut out = Vec::with_capacity(frame_bytes(pages.res, count));
    out.extend_from_slice(FRAME_MAGIC);
    out.extend_from_slice(&FRAME_VERSION.to_le_bytes());
    out.push(KIND_PTEX);
    out.push(format_code(Format::Bin));
    out.extend_from_slice(&u32::from(level).to_le_bytes());
    out.extend_from_slice(&i64::from(pages.res).to_le_bytes());
    out.extend_from_slice(&(count as i64).to_le_bytes());
    out.extend_from_slice(&version.to_le_bytes());
    let chunk = records.first().is_some_and(|r| r.face.is_chunk());
    let kind = if chunk { FACES_CHUNK } else { FACES_TILE };
    out.extend_from_slice(&kind.to_le_bytes());
    let payload = frame_bytes(pages.res, count) - FRAME_HEADER_BYTES;
    out.extend_from_slice(&(payload as u32).to_le_bytes());
    for r in &records[..count] {
        match r.face {
            PageFace::Tile(f) => {
                out.extend_from_slice(&f.lod.to_le_bytes());
                out.extend_from_slice(&r.slot.to_le_bytes());
                out.extend_from_slice(&f.fx.to_le_bytes());
                out.extend_from_slice(&f.fz.to_le_bytes());
                out.extend_from_slice(&u32::from(r.seams).to_le_bytes());
            }
            PageFace::Chunk(f) => {
                let c = f.chunk;
                out.extend_from_slice(&c.lod.to_le_bytes());
                out.extend_from_slice(&r.slot.to_le_bytes());
                out.extend_from_slice(&c.x.to_le_bytes());
                out.extend_from_slice(&c.z.to_le_bytes());
                // Chunk y is within ±511 (api/chunk_format_v1.md): an i32 holds it.
                out.extend_from_slice(&(c.y as i32).to_le_bytes());
            }
        }
        for v in r.bounds.centre.iter().chain([&r.bounds.radius]) {
            out.extend_from_slice(&v.to_le_bytes());
        }
        let last = match r.face {
            PageFace::Tile(_) => 0,
            PageFace::Chunk(f) => f.quad,
        };
        out.extend_from_slice(&last.to_le_bytes());
    }
    let per = pages.texels_per_face();
    for k in 0..count {
        let texels = k * per..(k + 1) * per;
        for a in &pages.albedo[texels.clone()] {
            out.extend_from_slice(a);
        }
        for n in &pages.normal[texels.clone()] {
            out.extend_from_slice(n);
        }
        for d in &pages.displacement[texels] {
            out.extend_from_slice(&d.to_le_bytes());
        }
    }
    out
}

/// Parses a Ptex frame; `None` for another kind or a malformed frame.
pub fn decode(bytes: &[u8]) -> Option<PtexFrame> {
    if bytes.len() < FRAME_HEADER_BYTES || &bytes[..4] != FRAME_MAGIC || bytes[6] != KIND_PTEX {
        return None;
    }
    let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().unwrap_or_default());
    let i64_at = |o: usize| i64::from_le_bytes(bytes[o..o + 8].try_into().unwrap_or_default());
    let f32_at = |o: usize| f32::from_bits(u32_at(o));
    let level = u8::try_from(u32_at(8)).ok()?;
    let res = u32::try_from(i64_at(12))
        .ok()
        .filter(|r| crate::ptex::valid_res(*r))?;
    let count = usize::try_from(i64_at(20)).ok()?;
    if count > bytes.len() || bytes.len() != frame_bytes(res, count) {
        return None;
    }
    let version = i64_at(28) as u64;
    let chunk = match u32_at(36) {
        FACES_TILE => false,
        FACES_CHUNK => true,
        _ => return None,
    };
    let mut records = Vec::with_capacity(count);
    for k in 0..count {
        let o = FRAME_HEADER_BYTES + k * PAGE_RECORD_BYTES;
        let face = if chunk {
            PageFace::Chunk(ChunkFaceKey {
                chunk: ChunkKey {
                    lod: u32_at(o),
                    x: i64_at(o + 8),
                    y: i64::from(u32_at(o + 24) as i32),
                    z: i64_at(o + 16),
                },
                quad: u32_at(o + 44),
            })
        } else {
            PageFace::Tile(TileFaceKey {
                lod: u32_at(o),
                fx: i64_at(o + 8),
                fz: i64_at(o + 16),
            })
        };
        records.push(PageRecord {
            face,
            slot: u32_at(o + 4),
            seams: if chunk { 0 } else { u32_at(o + 24) as u8 },
            bounds: FaceBounds {
                centre: [f32_at(o + 28), f32_at(o + 32), f32_at(o + 36)],
                radius: f32_at(o + 40),
            },
        });
    }
    let mut pages = Pages::default();
    pages.reset(res, count);
    let per = pages.texels_per_face();
    let mut o = FRAME_HEADER_BYTES + count * PAGE_RECORD_BYTES;
    for k in 0..count {
        for t in k * per..(k + 1) * per {
            pages.albedo[t].copy_from_slice(&bytes[o..o + 4]);
            o += 4;
        }
        for t in k * per..(k + 1) * per {
            pages.normal[t].copy_from_slice(&bytes[o..o + 4]);
            o += 4;
        }
        for t in k * per..(k + 1) * per {
            pages.displacement[t] = f32::from_le_bytes(bytes[o..o + 4].try_into().ok()?);
            o += 4;
        }
    }
    Some(PtexFrame {
        level,
        version,
        records,
        pages,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_decodes_to_what_was_encoded() {
        let mut pages = Pages::default();
        pages.reset(8, 2);
        for (i, a) in pages.albedo.iter_mut().enumerate() {
            *a = [i as u8, 1, 2, 3];
        }
        pages.displacement[7] = -1.5;
        let records = [
            PageRecord {
                face: PageFace::Tile(TileFaceKey {
                    lod: 1,
                    fx: -3,
                    fz: 9,
                }),
                seams: 0b0101,
                slot: 4,
                bounds: FaceBounds {
                    centre: [1.0, -2.5, 3.0],
                    radius: 11.5,
                },
            },
            PageRecord {
                face: PageFace::Tile(TileFaceKey {
                    lod: 0,
                    fx: 2,
                    fz: -1,
                }),
                seams: 0,
                slot: 0,
                bounds: FaceBounds {
                    centre: [0.0; 3],
                    radius: 1.0,
                },
            },
        ];
        let bytes = encode(0, 7, &records, &pages);
        assert_eq!(bytes.len(), frame_bytes(8, 2));
        let back = decode(&bytes).expect("a frame");
        assert_eq!((back.level, back.version), (0, 7));
        assert_eq!(back.records, records);
        assert_eq!(back.pages, pages);
        assert!(decode(&bytes[..bytes.len() - 1]).is_none());
        assert_eq!(
            u32::from_le_bytes(bytes[36..40].try_into().expect("4 bytes")),
            FACES_TILE
        );
    }

    #[test]
    fn a_frame_of_chunk_faces_names_them_and_decodes_to_what_was_encoded() {
        let mut pages = Pages::default();
        pages.reset(16, 2);
        for (i, a) in pages.albedo.iter_mut().enumerate() {
            *a = [3, i as u8, 2, 1];
        }
        let face = |y, quad| {
            PageFace::Chunk(ChunkFaceKey {
                chunk: ChunkKey {
                    lod: 2,
                    x: -7,
                    y,
                    z: 40,
                },
                quad,
            })
        };
        let bounds = FaceBounds {
            centre: [4.0, -1.0, 2.5],
            radius: 0.75,
        };
        let records = [
            PageRecord {
                face: face(-511, 1234),
                seams: 0,
                slot: 9,
                bounds,
            },
            PageRecord {
                face: face(63, 0),
                seams: 0,
                slot: 10,
                bounds,
            },
        ];
        let bytes = encode(1, 3, &records, &pages);
        assert_eq!(
            u32::from_le_bytes(bytes[36..40].try_into().expect("4 bytes")),
            FACES_CHUNK
        );
        let back = decode(&bytes).expect("a frame");
        assert_eq!((back.level, back.version), (1, 3));
        assert_eq!(back.records, records);
        assert_eq!(back.pages, pages);
        // An unknown kind of faces is not a frame this reader knows.
        let mut other = bytes.clone();
        other[36] = 2;
        assert!(decode(&other).is_none());
    }
}
