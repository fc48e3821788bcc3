// Which of a tile's wet vertices hold river water that a ribbon draws instead. The tiles the
// stream sends (`bin`, version 1) give each vertex's water depth but not whose water it is, so a
// wet vertex counts as the river's when it lies near a river line of the tile and its water
// surface is not the level of still water: the sea (sea level, and the last level of lines that
// end in the sea) or a lake (the last level of lines that end in one).
import type { Tile } from "./frame";
import type { RiverLine } from "./riverLines";
import { tileRect } from "./tileGround";

/** Water surfaces this close to a still-water level are that sea or lake, metres. */
const STILL_TOLERANCE_M = 0.05;

/**
 * One flag per vertex: 1 where the vertex is wet with river water near one of `lines` (within
 * half the channel's width plus one vertex spacing of its centre line), 0 elsewhere.
 */
export function riverVertices(tile: Tile, lines: RiverLine[], seaLevel: number | undefined): Uint8Array {
  const { size, spacing, heights, waterDepth } = tile;
  const flags = new Uint8Array(size * size);
  const still: number[] = seaLevel === undefined ? [] : [seaLevel];
  for (const l of lines) if (l.ends === "sea" || l.ends === "lake") still.push(l.points[l.points.length - 1][2]);
  const segments = nearSegments(tile, lines);
  if (segments.length === 0) return flags;
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const v = j * size + i;
      if (!(waterDepth[v] > 0)) continue;
      const surface = heights[v] + waterDepth[v];
      if (still.some((s) => Math.abs(surface - s) <= STILL_TOLERANCE_M)) continue;
      const x = tile.originX + i * spacing;
      const z = tile.originZ + j * spacing;
      for (const [ax, az, bx, bz, reach] of segments) {
        const dx = bx - ax;
        const dz = bz - az;
        const t = Math.max(0, Math.min(1, ((x - ax) * dx + (z - az) * dz) / (dx * dx + dz * dz || 1)));
        if (Math.hypot(ax + t * dx - x, az + t * dz - z) <= reach) {
          flags[v] = 1;
          break;
        }
      }
    }
  }
  return flags;
}

/** The pieces of `lines` near the tile: `[ax, az, bx, bz, reach]`, reach being half the width plus a spacing. */
function nearSegments(tile: Tile, lines: RiverLine[]): [number, number, number, number, number][] {
  const r = tileRect(tile);
  const out: [number, number, number, number, number][] = [];
  for (const line of lines) {
    for (let k = 0; k + 1 < line.points.length; k++) {
      const [ax, az] = line.points[k];
      const [bx, bz] = line.points[k + 1];
      const reach = Math.max(line.widths[k], line.widths[k + 1]) / 2 + tile.spacing;
      if (Math.max(ax, bx) + reach < r.x0 || Math.min(ax, bx) - reach > r.x1) continue;
      if (Math.max(az, bz) + reach < r.z0 || Math.min(az, bz) - reach > r.z1) continue;
      out.push([ax, az, bx, bz, reach]);
    }
  }
  return out;
}
