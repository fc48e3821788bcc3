// Texture splatting of the height tiles by their material weights, with procedural textures made
// in the bundle (no image assets).
//
// Weights: a tile vertex carries its dominant ground material (api/tile_format_v1.md: 0 seabed,
// 1 sand, 2 grass, 3 dirt, 4 rock, 5 snow; 6 mud in chunks to come), a one-hot weight vector. The
// vertex attributes are linear in it and the rasteriser interpolates them across the triangles,
// so a fragment blends the materials of its triangle's corners by their interpolated weights: the
// weights the Ptex bake gives a texel from its four control samples (`src/ptex/bake.rs`, step 1).
//
// Textures: at start-up, `makePatterns` fills a 256² RGBA texture with tileable value-noise fBm
// (integer hashing, quintic fade; the same bytes on every machine) repeating every REPEAT_M metres
// (read rotated, so the repeats do not line up with the world's axes; mipmapped, so the finer
// octaves fade with distance); each channel is a pattern of its own frequencies. Material m's
// pattern value is `t = ½ + A·(P − ½)` (P its channel, m mod 4; A its amplitude), clamped, and its
// albedo `base + (tint − base)·t` with the base and tint of the Ptex bake's material
// (`src/ptex/material.rs`, `DEFAULT_GROUND`), so a face keeps its palette when its Ptex page
// arrives. The patterns are projected tri-planarly (weights `n⁴/Σn⁴` of the normal, as the bake),
// each fragment reading the plane of its largest weight (one texture read; see SPLAT_FUNCTION).
//
// The biome tint (a fifth of the albedo, where the vertex colours take 45 %) and the water are
// blended in as the vertex colours do, and the result replaces the vertex colour. Everything
// linear in the weights is computed once per vertex when the mesh is built (`splatVertex`), so a
// fragment computes one pattern value. Ptex pages, where a face has one, take
// precedence (./ptex.ts calls the splat only for the faces without a page): the page is the
// server's bake of the same materials; it has no biome tint, so a face whose page arrives loses
// the splat's fifth of biome colour.
import * as THREE from "three";

/** Texels a side of the pattern texture. */
const SIZE = 256;
/** Metres one repeat of the pattern texture covers (a metre a texel): long enough that the
 * repeats do not show as a grid from the viewer's usual distances. */
const REPEAT_M = 256;
/** Lattice cells a repeat and octaves of the four patterns (power-of-two cells tile): features
 * from 128 m down to a metre, the finer ones averaged away by the mipmaps with distance. */
const PATTERNS = [
  [2, 8],
  [4, 7],
  [2, 7],
  [8, 6],
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
/** Per material, the pattern's amplitude in `t` (small enough that `t` seldom clamps: a clamped
 * pattern shows hard-edged patches). */
const AMP = [1.6, 1.4, 1.8, 1.6, 1.8, 1.0, 1.4, 1.8];
/** The largest amplitude: `splatSel` holds amplitudes over it in bytes. */
const AMP_MAX = 2;
/** The biome tint's share of the albedo. */
const BIOME_SHARE = 0.2;
/** How many times larger than the splat's the macro variation reads the patterns (macroFactor):
 * a repeat of 1 km, features from 512 m down to a few metres. */
const MACRO_SCALE = 4;
/** The second read's scale: a repeat of 1.7 km, incommensurate with the first's. */
const MACRO_SCALE_2 = 6.7;
/** The macro variation's brightness per unit of the two patterns' sum (each spreads about ±0.15
 * around ½: about ±15 % brightness). */
const MACRO_BRIGHTNESS = 0.7;
/** The macro variation's warm/cool shift per unit of the two patterns' sum (red up and blue
 * down, or the reverse). */
const MACRO_WARMTH = 0.3;

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

/** The patterns' bytes: row-major, RGBA (pattern c in channel c). */
export function makePatterns(): Uint8Array {
  const data = new Uint8Array(SIZE * SIZE * 4);
  PATTERNS.forEach(([cells, octaves], c) => {
    const seed = 1 + c;
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
        data[(y * SIZE + x) * 4 + c] = Math.round((255 * sum) / norm);
      }
    }
  });
  return data;
}

