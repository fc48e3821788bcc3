// The strata viewer: streams height tiles, volume chunks and Ptex pages over strata.stream.v2
// (credits: a slow client is slowed, not dropped) through a worker that holds the socket and
// decodes (./decode.worker.ts), and renders them with three.js.
//
// Query: ?seed=42 (default) or ?world=<id>&token=<read or edit token>; ?x=&z= (metres) where the
// camera looks at first, ?dist= (metres) how far away it starts and ?pitch= (degrees above the
// horizon, 90 straight down) from how high; ?rings=2,1,2,4,8,0,1,0,1 the LOD rings of the view
// (the coarse levels reach past 30 km, so the ground meets the sky at the horizon, not short of
// it), ?chunk_rings=2,2,2,2 the volume-chunk rings (empty for none), ?ptex=0 no Ptex pages (by
// default the view asks for them, the tiles' faces' and the chunks' quads', and draws them with
// their albedo, see ./ptex.ts), ?splat=0
// no texture splatting (faces without a page are then drawn with the vertex colours, see ./splat.ts).
// Without ?x=&z= the view opens on land with relief near the origin. With a world and a token the
// edit tools are shown (see ./edit.ts). Rivers are drawn as ribbons along the server's river lines
// (see ./rivers.ts).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { ChunkLayer } from "./chunk";
import { chunkKey } from "./chunkFormat";
import type { Decoded, ToWorker } from "./decoded";
import { decodeTile, type Tile } from "./frame";
import { groundSample as sampleGround } from "./ground";
import { CurveTool } from "./curveTool";
import { biomeTints, DEFAULT_BIOMES } from "./biomes";
import { buildMesh, disposeMesh, hasMarks, sharedMaterial, updateHidden } from "./mesh";
import { addSplat } from "./splat";
import { PtexStore } from "./ptex";
import { RiverLayer } from "./rivers";
import { shoreSamples, type ShoreSamples } from "./shoreline";
import { selectView, tileKey, viewExtentM, type Square } from "./view";
import { addPatch, crestRegion, pointRegion, removePatch, TOOLS, type GroundPoint, type Tool } from "./edit";

interface Held {
  mesh: THREE.Mesh;
  tile: Tile;
  version: number;
  /** Whether the server marks vertices of the tile that volume chunks override. */
  marked: boolean;
}

interface StrataState {
  tiles: number; // frames received since the page loaded
  held: number; // meshes in the scene
  inFlight: number; // tiles the server still has to send for the current view
  errors: string[]; // server errors and socket failures, as shown on screen
  webgl2: boolean;
  idle: boolean;
  frames: number;
  version: number;
  views: number; // view replies from the server
  viewTiles: number; // tiles in the current view (client-side selection)
  freed: number; // meshes freed because they left the view or were replaced
  /** Moves camera and target by (dx, dz) metres: lets tests fly without synthesising input. */
  moveBy: (dx: number, dz: number) => void;
  /** The water the held tiles' heights give under a `cols`×`rows` grid of screen points (tests). */
  shore: (cols: number, rows: number) => ShoreSamples;
  /** Shows or hides the water (sheets and ribbons): lets tests see what the water covers. */
  showWater: (on: boolean) => void;
  /** Shows or hides the volume chunks: lets tests find the chunks' pixels. */
  showChunks: (on: boolean) => void;
  tool: string; // the edit tool in use, "" when not editing
  edits: number; // edits the server acknowledged (durable)
  pendingEdits: number; // edits sent and not yet acknowledged
  lastEdit: string; // id of the last region element the viewer added
  rivers: number; // river ribbons drawn (one per river line and tile it crosses)
  riverLength: number; // their centre lines' total length, metres
  riverPending: number; // river-line requests queued or open
  riverTiles: number; // held tiles whose river lines have arrived
  riverAboveGround: number; // highest a ribbon lies above its tile's ground away from lakes and the sea, metres
  chunks: number; // chunk frames received since the page loaded
  heldChunks: number; // chunk meshes in the scene
  closed: string; // why the stream stopped for good ("" while it runs or reconnects)
  reconnects: number; // reconnection attempts
  retiring: number; // tiles that left the view, kept until their replacements cover them
  minClearance: number; // lowest camera height above the ground before the collision check, metres
  fogFar: number; // where the fog is complete, metres (the nearest edge of the held ground, or less)
  heldGround: () => { camera: number[]; halfAngleDeg: number; tiles: number[][] }; // the camera, its view cone and each held tile's [x0, z0, x1, z1], metres
  flySpeed: number; // how fast WASD flies now, metres per second (it grows with the height above the ground)
  horizon: number; // the horizon line's row as a fraction of the picture's height from the top (0 when above it)
  protocol: string; // the stream protocol the server speaks
  biomes: string[]; // the world's biomes in the order of the tiles' weights (the stream's hello)
  ptex: boolean; // whether the view asks for Ptex pages (?ptex=0 turns them off)
  ptexFrames: number; // Ptex frames (kind 3) received since the page loaded
  ptexPages: number; // pages in them
  ptexApplied: number; // pages written into the texture arrays for faces of held tiles
  ptexFaces: number; // faces of the view's tiles drawn with a page
  ptexDetail: number; // of those, faces drawn with a detail page (16² or finer)
  ptexChunkFaces: number; // faces (quads) of the held chunks drawn with a page
  ptexChunkDetail: number; // of those, faces drawn with a detail page
  chunkQuads: number; // quads of the held chunks (their Ptex faces)
  hiddenTiles: number; // held tiles with vertices hidden under held volume chunks
  splat: boolean; // whether the tiles are drawn with texture splatting (?splat=0 turns it off)
  curveHandles: number; // control-point handles the curve tool shows
  curveEdits: number; // curve edits the server accepted
  /** The curve tool's handles on the screen, CSS pixels (tests aim the mouse with it). */
  handlesOnScreen: () => { volume: string; curve: number; point: number; x: number; y: number; position: number[] }[];
  invalidatedChunks: number[][]; // the chunks (lod, x, y, z) the last invalidation listed
}

