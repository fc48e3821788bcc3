// Headless Chromium for the browser tests: Debian's /usr/bin/chromium (or $STRATA_CHROMIUM), never
// a downloaded browser, with WebGL2 through SwiftShader and a fresh profile each run.
import { chromium } from "playwright-core";
import { existsSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

export const CHROMIUM = process.env.STRATA_CHROMIUM ?? "/usr/bin/chromium";

// Launches Chromium with a `width`×`height` viewport in a fresh profile directory (playwright
// passes it as --user-data-dir). Exits the process with a message if the browser is missing.
// Returns the context and a function that closes it and removes the profile.
export async function launch(width, height) {
  if (!existsSync(CHROMIUM)) {
    console.error(`${CHROMIUM} is missing: install Debian's chromium (apt-get install -y chromium)`);
    process.exit(1);
  }
  const userDataDir = mkdtempSync(join(tmpdir(), "strata-chromium-"));
  const browser = await chromium.launchPersistentContext(userDataDir, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width, height },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--use-angle=swiftshader",
      "--enable-unsafe-swiftshader",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
      "--no-first-run",
      "--disable-quic",
    ],
  });
  const close = async () => {
    await browser.close();
    rmSync(userDataDir, { recursive: true, force: true });
  };
  return { browser, close };
}
