// The `bin` volume chunk format (api/chunk_format_v1.md), decoded without three.js so the decoding
// worker (./decode.worker.ts) can use it.

/** A decoded `bin` volume chunk: positions relative to its origin, quads as vertex indices. */
export interface Chunk {
  lod: number;
  x: number;
  y: number;
  z: number;
  origin: [number, number, number];
  positions: Float32Array;
  normals: Float32Array;
  materials: Uint8Array;
  quads: Uint32Array;
  skirtPositions: Float32Array;
  skirtQuads: Uint32Array;
}

export const chunkKey = (lod: number, x: number, y: number, z: number): string => `${lod}/${x}/${y}/${z}`;

const pad4 = (n: number) => (n + 3) & ~3;

/** The `bin` chunk format: the 96-byte header and the sections it counts. */
export function decodeChunk(p: DataView): Chunk {
  const tag = String.fromCharCode(p.getUint8(0), p.getUint8(1), p.getUint8(2), p.getUint8(3));
  if (p.byteLength < 96 || tag !== "STCK") throw new Error("not a STCK chunk");
  if (p.getUint32(4, true) !== 1) throw new Error(`unknown chunk version ${p.getUint32(4, true)}`);
  const V = p.getUint32(80, true);
  const Q = p.getUint32(84, true);
  const SV = p.getUint32(88, true);
  const SQ = p.getUint32(92, true);
  // Copies: the frame buffer's offsets need not be 4-byte aligned.
  const bytes = (off: number, len: number) => new Uint8Array(p.buffer.slice(p.byteOffset + off, p.byteOffset + off + len));
  let at = 96;
  const take = (len: number) => {
    const out = bytes(at, len);
    at += len;
    return out;
  };
  const positions = new Float32Array(take(12 * V).buffer);
  const normals = new Float32Array(take(12 * V).buffer);
  const materials = take(pad4(V)).slice(0, V);
  const quads = new Uint32Array(take(16 * Q).buffer);
  at += pad4(Q) + 32 * Q + 24 * Q; // classes, adjacency, edges: not drawn
  const skirtPositions = new Float32Array(take(12 * SV).buffer);
  const skirtQuads = new Uint32Array(take(16 * SQ).buffer);
  if (at > p.byteLength) throw new Error("truncated chunk");
  return {
    lod: p.getUint32(8, true),
    x: Number(p.getBigInt64(16, true)),
    y: Number(p.getBigInt64(24, true)),
    z: Number(p.getBigInt64(32, true)),
    origin: [p.getFloat64(48, true), p.getFloat64(56, true), p.getFloat64(64, true)],
    positions,
    normals,
    materials,
    quads,
    skirtPositions,
    skirtQuads,
  };
}

