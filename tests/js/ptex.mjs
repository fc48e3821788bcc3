// Ptex-textured terrain in the viewer (issue 20, Done-when 5): node ptex.mjs <server host:port>
// <on.png> <off.png>
//
// Opens the viewer twice at the same place (seed 42 around (-12 km, 26 km), looking down at 35°
// from 600 m): with Ptex pages (the default) and with `?ptex=0&splat=0`, the vertex colours alone
// (the texture splatting of faces without a page, web/src/splat.ts, is the bake's palette: with it
// both runs would show the same materials; tests/js/tools.mjs compares the splatting). Each run waits on the viewer's
// state, never on fixed sleeps: the view has streamed (`idle`, nothing in flight; `idle` comes
// after the view's pages too) and, with Ptex, every face of every held tile is drawn with a page
// (`__strata.ptexFaces` = 16 × held tiles) and some with a detail page; then two more pictures are
// drawn (the textures are uploaded as the frame draws) before the screenshot, with the viewer's
// panels hidden (their text differs between the runs).
//
// Fails unless: Ptex frames and pages arrived and were applied (counted by the viewer) in the
// Ptex run and none in the other, both runs hold the same tiles, neither shows an error or logs
// a console error, and the screenshots differ clearly over the terrain: the mean |Δ| of the RGB
// channels (0…255) over the pixels below the horizon is at least DIFF_MIN. Both runs draw the
// same tiles from the same camera, so without pages the pictures are the same (0.00 when both
// runs are opened with `?ptex=0`; the other screenshot tests see at most 0.25 of rendering noise,
// see cave.mjs); the pages' albedo (the server's materials, with their noise) replaces the
// viewer's biome-tinted vertex colours and differs by about 48 here. DIFF_MIN = 10 is 40 times
// the noise and a fifth of the difference seen: pages drawn on less than about a fifth of the
// terrain in the picture, or on none, fall below it.
import { launch } from "./chromium.mjs";
import { meanRgbDiff } from "./images.mjs";
import { PNG } from "pngjs";
import { mkdirSync } from "node:fs";
import { dirname } from "node:path";

const [addr, onPath, offPath] = process.argv.slice(2);
if (!addr || !onPath || !offPath) {
  console.error("usage: node ptex.mjs <host:port> <on.png> <off.png>");
  process.exit(2);
}
const W = 960;
const H = 540;
const FACES_PER_TILE = 16;
// The pictures must differ by at least this mean |Δ| per RGB channel below the horizon (0…255).
const DIFF_MIN = 10.0;
const TIMEOUT_MS = 200_000;
const PLACE = "seed=42&x=-12000&z=26000&dist=600&pitch=35&rings=1,1,1,1,1,1";

const failures = [];
const shots = {};
const states = {};
const { browser, close } = await launch(W, H);
try {
  for (const [name, query, path] of [
    ["ptex", "", onPath],
    ["off", "&ptex=0&splat=0", offPath],
  ]) {
    const page = await browser.newPage();
    const consoleErrors = [];
    page.on("console", (m) => {
      if (m.type() === "error") consoleErrors.push(m.text());
    });
    page.on("pageerror", (e) => consoleErrors.push(`page error: ${e.message}`));
    page.on("requestfailed", (r) => consoleErrors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
    const t0 = Date.now();
    await page.goto(`http://${addr}/?${PLACE}${query}`, { waitUntil: "load" });
    await page
      .waitForFunction(
        (perTile) => {
          const s = window.__strata;
          if (!s || !s.idle || s.inFlight !== 0 || s.held === 0) return false;
          return !s.ptex || (s.ptexFaces >= perTile * s.held && s.ptexDetail > 0);
        },
        FACES_PER_TILE,
        { timeout: TIMEOUT_MS, polling: 250 },
      )
      .catch(() => failures.push(`${name}: the view (and its pages) did not finish streaming in ${TIMEOUT_MS / 1000} s`));
    // Two more pictures: the pages reach the GPU as a frame draws.
    const drawn = await page.evaluate(() => window.__strata.frames);
    await page.waitForFunction((n) => window.__strata.frames >= n + 2, drawn, { timeout: 60_000, polling: 100 });
    await page.evaluate(() => document.querySelectorAll(".panel").forEach((e) => (e.style.visibility = "hidden")));
    const hidden = await page.evaluate(() => window.__strata.frames);
    await page.waitForFunction((n) => window.__strata.frames >= n + 2, hidden, { timeout: 60_000, polling: 100 });
    const s = await page.evaluate(() => {
      const { moveBy, shore, showWater, ...rest } = window.__strata;
      return rest;
    });
    states[name] = s;
    console.log(
      `${name}: ${((Date.now() - t0) / 1000).toFixed(0)} s, ${s.tiles} tiles received, ${s.held} held, ` +
        `${s.ptexFrames} Ptex frames, ${s.ptexPages} pages received, ${s.ptexApplied} applied, ` +
        `${s.ptexFaces} faces textured (${s.ptexDetail} in detail), errors ${s.errors.join(" | ") || "none"}`,
    );
    if (s.errors.length) failures.push(`${name}: the viewer shows errors: ${s.errors.join(" | ")}`);
    if (consoleErrors.length) failures.push(`${name}: console errors:\n  ${consoleErrors.join("\n  ")}`);
    mkdirSync(dirname(path), { recursive: true });
    shots[name] = { png: await page.screenshot({ path }), horizon: s.horizon };
    await page.close();
  }
} finally {
  await close();
}

const on = states.ptex ?? {};
const off = states.off ?? {};
if (!(on.ptex && on.ptexFrames > 0 && on.ptexPages > 0 && on.ptexApplied > 0)) failures.push("no Ptex pages arrived or were applied");
if (!(on.ptexFaces >= FACES_PER_TILE * on.held)) failures.push(`${on.ptexFaces} faces textured of ${FACES_PER_TILE * on.held}`);
if (!(on.ptexDetail > 0)) failures.push("no face got a detail page");
if (off.ptex || off.ptexFrames !== 0) failures.push(`?ptex=0 still received ${off.ptexFrames} Ptex frames`);
if (on.held !== off.held) failures.push(`the runs hold different tiles: ${on.held} and ${off.held}`);

if (shots.ptex && shots.off) {
  const a = PNG.sync.read(shots.ptex.png);
  const b = PNG.sync.read(shots.off.png);
  const top = Math.ceil(Math.max(shots.ptex.horizon, shots.off.horizon) * H) + 4;
  const diff = meanRgbDiff(a, b, top);
  console.log(`mean |Δ RGB| below the horizon (rows ${top}–${H - 1}): ${diff.toFixed(2)} (at least ${DIFF_MIN})`);
  if (!(diff >= DIFF_MIN)) failures.push(`the Ptex pages do not show: mean difference ${diff.toFixed(2)} < ${DIFF_MIN}`);
}
if (failures.length) {
  console.error(`ptex test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("ptex ok");
