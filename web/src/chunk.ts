// Volume chunks of stream protocol v2 (api/stream_protocol_v2.md) as three.js meshes (surface and
// skirt quads), decoded by ./chunkFormat.ts, drawn with the vertex colours of their materials or
// with the texture splatting of the tiles (./splat.ts).
//
// Splatting: a chunk vertex carries one material id (api/chunk_format_v1.md, `materials`), a
// one-hot weight as a tile vertex's, so the splat attributes are the tiles' (`splatVertex`); the
// splat is tri-planar (each fragment reads the plane its normal faces most), so the overhangs and
// the undersides of arches are textured as the ground is. Chunks carry no biome weights and no
// water: the splat's biome share is the material's own mid colour (no tint), as the chunks'
// vertex colours are the materials' alone; skirts read rock, as their vertex colours.
//
// Ptex pages (./ptex.ts): each quad is a face with a page of its own, so with pages the mesh
// gives each quad four vertices of its own (its corners in the class's order, uv (0, 0), (1, 0),
// (1, 1), (0, 1)) carrying the quad's page entry, which the store updates as pages arrive; the
// shared vertices follow, used by the skirts only (no page: splat or vertex colours).
import * as THREE from "three";
import { chunkKey, type Chunk } from "./chunkFormat";
import type { PtexStore } from "./ptex";
import { addSplat, splatMidColour, splatVertex } from "./splat";

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

let splatMaterial: THREE.MeshLambertMaterial | undefined;

/** The material chunks share: splatted (./splat.ts) or vertex colours alone. */
function sharedMaterial(splat: boolean): THREE.MeshLambertMaterial {
  if (!splat) return chunkMaterial;
  if (!splatMaterial) {
    splatMaterial = new THREE.MeshLambertMaterial({
      vertexColors: false,
      side: THREE.DoubleSide,
      polygonOffset: true,
      polygonOffsetFactor: 2,
      polygonOffsetUnits: 4,
    });
    splatMaterial.onBeforeCompile = (shader) => addSplat(shader);
    splatMaterial.customProgramCacheKey = () => "strata-splat-chunk";
  }
  return splatMaterial;
}

/** The splat attributes (./splat.ts) of a chunk's `V` surface vertices of `materials` and `SV`
 * skirt vertices (rock). */
function splatAttributes(materials: Uint8Array, V: number, SV: number): { base: Float32Array; span: Float32Array; sel: Uint8Array } {
  const out = { base: new Float32Array(3 * (V + SV)), span: new Float32Array(3 * (V + SV)), sel: new Uint8Array(4 * (V + SV)) };
  const none = new THREE.Color();
  for (let v = 0; v < V + SV; v++) {
    const m = v < V ? materials[v] : ROCK;
    splatVertex(v, m, splatMidColour(m), 0, none, out);
  }
  return out;
}

/** The rock material's id: what skirts are drawn with. */
const ROCK = 4;

/** The corners' uv of a quad's four vertices (api/chunk_format_v1.md). */
const QUAD_UV = [0, 0, 1, 0, 1, 1, 0, 1];

/** `geo` (vertices shared, `idx` its triangles: quads then skirts) with each of the `Q` quads
 * given four vertices of its own, then the shared vertices (for the skirts), and the attributes
 * of the Ptex pages: `ptexUv` and `ptexPage` (the quad's entry of `table`; −1 for the shared
 * vertices). */
function unshare(geo: THREE.BufferGeometry, quads: Uint32Array, idx: number[], table: Float32Array): THREE.BufferGeometry {
  const Q = quads.length / 4;
  const shared = geo.getAttribute("position").count;
  const map = new Uint32Array(4 * Q + shared);
  map.set(quads, 0);
  for (let v = 0; v < shared; v++) map[4 * Q + v] = v;
  const out = new THREE.BufferGeometry();
  for (const [name, attr] of Object.entries(geo.attributes)) {
    const a = attr as THREE.BufferAttribute;
    const size = a.itemSize;
    const src = a.array as Float32Array | Uint8Array;
    const dst = new (src.constructor as typeof Float32Array | typeof Uint8Array)(size * map.length);
    for (let v = 0; v < map.length; v++) for (let k = 0; k < size; k++) dst[size * v + k] = src[size * map[v] + k];
    out.setAttribute(name, new THREE.BufferAttribute(dst, size, a.normalized));
  }
  const uv = new Float32Array(2 * map.length);
  const page = new Float32Array(4 * map.length).fill(-1);
  for (let q = 0; q < Q; q++) {
    uv.set(QUAD_UV, 8 * q);
    for (let k = 0; k < 4; k++) page.set(table.subarray(4 * q, 4 * q + 4), 4 * (4 * q + k));
  }
  out.setAttribute("ptexUv", new THREE.BufferAttribute(uv, 2));
  out.setAttribute("ptexPage", new THREE.BufferAttribute(page, 4));
  const index: number[] = [];
  for (let q = 0; q < Q; q++) index.push(4 * q, 4 * q + 1, 4 * q + 2, 4 * q, 4 * q + 2, 4 * q + 3);
  for (let t = 6 * Q; t < idx.length; t++) index.push(4 * Q + idx[t]);
  out.setIndex(index);
  return out;
}

