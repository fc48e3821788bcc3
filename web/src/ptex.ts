// Ptex pages on the height tiles (stream protocol v2, frame kind 3; api/ptex_pages_v1.md): the
// pages the stream sends are kept in one texture array per detail level, and each tile is drawn
// with the albedo of its 4 × 4 faces' pages, lit by the tile's normals.
//
// Storage: level `l` holds pages of `S = 8·2^l + 2` texels a side (with their one-texel borders).
// The stream gives each page a slot of its level; slots are packed `g × g` to a layer of the
// level's `THREE.DataArrayTexture` (`g = ⌊264 / S⌋`: 26² vista pages or one 256² page a layer), so
// even thousands of slots need few layers. The array grows (doubling) when a slot lies past it.
//
// Drawing: each tile's material is the terrain's Lambert material with a face table (per face:
// level, layer and the page's corner in the layer, level −1 for a face without a page). The
// fragment shader finds the face and its uv from the tile-local lattice position, and samples the
// page at texel `1 + uv·R`: inside the border, with linear filtering, so at a face's edge it
// blends its own edge texels with the border texels, which are the neighbour's, as the neighbour
// does from its side; the faces meet without a seam. A face without a page keeps the vertex
// colours, or the texture splatting of ./splat.ts when the store is given it (the page takes
// precedence: it is the server's bake of the same materials; the splat is evaluated only for the
// faces without a page). A face's best page is drawn: its detail page if it holds one, else its vista page.
//
// Volume chunks (the view asks for their faces' pages with `ptex.chunks`): a chunk face is a
// surface-nets quad, its uv square the quad's (vertex 0 at (0, 0), 1 (1, 0), 2 (1, 1), 3 (0, 1),
// api/chunk_format_v1.md). The chunk mesh gives each quad four vertices of its own with their
// uv (./chunk.ts) and a per-vertex page entry (level, layer, page corner, as a tile's face
// table), which the store fills as the quad's pages arrive (`chunkFaces`); the chunks share one
// material (`chunkMaterial`) that samples the same texture arrays at `1 + uv·R`.
import * as THREE from "three";
import type { PtexPages } from "./ptexFormat";
import { tileKey } from "./view";
import { chunkKey } from "./chunkFormat";

const LEVELS = 6;
/** Tile faces per side (api/ptex_pages_v1.md: 4 × 4 faces, 16 lattice cells each). */
const FACES = 4;
const CELLS_PER_FACE = 16;

/** Page side with borders, pages per layer row and layer side (texels) of level `l`. */
function geometry(l: number): { s: number; g: number; side: number } {
  const s = (8 << l) + 2;
  const g = Math.max(1, Math.floor(264 / s));
  return { s, g, side: g * s };
}

interface Level {
  s: number;
  g: number;
  side: number;
  layers: number;
  texture: THREE.DataArrayTexture | undefined;
  /** The slot each face holds at this level, and the face each slot holds. */
  owner: Map<number, string>;
}

/** A face with pages: a tile's (`lod`, `fx`, `fz`) or, with `chunk` set, quad `quad` of that
 * chunk. */
interface Face {
  lod: number;
  fx: number;
  fz: number;
  chunk?: string;
  quad?: number;
  vista?: number;
  detail?: { level: number; slot: number };
}

/** A held chunk's face entries (per quad: level, layer, page corner x, y; level −1 without a
 * page) and what to tell when one changes. */
interface ChunkFaces {
  quads: number;
  table: Float32Array;
  changed: (quad: number) => void;
}

const faceKey = (lod: number, fx: number, fz: number): string => `${lod}/${fx}/${fz}`;
const chunkFaceKey = (chunk: string, quad: number): string => `c:${chunk}:${quad}`;
const faceTile = (f: Face): string => tileKey(f.lod, Math.floor(f.fx / FACES), Math.floor(f.fz / FACES));

/** The GLSL that samples level `l`'s array (constant sampler per branch, as GLSL ES 3.0 wants). */
function sampleLevels(): string {
  const lines = ["vec3 ptexAlbedo(int level, vec2 texel, float layer) {"];
  for (let l = 0; l < LEVELS; l++) {
    const { side } = geometry(l);
    lines.push(`  if (level == ${l}) return textureLod(ptexAtlas${l}, vec3(texel / ${side}.0, layer), 0.0).rgb;`);
  }
  lines.push("  return vec3(1.0);", "}");
  return lines.join("\n");
}