let bytes: Uint8Array | undefined;

/** `makePatterns()`, made once for the splat's texture and the macro variation. */
function patternBytes(): Uint8Array {
  bytes ??= makePatterns();
  return bytes;
}

const linear = (rgb: number[]) => new THREE.Color().setRGB(rgb[0], rgb[1], rgb[2], THREE.SRGBColorSpace);
const BASE_LINEAR = BASE.map(linear);
const TINT_LINEAR = TINT.map(linear);

let uniforms: Record<string, THREE.IUniform> | undefined;

/** The uniforms every splatted material shares (the pattern texture is made on first use). */
function sharedUniforms(): Record<string, THREE.IUniform> {
  if (uniforms) return uniforms;
  const texture = new THREE.DataTexture(patternBytes(), SIZE, SIZE);
  texture.format = THREE.RGBAFormat;
  texture.type = THREE.UnsignedByteType;
  texture.colorSpace = THREE.NoColorSpace;
  texture.wrapS = THREE.RepeatWrapping;
  texture.wrapT = THREE.RepeatWrapping;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.generateMipmaps = true;
  texture.needsUpdate = true;
  uniforms = { splatPatterns: { value: texture } };
  return uniforms;
}

// Per vertex (computed once, when the tile's mesh is built: `splatVertex`), everything that is
// linear in the weights: the albedo where the pattern is 0 with the biome tint and the water
// folded in (`splatBase`), what the pattern adds at 1 (`splatSpan`), and each pattern channel's
// share times the material's amplitude (`splatSel`: material m reads channel m mod 4). The
// rasteriser interpolates them, so a fragment pays for one pattern value and one multiply-add, and
// a vertex for three copies (headless Chromium's software renderer draws every vertex of every
// tile, a thousand per tile whatever its size on the screen).
const VERTEX_PARS = `
attribute vec3 splatBase;
attribute vec3 splatSpan;
attribute vec4 splatSel;
varying vec3 vSplatBase;
varying vec3 vSplatSpan;
varying vec4 vSplatSel;`;

const VERTEX = `
  vSplatBase = splatBase;
  vSplatSpan = splatSpan;
  vSplatSel = splatSel * ${AMP_MAX}.0;`;

const FRAGMENT_PARS = `
varying vec3 vSplatBase;
varying vec3 vSplatSpan;
varying vec4 vSplatSel;
uniform sampler2D splatPatterns;
// The texture is read rotated by 37°, so its repeats do not line up with the lattice axes.
const mat2 SPLAT_ROT = mat2(0.7986, 0.6018, -0.6018, 0.7986) / ${REPEAT_M}.0;
// The fragment's world position from Lambert's view-space position (no varying of its own).
vec3 strataSplatPosition() {
  return cameraPosition + (vec4(-vViewPosition, 0.0) * viewMatrix).xyz;
}`;

// The splatted albedo of a fragment at world position `p`, given the screen derivatives of `p`
// (taken in uniform control flow by the caller) and its world normal from Lambert's view-space
// one. Tri-planar projection with one texture read: the fragment reads the plane of its dominant
// tri-planar weight (`n⁴/Σn⁴`, as the Ptex bake's; X reads (y, z), Y (z, x), Z (x, y)) and the
// pattern's contrast fades where the two largest weights come close, so the switch between planes
// on a slope shows no seam. A branch does not save work here: the software renderer of headless
// Chromium runs both sides of a branch its pixels disagree on, and a texture read costs about as
// much as the rest of the fragment. Within one material this is the pattern of the module docs;
// across a material border the pattern value is that of the interpolated channel and amplitude.
const SPLAT_FUNCTION = `
vec3 strataSplat(vec3 p, vec3 gx, vec3 gy) {
  vec3 sn = inverseTransformDirection(normalize(vNormal), viewMatrix);
  vec3 a = sn * sn;
  a = a * a;
  a /= (a.x + a.y + a.z);
  float top = max(a.x, max(a.y, a.z));
  float second = 1.0 - top - min(a.x, min(a.y, a.z));
  bool ySide = a.y >= top;
  bool xSide = !ySide && a.x >= top;
  vec2 q = ySide ? p.zx : (xSide ? p.yz : p.xy);
  vec2 qx = ySide ? gx.zx : (xSide ? gx.yz : gx.xy);
  vec2 qy = ySide ? gy.zx : (xSide ? gy.yz : gy.xy);
  float contrast = clamp((top - second) * 4.0, 0.0, 1.0);
  vec4 pattern = textureGrad(splatPatterns, SPLAT_ROT * q, SPLAT_ROT * qx, SPLAT_ROT * qy);
  float t = clamp(0.5 + contrast * dot(pattern - 0.5, vSplatSel), 0.0, 1.0);
  return vSplatBase + vSplatSpan * t;
}`;

