// The Khronos glTF validator over glTF files: `node validate.mjs FILE...`. Prints each file's counts
// and its errors (warnings too, when asked with --warnings); exits 1 when any file has an error, 2 on
// a usage or read problem. Buffers and images are validated through their URIs beside the file.
import validator from 'gltf-validator';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const args = process.argv.slice(2);
const showWarnings = args.includes('--warnings');
const files = args.filter((a) => a !== '--warnings');
if (files.length === 0) {
  console.error('usage: node validate.mjs [--warnings] FILE.gltf|FILE.glb...');
  process.exit(2);
}

let failed = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (e) {
    console.error(`gltf-validator: ${file}: ${e.message}`);
    process.exit(2);
  }
  const report = await validator.validateBytes(bytes, {
    uri: file,
    maxIssues: 0,  // all of them
    externalResourceFunction: (uri) => readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const issues = report.issues;
  const info = report.info ?? {};
  const images = (info.resources ?? []).filter((r) => r.image).length;
  console.log(`gltf-validator ${report.validatorVersion}: ${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints; ${info.totalTriangleCount ?? 0} triangles, ` +
              `${info.materialCount ?? 0} materials, ${images} images, ${info.drawCallCount ?? 0} draw calls`);
  for (const m of issues.messages) {
    if (m.severity === 0 || (showWarnings && m.severity === 1))
      console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer ?? '(file)'}: ${m.message}`);
  }
  if (issues.numErrors > 0) failed = true;
}
process.exit(failed ? 1 : 0);
