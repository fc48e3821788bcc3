// Texture splatting of the height tiles by their material weights, with procedural textures made
// in the bundle (no image assets).
//
// Weights: a tile vertex carries its dominant ground material (api/tile_format_v1.md: 0 seabed,
// 1 sand, 2 grass, 3 dirt, 4 rock, 5 snow; 6 mud in chunks to come). Each vertex gets that
// material's one-hot vector (`splatA` materials 0–3, `splatB` 4–7) and the rasteriser
// interpolates it across the triangles, so a fragment's weights blend the materials of its
// triangle's corners: the weights the Ptex bake gives a texel from its four control samples
// (`src/ptex/bake.rs`, step 1).
//
// Textures: at start-up, `makePatterns` fills a 2-layer 128² RGBA texture array with tileable
// value-noise fBm (integer hashing, quintic fade; the same bytes on every machine): layer 0 repeats
// every FINE_M metres, layer 1 every COARSE_M metres (each read rotated, so the repeats do not line
// up with the world's axes), and each of their four channels is a pattern of its own frequency. A material's pattern value `t` is `½ + f·(fine − ½) + c·(coarse − ½)` of
// its channel (materials 4–7 read the channels rotated), clamped, and its albedo `base + (tint −
// base)·t` with the base and tint of the Ptex bake's material (`src/ptex/material.rs`,
// `DEFAULT_GROUND`), so a face drawn before and after its Ptex page arrives keeps its palette.
// The patterns are projected tri-planarly (weights `n⁴/Σn⁴` of the vertex normal, as the bake):
// ground whose normal is within about 20° of vertical reads the top projection alone (two
// texture reads a fragment), steeper ground all three (six), with explicit gradients so the
// branches keep their mipmaps.
//
// Then the biome tint (a fifth of the albedo, where the vertex colours take 45 %) and the water are
// blended in as the vertex colours do (`splatTint`: the biome colour and the water's share), and
// the result replaces the vertex colour. Ptex pages, where a face has one, replace it in turn
// (./ptex.ts applies its page after this): the page is the server's bake of the same materials, so
// the pages take precedence and the splat is what a face without a page shows; the page has no
// biome tint, so a face whose page arrives loses the splat's fifth of biome colour.
import * as THREE from "three";

/** Texels a side of each pattern layer. */
const SIZE = 128;
/** Metres one repeat of the fine and of the coarse layer covers. */
const FINE_M = 16;
const COARSE_M = 256;
/** Lattice cells a repeat and octaves of each layer's four patterns (power-of-two cells tile). */
const PATTERNS = [
  [
    [8, 4],
    [16, 3],
    [4, 4],
    [8, 3],
  ],
  [
    [4, 4],
    [2, 4],
    [8, 3],
    [4, 3],
  ],
];

// The Ptex bake's ground materials (sRGB base and tint, src/ptex/material.rs DEFAULT_GROUND):
// seabed, sand, grass, dirt, rock, snow, mud; slot 7 reads rock.
const BASE = [
  [0.4, 0.37, 0.3],
  [0.84, 0.76, 0.57],
  [0.35, 0.47, 0.19],
  [0.47, 0.38, 0.27],
  [0.52, 0.51, 0.49],
  [0.93, 0.94, 0.96],
  [0.31, 0.25, 0.18],
  [0.52, 0.51, 0.49],
];
const TINT = [
  [0.27, 0.29, 0.24],
  [0.71, 0.62, 0.44],
  [0.21, 0.33, 0.11],
  [0.34, 0.26, 0.18],
  [0.33, 0.32, 0.31],
  [0.8, 0.85, 0.92],
  [0.22, 0.17, 0.12],
  [0.33, 0.32, 0.31],
];
/** Per material, how much of the fine and of the coarse pattern its `t` takes. */
const FINE_AMP = [1.2, 1.6, 1.8, 1.6, 1.4, 0.8, 1.2, 1.4];
const COARSE_AMP = [1.6, 1.0, 1.6, 1.4, 2.0, 1.2, 1.4, 2.0];
/** The biome tint's share of the albedo. */
const BIOME_SHARE = 0.2;

/** A 32-bit integer hash of (seed, x, y) in [0, 1). */
function hash(seed: number, x: number, y: number): number {
  let h = Math.imul(seed ^ 0x9e3779b9, 0x85ebca6b) ^ Math.imul(x, 0xc2b2ae35) ^ Math.imul(y, 0x27d4eb2f);
  h = Math.imul(h ^ (h >>> 15), 0x2c1b3c6d);
  h = Math.imul(h ^ (h >>> 12), 0x297a2d39);
  h ^= h >>> 15;
  return (h >>> 0) / 4294967296;
}

