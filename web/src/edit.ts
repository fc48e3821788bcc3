// Editing tools of the viewer: each edit adds one authored region (issue 4's `regions` scene
// element) around the clicked point and goes over the stream socket as a JSON Patch; undo sends
// the inverse operation (test the element's id, remove it).
//
// Tools: raise / lower (an elevation constraint 60 m above / below the ground), crest (two
// clicks: a ridge 30 m above the higher end with 30° flanks), amplify (a gradient brush that
// doubles the slopes). Keys 1–4 pick a tool, Esc leaves edit mode, Ctrl+Z undoes.

/** A point on the ground, metres. */
export interface GroundPoint {
  x: number;
  y: number;
  z: number;
}

export type Tool = "raise" | "lower" | "crest" | "amplify";

export const TOOLS: Tool[] = ["raise", "lower", "crest", "amplify"];

/** Half the side of the region a point edit occupies, metres. */
export const POINT_REGION_M = 160;
/** Grid samples per side of an edit's region. */
export const EDIT_SAMPLES = 65;

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
  const ops =
    tool === "amplify"
      ? [{ op: "amplify", center: at, radius_m: r * 0.8, factor: 2.0 }]
      : [{ op: "elevation", shape: { point: at }, elevation_m: round(p.y + (tool === "raise" ? 60 : -60)), radius_m: 10 }];
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
