// The water the held tiles' heights give for points of the screen, for the water test
// (tests/js/water.mjs): a screen point's ray meets the first surface, ground or water, and that
// point is wet where the ground lies below the water level. The level of a point is the mean
// surface (`h + water_depth`) of the wet corners of its quad; a quad without one is dry. Heights
// are read on the terrain's triangles (./tileGround.ts) of the finest held tile there. Nothing
// here draws: it states where the shoreline of the heights is, to compare with a screenshot.
import * as THREE from "three";
import type { Tile } from "./frame";
import { finestTile } from "./ground";
import { groundHeight } from "./tileGround";

/** A `cols`×`rows` grid of screen points (row-major, top row first). */
export interface ShoreSamples {
  cols: number;
  rows: number;
  /** 1 wet, 0 dry, -1 no held tile under the point. */
  wet: number[];
  /** The world point the ray meets, metres. */
  x: number[];
  z: number[];
  /** The side of the tile holding it, metres (tile borders lie on multiples of it). */
  span: number[];
  /** The ground there and the water level (`NaN` where no corner of its quad is wet), metres. */
  ground: number[];
  level: number[];
}

/** Fixed-point steps from the ray's point at one level to the surface there: enough for views
 * within 45° of straight down over slopes under 45°. */
const STEPS = 10;

/** The surface at `(x, z)` of `t` (the water level where wet, else the ground), whether it is
 * wet, the ground and the level of its quad's wet corners (`NaN` when none is). */
function surface(t: Tile, x: number, z: number): { y: number; wet: boolean; ground: number; level: number } {
  const ground = groundHeight(t, x, z);
  const q = t.size - 1;
  const i = Math.min(Math.max(Math.floor((x - t.originX) / t.spacing), 0), q - 1);
  const j = Math.min(Math.max(Math.floor((z - t.originZ) / t.spacing), 0), q - 1);
  let sum = 0;
  let n = 0;
  for (const v of [j * t.size + i, j * t.size + i + 1, (j + 1) * t.size + i, (j + 1) * t.size + i + 1]) {
    if (t.waterDepth[v] > 0) {
      sum += t.heights[v] + t.waterDepth[v];
      n++;
    }
  }
  const level = n > 0 ? sum / n : NaN;
  return ground < level ? { y: level, wet: true, ground, level } : { y: ground, wet: false, ground, level };
}

export function shoreSamples(tiles: Tile[], camera: THREE.Camera, cols: number, rows: number): ShoreSamples {
  const out: ShoreSamples = { cols, rows, wet: [], x: [], z: [], span: [], ground: [], level: [] };
  const ray = new THREE.Raycaster();
  const ndc = new THREE.Vector2();
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      ndc.set(((c + 0.5) / cols) * 2 - 1, 1 - ((r + 0.5) / rows) * 2);
      ray.setFromCamera(ndc, camera);
      const { origin: o, direction: d } = ray.ray;
      let y = 0;
      let x = NaN;
      let z = NaN;
      let tile: Tile | undefined;
      let wet = false;
      let ground = NaN;
      let level = NaN;
      for (let s = 0; s < STEPS && d.y < -1e-6; s++) {
        const t = (y - o.y) / d.y;
        x = o.x + t * d.x;
        z = o.z + t * d.z;
        tile = finestTile(tiles, x, z);
        if (!tile) break;
        const here = surface(tile, x, z);
        y = here.y;
        wet = here.wet;
        ground = here.ground;
        level = here.level;
      }
      out.wet.push(tile ? (wet ? 1 : 0) : -1);
      out.x.push(x);
      out.z.push(z);
      out.span.push(tile ? (tile.size - 1) * tile.spacing : 0);
      out.ground.push(ground);
      out.level.push(level);
    }
  }
  return out;
}