const VERTEX_PARS = `
uniform float ptexSpacing;
attribute vec3 ptexMacro;
varying vec2 vPtexCell;
varying vec3 vPtexMacro;`;

const FRAGMENT_PARS = `
varying vec2 vPtexCell;
varying vec3 vPtexMacro;
uniform vec4 ptexFace[${FACES * FACES}];
${Array.from({ length: LEVELS }, (_, l) => `uniform highp sampler2DArray ptexAtlas${l};`).join("\n")}
${sampleLevels()}`;

// A chunk's vertices carry their quad's page entry and their uv in it (./chunk.ts).
const CHUNK_VERTEX_PARS = `
attribute vec4 ptexPage;
attribute vec2 ptexUv;
varying vec4 vPtexPage;
varying vec2 vPtexUv;`;

const CHUNK_FRAGMENT_PARS = `
varying vec4 vPtexPage;
varying vec2 vPtexUv;
${Array.from({ length: LEVELS }, (_, l) => `uniform highp sampler2DArray ptexAtlas${l};`).join("\n")}
${sampleLevels()}`;

// After the vertex colours: the quad's page, if it has one (the entry is the same at the quad's
// four vertices), read at texel 1 + uv·R as a tile face's.
const CHUNK_FRAGMENT_PTEX = `
{
#ifdef STRATA_SPLAT
  vec3 splatP = strataSplatPosition();
  vec3 splatGx = dFdx(splatP);
  vec3 splatGy = dFdy(splatP);
#endif
  if (vPtexPage.x >= -0.5) {
    float level = floor(vPtexPage.x + 0.5);
    float res = 8.0 * exp2(level);
    vec2 texel = floor(vPtexPage.zw + 0.5) + 1.0 + clamp(vPtexUv, 0.0, 1.0) * res;
    diffuseColor.rgb = ptexAlbedo(int(level), texel, floor(vPtexPage.y + 0.5));
  }
#ifdef STRATA_SPLAT
  else {
    diffuseColor.rgb = strataSplat(splatP, splatGx, splatGy);
  }
#endif
}`;

// After the vertex colours: the face's page, if it has one. The tile's vertex (i, j) sits at
// (i·spacing, j·spacing) in the mesh (skirts repeat their edge vertex's x and z). Face (fi, fj)
// covers cells 16·fi … 16·fi + 16 east and 16·fj … south; its u runs south and v east, and texel
// (i along u, j along v) is at column i + 1, row j + 1 of the page. Under water the page's albedo
// is drawn as it is (the vertex colours lean to the water's colour in deep water): the water sheet
// over it is what shows the water, and it must stand out from the ground it covers.
const FRAGMENT_PTEX = `
{
#ifdef STRATA_SPLAT
  vec3 splatP = strataSplatPosition();
  vec3 splatGx = dFdx(splatP);
  vec3 splatGy = dFdy(splatP);
#endif
  vec2 cell = clamp(vPtexCell, 0.0, ${FACES * CELLS_PER_FACE}.0);
  vec2 f = min(floor(cell / ${CELLS_PER_FACE}.0), vec2(${FACES - 1}.0));
  vec4 page = ptexFace[int(f.y) * ${FACES} + int(f.x)];
  if (page.x >= 0.0) {
    vec2 local = cell / ${CELLS_PER_FACE}.0 - f;
    float res = 8.0 * exp2(page.x);
    vec2 texel = page.zw + 1.0 + local.yx * res;
    // The large-scale variation of the tile's vertices (./splat.ts, macroFactor).
    diffuseColor.rgb = ptexAlbedo(int(page.x + 0.5), texel, page.y) * vPtexMacro;
  }
#ifdef STRATA_SPLAT
  else {
    diffuseColor.rgb = strataSplat(splatP, splatGx, splatGy);
  }
#endif
}`;

/** The pages a stream session sent, in texture arrays, and the face tables of the tiles. */
export class PtexStore {
  private readonly levels: Level[] = [];
  private readonly faces = new Map<string, Face>();
  /** Per held chunk key, its faces' entries. */
  private readonly chunks = new Map<string, ChunkFaces>();
  private chunkShared: THREE.MeshLambertMaterial | undefined;
  /** Per tile key, 16 × (level, layer, page corner x, y): what its material reads. */
  private readonly tables = new Map<string, Float32Array>();
  private readonly atlas: Record<string, { value: THREE.DataArrayTexture | null }> = {};
  private readonly maxLayers: number;

  /** Pages written into the arrays for faces of held tiles (since the page loaded). */
  applied = 0;

