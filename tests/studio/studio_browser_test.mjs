// The studio's page in Debian's chromium, driven by puppeteer-core
// (web/view's devDependencies): it loads from the server alone (no network,
// no script error, no CSP violation), shows the grammar's picture and the
// run's counts; typing an edit redraws; an edit that breaks the grammar
// shows the error at its line (in the editor and the list) and keeps the
// last good picture; a parameter control and "Another seed" redraw; the
// SVG export; the seeds sheet; the player steps; Save writes the file, and
// a change on disk reloads the page's text; an image file a drawing links is
// loaded from the address the server gives it; a 3D grammar is drawn in the
// viewer, whose camera and shader programs stay across redraws. Screenshots are kept in ARTIFACTS.
// Usage: node studio_browser_test.mjs G2D SOURCE_DIR ARTIFACTS
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { check, finish, launchChromium, pageErrors, startStudio, stop } from "./studio_page.mjs";

const [g2d, src, artifacts] = process.argv.slice(2).map((p) => resolve(p));
const work = mkdtempSync(join(tmpdir(), "g2d-studio-page-"));
mkdirSync(artifacts, { recursive: true });
copyFileSync(join(src, "examples/sierpinski.g2d"), join(work, "sierpinski.g2d"));

const { studio, url } = await startStudio(g2d, "sierpinski.g2d", work);
check(/^http:\/\/127\.0\.0\.1:\d+\/$/.test(url), `the URL: ${url}`);

