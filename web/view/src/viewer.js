// The 3D viewer both pages share: the --view page (view.js) and the player
// of a 3D trace (trace3d.js). It draws a model — faces as the triangles g2d
// found for them, edges as hairlines or, with a radius, as tubes (G^3's
// cylinders), nodes as spheres — with orbit controls, toggles for faces,
// edges, nodes and axes, and views: home, front, side, top, and one saved
// (localStorage); the current view and toggles live in the URL's hash, so a
// reload or a shared link shows the same.
//
// Model: { colors: [css...],
//   nodes: [[x, y, z, radius, color]...]      radius 0: not drawn
//   edges: [[a, b, color, radius]...]         a, b: node indices; radius 0: a hairline
//   faces: [[id, color, [x, y, z, ...], [i, j, k, ...]]...]
//                                             the face's points, and its triangles as
//                                             indices into them, each running the
//                                             face's way round (its front side)
//   faceAlphas: [opacity...] }                one per face (1: opaque)
// Colours are indices into `colors` (-1: none).
import {
  AmbientLight,
  AxesHelper,
  BackSide,
  BufferAttribute,
  BufferGeometry,
  CanvasTexture,
  Color,
  DirectionalLight,
  FrontSide,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  Sprite,
  SpriteMaterial,
  Vector3,
  WebGLRenderer,
} from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { impostors } from "./impostors.js";

// CSS colours as g2d styles write them (#hex, names, rgb(), hsl()); anything
// three cannot read (a gradient's url(#id)) shows grey, as an SVG fill would not.
export function cssColor(css) {
  const c = new Color(0xd9d9d9);
  try {
    c.setStyle(css);
  } catch (e) {
    /* keep grey */
  }
  return c;
}

// Faces, opaque or see-through (`translucent`), as one geometry drawn twice:
// front sides in their colour, back sides darker, each lit along its own side's
// normal (the face's, or its reverse), so an inside-out face shows as such.
function faceMeshes(model, palette, translucent) {
  const alphas = model.faceAlphas || model.faces.map(() => 1);
  let triangles = 0;
  model.faces.forEach((f, i) => {
    if ((alphas[i] < 1) === translucent) triangles += f[3].length / 3;
  });
  if (triangles === 0) return { meshes: [], triangles };
  const pos = new Float32Array(triangles * 9), col = new Float32Array(triangles * 12);
  let k = 0, q = 0;
  model.faces.forEach(([, ci, points, tris], i) => {
    if ((alphas[i] < 1) !== translucent) return;
    const c = palette[ci] || new Color(0xd9d9d9);
    for (const p of tris) {
      pos.set([points[3 * p], points[3 * p + 1], points[3 * p + 2]], k);
      col.set([c.r, c.g, c.b, alphas[i]], q);
      k += 3;
      q += 4;
    }
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(pos, 3));
  geometry.setAttribute("color", new BufferAttribute(col, 4));
  geometry.computeVertexNormals();   // unindexed: each triangle's own normal, the face's
  // Pushed back a little, so that edges along the faces stay in front.
  const material = (side, shade) => new MeshLambertMaterial({ vertexColors: true, side, color: shade,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    transparent: translucent, depthWrite: !translucent });
  const meshes = [new Mesh(geometry, material(FrontSide, 0xffffff)), new Mesh(geometry, material(BackSide, 0xa8a8a8))];
  if (translucent) meshes.forEach((m) => (m.renderOrder = 1));
  return { meshes, triangles };
}

const BLACK = new Color(0);

function hairlines(palette, nodes, edges) {
  const pos = new Float32Array(edges.length * 6), col = new Float32Array(edges.length * 6);
  edges.forEach(([a, b, ci], i) => {
    const c = palette[ci] || new Color(0);
    pos.set(nodes[a].slice(0, 3), i * 6);
    pos.set(nodes[b].slice(0, 3), i * 6 + 3);
    col.set([c.r, c.g, c.b, c.r, c.g, c.b], i * 6);
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(pos, 3));
  geometry.setAttribute("color", new BufferAttribute(col, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ vertexColors: true }));
}

// Thick edges as capped cylinders of their radius between their ends; nodes with a radius as balls.
function tubes(palette, nodes, edges) {
  const n = edges.length, a = new Float32Array(n * 3), b = new Float32Array(n * 3), r = new Float32Array(n);
  const color = new Float32Array(n * 3);
  edges.forEach(([from, to, ci, radius], i) => {
    for (let c = 0; c < 3; c++) (a[i * 3 + c] = nodes[from][c]), (b[i * 3 + c] = nodes[to][c]);
    r[i] = radius;
    const rgb = palette[ci] || BLACK;
    color[i * 3] = rgb.r, color[i * 3 + 1] = rgb.g, color[i * 3 + 2] = rgb.b;
  });
  return impostors("tube", { a, b, r, color });
}

function spheres(palette, shown) {
  const n = shown.length, at = new Float32Array(n * 3), r = new Float32Array(n), color = new Float32Array(n * 3);
  shown.forEach((node, i) => {
    for (let c = 0; c < 3; c++) at[i * 3 + c] = node[c];
    r[i] = node[3];
    const rgb = palette[node[4]] || BLACK;
    color[i * 3] = rgb.r, color[i * 3 + 1] = rgb.g, color[i * 3 + 2] = rgb.b;
  });
  return impostors("ball", { a: at, b: at, r, color });
}

function label(text, color) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const g = canvas.getContext("2d");
  g.font = "bold 48px sans-serif";
  g.textAlign = "center";
  g.textBaseline = "middle";
  g.fillStyle = color;
  g.fillText(text, 32, 34);
  return new Sprite(new SpriteMaterial({ map: new CanvasTexture(canvas), depthTest: false }));
}

