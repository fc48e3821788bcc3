//! Messages and frames of `api/stream_protocol_v1.md` and `api/stream_protocol_v2.md`.
//!
//! Client → server: JSON text messages ([`ClientMessage`]). Server → client: JSON text messages
//! ([`ServerMessage`]) for control, and binary frames with a 44-byte little-endian header
//! followed by the product: tiles ([`TileFrame`]) and, in v2, volume chunks ([`ChunkFrame`]).
//! Version 2 adds flow control (`credit`), chunk rings and asked chunks to the view; a v1
//! session parses and answers exactly as before.

use crate::encode::Format;
use crate::terrain::TileKey;
use crate::volume::chunk::ChunkKey;
use serde::{Deserialize, Serialize};

/// The protocol version of a session, chosen by the client when it connects (`?protocol=2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Protocol {
    /// `strata.stream.v1`: tiles, server-side backpressure.
    V1,
    /// `strata.stream.v2`: tiles and volume chunks, client-granted credits.
    V2,
}

impl Protocol {
    /// The name the `hello` message carries.
    pub fn name(self) -> &'static str {
        match self {
            Protocol::V1 => "strata.stream.v1",
            Protocol::V2 => "strata.stream.v2",
        }
    }
}

/// Frame kind of a volume chunk (protocol v2).
pub const KIND_CHUNK: u8 = 2;
/// Most frames one `credit` message may grant, and most credits a client may hold unspent.
pub const MAX_CREDITS: u32 = 1024;

/// Frame magic.
pub const FRAME_MAGIC: &[u8; 4] = b"STRF";
/// Frame layout version.
pub const FRAME_VERSION: u16 = 1;
/// Header bytes before the payload.
pub const FRAME_HEADER_BYTES: usize = 44;
/// Frame kind of a tile.
pub const KIND_TILE: u8 = 1;

/// A message from the client.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ClientMessage {
    /// Where the client is and what it wants.
    View {
        /// Camera X, metres.
        x: f64,
        /// Camera Z, metres.
        z: f64,
        /// Rings per LOD, finest first (Choroś & Topolski's `L = {A, B, C, …}`).
        rings: Vec<u32>,
        /// Tile format (`bin` by default).
        #[serde(default)]
        format: Option<String>,
        /// What a v2 view adds; `None` in v1.
        #[serde(skip)]
        volume: Option<VolumeView>,
    },
    /// Protocol v2: the client will accept `frames` more binary frames.
    Credit {
        /// Frames granted, 1 to [`MAX_CREDITS`].
        frames: u32,
    },
    /// An RFC 6902 JSON Patch for the world (world streams only; needs an edit token).
    Edit {
        /// Client's id for the acknowledgement.
        id: String,
        /// The patch.
        patch: serde_json::Value,
        /// Expected current version (optimistic concurrency).
        #[serde(default)]
        if_match: Option<u64>,
    },
}

/// Why a client message was refused: the field to blame (`type` when the message is not an
/// object with a known `type`) and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BadMessage {
    /// The offending field of the message: `type`, `x`, `rings`, `patch`, …
    pub field: String,
    /// Human-readable explanation.
    pub message: String,
}

impl BadMessage {
    fn new(field: &str, message: impl Into<String>) -> Self {
        Self {
            field: field.to_owned(),
            message: message.into(),
        }
    }
}

