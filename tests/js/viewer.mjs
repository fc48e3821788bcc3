// Drives the strata viewer in headless Chromium (Debian's /usr/bin/chromium, never a downloaded
// browser): node viewer.mjs <page url> <screenshot.png> [copy.png …]
//
// Fails (exit 1) unless: the page has a WebGL2 context, at least MIN_TILES tiles arrive, no console
// errors, no page errors, no errors shown by the viewer, the screenshot is not blank (pixel
// variance above a threshold, and both sky and terrain present), and river ribbons are drawn: the
// test's place (seed 42 around (-12 km, 26 km)) has a river through the view, so once every held
// tile's river lines have arrived at least one ribbon with MIN_RIVER_M of centre line is drawn.
// The viewer speaks strata.stream.v2. Flying 5 km east at the default speed opens no holes (sky
// below the horizon line of every sampled frame at most SKY_MAX), and the camera stays above the
// ground, also opened with `&dist=300` at this place (the orbit distance is measured from the
// ground, not from y = 0).
import { launch } from "./chromium.mjs";
import { PNG } from "pngjs";
import { copyFileSync, mkdirSync } from "node:fs";
import { dirname } from "node:path";

const [url, shot, ...copies] = process.argv.slice(2);
if (!url || !shot) {
  console.error("usage: node viewer.mjs <url> <screenshot.png> [copy.png …]");
  process.exit(2);
}
const MIN_TILES = 50;
const TILE_TIMEOUT_MS = 45_000;
const MIN_VARIANCE = 150; // per-channel luminance variance over the image, 0…65025
const MIN_RIVER_M = 1000; // river centre line drawn as ribbons in the first view, metres
const MAX_RIBBON_ABOVE_GROUND_M = 8.01; // ribbon.ts' CHANNEL_DEPTH_MAX_M, and rounding
const SKY_MAX = 0.01; // fraction of sky-coloured pixels below the horizon while flying
const SKY = [158, 189, 219]; // the viewer's sky (sRGB 0.62, 0.74, 0.86)

/** The fraction of the pixels below the horizon row (`horizon`, a fraction of the height from the
 * top) within 6 levels of the sky colour. */
function skyFraction(img, horizon) {
  let sky = 0;
  let n = 0;
  for (let y = Math.ceil(horizon * img.height); y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const p = 4 * (y * img.width + x);
      n++;
      if (SKY.every((c, i) => Math.abs(img.data[p + i] - c) <= 6)) sky++;
    }
  }
  return n ? sky / n : 0;
}

/**
 * Flies 5 km east at the speed WASD flies (`__strata.flySpeed`, which grows with the height above
 * the ground): every SAMPLE_MS of wall time the camera moves on by the speed times the time gone,
 * and the frame is sampled: at most SKY_MAX of its pixels below the horizon line may be sky.
 * Chromium draws 1–4 frames a second here, so the camera is moved rather than keys held, and at
 * most MAX_SAMPLES frames are sampled (a slow flight is then flown faster, and says so).
 */
async function fly5km(page, label) {
  const SAMPLE_MS = 1500;
  const MAX_SAMPLES = 12;
  const DISTANCE = 5000;
  let travelled = 0;
  let samples = 0;
  let worst = 0;
  let faster = 0;
  while (travelled < DISTANCE) {
    const speed = await page.evaluate(() => window.__strata.flySpeed);
    const left = DISTANCE - travelled;
    const step = Math.min(left, Math.max(speed * (SAMPLE_MS / 1000), left / (MAX_SAMPLES - samples)));
    if (step > speed * (SAMPLE_MS / 1000) + 1e-6) faster++;
    await page.evaluate((dx) => window.__strata.moveBy(dx, 0), step);
    travelled += step;
    await page.waitForTimeout(SAMPLE_MS);
    const horizon = await page.evaluate(() => window.__strata.horizon);
    const sky = skyFraction(PNG.sync.read(await page.screenshot()), horizon);
    samples++;
    worst = Math.max(worst, sky);
    if (sky > SKY_MAX)
      failures.push(`${label}: a hole ${travelled.toFixed(0)} m into the flight: ${(100 * sky).toFixed(2)} % sky below the horizon`);
  }
  const s = await page.evaluate(() => window.__strata);
  console.log(
    `${label}: flew ${travelled.toFixed(0)} m east at ${s.flySpeed.toFixed(0)} m/s in ${samples} samples; ` +
      `most sky below the horizon ${(100 * worst).toFixed(2)} %, lowest clearance ${s.minClearance.toFixed(1)} m` +
      (faster ? `; ${faster} steps faster than the default speed to keep within ${MAX_SAMPLES} samples` : ""),
  );
  if (!(s.minClearance > 0)) failures.push(`${label}: the camera went ${s.minClearance} m below the ground`);
}

