// The 2D trace page's script (`g2d run --trace OUT.html` of a 2D grammar,
// runtime/run/src/pages/trace_page.cpp): the trace from <script id="trace">,
// played in <svg id="stage">. Bundled by esbuild into dist/trace.bundle.js,
// which the runtime embeds.
import { playTrace2d } from "./trace2d_player.js";

playTrace2d(JSON.parse(document.getElementById("trace").textContent), document.getElementById("stage"),
  document.getElementById("info"));
