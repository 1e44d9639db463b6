// `g2d studio`: keystroke to new picture, in the page, for every example at
// its default size (interpreted). For each example a studio is started on a
// copy of it and the page is opened in Debian's chromium (puppeteer-core,
// software GL as in the tests); then, --keys times, a space is typed at the
// end of the text (or taken away again): a real edit, so the grammar is
// compiled, derived, sent and drawn again. The time is from the edit (the
// editor's change, in the keystroke's own task) to the task after the frame
// that shows the new picture and, for a 3D one, to the end of the GL work
// behind that frame (read back from its canvas). Jank: while typing a burst of --burst keys at
// --interval ms, the longest gap between animation frames and the frames it
// cost (a gap of n frame times costs n - 1).
// Prints one Markdown row per example, then the median and the worst.
// Usage: node bench/studio_keystroke.mjs [--g2d build/release/bin/g2d] [--keys 7] [--burst 12] [--interval 80] [--only NAME]
import { spawn } from "node:child_process";
import { cpSync, mkdtempSync, readdirSync, symlinkSync } from "node:fs";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { createInterface } from "node:readline";
import { fileURLToPath } from "node:url";

const root = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const option = (name, fallback) => {
  const i = process.argv.indexOf("--" + name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const g2d = resolve(option("g2d", join(root, "build/release/bin/g2d")));
const keys = Number(option("keys", 7)), burst = Number(option("burst", 12)), interval = Number(option("interval", 80));
const only = option("only", null);
const puppeteer = createRequire(join(root, "web/view/package.json"))("puppeteer-core");
const FRAME = 1000 / 60;

const work = mkdtempSync(join(tmpdir(), "g2d-studio-bench-"));
for (const f of readdirSync(join(root, "examples"))) if (f.endsWith(".g2d")) cpSync(join(root, "examples", f), join(work, f));
symlinkSync(join(root, "examples/assets"), join(work, "assets"));
const names = readdirSync(work).filter((f) => f.endsWith(".g2d") && (!only || f === only + ".g2d")).sort();

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--hide-scrollbars", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--disable-gpu-rasterization"],
  defaultViewport: { width: 1300, height: 800 },
});
const rows = [];
console.log("| example | space | elements | server ms | keystroke to picture ms (median) | worst | longest frame gap ms | frames lost |");
console.log("|---|---|---|---|---|---|---|---|");
try {
  for (const name of names) {
    const studio = spawn(g2d, ["studio", name, "--port", "0"], { cwd: work, stdio: ["ignore", "pipe", "ignore"] });
    const url = await new Promise((done) => createInterface({ input: studio.stdout }).once("line", done));
    const page = await browser.newPage();
    try {
      await page.goto(url, { waitUntil: "load" });
      await page.waitForFunction(() => window.g2dStudio && window.g2dStudio.last && window.g2dStudio.last.paintedAt, { timeout: 60000 });
      // A 3D picture is finished once a pixel of its canvas can be read back: the GL work behind the
      // frame is done (the viewer's context, which keeps its drawing buffer).
      await page.evaluate(() => {
        const pixel = new Uint8Array(4);
        const finish = (last) => {
          const canvas = document.querySelector("#solid canvas");
          const gl = canvas && !document.getElementById("solid").hidden && canvas.getContext("webgl2");
          if (gl) gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
          last.finishedAt = performance.now();
        };
        finish(window.g2dStudio.last);   // the first picture's, before typing
        window.g2dStudio.onPaint = finish;
      });
      // The cursor at the end of the text.
      await page.evaluate(() => window.g2dStudio.select(window.g2dStudio.text().slice(0, 1)));
      await page.keyboard.down("Control"), await page.keyboard.press("End"), await page.keyboard.up("Control");
      const times = [];
      let server = [];
      for (let k = 0; k < keys; k++) {
        const before = await page.evaluate(() => window.g2dStudio.draws);
        if (k % 2 === 0) await page.keyboard.type(" ");
        else await page.keyboard.press("Backspace");
        await page.waitForFunction((n) => window.g2dStudio.draws > n && window.g2dStudio.last.finishedAt, { timeout: 60000 }, before);
        const last = await page.evaluate(() => window.g2dStudio.last);
        times.push(last.finishedAt - last.editedAt);
        server.push(last.serverMs);
        await new Promise((r) => setTimeout(r, 150));
      }
      // A burst of typing: the gaps between animation frames (no read back, which would wait on the GL).
      await page.evaluate(() => {
        window.g2dStudio.onPaint = null;
        window.frameGaps = [];
        let prev = performance.now();
        const tick = (t) => {
          window.frameGaps.push(t - prev);
          prev = t;
          if (window.frameGaps.length < 100000) window.frameTicker = requestAnimationFrame(tick);
        };
        window.frameTicker = requestAnimationFrame(tick);
      });
      for (let k = 0; k < burst; k++) {
        await page.keyboard.type(k % 2 ? "" : " ");
        if (k % 2) await page.keyboard.press("Backspace");
        await new Promise((r) => setTimeout(r, interval));
      }
      await new Promise((r) => setTimeout(r, 300));
      const gaps = await page.evaluate(() => (cancelAnimationFrame(window.frameTicker), window.frameGaps.slice(1)));
      const longest = Math.max(...gaps);
      const lost = Math.max(...gaps.map((g) => Math.max(0, Math.round(g / FRAME) - 1)));
      const last = await page.evaluate(() => window.g2dStudio.last);
      const e = last.elements;
      const row = { name: name.replace(/\.g2d$/, ""), space: last.space, elements: e.nodes + e.edges + e.faces,
                    server: median(server), median: median(times), worst: Math.max(...times), longest, lost };
      rows.push(row);
      console.log(`| ${row.name} | ${row.space} | ${row.elements} | ${row.server.toFixed(1)} | ${row.median.toFixed(0)} | ` +
                  `${row.worst.toFixed(0)} | ${row.longest.toFixed(0)} | ${row.lost} |`);
    } finally {
      await page.close();
      studio.kill("SIGINT");
    }
  }
} finally {
  await browser.close();
}
const all = rows.map((r) => r.median);
console.log(`\nMedian over the examples: ${median(all).toFixed(0)} ms; worst example (its median): ` +
            `${Math.max(...all).toFixed(0)} ms; worst single keystroke: ${Math.max(...rows.map((r) => r.worst)).toFixed(0)} ms; ` +
            `most frames lost in one gap: ${Math.max(...rows.map((r) => r.lost))}.`);
