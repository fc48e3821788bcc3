// Editing tools of the viewer: each edit adds one authored region (issue 4's `regions` scene
// element) around the clicked point and goes over the stream socket as a JSON Patch; undo sends
// the inverse operation (test the element's id, remove it).
//
// Tools: raise (an elevation constraint 60 m above the ground), hill (a smooth hill 40 m above the
// ground: the elevation constraint with a C² ring, `ring_m`, over which it blends into the ground
// with height, slope and curvature continuous), lower (60 m below), crest (two clicks: a ridge 30 m
// above the higher end with 30° flanks), amplify (a gradient brush that doubles the slopes). Keys
// 1–5 pick a tool, Esc leaves edit mode, Ctrl+Z undoes. The curve tool (key 6, ./curveTool.ts)
// drags the control points of volume regions' feature curves instead.

/** A point on the ground, metres. */
export interface GroundPoint {
  x: number;
  y: number;
  z: number;
}

export type Tool = "raise" | "hill" | "lower" | "crest" | "amplify" | "curve";

export const TOOLS: Tool[] = ["raise", "hill", "lower", "crest", "amplify", "curve"];

/** Half the side of the region a point edit occupies, metres. */
export const POINT_REGION_M = 160;
/** Grid samples per side of an edit's region. */
export const EDIT_SAMPLES = 65;
/** The hill: its top 40 m above the clicked ground, flat within 6 m of the click, and its C² ring
 * 110 m wide beyond (the ring and two region spacings, 5 m each, stay inside the ±160 m region). */
export const HILL = { height_m: 40, radius_m: 6, ring_m: 110 };

let counter = 0;

function newId(tool: Tool): string {
  counter++;
  return `edit-${tool}-${Date.now().toString(36)}-${counter}`;
}

const round = (v: number) => Math.round(v * 100) / 100;

/** The region element of a point tool at `p`. */
export function pointRegion(tool: Tool, p: GroundPoint): object {
  const r = POINT_REGION_M;
  const bbox = { min: [round(p.x - r), round(p.z - r)], max: [round(p.x + r), round(p.z + r)] };
  const at = [round(p.x), round(p.z)];
  let op: object;
  if (tool === "amplify") op = { op: "amplify", center: at, radius_m: r * 0.8, factor: 2.0 };
  else if (tool === "hill")
    op = { op: "elevation", shape: { point: at }, elevation_m: round(p.y + HILL.height_m), radius_m: HILL.radius_m, ring_m: HILL.ring_m };
  else op = { op: "elevation", shape: { point: at }, elevation_m: round(p.y + (tool === "raise" ? 60 : -60)), radius_m: 10 };
  const ops = [op];
  return { id: newId(tool), bbox, samples: EDIT_SAMPLES, ops };
}

/** The region element of a crest from `a` to `b`. */
export function crestRegion(a: GroundPoint, b: GroundPoint): object {
  const width = 45;
  const pad = width + 40;
  const bbox = {
    min: [round(Math.min(a.x, b.x) - pad), round(Math.min(a.z, b.z) - pad)],
    max: [round(Math.max(a.x, b.x) + pad), round(Math.max(a.z, b.z) + pad)],
  };
  const op = {
    op: "crest",
    points: [
      [round(a.x), round(a.z)],
      [round(b.x), round(b.z)],
    ],
    elevation_m: round(Math.max(a.y, b.y) + 30),
    slope_deg: 30,
    width_m: width,
  };
  return { id: newId("crest"), bbox, samples: 129, ops: [op] };
}

/** Patch that appends a region. */
export function addPatch(region: object): object[] {
  return [{ op: "add", path: "/regions/-", value: region }];
}

/** Patch that removes region `id` at `index` (fails cleanly if the scene moved on). */
export function removePatch(id: string, index: number): object[] {
  return [
    { op: "test", path: `/regions/${index}/id`, value: id },
    { op: "remove", path: `/regions/${index}` },
  ];
}