/** Where a chunk mesh's quads read their Ptex pages: the store and the chunk's key in it. */
export interface ChunkPtex {
  store: PtexStore;
  key: string;
}

/** The chunk's surface and skirts as one mesh at its origin, splatted when `splat`, drawn with
 * its quads' Ptex pages when `ptex` is given; `undefined` for an empty chunk. */
export function buildChunkMesh(c: Chunk, splat = false, ptex?: ChunkPtex): THREE.Mesh | undefined {
  const V = c.positions.length / 3;
  const SV = c.skirtPositions.length / 3;
  if (c.quads.length === 0) return undefined;
  const pos = new Float32Array(3 * (V + SV));
  pos.set(c.positions, 0);
  pos.set(c.skirtPositions, 3 * V);
  const col = new Float32Array(3 * (V + SV));
  for (let v = 0; v < V; v++) {
    const m = MATERIAL[c.materials[v]] ?? MATERIAL[ROCK];
    col.set([m.r, m.g, m.b], 3 * v);
  }
  for (let v = 0; v < SV; v++) col.set([MATERIAL[ROCK].r, MATERIAL[ROCK].g, MATERIAL[ROCK].b], 3 * (V + v));
  const idx: number[] = [];
  for (const q of [c.quads, c.skirtQuads]) {
    for (let i = 0; i + 3 < q.length; i += 4) idx.push(q[i], q[i + 1], q[i + 2], q[i], q[i + 2], q[i + 3]);
  }
  const geo = new THREE.BufferGeometry();
  geo.setIndex(idx);
  geo.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  geo.setAttribute("color", new THREE.BufferAttribute(col, 3));
  if (splat) {
    const a = splatAttributes(c.materials, V, SV);
    geo.setAttribute("splatBase", new THREE.BufferAttribute(a.base, 3));
    geo.setAttribute("splatSpan", new THREE.BufferAttribute(a.span, 3));
    geo.setAttribute("splatSel", new THREE.BufferAttribute(a.sel, 4, true));
  }
  geo.computeVertexNormals();
  // The surface's own normals where it has them (skirts keep the computed ones).
  const nor = geo.getAttribute("normal") as THREE.BufferAttribute;
  (nor.array as Float32Array).set(c.normals, 0);
  let drawn = geo;
  let material = sharedMaterial(splat);
  if (ptex) {
    const Q = c.quads.length / 4;
    let page: THREE.BufferAttribute | undefined;
    const table = ptex.store.chunkFaces(ptex.key, Q, (q) => {
      if (!page) return;
      const arr = page.array as Float32Array;
      for (let k = 0; k < 4; k++) arr.set(table.subarray(4 * q, 4 * q + 4), 4 * (4 * q + k));
      page.needsUpdate = true;
    });
    drawn = unshare(geo, c.quads, idx, table);
    geo.dispose();
    page = drawn.getAttribute("ptexPage") as THREE.BufferAttribute;
    material = ptex.store.chunkMaterial();
  }
  drawn.computeBoundingSphere();
  const mesh = new THREE.Mesh(drawn, material);
  mesh.position.set(c.origin[0], c.origin[1], c.origin[2]);
  mesh.matrixAutoUpdate = false;
  mesh.updateMatrix();
  return mesh;
}

/** The chunk meshes in a scene, by chunk key (empty chunks are held without a mesh), splatted
 * when `splat`, drawn with their quads' Ptex pages from `ptex` when given. */
export class ChunkLayer {
  private readonly group = new THREE.Group();
  private readonly meshes = new Map<string, THREE.Mesh | undefined>();
  private readonly quads = new Map<string, number>();
  private readonly splat: boolean;
  private readonly ptex: PtexStore | undefined;

  constructor(scene: THREE.Scene, splat: boolean, ptex?: PtexStore) {
    scene.add(this.group);
    this.splat = splat;
    this.ptex = ptex;
  }

  /** Whether chunk `key` is held (with or without a mesh). */
  holds(key: string): boolean {
    return this.meshes.has(key);
  }

  /** The quads of the held chunks: their Ptex faces. */
  quadCount(): number {
    let n = 0;
    for (const q of this.quads.values()) n += q;
    return n;
  }

  /** Shows or hides every chunk mesh (tests find the chunks' pixels with it). */
  show(on: boolean): void {
    this.group.visible = on;
  }

  /** Replaces chunk `key` with `chunk`; returns how many chunks are held. */
  put(key: string, chunk: Chunk): number {
    this.remove(key);
    const mesh = buildChunkMesh(chunk, this.splat, this.ptex ? { store: this.ptex, key } : undefined);
    this.quads.set(key, chunk.quads.length / 4);
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
    this.quads.delete(key);
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
