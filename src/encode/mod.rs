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
//! plus [`scatter`] (JSON) for the scatter product and [`rivers`] (JSON) for a tile's river
//! lines. The normative description of the tile formats is `api/tile_format_v1.md`; `json` and
//! `bin` also have a [`TileVersion::V2`] (`?format=2`, `api/tile_format_v2.md`) that adds each
//! vertex's water surface height and water kind ([`water`]). The river lines are specified in
//! `api/rivers_v1.md`. [`ptex`] writes the Ptex pages of `api/ptex_pages_v1.md` and [`ptx`]
//! Disney's Ptex file format.

pub mod bin;
pub mod chunk;
pub mod chunk_glb;
pub mod glb;
pub mod heightmap;
pub mod json;
pub mod ptex;
pub mod ptx;
pub mod region_glb;
pub mod rivers;
pub mod scatter;
pub mod water;
pub mod water_glb;

use crate::terrain::Tile;

/// Format identifier in the JSON products.
pub const TILE_FORMAT: &str = "strata.tile.v1";
/// Format identifier of the version 2 JSON tile.
pub const TILE_FORMAT_V2: &str = "strata.tile.v2";
/// `Content-Type` of the version 2 binary tile.
pub const BIN_V2_CONTENT_TYPE: &str = "application/vnd.strata.tile.v2";

/// A version of the tile encodings `json` and `bin` (the `?format=` query parameter); `png` and
/// `glb` have version 1 only.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum TileVersion {
    /// `strata.tile.v1` and `STRT` v1 (`api/tile_format_v1.md`), the default.
    #[default]
    V1,
    /// `strata.tile.v2` and `STRT` v2 (`api/tile_format_v2.md`): v1 plus the water surface
    /// height and the water kind of every vertex.
    V2,
}

impl TileVersion {
    /// All versions, oldest first.
    pub const ALL: [TileVersion; 2] = [TileVersion::V1, TileVersion::V2];

    /// The version's number (`1` or `2`), as in `?format=` and the binary header.
    pub fn number(self) -> u16 {
        match self {
            Self::V1 => 1,
            Self::V2 => 2,
        }
    }

    /// Whether `format` exists in this version (version 2 is defined for `json` and `bin`).
    pub fn has(self, format: Format) -> bool {
        self == Self::V1 || matches!(format, Format::Json | Format::Bin)
    }

    /// The `Content-Type` of `format` in this version.
    pub fn content_type(self, format: Format) -> &'static str {
        match (self, format) {
            (Self::V2, Format::Bin) => BIN_V2_CONTENT_TYPE,
            _ => format.content_type(),
        }
    }

    /// A short name of `format` in this version, unique among the pairs that exist (`bin`,
    /// `bin.v2`, …; see [`TileVersion::has`]): the body cache's key.
    pub fn tag(self, format: Format) -> &'static str {
        match (self, format) {
            (Self::V2, Format::Json) => "json.v2",
            (Self::V2, Format::Bin) => "bin.v2",
            _ => format.extension(),
        }
    }
}

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

/// A tile encoded in one format of one version ([`tile`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EncodedTile {
    /// The bytes.
    pub body: Vec<u8>,
    /// Their `Content-Type`.
    pub content_type: &'static str,
    /// How a PNG's 16-bit samples map to metres (`png` only).
    pub png_mapping: Option<heightmap::HeightMapping>,
}

/// Why a tile could not be encoded.
#[derive(Debug, thiserror::Error)]
pub enum EncodeError {
    /// The PNG encoder failed.
    #[error("PNG encoding failed: {0}")]
    Png(#[from] png::EncodingError),
}

/// Encodes `tile` (of the world `plan`) in `format` of `version`: the one dispatch of the tile
/// formats, used by the tile routes, the stream and export archives. `png` and `glb` have
/// version 1 only, which they give for any `version` (the routes refuse version 2 of them).
pub fn tile(
    plan: &crate::terrain::WorldPlan,
    tile: &Tile,
    format: Format,
    version: TileVersion,
) -> Result<EncodedTile, EncodeError> {
    let mut png_mapping = None;
    let body = match format {
        Format::Json => json::encode_version(plan, tile, version),
        Format::Bin => bin::encode_version(plan, tile, version),
        Format::Glb => glb::encode(plan, tile),
        Format::Png => {
            let png = heightmap::encode(plan, tile)?;
            png_mapping = Some(png.mapping);
            png.bytes
        }
    };
    Ok(EncodedTile {
        body,
        content_type: version.content_type(format),
        png_mapping,
    })
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