/// The volume part of a v2 view: where the camera is in height, which chunk rings to stream
/// around it and which chunks the client asks for by address.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
pub struct VolumeView {
    /// Camera height, metres (0 when not given).
    pub y: f64,
    /// Chunk rings per chunk LOD, finest first (none: no ring chunks).
    pub chunk_rings: Vec<u32>,
    /// Chunks asked for by `[lod, x, y, z]`, streamed whether or not a volume region meets them.
    pub chunks: Vec<[i64; 4]>,
    /// Chunk format: `bin` (default), `json` or `glb`.
    pub chunk_format: Option<String>,
    /// Ptex pages: the client opts in with its view direction ([`super::ptex`]).
    pub ptex: Option<super::ptex::PtexView>,
    /// Version of the tile frames' encoding, `1` (default) or `2` (`api/tile_format_v2.md`:
    /// each vertex's water surface and kind); `None` when not given.
    pub tile_format: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ViewFields {
    x: f64,
    z: f64,
    rings: Vec<u32>,
    #[serde(default)]
    format: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ViewFieldsV2 {
    x: f64,
    z: f64,
    rings: Vec<u32>,
    #[serde(default)]
    format: Option<String>,
    #[serde(default)]
    y: Option<f64>,
    #[serde(default)]
    chunk_rings: Vec<u32>,
    #[serde(default)]
    chunks: Vec<[i64; 4]>,
    #[serde(default)]
    chunk_format: Option<String>,
    #[serde(default)]
    ptex: Option<super::ptex::PtexView>,
    #[serde(default)]
    tile_format: Option<u32>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CreditFields {
    frames: u32,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct EditFields {
    id: String,
    patch: serde_json::Value,
    #[serde(default)]
    if_match: Option<u64>,
}

impl ClientMessage {
    /// Parses a text message of `protocol`, blaming the field that is missing, unknown or of
    /// the wrong type.
    pub fn parse(text: &str, protocol: Protocol) -> Result<Self, BadMessage> {
        let value: serde_json::Value = serde_json::from_str(text)
            .map_err(|e| BadMessage::new("type", format!("not a JSON message: {e}")))?;
        let serde_json::Value::Object(mut fields) = value else {
            return Err(BadMessage::new("type", "a message is a JSON object"));
        };
        let kind = match fields.remove("type") {
            Some(serde_json::Value::String(kind)) => kind,
            _ => {
                return Err(BadMessage::new(
                    "type",
                    match protocol {
                        Protocol::V1 => "`type` must be \"view\" or \"edit\"",
                        Protocol::V2 => "`type` must be \"view\", \"credit\" or \"edit\"",
                    },
                ))
            }
        };
        let rest = serde_json::Value::Object(fields);
        match (kind.as_str(), protocol) {
            ("view", Protocol::V1) => {
                let f: ViewFields = fields_of(&rest)?;
                Ok(ClientMessage::View {
                    x: f.x,
                    z: f.z,
                    rings: f.rings,
                    format: f.format,
                    volume: None,
                })
            }
            ("view", Protocol::V2) => {
                let f: ViewFieldsV2 = fields_of(&rest)?;
                Ok(ClientMessage::View {
                    x: f.x,
                    z: f.z,
                    rings: f.rings,
                    format: f.format,
                    volume: Some(VolumeView {
                        y: f.y.unwrap_or(0.0),
                        chunk_rings: f.chunk_rings,
                        chunks: f.chunks,
                        chunk_format: f.chunk_format,
                        ptex: f.ptex,
                        tile_format: f.tile_format,
                    }),
                })
            }
            ("credit", Protocol::V2) => {
                let f: CreditFields = fields_of(&rest)?;
                if f.frames == 0 || f.frames > MAX_CREDITS {
                    return Err(BadMessage::new(
                        "frames",
                        format!("frames must be 1 to {MAX_CREDITS}"),
                    ));
                }
                Ok(ClientMessage::Credit { frames: f.frames })
            }
            ("edit", _) => {
                let f: EditFields = fields_of(&rest)?;
                Ok(ClientMessage::Edit {
                    id: f.id,
                    patch: f.patch,
                    if_match: f.if_match,
                })
            }
            (other, _) => Err(BadMessage::new(
                "type",
                format!(
                    "unknown message type {:?}; known: {}",
                    other.chars().take(40).collect::<String>(),
                    match protocol {
                        Protocol::V1 => "view, edit",
                        Protocol::V2 => "view, credit, edit",
                    }
                ),
            )),
        }
    }
}

/// The fields of a message of a known type, or the top-level field to blame: the first segment
/// of the error's path, else the field a "missing field" or "unknown field" error names.
fn fields_of<T: serde::de::DeserializeOwned>(value: &serde_json::Value) -> Result<T, BadMessage> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let message = e.inner().to_string();
        let from_path = e.path().iter().find_map(|s| match s {
            serde_path_to_error::Segment::Map { key } => Some(key.clone()),
            _ => None,
        });
        let named = || {
            let (_, rest) = message.split_once("field `")?;
            rest.split_once('`').map(|(name, _)| name.to_owned())
        };
        let field = from_path
            .or_else(named)
            .unwrap_or_else(|| "type".to_owned());
        // An unknown field's name is the client's own text: echo at most 64 characters of it.
        BadMessage {
            field: field.chars().take(64).collect(),
            message: message.chars().take(300).collect(),
        }
    })
}

/// A control message from the server.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum ServerMessage {
    /// First message: what the stream is.
    Hello {
        /// Protocol name and version, `strata.stream.v1` or `strata.stream.v2`.
        protocol: &'static str,
        /// Current world version (1 for a bare seed).
        version: u64,
        /// Frame queue bound: at most this many frames are buffered for the client.
        queue_frames: usize,
        /// v2: the credits the client holds now (0: nothing is sent before a `credit`).
        #[serde(skip_serializing_if = "Option::is_none")]
        credits: Option<u32>,
        /// v2: the world's generator (`earth-1` or `classic`) at `version`.
        #[serde(skip_serializing_if = "Option::is_none")]
        generator: Option<crate::terrain::Generator>,
        /// v2: the names of the world's biomes at `version`, in the order of the tiles' biome
        /// weights (the `bin` tile carries only their count).
        #[serde(skip_serializing_if = "Option::is_none")]
        biomes: Option<Vec<String>>,
    },
    /// v2: an edit changed the world's generator or its biomes (their names or their order):
    /// sent before the edit's `invalidate`, so the client reads the fresh tiles' biome weights
    /// with the new names.
    World {
        /// The world version whose generator and biomes these are.
        version: u64,
        /// The world's generator (`earth-1` or `classic`).
        generator: crate::terrain::Generator,
        /// The names of the world's biomes, in the order of the tiles' biome weights.
        biomes: Vec<String>,
    },
    /// The view was accepted; `tiles` (and in v2 `chunks`) will arrive nearest first.
    View {
        /// Tiles in the view.
        tiles: usize,
        /// Frames that will be sent (products the client does not hold at the current version).
        sending: usize,
        /// v2: `[lod, x, y, z]` of the view's chunks, nearest first.
        #[serde(skip_serializing_if = "Option::is_none")]
        chunks: Option<Vec<[i64; 4]>>,
    },
    /// Every tile of the current view has been sent.
    Idle {
        /// World version the view is complete at.
        version: u64,
    },
    /// An edit changed these held tiles; fresh frames follow.
    Invalidate {
        /// New world version.
        version: u64,
        /// `[lod, x, z]` of each invalidated tile the client holds.
        tiles: Vec<[i64; 3]>,
        /// v2: `[lod, x, y, z]` of each invalidated chunk the client holds (fresh frames follow
        /// for those still in the view).
        #[serde(skip_serializing_if = "Option::is_none")]
        chunks: Option<Vec<[i64; 4]>>,
        /// v2: `[lod, x, y, z]` of held chunks the edit took out of the view (no volume region
        /// meets them any more): the client drops them.
        #[serde(skip_serializing_if = "Option::is_none")]
        dropped: Option<Vec<[i64; 4]>>,
    },
    /// An edit sent on this socket was accepted.
    Ack {
        /// The client's id.
        id: String,
        /// The new version.
        version: u64,
    },
    /// A request was refused; same shape as the HTTP error body plus the message id if any.
    Error {
        /// Stable code, as in HTTP errors.
        code: String,
        /// Human-readable message.
        message: String,
        /// Offending field, if any.
        field: Option<String>,
        /// Id of the edit it answers, if any.
        id: Option<String>,
    },
}

