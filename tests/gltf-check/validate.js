// Validates .glb files with the Khronos glTF validator (npm gltf-validator):
// prints each file's counts and every message above "info", and exits 1 when
// a file has an error or a warning. Usage: node validate.js FILE.glb...
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

async function check(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
  const { numErrors, numWarnings, numInfos } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
  for (const m of report.issues.messages)
    if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer}: ${m.message}`);
  return numErrors === 0 && numWarnings === 0;
}

(async () => {
  let ok = true;
  for (const file of process.argv.slice(2)) ok = (await check(file)) && ok;
  process.exit(ok ? 0 : 1);
})().catch((e) => {
  console.error(e);
  process.exit(2);
});
