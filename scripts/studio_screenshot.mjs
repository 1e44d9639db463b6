// Makes docs/studio.png: the studio on a copy of examples/g3_house.g2d, in
// Debian's chromium (puppeteer-core from web/view), once the house is drawn.
// Usage: node scripts/studio_screenshot.mjs G2D [OUT.png] [EXAMPLE]
import { spawn } from "node:child_process";
import { copyFileSync, mkdtempSync } from "node:fs";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import { basename, dirname, join, resolve } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";

const src = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const [g2d, out = join(src, "docs/studio.png"), example = join(src, "examples/g3_house.g2d")] =
  process.argv.slice(2).map((p) => resolve(p));
if (!g2d) {
  console.error("usage: node scripts/studio_screenshot.mjs G2D [OUT.png] [EXAMPLE]");
  process.exit(2);
}
const puppeteer = createRequire(join(src, "web/view/package.json"))("puppeteer-core");
const work = mkdtempSync(join(tmpdir(), "g2d-studio-shot-"));
copyFileSync(example, join(work, basename(example)));

const studio = spawn(g2d, ["studio", basename(example), "--port", "0"], { cwd: work, stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((done) => createInterface({ input: studio.stdout }).once("line", done));
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--hide-scrollbars", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
  defaultViewport: { width: 1280, height: 760 },
});
try {
  const page = await browser.newPage();
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => window.g2dStudio && window.g2dStudio.last && window.g2dStudio.last.paintedAt !== null,
    { timeout: 30000 });
  await page.screenshot({ path: out });
  console.log(out);
} finally {
  await browser.close();
  studio.kill();
}
