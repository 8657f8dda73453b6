// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Runs the reference MikkTSpace (npm package "mikktspace", a WebAssembly build of the
// reference algorithm) on an unindexed triangle list written by the C++ tests.
//   node mikktspace_reference.js <module dir> <in.bin> <out.bin> [repetitions]
// in.bin: uint32 corner count n, then n*3 float32 positions, n*3 normals, n*2 texcoords.
// out.bin: n*4 float32 tangents (xyz, w). With repetitions > 0 it also prints the median
// time of one generateTangents call in milliseconds (for BENCHMARKS.md).
'use strict';
const fs = require('fs');
const path = require('path');

const [moduleDir, inFile, outFile, repArg] = process.argv.slice(2);
const { generateTangents } = require(path.join(moduleDir, 'node_modules', 'mikktspace'));

const buf = fs.readFileSync(inFile);
const n = buf.readUInt32LE(0);
const floats = new Float32Array(buf.buffer.slice(buf.byteOffset + 4, buf.byteOffset + 4 + n * 8 * 4));
const positions = floats.slice(0, 3 * n);
const normals = floats.slice(3 * n, 6 * n);
const texcoords = floats.slice(6 * n, 8 * n);

let tangents = generateTangents(positions, normals, texcoords);
const reps = repArg ? parseInt(repArg, 10) : 0;
if (reps > 0) {
  const times = [];
  for (let r = 0; r < reps; ++r) {
    const t0 = process.hrtime.bigint();
    tangents = generateTangents(positions, normals, texcoords);
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
  times.sort((a, b) => a - b);
  console.log(`generateTangents median ${times[Math.floor(reps / 2)].toFixed(1)} ms over ${reps} runs, ${n / 3} triangles`);
}
if (tangents.length !== 4 * n) {
  console.error(`expected ${4 * n} tangent values, got ${tangents.length}`);
  process.exit(1);
}
fs.writeFileSync(outFile, Buffer.from(tangents.buffer, tangents.byteOffset, tangents.byteLength));
