// The --view page and the 3D trace player in Debian's chromium, driven by
// puppeteer-core (web/view's devDependencies): toggles hide what they name
// (pixel counts of the canvas change), views are kept in the URL's hash and
// in localStorage (a reload shows the same), a thick edge is a tube (more
// pixels than its hairline), the legend counts the graph's elements, and the
// 3D trace player steps through the derivation (elements per step as the
// trace says). Screenshots of the sofa, house, tree_box, a 2D example and a
// 3D trace are kept in ARTIFACTS.
// Usage: node view_browser_test.mjs G2D SOURCE_DIR ARTIFACTS
import { execFileSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";

const [g2d, src, artifacts] = process.argv.slice(2).map((p) => resolve(p));
const require = createRequire(join(src, "web/view/package.json"));
const puppeteer = require("puppeteer-core");
const work = mkdtempSync(join(tmpdir(), "g2d-view-"));
mkdirSync(artifacts, { recursive: true });
let failures = 0;
const check = (ok, what) => {
  if (!ok) failures++, console.log("FAIL:", what);
};

function run(grammar, ...args) {
  execFileSync(g2d, ["run", join(src, grammar), "--no-svg", ...args], { cwd: work, stdio: ["ignore", "ignore", "inherit"] });
}
run("examples/g3_sofa.g2d", "--view", "sofa.html");
run("examples/g3_house.g2d", "--view", "house.html", "--json", "house.json");
run("examples/g3_tree_box.g2d", "--view", "tree_box.html");
run("examples/subdivide.g2d", "-D", "depth=2", "--view", "subdivide.html");
run("tests/view/fan_colours.g2d", "--view", "fan.html");
run("tests/view/tubes.g2d", "-D", "r=0.04", "--view", "tube.html");
run("tests/view/tubes.g2d", "-D", "r=0", "--view", "hairline.html");
run("examples/g3_box.g2d", "--trace", "box_trace.html", "--trace-json", "box_trace.json");
run("examples/g3_house.g2d", "--trace", "house_trace.html", "--trace-json", "house_trace.json");

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  // WebGL without a GPU (ANGLE on SwiftShader); no host resolves, so a page
  // that leaned on the network would fail.
  args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--host-resolver-rules=MAP * ~NOTFOUND",
         "--hide-scrollbars", "--allow-file-access-from-files"],
  defaultViewport: { width: 1000, height: 700 },
});
const page = await browser.newPage();
const errors = [];
page.on("pageerror", (e) => errors.push(e.message));
page.on("requestfailed", (r) => errors.push("request failed: " + r.url()));

async function open(name, hash = "") {
  await page.goto("file://" + join(work, name) + hash, { waitUntil: "load" });
  await page.waitForFunction(() => document.getElementById("status").textContent === "" || document.getElementById("status").textContent.startsWith("This page could"));
  const status = await page.$eval("#status", (s) => s.textContent);
  check(status === "", `${name}: ${status}`);
}
// Pixels of the canvas: not white, and near each colour given (#rrggbb).
async function pixels(...colors) {
  return page.evaluate((colors) => {
    const src = document.querySelector("canvas"), c = document.createElement("canvas");
    c.width = src.width;
    c.height = src.height;
    const g = c.getContext("2d");
    g.drawImage(src, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const want = colors.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
    const out = { ink: 0 };
    colors.forEach((h) => (out[h] = 0));
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 245 || d[i + 1] < 245 || d[i + 2] < 245) out.ink++;
      want.forEach((w, k) => {
        if (Math.abs(d[i] - w[0]) + Math.abs(d[i + 1] - w[1]) + Math.abs(d[i + 2] - w[2]) < 60) out[colors[k]]++;
      });
    }
    return out;
  }, colors);
}
const shot = (name) => page.screenshot({ path: join(artifacts, name) });
const key = async (k) => {
  await page.keyboard.press(k);
  await new Promise((r) => setTimeout(r, 50));
};
const camera = () => page.evaluate(() => window.g2dView.viewer.camera());
const legend = () => page.$eval("#legend", (l) => l.textContent);

// The screenshots to look at.
for (const name of ["sofa", "house", "tree_box", "subdivide"]) {
  await open(name + ".html");
  await shot(`view_${name}.png`);
}

