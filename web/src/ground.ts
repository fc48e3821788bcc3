// The ground under a point, from the held tiles: the finest tile covering it, bilinear.
import type { Tile } from "./frame";

/** Ground height at world (x, z) and the LOD of the finest of `tiles` covering it; `undefined`
 * when none does. */
export function groundSample(tiles: Iterable<Tile>, x: number, z: number): { height: number; lod: number } | undefined {
  const t = finestTile(tiles, x, z);
  if (!t) return undefined;
  const fi = Math.min((x - t.originX) / t.spacing, t.size - 1.0001);
  const fj = Math.min((z - t.originZ) / t.spacing, t.size - 1.0001);
  const i = Math.floor(fi);
  const j = Math.floor(fj);
  const u = fi - i;
  const w = fj - j;
  const h = (a: number, b: number) => t.heights[b * t.size + a];
  const height = (1 - w) * ((1 - u) * h(i, j) + u * h(i + 1, j)) + w * ((1 - u) * h(i, j + 1) + u * h(i + 1, j + 1));
  return { height, lod: t.lod };
}

/** The finest of `tiles` covering world (x, z); `undefined` when none does. */
export function finestTile(tiles: Iterable<Tile>, x: number, z: number): Tile | undefined {
  let best: Tile | undefined;
  for (const t of tiles) {
    const extent = (t.size - 1) * t.spacing;
    if (x < t.originX || z < t.originZ || x > t.originX + extent || z > t.originZ + extent) continue;
    if (!best || t.lod < best.lod) best = t;
  }
  return best;
}
