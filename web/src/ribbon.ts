// River ribbons: each centre line of a tile as a band of its channel width, cut to the tile's
// square (so the pieces of neighbouring tiles meet on their shared edge) and laid on the water
// level, or just above the tile's ground where the ground is higher than the level, or at most
// a channel's depth above the ground where the level floats higher (a line's levels follow the
// river network's, which reads the ground smoothed over kilometres: across a hollow its valley
// does not reach, the level stood up to 70 m above the land and the band hung in the air). A line runs on
// through the lakes it crosses, at the lake's level, and ends a piece or two into the sea: a piece
// whose corners all lie over lake or sea water (the tile's water kinds, `api/tile_format_v2.md`)
// is left to that water's sheet, which would otherwise show the band as a darker line across it.
import * as THREE from "three";
import { WATER_LAKE, WATER_SEA, type Tile } from "./frame";
import type { RiverLine } from "./riverLines";
import { groundHeight, tileRect, type Rect } from "./tileGround";

/** A corner of a ribbon piece: world `x`, `z` and the water level there. */
type Corner = [number, number, number];

/** What one tile's ribbons hold: the geometry (relative to the tile's origin, as its mesh) and what the HUD counts. */
export interface Ribbons {
  geometry: THREE.BufferGeometry | undefined;
  /** Lines with a piece inside the tile. */
  count: number;
  /** Length of their centre lines inside the tile, metres. */
  length: number;
  /** Highest a drawn corner lies above the tile's ground away from lakes and the sea, metres (0 without one). */
  aboveGround: number;
}

/** How far above the ground a ribbon lies where the ground is above the water level, metres. */
const LIFT_M = 0.15;
/**
 * Highest a ribbon lies above the tile's ground away from lakes and the sea, metres: the deepest
 * channel the carve cuts (0.3 + 0.4 · Q^0.4 for the largest discharge, about 7.4 m), so a river
 * in its channel keeps its level and one whose level floats above a hollow lies on the ground.
 */
const CHANNEL_DEPTH_MAX_M = 8;
/** The sharpest bend's offset: a miter is at most this many half widths long. */
const MITER_LIMIT = 2.5;

/** The ribbons of `lines` inside `tile`'s square, draped on the tile's heights. */
export function buildRibbons(tile: Tile, lines: RiverLine[]): Ribbons {
  const rect = tileRect(tile);
  // One piece per tile quad along the line, at least, so the band follows the ground.
  const step = Math.max(tile.spacing, 0.5);
  const pos: number[] = [];
  let count = 0;
  let length = 0;
  let aboveGround = 0;
  for (const line of lines) {
    const inside = clippedLength(line, rect);
    const before = pos.length;
    ribbon(line, rect, step, (poly) => {
      if (!overStillWater(poly, tile)) aboveGround = Math.max(aboveGround, emit(poly, tile, pos));
    });
    if (inside > 0 || pos.length > before) {
      count++;
      length += inside;
    }
  }
  if (pos.length === 0) return { geometry: undefined, count, length, aboveGround };
  const geo = new THREE.BufferGeometry();
  const normals = new Float32Array(pos.length);
  for (let v = 1; v < normals.length; v += 3) normals[v] = 1;
  geo.setAttribute("position", new THREE.BufferAttribute(new Float32Array(pos), 3));
  geo.setAttribute("normal", new THREE.BufferAttribute(normals, 3));
  geo.computeBoundingSphere();
  return { geometry: geo, count, length, aboveGround };
}

