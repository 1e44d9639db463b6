// The seeds sheet: the grammar for 16 seeds side by side (small PNGs the
// server renders in one job); a click on one takes its seed.
const COUNT = 16, WIDTH = 220;

export function createSeedsSheet(root, { api, request, takeSeed, status }) {
  const grid = Object.assign(document.createElement("div"), { id: "seed-grid" });
  const more = Object.assign(document.createElement("button"), { id: "next-seeds", type: "button", textContent: "Next 16 seeds" });
  root.append(more, grid);
  let first = 1, asked = 0;

  async function fill() {
    const mine = ++asked;
    status(`Deriving seeds ${first}–${first + COUNT - 1}…`);
    const { status: code, data } = await api("POST", "/api/seeds", { ...request(), first, count: COUNT, width: WIDTH });
    if (mine !== asked) return;
    if (code === 409) return fill();   // cancelled by an older request that arrived later (see studio.js)
    if (data.status !== "ok") return status(data.message || "The grammar has errors: the sheet is as it was");
    grid.replaceChildren(...data.sheet.map((cell) => {
      const b = Object.assign(document.createElement("button"), { type: "button", className: "seed-cell" });
      b.dataset.seed = cell.seed;
      if (cell.png) b.append(Object.assign(document.createElement("img"), { src: cell.png, alt: `seed ${cell.seed}` }));
      else b.append(Object.assign(document.createElement("p"), { className: "error", textContent: cell.message }));
      const caption = cell.elements ? `seed ${cell.seed}: ${cell.steps} steps` : `seed ${cell.seed}`;
      b.append(Object.assign(document.createElement("span"), { textContent: caption }));
      b.addEventListener("click", () => takeSeed(cell.seed));
      return b;
    }));
    status(`Seeds ${first}–${first + COUNT - 1}; click one to take its seed`);
  }
  more.addEventListener("click", () => ((first += COUNT), fill()));
  return { fill };
}
