// A cave opening in the viewer (issue 19, Done-when 1, the cave): node cave.mjs <server host:port>
// <strata element JSON> <geometry JSON> <with.png> <without.png>
//
// Creates two public worlds of seed 7, one with a `strata` element holding one cave that opens
// to the ground (`mark_openings`), one without it, and opens the viewer on each with the same
// camera: the orbit target on unbreached ground by the cave, LOD-0 chunk rings only. Fails unless
// chunk frames arrive for the cave's world (counted, none for the plain one) and the screenshots
// differ inside the cave's projected box and not outside it. Both runs are without Ptex pages
// (`&ptex=0`; the texture splatting is a function of the tiles alone): the stream's page budget
// is shared by the tiles' faces and the chunks' quads, so in the cave's world the chunks' vista
// pages leave the tile faces a little less for the finest levels, and the edge of the finest
// pages around the camera moves (0.26 outside the box with pages, over OUTSIDE_MAX), which is
// the budget at work and not the cave's geometry. volume.mjs checks the chunks' pages.
//
// The geometry (from tests/viewer.rs) gives the target `[x, z]`, the ground there, the orbit
// distance and pitch, and the box: the cave's bounding square, from below the cave's lowest
// opening to above the highest ground there. The box's eight corners are projected with the
// viewer's camera (55° vertical field of view, looking at the target from the camera position
// the HUD reports) and the rectangle around them widened by MARGIN_PX. The screenshots are taken
// with the viewer's panels (HUD, world picker) hidden: their text differs between the worlds.
import { launch } from "./chromium.mjs";
import { PNG } from "pngjs";
import { mkdirSync } from "node:fs";
import { dirname } from "node:path";

const [addr, element, geometry, withPath, withoutPath] = process.argv.slice(2);
if (!addr || !element || !geometry || !withPath || !withoutPath) {
  console.error("usage: node cave.mjs <host:port> <strata element JSON> <geometry JSON> <with.png> <without.png>");
  process.exit(2);
}
const geo = JSON.parse(geometry);
const W = 960;
const H = 540;
const FOV_DEG = 55;
// The box's rectangle is widened by this many pixels: the HUD reports the camera to the metre.
const MARGIN_PX = 12;
// Inside the box the cave must change the picture: mean |Δ luminance| (0…255) at least this.
const INSIDE_MIN = 2.0;
// Outside it nothing may change: the two worlds' tiles are the same bytes there and the camera
// is the same, so the mean |Δ luminance| stays below this, and at most OUTSIDE_PIXELS_MAX of the
// outside pixels change by more than 16 (a rendering-order flicker, not a feature).
const OUTSIDE_MAX = 0.25;
const OUTSIDE_PIXELS_MAX = 0.002;

async function create(scene) {
  const r = await fetch(`http://${addr}/v1/worlds`, {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify({ seed: "7", public: true, scene }),
  });
  if (!r.ok) {
    console.error(`POST /v1/worlds: HTTP ${r.status} ${await r.text()}`);
    process.exit(1);
  }
  return (await r.json()).id;
}

function luminance(png) {
  const img = PNG.sync.read(png);
  const y = new Float32Array(img.width * img.height);
  for (let p = 0; p < y.length; p++) {
    y[p] = 0.2126 * img.data[4 * p] + 0.7152 * img.data[4 * p + 1] + 0.0722 * img.data[4 * p + 2];
  }
  return y;
}

const sub = (a, b) => a.map((v, i) => v - b[i]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => a.map((v) => v / Math.sqrt(dot(a, a)));

// The screen rectangle [x0, y0, x1, y1] (pixels) around the box's projected corners, seen from
// `eye` looking at `target`, widened by MARGIN_PX and clipped to the screen.
function projectedBox(eye, target, box) {
  const f = unit(sub(target, eye));
  const r = unit(cross(f, [0, 1, 0]));
  const u = cross(r, f);
  const t = Math.tan((FOV_DEG * Math.PI) / 360);
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const x of [box.min[0], box.max[0]])
    for (const y of [box.min[1], box.max[1]])
      for (const z of [box.min[2], box.max[2]]) {
        const d = sub([x, y, z], eye);
        const depth = Math.max(dot(d, f), 1);
        const sx = ((dot(d, r) / (depth * t * (W / H)) + 1) / 2) * W;
        const sy = ((1 - dot(d, u) / (depth * t)) / 2) * H;
        [x0, y0, x1, y1] = [Math.min(x0, sx), Math.min(y0, sy), Math.max(x1, sx), Math.max(y1, sy)];
      }
  const clip = (v, hi) => Math.round(Math.max(0, Math.min(hi, v)));
  return [clip(x0 - MARGIN_PX, W), clip(y0 - MARGIN_PX, H), clip(x1 + MARGIN_PX, W), clip(y1 + MARGIN_PX, H)];
}

