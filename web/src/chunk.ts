// Volume chunks of stream protocol v2 (api/stream_protocol_v2.md): their frames' header and the
// `bin` chunk body (api/chunk_format_v1.md), as three.js meshes (surface and skirt quads).
import * as THREE from "three";

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

// Materials as the tiles': 0 seabed, 1 sand, 2 grass, 3 dirt, 4 rock, 5 snow.
const MATERIAL = [
  [0.42, 0.4, 0.33],
  [0.84, 0.77, 0.56],
  [0.33, 0.46, 0.22],
  [0.5, 0.39, 0.26],
  [0.55, 0.5, 0.45],
  [0.96, 0.97, 0.99],
].map(([r, g, b]) => new THREE.Color().setRGB(r, g, b, THREE.SRGBColorSpace));

// Pushed back in depth: where a chunk's surface is the heightfield's (outside the volume region,
// where the tiles are not hidden) the tile wins instead of z-fighting with it.
const chunkMaterial = new THREE.MeshLambertMaterial({
  vertexColors: true,
  side: THREE.DoubleSide,
  polygonOffset: true,
  polygonOffsetFactor: 2,
  polygonOffsetUnits: 4,
});

/** The chunk's surface and skirts as one mesh at its origin; `undefined` for an empty chunk. */
export function buildChunkMesh(c: Chunk): THREE.Mesh | undefined {
  const V = c.positions.length / 3;
  const SV = c.skirtPositions.length / 3;
  if (c.quads.length === 0) return undefined;
  const pos = new Float32Array(3 * (V + SV));
  pos.set(c.positions, 0);
  pos.set(c.skirtPositions, 3 * V);
  const col = new Float32Array(3 * (V + SV));
  for (let v = 0; v < V; v++) {
    const m = MATERIAL[c.materials[v]] ?? MATERIAL[4];
    col.set([m.r, m.g, m.b], 3 * v);
  }
  for (let v = 0; v < SV; v++) col.set([MATERIAL[4].r, MATERIAL[4].g, MATERIAL[4].b], 3 * (V + v));
  const idx: number[] = [];
  for (const q of [c.quads, c.skirtQuads]) {
    for (let i = 0; i + 3 < q.length; i += 4) idx.push(q[i], q[i + 1], q[i + 2], q[i], q[i + 2], q[i + 3]);
  }
  const geo = new THREE.BufferGeometry();
  geo.setIndex(idx);
  geo.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  geo.setAttribute("color", new THREE.BufferAttribute(col, 3));
  geo.computeVertexNormals();
  // The surface's own normals where it has them (skirts keep the computed ones).
  const nor = geo.getAttribute("normal") as THREE.BufferAttribute;
  (nor.array as Float32Array).set(c.normals, 0);
  geo.computeBoundingSphere();
  const mesh = new THREE.Mesh(geo, chunkMaterial);
  mesh.position.set(c.origin[0], c.origin[1], c.origin[2]);
  mesh.matrixAutoUpdate = false;
  mesh.updateMatrix();
  return mesh;
}
