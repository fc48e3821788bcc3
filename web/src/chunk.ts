// Volume chunks of stream protocol v2 (api/stream_protocol_v2.md) as three.js meshes (surface and
// skirt quads), decoded by ./chunkFormat.ts.
import * as THREE from "three";
import { chunkKey, type Chunk } from "./chunkFormat";

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

/** The chunk meshes in a scene, by chunk key (empty chunks are held without a mesh). */
export class ChunkLayer {
  private readonly group = new THREE.Group();
  private readonly meshes = new Map<string, THREE.Mesh | undefined>();

  constructor(scene: THREE.Scene) {
    scene.add(this.group);
  }

  /** Replaces chunk `key` with `chunk`; returns how many chunks are held. */
  put(key: string, chunk: Chunk): number {
    this.remove(key);
    const mesh = buildChunkMesh(chunk);
    if (mesh) this.group.add(mesh);
    this.meshes.set(key, mesh);
    return this.meshes.size;
  }

  /** Frees chunk `key`; returns how many chunks are held. */
  remove(key: string): number {
    const mesh = this.meshes.get(key);
    if (mesh) {
      this.group.remove(mesh);
      mesh.geometry.dispose();
    }
    this.meshes.delete(key);
    return this.meshes.size;
  }

  /** Whether a held chunk (of LOD 0–3, a chunk `(lod, x, y, z)` spanning `32·cellM·2^lod` metres
   * from `(x, y, z)` times that) contains world (x, y, z) metres: that chunk, empty or not, gives
   * the surface there. */
  covers(x: number, y: number, z: number, cellM: number): boolean {
    if (this.meshes.size === 0) return false;
    for (let lod = 0; lod < 4; lod++) {
      const size = 32 * cellM * 2 ** lod;
      if (this.meshes.has(chunkKey(lod, Math.floor(x / size), Math.floor(y / size), Math.floor(z / size)))) return true;
    }
    return false;
  }

  /** Frees the chunks not in `wanted`; returns how many chunks are held. */
  keep(wanted: Set<string>): number {
    for (const key of [...this.meshes.keys()]) if (!wanted.has(key)) this.remove(key);
    return this.meshes.size;
  }
}
