// Generate src/schema.d.ts from docs/openapi.json with openapi-typescript (`make clients`),
// or, with an output path argument, into that file (the drift check of tests/clients).
//
// Options that matter:
// - defaultNonNullable: false (the CLI's --default-non-nullable false): a request field that
//   has a default stays optional. openapi-typescript's default makes it required, and an IK
//   request would then need its 8 fields that have defaults instead of its one target.
// - binary strings (the package archive of POST /robots/package) are Blob, what FormData
//   takes, instead of string.
// - examples given by `externalValue` (the recorded PNG slice, a path the served document
//   resolves against its own address) are left out: they type nothing, and the bundler would
//   look for them on disk.
import fs from "node:fs";
import openapiTS, { astToString } from "openapi-typescript";
import ts from "typescript";

const BLOB = ts.factory.createTypeReferenceNode(ts.factory.createIdentifier("Blob"));
const document = new URL("../../docs/openapi.json", import.meta.url);
const output = process.argv[2] ?? new URL("src/schema.d.ts", import.meta.url);

function withoutExternalExamples(node) {
  if (Array.isArray(node)) return node.map(withoutExternalExamples);
  if (node === null || typeof node !== "object") return node;
  const out = {};
  for (const [key, value] of Object.entries(node)) {
    if (key === "examples" && value && typeof value === "object" && !Array.isArray(value)) {
      const kept = Object.entries(value).filter(([, example]) => !example?.externalValue);
      if (kept.length) out[key] = withoutExternalExamples(Object.fromEntries(kept));
    } else {
      out[key] = withoutExternalExamples(value);
    }
  }
  return out;
}

const spec = withoutExternalExamples(JSON.parse(fs.readFileSync(document, "utf8")));
const ast = await openapiTS(spec, {
  defaultNonNullable: false,
  transform(schemaObject) {
    return schemaObject.format === "binary" ? BLOB : undefined;
  },
});
const header = "// Generated from docs/openapi.json by clients/typescript/generate.mjs: do not edit.\n\n";
fs.writeFileSync(output, header + astToString(ast));
