//! The disk form of a tile ([`encode_tile`], [`decode_tile`]): what the disk tier writes. The
//! bytes are pinned by tests; a change needs a new [`DISK_FORMAT_VERSION`].

use super::InputHash;
use crate::terrain::plan::{MAX_LOD, TILE_VERTEX_COUNT};
use crate::terrain::world::MAX_BIOMES;
use crate::terrain::{Tile, TileKey};

/// Version of the disk file layout.
pub const DISK_FORMAT_VERSION: u32 = 3;
/// Magic at the start of a disk cache file.
pub const DISK_MAGIC: [u8; 4] = *b"STRC";

/// Header: magic, format version, hash, lod, x, z, spacing, biome count, skirt depth.
const HEADER_LEN: usize = 4 + 4 + 32 + 4 + 8 + 8 + 4 + 4 + 4;

/// The disk form of a tile: the header, then heights, normals (x, y, z), weights, materials,
/// water depth, a byte saying whether the volume-override marks follow and the marks (one byte
/// per vertex), a byte saying whether the water kinds follow and the kinds (one byte per vertex),
/// all little-endian, then blake3 of everything before it.
pub fn encode_tile(hash: &InputHash, t: &Tile) -> Vec<u8> {
    let n = t.heights.len();
    let mut out = Vec::with_capacity(HEADER_LEN + n * (4 + 12 + 1 + 4) + t.weights.len() * 4 + 32);
    out.extend_from_slice(&DISK_MAGIC);
    out.extend_from_slice(&DISK_FORMAT_VERSION.to_le_bytes());
    out.extend_from_slice(hash);
    out.extend_from_slice(&t.key.lod.to_le_bytes());
    out.extend_from_slice(&t.key.x.to_le_bytes());
    out.extend_from_slice(&t.key.z.to_le_bytes());
    out.extend_from_slice(&t.spacing_m.to_le_bytes());
    out.extend_from_slice(&(t.biome_count as u32).to_le_bytes());
    out.extend_from_slice(&t.skirt_depth_m.to_le_bytes());
    for v in &t.heights {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in t.normals.iter().flatten() {
        out.extend_from_slice(&v.to_le_bytes());
    }
    for v in &t.weights {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&t.materials);
    for v in &t.water_depth {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.push(u8::from(!t.volume_override.is_empty()));
    out.extend_from_slice(&t.volume_override);
    out.push(u8::from(!t.water_kind.is_empty()));
    out.extend_from_slice(&t.water_kind);
    let sum = blake3::hash(&out);
    out.extend_from_slice(sum.as_bytes());
    out
}

struct Reader<'a> {
    bytes: &'a [u8],
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let (head, rest) = self.bytes.split_at(N);
        self.bytes = rest;
        head.try_into().unwrap_or([0; N])
    }

    fn f32s(&mut self, n: usize) -> Vec<f32> {
        (0..n).map(|_| f32::from_le_bytes(self.take())).collect()
    }
}

/// Parses [`encode_tile`]'s output, checking the checksum, the hash and every length.
pub fn decode_tile(bytes: &[u8], hash: &InputHash) -> Result<Tile, String> {
    if bytes.len() < HEADER_LEN + 32 {
        return Err(format!("{} bytes is too short", bytes.len()));
    }
    let (body, sum) = bytes.split_at(bytes.len() - 32);
    if blake3::hash(body).as_bytes() != sum {
        return Err("checksum mismatch".into());
    }
    let mut r = Reader { bytes: body };
    if r.take::<4>() != DISK_MAGIC {
        return Err("not a strata cache file".into());
    }
    let version = u32::from_le_bytes(r.take());
    if version != DISK_FORMAT_VERSION {
        return Err(format!("format version {version}"));
    }
    if &r.take::<32>() != hash {
        return Err("the file holds another hash".into());
    }
    let lod = u32::from_le_bytes(r.take());
    let x = i64::from_le_bytes(r.take());
    let z = i64::from_le_bytes(r.take());
    let spacing_m = f32::from_le_bytes(r.take());
    let k = u32::from_le_bytes(r.take()) as usize;
    let skirt_depth_m = f32::from_le_bytes(r.take());
    if lod > MAX_LOD || k == 0 || k > MAX_BIOMES {
        return Err(format!("lod {lod} or biome count {k} out of range"));
    }
    let n = TILE_VERTEX_COUNT;
    let fixed = n * (4 + 12 + 4 * k + 1 + 4) + 2;
    if ![fixed, fixed + n, fixed + 2 * n].contains(&r.bytes.len()) {
        return Err(format!("{} payload bytes for {k} biomes", r.bytes.len()));
    }
    let heights = r.f32s(n);
    let normals = r
        .f32s(3 * n)
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    let weights = r.f32s(n * k);
    let materials = r.bytes[..n].to_vec();
    r.bytes = &r.bytes[n..];
    let water_depth = r.f32s(n);
    let optional = |r: &mut Reader| -> Result<Vec<u8>, String> {
        if r.take::<1>()[0] != 1 {
            return Ok(Vec::new());
        }
        if r.bytes.len() < n {
            return Err("a section is cut short".into());
        }
        let (head, rest) = r.bytes.split_at(n);
        r.bytes = rest;
        Ok(head.to_vec())
    };
    let volume_override = optional(&mut r)?;
    if r.bytes.is_empty() {
        return Err("the water-kind flag is missing".into());
    }
    let water_kind = optional(&mut r)?;
    if !r.bytes.is_empty() {
        return Err(format!("{} bytes left over", r.bytes.len()));
    }
    Ok(Tile {
        key: TileKey { lod, x, z },
        spacing_m,
        biome_count: k,
        heights,
        normals,
        weights,
        materials,
        water_depth,
        water_kind,
        skirt_depth_m,
        volume_override,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cache::test_util::{h, tile};

    #[test]
    fn disk_format_round_trips_and_rejects_damage() {
        let t = tile(5);
        let bytes = encode_tile(&h(7), &t);
        assert_eq!(decode_tile(&bytes, &h(7)).expect("decodes"), t);
        assert!(decode_tile(&bytes, &h(8)).is_err(), "other hash");
        let mut bad = bytes.clone();
        bad[100] ^= 1;
        assert!(decode_tile(&bad, &h(7)).is_err(), "checksum");
        assert!(decode_tile(&bytes[..bytes.len() - 1], &h(7)).is_err());
        assert!(decode_tile(&[], &h(7)).is_err());
    }
}
