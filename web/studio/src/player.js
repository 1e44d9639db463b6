// The derivation player: the run again with its trace, stepped back and
// forth with the --trace pages' players (web/view/src): in 2D as SVG, in 3D
// in a viewer of its own. The controls (#first … #slider, #info) are the
// page's, in the Player pane.
import { playTrace } from "../../view/src/trace3d.js";
import { playTrace2d } from "../../view/src/trace2d_player.js";
import { createViewer } from "../../view/src/viewer.js";

export function createPlayer({ stage, solid, panel, info }) {
  let go = null, viewer = null;
  return {
    // A run's answer with "trace".
    play(data) {
      if (go && go.dispose) go.dispose();
      if (data.space === "3d") {
        stage.hidden = true, solid.hidden = false, panel.hidden = false;
        if (!viewer) viewer = createViewer({ panel, key: "studio-player", container: solid, keepInHash: false });
        playTrace(data.trace, viewer);
        go = window.g2dTrace.go;
      } else {
        solid.hidden = true, panel.hidden = true, stage.hidden = false;
        go = playTrace2d(data.trace, stage, info);
      }
    },
  };
}
