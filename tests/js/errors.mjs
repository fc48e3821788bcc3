// The viewer's errors (issue 19, Done-when 3): node errors.mjs <server host:port>
//
// Opens the viewer on a bad seed and on an unknown world. Fails unless each time the viewer shows
// the server's own error (its code and message, read from the stream route over HTTP because a
// browser learns nothing from a refused WebSocket handshake) and stops: no reconnection attempt
// follows, even after the 3 s the viewer waits before reconnecting to a stream that merely dropped.
import { launch } from "./chromium.mjs";

const [addr] = process.argv.slice(2);
if (!addr) {
  console.error("usage: node errors.mjs <host:port>");
  process.exit(2);
}
const failures = [];
const { browser, close } = await launch(640, 360);
try {
  for (const [query, code] of [
    ["seed=not-a-seed", "bad_seed"],
    ["world=no-such-world", "world_not_found"],
  ]) {
    const page = await browser.newPage();
    await page.goto(`http://${addr}/?${query}`, { waitUntil: "load" });
    const shown = await page
      .waitForFunction(() => window.__strata && window.__strata.closed !== "", null, { timeout: 30_000, polling: 250 })
      .then(() => true)
      .catch(() => false);
    // Longer than the reconnect delay: a viewer that reconnects would have tried by now.
    await page.waitForTimeout(4000);
    const s = await page.evaluate(() => ({ closed: window.__strata.closed, reconnects: window.__strata.reconnects }));
    const text = await page.evaluate(() => document.getElementById("errors")?.textContent ?? "");
    console.log(`?${query}: closed "${s.closed}", ${s.reconnects} reconnects; shown: ${text}`);
    if (!shown) failures.push(`?${query}: the viewer did not stop with a reason`);
    if (!s.closed.includes(code)) failures.push(`?${query}: the reason "${s.closed}" does not name ${code}`);
    if (!text.includes(code)) failures.push(`?${query}: the page does not show ${code}`);
    if (s.reconnects !== 0) failures.push(`?${query}: ${s.reconnects} reconnection attempts after a 4xx`);
    await page.close();
  }
} finally {
  await close();
}
if (failures.length) {
  console.error(`errors test failed:\n- ${failures.join("\n- ")}`);
  process.exit(1);
}
console.log("errors ok");
