// The live picture: a 2D run's SVG, or a 3D run's model in the --view page's
// viewer (web/view/src/viewer.js), whose camera stays where the user put it
// from one redraw to the next. A drawing of more than LARGE elements is
// shown as an image (rendered once by the browser, not as 10^5 DOM
// elements), and the page says so.
import { createViewer, softwareGL } from "../../view/src/viewer.js";

const LARGE = 100000;

export function createPicture({ flat, solid, panel, note }) {
  let viewer = null, imageUrl = null;

  function showSvg(svgText, elements) {
    solid.hidden = true, flat.hidden = false, panel.hidden = true;
    if (imageUrl) URL.revokeObjectURL(imageUrl), (imageUrl = null);
    const count = elements.nodes + elements.edges + elements.faces;
    if (count > LARGE) {
      imageUrl = URL.createObjectURL(new Blob([svgText], { type: "image/svg+xml" }));
      const img = Object.assign(document.createElement("img"), { src: imageUrl, alt: "The derived drawing" });
      flat.replaceChildren(img);
      note.textContent = `${count} elements: shown as an image, so the page stays quick (export the SVG for the drawing itself).`;
      return;
    }
    // Read by the HTML parser (inline SVG): 2.5 times as fast as DOMParser's XML on large drawings.
    // A template's content is inert until it is placed.
    const template = document.createElement("template");
    template.innerHTML = svgText;
    const svg = template.content.querySelector("svg");
    if (!svg) throw new Error("the run's SVG could not be read");
    flat.replaceChildren(svg);
    note.textContent = "";
  }

  function showModel(model) {
    flat.hidden = true, solid.hidden = false, panel.hidden = false;
    const { lo, hi } = viewer ? viewer.bounds(model) : {};
    if (!viewer) {
      // Redrawn on every edit: without a GPU, smooth edges cost more than the picture is worth.
      viewer = createViewer({ panel, key: "studio", container: solid, keepInHash: false, antialias: !softwareGL() });
      viewer.draw(model);
      const box = viewer.bounds(model);
      viewer.frame(box.lo, box.hi, model.home);
    } else {
      viewer.frame(lo, hi, model.home, true);   // the camera where the user left it
      viewer.draw(model);                        // one render
    }
    note.textContent = "";
  }

  return {
    // A run's answer (200 from /api/run).
    show(data) {
      if (data.space === "3d") showModel(data.model);
      else showSvg(data.svg, data.elements);
    },
    viewer: () => viewer,
  };
}
