// The studio's first page in Debian's chromium, driven by puppeteer-core
// (web/view's devDependencies): it loads from the server alone (no network,
// no script error, no CSP violation), shows the grammar's picture and the
// run's counts; an edit that breaks the grammar shows the error at its line
// and keeps the last good picture; an edit that mends it redraws; Save
// writes the file, and a change on disk reloads the page's text. A
// screenshot is kept in ARTIFACTS.
// Usage: node studio_browser_test.mjs G2D SOURCE_DIR ARTIFACTS
import { spawn } from "node:child_process";
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { createInterface } from "node:readline";

const [g2d, src, artifacts] = process.argv.slice(2).map((p) => resolve(p));
const require = createRequire(join(src, "web/view/package.json"));
const puppeteer = require("puppeteer-core");
const work = mkdtempSync(join(tmpdir(), "g2d-studio-page-"));
mkdirSync(artifacts, { recursive: true });
copyFileSync(join(src, "examples/sierpinski.g2d"), join(work, "sierpinski.g2d"));
let failures = 0;
const check = (ok, what) => {
  if (!ok) failures++, console.log("FAIL:", what);
};

const studio = spawn(g2d, ["studio", "sierpinski.g2d", "--port", "0"], { cwd: work, stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((done) => createInterface({ input: studio.stdout }).once("line", done));
check(/^http:\/\/127\.0\.0\.1:\d+\/$/.test(url), `the URL: ${url}`);

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1", "--hide-scrollbars"],
  defaultViewport: { width: 1100, height: 700 },
});
try {
  const page = await browser.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  // A broken grammar's run answers 422, which the console reports; nothing else may fail.
  page.on("console", (m) => m.type() === "error" && !m.text().includes("status of 422") && errors.push(m.text()));
  page.on("requestfailed", (r) => errors.push("request failed: " + r.url()));
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => document.querySelector("#picture svg") !== null, { timeout: 20000 });
  const picture = await page.$eval("#picture svg", (svg) => ({
    drawn: svg.querySelectorAll("path, line, polyline, polygon, circle").length,
    width: svg.getBoundingClientRect().width,
  }));
  check(picture.drawn > 0 && picture.width > 100, `the picture: ${JSON.stringify(picture)}`);
  const status = await page.$eval("#status", (s) => s.textContent);
  check(/^5 steps, 366 nodes, 729 edges, 0 faces, [\d.]+ ms$/.test(status), `the status: ${status}`);
  check((await page.$eval("#editor", (e) => e.value)).includes("rule Split parallel"), "the editor holds the file");
  await page.screenshot({ path: join(artifacts, "studio_sierpinski.png") });

  // Break the grammar: the error at its line, the picture kept.
  const before = await page.$eval("#picture", (p) => p.innerHTML);
  await page.$eval("#editor", (e) => {
    e.value = e.value.replace("limit generations + 1;", "limit generations +;");
    e.dispatchEvent(new Event("input"));
  });
  await page.waitForFunction(() => document.querySelector("#diagnostics .error") !== null, { timeout: 20000 });
  const error = await page.$eval("#diagnostics .error", (li) => li.textContent);
  check(/^32:\d+: error: /.test(error), `the error: ${error}`);
  check((await page.$eval("#picture", (p) => p.innerHTML)) === before, "the last good picture stays");

  // Mend it with fewer generations: a new picture.
  await page.$eval("#editor", (e) => {
    e.value = e.value.replace("limit generations +;", "limit generations + 1;").replace("int = 5", "int = 2");
    e.dispatchEvent(new Event("input"));
  });
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("2 steps"), { timeout: 20000 });
  check((await page.$$eval("#diagnostics li", (l) => l.length)) === 0, "the diagnostics are cleared");
  check((await page.$eval("#picture", (p) => p.innerHTML)) !== before, "the picture is redrawn");

  // Saved, then changed on disk by another editor: the page reloads the file and redraws.
  await page.click("#save");
  await page.waitForFunction(() => document.getElementById("status").textContent === "Saved", { timeout: 20000 });
  check(readFileSync(join(work, "sierpinski.g2d"), "utf8").includes("int = 2"), "the save wrote the file");
  writeFileSync(join(work, "sierpinski.g2d"), readFileSync(join(src, "examples/sierpinski.g2d"), "utf8").replace("int = 5", "int = 1"));
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("1 step,"), { timeout: 20000 });
  check((await page.$eval("#editor", (e) => e.value)).includes("int = 1"), "the editor shows the file as changed on disk");
  check(errors.length === 0, `page errors: ${errors.join("; ")}`);
} finally {
  await browser.close();
  studio.kill("SIGINT");
}
const code = await new Promise((done) => studio.once("exit", (c) => done(c)));
check(code === 0, `the studio's exit code: ${code}`);
if (failures) {
  console.log(`${failures} failures`);
  process.exit(1);
}
console.log("studio page: all checks passed");
