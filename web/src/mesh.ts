// STRT tiles as three.js meshes: 65×65 surface plus skirts (the glb layout of
// api/tile_format_v1.md), vertex colours from biome weights (tinted by the world's biomes,
// ./biomes.ts) and materials, the attributes of the texture splatting (./splat.ts), water as a
// translucent sheet cut along the shoreline (see ./water.ts).
import * as THREE from "three";
import { tintOf } from "./biomes";
import type { Tile } from "./frame";
import { addSplat, macroFactor, splatVertex } from "./splat";
import { setWater, waterMaterial } from "./water";

// Materials: 0 seabed, 1 sand, 2 grass, 3 dirt, 4 rock, 5 snow.
const MATERIAL = [
  [0.42, 0.40, 0.33],
  [0.84, 0.77, 0.56],
  [0.28, 0.46, 0.18],
  [0.50, 0.39, 0.26],
  [0.52, 0.47, 0.42],
  [0.96, 0.97, 0.99],
].map(([r, g, b]) => new THREE.Color().setRGB(r, g, b, THREE.SRGBColorSpace));

const indexCache = new Map<number, Uint16Array>();

/** Triangle indices for a `size`×`size` grid plus its four skirts (one array for every tile; each
 * geometry gets its own attribute, so disposing one tile never frees another's GPU buffer). */
function indices(size: number): Uint16Array {
  const cached = indexCache.get(size);
  if (cached) return cached;
  const q = size - 1;
  const n = size * size;
  const idx: number[] = [];
  for (let j = 0; j < q; j++) {
    for (let i = 0; i < q; i++) {
      const v00 = j * size + i;
      const v10 = v00 + 1;
      const v01 = v00 + size;
      const v11 = v01 + 1;
      idx.push(v00, v01, v10, v10, v01, v11);
    }
  }
  for (let e = 0; e < 4; e++) {
    for (let t = 0; t < q; t++) {
      const [t0, t1] = [edgeVertex(e, t, size), edgeVertex(e, t + 1, size)];
      const [b0, b1] = [n + e * size + t, n + e * size + t + 1];
      if (e < 2) idx.push(t0, t1, b0, t1, b1, b0);
      else idx.push(t0, b0, t1, t1, b0, b1);
    }
  }
  const arr = new Uint16Array(idx);
  indexCache.set(size, arr);
  return arr;
}

/** Whether a volume chunk the viewer holds gives the surface at world (x, y, z), metres. */
export type Covered = (x: number, y: number, z: number) => boolean;

/** Whether the server marks any vertex of `tile` as overridden by a volume chunk. */
export function hasMarks(tile: Tile): boolean {
  return tile.volumeOverride.some((m) => m === 1);
}

/** Writes to `out` the triangles of `idx` that touch no vertex a held volume chunk overrides and
 * returns their index count. A vertex is hidden when the server marks it (`volumeOverride[v] ===
 * 1`) and a chunk the viewer holds covers it: the chunk draws the surface there. A marked vertex
 * where the viewer holds no chunk (outside its chunk rings, or before the chunk arrives) stays
 * drawn, or the terrain would show a hole. Skirt vertices (past the marks) are never hidden. */
function visible(idx: Uint16Array, tile: Tile, covered: Covered, out: Uint16Array): number {
  const marks = tile.volumeOverride;
  const hide = new Uint8Array(marks.length);
  for (let v = 0; v < marks.length; v++) {
    if (marks[v] !== 1) continue;
    const i = v % tile.size;
    const j = (v - i) / tile.size;
    hide[v] = covered(tile.originX + i * tile.spacing, tile.heights[v], tile.originZ + j * tile.spacing) ? 1 : 0;
  }
  const hidden = (v: number) => v < hide.length && hide[v] === 1;
  let n = 0;
  for (let t = 0; t < idx.length; t += 3) {
    if (hidden(idx[t]) || hidden(idx[t + 1]) || hidden(idx[t + 2])) continue;
    out[n++] = idx[t];
    out[n++] = idx[t + 1];
    out[n++] = idx[t + 2];
  }
  return n;
}

/** Hides again the triangles of a tile mesh with marked vertices that the held chunks cover (call
 * when chunks arrive or are freed); the index keeps its buffer and the draw range shrinks. */
export function updateHidden(mesh: THREE.Mesh, tile: Tile, covered: Covered): void {
  const geo = mesh.geometry;
  const index = geo.getIndex();
  if (!index) return;
  const count = visible(indices(tile.size), tile, covered, index.array as Uint16Array);
  index.needsUpdate = true;
  geo.setDrawRange(0, count);
}

/** Edge `e` (n, e, s, w) position `t` as a surface vertex index. */
function edgeVertex(e: number, t: number, size: number): number {
  const q = size - 1;
  switch (e) {
    case 0:
      return t; // north (t, 0)
    case 1:
      return t * size + q; // east (q, t)
    case 2:
      return q * size + t; // south (t, q)
    default:
      return t * size; // west (0, t)
  }
}

const terrainMaterial = new THREE.MeshLambertMaterial({ vertexColors: true });
let splatMaterial: THREE.MeshLambertMaterial | undefined;