const withCave = await create({ strata: [JSON.parse(element)] });
const plain = await create({});
const failures = [];
const shots = {};
const eyes = {};
const { browser, close } = await launch(W, H);
try {
  for (const [name, id, path] of [
    ["cave", withCave, withPath],
    ["plain", plain, withoutPath],
  ]) {
    const page = await browser.newPage();
    const [x, z] = geo.target;
    const url = `http://${addr}/?world=${id}&x=${x}&z=${z}&dist=${geo.dist}&pitch=${geo.pitch}&rings=1,1,1,1&chunk_rings=4&ptex=0`;
    await page.goto(url, { waitUntil: "load" });
    await page
      .waitForFunction(() => window.__strata && window.__strata.idle && window.__strata.inFlight === 0, null, {
        timeout: 240_000,
        polling: 250,
      })
      .catch(() => failures.push(`${name}: the view did not finish streaming`));
    await page.waitForTimeout(1500);
    const s = await page.evaluate(() => ({ ...window.__strata }));
    const hud = await page.evaluate(() => document.getElementById("hud")?.textContent ?? "");
    const m = hud.match(/camera\s+x (-?\d+)\s+y (-?\d+)\s+z (-?\d+)/);
    if (m) eyes[name] = [Number(m[1]), Number(m[2]), Number(m[3])];
    else failures.push(`${name}: no camera position in the HUD: ${hud}`);
    console.log(`${name}: ${s.tiles} tiles, ${s.chunks} chunk frames, ${s.heldChunks} chunks held, camera ${eyes[name]}, errors ${s.errors.join(" | ")}`);
    if (s.errors.length) failures.push(`${name}: the viewer shows errors: ${s.errors.join(" | ")}`);
    if (name === "cave" && !(s.chunks > 0 && s.heldChunks > 0)) failures.push("no chunk frames arrived for the cave");
    if (name === "plain" && s.chunks !== 0) failures.push(`${s.chunks} chunk frames for a world without caves`);
    await page.evaluate(() => document.querySelectorAll(".panel").forEach((e) => (e.style.visibility = "hidden")));
    await page.waitForTimeout(500);
    mkdirSync(dirname(path), { recursive: true });
    shots[name] = await page.screenshot({ path });
    await page.close();
  }
} finally {
  await close();
}
if (eyes.cave && eyes.plain && eyes.cave.some((v, i) => Math.abs(v - eyes.plain[i]) > 1)) {
  failures.push(`the camera differs between the worlds: ${eyes.cave} and ${eyes.plain}`);
}
const eye = eyes.plain ?? [geo.target[0], geo.ground + geo.dist, geo.target[1]];
const [bx0, by0, bx1, by1] = projectedBox(eye, [geo.target[0], geo.ground, geo.target[1]], geo.box);
const a = luminance(shots.cave);
const b = luminance(shots.plain);
let [inSum, inN, outSum, outN, outBig] = [0, 0, 0, 0, 0];
for (let y = 0; y < H; y++) {
  for (let x = 0; x < W; x++) {
    const d = Math.abs(a[y * W + x] - b[y * W + x]);
    if (x >= bx0 && x < bx1 && y >= by0 && y < by1) {
      inSum += d;
      inN++;
    } else {
      outSum += d;
      outN++;
      if (d > 16) outBig++;
    }
  }
}
const inside = inN ? inSum / inN : 0;
const outside = outN ? outSum / outN : 0;
const big = outN ? outBig / outN : 0;
console.log(
  `box [${bx0}, ${by0}]–[${bx1}, ${by1}] px (${((100 * inN) / (W * H)).toFixed(1)} % of the picture); ` +
    `mean |Δ luminance| inside ${inside.toFixed(2)}, outside ${outside.toFixed(3)}; outside pixels changed by > 16: ${(100 * big).toFixed(3)} %`,
);
if (inN === 0 || inN === W * H) failures.push(`the cave's box covers ${inN} of ${W * H} pixels`);
if (inside < INSIDE_MIN) failures.push(`the cave does not show: inside difference ${inside.toFixed(2)} < ${INSIDE_MIN}`);
if (outside > OUTSIDE_MAX) failures.push(`the picture changed outside the cave's box: ${outside.toFixed(3)} > ${OUTSIDE_MAX}`);
if (big > OUTSIDE_PIXELS_MAX) failures.push(`${(100 * big).toFixed(3)} % of the outside pixels changed by more than 16`);
if (failures.length) {
  console.error(`cave test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("cave ok");
