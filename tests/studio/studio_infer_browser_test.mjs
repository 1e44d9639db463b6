// The studio's infer mode in Debian's chromium, driven by puppeteer-core
// (web/view's devDependencies): the Infer tab takes an example from the
// file picker (the author's JSON), from a drop (an SVG) and from the drawing
// grid; each shows the example, its primitives and rules as `g2d infer
// --stats` counts them, and a generated output; Generate draws another
// seed; a broken example says why and keeps the last results; "Open grammar
// in editor" puts the written grammar in the editor, and the Picture tab
// draws it. No
// script error, no CSP violation. Screenshots are kept in ARTIFACTS.
// Usage: node studio_infer_browser_test.mjs G2D SOURCE_DIR ARTIFACTS
import { execFileSync } from "node:child_process";
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { check, finish, launchChromium, pageErrors, startStudio, stop } from "./studio_page.mjs";

const [g2d, src, artifacts] = process.argv.slice(2).map((p) => resolve(p));
const work = mkdtempSync(join(tmpdir(), "g2d-studio-infer-page-"));
mkdirSync(artifacts, { recursive: true });
copyFileSync(join(src, "examples/sierpinski.g2d"), join(work, "sierpinski.g2d"));
const T_JSON = join(src, "examples/infer/merrell/2D Branches/T.json");
const HOUSE = readFileSync(join(src, "examples/infer/house.svg"), "utf8");
const stats = (file) => JSON.parse(execFileSync(g2d, ["infer", "--stats", file], { encoding: "utf8" }));

const { studio, url } = await startStudio(g2d, "sierpinski.g2d", work);

