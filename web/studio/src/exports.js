// The export buttons: each file made by the server as `g2d run` makes it
// (same grammar, parameters and seed), then downloaded.
const FORMATS = [
  ["svg", "SVG"], ["png", "PNG"], ["json", "JSON"], ["obj", "OBJ"], ["glb", "glTF"],
];

export function createExports(root, { api, request, stem, status }) {
  async function download(format, tries = 3) {
    const { status: code, data, blob } = await api("POST", "/api/export", { ...request(), format });
    // A run started while the file was made cancels it: the file is asked for again.
    if (code === 409 && tries > 1) return download(format, tries - 1);
    if (code !== 200 || !blob) {
      if (code !== 409) status(`${format.toUpperCase()}: ${data ? data.message || "the grammar has errors" : code}`);
      return false;
    }
    const a = Object.assign(document.createElement("a"), { href: URL.createObjectURL(blob), download: `${stem()}.${format}` });
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
    return true;
  }
  for (const [format, label] of FORMATS) {
    const b = Object.assign(document.createElement("button"), { type: "button", id: "export-" + format, textContent: label,
      title: `Download the ${label} that g2d run writes` });
    // An OBJ comes with its materials (.mtl), as `g2d run --obj` writes them.
    b.addEventListener("click", async () => (await download(format)) && format === "obj" && download("mtl"));
    root.append(b);
  }
}