declare global {
  interface Window {
    __strata: StrataState;
  }
}

const state: StrataState = {
  tiles: 0,
  held: 0,
  inFlight: 0,
  errors: [],
  webgl2: false,
  idle: false,
  frames: 0,
  version: 0,
  views: 0,
  viewTiles: 0,
  freed: 0,
  moveBy: () => {},
  shore: () => ({ cols: 0, rows: 0, wet: [], x: [], z: [], span: [], ground: [], level: [] }),
  showWater: () => {},
  showChunks: () => {},
  tool: "",
  edits: 0,
  pendingEdits: 0,
  lastEdit: "",
  rivers: 0,
  riverLength: 0,
  riverPending: 0,
  riverTiles: 0,
  riverAboveGround: 0,
  chunks: 0,
  heldChunks: 0,
  closed: "",
  reconnects: 0,
  retiring: 0,
  minClearance: Infinity,
  fogFar: 0,
  heldGround: () => ({ camera: [], halfAngleDeg: 0, tiles: [] }),
  flySpeed: 0,
  horizon: 0,
  protocol: "",
  biomes: [],
  ptex: false,
  ptexFrames: 0,
  ptexPages: 0,
  ptexApplied: 0,
  ptexFaces: 0,
  ptexDetail: 0,
  ptexChunkFaces: 0,
  ptexChunkDetail: 0,
  chunkQuads: 0,
  hiddenTiles: 0,
  splat: false,
  curveHandles: 0,
  curveEdits: 0,
  handlesOnScreen: () => [],
  invalidatedChunks: [],
};
window.__strata = state;

const q = new URLSearchParams(location.search);
const seed = q.get("seed") ?? "42";
const world = q.get("world");
const token = q.get("token");
const rings = (q.get("rings") ?? "2,1,2,4,8,0,1,0,1").split(",").map((s) => Math.max(0, Math.min(16, parseInt(s, 10) || 0)));
// Volume-chunk rings (LOD 0–3) around the camera, where the world has volume regions; an empty
// ?chunk_rings= asks for no chunks (0 rings is still the camera's chunk at each level).
const chunkRings = (q.get("chunk_rings") ?? "2,2,2,2")
  .split(",")
  .filter((s) => s.trim() !== "")
  .slice(0, 4)
  .map((s) => Math.max(0, Math.min(4, parseInt(s, 10) || 0)));
// Ptex pages for the tiles' faces (stream protocol v2), unless ?ptex=0.
const ptexOn = q.get("ptex") !== "0";
state.ptex = ptexOn;
// Texture splatting by the tiles' material weights, unless ?splat=0.
const splatOn = q.get("splat") !== "0";
state.splat = splatOn;
// The view cone the Ptex pages are chosen for reaches this far, metres (the fog starts at 8 km).
const PTEX_FAR_M = 8192;
// A turn of the camera by more than this (radians) sends the view again: the pages follow the cone.
const PTEX_TURN = 0.2;
// Frames the viewer lets the server send ahead of what it has decoded (stream protocol v2 credits).
const CREDIT_WINDOW = 16;
// The camera keeps at least this height above the ground under it, metres.
const MIN_CLEARANCE_M = 8;
const startX = Number(q.get("x") ?? 0) || 0;
const startZ = Number(q.get("z") ?? 0) || 0;
const startDist = Math.max(50, Math.min(20000, Number(q.get("dist") ?? 4600) || 4600));
const startPitch = (Math.max(5, Math.min(89.9, Number(q.get("pitch") ?? 34.4) || 34.4)) * Math.PI) / 180;
const CELL_M = 1; // default world; refined from /v1/info below

// ---- HUD and errors -------------------------------------------------------------------------
const hud = document.getElementById("hud") as HTMLElement;
const errorBox = document.getElementById("errors") as HTMLElement;
const title = document.getElementById("title-text") as HTMLElement;
title.textContent = world ? `world ${world}` : `seed ${seed}`;

function showError(text: string): void {
  state.errors.push(text);
  const line = document.createElement("div");
  line.textContent = text;
  errorBox.appendChild(line);
  while (errorBox.childElementCount > 6) errorBox.firstElementChild?.remove();
  errorBox.hidden = false;
}