/// Numeric format codes of the frame header.
pub fn format_code(f: Format) -> u8 {
    match f {
        Format::Json => 1,
        Format::Bin => 2,
        Format::Png => 3,
        Format::Glb => 4,
    }
}

/// A tile frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TileFrame {
    /// Address.
    pub key: TileKey,
    /// Payload format.
    pub format: Format,
    /// World version the tile is of.
    pub version: u64,
    /// Seam flags `n, e, s, w` the edges were snapped with.
    pub seams: [bool; 4],
    /// The tile in `format`.
    pub payload: Vec<u8>,
}

impl TileFrame {
    /// The frame's bytes: header (little-endian) then payload.
    pub fn encode(&self) -> Vec<u8> {
        Self::encode_parts(
            self.key,
            self.format,
            self.version,
            self.seams,
            &self.payload,
        )
    }

    /// The bytes of the frame of tile `key` of world `version` with `seams`, its `payload` in
    /// `format`: what [`TileFrame::encode`] writes, from borrowed parts (a server frames a cached
    /// body without copying it first).
    pub fn encode_parts(
        key: TileKey,
        format: Format,
        version: u64,
        seams: [bool; 4],
        payload: &[u8],
    ) -> Vec<u8> {
        let bits = seams
            .iter()
            .enumerate()
            .fold(0u8, |b, (i, s)| b | ((*s as u8) << i));
        let head = Header {
            lod: key.lod,
            x: key.x,
            z: key.z,
            version,
            at36: [bits, 0, 0, 0],
        };
        head.frame(KIND_TILE, format, payload)
    }