// The large-scale variation drawn over the Ptex pages (./ptex.ts, with or without the
// splatting): a page carries its materials' patterns only down to its texel, and the default
// materials' patterns are finer than a metre, so a vista page (8² texels a face) is one flat colour
// and a meadow seen from a few hundred metres reads as a uniform green blanket, with the faces
// holding detail pages standing out as grainy squares. `macroFactor` varies the albedo over tens
// to hundreds of metres, the same at every page level and across faces and tiles (a function of
// the world position): brightness and a warm or cool shift, each the sum of two patterns read at
// MACRO_SCALE and MACRO_SCALE_2 times the splat's scale, turned by different angles, so the sum
// repeats at neither period (one read alone tiles a 1 km grid of blobs across the far plains). It
// is computed per vertex when a tile's mesh is built (./mesh.ts; a fragment pays one multiply, no
// texture read: headless Chromium's software renderer is slow enough already) from the pattern
// bytes' box-filtered mip at the tile's vertex spacing, so coarse tiles see the patterns' coarse
// octaves only, as a mipmapped read would.

/** The patterns' mip chain for `macroFactor`: level `l` holds `(SIZE >> l)²` texels of four
 * channels in [0, 1], each the mean of the 2 × 2 texels below it. */
let macroMips: Float32Array[] | undefined;

function macroLevels(): Float32Array[] {
  if (macroMips) return macroMips;
  const levels = [Float32Array.from(patternBytes(), (b) => b / 255)];
  for (let side = SIZE >> 1; side >= 1; side >>= 1) {
    const up = levels[levels.length - 1];
    const out = new Float32Array(side * side * 4);
    for (let y = 0; y < side; y++) {
      for (let x = 0; x < side; x++) {
        for (let c = 0; c < 4; c++) {
          const at = (yy: number, xx: number) => up[((2 * y + yy) * 2 * side + 2 * x + xx) * 4 + c];
          out[(y * side + x) * 4 + c] = 0.25 * (at(0, 0) + at(0, 1) + at(1, 0) + at(1, 1));
        }
      }
    }
    levels.push(out);
  }
  macroMips = levels;
  return levels;
}

/** Channel `c` of mip `level` at texture coordinates (u, v) (repeats of 1), bilinear, wrapped. */
function macroSample(level: number, u: number, v: number, c: number): number {
  const mips = macroLevels();
  const l = Math.min(level, mips.length - 1);
  const side = SIZE >> l;
  const data = mips[l];
  const x = u * side - 0.5;
  const y = v * side - 0.5;
  const i = Math.floor(x);
  const j = Math.floor(y);
  const fx = x - i;
  const fy = y - j;
  const at = (a: number, b: number) => data[((((b % side) + side) % side) * side + (((a % side) + side) % side)) * 4 + c];
  const top = at(i, j) + (at(i + 1, j) - at(i, j)) * fx;
  const bottom = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * fx;
  return top + (bottom - top) * fy;
}

/** Writes the macro factor (linear RGB multipliers) of a vertex at world (x, z) of a mesh whose
 * vertices are `spacing` metres apart into `out` at `3·v` (module docs above). */
