// The script of the pages g2d writes in 3D, bundled by esbuild into one file
// that the runtime embeds (the pages need no network):
// - `g2d run --view OUT.html` (runtime/run/src/pages/view_page.cpp): the model
//   from <script id="g2d-model">, shown by the viewer (viewer.js documents the
//   model's JSON; the page's adds `title`, `home` and `counts`);
// - `g2d run --trace OUT.html` of a 3D grammar (trace_page.cpp): the trace
//   from <script id="trace">, played step by step (trace3d.js).
// `home`: the direction the camera first looks from, z up (3D grammars);
// without it, from above, a little from the front and the side (a 2D drawing).
import { createViewer } from "./viewer.js";
import { playTrace } from "./trace3d.js";

const status = document.getElementById("status");
try {
  const modelScript = document.getElementById("g2d-model");
  if (modelScript) {
    const model = JSON.parse(modelScript.textContent);
    const viewer = createViewer({ panel: document.getElementById("legend"), key: model.title });
    viewer.draw(model);
    const { lo, hi } = viewer.bounds(model);
    viewer.frame(lo, hi, model.home);
    // For tests and the curious: what was drawn.
    window.g2dView = { ...viewer.drawn, viewer };
  } else {
    const trace = JSON.parse(document.getElementById("trace").textContent);
    playTrace(trace, createViewer({ panel: document.getElementById("legend"), key: "trace:" + trace.grammar }));
  }
  if (status) status.textContent = "";
} catch (e) {
  if (status) status.textContent = "This page could not draw its model: " + e.message;
  throw e;
}