const browser = await launchChromium(src, [], { width: 1200, height: 900 });
try {
  const page = await browser.newPage();
  const errors = pageErrors(page);
  let lastInfer = null;   // the last answer of /api/infer the page got
  page.on("response", async (r) => r.url().endsWith("/api/infer") && r.status() === 200 && (lastInfer = await r.json()));
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => document.querySelector("#flat svg, #flat img") !== null, { timeout: 20000 });
  const sierpinski = await page.$eval("#flat", (f) => f.innerHTML);
  await page.click("#mode-infer");
  await page.waitForSelector("#infer-file", { timeout: 20000 });
  const status = () => page.$eval("#infer-status", (s) => s.textContent);
  const shown = () => page.evaluate(() => ({
    primitives: document.querySelectorAll("#infer-primitives li svg").length,
    rules: document.querySelectorAll("#infer-rules li").length,
    ruleSvgs: document.querySelectorAll("#infer-rules li svg").length,
    exampleDots: document.querySelectorAll("#infer-example svg circle").length,
    generated: document.querySelectorAll("#infer-generated svg :is(path, line, polygon)").length,
  }));
  const expect = async (what, s) => {
    const got = await shown();
    check(got.primitives === s.primitives && got.rules === s.rules + s.starters && got.ruleSvgs >= got.rules
          && got.exampleDots === s.vertices && got.generated > 0, `${what}: ${JSON.stringify(got)} vs ${JSON.stringify(s)}`);
  };

  // A wait for the status to start with `prefix`, which says the status when it times out.
  const waitStatus = (prefix) =>
    page.waitForFunction((p) => document.getElementById("infer-status").textContent.startsWith(p), { timeout: 30000 }, prefix)
      .catch(async (e) => {
        throw new Error(`waiting for the status "${prefix}…": ${e.message} (the status: ${await status()})`);
      });
  // Outputs of 60 vertices: the sanitizer build's runs stay inside the studio's 5 s budget.
  await page.type("#infer-size", "60");

  // The file picker: the author's JSON.
  await (await page.$("#infer-file")).uploadFile(T_JSON);
  await waitStatus("T: ");
  await expect("T.json picked", stats(T_JSON));
  check(/^T: 2 edge labels, 4 primitives, 5 rules and 1 starter rule in \d+ ms; seed 1$/.test(await status()), `status: ${await status()}`);

  // A drop: the house drawn as SVG.
  const drop = (name, text) => page.$eval("#infer-drop", (zone, name, text) => {
    const data = new DataTransfer();
    data.items.add(new File([text], name, { type: name.endsWith(".svg") ? "image/svg+xml" : "application/json" }));
    zone.dispatchEvent(new DragEvent("drop", { dataTransfer: data, bubbles: true, cancelable: true }));
  }, name, text);
  await drop("house.svg", HOUSE);
  await waitStatus("House: ");
  await expect("house.svg dropped", stats(join(src, "examples/infer/house.svg")));
  await page.screenshot({ path: join(artifacts, "studio_infer_house.png"), fullPage: true });

  // Generate: another seed, another picture.
  const before = await page.$eval("#infer-generated", (g) => g.innerHTML);
  await page.click("#infer-generate");
  await waitStatus("Generated with seed 2");
  check((await page.$eval("#infer-generated", (g) => g.innerHTML)) !== before, "Generate draws another output");

  // A broken example: the reader's message with its line; the results stay.
  await drop("bad.svg", '<svg xmlns="http://www.w3.org/2000/svg">\n<g stroke="black">\n<circle r="3"/>\n</g>\n</svg>\n');
  await waitStatus("The example was refused");
  check((await status()) === "The example was refused: bad.svg:3: <circle> is not supported: edges must be straight (draw a polygon)",
        `the refusal: ${await status()}`);
  check((await shown()).rules > 0, "the last results stay");

  // The drawing grid: a square (closed by clicking its first point) with a line out of a corner.
  await page.click("#infer-draw summary");
  const box = await (await page.$("#infer-canvas")).boundingBox();
  const at = async (x, y) => page.mouse.click(box.x + (x / 480) * box.width, box.y + (y / 320) * box.height);
  for (const [x, y] of [[80, 80], [160, 80], [160, 160], [80, 160], [80, 80]]) await at(x, y);
  for (const [x, y] of [[160, 160], [240, 240], [240, 240]]) await at(x, y);
  await page.click("#infer-use-drawing");
  await waitStatus("Drawing: ");
  const drawn = await shown();
  check(drawn.exampleDots === 5 && drawn.primitives === 5 && drawn.rules > 0 && drawn.generated > 0, `the drawing: ${JSON.stringify(drawn)}`);
  await page.screenshot({ path: join(artifacts, "studio_infer_drawing.png"), fullPage: true });

  // Open grammar in editor over unsaved edits asks first; dismissed, the edits stay.
  await page.evaluate(() => window.g2dStudio.select("// Sierpinski"));
  await page.keyboard.type("// Sierpinski!");
  const asked = [];
  page.once("dialog", (d) => (asked.push(d.message()), d.dismiss()));
  await page.click("#infer-open");
  await new Promise((done) => setTimeout(done, 300));
  check(asked[0] === "Replace your unsaved edits of sierpinski.g2d with the inferred grammar?", `the question: ${asked[0]}`);
  check((await page.evaluate(() => window.g2dStudio.text())).startsWith("// Sierpinski!"), "dismissed, the edits stay");
  await page.click("#mode-infer");

  // Accepted: the written grammar in the editor, and its picture in the Picture tab.
  page.once("dialog", (d) => d.accept());
  await page.click("#infer-open");
  await page.waitForFunction(() => window.g2dStudio.text().startsWith("// Inferred by `g2d infer` from drawing.svg"), { timeout: 20000 });
  check((await page.evaluate(() => window.g2dStudio.text())) === lastInfer.grammar, "the editor holds the grammar /api/infer wrote");
  if (await page.$eval("#picture-pane", (p) => p.hidden)) await page.click("#mode-picture");
  await page.waitForFunction((old) => document.querySelector("#flat svg, #flat img") !== null && document.getElementById("flat").innerHTML !== old,
                             { timeout: 30000 }, sierpinski);
  await page.screenshot({ path: join(artifacts, "studio_infer_opened.png") });
  check(errors.length === 0, `page errors: ${errors.join("; ")}`);
} finally {
  await stop(browser, studio);
}
await finish(studio, "studio infer mode");