const fade = (t: number) => t * t * t * (t * (t * 6 - 15) + 10);

/** Value noise at (u, v) in [0, 1)² on a lattice of `cells` cells per side that wraps. */
function valueNoise(seed: number, cells: number, u: number, v: number): number {
  const x = u * cells;
  const y = v * cells;
  const i = Math.floor(x);
  const j = Math.floor(y);
  const fx = fade(x - i);
  const fy = fade(y - j);
  const at = (a: number, b: number) => hash(seed, ((a % cells) + cells) % cells, ((b % cells) + cells) % cells);
  const top = at(i, j) + (at(i + 1, j) - at(i, j)) * fx;
  const bottom = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * fx;
  return top + (bottom - top) * fy;
}

/** The patterns' bytes: layer-major, row-major, RGBA. */
export function makePatterns(): Uint8Array {
  const data = new Uint8Array(SIZE * SIZE * 4 * PATTERNS.length);
  PATTERNS.forEach((layer, l) => {
    layer.forEach(([cells, octaves], c) => {
      const seed = 1 + 4 * l + c;
      for (let y = 0; y < SIZE; y++) {
        for (let x = 0; x < SIZE; x++) {
          let sum = 0;
          let amp = 0.5;
          let norm = 0;
          for (let o = 0; o < octaves; o++) {
            sum += amp * valueNoise(seed * 31 + o, cells << o, x / SIZE, y / SIZE);
            norm += amp;
            amp *= 0.5;
          }
          data[((l * SIZE + y) * SIZE + x) * 4 + c] = Math.round((255 * sum) / norm);
        }
      }
    });
  });
  return data;
}

const linear = (rgb: number[]) => new THREE.Color().setRGB(rgb[0], rgb[1], rgb[2], THREE.SRGBColorSpace);
const vec4 = (a: number[], from: number) => new THREE.Vector4(a[from], a[from + 1], a[from + 2], a[from + 3]);

let uniforms: Record<string, THREE.IUniform> | undefined;

/** The uniforms every splatted material shares (the pattern array is made on first use). */
function sharedUniforms(water: THREE.Color): Record<string, THREE.IUniform> {
  if (uniforms) return uniforms;
  const texture = new THREE.DataArrayTexture(makePatterns(), SIZE, SIZE, PATTERNS.length);
  texture.format = THREE.RGBAFormat;
  texture.type = THREE.UnsignedByteType;
  texture.colorSpace = THREE.NoColorSpace;
  texture.wrapS = THREE.RepeatWrapping;
  texture.wrapT = THREE.RepeatWrapping;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  texture.needsUpdate = true;
  uniforms = {
    splatPatterns: { value: texture },
    splatBase: { value: BASE.map(linear) },
    splatTintColour: { value: TINT.map(linear) },
    splatFineA: { value: vec4(FINE_AMP, 0) },
    splatFineB: { value: vec4(FINE_AMP, 4) },
    splatCoarseA: { value: vec4(COARSE_AMP, 0) },
    splatCoarseB: { value: vec4(COARSE_AMP, 4) },
    splatWater: { value: water },
  };
  return uniforms;
}

const VERTEX_PARS = `
attribute vec4 splatA;
attribute vec4 splatB;
attribute vec4 splatTint;
varying vec4 vSplatA;
varying vec4 vSplatB;
varying vec4 vSplatTint;
varying vec3 vSplatPos;
varying vec3 vSplatNormal;`;

const VERTEX = `
  vSplatA = splatA;
  vSplatB = splatB;
  vSplatTint = splatTint;
  vSplatPos = (modelMatrix * vec4(transformed, 1.0)).xyz;
  vSplatNormal = normal;`;

const FRAGMENT_PARS = `
varying vec4 vSplatA;
varying vec4 vSplatB;
varying vec4 vSplatTint;
varying vec3 vSplatPos;
varying vec3 vSplatNormal;
uniform highp sampler2DArray splatPatterns;
uniform vec3 splatBase[8];
uniform vec3 splatTintColour[8];
uniform vec4 splatFineA;
uniform vec4 splatFineB;
uniform vec4 splatCoarseA;
uniform vec4 splatCoarseB;
uniform vec3 splatWater;
// The layers are read rotated (by 37° and −23°), so neither repeats along the lattice axes.
const mat2 SPLAT_ROT0 = mat2(0.7986, 0.6018, -0.6018, 0.7986);
const mat2 SPLAT_ROT1 = mat2(0.9205, -0.3907, 0.3907, 0.9205);
vec4 splatRead(vec2 q, vec2 gx, vec2 gy, float layer, float repeat) {
  mat2 r = (layer < 0.5 ? SPLAT_ROT0 : SPLAT_ROT1) / repeat;
  return textureGrad(splatPatterns, vec3(r * q, layer), r * gx, r * gy);
}`;