/** Offsets of each point to the left bank: the unit normal times half the width, mitred at bends. */
function offsets(pts: [number, number, number][], widths: number[]): [number, number][] {
  const n = pts.length;
  const dir: [number, number][] = [];
  for (let k = 0; k + 1 < n; k++) {
    const dx = pts[k + 1][0] - pts[k][0];
    const dz = pts[k + 1][1] - pts[k][1];
    const len = Math.hypot(dx, dz) || 1;
    dir.push([dx / len, dz / len]);
  }
  const out: [number, number][] = [];
  for (let k = 0; k < n; k++) {
    const a = dir[Math.max(k - 1, 0)];
    const b = dir[Math.min(k, n - 2)];
    // The normal of each side (left of the flow), then their mean, lengthened to keep the width.
    let mx = -(a[1] + b[1]);
    let mz = a[0] + b[0];
    const ml = Math.hypot(mx, mz);
    if (ml < 1e-6) {
      mx = -b[1];
      mz = b[0];
    } else {
      mx /= ml;
      mz /= ml;
    }
    const cos = mx * -b[1] + mz * b[0];
    const scale = Math.min(1 / Math.max(cos, 1e-3), MITER_LIMIT);
    const hw = (widths[k] / 2) * scale;
    out.push([mx * hw, mz * hw]);
  }
  return out;
}

/** Removes points that repeat the one before (a zero-length piece has no direction). */
function distinct(line: RiverLine): { pts: [number, number, number][]; widths: number[] } {
  const pts: [number, number, number][] = [];
  const widths: number[] = [];
  line.points.forEach((p, k) => {
    const last = pts[pts.length - 1];
    if (last && Math.hypot(p[0] - last[0], p[1] - last[1]) < 1e-3) return;
    pts.push(p);
    widths.push(line.widths[k]);
  });
  return { pts, widths };
}

/** Calls `out` with each ribbon quad that touches `rect`, cut to it (a convex polygon). */
function ribbon(line: RiverLine, rect: Rect, step: number, out: (poly: Corner[]) => void): void {
  const { pts, widths } = distinct(line);
  if (pts.length < 2) return;
  const off = offsets(pts, widths);
  for (let k = 0; k + 1 < pts.length; k++) {
    const [p, q] = [pts[k], pts[k + 1]];
    const reach = Math.max(widths[k], widths[k + 1]) * MITER_LIMIT;
    if (Math.max(p[0], q[0]) + reach < rect.x0 || Math.min(p[0], q[0]) - reach > rect.x1) continue;
    if (Math.max(p[1], q[1]) + reach < rect.z0 || Math.min(p[1], q[1]) - reach > rect.z1) continue;
    const left = (t: number): Corner => [
      p[0] + off[k][0] + t * (q[0] + off[k + 1][0] - p[0] - off[k][0]),
      p[1] + off[k][1] + t * (q[1] + off[k + 1][1] - p[1] - off[k][1]),
      p[2] + t * (q[2] - p[2]),
    ];
    const right = (t: number): Corner => [
      p[0] - off[k][0] + t * (q[0] - off[k + 1][0] - p[0] + off[k][0]),
      p[1] - off[k][1] + t * (q[1] - off[k + 1][1] - p[1] + off[k][1]),
      p[2] + t * (q[2] - p[2]),
    ];
    const pieces = Math.max(1, Math.ceil(Math.hypot(q[0] - p[0], q[1] - p[1]) / step));
    for (let s = 0; s < pieces; s++) {
      const [t0, t1] = [s / pieces, (s + 1) / pieces];
      const poly = clip([left(t0), right(t0), right(t1), left(t1)], rect);
      if (poly.length >= 3) out(poly);
    }
  }
}

/** Sutherland–Hodgman: the part of polygon `poly` inside `rect`, levels interpolated. */
function clip(poly: Corner[], rect: Rect): Corner[] {
  const planes: [number, number, number][] = [
    [0, 1, rect.x0], // x ≥ x0
    [0, -1, -rect.x1], // x ≤ x1
    [1, 1, rect.z0], // z ≥ z0
    [1, -1, -rect.z1], // z ≤ z1
  ];
  let cur = poly;
  for (const [axis, sign, bound] of planes) {
    const next: Corner[] = [];
    const d = (c: Corner) => sign * c[axis] - bound;
    for (let i = 0; i < cur.length; i++) {
      const a = cur[i];
      const b = cur[(i + 1) % cur.length];
      const [da, db] = [d(a), d(b)];
      if (da >= 0) next.push(a);
      if (da >= 0 !== db >= 0) {
        const t = da / (da - db);
        next.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]);
      }
    }
    cur = next;
    if (cur.length < 3) return [];
  }
  return cur;
}

