// Validates Kubernetes manifests against the API's published schemas, offline: kubernetes-models
// (npm, pinned in tests/web/package.json) carries the OpenAPI schemas of every built-in kind and
// validates an object with ajv. Every document of every file must be a known kind and valid.
//   node lint_kubernetes.mjs FILE.yaml...
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";

// The packages live in tests/web/node_modules (scripts/install-deps.sh installs them).
const require = createRequire(new URL("../web/package.json", import.meta.url));
const { parseAllDocuments } = require("yaml");
let failed = 0;
for (const file of process.argv.slice(2)) {
  for (const doc of parseAllDocuments(readFileSync(file, "utf8"))) {
    if (doc.errors.length) {
      console.log(`${file}: YAML: ${doc.errors[0].message}`);
      failed++;
      continue;
    }
    const object = doc.toJS();
    if (object === null) continue;
    const { apiVersion, kind } = object;
    const where = `${file}: ${kind} ${object.metadata?.name}`;
    let Model;
    try {
      Model = require(`kubernetes-models/${apiVersion}/${kind}`)[kind];
    } catch {
      console.log(`${where}: unknown apiVersion/kind ${apiVersion}/${kind}`);
      failed++;
      continue;
    }
    try {
      new Model(object).validate();
      console.log(`${where}: valid`);
    } catch (error) {
      console.log(`${where}: ${error.message}`);
      failed++;
    }
  }
}
process.exit(failed ? 1 : 0);
