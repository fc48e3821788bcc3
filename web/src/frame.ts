// Decoding of stream frames (api/stream_protocol_v1.md, _v2.md) and STRT v1 tiles
// (api/tile_format_v1.md).

/** Frame kinds: a height tile, a volume chunk, Ptex pages (v2). */
export const KIND_TILE = 1;
export const KIND_CHUNK = 2;
export const KIND_PTEX = 3;

/** A frame's header fields; for Ptex pages `lod` is the level, `x` the pages' resolution, `z`
 * their count and `faces` their faces' kind (0 height-tile faces, 1 volume-chunk faces). */
export interface Frame {
  kind: number;
  lod: number;
  x: number;
  /** A chunk's y (0 for tiles). */
  y: number;
  z: number;
  version: number;
  seams: number;
  /** Ptex pages: the kind of their faces (0 tiles', 1 chunks'). */
  faces: number;
  format: number;
  payload: DataView;
}

export interface Tile {
  lod: number;
  x: number;
  z: number;
  size: number;
  biomeCount: number;
  spacing: number;
  originX: number;
  originZ: number;
  skirtDepth: number;
  minHeight: number;
  maxHeight: number;
  heights: Float32Array;
  normals: Float32Array;
  weights: Uint8Array;
  materials: Uint8Array;
  waterDepth: Float32Array;
  /** Water kind per vertex (`api/tile_format_v2.md`: 0 none, 1 sea, 2 lake, 3 river); empty in a version 1 tile. */
  waterKind: Uint8Array;
  /** 1 where a volume chunk gives the surface (the tile hides those vertices); empty when none. */
  volumeOverride: Uint8Array;
}

/** Water kinds of a version 2 tile (`api/tile_format_v2.md`). */
export const WATER_SEA = 1;
export const WATER_LAKE = 2;
export const WATER_RIVER = 3;

const FRAME_HEADER = 44;

function magic(v: DataView, at: number): string {
  return String.fromCharCode(v.getUint8(at), v.getUint8(at + 1), v.getUint8(at + 2), v.getUint8(at + 3));
}

/** The 44-byte little-endian frame header and its payload (a tile's seams, a chunk's y or the
 * Ptex pages' kind of faces at 36). */
export function decodeFrame(buf: ArrayBuffer): Frame {
  const v = new DataView(buf);
  if (buf.byteLength < FRAME_HEADER || magic(v, 0) !== "STRF") throw new Error("not a STRF frame");
  const layout = v.getUint16(4, true);
  if (layout !== 1) throw new Error(`unknown frame layout ${layout}`);
  const kind = v.getUint8(6);
  const len = v.getUint32(40, true);
  if (FRAME_HEADER + len > buf.byteLength) throw new Error("truncated frame");
  return {
    kind,
    format: v.getUint8(7),
    lod: v.getUint32(8, true),
    x: Number(v.getBigInt64(12, true)),
    y: kind === KIND_CHUNK ? v.getInt32(36, true) : 0,
    z: Number(v.getBigInt64(20, true)),
    version: Number(v.getBigUint64(28, true)),
    seams: kind === KIND_TILE ? v.getUint8(36) : 0,
    faces: kind === KIND_PTEX ? v.getUint32(36, true) : 0,
    payload: new DataView(buf, FRAME_HEADER, len),
  };
}

/** A `bin` tile of version 1 or 2: checks magic and version, reads sections at the offsets the header gives. */
export function decodeTile(p: DataView): Tile {
  if (p.byteLength < 128 || magic(p, 0) !== "STRT") throw new Error("not a STRT tile");
  const version = p.getUint16(4, true);
  if (version !== 1 && version !== 2) throw new Error(`unknown tile version ${version}`);
  const size = p.getUint16(36, true);
  const biomeCount = p.getUint16(38, true);
  const n = p.getUint32(40, true);
  if (n !== size * size) throw new Error("vertex count is not size²");
  if (p.getUint8(76) !== 0 || p.getUint8(77) !== 1) throw new Error("unknown normal/weight encoding");
  const total = p.getUint32(100, true);
  if (total > p.byteLength) throw new Error("truncated tile");
  // Copy the sections out: the frame buffer's offsets need not be 4-byte aligned.
  const bytes = (off: number, len: number) => new Uint8Array(p.buffer.slice(p.byteOffset + off, p.byteOffset + off + len));
  const f32 = (off: number, count: number) => new Float32Array(bytes(off, count * 4).buffer);
  return {
    x: Number(p.getBigInt64(16, true)),
    z: Number(p.getBigInt64(24, true)),
    lod: p.getUint32(32, true),
    size,
    biomeCount,
    spacing: p.getFloat32(44, true),
    originX: p.getFloat64(48, true),
    originZ: p.getFloat64(56, true),
    skirtDepth: p.getFloat32(64, true),
    minHeight: p.getFloat32(68, true),
    maxHeight: p.getFloat32(72, true),
    heights: f32(p.getUint32(80, true), n),
    normals: f32(p.getUint32(84, true), 3 * n),
    weights: bytes(p.getUint32(88, true), n * biomeCount),
    materials: bytes(p.getUint32(92, true), n),
    waterDepth: f32(p.getUint32(96, true), n),
    waterKind: version === 2 ? bytes(p.getUint32(112, true), n) : new Uint8Array(0),
    volumeOverride: p.getUint32(104, true) ? bytes(p.getUint32(104, true), n) : new Uint8Array(0),
  };
}
