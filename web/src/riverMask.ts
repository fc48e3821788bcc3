// Which of a tile's wet vertices hold river water that a ribbon draws instead: those whose water
// kind is a river's (the stream's tiles are version 2, `api/tile_format_v2.md`) near a river line
// of the tile. A river line also runs through the lakes it crosses, at the lake's level; the
// kinds keep those lakes' vertices lake water, so the lake's sheet has no gap along the line.
import { WATER_RIVER, type Tile } from "./frame";
import type { RiverLine } from "./riverLines";
import { tileRect } from "./tileGround";

/**
 * One flag per vertex: 1 where the vertex holds river water (kind 3) near one of `lines` (within
 * half the channel's width plus one vertex spacing of its centre line), 0 elsewhere. A version 1
 * tile (no kinds) has none.
 */
export function riverVertices(tile: Tile, lines: RiverLine[]): Uint8Array {
  const { size, spacing, waterKind } = tile;
  const flags = new Uint8Array(size * size);
  if (waterKind.length === 0) return flags;
  const segments = nearSegments(tile, lines);
  if (segments.length === 0) return flags;
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const v = j * size + i;
      if (waterKind[v] !== WATER_RIVER) continue;
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
