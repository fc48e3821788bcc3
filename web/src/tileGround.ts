// Ground height inside one tile, on the same triangles the tile's mesh draws (each quad split
// along its (i+1, j)–(i, j+1) diagonal, as `mesh.ts` indexes it), so what lies on it stays on it.
import type { Tile } from "./frame";

/** The tile's world rectangle: `[x0, x1] × [z0, z1]` metres. */
export interface Rect {
  x0: number;
  z0: number;
  x1: number;
  z1: number;
}

export function tileRect(tile: Tile): Rect {
  const extent = (tile.size - 1) * tile.spacing;
  return { x0: tile.originX, z0: tile.originZ, x1: tile.originX + extent, z1: tile.originZ + extent };
}

/** The height of the tile's surface at world `(x, z)`, clamped to the tile. */
export function groundHeight(tile: Tile, x: number, z: number): number {
  const q = tile.size - 1;
  const fi = Math.max(0, Math.min((x - tile.originX) / tile.spacing, q));
  const fj = Math.max(0, Math.min((z - tile.originZ) / tile.spacing, q));
  const i = Math.min(Math.floor(fi), q - 1);
  const j = Math.min(Math.floor(fj), q - 1);
  const u = fi - i;
  const w = fj - j;
  const h = tile.heights;
  const v00 = j * tile.size + i;
  const h00 = h[v00];
  const h10 = h[v00 + 1];
  const h01 = h[v00 + tile.size];
  const h11 = h[v00 + tile.size + 1];
  if (u + w <= 1) return h00 + u * (h10 - h00) + w * (h01 - h00);
  return h11 + (1 - u) * (h01 - h11) + (1 - w) * (h10 - h11);
}