// Tri-planar projections as the Ptex bake's: X reads (y, z), Y (z, x), Z (x, y).
const FRAGMENT = `
{
  vec3 sn = normalize(vSplatNormal);
  vec3 a = sn * sn;
  a = a * a;
  a /= (a.x + a.y + a.z);
  vec3 p = vSplatPos;
  vec3 gx = dFdx(p);
  vec3 gy = dFdy(p);
  vec4 fine = splatRead(p.zx, gx.zx, gy.zx, 0.0, ${FINE_M}.0);
  vec4 coarse = splatRead(p.zx, gx.zx, gy.zx, 1.0, ${COARSE_M}.0);
  if (a.y < 0.97) {
    fine = a.y * fine + a.x * splatRead(p.yz, gx.yz, gy.yz, 0.0, ${FINE_M}.0)
      + a.z * splatRead(p.xy, gx.xy, gy.xy, 0.0, ${FINE_M}.0);
    coarse = a.y * coarse + a.x * splatRead(p.yz, gx.yz, gy.yz, 1.0, ${COARSE_M}.0)
      + a.z * splatRead(p.xy, gx.xy, gy.xy, 1.0, ${COARSE_M}.0);
  }
  vec4 tA = clamp(0.5 + splatFineA * (fine - 0.5) + splatCoarseA * (coarse - 0.5), 0.0, 1.0);
  vec4 tB = clamp(0.5 + splatFineB * (fine.yzwx - 0.5) + splatCoarseB * (coarse.wxyz - 0.5), 0.0, 1.0);
  float total = max(dot(vSplatA, vec4(1.0)) + dot(vSplatB, vec4(1.0)), 1e-4);
  vec3 albedo = vec3(0.0);
  for (int m = 0; m < 4; m++) {
    albedo += vSplatA[m] * mix(splatBase[m], splatTintColour[m], tA[m]);
    albedo += vSplatB[m] * mix(splatBase[m + 4], splatTintColour[m + 4], tB[m]);
  }
  albedo = mix(albedo / total, vSplatTint.rgb, ${BIOME_SHARE});
  diffuseColor.rgb = mix(albedo, splatWater, vSplatTint.a);
}`;

/** Adds the splatting to a Lambert shader: after the vertex colours, before anything a later
 * patch inserts after `#include <color_fragment>` (call it after such a patch, e.g. Ptex's). */
export function addSplat(shader: THREE.WebGLProgramParametersWithUniforms, water: THREE.Color): void {
  Object.assign(shader.uniforms, sharedUniforms(water));
  shader.vertexShader = shader.vertexShader
    .replace("#include <common>", `#include <common>${VERTEX_PARS}`)
    .replace("#include <begin_vertex>", `#include <begin_vertex>${VERTEX}`);
  shader.fragmentShader = shader.fragmentShader
    .replace("#include <common>", `#include <common>${FRAGMENT_PARS}`)
    .replace("#include <color_fragment>", `#include <color_fragment>${FRAGMENT}`);
}

/** The splat attributes of vertex `v` of a tile: its material's one-hot weights (materials 0–3 in
 * `a`, 4–7 in `b`) and `tint` (the biome colour, linear, and the water's share), as bytes. */
export function splatVertex(
  v: number,
  material: number,
  biome: THREE.Color,
  water: number,
  a: Uint8Array,
  b: Uint8Array,
  tint: Uint8Array,
): void {
  const m = Math.min(7, material);
  a[4 * v + 0] = m === 0 ? 255 : 0;
  a[4 * v + 1] = m === 1 ? 255 : 0;
  a[4 * v + 2] = m === 2 ? 255 : 0;
  a[4 * v + 3] = m === 3 ? 255 : 0;
  b[4 * v + 0] = m === 4 ? 255 : 0;
  b[4 * v + 1] = m === 5 ? 255 : 0;
  b[4 * v + 2] = m === 6 ? 255 : 0;
  b[4 * v + 3] = m === 7 ? 255 : 0;
  tint[4 * v + 0] = Math.round(255 * Math.min(1, biome.r));
  tint[4 * v + 1] = Math.round(255 * Math.min(1, biome.g));
  tint[4 * v + 2] = Math.round(255 * Math.min(1, biome.b));
  tint[4 * v + 3] = Math.round(255 * Math.min(1, water));
}