/** Whether the vertex of `tile` nearest `(x, z)` holds lake or sea water (never, in a tile without kinds). */
function stillWaterAt(tile: Tile, x: number, z: number): boolean {
  if (tile.waterKind.length === 0) return false;
  const i = Math.min(tile.size - 1, Math.max(0, Math.round((x - tile.originX) / tile.spacing)));
  const j = Math.min(tile.size - 1, Math.max(0, Math.round((z - tile.originZ) / tile.spacing)));
  const kind = tile.waterKind[j * tile.size + i];
  return kind === WATER_LAKE || kind === WATER_SEA;
}

/** Whether every corner of `poly` lies nearest a vertex of `tile` with lake or sea water. */
function overStillWater(poly: Corner[], tile: Tile): boolean {
  return poly.every(([x, z]) => stillWaterAt(tile, x, z));
}

/** The height of a ribbon's corner at `(x, z)` whose water level is `level`: on the level, lifted
 *  over ground above it and, away from lakes and the sea, at most a channel's depth above the
 *  ground; and how far that lies above the ground there (0 over lakes and the sea). */
function ribbonHeight(tile: Tile, x: number, z: number, level: number): [number, number] {
  const ground = groundHeight(tile, x, z);
  const onLevel = Math.max(level, ground + LIFT_M);
  if (stillWaterAt(tile, x, z)) return [onLevel, 0];
  const y = Math.min(onLevel, ground + CHANNEL_DEPTH_MAX_M);
  return [y, y - ground];
}

/** Appends `poly` as a fan of upward-facing triangles, each corner draped on the tile, relative to
 *  its origin; returns the highest a corner away from lakes and the sea lies above the ground. */
function emit(poly: Corner[], tile: Tile, pos: number[]): number {
  const corners = poly.map(([x, z, level]) => ribbonHeight(tile, x, z, level));
  const y = corners.map(([h]) => h);
  const above = Math.max(0, ...corners.map(([, a]) => a));
  for (let i = 1; i + 1 < poly.length; i++) {
    let [b, c] = [i, i + 1];
    // Counter-clockwise seen from above: (b − a) × (c − a) points up (+y).
    const cross = (poly[c][0] - poly[0][0]) * (poly[b][1] - poly[0][1]) - (poly[b][0] - poly[0][0]) * (poly[c][1] - poly[0][1]);
    if (cross < 0) [b, c] = [c, b];
    for (const v of [0, b, c]) pos.push(poly[v][0] - tile.originX, y[v], poly[v][1] - tile.originZ);
  }
  return above;
}

/** Length of the line's centre line inside `rect` (Liang–Barsky on each piece), metres. */
function clippedLength(line: RiverLine, rect: Rect): number {
  let total = 0;
  for (let k = 0; k + 1 < line.points.length; k++) {
    const [ax, az] = line.points[k];
    const [bx, bz] = line.points[k + 1];
    const [dx, dz] = [bx - ax, bz - az];
    let t0 = 0;
    let t1 = 1;
    const tests: [number, number][] = [
      [-dx, ax - rect.x0],
      [dx, rect.x1 - ax],
      [-dz, az - rect.z0],
      [dz, rect.z1 - az],
    ];
    let inside = true;
    for (const [p, q] of tests) {
      if (p === 0) {
        if (q < 0) inside = false;
      } else if (p < 0) t0 = Math.max(t0, q / p);
      else t1 = Math.min(t1, q / p);
    }
    if (inside && t1 > t0) total += (t1 - t0) * Math.hypot(dx, dz);
  }
  return total;
}