    /// Parses a frame (the client side, for tests and tools).
    pub fn decode(bytes: &[u8]) -> Option<Self> {
        let (head, format, payload) = Header::read(bytes, KIND_TILE)?;
        Some(TileFrame {
            key: TileKey {
                lod: head.lod,
                x: head.x,
                z: head.z,
            },
            format,
            version: head.version,
            seams: [0, 1, 2, 3].map(|i| head.at36[0] & (1 << i) != 0),
            payload: payload.to_vec(),
        })
    }
}

/// `[lod, x, y, z]` of a chunk, as messages carry it.
pub fn chunk_address(key: ChunkKey) -> [i64; 4] {
    [i64::from(key.lod), key.x, key.y, key.z]
}

/// A volume chunk frame (protocol v2): the tile frame's 44-byte header with kind 2, the chunk's
/// `y` as an `i32` at offset 36 (where tiles carry seam flags), then the chunk's bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChunkFrame {
    /// Address.
    pub key: ChunkKey,
    /// Payload format (`json`, `bin` or `glb`).
    pub format: Format,
    /// World version the chunk is of.
    pub version: u64,
    /// The chunk in `format` (`api/chunk_format_v1.md`).
    pub payload: Vec<u8>,
}

impl ChunkFrame {
    /// The bytes of the frame of chunk `key` of world `version`, its `payload` in `format`.
    pub fn encode_parts(key: ChunkKey, format: Format, version: u64, payload: &[u8]) -> Vec<u8> {
        // Chunk y is within ±511 (`volume::chunk::max_chunk_y`), so it fits an i32.
        let y = i32::try_from(key.y).unwrap_or(if key.y < 0 { i32::MIN } else { i32::MAX });
        let head = Header {
            lod: key.lod,
            x: key.x,
            z: key.z,
            version,
            at36: y.to_le_bytes(),
        };
        head.frame(KIND_CHUNK, format, payload)
    }

    /// Parses a chunk frame (the client side, for tests and tools).
    pub fn decode(bytes: &[u8]) -> Option<Self> {
        let (head, format, payload) = Header::read(bytes, KIND_CHUNK)?;
        if format == Format::Png {
            return None;
        }
        Some(ChunkFrame {
            key: ChunkKey {
                lod: head.lod,
                x: head.x,
                y: i64::from(i32::from_le_bytes(head.at36)),
                z: head.z,
            },
            format,
            version: head.version,
            payload: payload.to_vec(),
        })
    }
}

/// The fields of the 44-byte frame header that tile and chunk frames share (little-endian):
/// magic, frame version, kind and format at 0–7, then `lod` (u32) at 8, `x` (i64) at 12, `z`
/// (i64) at 20, the world version (u64) at 28, four kind-specific bytes at 36 and the payload's
/// length (u32) at 40.
struct Header {
    lod: u32,
    x: i64,
    z: i64,
    version: u64,
    /// Bytes 36–39: a tile's seam flags and three zeros, or a chunk's `y` as an i32.
    at36: [u8; 4],
}

impl Header {
    /// The frame: this header with `kind` and `format`, then `payload`.
    fn frame(&self, kind: u8, format: Format, payload: &[u8]) -> Vec<u8> {
        let mut out = Vec::with_capacity(FRAME_HEADER_BYTES + payload.len());
        out.extend_from_slice(FRAME_MAGIC);
        out.extend_from_slice(&FRAME_VERSION.to_le_bytes());
        out.push(kind);
        out.push(format_code(format));
        out.extend_from_slice(&self.lod.to_le_bytes());
        out.extend_from_slice(&self.x.to_le_bytes());
        out.extend_from_slice(&self.z.to_le_bytes());
        out.extend_from_slice(&self.version.to_le_bytes());
        out.extend_from_slice(&self.at36);
        out.extend_from_slice(&(payload.len() as u32).to_le_bytes());
        out.extend_from_slice(payload);
        out
    }