  /** A further patch of the tiles' shaders, applied after the pages' (the splatting), and its
   * name in the program cache key. */
  private readonly extra: { patch: (shader: THREE.WebGLProgramParametersWithUniforms) => void; key: string } | undefined;

  constructor(maxLayers: number, extra?: { patch: (shader: THREE.WebGLProgramParametersWithUniforms) => void; key: string }) {
    this.maxLayers = Math.max(1, maxLayers);
    this.extra = extra;
    for (let l = 0; l < LEVELS; l++) {
      this.levels.push({ ...geometry(l), layers: 0, texture: undefined, owner: new Map() });
      this.atlas[`ptexAtlas${l}`] = { value: null };
    }
  }

  /** The face table of tile `key` (all faces without a page until pages arrive). */
  private table(key: string): Float32Array {
    let t = this.tables.get(key);
    if (!t) {
      t = new Float32Array(4 * FACES * FACES);
      for (let f = 0; f < FACES * FACES; f++) t[4 * f] = -1;
      this.tables.set(key, t);
    }
    return t;
  }

  /** A material for tile `key` (vertex spacing `spacing` metres) that draws its faces' pages. */
  material(key: string, spacing: number): THREE.MeshLambertMaterial {
    // With the splatting, a face without a page is splatted: the vertex colours are not read.
    const m = new THREE.MeshLambertMaterial({ vertexColors: !this.extra });
    const table = this.table(key);
    m.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, this.atlas, {
        ptexFace: { value: table },
        ptexSpacing: { value: spacing },
      });
      shader.vertexShader = shader.vertexShader
        .replace("#include <common>", `#include <common>${VERTEX_PARS}`)
        .replace("#include <begin_vertex>", "#include <begin_vertex>\n  vPtexCell = position.xz / ptexSpacing;\n  vPtexMacro = ptexMacro;");
      shader.fragmentShader = shader.fragmentShader
        .replace("#include <common>", `#include <common>${FRAGMENT_PARS}`)
        .replace("#include <color_fragment>", `#include <color_fragment>${FRAGMENT_PTEX}`);
      // The splatting (./splat.ts) defines what the page's else branch calls.
      this.extra?.patch(shader);
    };
    const cacheKey = `strata-ptex-tile${this.extra ? `-${this.extra.key}` : ""}`;
    m.customProgramCacheKey = () => cacheKey;
    return m;
  }

  /** The material every chunk mesh shares: its quads' pages, else the splat (or the vertex
   * colours), double-sided and pushed back in depth as ./chunk.ts's. */
  chunkMaterial(): THREE.MeshLambertMaterial {
    if (this.chunkShared) return this.chunkShared;
    const m = new THREE.MeshLambertMaterial({
      vertexColors: !this.extra,
      side: THREE.DoubleSide,
      polygonOffset: true,
      polygonOffsetFactor: 2,
      polygonOffsetUnits: 4,
    });
    m.onBeforeCompile = (shader) => {
      Object.assign(shader.uniforms, this.atlas);
      shader.vertexShader = shader.vertexShader
        .replace("#include <common>", `#include <common>${CHUNK_VERTEX_PARS}`)
        .replace("#include <begin_vertex>", "#include <begin_vertex>\n  vPtexPage = ptexPage;\n  vPtexUv = ptexUv;");
      shader.fragmentShader = shader.fragmentShader
        .replace("#include <common>", `#include <common>${CHUNK_FRAGMENT_PARS}`)
        .replace("#include <color_fragment>", `#include <color_fragment>${CHUNK_FRAGMENT_PTEX}`);
      this.extra?.patch(shader);
    };
    const cacheKey = `strata-ptex-chunk${this.extra ? `-${this.extra.key}` : ""}`;
    m.customProgramCacheKey = () => cacheKey;
    this.chunkShared = m;
    return m;
  }

  /** The face entries of chunk `key` with `quads` quads (4 floats a quad: level, layer, page
   * corner; level −1 without a page), `changed` called with a quad whose entry changes. A chunk
   * held again with as many quads keeps its pages until new ones arrive; with another count its
   * faces are forgotten (the server holds the new quads afresh). */
  chunkFaces(key: string, quads: number, changed: (quad: number) => void): Float32Array {
    const held = this.chunks.get(key);
    if (held && held.quads === quads) {
      held.changed = changed;
      return held.table;
    }
    if (held) this.forgetChunk(key);
    const table = new Float32Array(4 * quads);
    for (let q = 0; q < quads; q++) table[4 * q] = -1;
    this.chunks.set(key, { quads, table, changed });
    return table;
  }

  /** Frees the pages of the chunks not in `wanted` (keys of the view's chunks). */
  keepChunks(wanted: Set<string>): void {
    for (const key of [...this.chunks.keys()]) if (!wanted.has(key)) this.forgetChunk(key);
  }

  private forgetChunk(key: string): void {
    const held = this.chunks.get(key);
    if (!held) return;
    for (let q = 0; q < held.quads; q++) {
      const fk = chunkFaceKey(key, q);
      const face = this.faces.get(fk);
      if (!face) continue;
      if (face.vista !== undefined) this.free(fk, { level: 0, slot: face.vista });
      if (face.detail) this.free(fk, face.detail);
      this.faces.delete(fk);
    }
    this.chunks.delete(key);
  }

  /** Writes the pages of a frame whose tiles `holds` says are held (a frame of chunk faces:
   * whose chunks `holdsChunk` says are, with the face entries of `chunkFaces`); returns how
   * many. */
  put(pages: PtexPages, holds: (tile: string) => boolean, holdsChunk: (chunk: string) => boolean = () => false): number {
    const level = this.levels[pages.level];
    const texels = level.s * level.s * 4;
    let n = 0;
    for (let k = 0; k < pages.count; k++) {
      let key: string;
      let face: Face;
      if (pages.chunk) {
        const chunk = chunkKey(pages.lod[k], pages.fx[k], pages.y[k], pages.fz[k]);
        const held = this.chunks.get(chunk);
        if (!held || pages.quad[k] >= held.quads || !holdsChunk(chunk)) continue; // not held (any more)
        key = chunkFaceKey(chunk, pages.quad[k]);
        face = this.faces.get(key) ?? { lod: pages.lod[k], fx: pages.fx[k], fz: pages.fz[k], chunk, quad: pages.quad[k] };
      } else {
        key = faceKey(pages.lod[k], pages.fx[k], pages.fz[k]);
        face = this.faces.get(key) ?? { lod: pages.lod[k], fx: pages.fx[k], fz: pages.fz[k] };
        if (!holds(faceTile(face))) continue; // its tile left the view since
      }
      const slot = pages.slot[k];
      if (!this.write(pages.level, slot, pages.albedo.subarray(k * texels, (k + 1) * texels))) continue;
      this.faces.set(key, face);
      // A page that fills a slot replaces whatever face held it.
      const before = level.owner.get(slot);
      if (before !== undefined && before !== key) {
        const other = this.faces.get(before);
        if (other) {
          if (pages.level === 0) other.vista = undefined;
          else other.detail = undefined;
          this.refresh(other);
        }
      }
      level.owner.set(slot, key);
      if (pages.level === 0) {
        face.vista = slot;
      } else {
        if (face.detail && (face.detail.level !== pages.level || face.detail.slot !== slot)) this.free(key, face.detail);
        face.detail = { level: pages.level, slot };
      }
      this.refresh(face);
      n++;
    }
    this.applied += n;
    return n;
  }

  /** The faces (`[lod, fx, fz]` of a tile's, `[lod, x, y, z, quad]` of a chunk's) that left
   * their detail level keep their vista page. */
  toVista(faces: number[][]): void {
    for (const f of faces) {
      const key = f.length === 5 ? chunkFaceKey(chunkKey(f[0], f[1], f[2], f[3]), f[4]) : faceKey(f[0], f[1], f[2]);
      const face = this.faces.get(key);
      if (!face?.detail) continue;
      this.free(key, face.detail);
      face.detail = undefined;
      this.refresh(face);
    }
  }

  /** Frees the pages of the tile faces whose tile is not in `tiles` (keys of the view's tiles). */
  keep(tiles: Set<string>): void {
    for (const [key, face] of [...this.faces]) {
      if (face.chunk !== undefined || tiles.has(faceTile(face))) continue;
      if (face.vista !== undefined) this.free(key, { level: 0, slot: face.vista });
      if (face.detail) this.free(key, face.detail);
      this.faces.delete(key);
    }
    for (const [key, t] of [...this.tables]) {
      if (tiles.has(key)) continue;
      for (let f = 0; f < FACES * FACES; f++) t[4 * f] = -1;
      this.tables.delete(key);
    }
  }

  /** Forgets every page (a new stream session starts afresh); the held tiles' tables stay theirs,
   * with no page until the new session's pages arrive. */
  clear(): void {
    for (const level of this.levels) level.owner.clear();
    this.faces.clear();
    for (const t of this.tables.values()) for (let f = 0; f < FACES * FACES; f++) t[4 * f] = -1;
    for (const c of this.chunks.values()) {
      for (let q = 0; q < c.quads; q++) {
        c.table[4 * q] = -1;
        c.changed(q);
      }
    }
  }

  /** Tile faces with a page and, of those, with a detail page; the same of chunk faces. */
  stats(): { faces: number; detail: number; chunkFaces: number; chunkDetail: number } {
    const out = { faces: 0, detail: 0, chunkFaces: 0, chunkDetail: 0 };
    for (const f of this.faces.values()) {
      const paged = f.vista !== undefined || f.detail !== undefined;
      if (f.chunk !== undefined) {
        if (paged) out.chunkFaces++;
        if (f.detail) out.chunkDetail++;
      } else {
        if (paged) out.faces++;
        if (f.detail) out.detail++;
      }
    }
    return out;
  }

  private free(key: string, at: { level: number; slot: number }): void {
    const owner = this.levels[at.level].owner;
    if (owner.get(at.slot) === key) owner.delete(at.slot);
  }

  /** Points the face's table entry at its best page (or at none). */
  private refresh(face: Face): void {
    let t: Float32Array;
    let e: number;
    let chunk: ChunkFaces | undefined;
    if (face.chunk !== undefined) {
      chunk = this.chunks.get(face.chunk);
      if (!chunk || face.quad === undefined || face.quad >= chunk.quads) return;
      t = chunk.table;
      e = 4 * face.quad;
    } else {
      t = this.table(faceTile(face));
      const fi = face.fx - FACES * Math.floor(face.fx / FACES);
      const fj = face.fz - FACES * Math.floor(face.fz / FACES);
      e = 4 * (fj * FACES + fi);
    }
    this.point(face, t, e);
    if (chunk && face.quad !== undefined) chunk.changed(face.quad);
  }

  /** Writes the entry at `e` of `t` for the face's best page (or none). */
  private point(face: Face, t: Float32Array, e: number): void {
    const at = face.detail ?? (face.vista !== undefined ? { level: 0, slot: face.vista } : undefined);
    if (!at) {
      t[e] = -1;
      return;
    }
    const { s, g } = this.levels[at.level];
    const cell = at.slot % (g * g);
    t[e] = at.level;
    t[e + 1] = Math.floor(at.slot / (g * g));
    t[e + 2] = (cell % g) * s;
    t[e + 3] = Math.floor(cell / g) * s;
  }

  /** Copies one page into slot `slot` of level `l`, growing the array; false if it cannot. */
  private write(l: number, slot: number, albedo: Uint8Array): boolean {
    const level = this.levels[l];
    const { s, g, side } = level;
    const layer = Math.floor(slot / (g * g));
    if (layer >= this.maxLayers) return false;
    if (layer >= level.layers) this.grow(l, Math.min(this.maxLayers, Math.max(layer + 1, 2 * level.layers)));
    const texture = level.texture as THREE.DataArrayTexture;
    const data = texture.image.data as Uint8Array;
    const cell = slot % (g * g);
    const x0 = (cell % g) * s;
    const y0 = Math.floor(cell / g) * s;
    for (let row = 0; row < s; row++) {
      data.set(albedo.subarray(row * s * 4, (row + 1) * s * 4), ((layer * side + y0 + row) * side + x0) * 4);
    }
    texture.addLayerUpdate(layer);
    texture.needsUpdate = true;
    return true;
  }

  private grow(l: number, layers: number): void {
    const level = this.levels[l];
    const data = new Uint8Array(level.side * level.side * 4 * layers);
    const old = level.texture;
    if (old) data.set(old.image.data as Uint8Array);
    const texture = new THREE.DataArrayTexture(data, level.side, level.side, layers);
    texture.format = THREE.RGBAFormat;
    texture.type = THREE.UnsignedByteType;
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.minFilter = THREE.LinearFilter;
    texture.magFilter = THREE.LinearFilter;
    texture.wrapS = THREE.ClampToEdgeWrapping;
    texture.wrapT = THREE.ClampToEdgeWrapping;
    texture.generateMipmaps = false;
    // Uploads go layer by layer: the layers the old array held go up with the first.
    for (let i = 0; i < level.layers; i++) texture.addLayerUpdate(i);
    texture.needsUpdate = true;
    old?.dispose();
    level.texture = texture;
    level.layers = layers;
    this.atlas[`ptexAtlas${l}`].value = texture;
  }
}