// ---- renderer, scene, camera --------------------------------------------------------------------
const canvas = document.getElementById("view") as HTMLCanvasElement;
const gl = canvas.getContext("webgl2", { antialias: true, preserveDrawingBuffer: true });
state.webgl2 = gl !== null;
if (!gl) showError("this browser has no WebGL2: the viewer cannot draw");
const renderer = new THREE.WebGLRenderer({ canvas, context: gl ?? undefined, antialias: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.setSize(window.innerWidth, window.innerHeight);

const SKY = new THREE.Color().setRGB(0.62, 0.74, 0.86, THREE.SRGBColorSpace);
const scene = new THREE.Scene();
scene.background = SKY;
// Linear fog from FOG_NEAR_M to at most FOG_FAR_M; `updateFog` brings the far end in to the edge
// of the ground the view holds, so that edge never shows against the sky.
const FOG_NEAR_M = 8000;
const FOG_FAR_M = 36000;
const fog = new THREE.Fog(SKY, FOG_NEAR_M, FOG_FAR_M);
scene.fog = fog;
scene.add(new THREE.HemisphereLight(0xdde8ff, 0x4a3c2a, 0.8));
const sun = new THREE.DirectionalLight(0xfff1d8, 2.8);
sun.position.set(-0.8, 0.55, -0.3);
scene.add(sun);

const camera = new THREE.PerspectiveCamera(55, window.innerWidth / window.innerHeight, 5, 60000);
camera.position.set(startX, startDist * Math.sin(startPitch), startZ + startDist * Math.cos(startPitch));
const controls = new OrbitControls(camera, canvas);
controls.target.set(startX, 0, startZ);
controls.enableDamping = true;
controls.maxPolarAngle = Math.PI * 0.495;
controls.minDistance = 20;
controls.maxDistance = 20000;
controls.update();
state.moveBy = (dx, dz) => {
  camera.position.x += dx;
  camera.position.z += dz;
  controls.target.x += dx;
  controls.target.z += dz;
};

state.heldGround = () => ({
  camera: camera.position.toArray(),
  halfAngleDeg: halfAngleDeg(),
  tiles: [...heldTiles()].map((t) => {
    const side = t.spacing * (t.size - 1);
    return [t.originX, t.originZ, t.originX + side, t.originZ + side];
  }),
});
state.shore = (cols, rows) => shoreSamples([...heldTiles()], camera, cols, rows);
state.showWater = (on) => {
  terrain.traverse((o) => {
    if (o.name === "water" || o.name === "rivers") o.visible = on;
  });
};

window.addEventListener("resize", () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
});

// Fly: WASD / arrows move camera and target over the ground, R/F up and down, speed ∝ height.
const keys = new Set<string>();
window.addEventListener("keydown", (e) => keys.add(e.key.toLowerCase()));
window.addEventListener("keyup", (e) => keys.delete(e.key.toLowerCase()));
/** WASD's speed, metres per second: 1.2 times the height above the ground, at least 60. */
function flySpeed(): number {
  return Math.max(50, camera.position.y - groundAt(camera.position.x, camera.position.z)) * 1.2;
}

/** The row of the horizon (the camera's height, far ahead) as a fraction of the picture from the top. */
function horizonRow(): number {
  const ahead = new THREE.Vector3();
  camera.getWorldDirection(ahead);
  ahead.y = 0;
  if (ahead.lengthSq() < 1e-9) return 0;
  ahead.normalize().multiplyScalar(1e7).add(camera.position);
  const ndc = ahead.project(camera);
  return Math.max(0, Math.min(1, (1 - ndc.y) / 2));
}

function fly(dt: number): void {
  const forward = new THREE.Vector3();
  camera.getWorldDirection(forward);
  forward.y = 0;
  if (forward.lengthSq() < 1e-6) return;
  forward.normalize();
  const right = new THREE.Vector3(-forward.z, 0, forward.x);
  const move = new THREE.Vector3();
  if (keys.has("w") || keys.has("arrowup")) move.add(forward);
  if (keys.has("s") || keys.has("arrowdown")) move.sub(forward);
  if (keys.has("d") || keys.has("arrowright")) move.add(right);
  if (keys.has("a") || keys.has("arrowleft")) move.sub(right);
  if (keys.has("r")) move.y += 1;
  if (keys.has("f")) move.y -= 1;
  if (move.lengthSq() === 0) return;
  const speed = flySpeed();
  move.normalize().multiplyScalar(speed * dt);
  camera.position.add(move);
  controls.target.add(move);
}

// ---- tiles ----------------------------------------------------------------------------------------
const held = new Map<string, Held>();
// The Ptex pages of the stream session, in texture arrays the tiles' materials sample.
const ptex = new PtexStore(
  gl ? (gl.getParameter(gl.MAX_ARRAY_TEXTURE_LAYERS) as number) : 256,
  splatOn ? { patch: (shader) => addSplat(shader, true), key: "splat" } : undefined,
);
const terrain = new THREE.Group();
scene.add(terrain);
let wanted = new Set<string>(); // keys of the current view (client-side selection, as the server's)
let cellM = CELL_M;

// The river ribbons of held tiles; the lines of a world are pinned to the tile's version, so an
// edit that re-sends a tile also fetches its lines again.
const riverBase = world
  ? `v1/worlds/${encodeURIComponent(world)}/rivers/`
  : `v1/seeds/${encodeURIComponent(seed)}/rivers/`;
const rivers = new RiverLayer(
  (lod, x, z, version) =>
    new URL(`${riverBase}${lod}/${x}/${z}.json${world ? `?v=${version}` : ""}`, `${location.origin}${location.pathname}`).toString(),
  token ? { authorization: `Bearer ${token}` } : {},
  showError,
);

function putTile(tile: Tile, version: number): void {
  const key = tileKey(tile.lod, tile.x, tile.z);
  removeMesh(key);
  disposeRetiring(key);
  const mesh = buildMesh(tile, covered, tints, ptexOn ? ptex.material(key, tile.spacing) : sharedMaterial(splatOn));
  terrain.add(mesh);
  held.set(key, { mesh, tile, version, marked: hasMarks(tile) });
  state.held = held.size;
  rivers.put(key, mesh, tile, version);
  settleRetiring(false);
}

// Tiles that left the view stay drawn (a little lower, so their replacements win the depth test)
// until the view's tiles that cover their ground have all arrived: moving never opens holes.
const retiring = new Map<string, Held>();

function disposeRetiring(key: string): void {
  const h = retiring.get(key);
  if (!h) return;
  terrain.remove(h.mesh);
  disposeMesh(h.mesh);
  retiring.delete(key);
  state.retiring = retiring.size;
  state.freed++;
}

/** Frees the retiring tiles whose ground the view's held tiles cover (all of them when `all`). */
function settleRetiring(all: boolean): void {
  if (retiring.size === 0) return;
  const view = [...wanted].map((k) => k.split("/").map(Number));
  for (const [key, h] of [...retiring]) {
    const t = h.tile;
    const s = 2 ** t.lod;
    const [x0, z0, x1, z1] = [t.x * s, t.z * s, (t.x + 1) * s, (t.z + 1) * s];
    let covered = true;
    for (const [lod, x, z] of view) {
      const w = 2 ** lod;
      if (x * w >= x1 || (x + 1) * w <= x0 || z * w >= z1 || (z + 1) * w <= z0) continue;
      if (!held.has(tileKey(lod, x, z))) {
        covered = false;
        break;
      }
    }
    if (all || covered) disposeRetiring(key);
  }
}

/** Removes and disposes the mesh of `key` (its water and ribbons with it); whether there was one. */
function removeMesh(key: string): boolean {
  const h = held.get(key);
  if (!h) return false;
  terrain.remove(h.mesh);
  disposeMesh(h.mesh);
  held.delete(key);
  state.held = held.size;
  state.freed++;
  return true;
}

/** Retires the meshes the current view no longer holds: they are freed once covered. Their Ptex
 * pages are freed at once (the server reuses their slots), so they are drawn with vertex colours. */
function pruneToView(): void {
  ptex.keep(wanted);
  for (const [key, h] of [...held]) {
    if (wanted.has(key)) continue;
    rivers.drop(key);
    held.delete(key);
    disposeRetiring(key);
    h.mesh.position.y = -2 * 2 ** h.tile.lod;
    h.mesh.updateMatrix();
    retiring.set(key, h);
  }
  state.held = held.size;
  state.retiring = retiring.size;
  settleRetiring(false);
}

/** Ground height at world (x, z) from the finest held tile, bilinear; 0 when none covers it. */
function groundAt(x: number, z: number): number {
  return groundOrUndefined(x, z) ?? 0;
}

/** Ground height at world (x, z) from the finest held tile, bilinear; `undefined` when none covers it. */
function groundOrUndefined(x: number, z: number): number | undefined {
  return groundSample(x, z)?.height;
}

/** Ground height at world (x, z) and the LOD of the finest held tile it comes from. */
function groundSample(x: number, z: number): { height: number; lod: number } | undefined {
  return sampleGround(heldTiles(), x, z);
}

/** The held tiles (not the retiring ones). */
function* heldTiles(): Iterable<Tile> {
  for (const h of held.values()) yield h.tile;
}

// ---- volume chunks -----------------------------------------------------------------------------------
// Where the world's surface is not a heightfield (volume regions), the server streams chunk meshes;
// the tiles hide the vertices the chunks override.
const chunks = new ChunkLayer(scene, splatOn, ptexOn ? ptex : undefined);
state.showChunks = (on) => chunks.show(on);
let wantedChunks = new Set<string>();
/** Whether a held chunk gives the surface at world (x, y, z): the tiles hide marked vertices there. */
const covered = (x: number, y: number, z: number) => chunks.covers(x, y, z, cellM);
// Set when chunks arrive or are freed: the marked tiles' hidden vertices are re-evaluated before
// the next picture.
let hiddenStale = false;

function setHeldChunks(n: number): void {
  state.heldChunks = n;
  state.chunkQuads = chunks.quadCount();
  hiddenStale = true;
}

/** Hides the marked vertices of the held and retiring tiles where held chunks cover them now. */
function refreshHidden(): void {
  if (!hiddenStale) return;
  hiddenStale = false;
  let n = 0;
  for (const h of [...held.values(), ...retiring.values()]) {
    if (!h.marked) continue;
    updateHidden(h.mesh, h.tile, covered);
    const index = h.mesh.geometry.getIndex();
    if (index && h.mesh.geometry.drawRange.count < index.count) n++;
  }
  state.hiddenTiles = n;
}

const addressKey = (a: number[]) => chunkKey(a[0], a[1], a[2], a[3]);

// ---- the stream -------------------------------------------------------------------------------------
// Whether the stream worker's socket is open (the worker holds it; see connect()).
let socketOpen = false;
let lastCell = "";
let lastSent = 0;
// The world's biomes in the order of the tiles' weights, and their tints: the stream's `hello`
// names them (./biomes.ts).
let biomes: string[] = DEFAULT_BIOMES;
let tints = biomeTints(biomes);

/** The stream's URL (protocol v2), over `ws:`/`wss:` or, to read a refusal's JSON, `http:`/`https:`. */
function streamUrl(http = false): string {
  const proto = http ? location.protocol : location.protocol === "https:" ? "wss:" : "ws:";
  const query = new URLSearchParams({ protocol: "2" });
  if (world && token) query.set("token", token);
  const path = world ? `/v1/worlds/${encodeURIComponent(world)}/stream` : `/v1/seeds/${encodeURIComponent(seed)}/stream`;
  return new URL(`${path}?${query}`, `${proto}//${location.host}${location.pathname}`).toString();
}

/**
 * Why the server refuses the stream, when it does: a browser learns nothing from a failed
 * WebSocket handshake (close code 1006), so the same URL is asked over plain HTTP, where a bad
 * seed, an unknown world or a missing token is a 4xx JSON error (426 means the route is fine).
 */
async function refusal(): Promise<string | undefined> {
  try {
    const r = await fetch(streamUrl(true));
    if (r.status < 400 || r.status >= 500 || r.status === 426) return undefined;
    const e = (await r.json().catch(() => undefined))?.error;
    return e
      ? `server refused the stream: ${e.code}: ${e.message}${e.field ? ` (field ${e.field})` : ""}`
      : `server refused the stream: HTTP ${r.status}`;
  } catch {
    return undefined;
  }
}

/** Stops streaming for good and says why. */
function stop(reason: string): void {
  state.closed = reason;
  showError(`${reason}; not reconnecting (reload the page to try again)`);
}

// Credits owed to the server: one per handled frame, granted together once the frames waiting
// in the socket are handled (a task later), so the server sends no faster than this page
// decodes and meshes, and a hidden tab (no animation frames) still grants.
let owed = 0;
let grantScheduled = false;

function grant(): void {
  grantScheduled = false;
  if (owed === 0 || !socketOpen) return;
  send({ type: "credit", frames: owed });
  owed = 0;
}

function owe(): void {
  owed++;
  if (!grantScheduled) {
    grantScheduled = true;
    setTimeout(grant, 0);
  }
}

const lastForward = new THREE.Vector3();
/** The ground the last view sent holds (its coarsest square), metres; none before the first. */
let extent: Square | undefined;

/**
 * The distance in the ground plane from `(x, z)` to the nearest tile of the view that has not
 * arrived yet, metres (infinite when every one is held, or while tiles the view left still cover
 * the ground: they stay until their replacements arrive). While a view loads, its far rings are
 * the last to come, and the loaded rings' edge, their skirts hanging into nothing, stood on the
 * horizon as flat-topped blocks.
 */
function nearestMissingM(x: number, z: number): number {
  if (retiring.size > 0) return Infinity;
  let best = Infinity;
  for (const key of wanted) {
    if (held.has(key)) continue;
    const [lod, tx, tz] = key.split("/").map(Number);
    const size = 64 * cellM * 2 ** lod;
    const dx = Math.max(tx * size - x, x - (tx + 1) * size, 0);
    const dz = Math.max(tz * size - z, z - (tz + 1) * size, 0);
    best = Math.min(best, Math.hypot(dx, dz));
  }
  return best;
}

let missingM = Infinity;
let missingAt = 0;

/**
 * Makes the fog complete where the held ground ends: at the nearest edge of the view's extent, or
 * nearer where tiles of the view have not arrived yet, shortened by the cosine of the view cone's
 * half angle, since the fog grows with the depth along the view direction and an edge at the side
 * of the picture is that much shallower than it is far. Without it the last ring's outer edge
 * stood on the horizon as a stepped wall of tile edges.
 */
function updateFog(now: number): void {
  if (!extent) return;
  const p = camera.position;
  if (now - missingAt > 250) {
    missingAt = now;
    missingM = nearestMissingM(p.x, p.z);
  }
  const edge = Math.min(p.x - extent.x0, extent.x1 - p.x, p.z - extent.z0, extent.z1 - p.z, missingM);
  const far = Math.max(1000, Math.min(FOG_FAR_M, edge * Math.cos(THREE.MathUtils.degToRad(halfAngleDeg()))));
  fog.far = far;
  fog.near = Math.min(FOG_NEAR_M, 0.5 * far);
  state.fogFar = far;
}

/** The half angle of the camera's view cone (to the picture's corners), degrees. */
function halfAngleDeg(): number {
  const t = Math.tan(THREE.MathUtils.degToRad(camera.fov / 2));
  return Math.min(90, THREE.MathUtils.radToDeg(Math.atan(t * Math.hypot(1, camera.aspect))));
}

function sendView(force = false): void {
  if (!socketOpen) return;
  const x = camera.position.x;
  const z = camera.position.z;
  const size = 64 * cellM;
  // The chunk rings are centred on the camera in 3D: climbing a LOD-0 chunk (32 cells) is a new view.
  const cell = `${Math.floor(x / size)},${Math.floor(z / size)},${Math.floor(camera.position.y / (32 * cellM))}`;
  // The Ptex pages follow the view cone: turning the camera is a new view too.
  const forward = camera.getWorldDirection(new THREE.Vector3());
  const turned = ptexOn && forward.angleTo(lastForward) > PTEX_TURN;
  if (!force && cell === lastCell && !turned) return;
  const now = performance.now();
  if (!force && now - lastSent < 250) {
    return; // retried next frame
  }
  lastCell = cell;
  lastSent = now;
  wanted = selectView(x, z, rings, cellM);
  extent = viewExtentM(x, z, rings, cellM);
  state.viewTiles = wanted.size;
  const y = camera.position.y;
  lastForward.copy(forward);
  // `tile_format: 2`: the tiles carry each vertex's water kind, so ./riverMask.ts knows a river's water from a lake's.
  const view: Record<string, unknown> = { type: "view", x, z, rings, format: "bin", tile_format: 2, y, chunk_rings: chunkRings };
  // `chunks`: the volume chunks' quads get pages too (./chunk.ts draws them).
  if (ptexOn) view.ptex = { forward: forward.toArray(), half_angle_deg: halfAngleDeg(), far_m: PTEX_FAR_M, chunks: true };
  send(view);
}

/** Sends a message on the stream (through the worker, which holds the socket). */
function send(message: object): void {
  stream.postMessage({ op: "send", text: JSON.stringify(message) } satisfies ToWorker);
}

function connect(): void {
  socketOpen = false;
  stream.postMessage({ op: "connect", url: streamUrl() } satisfies ToWorker);
}

function onOpen(): void {
  socketOpen = true;
  lastCell = "";
  owed = 0;
  // A new session sends every page afresh, in slots of its own.
  ptex.clear();
  sendView(true);
  send({ type: "credit", frames: CREDIT_WINDOW });
}

function onClose(code: number, reason: string): void {
  socketOpen = false;
  state.inFlight = 0;
  // 1008 (no credit, too slow), 1009 (message too big), 1003 (unacceptable data): the server
  // closed on purpose and says why; reconnecting would end the same way.
  if (code === 1008 || code === 1009 || code === 1003) {
    stop(`stream closed by the server (${code}): ${reason || "no reason given"}`);
    return;
  }
  void refusal().then((why) => {
    if (why) {
      stop(why);
      return;
    }
    showError(`stream closed (${code}${reason ? ` ${reason}` : ""}); reconnecting in 3 s`);
    state.reconnects++;
    setTimeout(connect, 3000);
  });
}

// The socket and the decoding live in a worker: every message comes back from it in order, frames
// decoded (meshes are built here from the typed arrays it transfers), and the socket is read
// there even while a picture is being drawn here.
const stream = new Worker(new URL("./decode.worker.ts", import.meta.url), { type: "module" });
stream.onmessage = (ev: MessageEvent<Decoded>) => onDecoded(ev.data);
stream.onerror = (e) => showError(`stream worker: ${e.message}`);

function onDecoded(m: Decoded): void {
  if (m.type === "text") {
    onControl(JSON.parse(m.text));
    return;
  }
  if (m.type === "open") {
    onOpen();
    return;
  }
  if (m.type === "closed") {
    onClose(m.code, m.reason);
    return;
  }
  // Every binary frame spent a credit: give it back once the frame is handled.
  owe();
  switch (m.type) {
    case "error":
      showError(`bad frame: ${m.message}`);
      return;
    case "chunk": {
      state.inFlight = Math.max(0, state.inFlight - 1);
      state.chunks++;
      const key = chunkKey(m.lod, m.x, m.y, m.z);
      if (wantedChunks.has(key)) setHeldChunks(chunks.put(key, m.chunk));
      return;
    }
    case "ptex": {
      // Not counted in flight: the view reply's `sending` counts tiles and chunks only.
      state.ptexFrames++;
      state.ptexPages += m.pages.count;
      ptex.put(
        m.pages,
        (tile) => wanted.has(tile),
        (chunk) => wantedChunks.has(chunk) && chunks.holds(chunk),
      );
      updatePtexStats();
      return;
    }
    case "tile": {
      state.inFlight = Math.max(0, state.inFlight - 1);
      state.tiles++;
      const key = tileKey(m.lod, m.x, m.z);
      if (!wanted.has(key)) return; // sent for a view we have since left
      putTile(m.tile, m.version);
      return;
    }
    default:
      return; // a kind this viewer does not draw
  }
}

function updatePtexStats(): void {
  const s = ptex.stats();
  state.ptexApplied = ptex.applied;
  state.ptexFaces = s.faces;
  state.ptexDetail = s.detail;
  state.ptexChunkFaces = s.chunkFaces;
  state.ptexChunkDetail = s.chunkDetail;
}

/** The biome names of a `hello` or `world` message (v1's hello has none: the default world's
 * stay). */
function setBiomes(names: unknown): void {
  if (Array.isArray(names)) {
    biomes = names;
    tints = biomeTints(biomes);
  }
  state.biomes = biomes;
}

// eslint-disable-next-line @typescript-eslint/no-explicit-any
function onControl(m: any): void {
  switch (m.type) {
    case "hello":
      state.version = m.version;
      state.protocol = m.protocol;
      setBiomes(m.biomes);
      break;
    case "world":
      // An edit changed the generator or the biomes: the fresh tiles that follow weigh these.
      setBiomes(m.biomes);
      break;
    case "view":
      state.views++;
      state.inFlight = m.sending;
      state.idle = false;
      pruneToView();
      wantedChunks = new Set((m.chunks ?? []).map(addressKey));
      setHeldChunks(chunks.keep(wantedChunks));
      ptex.keepChunks(wantedChunks);
      updatePtexStats();
      break;
    case "idle":
      state.idle = true;
      state.inFlight = 0;
      state.version = m.version;
      settleRetiring(true);
      break;
    case "invalidate":
      // Fresh frames follow; the held meshes stay until they arrive and replace them.
      state.version = m.version;
      state.inFlight += m.tiles.length + (m.chunks ?? []).length;
      state.invalidatedChunks = m.chunks ?? [];
      curveTool?.onVersion(m.version);
      for (const a of m.dropped ?? []) {
        wantedChunks.delete(addressKey(a));
        setHeldChunks(chunks.remove(addressKey(a)));
      }
      ptex.keepChunks(wantedChunks);
      break;
    case "ptex":
      // The session's page budget; the faces listed left their detail level (their slots are free).
      ptex.toVista(m.to_vista ?? []);
      updatePtexStats();
      break;
    case "ack":
      onAck(m.id, m.version);
      break;
    case "error":
      showError(`server: ${m.code}: ${m.message}${m.field ? ` (${m.field})` : ""}`);
      if (typeof m.id === "string" && pending.delete(m.id)) state.pendingEdits = pending.size;
      break;
    default:
      showError(`unknown message ${String(m.type)}`);
  }
}

fetch(new URL("v1/info", `${location.origin}${location.pathname}`))
  .then((r) => (r.ok ? r.json() : Promise.reject(new Error(`/v1/info: HTTP ${r.status}`))))
  .then((info) => {
    if (typeof info?.limits?.max_river_lod === "number") rivers.enable(info.limits.max_river_lod);
    if (typeof info?.world?.cell_m === "number" && info.world.cell_m !== cellM) {
      cellM = info.world.cell_m;
      sendView(true);
    }
  })
  .catch((e: Error) => showError(e.message));
void pickStart().finally(connect);

/**
 * Without `?x=`/`?z=`, the view opens on land with relief rather than at (0, 0), which may be
 * seabed: the 16 km LOD-8 tile at the origin is searched for the land vertex (above 30 m) with
 * the most relief around it, and camera and target move there. Any failure keeps (0, 0).
 */
async function pickStart(): Promise<void> {
  if (q.has("x") || q.has("z")) return;
  const base = world ? `v1/worlds/${encodeURIComponent(world)}` : `v1/seeds/${encodeURIComponent(seed)}`;
  try {
    const r = await fetch(new URL(`${base}/tiles/8/0/0.bin`, `${location.origin}${location.pathname}`), {
      headers: token ? { authorization: `Bearer ${token}` } : {},
    });
    if (!r.ok) return;
    const t = decodeTile(new DataView(await r.arrayBuffer()));
    let best = { score: 0, i: 0, j: 0 };
    for (let j = 2; j < t.size - 2; j++) {
      for (let i = 2; i < t.size - 2; i++) {
        const h = t.heights[j * t.size + i];
        if (h < 30) continue;
        let lo = h;
        let hi = h;
        for (let b = -2; b <= 2; b++) {
          for (let a = -2; a <= 2; a++) {
            const n = t.heights[(j + b) * t.size + i + a];
            lo = Math.min(lo, n);
            hi = Math.max(hi, n);
          }
        }
        // Relief, unless the neighbourhood dips into the sea (a coast is not the goal).
        const score = lo < 0 ? 0 : hi - lo;
        if (score > best.score) best = { score, i, j };
      }
    }
    if (best.score === 0) return;
    state.moveBy(t.originX + best.i * t.spacing - controls.target.x, t.originZ + best.j * t.spacing - controls.target.z);
  } catch {
    // Keep (0, 0).
  }
}

// ---- editing ------------------------------------------------------------------------------------------
// Each edit is one region element added over the socket; `pending` maps the edit message's id to
// what it does, so the ack can push the element on the undo stack.
const pending = new Map<string, { add?: string }>();
const undoStack: string[] = [];
let editSeq = 0;
let crestStart: GroundPoint | undefined;
const toolsBox = document.getElementById("tools") as HTMLElement | null;
const toolStatus = document.getElementById("tool-status") as HTMLElement | null;

function setStatus(text: string): void {
  if (toolStatus) toolStatus.textContent = text;
}

function setTool(tool: Tool | ""): void {
  state.tool = tool;
  crestStart = undefined;
  controls.enabled = true;
  if (curveTool) void curveTool.show(tool === "curve").then(() => (state.curveHandles = curveTool?.count ?? 0));
  for (const b of toolsBox?.querySelectorAll("button[data-tool]") ?? []) {
    (b as HTMLButtonElement).classList.toggle("on", b.getAttribute("data-tool") === tool);
  }
  if (tool !== "curve") setStatus(tool ? `${tool}: click the terrain${tool === "crest" ? " at both ends" : ""} · Esc: stop` : "");
}

function sendEdit(patch: object[], add?: string): void {
  if (!socketOpen) {
    showError("cannot edit: the stream is not connected");
    return;
  }
  const id = `e${++editSeq}`;
  pending.set(id, { add });
  state.pendingEdits = pending.size;
  send({ type: "edit", id, patch });
  setStatus(`sent ${add ?? "undo"}…`);
}

function onAck(id: string, version: number): void {
  const p = pending.get(id);
  if (!p) return;
  pending.delete(id);
  state.pendingEdits = pending.size;
  state.edits++;
  if (p.add) {
    undoStack.push(p.add);
    state.lastEdit = p.add;
  }
  setStatus(`saved as version ${version}`);
}

async function undo(): Promise<void> {
  const id = undoStack.pop();
  if (!id || !world) return;
  try {
    const r = await fetch(new URL(`v1/worlds/${encodeURIComponent(world)}`, `${location.origin}${location.pathname}`), {
      headers: token ? { authorization: `Bearer ${token}` } : {},
    });
    if (!r.ok) throw new Error(`GET world: HTTP ${r.status}`);
    const doc = await r.json();
    const index = (doc?.scene?.regions ?? []).findIndex((e: { id?: string }) => e?.id === id);
    if (index < 0) throw new Error(`undo: region ${id} is no longer in the scene`);
    sendEdit(removePatch(id, index));
  } catch (e) {
    showError((e as Error).message);
  }
}

function groundHit(clientX: number, clientY: number): GroundPoint | undefined {
  const ndc = new THREE.Vector2((clientX / window.innerWidth) * 2 - 1, -(clientY / window.innerHeight) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObjects(terrain.children, false)[0];
  return hit ? { x: hit.point.x, y: hit.point.y, z: hit.point.z } : undefined;
}

function applyTool(p: GroundPoint): void {
  const tool = state.tool as Tool;
  if (tool === "crest") {
    if (!crestStart) {
      crestStart = p;
      setStatus("crest: now click the other end");
      return;
    }
    const region = crestRegion(crestStart, p) as { id: string };
    crestStart = undefined;
    sendEdit(addPatch(region), region.id);
    return;
  }
  const region = pointRegion(tool, p) as { id: string };
  sendEdit(addPatch(region), region.id);
}

// The curve tool drags the control points of the world's volume regions (./curveTool.ts).
const curveTool =
  world && token
    ? new CurveTool({
        scene,
        camera,
        worldUrl: new URL(`v1/worlds/${encodeURIComponent(world)}`, `${location.origin}${location.pathname}`).toString(),
        headers: { authorization: `Bearer ${token}` },
        showError,
        setStatus,
      })
    : undefined;
state.handlesOnScreen = () => curveTool?.onScreen(window.innerWidth, window.innerHeight) ?? [];

/** The pointer's position in normalised device coordinates. */
function ndcOf(e: PointerEvent): THREE.Vector2 {
  return new THREE.Vector2((e.clientX / window.innerWidth) * 2 - 1, -(e.clientY / window.innerHeight) * 2 + 1);
}

if (world && token && toolsBox && curveTool) {
  toolsBox.hidden = false;
  // The curve tool's drag: a press on a handle is the tool's, not the orbit's (a capturing
  // listener runs before the orbit controls' and stops the event there).
  canvas.addEventListener(
    "pointerdown",
    (e) => {
      if (state.tool !== "curve" || e.button !== 0) return;
      if (!curveTool.down(ndcOf(e), e.shiftKey)) return;
      e.stopImmediatePropagation();
      controls.enabled = false;
      canvas.setPointerCapture(e.pointerId);
    },
    { capture: true },
  );
  canvas.addEventListener("pointermove", (e) => {
    if (curveTool.dragging) curveTool.move(ndcOf(e));
  });
  canvas.addEventListener("pointerup", () => {
    if (!curveTool.dragging) return;
    controls.enabled = true;
    void curveTool.up().then(() => {
      state.curveEdits = curveTool.commits;
      state.curveHandles = curveTool.count;
    });
  });
  for (const b of toolsBox.querySelectorAll("button[data-tool]")) {
    b.addEventListener("click", () => {
      const t = b.getAttribute("data-tool") as Tool;
      setTool(state.tool === t ? "" : t);
    });
  }
  toolsBox.querySelector("#undo")?.addEventListener("click", () => void undo());
  window.addEventListener("keydown", (e) => {
    if (e.key === "Escape") setTool("");
    const n = Number(e.key);
    if (n >= 1 && n <= TOOLS.length) setTool(TOOLS[n - 1]);
    if (e.key === "z" && (e.ctrlKey || e.metaKey)) void undo();
  });
  // A click (no drag) with a tool selected edits; drags still orbit.
  let down: { x: number; y: number; t: number } | undefined;
  canvas.addEventListener("pointerdown", (e) => {
    down = { x: e.clientX, y: e.clientY, t: performance.now() };
  });
  canvas.addEventListener("pointerup", (e) => {
    if (!state.tool || state.tool === "curve" || !down || e.button !== 0) return;
    const moved = Math.hypot(e.clientX - down.x, e.clientY - down.y);
    if (moved > 5 || performance.now() - down.t > 600) return;
    const p = groundHit(e.clientX, e.clientY);
    if (!p) {
      showError("edit: no terrain under the cursor");
      return;
    }
    applyTool(p);
  });
}

// ---- world picker ----------------------------------------------------------------------------------
const picker = document.getElementById("picker") as HTMLSelectElement | null;
if (picker) {
  const here = world ? `world:${world}` : `seed:${seed}`;
  const option = (value: string, label: string) => {
    const o = document.createElement("option");
    o.value = value;
    o.textContent = label;
    o.selected = value === here;
    picker.appendChild(o);
  };
  for (const s of new Set([seed, "42", "7", "2026"])) option(`seed:${s}`, `seed ${s}`);
  fetch(new URL("v1/worlds", `${location.origin}${location.pathname}`), {
    headers: token ? { authorization: `Bearer ${token}` } : {},
  })
    .then((r) => (r.ok ? r.json() : Promise.reject(new Error(`world list: HTTP ${r.status}`))))
    .then((doc) => {
      for (const w of doc?.worlds ?? []) option(`world:${w.id}`, `world ${w.id} (seed ${w.seed})`);
    })
    .catch((e: Error) => showError(e.message));
  picker.addEventListener("change", () => {
    const [kind, value] = picker.value.split(/:(.*)/s);
    const next = new URLSearchParams();
    next.set(kind, value);
    if (kind === "world" && value === world && token) next.set("token", token);
    location.search = next.toString();
  });
}

// ---- cursor probe and HUD ------------------------------------------------------------------------
const pointer = new THREE.Vector2(2, 2);
canvas.addEventListener("pointermove", (e) => {
  pointer.set((e.clientX / window.innerWidth) * 2 - 1, -(e.clientY / window.innerHeight) * 2 + 1);
});
canvas.addEventListener("pointerleave", () => pointer.set(2, 2));
const raycaster = new THREE.Raycaster();

function probe(): string {
  if (Math.abs(pointer.x) > 1) return "–";
  raycaster.setFromCamera(pointer, camera);
  const hit = raycaster.intersectObjects(terrain.children, false)[0];
  if (!hit || !hit.face) return "–";
  const h = [...held.values()].find((x) => x.mesh === hit.object);
  if (!h) return "–";
  const t = h.tile;
  const n = t.size * t.size;
  const v = [hit.face.a, hit.face.b, hit.face.c].find((i) => i < n) ?? 0;
  let best = 0;
  for (let b = 1; b < t.biomeCount; b++) if (t.weights[v * t.biomeCount + b] > t.weights[v * t.biomeCount + best]) best = b;
  const slope = (Math.acos(Math.min(1, t.normals[3 * v + 1])) * 180) / Math.PI;
  return `${hit.point.y.toFixed(1)} m, slope ${slope.toFixed(0)}°, ${biomes[best] ?? `biome ${best}`} (LOD ${t.lod})`;
}

/** The orbit target rides on the ground (camera and target move together), so the orbit distance
 * is measured from the ground, not from y = 0. It is put back on the ground when it moves over
 * the ground or a finer tile arrives under it, not when an edit changes the ground under a still
 * target (an edit does not move the camera). */
let followed = "";
function followGround(): void {
  const g = groundSample(controls.target.x, controls.target.z);
  if (g === undefined) return;
  const at = `${controls.target.x.toFixed(1)},${controls.target.z.toFixed(1)},${g.lod}`;
  if (at === followed) return;
  followed = at;
  const dy = g.height - controls.target.y;
  controls.target.y += dy;
  camera.position.y += dy;
}

/** Collision: the camera never goes below the ground under it (plus a small clearance). The
 * clearance before this correction is recorded: with the target on the ground it stays positive
 * unless the ground rises between target and camera. */
function keepAboveGround(): void {
  // Not before the target is on the ground: raising the camera first and then the target with it
  // would lift the camera twice.
  if (followed === "") return;
  const g = groundOrUndefined(camera.position.x, camera.position.z);
  if (g === undefined) return;
  state.minClearance = Math.min(state.minClearance, camera.position.y - g);
  if (camera.position.y < g + MIN_CLEARANCE_M) camera.position.y = g + MIN_CLEARANCE_M;
}

let fps = 0;
let fpsFrames = 0;
let fpsSince = performance.now();
let hudAt = 0;
let last = performance.now();

function frame(now: number): void {
  const dt = Math.min(0.1, (now - last) / 1000);
  last = now;
  fly(dt);
  followGround();
  controls.update();
  keepAboveGround();
  sendView(false); // throttled: only when the camera crossed a LOD-0 tile or turned
  updateFog(now);
  refreshHidden();
  curveTool?.update(window.innerHeight);
  renderer.render(scene, camera);
  state.frames++;
  state.flySpeed = flySpeed();
  state.horizon = horizonRow();
  fpsFrames++;
  if (now - fpsSince >= 1000) {
    fps = (fpsFrames * 1000) / (now - fpsSince);
    fpsFrames = 0;
    fpsSince = now;
  }
  if (now - hudAt > 200) {
    hudAt = now;
    const r = rivers.stats();
    state.rivers = r.ribbons;
    state.riverLength = r.length;
    state.riverPending = r.pending;
    state.riverTiles = r.tiles;
    state.riverAboveGround = r.aboveGround;
    const p = camera.position;
    const ground = groundAt(p.x, p.z);
    hud.textContent = [
      `camera  x ${p.x.toFixed(0)}  y ${p.y.toFixed(0)}  z ${p.z.toFixed(0)} m`,
      `ground under camera ${ground.toFixed(1)} m, ${(p.y - ground).toFixed(0)} m above`,
      `cursor  ${probe()}`,
      `${fps.toFixed(0)} fps · tiles held ${state.held} · in flight ${state.inFlight} · received ${state.tiles} · chunks ${state.heldChunks} · v${state.version}`,
      ptexOn
        ? `ptex ${state.ptexFaces} faces textured, ${state.ptexDetail} in detail · chunks ${state.ptexChunkFaces} of ${state.chunkQuads} quads · ${state.ptexFrames} frames`
        : "ptex off (?ptex=0)",
      `rivers ${r.ribbons} ribbons, ${(r.length / 1000).toFixed(1)} km${r.pending ? ` · ${r.pending} tiles' lines to load` : ""}`,
      `drag: orbit · right-drag: pan · wheel: zoom · WASD/arrows: fly · R/F: up/down${world && token ? " · 1–6: edit tools · Ctrl+Z: undo" : ""}`,
    ].join("\n");
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
