// Loads .glb files with three.js's GLTFLoader (the three of the --view page,
// web/view, as scripts/install-npm.sh installs it) and prints, a line each:
// FILE: the scene's node names, its meshes, triangles and line sets. Exits 1
// when a file does not load. Usage: node three_load.mjs FILE.glb...
import fs from 'fs';
import { GLTFLoader } from '../../web/view/node_modules/three/examples/jsm/loaders/GLTFLoader.js';

let ok = true;
for (const file of process.argv.slice(2)) {
  const bytes = fs.readFileSync(file);
  const data = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  try {
    const gltf = await new Promise((resolve, reject) => new GLTFLoader().parse(data, '', resolve, reject));
    let meshes = 0, triangles = 0, lines = 0;
    gltf.scene.traverse((o) => {
      if (o.isMesh) meshes++, triangles += o.geometry.index.count / 3;
      if (o.isLineSegments) lines++;
    });
    console.log(`${file}: ${gltf.scene.children.map((c) => c.name).join(',')}; ${meshes} meshes, ${triangles} triangles, ${lines} line sets`);
  } catch (e) {
    console.log(`${file}: does not load: ${e.message || e}`);
    ok = false;
  }
}
process.exit(ok ? 0 : 1);
