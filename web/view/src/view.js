// The script of the page `g2d run --view OUT.html` writes (runtime/run/src/pages/view_page.cpp):
// reads the model from <script id="g2d-model"> and shows it with three.js —
// faces as one flat-shaded mesh, edges as line segments, nodes as spheres —
// with orbit controls. Bundled by esbuild into one file that the runtime
// embeds, so the page needs no network.
//
// Model (JSON): { title, home?: [x, y, z], colors: [css...],
//   nodes: [[x, y, z, radius, color]...]   radius 0: not drawn (still an end or corner)
//   edges: [[a, b, color]...]               a, b: node indices
//   faces: [[color, i, j, k, ...]...]       corners in order; color: an index into colors
//   faceAlphas: [opacity...] }              one per face (1: opaque)
// `home`: the direction the camera looks from, z up (3D grammars); without
// it, from above, y up (a 2D drawing).
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  InstancedMesh,
  LineBasicMaterial,
  LineSegments,
  Matrix4,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
} from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const model = JSON.parse(document.getElementById("g2d-model").textContent);
const status = document.getElementById("status");

// CSS colours as g2d styles write them (#hex, names, rgb(), hsl()); anything
// three cannot read (a gradient's url(#id)) shows grey, as an SVG fill would not.
const palette = model.colors.map((css) => {
  const c = new Color(0xd9d9d9);
  try {
    c.setStyle(css);
  } catch (e) {
    /* keep grey */
  }
  return c;
});

const nodes = model.nodes;
const nodePos = (i) => new Vector3(nodes[i][0], nodes[i][1], nodes[i][2]);

// The faces that are opaque, or those that are not (`translucent`), as one
// mesh: see-through ones carry their opacity per vertex and are drawn after
// the rest without hiding what lies behind them.
const alphas = model.faceAlphas || model.faces.map(() => 1);
function faceMesh(translucent) {
  const chosen = model.faces.filter((f, i) => (alphas[i] < 1) === translucent);
  const alpha = model.faces.map((f, i) => alphas[i]).filter((a) => (a < 1) === translucent);
  let triangles = 0;
  for (const f of chosen) triangles += f.length - 3;
  const pos = new Float32Array(triangles * 9), col = new Float32Array(triangles * 12);
  let k = 0, q = 0;
  // Each polygon as a fan from its first corner.
  chosen.forEach((f, i) => {
    const c = palette[f[0]];
    for (let t = 2; t + 1 < f.length; t++) {
      for (const n of [f[1], f[t], f[t + 1]]) {
        pos.set(nodes[n].slice(0, 3), k);
        col.set([c.r, c.g, c.b, alpha[i]], q);
        k += 3;
        q += 4;
      }
    }
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(pos, 3));
  geometry.setAttribute("color", new BufferAttribute(col, 4));
  geometry.computeVertexNormals();   // unindexed: one normal per triangle
  // Pushed back a little, so that edges along the faces stay in front.
  const material = new MeshLambertMaterial({ vertexColors: true, side: DoubleSide, flatShading: true,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    transparent: translucent, depthWrite: !translucent });
  const mesh = new Mesh(geometry, material);
  if (translucent) mesh.renderOrder = 1;
  return { mesh, triangles };
}

function edgeLines() {
  const pos = new Float32Array(model.edges.length * 6), col = new Float32Array(model.edges.length * 6);
  model.edges.forEach(([a, b, ci], i) => {
    const c = palette[ci];
    pos.set(nodes[a].slice(0, 3), i * 6);
    pos.set(nodes[b].slice(0, 3), i * 6 + 3);
    col.set([c.r, c.g, c.b, c.r, c.g, c.b], i * 6);
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(pos, 3));
  geometry.setAttribute("color", new BufferAttribute(col, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ vertexColors: true }));
}

function nodeSpheres() {
  const shown = nodes.filter((n) => n[3] > 0);
  const mesh = new InstancedMesh(new SphereGeometry(1, 16, 12), new MeshLambertMaterial(), shown.length);
  const m = new Matrix4();
  shown.forEach((n, i) => {
    m.makeScale(n[3], n[3], n[3]).setPosition(n[0], n[1], n[2]);
    mesh.setMatrixAt(i, m);
    mesh.setColorAt(i, palette[n[4]]);
  });
  return mesh;
}

// The bounding box of everything drawn: the camera frames it.
const lo = new Vector3(Infinity, Infinity, Infinity), hi = new Vector3(-Infinity, -Infinity, -Infinity);
nodes.forEach((n, i) => {
  const r = n[3];
  lo.min(nodePos(i).subScalar(r));
  hi.max(nodePos(i).addScalar(r));
});
if (nodes.length === 0) lo.set(-1, -1, -1), hi.set(1, 1, 1);
const center = lo.clone().add(hi).multiplyScalar(0.5);
const radius = Math.max(hi.distanceTo(lo) / 2, 1e-6);

const scene = new Scene();
scene.background = new Color(0xffffff);
let triangles = 0;
for (const translucent of [false, true]) {
  const part = faceMesh(translucent);
  if (part.triangles > 0) scene.add(part.mesh);
  triangles += part.triangles;
}
if (model.edges.length > 0) scene.add(edgeLines());
if (nodes.some((n) => n[3] > 0)) scene.add(nodeSpheres());

// A soft fill plus a light over the viewer's shoulder, so that slopes read
// as shades; a face turned to the viewer shows about its own colour.
const camera = new PerspectiveCamera(35, 1, radius / 100, radius * 100);
scene.add(new AmbientLight(0xffffff, 1.1));
const headlight = new DirectionalLight(0xffffff, 2.2);
headlight.position.set(-0.3, 0.5, 1);
camera.add(headlight);
scene.add(camera);

let renderer;
try {
  renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
} catch (e) {
  status.textContent = "This browser cannot show WebGL, which this page needs.";
  throw e;
}
renderer.setPixelRatio(window.devicePixelRatio || 1);
document.body.appendChild(renderer.domElement);

if (model.home) camera.up.set(0, 0, 1);   // 3D grammars: z is up, as in the SVG
const controls = new OrbitControls(camera, renderer.domElement);
// A 3D grammar's model from its `home` (the SVG's direction); a 2D one
// looking down, a little from the front and the side, so it reads as its drawing.
function home() {
  const fov = (camera.fov * Math.PI) / 180;
  const fit = Math.min(fov, 2 * Math.atan(Math.tan(fov / 2) * camera.aspect)) / 2;
  const distance = (radius / Math.sin(fit)) * 1.05;
  const from = model.home ? new Vector3(...model.home) : new Vector3(0.25, -0.4, 1);
  camera.position.copy(center).add(from.normalize().multiplyScalar(distance));
  controls.target.copy(center);
  controls.maxDistance = distance * 10;
  controls.update();
}

function render() {
  renderer.render(scene, camera);
}
function resize() {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / Math.max(window.innerHeight, 1);
  camera.updateProjectionMatrix();
  render();
}
controls.addEventListener("change", render);
window.addEventListener("resize", resize);
window.addEventListener("keydown", (e) => {
  if (e.key === "r" || e.key === "R") home(), render();
});
resize();
home();
render();
// For tests and the curious: what was drawn.
window.g2dView = { triangles, edges: model.edges.length, nodes: nodes.length, home };
status.textContent = "";