    /// The header, format and payload of a frame of `kind`; `None` for another kind, a bad
    /// magic or format, or a length that is not the payload's.
    fn read(bytes: &[u8], kind: u8) -> Option<(Header, Format, &[u8])> {
        if bytes.len() < FRAME_HEADER_BYTES || &bytes[..4] != FRAME_MAGIC || bytes[6] != kind {
            return None;
        }
        let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().unwrap_or_default());
        let i64_at = |o: usize| i64::from_le_bytes(bytes[o..o + 8].try_into().unwrap_or_default());
        let format = match bytes[7] {
            1 => Format::Json,
            2 => Format::Bin,
            3 => Format::Png,
            4 => Format::Glb,
            _ => return None,
        };
        if bytes.len() != FRAME_HEADER_BYTES + u32_at(40) as usize {
            return None;
        }
        let mut at36 = [0u8; 4];
        at36.copy_from_slice(&bytes[36..40]);
        let head = Header {
            lod: u32_at(8),
            x: i64_at(12),
            z: i64_at(20),
            version: i64_at(28) as u64,
            at36,
        };
        Some((head, format, &bytes[FRAME_HEADER_BYTES..]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_round_trip() {
        let f = TileFrame {
            key: TileKey {
                lod: 3,
                x: -7,
                z: 1 << 40,
            },
            format: Format::Glb,
            version: 9,
            seams: [true, false, false, true],
            payload: vec![1, 2, 3],
        };
        let bytes = f.encode();
        assert_eq!(bytes.len(), FRAME_HEADER_BYTES + 3);
        assert_eq!(TileFrame::decode(&bytes), Some(f));
        assert_eq!(TileFrame::decode(&bytes[..20]), None);
    }

    #[test]
    fn chunk_frames_round_trip_and_are_not_tiles() {
        let f = ChunkFrame {
            key: ChunkKey {
                lod: 2,
                x: -5,
                y: -3,
                z: 1 << 33,
            },
            format: Format::Bin,
            version: 4,
            payload: vec![9; 5],
        };
        let bytes = ChunkFrame::encode_parts(f.key, f.format, f.version, &f.payload);
        assert_eq!(bytes.len(), FRAME_HEADER_BYTES + 5);
        assert_eq!(ChunkFrame::decode(&bytes), Some(f));
        assert_eq!(TileFrame::decode(&bytes), None);
    }

    #[test]
    fn v2_messages_parse_and_v1_refuses_them() {
        let credit = r#"{"type":"credit","frames":3}"#;
        assert_eq!(
            ClientMessage::parse(credit, Protocol::V2),
            Ok(ClientMessage::Credit { frames: 3 })
        );
        assert_eq!(
            ClientMessage::parse(credit, Protocol::V1).map_err(|e| e.field),
            Err("type".to_string())
        );
        let zero = ClientMessage::parse(r#"{"type":"credit","frames":0}"#, Protocol::V2);
        assert_eq!(zero.map_err(|e| e.field), Err("frames".to_string()));
        let view = r#"{"type":"view","x":1,"z":2,"rings":[1],"y":30,"chunk_rings":[2]}"#;
        match ClientMessage::parse(view, Protocol::V2) {
            Ok(ClientMessage::View {
                volume: Some(v), ..
            }) => assert_eq!((v.y, v.chunk_rings), (30.0, vec![2])),
            other => panic!("a v2 view: {other:?}"),
        }
        let with_y = r#"{"type":"view","x":1,"z":2,"rings":[1],"y":30}"#;
        let refused = ClientMessage::parse(with_y, Protocol::V1).map_err(|e| e.field);
        assert_eq!(refused, Err("y".to_string()));
    }

    #[test]
    fn client_messages_parse_and_reject_unknown_fields() {
        let v: ClientMessage =
            serde_json::from_str(r#"{"type":"view","x":1.5,"z":-3,"rings":[2,1]}"#).expect("view");
        assert!(matches!(v, ClientMessage::View { format: None, .. }));
        assert!(serde_json::from_str::<ClientMessage>(
            r#"{"type":"view","x":1,"z":1,"rings":[],"zoom":2}"#
        )
        .is_err());
        assert!(serde_json::from_str::<ClientMessage>(r#"{"type":"teleport"}"#).is_err());
    }
}
