// A scripted edit through the viewer's UI (issue 7, Done-when 2): node edit.mjs <server host:port>
// <before.png> <after.png>
//
// Creates a world over HTTP (its admin token can edit), opens the viewer on it with the token,
// waits for the view to stream, takes a screenshot, picks the "raise" tool with key 1, clicks the
// terrain at the centre of the canvas, waits for the server's ack and the re-streamed tiles, and
// takes a second screenshot. Fails unless the picture changed around the click (mean luminance
// difference above EDITED_MIN in a box there) and not far from it (below FAR_MAX in patches
// at the left and right edges, hundreds of metres outside the edit's region).
import { launch } from "./chromium.mjs";
import { PNG } from "pngjs";
import { mkdirSync, writeFileSync } from "node:fs";
import { dirname } from "node:path";

const [addr, beforePath, afterPath] = process.argv.slice(2);
if (!addr || !beforePath || !afterPath) {
  console.error("usage: node edit.mjs <host:port> <before.png> <after.png>");
  process.exit(2);
}
const W = 1280;
const H = 720;
const EDITED_MIN = 2.0; // mean |Δ luminance| in the box around the click, 0…255
const FAR_MAX = 0.5; // mean |Δ luminance| in the far patches

const created = await fetch(`http://${addr}/v1/worlds`, {
  method: "POST",
  headers: { "content-type": "application/json" },
  body: JSON.stringify({ seed: "42" }),
});
if (!created.ok) {
  console.error(`POST /v1/worlds: HTTP ${created.status} ${await created.text()}`);
  process.exit(1);
}
const world = await created.json();
const token = world.tokens?.admin;
const url = `http://${addr}/?world=${encodeURIComponent(world.id)}&token=${encodeURIComponent(token)}&x=-12000&z=26000&dist=1200&rings=1,1,1,1,1,1`;
console.log(`world ${world.id}: ${url}`);

const failures = [];
const consoleErrors = [];
const { browser, close } = await launch(W, H);

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

async function settle(page) {
  await page.waitForFunction(() => window.__strata && window.__strata.idle && window.__strata.inFlight === 0, null, {
    timeout: 150_000,
    polling: 250,
  });
  await page.waitForTimeout(1500);
}

try {
  const page = browser.pages()[0] ?? (await browser.newPage());
  page.on("console", (m) => {
    if (m.type() === "error") consoleErrors.push(m.text());
  });
  page.on("pageerror", (e) => consoleErrors.push(`page error: ${e.message}`));
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => window.__strata && window.__strata.tiles >= 20, null, { timeout: 60_000 });
  await settle(page);
  const tools = await page.isVisible("#tools");
  if (!tools) failures.push("the edit tools are not shown for a world with an edit token");
  const before = await page.screenshot();
  mkdirSync(dirname(beforePath), { recursive: true });
  writeFileSync(beforePath, before);

  // Through the UI: key 1 picks "raise", a click on the terrain edits.
  await page.keyboard.press("1");
  const tool = await page.evaluate(() => window.__strata.tool);
  if (tool !== "raise") failures.push(`key 1 selected tool ${JSON.stringify(tool)}, not "raise"`);
  const v0 = await page.evaluate(() => window.__strata.version);
  await page.mouse.click(W / 2, H / 2);
  await page.waitForFunction(() => window.__strata.edits >= 1, null, { timeout: 30_000, polling: 100 }).catch(() => {
    failures.push("no ack for the edit within 30 s");
  });
  await page.waitForFunction((v) => window.__strata.version > v, v0, { timeout: 30_000 }).catch(() => {});
  await settle(page);
  const after = await page.screenshot();
  writeFileSync(afterPath, after);
  const s = await page.evaluate(() => window.__strata);
  console.log(`edits ${s.edits}, version ${v0} → ${s.version}, last region ${s.lastEdit}, errors ${s.errors.length}`);
  if (s.errors.length) failures.push(`the viewer shows errors: ${s.errors.join(" | ")}`);

  const a = luminance(before);
  const b = luminance(after);
  const edited = meanDiff(a, b, W / 2 - 100, H / 2 - 100, 200, 200);
  // Left and right of the click at mid-height: terrain some 600 m sideways of the edited
  // region (±160 m), clear of the HUD, the title and the tool bar.
  const farLeft = meanDiff(a, b, 10, H / 2 + 20, 80, 80);
  const farRight = meanDiff(a, b, W - 90, H / 2 + 20, 80, 80);
  console.log(`mean |Δ luminance|: around the click ${edited.toFixed(2)}, far patches ${farLeft.toFixed(2)} and ${farRight.toFixed(2)}`);
  if (edited < EDITED_MIN) failures.push(`the edited area barely changed (${edited.toFixed(2)} < ${EDITED_MIN})`);
  if (farLeft > FAR_MAX || farRight > FAR_MAX)
    failures.push(`far from the edit the picture changed (${farLeft.toFixed(2)}, ${farRight.toFixed(2)} > ${FAR_MAX})`);
} finally {
  await close();
}
if (consoleErrors.length) failures.push(`console errors:\n  ${consoleErrors.join("\n  ")}`);
if (failures.length) {
  console.error(`edit test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("edit ok");
