//! Wire formats of the products.
//!
//! Every encoder is a pure function of `(plan, tile)`: the same tile gives the same bytes on every
//! node and every day, so a blake3 hash of the bytes is a valid HTTP `ETag`. The plan supplies the
//! seed and the names of biomes and materials, which a [`Tile`] does not carry.
//!
//! | format | module | content type | layout |
//! |---|---|---|---|
//! | `json` | [`json`] | `application/json` | `strata.tile.v1` object |
//! | `bin` | [`bin`] | `application/vnd.strata.tile.v1` | little-endian `STRT` v1 |
//! | `png` | [`heightmap`] | `image/png` | 16-bit greyscale 65×65 |
//! | `glb` | [`glb`] | `model/gltf-binary` | glTF 2.0 binary with skirts |
//!
//! plus [`scatter`] (JSON) for the scatter product. The normative description of all of them is
//! `api/tile_format_v1.md`.

pub mod bin;
pub mod chunk;
pub mod chunk_glb;
pub mod glb;
pub mod heightmap;
pub mod json;
pub mod region_glb;
pub mod scatter;

use crate::terrain::Tile;

/// Format identifier in the JSON products.
pub const TILE_FORMAT: &str = "strata.tile.v1";

/// A tile wire format, named by the URL extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// `strata.tile.v1` JSON ([`json`]).
    Json,
    /// `STRT` v1 little-endian binary ([`bin`]).
    Bin,
    /// 16-bit greyscale PNG heightmap ([`heightmap`]).
    Png,
    /// glTF 2.0 binary mesh with skirts ([`glb`]).
    Glb,
}

impl Format {
    /// All formats, in the order `/v1/info` lists them.
    pub const ALL: [Format; 4] = [Format::Json, Format::Bin, Format::Png, Format::Glb];

    /// Parses a URL extension (case-sensitive, lower case).
    pub fn from_extension(ext: &str) -> Option<Self> {
        match ext {
            "json" => Some(Self::Json),
            "bin" => Some(Self::Bin),
            "png" => Some(Self::Png),
            "glb" => Some(Self::Glb),
            _ => None,
        }
    }

    /// The URL extension.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Json => "json",
            Self::Bin => "bin",
            Self::Png => "png",
            Self::Glb => "glb",
        }
    }

    /// The `Content-Type` of responses in this format.
    pub fn content_type(self) -> &'static str {
        match self {
            Self::Json => "application/json",
            Self::Bin => "application/vnd.strata.tile.v1",
            Self::Png => "image/png",
            Self::Glb => "model/gltf-binary",
        }
    }
}

/// Lowest and highest height of a tile, metres (NaNs ignored; `(0, 0)` if there are none).
pub fn height_range(tile: &Tile) -> (f32, f32) {
    let mut lo = f32::INFINITY;
    let mut hi = f32::NEG_INFINITY;
    for &h in tile.heights.iter().filter(|h| h.is_finite()) {
        lo = lo.min(h);
        hi = hi.max(h);
    }
    if lo > hi {
        (0.0, 0.0)
    } else {
        (lo, hi)
    }
}

#[cfg(test)]
pub(crate) mod test_util {
    use crate::terrain::{synthesize, Tile, TileKey, WorldParams, WorldPlan};
    use std::sync::OnceLock;

    /// The default world of seed 7, built once per test binary.
    pub fn plan() -> &'static WorldPlan {
        static PLAN: OnceLock<WorldPlan> = OnceLock::new();
        PLAN.get_or_init(|| {
            WorldPlan::new(7, WorldParams::default()).expect("default params are valid")
        })
    }

    /// A CPU tile of the default world of seed 7.
    pub fn tile(lod: u32, x: i64, z: i64) -> Tile {
        synthesize(plan(), TileKey { lod, x, z })
    }
}
