// Shared by the studio's browser tests: soft checks, a studio started on a
// file, Debian's chromium (puppeteer-core from web/view's devDependencies),
// the page's errors, and the end: the studio, stopped with SIGINT, must exit
// with 0; then one line and the exit status.
import { spawn } from "node:child_process";
import { createRequire } from "node:module";
import { join } from "node:path";
import { createInterface } from "node:readline";

let failures = 0;
export const check = (ok, what) => {
  if (!ok) failures++, console.log("FAIL:", what);
};

// `g2d studio FILE --port 0` in `cwd`, and the URL it prints first.
export async function startStudio(g2d, file, cwd) {
  const studio = spawn(g2d, ["studio", file, "--port", "0"], { cwd, stdio: ["ignore", "pipe", "inherit"] });
  const url = await new Promise((done) => createInterface({ input: studio.stdout }).once("line", done));
  return { studio, url };
}

// Headless chromium that reaches 127.0.0.1 only; `args` are added.
export function launchChromium(src, args, viewport) {
  const puppeteer = createRequire(join(src, "web/view/package.json"))("puppeteer-core");
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1", "--hide-scrollbars", ...args],
    defaultViewport: viewport,
  });
}

// The page's script errors, failed requests and console errors, as a list that fills as they come.
// A refused request answers 422 and a run cancelled by a newer one 409, which the console
// reports; nothing else may fail.
export function pageErrors(page) {
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => m.type() === "error" && !/status of (422|409)/.test(m.text()) && errors.push(m.text()));
  page.on("requestfailed", (r) => errors.push("request failed: " + r.url()));
  return errors;
}

export async function stop(browser, studio) {
  await browser.close();
  studio.kill("SIGINT");
}

export async function finish(studio, label) {
  const code = studio.exitCode ?? (await new Promise((done) => studio.once("exit", (c) => done(c))));
  check(code === 0, `the studio's exit code: ${code}`);
  if (failures) {
    console.log(`${failures} failures`);
    process.exit(1);
  }
  console.log(`${label}: all checks passed`);
}
