// Balls and tubes drawn as impostors: each instance is one camera-facing
// quad, and its fragments cast a ray at the exact sphere or capped cylinder,
// writing its normal and depth. A ball costs 2 triangles instead of 80 and
// stays round at any zoom; in software GL (no GPU) many small balls and
// tubes were most of a frame's time.
//
// The material is three's MeshLambertMaterial with its normal and position
// replaced, so the lights, colours and output are three's own.
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshLambertMaterial } from "three";

// Each quad is pulled toward the camera by the radius: a square of the radius there covers the
// cone from the camera to the sphere (or capsule end) behind it.
const VERTEX = {
  ball: /* glsl */ `
    vec3 center = (modelViewMatrix * vec4(endA, 1.0)).xyz;
    float radius = endRadius * length(modelViewMatrix[0].xyz);
    vec3 toward = normalize(center);
    vec3 across = normalize(cross(abs(toward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), toward));
    vec3 up = cross(toward, across);
    vec4 mvPosition = vec4(center + (across * position.x + up * position.y - toward) * radius, 1.0);
    gl_Position = projectionMatrix * mvPosition;
    vEndA = center;
    vEndB = center;
    vRadius = radius;
  `,
  tube: /* glsl */ `
    vec3 a = (modelViewMatrix * vec4(endA, 1.0)).xyz;
    vec3 b = (modelViewMatrix * vec4(endB, 1.0)).xyz;
    float radius = endRadius * length(modelViewMatrix[0].xyz);
    vec3 end = position.y < 0.0 ? a : b;
    vec3 toward = normalize(end);
    vec3 axis = b - a;
    vec3 across = cross(axis, toward);
    // Seen along its axis a tube is a disc: any direction across will do.
    if (dot(across, across) < 1e-12 * max(dot(axis, axis), 1e-30))
      across = cross(abs(toward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), toward);
    across = normalize(across);
    vec3 along = cross(toward, across);   // outward, past this end
    if (dot(along, position.y < 0.0 ? a - b : b - a) < 0.0) along = -along;
    // 1.1: the two ends' squares face slightly different ways under perspective.
    vec4 mvPosition = vec4(end + (across * position.x + along - toward) * radius * 1.1, 1.0);
    gl_Position = projectionMatrix * mvPosition;
    vEndA = a;
    vEndB = b;
    vRadius = radius;
  `,
};

// The hit along the ray from the camera (the view space's origin) through this fragment: its
// distance t and the surface normal there, or t < 0 for a miss.
const HIT = {
  ball: /* glsl */ `
    vec4 impostorHit(vec3 ray) {
      float b = dot(vEndA, ray);
      float h = b * b - dot(vEndA, vEndA) + vRadius * vRadius;
      if (h < 0.0) return vec4(-1.0);
      float t = b - sqrt(h);
      return vec4(t, (t * ray - vEndA) / vRadius);
    }
  `,
  // A capped cylinder from vEndA to vEndB.
  tube: /* glsl */ `
    vec4 impostorHit(vec3 ray) {
      vec3 ba = vEndB - vEndA, oc = -vEndA;
      float baba = dot(ba, ba), bard = dot(ba, ray), baoc = dot(ba, oc);
      float k2 = baba - bard * bard;
      float k1 = baba * dot(oc, ray) - baoc * bard;
      float k0 = baba * dot(oc, oc) - baoc * baoc - vRadius * vRadius * baba;
      float h = k1 * k1 - k2 * k0;
      if (h < 0.0) return vec4(-1.0);
      h = sqrt(h);
      float t = (-k1 - h) / k2;
      float y = baoc + t * bard;
      if (y > 0.0 && y < baba) return vec4(t, (oc + t * ray - ba * y / baba) / vRadius);
      // Past an end: the cap there.
      t = ((y < 0.0 ? 0.0 : baba) - baoc) / bard;
      if (abs(k1 + k2 * t) < h) return vec4(t, ba * sign(y) / sqrt(baba));
      return vec4(-1.0);
    }
  `,
};

const NORMAL = /* glsl */ `
  float faceDirection = 1.0;
  vec3 ray = normalize(-vViewPosition);
  vec4 hit = impostorHit(ray);
  if (hit.x < 0.0) discard;
  vec3 normal = normalize(hit.yzw);
  vec3 nonPerturbedNormal = normal;
  vec4 hitClip = projectionMatrix * vec4(hit.x * ray, 1.0);
  gl_FragDepth = 0.5 * hitClip.z / hitClip.w + 0.5;
`;

const VARYINGS = "varying vec3 vEndA;\nvarying vec3 vEndB;\nvarying float vRadius;\n";

function impostorMaterial(kind) {
  // Colours per vertex; a quad's winding depends on the view.
  const material = new MeshLambertMaterial({ side: DoubleSide, vertexColors: true });
  material.onBeforeCompile = (shader) => {
    shader.vertexShader = shader.vertexShader
      .replace("#include <common>", "#include <common>\nattribute vec3 endA;\nattribute vec3 endB;\nattribute float endRadius;\n" + VARYINGS)
      .replace("#include <project_vertex>", VERTEX[kind]);
    shader.fragmentShader = shader.fragmentShader
      .replace("#include <common>", "#include <common>\nuniform mat4 projectionMatrix;\n" + VARYINGS + HIT[kind])
      .replace("#include <normal_fragment_begin>", NORMAL);
  };
  material.customProgramCacheKey = () => "g2d-impostor-" + kind;
  return material;
}

// One mesh of n shapes given as flat arrays: `a` and `b` (x, y, z each; a tube's two ends, or a
// ball's centre twice), `r` and `color` (r, g, b each, linear). Each shape is a quad of four
// corners that carry it, not an instance (software GL drew instances one by one).
export function impostors(kind, { a, b, r, color }) {
  const n = r.length;
  const corner = new Float32Array(n * 12), endA = new Float32Array(n * 12), endB = new Float32Array(n * 12);
  const radius = new Float32Array(n * 4), colors = new Float32Array(n * 12), index = new Uint32Array(n * 6);
  const corners = [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0];
  for (let i = 0; i < n; i++) {
    for (let k = 0; k < 4; k++) {
      const v = (i * 4 + k) * 3;
      for (let c = 0; c < 3; c++) {
        corner[v + c] = corners[k * 3 + c];
        endA[v + c] = a[i * 3 + c];
        endB[v + c] = b[i * 3 + c];
        colors[v + c] = color[i * 3 + c];
      }
      radius[i * 4 + k] = r[i];
    }
    const q = i * 4, t = i * 6;
    index[t] = q, index[t + 1] = q + 1, index[t + 2] = q + 2, index[t + 3] = q, index[t + 4] = q + 2, index[t + 5] = q + 3;
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(corner, 3));
  geometry.setAttribute("endA", new BufferAttribute(endA, 3));
  geometry.setAttribute("endB", new BufferAttribute(endB, 3));
  geometry.setAttribute("endRadius", new BufferAttribute(radius, 1));
  geometry.setAttribute("color", new BufferAttribute(colors, 3));
  geometry.setIndex(new BufferAttribute(index, 1));
  const mesh = new Mesh(geometry, impostorMaterial(kind));
  mesh.frustumCulled = false;   // the quads' corners are not where the shapes are
  return mesh;
}