// Toggles: faces off takes the sofa's faces away; back on restores them; axes too.
await open("sofa.html");
const sofa = await pixels("#d62728", "#2ca02c", "#1f77b4");
check(sofa.ink > 50000, `sofa: ${sofa.ink} pixels drawn`);
await page.click("#show-faces");
const noFaces = await pixels();
check(noFaces.ink < sofa.ink / 4, `sofa: faces off leaves ${noFaces.ink} of ${sofa.ink} pixels`);
await key("f");
check((await pixels()).ink === sofa.ink, "sofa: faces back on (key F) restores the picture");
await key("a");
const noAxes = await pixels("#d62728", "#2ca02c", "#1f77b4");
check(noAxes["#1f77b4"] < sofa["#1f77b4"] - 50 && noAxes["#d62728"] < sofa["#d62728"] - 50,
      `sofa: axes off removes the red and blue axes (${JSON.stringify(sofa)} -> ${JSON.stringify(noAxes)})`);
await key("a");
const sofaLegend = await legend();
check(/3776 faces/.test(sofaLegend), `sofa legend: ${sofaLegend}`);
check((await page.evaluate(() => window.g2dView.triangles)) > 3776, "sofa: more triangles than faces");

// Edges and nodes toggled on the fan: red edges, blue nodes.
await open("fan.html");
const fan = await pixels("#d62728", "#1f77b4");
await key("e");
const fanNoEdges = await pixels("#d62728", "#1f77b4");
await key("n");
const fanBare = await pixels("#d62728", "#1f77b4");
check(fan["#d62728"] > 300 && fanNoEdges["#d62728"] < fan["#d62728"] / 5, `fan: edges off ${JSON.stringify([fan, fanNoEdges])}`);
check(fanNoEdges["#1f77b4"] > 1000 && fanBare["#1f77b4"] < fanNoEdges["#1f77b4"] / 5, `fan: nodes off ${JSON.stringify([fanNoEdges, fanBare])}`);
// The checkboxes follow the keys, and the hash keeps what is hidden.
check(!(await page.$eval("#show-edges", (b) => b.checked)) && (await page.evaluate(() => location.hash)).includes("hide=edges,nodes"),
      "fan: checkboxes and hash after E and N");
await page.reload({ waitUntil: "load" });
check((await pixels("#d62728", "#1f77b4"))["#1f77b4"] === fanBare["#1f77b4"], "fan: a reload keeps edges and nodes hidden");

// `panel=off` (the gallery's screenshots): the legend and its controls hidden,
// and kept so when the view changes.
await page.goto("about:blank");   // else a change of hash alone would not load the page again
await open("fan.html", "#panel=off");
check(await page.$eval("#legend", (l) => l.offsetParent === null), "fan: panel=off hides the legend");
await key("e");
check((await page.evaluate(() => location.hash)).includes("panel=off"), "fan: the hash keeps panel=off");

// Views: the top view survives a reload (hash); a saved view comes back with V,
// also on a fresh load of the page (localStorage).
await open("house.html");
const home = await camera(), homePixels = await pixels();
await key("3");
const top = await camera(), topPixels = await pixels();
check(JSON.stringify(top) !== JSON.stringify(home), "house: the top view moves the camera");
check(Math.abs(top[0] - top[3]) < 1e-3 * Math.abs(top[2] - top[5]) + 1e-3, `house: top looks down ${top}`);
await shot("view_house_top.png");
await page.reload({ waitUntil: "load" });
check(JSON.stringify(await camera()) === JSON.stringify(top), "house: a reload keeps the top view");
check((await pixels()).ink === topPixels.ink, "house: a reload draws the top view again");
await key("1");
const front = await camera();
await key("s");
await key("r");
check(JSON.stringify(await camera()) === JSON.stringify(home), "house: R goes home");
check((await pixels()).ink === homePixels.ink, "house: home draws as at first");
await open("house.html");   // a fresh load, no hash
check(JSON.stringify(await camera()) === JSON.stringify(home), "house: a fresh load starts at home");
await key("v");
check(JSON.stringify(await camera()) === JSON.stringify(front), "house: V goes to the saved (front) view");
// The legend counts the graph's elements, and says how many are drawn.
const house = JSON.parse(readFileSync(join(work, "house.json"), "utf8"));
const houseLegend = await legend();
for (const [what, n] of [["node", house.nodes.length], ["edge", house.links.length], ["face", house.faces.length]])
  check(houseLegend.includes(`${n} ${what}`), `house legend ${houseLegend}: ${n} ${what}s`);