// Axes at the origin, x red, y green, z blue, each with its letter, drawn
// over the model (they often run along its edges).
function axes(size) {
  const group = new Group();
  const helper = new AxesHelper(size);
  helper.setColors(new Color("#d62728"), new Color("#2ca02c"), new Color("#1f77b4"));
  helper.material.depthTest = false;
  helper.renderOrder = 2;
  group.add(helper);
  [["x", "#d62728", [1, 0, 0]], ["y", "#2ca02c", [0, 1, 0]], ["z", "#1f77b4", [0, 0, 1]]].forEach(([name, color, dir]) => {
    const s = label(name, color);
    s.position.set(...dir.map((d) => d * size * 1.12));
    s.scale.setScalar(size * 0.16);
    s.renderOrder = 2;
    group.add(s);
  });
  return group;
}

// True when WebGL runs in software (SwiftShader, llvmpipe: a machine or VM
// without a GPU), where every pixel and vertex costs CPU time.
export function softwareGL() {
  const gl = document.createElement("canvas").getContext("webgl2") || document.createElement("canvas").getContext("webgl");
  if (!gl) return false;
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const lose = gl.getExtension("WEBGL_lose_context");
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

function release(object) {
  object.traverse((o) => {
    if (o.geometry) o.geometry.dispose();
    if (o.material) [].concat(o.material).forEach((m) => m.dispose());
  });
}

function dispose(group) {
  release(group);
  group.clear();
}

const PARTS = ["faces", "edges", "nodes", "axes"];
const KEYS = { f: "faces", e: "edges", n: "nodes", a: "axes" };

// A viewer in `container` (the whole window when it is `document.body`),
// its controls added to `panel`. `key` names the saved view in localStorage
// (the page's title). `keepInHash`: the camera and hidden parts are kept in the
// URL's hash (the --view page), not on a page with its own state (the studio).
// `antialias`: smooth edges (costly in software GL, where a page that redraws
// often may do without).
export function createViewer({ panel, key, container = document.body, keepInHash = true, antialias = true }) {
  const scene = new Scene();
  scene.background = new Color(0xffffff);
  const groups = {};
  for (const part of PARTS) scene.add((groups[part] = new Group()));
  // Made once and scaled to each model: new axes would free their shader programs, and compiling
  // them again stalled the next redraw (most of a second in software GL).
  groups.axes.add(axes(1));
  const camera = new PerspectiveCamera(35, 1, 0.01, 100);
  camera.up.set(0, 0, 1);   // z up, as in the SVG of a 3D grammar; a 2D drawing lies in z = 0
  // A soft fill plus a light over the viewer's shoulder, so that slopes read
  // as shades; a face turned to the viewer shows about its own colour.
  scene.add(new AmbientLight(0xffffff, 1.1));
  const headlight = new DirectionalLight(0xffffff, 2.2);
  headlight.position.set(-0.3, 0.5, 1);
  camera.add(headlight);
  scene.add(camera);

  const renderer = new WebGLRenderer({ antialias, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  container.appendChild(renderer.domElement);
  const controls = new OrbitControls(camera, renderer.domElement);

  const center = new Vector3(), drawn = { triangles: 0, faces: 0, edges: 0, tubes: 0, nodes: 0 };
  // A 2D drawing (no `home`): from above and a little from the front, so that
  // it reads as the SVG does, y up the screen.
  let radius = 1, homeFrom = new Vector3(0, -0.35, 1);

  function render() {
    renderer.render(scene, camera);
  }

  // The view: a camera direction from the centre, at the distance that fits the model.
  function look(from, up = new Vector3(0, 0, 1)) {
    const fov = (camera.fov * Math.PI) / 180;
    const fit = Math.min(fov, 2 * Math.atan(Math.tan(fov / 2) * camera.aspect)) / 2;
    const distance = (radius / Math.sin(fit)) * 1.05;
    camera.up.copy(up);
    camera.position.copy(center).add(from.clone().normalize().multiplyScalar(distance));
    controls.target.copy(center);
    controls.update();
    remember();
    render();
  }
  // Straight down, y up the screen: a hair toward -y so that orbiting about z stays defined.
  const views = {
    home: () => look(homeFrom),
    front: () => look(new Vector3(0, -1, 0)),
    side: () => look(new Vector3(1, 0, 0)),
    top: () => look(new Vector3(0, -1e-4, 1)),
  };

  // The hash: view=px,py,pz,tx,ty,tz and hide=parts, for reloads and links.
  const round = (x) => Number(x.toPrecision(7));
  function cameraState() {
    return [...camera.position.toArray(), ...controls.target.toArray()].map(round);
  }
  function setCamera(v) {
    camera.up.set(0, 0, 1);
    camera.position.set(v[0], v[1], v[2]);
    controls.target.set(v[3], v[4], v[5]);
    controls.update();
    render();
  }
  function remember() {
    if (!keepInHash) return;
    const hidden = PARTS.filter((p) => !groups[p].visible);
    const hash = "#view=" + cameraState().join(",") + (hidden.length ? "&hide=" + hidden.join(",") : "") +
      (panel.hidden ? "&panel=off" : "");
    try {
      history.replaceState(null, "", hash);
    } catch (e) {
      /* a page without history (about:blank): the view is not kept */
    }
  }
  function fromHash() {
    if (!keepInHash) return null;
    const params = new URLSearchParams(location.hash.slice(1));
    const v = (params.get("view") || "").split(",").map(Number);
    for (const p of (params.get("hide") || "").split(",")) if (groups[p]) show(p, false, false);
    // `panel=off`: the picture alone, for screenshots (scripts/gallery.sh).
    panel.hidden = params.get("panel") === "off";
    return v.length === 6 && v.every(Number.isFinite) ? v : null;
  }
  const storeKey = "g2d-view:" + key;
  function save() {
    try {
      localStorage.setItem(storeKey, JSON.stringify(cameraState()));
    } catch (e) {
      /* storage off: nothing saved */
    }
    saved.disabled = false;
  }
  function restore() {
    let v = null;
    try {
      v = JSON.parse(localStorage.getItem(storeKey) || "null");
    } catch (e) {
      v = null;
    }
    if (Array.isArray(v) && v.length === 6) setCamera(v), remember();
  }

  // The panel: a checkbox per part, then the views.
  const boxes = {};
  const bar = document.createElement("div");
  bar.id = "toggles";
  for (const part of PARTS) {
    const box = document.createElement("input");
    box.type = "checkbox";
    box.checked = true;
    box.id = "show-" + part;
    box.addEventListener("change", () => show(part, box.checked));
    const text = document.createElement("label");
    text.htmlFor = box.id;
    text.textContent = part[0].toUpperCase() + part.slice(1);
    text.title = "key " + part[0].toUpperCase();
    text.prepend(box);
    bar.append(text);
    boxes[part] = box;
  }
  const buttons = document.createElement("div");
  buttons.id = "views";
  const button = (text, title, act) => {
    const b = document.createElement("button");
    b.textContent = text;
    b.title = title;
    b.addEventListener("click", act);
    buttons.append(b);
    return b;
  };
  button("Home", "R: the first view", views.home);
  button("Front", "1: from the front (-y)", views.front);
  button("Side", "2: from the side (+x)", views.side);
  button("Top", "3: from above (+z)", views.top);
  button("Save", "S: keep this view (in the browser)", save);
  const saved = button("Saved", "V: the view kept with Save", restore);
  try {
    saved.disabled = !localStorage.getItem(storeKey);
  } catch (e) {
    saved.disabled = true;
  }
  panel.append(bar, buttons);

  function show(part, visible, keep = true) {
    groups[part].visible = visible;
    boxes[part].checked = visible;
    if (keep) remember(), render();
  }

  // Keys act on the picture only when nothing that takes text has the focus (the studio's editor).
  // (A checkbox or button keeps the keys: the toggles are clicked, then keys pressed.)
  const typing = (t) => t instanceof HTMLInputElement && !["checkbox", "radio", "button", "submit", "reset"].includes(t.type) ||
    t instanceof HTMLTextAreaElement || t instanceof HTMLSelectElement || (t instanceof HTMLElement && t.isContentEditable);
  function onKey(e) {
    if (e.ctrlKey || e.metaKey || e.altKey || typing(e.target) || !renderer.domElement.isConnected ||
        renderer.domElement.offsetParent === null && container !== document.body) return;
    const k = e.key.toLowerCase();
    if (KEYS[k]) show(KEYS[k], !groups[KEYS[k]].visible);
    else if (k === "r") views.home();
    else if (k === "1") views.front();
    else if (k === "2") views.side();
    else if (k === "3") views.top();
    else if (k === "s") save();
    else if (k === "v") restore();
  }
  window.addEventListener("keydown", onKey);
  controls.addEventListener("change", render);
  controls.addEventListener("end", remember);
  const whole = container === document.body;
  const onWindowResize = () => resize();
  // Sizes the canvas to its place (reallocated only when that changed) and
  // renders, unless `quiet` (the caller renders next).
  let size = "";
  function resize(quiet = false) {
    const width = whole ? window.innerWidth : container.clientWidth, height = whole ? window.innerHeight : container.clientHeight;
    if (width === 0 || height === 0) return;   // hidden: sized when shown
    if (size !== `${width}x${height}`) renderer.setSize(width, height), (size = `${width}x${height}`);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    if (!quiet) render();
  }
  const resizes = whole ? null : new ResizeObserver(() => resize());
  if (resizes) resizes.observe(container);
  else window.addEventListener("resize", onWindowResize);

  // What the camera frames: the box low..high ([x, y, z] each), first seen
  // from `from` (z up), or as the hash says. `keep`: the camera stays where
  // the user put it, and nothing is rendered: the caller draws the edited
  // model next (each render costs much in software GL); Home frames the new box.
  function frame(low, high, from, keep = false) {
    const lo = new Vector3(...low), hi = new Vector3(...high);
    center.copy(lo).add(hi).multiplyScalar(0.5);
    radius = Math.max(hi.distanceTo(lo) / 2, 1e-6);
    if (from) homeFrom = new Vector3(...from);
    camera.near = radius / 100;
    camera.far = radius * 100;
    controls.maxDistance = radius * 40;
    resize(true);
    groups.axes.scale.setScalar(radius * 0.5);
    if (keep) return;
    const v = fromHash();
    if (v) setCamera(v);
    else views.home();
  }

  // Draws `model` in place of what was drawn.
  function draw(model) {
    const palette = model.colors.map(cssColor);
    const old = [];
    for (const part of ["faces", "edges", "nodes"]) old.push(...groups[part].children), groups[part].clear();
    drawn.triangles = 0;
    for (const translucent of [false, true]) {
      const part = faceMeshes(model, palette, translucent);
      part.meshes.forEach((m) => groups.faces.add(m));
      drawn.triangles += part.triangles;
    }
    drawn.faces = model.faces.length;
    const thin = model.edges.filter((e) => !(e[3] > 0)), thick = model.edges.filter((e) => e[3] > 0);
    if (thin.length) groups.edges.add(hairlines(palette, model.nodes, thin));
    if (thick.length) groups.edges.add(tubes(palette, model.nodes, thick));
    drawn.edges = model.edges.length;
    drawn.tubes = thick.length;
    const shown = model.nodes.filter((n) => n[3] > 0);
    if (shown.length) groups.nodes.add(spheres(palette, shown));
    drawn.nodes = shown.length;
    render();
    // Freed once the new meshes are drawn: the shader programs they share stay compiled (a
    // redraw in the studio compiled them all again, the most of its time in software GL).
    old.forEach(release);
  }

  // The box of a model's nodes with their radii.
  function bounds(model) {
    const lo = new Vector3(Infinity, Infinity, Infinity), hi = new Vector3(-Infinity, -Infinity, -Infinity);
    for (const n of model.nodes) {
      const p = new Vector3(n[0], n[1], n[2]);
      lo.min(p.clone().subScalar(n[3]));
      hi.max(p.addScalar(n[3]));
    }
    if (model.nodes.length === 0) lo.set(-1, -1, -1), hi.set(1, 1, 1);
    return { lo: lo.toArray(), hi: hi.toArray() };
  }

  const visible = () => Object.fromEntries(PARTS.map((p) => [p, groups[p].visible]));
  // Frees the GL context and the listeners (the studio makes viewers as grammars change space).
  function destroy() {
    window.removeEventListener("keydown", onKey);
    if (resizes) resizes.disconnect();
    else window.removeEventListener("resize", onWindowResize);
    controls.dispose();
    for (const part of PARTS) dispose(groups[part]);
    renderer.dispose();
    renderer.domElement.remove();
    bar.remove(), buttons.remove();
  }

  return { draw, frame, bounds, render, views, show, visible, save, restore, drawn, camera: cameraState, destroy,
           canvas: renderer.domElement,
           // The shader programs made so far, as [id, name] (a redraw of the same kinds of parts makes none).
           programs: () => renderer.info.programs.map((p) => [p.id, p.name]) };
}
