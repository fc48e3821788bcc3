// Validates glb files with the Khronos glTF validator (npm package `gltf-validator`).
//
// Usage: node validate.mjs <file.glb>...
//
// For each file prints the issues (errors, warnings, infos) and one machine-readable line
//   STRATA_GLTF_REPORT {"file": ..., "errors": n, "warnings": n, "infos": n, "hints": n}
// Exits with status 1 if any file has an error or could not be validated, 2 on bad usage.
import { readFile } from "node:fs/promises";
import { basename } from "node:path";
import validator from "gltf-validator";

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error("usage: node validate.mjs <file.glb>...");
  process.exit(2);
}

const SEVERITY = ["error", "warning", "info", "hint"];
let failed = false;
console.log(`gltf-validator ${validator.version()}`);
for (const file of files) {
  try {
    const bytes = new Uint8Array(await readFile(file));
    const report = await validator.validateBytes(bytes, {
      uri: basename(file),
      format: "glb",
      maxIssues: 0, // 0 = unlimited
    });
    const issues = report.issues;
    for (const m of issues.messages) {
      console.log(`${file}: ${SEVERITY[m.severity] ?? m.severity} ${m.code} at ${m.pointer ?? m.offset ?? "-"}: ${m.message}`);
    }
    const summary = {
      file,
      errors: issues.numErrors,
      warnings: issues.numWarnings,
      infos: issues.numInfos,
      hints: issues.numHints,
      vertices: report.info?.totalVertexCount,
      triangles: report.info?.totalTriangleCount,
    };
    console.log(`STRATA_GLTF_REPORT ${JSON.stringify(summary)}`);
    if (issues.numErrors > 0) failed = true;
  } catch (e) {
    console.log(`STRATA_GLTF_REPORT ${JSON.stringify({ file, errors: 1, failure: String(e) })}`);
    failed = true;
  }
}
process.exit(failed ? 1 : 0);