console.log("house legend:", houseLegend.split("Drag")[0]);

// Tubes: the thick edge covers several times the pixels of its hairline.
await open("tube.html");
const tube = await pixels("#d62728");
await shot("view_tube.png");
await open("hairline.html");
const hairline = await pixels("#d62728");
console.log(`edge pixels: tube ${tube["#d62728"]}, hairline ${hairline["#d62728"]}`);
check(tube["#d62728"] > 4 * hairline["#d62728"] && hairline["#d62728"] > 100, "a thick edge as a tube");
check((await page.evaluate(() => window.g2dView.tubes)) === 0, "the hairline is no tube");

// The 3D trace: nodes keep z; the player steps, drawing per step the elements the trace says.
const trace = JSON.parse(readFileSync(join(work, "box_trace.json"), "utf8"));
check(trace.space === "3d" && trace.axiom.nodes.every((n) => n.length === 5), "the 3D trace keeps z");
// The graph's counts after each step, replayed here from the trace.
function countsPerStep(trace) {
  const nodes = new Set(trace.axiom.nodes.map((n) => n[0])), edges = new Set(trace.axiom.edges.map((e) => e[0]));
  const faces = new Set(trace.axiom.faces.map((f) => f[0]));
  const out = [[nodes.size, edges.size, faces.size]];
  for (const s of trace.steps) {
    s.deleted.nodes.forEach((i) => nodes.delete(i));
    s.deleted.edges.forEach((i) => edges.delete(i));
    s.deleted.faces.forEach((i) => faces.delete(i));
    s.added.nodes.forEach((n) => nodes.add(n[0]));
    s.added.edges.forEach((e) => edges.add(e[0]));
    s.added.faces.forEach((f) => faces.add(f[0]));
    out.push([nodes.size, edges.size, faces.size]);
  }
  return out;
}
// Steps through a trace page with the Next button: what it draws per step,
// and (`ink`) the canvas's pixels drawn per step.
async function stepThrough(name, steps, ink) {
  await page.goto("file://" + join(work, name), { waitUntil: "load" });
  await page.waitForFunction(() => window.g2dTrace && window.g2dTrace.drawn);
  check((await page.$eval("#status", (s) => s.textContent)) === "", `${name}: the script ran`);
  const seen = [];
  await page.evaluate(() => window.g2dTrace.go(0));
  for (let f = 0; f <= steps; f++) {
    if (f > 0) await page.click("#next");
    const d = await page.evaluate(() => window.g2dTrace.drawn);
    seen.push([d.nodes, d.edges, d.faces]);
    if (ink) ink.push((await pixels()).ink);
  }
  return seen;
}
const ink = [];
let seen = await stepThrough("box_trace.html", trace.steps.length, ink);
check(JSON.stringify(seen) === JSON.stringify(countsPerStep(trace)), `box trace per step ${JSON.stringify(seen)}`);
check(ink.every((n) => n > 1000) && ink[ink.length - 1] > ink[0], `box trace: pixels per step ${ink}`);
await page.evaluate(() => window.g2dTrace.go(2));
await shot("trace3d_box_step2.png");
console.log("box trace: elements per step", JSON.stringify(seen));
const houseTrace = JSON.parse(readFileSync(join(work, "house_trace.json"), "utf8"));
seen = await stepThrough("house_trace.html", houseTrace.steps.length, null);
check(JSON.stringify(seen) === JSON.stringify(countsPerStep(houseTrace)), `house trace per step ${JSON.stringify(seen)}`);
await shot("trace3d_house_final.png");
const last = await page.evaluate(() => window.g2dTrace.drawn);
check(last.triangles > last.faces, `house trace: faces drawn as triangles (${last.triangles})`);
console.log("house trace: nodes, edges, faces at the last step", JSON.stringify(seen[seen.length - 1]));

check(errors.length === 0, "page errors: " + errors.join("; "));
await browser.close();
console.log(`${failures} failed`);
process.exit(failures ? 1 : 0);
