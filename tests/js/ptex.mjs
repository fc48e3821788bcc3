// Ptex-textured terrain in the viewer (issue 20, Done-when 5): node ptex.mjs <server host:port>
// <on.png> <off.png>
//
// Opens the viewer twice at the same place (seed 42 around (-12 km, 26 km), grassy plains, looking
// down at 50° from 150 m, so the lower half of the picture is within 128 m of the camera, where
// faces get 256² pages), both without texture splatting (`?splat=0`; web/src/splat.ts would give the faces
// without a page a texture of its own, tests/js/tools.mjs compares it): with Ptex pages (the
// default) and with `?ptex=0`, the vertex colours alone. Each run waits on the viewer's state,
// never on fixed sleeps: the view has streamed (`idle`, nothing in flight; `idle` comes after the
// view's pages too) and, with Ptex, every face of every held tile is drawn with a page
// (`__strata.ptexFaces` = 16 × held tiles) and some with a detail page; then two more pictures are
// drawn (the textures are uploaded as the frame draws) before the screenshot, with the viewer's
// panels hidden (their text differs between the runs).
//
// Fails unless: Ptex frames and pages arrived and were applied (counted by the viewer) in the
// Ptex run and none in the other, both runs hold the same tiles, neither shows an error or logs
// a console error, and the Ptex picture has clearly more texture detail over the terrain.
//
// What Ptex adds is texture detail: the pages are the server's bake of the materials with their
// patterns, texel by texel (16 texels a metre on a 256² page of a LOD-0 face), where the vertex
// colours are one colour a vertex, smoothly interpolated. A page keeps only the pattern octaves of
// at most half its texel rate (src/ptex/bake.rs), and grass's start at 4 cycles a metre, so only
// the near faces' finest pages show its pattern; farther ones (and the whole view from 600 m, the
// earlier camera of this test) show grass as one flat colour, and there a Ptex page differs
// from the vertex colours only by its hue. Its measure is the mean |Laplacian| of the
// luminance below the horizon (tests/js/images.mjs, `meanAbsLaplacian`): the vertex-colour view
// has some (the lighting of the relief, silhouettes, water edges; the same in both runs, as both
// draw the same tiles from the same camera), the Ptex view that plus the pages' texel-to-texel
// variation. The test asks that the Ptex view's detail be at least DETAIL_RATIO_MIN times the
// vertex-colour view's. A colour difference (the earlier check) would pass for the wrong reason
// (vertex colours tinted unlike the pages' materials) and fail for one too (vertex colours tinted
// like them); the detail ratio does neither: the same tiles drawn twice with `?ptex=0` give a
// ratio of 1.00, and pages missing on the terrain (faces drawn with the vertex colours) pull it
// towards 1.
import { launch } from "./chromium.mjs";
import { meanAbsLaplacian } from "./images.mjs";
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
// The Ptex picture's texture detail (mean |Laplacian| of the luminance below the horizon) must be
// at least this many times the vertex-colour picture's. Seen: 6.80 against 0.09, a ratio of 76
// (the 256² pages cover about 45 % of the picture, at about 15 each); two runs with `?ptex=0` give
// 1.00, and a Ptex run whose pages were not applied is such a run. 10 is ten times that and
// a seventh of the ratio seen: detail pages drawn on less than about 6 % of the picture fail.
const DETAIL_RATIO_MIN = 10;
const TIMEOUT_MS = 200_000;
const PLACE = "seed=42&x=-12000&z=26000&dist=150&pitch=50&rings=1,1,1,1,1,1";

const failures = [];
const shots = {};
const states = {};
const { browser, close } = await launch(W, H);
try {
  for (const [name, query, path] of [
    ["ptex", "&splat=0", onPath],
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
      const { moveBy, shore, showWater, showChunks, ...rest } = window.__strata;
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
  const detail = { ptex: meanAbsLaplacian(a, top), off: meanAbsLaplacian(b, top) };
  const ratio = detail.off > 0 ? detail.ptex / detail.off : Infinity;
  console.log(
    `texture detail (mean |Laplacian| of the luminance) below the horizon (rows ${top}–${H - 1}): ` +
      `Ptex ${detail.ptex.toFixed(2)}, vertex colours ${detail.off.toFixed(2)}, ratio ${ratio.toFixed(2)} (at least ${DETAIL_RATIO_MIN})`,
  );
  if (!(ratio >= DETAIL_RATIO_MIN)) failures.push(`the Ptex pages add too little detail: ratio ${ratio.toFixed(2)} < ${DETAIL_RATIO_MIN}`);
}
if (failures.length) {
  console.error(`ptex test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("ptex ok");
