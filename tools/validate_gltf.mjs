#!/usr/bin/env node
// Validates glTF files with the Khronos glTF-Validator (npm "gltf-validator", pinned in
// tools/package.json; install with `npm ci --prefix tools`).
//
// Usage: node tools/validate_gltf.mjs <file-or-folder>...
// Folders are searched recursively for .gltf and .glb files. Prints one summary line per
// file and every error and warning with its JSON pointer. Exit status: 0 when no file has
// errors or warnings (infos and hints are allowed), 1 otherwise, also when a file cannot
// be read or no glTF file was found, 2 on usage errors.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const require = createRequire(import.meta.url);
let validator;
try {
  validator = require('gltf-validator');
} catch (e) {
  console.error('error: gltf-validator is not installed; run `npm ci --prefix tools` (or npm install --prefix tools)');
  process.exit(2);
}

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function collect(target, out) {
  const stat = fs.statSync(target, { throwIfNoEntry: false });
  if (!stat) throw new Error(`${target}: no such file or folder`);
  if (stat.isDirectory()) {
    // Sorted, so the output is stable from run to run.
    for (const name of fs.readdirSync(target).sort()) {
      const child = path.join(target, name);
      const s = fs.statSync(child);
      if (s.isDirectory()) collect(child, out);
      else if (/\.(gltf|glb)$/i.test(name)) out.push(child);
    }
  } else {
    out.push(target);
  }
}

async function validateFile(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const isGlb = /\.glb$/i.test(file);
  return validator.validateBytes(bytes, {
    uri: path.basename(file),
    format: isGlb ? 'glb' : 'gltf',
    maxIssues: 0,          // unlimited: every problem is listed
    writeTimestamp: false,
    // External buffers and images resolve relative to the file being validated.
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        const resolved = path.resolve(path.dirname(file), decodeURIComponent(uri));
        fs.readFile(resolved, (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
      }),
  });
}

async function main(args) {
  if (args.length === 0 || args.includes('--help') || args.includes('-h')) {
    console.error('usage: node tools/validate_gltf.mjs <file-or-folder>...');
    return 2;
  }
  const files = [];
  try {
    for (const a of args) collect(a, files);
  } catch (e) {
    console.error(`error: ${e.message}`);
    return 1;
  }
  if (files.length === 0) {
    console.error(`error: no .gltf or .glb file under ${args.join(' ')}`);
    return 1;
  }
  let failed = 0;
  for (const file of files) {
    let report;
    try {
      report = await validateFile(file);
    } catch (e) {
      console.log(`FAIL ${file}: validator could not read the file: ${e}`);
      ++failed;
      continue;
    }
    const i = report.issues;
    const bad = i.numErrors > 0 || i.numWarnings > 0;
    if (bad) ++failed;
    console.log(`${bad ? 'FAIL' : 'ok  '} ${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ` +
                `${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages) {
      if (m.severity > 1) continue;  // infos and hints are counted, not listed
      console.log(`    ${SEVERITY[m.severity]} ${m.code} at ${m.pointer ?? m.offset ?? '/'}: ${m.message}`);
    }
  }
  console.log(`${files.length} files validated, ${failed} with errors or warnings`);
  return failed ? 1 : 0;
}

process.exitCode = await main(process.argv.slice(2));
