// Checks every document of a rendered Kubernetes manifest (kubectl kustomize's output) against
// the Kubernetes API's JSON schema of its apiVersion and kind, as shipped by kubernetes-models
// (offline): types, required fields and enumerations. A kind without a schema is a failure.
// Usage: node validate.js MANIFEST.yaml (run from this folder's node_modules, `npm ci`).
"use strict";
const fs = require("fs");
const path = require("path");
const yaml = require("js-yaml");

const models = path.dirname(require.resolve("kubernetes-models/package.json"));
const docs = yaml.loadAll(fs.readFileSync(process.argv[2], "utf8")).filter((d) => d);
let failures = 0;
for (const doc of docs) {
  const name = `${doc.kind}/${doc.metadata && doc.metadata.name}`;
  const folder = doc.apiVersion.includes("/") ? doc.apiVersion : `v1`;
  const file = path.join(models, folder, `${doc.kind}.js`);
  if (!fs.existsSync(file)) {
    console.log(`FAIL ${name}: no schema for ${doc.apiVersion} ${doc.kind}`);
    failures++;
    continue;
  }
  const Model = require(file)[doc.kind];
  try {
    new Model(doc).validate();
    console.log(`ok   ${name}`);
  } catch (e) {
    console.log(`FAIL ${name}: ${e.message}`);
    failures++;
  }
}
console.log(`${docs.length} documents, ${failures} invalid`);
process.exit(failures > 0 || docs.length === 0 ? 1 : 0);