export function macroFactor(x: number, z: number, spacing: number, out: Float32Array, v: number): void {
  const read = (scale: number, cos: number, sin: number, cx: number, cy: number): [number, number] => {
    const repeat = REPEAT_M * scale;
    const texel = repeat / SIZE;
    const level = Math.max(0, Math.ceil(Math.log2(spacing / texel)));
    const u = (cos * z - sin * x) / repeat;
    const w = (sin * z + cos * x) / repeat;
    return [macroSample(level, u, w, cx), macroSample(level, u, w, cy)];
  };
  const [a0, a3] = read(MACRO_SCALE, 0.7986, 0.6018, 0, 3);
  const [b2, b1] = read(MACRO_SCALE_2, 0.3256, -0.9455, 2, 1);
  const bright = 1 + MACRO_BRIGHTNESS * (a0 + b2 - 1);
  const warm = MACRO_WARMTH * (a3 + b1 - 1);
  out[3 * v] = bright * (1 + warm);
  out[3 * v + 1] = bright;
  out[3 * v + 2] = bright * (1 - warm);
}

// Where no Ptex page is drawn after it: the splat replaces the vertex colours.
const FRAGMENT = `
  vec3 splatP = strataSplatPosition();
  diffuseColor.rgb = strataSplat(splatP, dFdx(splatP), dFdy(splatP));`;

/** Adds the splatting to a Lambert shader. Alone (`underPtex` false) the splat replaces the vertex
 * colours after `#include <color_fragment>`; under Ptex (./ptex.ts) it only defines
 * `STRATA_SPLAT` and `strataSplat`, which the Ptex fragment calls for faces without a page. */
export function addSplat(shader: THREE.WebGLProgramParametersWithUniforms, underPtex = false): void {
  Object.assign(shader.uniforms, sharedUniforms());
  shader.vertexShader = shader.vertexShader
    .replace("#include <common>", `#include <common>${VERTEX_PARS}`)
    .replace("#include <begin_vertex>", `#include <begin_vertex>${VERTEX}`);
  // After the last declarations (Lambert's varyings are read), before main.
  shader.fragmentShader = shader.fragmentShader
    .replace("#include <common>", "#include <common>\n#define STRATA_SPLAT")
    .replace("#include <clipping_planes_pars_fragment>", `#include <clipping_planes_pars_fragment>${FRAGMENT_PARS}${SPLAT_FUNCTION}`);
  if (!underPtex) shader.fragmentShader = shader.fragmentShader.replace("#include <color_fragment>", `#include <color_fragment>${FRAGMENT}`);
}

/** The biome tint's share of the albedo. */
const SHARE = BIOME_SHARE;

/** Material `material`'s mid colour (linear, half way between its base and tint): the biome
 * colour of a vertex without biome weights (a volume chunk's, ./chunk.ts), so its splat is the
 * material's pattern untinted. */
export function splatMidColour(material: number): THREE.Color {
  const m = Math.min(BASE.length - 1, material);
  return BASE_LINEAR[m].clone().lerp(TINT_LINEAR[m], 0.5);
}

/** Writes the splat attributes of vertex `v` (module docs): `base` and `span` (linear RGB, three
 * floats each) and `sel` (bytes: the amplitude over AMP_MAX of the channel material `material`
 * reads), from its material, its biome colour (linear) and the water's share of its colour. */
export function splatVertex(
  v: number,
  material: number,
  biome: THREE.Color,
  water: number,
  waterColour: THREE.Color,
  out: { base: Float32Array; span: Float32Array; sel: Uint8Array },
): void {
  const m = Math.min(BASE.length - 1, material);
  const dry = 1 - water;
  const k = (1 - SHARE) * dry;
  const b = BASE_LINEAR[m];
  const t = TINT_LINEAR[m];
  out.base[3 * v] = k * b.r + dry * SHARE * biome.r + water * waterColour.r;
  out.base[3 * v + 1] = k * b.g + dry * SHARE * biome.g + water * waterColour.g;
  out.base[3 * v + 2] = k * b.b + dry * SHARE * biome.b + water * waterColour.b;
  out.span[3 * v] = k * (t.r - b.r);
  out.span[3 * v + 1] = k * (t.g - b.g);
  out.span[3 * v + 2] = k * (t.b - b.b);
  for (let c = 0; c < 4; c++) out.sel[4 * v + c] = c === m % 4 ? Math.round((255 * AMP[m]) / AMP_MAX) : 0;
}