const browser = await launchChromium(src, ["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
                                     { width: 1100, height: 700 });
try {
  const page = await browser.newPage();
  const errors = pageErrors(page);
  await page.goto(url, { waitUntil: "load" });
  const status = () => page.$eval("#status", (s) => s.textContent);
  const draws = () => page.evaluate(() => window.g2dStudio.draws);
  // A wait that says what it waited for when it times out.
  const waitFor = (what, fn, options, ...args) =>
    page.waitForFunction(fn, options, ...args).catch(async (e) => {
      const state = await page.evaluate(() => ({ line12: window.g2dStudio.text().split("\n")[11], runs: window.g2dStudio.runs,
        draws: window.g2dStudio.draws, generations: (document.getElementById("param-generations") || {}).value }));
      throw new Error(`waiting for ${what}: ${e.message} (the status: ${await status()}; ${JSON.stringify(state)})`);
    });
  const waitStatus = (prefix) => waitFor(`the status "${prefix}…"`, (p) => document.getElementById("status").textContent.startsWith(p),
    { timeout: 20000 }, prefix);
  await waitFor("the first picture", () => document.querySelector("#flat svg") !== null, { timeout: 20000 });
  const picture = await page.$eval("#flat svg", (svg) => ({
    drawn: svg.querySelectorAll("path, line, polyline, polygon, circle").length,
    width: svg.getBoundingClientRect().width,
  }));
  check(picture.drawn > 0 && picture.width > 100, `the picture: ${JSON.stringify(picture)}`);
  check(/^5 steps, 366 nodes, 729 edges, 0 faces, [\d.]+ ms$/.test(await status()), `the status: ${await status()}`);
  check((await page.evaluate(() => window.g2dStudio.text())).includes("rule Split parallel"), "the editor holds the file");
  check(await page.$eval(".cm-content", (c) => c.querySelector(".tok-keyword, .ͼb, [class*=tok]") !== null ||
        getComputedStyle(c.querySelector(".cm-line span") || c).color !== getComputedStyle(c).color), "the text is highlighted");
  await page.screenshot({ path: join(artifacts, "studio_sierpinski.png") });

  // Typing an edit redraws: the default 5 becomes 3, key by key.
  await page.evaluate(() => window.g2dStudio.select("int = 5") && window.g2dStudio.select("5;"));
  await page.keyboard.type("3;");
  await waitStatus("3 steps");
  check(/^3 steps, 42 nodes, 81 edges/.test(await status()), `after typing: ${await status()}`);

  // Break the grammar: the error at its line in the editor and the list, the picture kept.
  const before = await page.$eval("#flat", (p) => p.innerHTML);
  await page.evaluate(() => window.g2dStudio.select("generations + 1;") && window.g2dStudio.select("1;"));
  await page.keyboard.type(";");
  await waitFor("the error", () => document.querySelector("#diagnostics .error") !== null, { timeout: 20000 });
  const error = await page.$eval("#diagnostics .error", (li) => li.textContent);
  check(/^32:\d+: error: /.test(error), `the error in the list: ${error}`);
  const marks = await page.evaluate(() => window.g2dStudio.marks());
  check(marks.length > 0 && marks[0].line === 32 && marks[0].severity === "error", `the error in the editor: ${JSON.stringify(marks)}`);
  check((await page.$$(".cm-lint-marker-error")).length > 0 || (await page.$$(".cm-lintRange-error")).length > 0,
        "the editor marks the error");
  check((await page.$eval("#flat", (p) => p.innerHTML)) === before, "the last good picture stays");
  check((await status()).includes("last good"), `the status says the picture is the last good one: ${await status()}`);

  // Mend it: a new picture, no diagnostics.
  await page.evaluate(() => window.g2dStudio.select("+ ;"));
  await page.keyboard.type("+ 1;");
  await waitFor("the diagnostics to clear", () => document.querySelectorAll("#diagnostics li").length === 0, { timeout: 20000 });
  check((await page.evaluate(() => window.g2dStudio.marks())).length === 0, "the editor's marks are cleared");

  // Completion as the language server gives it: after `ab.`, the edge's attribute.
  await page.evaluate(() => window.g2dStudio.select("ab.gen <") && window.g2dStudio.select("gen <"));
  await page.keyboard.press("ArrowLeft");
  await page.keyboard.down("Control"), await page.keyboard.press("Space"), await page.keyboard.up("Control");
  await waitFor("the completion list", () => document.querySelector(".cm-tooltip-autocomplete li") !== null, { timeout: 20000 });
  const offered = await page.$$eval(".cm-tooltip-autocomplete li", (l) => l.map((li) => li.textContent));
  check(offered.some((o) => o.startsWith("gen")) && !offered.some((o) => o.startsWith("Corner")), `completion after ab.: ${offered}`);
  await page.keyboard.press("Escape");

  // The parameters panel: a labelled control per param; changing it redraws.
  check(await page.$eval("label[for=param-generations]", (l) => l.textContent) === "generations", "the parameter's label");
  await page.$eval("#param-generations", (f) => ((f.value = "2"), f.dispatchEvent(new Event("input"))));
  await waitStatus("2 steps");
  check(/^2 steps, 15 nodes, 27 edges/.test(await status()), `after the parameter: ${await status()}`);
  // "Another seed" redraws with the next seed.
  let n = await draws();
  await page.click("#another-seed");
  await waitFor("another seed's picture", (k) => window.g2dStudio.draws > k, { timeout: 20000 }, n);
  check(await page.$eval("#seed", (f) => f.value) === "2", "another seed: 2");

  // Exports: the file the server makes, downloaded under the grammar's name.
  await page.evaluate(() => {   // the blob each download link names (the page's CSP lets no fetch read it back)
    const blobs = new Map(), make = URL.createObjectURL;
    URL.createObjectURL = (blob) => {
      const u = make(blob);
      blobs.set(u, blob);
      return u;
    };
    window.downloads = [];
    HTMLAnchorElement.prototype.click = function () {
      window.downloads.push(blobs.get(this.href).text().then((t) => ({ name: this.download, text: t })));
    };
  });
  await page.click("#export-svg");
  await waitFor("the download", () => window.downloads.length === 1, { timeout: 20000 });
  const svg = await page.evaluate(() => window.downloads[0]);
  check(svg.name === "sierpinski.svg" && svg.text.includes("<svg"), `the SVG export: ${svg.name} ${svg.text.slice(0, 60)}`);

  // The seeds sheet: 16 seeds; a click takes one.
  await page.click("#mode-seeds");
  await waitFor("16 seeds", () => document.querySelectorAll(".seed-cell img").length === 16, { timeout: 30000 });
  n = await draws();
  await page.click(".seed-cell[data-seed='7']");
  await waitFor("the seed's picture", (k) => window.g2dStudio.draws > k, { timeout: 20000 }, n);
  check(await page.$eval("#seed", (f) => f.value) === "7" && !(await page.$eval("#picture-pane", (p) => p.hidden)),
        "a seed taken from the sheet");

  // The player steps through the derivation.
  await page.click("#mode-player");
  await waitFor("the trace", () => window.g2dTrace && window.g2dTrace.steps === 2, { timeout: 20000 });
  await page.click("#first");
  check(await page.evaluate(() => window.g2dTrace.frame) === 0, "the player's first frame");
  await page.click("#next");
  const step1 = await page.evaluate(() => ({ frame: window.g2dTrace.frame, drawn: window.g2dTrace.drawn }));
  check(step1.frame === 1 && step1.drawn.added > 0 && step1.drawn.deleted > 0, `the player's step 1: ${JSON.stringify(step1)}`);
  check(await page.$eval("#stage", (s) => s.querySelectorAll("line").length) > 0, "the player draws the graph");
  await page.screenshot({ path: join(artifacts, "studio_player.png") });
  await page.click("#mode-picture");

  // "Defaults": the parameters as the text declares them again.
  await page.click("#reset-params");
  await waitStatus("3 steps");
  check(await page.$eval("#param-generations", (f) => f.value) === "3", "the parameter's default again");

  // Saved, then changed on disk by another editor: the page reloads the file and redraws.
  await page.click("#save");
  await waitFor("the save", () => document.getElementById("status").textContent === "Saved", { timeout: 20000 });
  check(readFileSync(join(work, "sierpinski.g2d"), "utf8").includes("generations + 1;"), "the save wrote the file");
  writeFileSync(join(work, "sierpinski.g2d"), readFileSync(join(src, "examples/sierpinski.g2d"), "utf8").replace("int = 5", "int = 1"));
  await waitStatus("1 step,");
  check((await page.evaluate(() => window.g2dStudio.text())).includes("int = 1"), "the editor shows the file as changed on disk");

  // Changed on disk under unsaved edits: the page says so and keeps the edits; the user keeps them…
  const onDisk = (n) => readFileSync(join(src, "examples/sierpinski.g2d"), "utf8").replace("int = 5", `int = ${n}`);
  await page.evaluate(() => window.g2dStudio.select("int = 1"));
  await page.keyboard.type("int = 2");
  await waitStatus("2 steps");
  writeFileSync(join(work, "sierpinski.g2d"), onDisk(4));
  await waitFor("the conflict bar", () => !document.getElementById("conflict").hidden, { timeout: 20000 });
  check((await page.evaluate(() => window.g2dStudio.text())).includes("int = 2"), "the edits stay when the file changes on disk");
  await page.click("#overwrite-file");
  await waitFor("the save over the file", () => document.getElementById("status").textContent === "Saved", { timeout: 20000 });
  check(readFileSync(join(work, "sierpinski.g2d"), "utf8").includes("int = 2;") && await page.$eval("#conflict", (c) => c.hidden),
        "Keep mine and save writes the edits over the file");
  // … or reloads the file.
  await page.evaluate(() => window.g2dStudio.select("int = 2"));
  await page.keyboard.type("int = 3");
  await waitStatus("3 steps");
  writeFileSync(join(work, "sierpinski.g2d"), onDisk(1));
  await waitFor("the conflict bar again", () => !document.getElementById("conflict").hidden, { timeout: 20000 });
  await page.click("#reload-file");
  await waitStatus("1 step,");
  check((await page.evaluate(() => window.g2dStudio.text())).includes("int = 1;"), "Reload it takes the file from disk");

  // A drawing of an image file (beside the grammar): the page loads the image the server gives an address.
  mkdirSync(join(work, "pics"));
  copyFileSync(join(src, "examples/assets/brush.png"), join(work, "pics/dot.png"));
  writeFileSync(join(work, "sierpinski.g2d"),
    'node A { style { tag = "image"; href = "pics/dot.png"; width = 1; height = 1; } }\naxiom { a: A at (0, 0); }\n');
  await waitStatus("0 steps, 1 node,");
  await waitFor("the image", () => document.querySelector("#flat image") !== null &&
    performance.getEntriesByType("resource").some((e) => e.name.endsWith("/api/image/0") && e.responseStatus === 200), { timeout: 20000 });
  check(await page.$eval("#flat image", (i) => i.getAttribute("href")) === "/api/image/0", "the image's address");

  // A 3D grammar on disk: the viewer draws it; a parameter redraws it with the camera where it was.
  // (Its height given a range, so that the panel shows a slider.)
  const ranged = readFileSync(join(src, "examples/g3_box.g2d"), "utf8").replace("param height: float = 1;", "param height: float = 1 in 0.5..3 step 0.5;");
  check(ranged.includes("in 0.5..3"), "the 3D grammar's range");
  writeFileSync(join(work, "sierpinski.g2d"), ranged);
  await waitFor("the 3D picture", () => window.g2dStudio.last && window.g2dStudio.last.space === "3d", { timeout: 20000 });
  check(await page.$eval("#solid canvas", (c) => c.width > 100 && c.height > 100), "the 3D picture's canvas");
  check(!(await page.$eval("#view-panel", (p) => p.hidden)) && (await page.$eval("#flat", (p) => p.hidden)), "3D: the viewer's panel, no SVG");
  await page.click("#solid canvas");
  await page.keyboard.press("2");   // the viewer's side view
  const camera = await page.evaluate(() => window.g2dStudio.camera());
  const programs = JSON.stringify(await page.evaluate(() => window.g2dStudio.programs()));
  n = await draws();
  const slider = await page.$eval("#param-height + input[type=range], .param input[type=range][aria-label=height]",
    (r) => ({ min: r.min, max: r.max, step: r.step, value: r.value }));
  check(JSON.stringify(slider) === JSON.stringify({ min: "0.5", max: "3", step: "0.5", value: "1" }), `the range's slider: ${JSON.stringify(slider)}`);
  await page.$eval(".param input[type=range][aria-label=height]", (r) => ((r.value = "2"), r.dispatchEvent(new Event("input"))));
  await waitFor("the 3D redraw", (k) => window.g2dStudio.draws > k, { timeout: 20000 }, n);
  check(JSON.stringify(await page.evaluate(() => window.g2dStudio.camera())) === JSON.stringify(camera),
        "the camera stays across redraws");
  // Compiling shaders again stalled a redraw for most of a second in software GL.
  const after = JSON.stringify(await page.evaluate(() => window.g2dStudio.programs()));
  check(after === programs && JSON.parse(after).length >= 3, `the redraw's shader programs are the first picture's: ${programs} then ${after}`);
  check(await page.$eval("#param-height", (f) => f.value) === "2", "the slider moves the number field");
  await page.screenshot({ path: join(artifacts, "studio_g3_box.png") });
  check(errors.length === 0, `page errors: ${errors.join("; ")}`);
} finally {
  await stop(browser, studio);
}
await finish(studio, "studio page");
