//! Disney's Ptex file format (`.ptx`), written from the published specification ("Ptex File
//! Format Specification", version 1.3r1, ptex.us): a quad mesh's per-face textures with their
//! adjacency, zlib-compressed, with mip levels, so offline renderers and DCC tools read baked
//! pages.
//!
//! What is written: a quad mesh (`meshtype 1`), `float32` data, no alpha channel, 8 channels in
//! this order — albedo R, G, B (the page bytes over 255, sRGB-encoded as in the pages),
//! roughness (byte over 255), normal x, y, z (signed byte over 127, world space), displacement
//! (metres). Every face has the resolution `res × res` of the pages' interior (no border: Ptex
//! filters across edges through the adjacency). Blocks, little-endian: the 64-byte header, the
//! 40-byte extended header (border modes clamp, no large meta data, no edits), the zipped face
//! info (per face `ulog2, vlog2, adjedges, flags = 0, adjfaces[4]`), the zipped constant data (per
//! face the 1 × 1 level's value per channel, the average), the level info, the levels (level 0 the
//! full resolution, level `L` each face halved `L` times by 2 × 2 box averages, down to 1 × 1;
//! every face in id order, as all have one size), no meta data, the compatibility barrier (a
//! zero `u64`). Each level is a zipped header of `u32` block sizes with encoding 1 (zip) in bits
//! 30–31, then per face its texels with channels separated (each channel's texels `v`-major,
//! `u` fastest, starting at `u = v = 0`), zipped.

use crate::ptex::Pages;
use flate2::write::ZlibEncoder;
use flate2::Compression;
use std::io::Write;

/// Channels written.
pub const CHANNELS: usize = 8;
/// Header bytes.
pub const HEADER_BYTES: u32 = 64;
/// Extended header bytes.
pub const EXT_HEADER_BYTES: u32 = 40;

/// The adjacency of one face: the neighbour across each edge (`−1` for none) and its edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PtxFace {
    /// Face id across edges 0..4, or −1.
    pub adjfaces: [i32; 4],
    /// The neighbour's edge (0..4) across each edge; 0 where there is none.
    pub adjedges: [u8; 4],
}

fn zip(data: &[u8]) -> Vec<u8> {
    let mut z = ZlibEncoder::new(Vec::new(), Compression::default());
    // Writing to a Vec cannot fail.
    let _ = z.write_all(data);
    z.finish().unwrap_or_default()
}

/// The 8 channel values of every interior texel of face `f` (`res²` texels, `u` fastest).
fn level0(pages: &Pages, f: usize) -> Vec<[f32; CHANNELS]> {
    pages
        .interior(f)
        .map(|(a, n, d)| {
            let s = |b: u8| f32::from(b as i8) / 127.0;
            [
                f32::from(a[0]) / 255.0,
                f32::from(a[1]) / 255.0,
                f32::from(a[2]) / 255.0,
                f32::from(a[3]) / 255.0,
                s(n[0]),
                s(n[1]),
                s(n[2]),
                d,
            ]
        })
        .collect()
}

/// A 2 × 2 box reduction of a `side × side` face.
fn reduce(texels: &[[f32; CHANNELS]], side: usize) -> Vec<[f32; CHANNELS]> {
    let h = side / 2;
    let mut out = Vec::with_capacity(h * h);
    for v in 0..h {
        for u in 0..h {
            let at = |du: usize, dv: usize| texels[(2 * v + dv) * side + 2 * u + du];
            let (a, b, c, d) = (at(0, 0), at(1, 0), at(0, 1), at(1, 1));
            out.push(std::array::from_fn(|k| {
                ((a[k] + b[k]) + (c[k] + d[k])) * 0.25
            }));
        }
    }
    out
}

/// A face block: channels separated, little-endian `f32`, zipped.
fn face_block(texels: &[[f32; CHANNELS]]) -> Vec<u8> {
    let mut raw = Vec::with_capacity(texels.len() * CHANNELS * 4);
    for c in 0..CHANNELS {
        for t in texels {
            raw.extend_from_slice(&t[c].to_le_bytes());
        }
    }
    zip(&raw)
}