/** The material tiles share without Ptex pages: splatted (./splat.ts) or vertex colours alone. */
export function sharedMaterial(splat: boolean): THREE.MeshLambertMaterial {
  if (!splat) return terrainMaterial;
  if (!splatMaterial) {
    // The splat replaces the vertex colours, so they are not interpolated (./splat.ts).
    splatMaterial = new THREE.MeshLambertMaterial({ vertexColors: false });
    splatMaterial.onBeforeCompile = (shader) => addSplat(shader);
    splatMaterial.customProgramCacheKey = () => "strata-splat-tile";
  }
  return splatMaterial;
}

/** The mesh of `tile`, drawn with `material` (the shared vertex-colour material by default), its
 * marked vertices hidden where `covered` says a held chunk draws the surface; `tints` are the
 * world's biome tints in the order of the tile's weights (./biomes.ts). */
export function buildMesh(
  tile: Tile,
  covered: Covered,
  tints: readonly THREE.Color[],
  material: THREE.Material = terrainMaterial,
): THREE.Mesh {
  const { size, heights, normals, weights, materials, biomeCount: k } = tile;
  const n = size * size;
  const total = n + 4 * size;
  const pos = new Float32Array(3 * total);
  const nor = new Float32Array(3 * total);
  const col = new Float32Array(3 * total);
  const splat = { base: new Float32Array(3 * total), span: new Float32Array(3 * total), sel: new Uint8Array(4 * total) };
  const macro = new Float32Array(3 * total);
  const c = new THREE.Color();
  const b = new THREE.Color();
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const v = j * size + i;
      pos[3 * v] = i * tile.spacing;
      pos[3 * v + 1] = heights[v];
      pos[3 * v + 2] = j * tile.spacing;
      nor[3 * v] = normals[3 * v];
      nor[3 * v + 1] = normals[3 * v + 1];
      nor[3 * v + 2] = normals[3 * v + 2];
      b.setRGB(0, 0, 0);
      for (let bi = 0; bi < k; bi++) {
        const w = weights[v * k + bi] / 255;
        const tint = tintOf(tints, bi);
        b.r += w * tint.r;
        b.g += w * tint.g;
        b.b += w * tint.b;
      }
      c.copy(MATERIAL[materials[v]] ?? MATERIAL[4]).lerp(b, 0.45);
      const depth = tile.waterDepth[v];
      const wet = depth > 0 ? Math.min(depth / 60, 0.85) : 0;
      if (wet > 0) c.lerp(waterMaterial.color, wet);
      splatVertex(v, materials[v], b, wet, waterMaterial.color, splat);
      macroFactor(tile.originX + i * tile.spacing, tile.originZ + j * tile.spacing, tile.spacing, macro, v);
      col[3 * v] = c.r;
      col[3 * v + 1] = c.g;
      col[3 * v + 2] = c.b;
    }
  }
  for (let e = 0; e < 4; e++) {
    for (let t = 0; t < size; t++) {
      const s = edgeVertex(e, t, size);
      const d = n + e * size + t;
      for (let a = 0; a < 3; a++) {
        pos[3 * d + a] = pos[3 * s + a];
        nor[3 * d + a] = nor[3 * s + a];
        col[3 * d + a] = col[3 * s + a];
        macro[3 * d + a] = macro[3 * s + a];
      }
      for (let a = 0; a < 3; a++) {
        splat.base[3 * d + a] = splat.base[3 * s + a];
        splat.span[3 * d + a] = splat.span[3 * s + a];
      }
      for (let a = 0; a < 4; a++) splat.sel[4 * d + a] = splat.sel[4 * s + a];
      pos[3 * d + 1] -= tile.skirtDepth;
    }
  }
  const geo = new THREE.BufferGeometry();
  const all = indices(size);
  const index = new Uint16Array(all.length);
  geo.setIndex(new THREE.BufferAttribute(index, 1));
  let count = all.length;
  if (hasMarks(tile)) count = visible(all, tile, covered, index);
  else index.set(all);
  geo.setDrawRange(0, count);
  geo.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  geo.setAttribute("normal", new THREE.BufferAttribute(nor, 3));
  geo.setAttribute("color", new THREE.BufferAttribute(col, 3));
  geo.setAttribute("splatBase", new THREE.BufferAttribute(splat.base, 3));
  geo.setAttribute("splatSpan", new THREE.BufferAttribute(splat.span, 3));
  geo.setAttribute("splatSel", new THREE.BufferAttribute(splat.sel, 4, true));
  geo.setAttribute("ptexMacro", new THREE.BufferAttribute(macro, 3));
  geo.computeBoundingSphere();
  geo.computeBoundingBox();
  const mesh = new THREE.Mesh(geo, material);
  mesh.position.set(tile.originX, 0, tile.originZ);
  mesh.matrixAutoUpdate = false;
  mesh.updateMatrix();
  setWater(mesh, tile);
  return mesh;
}

export function disposeMesh(mesh: THREE.Mesh): void {
  mesh.geometry.dispose();
  if (mesh.material !== terrainMaterial && mesh.material !== splatMaterial) (mesh.material as THREE.Material).dispose();
  for (const child of mesh.children) {
    if (child instanceof THREE.Mesh) child.geometry.dispose();
  }
}