const failures = [];
const consoleErrors = [];
const { browser, close } = await launch(1280, 720);
try {
  const page = browser.pages()[0] ?? (await browser.newPage());
  page.on("console", (m) => {
    if (m.type() === "error") consoleErrors.push(m.text());
  });
  page.on("pageerror", (e) => consoleErrors.push(`page error: ${e.message}`));
  page.on("requestfailed", (r) => consoleErrors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));

  const t0 = Date.now();
  await page.goto(url, { waitUntil: "load" });
  try {
    await page.waitForFunction((n) => window.__strata && window.__strata.tiles >= n, MIN_TILES, {
      timeout: TILE_TIMEOUT_MS,
      polling: 250,
    });
  } catch {
    failures.push(`fewer than ${MIN_TILES} tiles within ${TILE_TIMEOUT_MS / 1000} s`);
  }
  // Let the view finish (idle) or give it a while longer, then a few frames to draw.
  await page
    .waitForFunction(() => window.__strata && window.__strata.idle, null, { timeout: 30_000, polling: 250 })
    .catch(() => {});
  // The river lines of the held tiles: requested after their tiles, two at a time.
  await page
    .waitForFunction(() => window.__strata && window.__strata.riverPending === 0 && window.__strata.riverTiles > 0, null, {
      timeout: 30_000,
      polling: 250,
    })
    .catch(() => {});
  await page.waitForTimeout(1500);
  const s = await page.evaluate(() => window.__strata);
  console.log(
    `after ${((Date.now() - t0) / 1000).toFixed(1)} s: tiles received ${s?.tiles}, held ${s?.held}, ` +
      `in flight ${s?.inFlight}, idle ${s?.idle}, frames ${s?.frames}, webgl2 ${s?.webgl2}`,
  );
  if (!s) failures.push("window.__strata is missing");
  else {
    if (!s.webgl2) failures.push("no WebGL2 context");
    if (s.errors.length) failures.push(`the viewer shows errors: ${s.errors.join(" | ")}`);
    if (s.held < 1) failures.push("no tile meshes held");
    if (s.protocol !== "strata.stream.v2") failures.push(`the viewer speaks ${s.protocol}, not strata.stream.v2`);
    // The fog is complete where the held ground ends, so its edge never stands on the horizon as
    // a stepped wall: at most the distance from the camera to the nearest side of the held
    // tiles' bounds, times the cosine of the view cone's half angle (the fog grows with depth).
    const ground = await page.evaluate(() => window.__strata.heldGround());
    const [cx, , cz] = ground.camera;
    const b = ground.tiles.reduce(
      (a, t) => [Math.min(a[0], t[0]), Math.min(a[1], t[1]), Math.max(a[2], t[2]), Math.max(a[3], t[3])],
      [Infinity, Infinity, -Infinity, -Infinity],
    );
    const edge = Math.min(cx - b[0], cz - b[1], b[2] - cx, b[3] - cz);
    const limit = edge * Math.cos((ground.halfAngleDeg * Math.PI) / 180);
    console.log(`fog complete at ${s.fogFar.toFixed(0)} m; held ground's nearest edge ${edge.toFixed(0)} m (limit ${limit.toFixed(0)} m)`);
    if (!(s.fogFar > 0 && s.fogFar <= limit + 1))
      failures.push(`the fog is complete at ${s.fogFar} m, beyond the held ground's edge (${limit.toFixed(0)} m in depth)`);
    console.log(
      `rivers: ${s.rivers} ribbons, ${(s.riverLength / 1000).toFixed(2)} km of centre line, ` +
        `lines for ${s.riverTiles} tiles, ${s.riverPending} requests left`,
    );
    // Away from lakes and the sea a ribbon lies at most a channel's depth (8 m, `ribbon.ts`)
    // above the ground: a line's level follows the network's, which can float tens of metres
    // above a hollow its valley does not reach (82 m near this place), where the band hung in
    // the air. Distances read the same interpolated ground, so only rounding can add to 8 m.
    console.log(`ribbons lie at most ${s.riverAboveGround.toFixed(2)} m above the ground`);
    if (!(s.riverAboveGround <= MAX_RIBBON_ABOVE_GROUND_M))
      failures.push(`a river ribbon lies ${s.riverAboveGround} m above the ground, over ${MAX_RIBBON_ABOVE_GROUND_M}`);
    if (!(s.rivers > 0)) failures.push("no river ribbons drawn at a place with a river");
    else if (!(s.riverLength >= MIN_RIVER_M))
      failures.push(`river ribbons hold ${s.riverLength} m of centre line, fewer than ${MIN_RIVER_M}`);
  }
  const glVersion = await page.evaluate(() => {
    const gl = document.querySelector("canvas")?.getContext("webgl2");
    return gl ? gl.getParameter(gl.VERSION) : null;
  });
  console.log(`WebGL: ${glVersion}`);
  if (!glVersion) failures.push("the canvas has no webgl2 context");

  mkdirSync(dirname(shot), { recursive: true });
  const png = await page.screenshot({ path: shot });
  for (const c of copies) {
    mkdirSync(dirname(c), { recursive: true });
    copyFileSync(shot, c);
  }
  const img = PNG.sync.read(png);
  let sum = 0;
  let sum2 = 0;
  const n = img.width * img.height;
  const buckets = new Map();
  for (let p = 0; p < n; p++) {
    const [r, g, b] = [img.data[4 * p], img.data[4 * p + 1], img.data[4 * p + 2]];
    const y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    sum += y;
    sum2 += y * y;
    const k = `${r >> 4},${g >> 4},${b >> 4}`;
    buckets.set(k, (buckets.get(k) ?? 0) + 1);
  }
  const mean = sum / n;
  const variance = sum2 / n - mean * mean;
  console.log(
    `screenshot ${shot}: ${img.width}×${img.height}, luminance mean ${mean.toFixed(1)}, variance ${variance.toFixed(1)}, ` +
      `${buckets.size} colour buckets`,
  );
  if (variance < MIN_VARIANCE) failures.push(`screenshot variance ${variance.toFixed(1)} < ${MIN_VARIANCE}: blank or flat`);
  if (buckets.size < 64) failures.push(`screenshot has only ${buckets.size} colour buckets: not a terrain`);

  // Fly 200 m east: the view changes, tiles that left it are freed, the new ones stream in, and
  // once the server reports idle the meshes held are exactly the view's tiles (bounded).
  const before = await page.evaluate(() => ({ ...window.__strata, errors: undefined }));
  await page.evaluate(() => window.__strata.moveBy(200, 0));
  const moved = await page
    .waitForFunction((v) => window.__strata.views > v && window.__strata.idle, before.views, {
      timeout: 15_000,
      polling: 250,
    })
    .then(() => true)
    .catch(() => false);
  const after = await page.evaluate(() => window.__strata);
  console.log(
    `after moving 200 m east: views ${before.views} → ${after.views}, received ${before.tiles} → ${after.tiles}, ` +
      `freed ${before.freed} → ${after.freed}, held ${after.held} of ${after.viewTiles} in view, idle ${after.idle}`,
  );
  if (after.views <= before.views) failures.push("moving the camera sent no new view");
  if (after.tiles <= before.tiles) failures.push("moving the camera streamed no new tiles");
  if (after.freed <= before.freed) failures.push("moving the camera freed no tiles");
  if (after.held > after.viewTiles) failures.push(`${after.held} meshes held for a view of ${after.viewTiles} tiles`);
  if (moved && after.held !== after.viewTiles)
    failures.push(`idle with ${after.held} meshes held for a view of ${after.viewTiles} tiles`);
  if (after.errors.length) failures.push(`the viewer shows errors: ${after.errors.join(" | ")}`);

  // Fly 5 km east at the viewer's default speed (issue 19, Done-when 2), then again opened with
  // `&dist=300` (a camera close to the ground, so a slow flight over fine tiles).
  await fly5km(page, "default distance");
  // Leaving the page aborts the requests still open (river lines), which the browser reports as
  // failed requests: the flight's view and its river lines finish first (within 90 s on the
  // usual 2-core machine; not within 90 s beside the other viewer test on a day it ran its
  // compute benches 1.5 times slower).
  await page
    .waitForFunction(() => window.__strata.idle && window.__strata.riverPending === 0, null, { timeout: 180_000, polling: 250 })
    .catch(() => failures.push("after the flight: the view or its river lines did not finish loading"));
  await page.goto(`${url}&dist=300`, { waitUntil: "load" });
  await page
    .waitForFunction(() => window.__strata && window.__strata.tiles >= 20, null, { timeout: 45_000, polling: 250 })
    .catch(() => failures.push("dist=300: fewer than 20 tiles"));
  await page.waitForTimeout(1000);
  const close300 = await page.evaluate(() => window.__strata.minClearance);
  console.log(`dist=300: lowest clearance ${close300.toFixed(1)} m`);
  if (!(close300 > 0)) failures.push(`dist=300: the camera went ${close300} m below the ground`);
  // The flight starts from a whole view, as the first one did.
  await page
    .waitForFunction(() => window.__strata.idle, null, { timeout: 150_000, polling: 500 })
    .catch(() => failures.push("dist=300: the view did not finish streaming"));
  await fly5km(page, "dist=300");
} finally {
  await close();
}
if (consoleErrors.length) failures.push(`console errors:\n  ${consoleErrors.join("\n  ")}`);
if (failures.length) {
  console.error(`viewer test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("viewer ok");
