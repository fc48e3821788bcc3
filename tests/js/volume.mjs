// Volume chunks in the viewer (issue 19, Done-when 1, the arch): node volume.mjs <server host:port>
// <arch element JSON> <with.png> <without.png>
//
// Creates two public worlds of seed 7, one with the arch volume element, one without, opens the
// viewer on each at the arch and waits for the view to stream. Fails unless chunk frames arrive
// over the stream for the arch's world (counted) and are drawn, none arrive for the plain world,
// and the screenshots differ where the arch stands (a box at the centre) and not at the left and
// right edges, over a hundred metres from the arch's box. Issue 19's hole: the arch's world opened
// again without chunk rings (`&chunk_rings=`, no chunk arrives) must look like the plain world at the centre too
// (`<with>-no-chunks.png`): the tiles hide the vertices the arch overrides only where the viewer
// holds the chunk that draws them, so without chunks the ground is drawn whole, not with a hole
// (`__strata.hiddenTiles`, the tiles hiding vertices, is 0 there and not in the arch's run).
import { launch } from "./chromium.mjs";
import { PNG } from "pngjs";
import { mkdirSync } from "node:fs";
import { dirname } from "node:path";

const [addr, arch, withPath, withoutPath] = process.argv.slice(2);
if (!addr || !arch || !withPath || !withoutPath) {
  console.error("usage: node volume.mjs <host:port> <arch element JSON> <with.png> <without.png>");
  process.exit(2);
}
const W = 960;
const H = 540;
const ARCH_MIN = 2.0; // mean |Δ luminance| in the centre box, 0…255
const FAR_MAX = 0.5; // mean |Δ luminance| in the edge patches
const HOLE_MAX = 0.5; // mean |Δ luminance| in the centre box, the arch's world without chunks

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

function meanDiff(a, b, x0, y0, w, h) {
  let s = 0;
  for (let y = y0; y < y0 + h; y++) for (let x = x0; x < x0 + w; x++) s += Math.abs(a[y * W + x] - b[y * W + x]);
  return s / (w * h);
}

const withArch = await create({ volumes: [JSON.parse(arch)] });
const plain = await create({});
const failures = [];
const shots = {};
const { browser, close } = await launch(W, H);
try {
  for (const [name, id, path] of [
    ["arch", withArch, withPath],
    ["plain", plain, withoutPath],
    ["arch without chunks", withArch, withPath.replace(/\.png$/, "-no-chunks.png")],
  ]) {
    const page = await browser.newPage();
    const rings = name === "arch without chunks" ? "&chunk_rings=" : "";
    const url = `http://${addr}/?world=${id}&x=32&z=24&dist=170&pitch=22&rings=1,1,1,1${rings}`;
    await page.goto(url, { waitUntil: "load" });
    await page
      .waitForFunction(() => window.__strata && window.__strata.idle && window.__strata.inFlight === 0, null, {
        timeout: 240_000,
        polling: 250,
      })
      .catch(() => failures.push(`${name}: the view did not finish streaming`));
    await page.waitForTimeout(1500);
    const s = await page.evaluate(() => ({ ...window.__strata }));
    console.log(
      `${name}: ${s.tiles} tiles, ${s.chunks} chunk frames, ${s.heldChunks} chunks held, ` +
        `${s.hiddenTiles} tiles with vertices hidden under chunks, errors ${s.errors.join(" | ")}`,
    );
    if (s.errors.length) failures.push(`${name}: the viewer shows errors: ${s.errors.join(" | ")}`);
    if (name === "arch" && !(s.chunks > 0 && s.heldChunks > 0)) failures.push("no chunk frames arrived for the arch");
    if (name === "arch" && !(s.hiddenTiles > 0)) failures.push("no tile hides the vertices the arch's chunks draw");
    if (name !== "arch" && s.hiddenTiles !== 0) failures.push(`${name}: ${s.hiddenTiles} tiles hide vertices with no chunk held`);
    if (name !== "arch" && s.chunks !== 0) failures.push(`${name}: ${s.chunks} chunk frames arrived`);
    mkdirSync(dirname(path), { recursive: true });
    shots[name] = await page.screenshot({ path });
    await page.close();
  }
} finally {
  await close();
}
const a = luminance(shots.arch);
const b = luminance(shots.plain);
const centre = meanDiff(a, b, W / 2 - 120, H / 2 - 120, 240, 240);
const left = meanDiff(a, b, 0, H / 2, 60, 100);
const right = meanDiff(a, b, W - 60, H / 2, 60, 100);
const bare = meanDiff(luminance(shots["arch without chunks"]), b, W / 2 - 120, H / 2 - 120, 240, 240);
console.log(
  `mean |Δ luminance|: centre ${centre.toFixed(2)}, left edge ${left.toFixed(2)}, right edge ${right.toFixed(2)}; ` +
    `centre without chunks ${bare.toFixed(2)}`,
);
if (bare > HOLE_MAX) failures.push(`without chunks the arch's world differs from the plain one at the centre: ${bare.toFixed(2)} (a hole)`);
if (centre < ARCH_MIN) failures.push(`the arch does not show: centre difference ${centre.toFixed(2)} < ${ARCH_MIN}`);
if (left > FAR_MAX || right > FAR_MAX) failures.push(`the picture changed far from the arch: ${left.toFixed(2)}, ${right.toFixed(2)}`);
if (failures.length) {
  console.error(`volume test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("volume ok");
