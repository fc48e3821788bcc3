// The water sheet of a tile: one surface at the water level of the tile's sea, lakes and rivers,
// cut along the shoreline of the heights rather than along quads or tile borders.
//
// Each vertex of a quad with a wet corner (water depth > 0, api/tile_format_v1.md) gets a water
// level: its own surface (`h + water_depth`) where it is wet, the mean surface of its wet
// neighbours (8-neighbourhood) where it is dry, so the sheet is flat at the sea's level and
// follows a lake's or a river's level. Each vertex also carries `depth = level − h` (negative on
// dry ground); the sheet's fragments whose interpolated depth is not positive are discarded. Level
// and ground are linear on the same triangles (the terrain's diagonal, as `mesh.ts` indexes it),
// so the water ends exactly on the contour where the ground meets the water level: the shoreline,
// whatever the LOD or tile border. Neighbouring tiles of one LOD share their edge vertices bit for
// bit, so one sea is one continuous sheet. Vertices whose river water a ribbon draws (`river`,
// see ./rivers.ts) count as dry, so the sheet gives way to the ribbon along a contour too.
import * as THREE from "three";
import type { Tile } from "./frame";

/** The water's colour and translucency (the ribbons use a copy). */
export const waterMaterial = new THREE.MeshLambertMaterial({
  color: new THREE.Color().setRGB(0.12, 0.32, 0.5, THREE.SRGBColorSpace),
  transparent: true,
  opacity: 0.72,
  depthWrite: false,
});

/** The sheet's opacity over shallow water (at the shore) and the most it reaches over deep water. */
const SHALLOW_OPACITY = 0.55;
const DEEP_OPACITY = 0.96;
/** Depth over which the sheet goes from shallow to deep opacity (1 − 1/e of the way), metres. */
const OPACITY_DEPTH_M = 12;

/**
 * The sheet's material: `waterMaterial` whose fragments on dry ground (depth ≤ 0) are discarded
 * and whose opacity grows with the water's depth, so the ground shows through at the shore and a
 * lake's or the sea's bed tens of metres down does not.
 */
export const sheetMaterial = waterMaterial.clone();
sheetMaterial.onBeforeCompile = (shader) => {
  const f = (v: number) => v.toFixed(4);
  shader.vertexShader = shader.vertexShader
    .replace("#include <common>", "#include <common>\nattribute float depth;\nvarying float vWaterDepth;")
    .replace("#include <begin_vertex>", "#include <begin_vertex>\nvWaterDepth = depth;");
  shader.fragmentShader = shader.fragmentShader
    .replace("#include <common>", "#include <common>\nvarying float vWaterDepth;")
    .replace("void main() {", "void main() {\n\tif (vWaterDepth <= 0.0) discard;")
    .replace(
      "#include <color_fragment>",
      `#include <color_fragment>\n\tdiffuseColor.a = mix(${f(SHALLOW_OPACITY)}, ${f(DEEP_OPACITY)}, 1.0 - exp(-vWaterDepth / ${f(OPACITY_DEPTH_M)}));`,
    );
};
sheetMaterial.customProgramCacheKey = () => "strata-water-sheet";

/** How far below the ground a dry vertex's level is at least, metres: the shore stays off it. */
const DRY_MARGIN_M = 0.001;

/**
 * The water levels of `tile`'s vertices: the surface where `wet`, the mean of the wet
 * 8-neighbours' surfaces where not, `NaN` where not wet with no wet neighbour.
 */
export function waterLevels(tile: Tile, wet: (v: number) => boolean): Float32Array {
  const { size, heights, waterDepth } = tile;
  const level = new Float32Array(size * size).fill(NaN);
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const v = j * size + i;
      if (wet(v)) {
        level[v] = heights[v] + waterDepth[v];
        continue;
      }
      let sum = 0;
      let n = 0;
      for (let b = Math.max(0, j - 1); b <= Math.min(size - 1, j + 1); b++) {
        for (let a = Math.max(0, i - 1); a <= Math.min(size - 1, i + 1); a++) {
          const u = b * size + a;
          if (wet(u)) {
            sum += heights[u] + waterDepth[u];
            n++;
          }
        }
      }
      if (n > 0) level[v] = sum / n;
    }
  }
  return level;
}

/**
 * The sheet's geometry (relative to the tile's origin), or `undefined` when no quad is left. The
 * vertices `river` flags (river water a ribbon draws) count as dry, so the sheet ends on a
 * contour between them and the other wet vertices rather than along quads.
 */
export function waterGeometry(tile: Tile, river?: Uint8Array): THREE.BufferGeometry | undefined {
  const { size, heights, waterDepth } = tile;
  const wet = (v: number) => waterDepth[v] > 0 && !(river && river[v] === 1);
  const idx: number[] = [];
  for (let j = 0; j + 1 < size; j++) {
    for (let i = 0; i + 1 < size; i++) {
      const a = j * size + i;
      const [b, c, d] = [a + 1, a + size, a + size + 1];
      if (!(wet(a) || wet(b) || wet(c) || wet(d))) continue;
      idx.push(a, c, b, b, c, d);
    }
  }
  if (idx.length === 0) return undefined;
  const level = waterLevels(tile, wet);
  const pos = new Float32Array(3 * size * size);
  const depth = new Float32Array(size * size);
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const v = j * size + i;
      const y = Number.isNaN(level[v]) ? heights[v] : level[v];
      pos[3 * v] = i * tile.spacing;
      pos[3 * v + 1] = y;
      pos[3 * v + 2] = j * tile.spacing;
      depth[v] = wet(v) ? waterDepth[v] : Math.min(y - heights[v], -DRY_MARGIN_M);
    }
  }
  const geo = new THREE.BufferGeometry();
  geo.setIndex(idx);
  geo.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  geo.setAttribute("depth", new THREE.BufferAttribute(depth, 1));
  geo.computeVertexNormals();
  geo.computeBoundingSphere();
  return geo;
}

/** Replaces the water sheet under the tile's `mesh`, leaving out the quads `river` flags. */
export function setWater(mesh: THREE.Mesh, tile: Tile, river?: Uint8Array): void {
  for (const child of [...mesh.children]) {
    if (child instanceof THREE.Mesh && child.name === "water") {
      mesh.remove(child);
      child.geometry.dispose();
    }
  }
  const sheet = waterGeometry(tile, river);
  if (sheet === undefined) return;
  const water = new THREE.Mesh(sheet, sheetMaterial);
  water.name = "water";
  water.renderOrder = 1;
  water.matrixAutoUpdate = false;
  water.updateMatrix();
  mesh.add(water);
}