/// Writes the interior texels of `pages` (faces in id order, `res` a power of two) with the
/// adjacency `faces` (one per page face) as a `.ptx` file.
pub fn write(pages: &Pages, faces: &[PtxFace]) -> Vec<u8> {
    let nfaces = pages.faces;
    let res = pages.res as usize;
    let log2 = pages.res.trailing_zeros() as u8;
    let nlevels = log2 as usize + 1;
    // Every level of every face, finest first.
    let mut levels: Vec<Vec<Vec<[f32; CHANNELS]>>> =
        vec![(0..nfaces).map(|f| level0(pages, f)).collect()];
    for l in 1..nlevels {
        let side = res >> (l - 1);
        let next = levels[l - 1].iter().map(|t| reduce(t, side)).collect();
        levels.push(next);
    }
    let mut info = Vec::with_capacity(nfaces * 20);
    for f in 0..nfaces {
        let face = faces.get(f).copied().unwrap_or(PtxFace {
            adjfaces: [-1; 4],
            adjedges: [0; 4],
        });
        let adjedges = face
            .adjedges
            .iter()
            .enumerate()
            .fold(0u8, |acc, (k, e)| acc | ((e & 3) << (2 * k)));
        info.extend_from_slice(&[log2, log2, adjedges, 0]);
        for a in face.adjfaces {
            info.extend_from_slice(&a.to_le_bytes());
        }
    }
    let info = zip(&info);
    let mut constant = Vec::with_capacity(nfaces * CHANNELS * 4);
    for t in &levels[nlevels - 1] {
        for v in t[0] {
            constant.extend_from_slice(&v.to_le_bytes());
        }
    }
    let constant = zip(&constant);
    let mut level_info = Vec::with_capacity(nlevels * 16);
    let mut level_data = Vec::new();
    for faces_of_level in &levels {
        let blocks: Vec<Vec<u8>> = faces_of_level.iter().map(|t| face_block(t)).collect();
        let mut header = Vec::with_capacity(blocks.len() * 4);
        for b in &blocks {
            header.extend_from_slice(&((b.len() as u32) | (1 << 30)).to_le_bytes());
        }
        let header = zip(&header);
        let size = header.len() + blocks.iter().map(Vec::len).sum::<usize>();
        level_info.extend_from_slice(&(size as u64).to_le_bytes());
        level_info.extend_from_slice(&(header.len() as u32).to_le_bytes());
        level_info.extend_from_slice(&(blocks.len() as u32).to_le_bytes());
        level_data.extend_from_slice(&header);
        for b in &blocks {
            level_data.extend_from_slice(b);
        }
    }
    let mut out = Vec::new();
    out.extend_from_slice(b"Ptex");
    for v in [1u32, 1, 3, u32::MAX] {
        // version, meshtype (quad), datatype (float32), alphachan (none)
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&(CHANNELS as u16).to_le_bytes());
    out.extend_from_slice(&(nlevels as u16).to_le_bytes());
    for v in [
        nfaces as u32,
        EXT_HEADER_BYTES,
        info.len() as u32,
        constant.len() as u32,
        level_info.len() as u32,
        3,
    ] {
        // nfaces, extheader, faceinfo, constdata and levelinfo sizes, minor version
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&(level_data.len() as u64).to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes()); // meta data zipsize
    out.extend_from_slice(&0u32.to_le_bytes()); // meta data memsize
    debug_assert_eq!(out.len(), HEADER_BYTES as usize);
    let end = HEADER_BYTES as u64
        + u64::from(EXT_HEADER_BYTES)
        + (info.len() + constant.len() + level_info.len() + level_data.len()) as u64
        + 8;
    // Extended header: border modes (clamp), large meta data (none), edit data (none, at the end).
    for v in [0u32, 0, 0, 0] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in [0u64, 0, end] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&info);
    out.extend_from_slice(&constant);
    out.extend_from_slice(&level_info);
    out.extend_from_slice(&level_data);
    out.extend_from_slice(&0u64.to_le_bytes()); // compatibility barrier
    debug_assert_eq!(out.len() as u64, end);
    out
}

/// The `.ptx` adjacency of a face set's output faces: links to output faces kept, others none.
pub fn adjacency(set: &crate::ptex::FaceSet) -> Vec<PtxFace> {
    set.links
        .iter()
        .take(set.output)
        .map(|row| {
            let mut f = PtxFace {
                adjfaces: [-1; 4],
                adjedges: [0; 4],
            };
            for (k, l) in row.iter().enumerate() {
                if (l.face as usize) < set.output && l.span == crate::ptex::Span::Whole {
                    f.adjfaces[k] = l.face as i32;
                    f.adjedges[k] = l.edge;
                }
            }
            f
        })
        .collect()
}
