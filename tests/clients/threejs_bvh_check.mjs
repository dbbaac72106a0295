// Reads BVH files with three.js's BVHLoader and compares every joint's world position at
// every frame with mocapfill's forward kinematics (mocapfill_fk_dump's JSON).
//
// Usage: node threejs_bvh_check.mjs NODE_MODULES [--tolerance-mm 0.01] \
//          FILE.bvh EXPECTED.json [...] [--report-only FILE.bvh EXPECTED.json ...]
// NODE_MODULES holds `three` (tools/node_modules). Files after --report-only are measured and
// printed but do not decide the exit code. Exit 0 when every checked file is within the
// tolerance, 1 otherwise, 77 (a skip) when three.js cannot be loaded.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const args = process.argv.slice(2);
const modules = args.shift();
let toleranceM = 0.01e-3;
const checked = [];
const reported = [];
let target = checked;
while (args.length) {
  const a = args.shift();
  if (a === '--tolerance-mm') toleranceM = Number(args.shift()) * 1e-3;
  else if (a === '--report-only') target = reported;
  else target.push([a, args.shift()]);
}
if (!modules || !checked.length || checked.concat(reported).some(([, e]) => !e)) {
  console.error('usage: node threejs_bvh_check.mjs NODE_MODULES FILE.bvh EXPECTED.json ... [--report-only ...]');
  process.exit(2);
}

let BVHLoader;
try {
  ({ BVHLoader } = await import(pathToFileURL(path.join(modules, 'three/examples/jsm/loaders/BVHLoader.js')).href));
} catch (e) {
  console.log(`threejs_bvh_check: SKIPPED: three.js not found under ${modules} (npm install --prefix tools): ${e.message}`);
  process.exit(77);
}

// Worst distance (metres) between three.js's joint world positions and the expected ones.
function measure(bvhPath, expectedPath) {
  const expected = JSON.parse(readFileSync(expectedPath, 'utf8'));
  const result = new BVHLoader().parse(readFileSync(bvhPath, 'utf8'));
  const bones = new Map(result.skeleton.bones.map((b) => [b.name, b]));
  const missing = expected.joints.filter((j) => !bones.has(j));
  if (missing.length) throw new Error(`joints three.js did not read: ${missing.join(', ')}`);
  // Each track holds the bone's local position or rotation per frame (for positions, the
  // OFFSET plus the channels, which is where readers differ).
  const tracks = result.clip.tracks.map((t) => {
    const [name, property] = t.name.split('.');
    return { bone: bones.get(name), property, values: t.values, size: t.getValueSize() };
  });
  const frames = expected.positions.length;
  for (const t of tracks)
    if (t.values.length !== frames * t.size)
      throw new Error(`track of ${t.bone.name} has ${t.values.length / t.size} frames, expected ${frames}`);
  const roots = result.skeleton.bones.filter((b) => !b.parent || !bones.has(b.parent.name));
  const unit = expected.metres_per_unit;
  let worst = 0;
  let where = '-';
  for (let f = 0; f < frames; ++f) {
    for (const t of tracks) {
      if (t.property === 'position') t.bone.position.fromArray(t.values, f * 3);
      else if (t.property === 'quaternion') t.bone.quaternion.fromArray(t.values, f * 4);
    }
    for (const r of roots) r.updateMatrixWorld(true);
    expected.joints.forEach((name, j) => {
      const e = bones.get(name).matrixWorld.elements;
      const want = expected.positions[f][j];
      const d = Math.hypot(e[12] * unit - want[0], e[13] * unit - want[1], e[14] * unit - want[2]);
      if (d > worst) {
        worst = d;
        where = `${name} at frame ${f}`;
      }
    });
  }
  return { worst, where, joints: expected.joints.length, frames };
}

let failed = 0;
let overall = 0;
for (const [list, decides] of [[checked, true], [reported, false]]) {
  for (const [bvh, expected] of list) {
    let line;
    try {
      const m = measure(bvh, expected);
      const ok = m.worst <= toleranceM;
      if (decides && !ok) ++failed;
      if (decides) overall = Math.max(overall, m.worst);
      line = `${decides ? (ok ? 'ok' : 'FAILED') : 'report only'}: ${m.joints} joints, ${m.frames} frames; ` +
             `worst error ${(m.worst * 1000).toFixed(6)} mm (${m.where})`;
    } catch (e) {
      if (decides) ++failed;
      line = `${decides ? 'FAILED' : 'report only'}: ${e.message}`;
    }
    console.log(`threejs_bvh_check: ${bvh}: ${line}`);
  }
}
console.log(`threejs_bvh_check: ${checked.length} file(s) checked, ${failed} failed; worst error ` +
            `${(overall * 1000).toFixed(6)} mm (tolerance ${(toleranceM * 1000).toFixed(4)} mm)`);
process.exit(failed ? 1 : 0);
