#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
// Runs Shewchuk's Triangle (the triangle-wasm 1.0.0 build) on a .poly file, the
// way the native `triangle` command does, for lepp's comparisons.
//
//   node triangle.js IN.poly SWITCHES OUT_PREFIX      e.g.  node triangle.js square400.poly -pq30 out/sq
//
// Writes OUT_PREFIX.node, OUT_PREFIX.ele and OUT_PREFIX.poly (1-based, Triangle's
// formats) and prints "points added N" (output vertices minus input vertices)
// on stdout. Triangle is given segment markers 1..n (the file's own markers are
// dropped), so each output segment's marker is the input segment id + 1: the
// reading lepp's read_mesh gives it. Input vertices keep their numbers (no -j).
// Exit status: 0 ok, 2 bad input or usage, 1 Triangle failed, 77 triangle-wasm
// not installed.
'use strict';

const fs = require('fs');
const path = require('path');

// triangle-wasm's Emscripten loader fetches the .wasm as a URL whenever fetch
// exists; under Node it must read the file instead.
globalThis.fetch = undefined;
let Triangle;
try {
  Triangle = require('triangle-wasm');
} catch (e) {
  process.stderr.write('triangle.js: triangle-wasm is not installed: run `npm ci` in tools/triangle (scripts/install-deps.sh does)\n');
  process.exit(77);
}

function usage(message) {
  process.stderr.write(`triangle.js: ${message}\nusage: node triangle.js IN.poly SWITCHES OUT_PREFIX\n`);
  process.exit(2);
}

// Tokens of a Triangle file, line by line, with comments (#...) and blank lines dropped.
function readLines(file) {
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (e) {
    usage(`cannot read ${file}: ${e.message}`);
  }
  return text
    .split(/\r?\n/)
    .map((line) => line.replace(/#.*/, '').trim())
    .filter((line) => line.length > 0)
    .map((line) => line.split(/[\s,]+/));
}

function bad(file, what) {
  process.stderr.write(`triangle.js: ${file}: ${what}\n`);
  process.exit(2);
}

// Reads vertices starting at lines[at]; returns {points, markers, ids, next}.
function readVertices(file, lines, at) {
  if (at >= lines.length) bad(file, 'missing vertex header');
  const [n, dim, nattr, nmark] = lines[at].map(Number);
  if (!(n >= 0) || (n > 0 && dim !== 2)) bad(file, 'bad vertex header');
  const points = [];
  const markers = [];
  const ids = new Map(); // file id -> 0-based index
  for (let i = 0; i < n; i++) {
    const row = lines[at + 1 + i];
    if (!row || row.length < 3) bad(file, `vertex ${i + 1} missing or short`);
    ids.set(Number(row[0]), i);
    points.push(Number(row[1]), Number(row[2]));
    markers.push(nmark > 0 ? Number(row[3 + (nattr || 0)]) || 0 : 0);
  }
  return { points, markers, ids, next: at + 1 + n, count: n };
}

function readPoly(file) {
  const lines = readLines(file);
  let v = readVertices(file, lines, 0);
  let at = v.next;
  if (v.count === 0) {
    // The vertices live in the .node file beside the .poly.
    const nodeFile = file.replace(/\.poly$/, '.node');
    v = readVertices(nodeFile, readLines(nodeFile), 0);
  }
  if (at >= lines.length) bad(file, 'missing segment header');
  const nseg = Number(lines[at][0]);
  const segments = [];
  const segmentMarkers = [];
  for (let i = 0; i < nseg; i++) {
    const row = lines[at + 1 + i];
    if (!row || row.length < 3) bad(file, `segment ${i + 1} missing or short`);
    const a = v.ids.get(Number(row[1]));
    const b = v.ids.get(Number(row[2]));
    if (a === undefined || b === undefined) bad(file, `segment ${i + 1} names an unknown vertex`);
    segments.push(a, b);
    segmentMarkers.push(i + 1);
  }
  at += 1 + nseg;
  const holes = [];
  if (at < lines.length) {
    const nholes = Number(lines[at][0]);
    for (let i = 0; i < nholes; i++) {
      const row = lines[at + 1 + i];
      if (!row || row.length < 3) bad(file, `hole ${i + 1} missing or short`);
      holes.push(Number(row[1]), Number(row[2]));
    }
  }
  return { points: v.points, markers: v.markers, segments, segmentMarkers, holes };
}

function writeOutput(prefix, out) {
  const np = out.numberofpoints;
  const pts = out.pointlist;
  const pm = out.pointmarkerlist;
  const node = [`${np} 2 0 1`];
  for (let i = 0; i < np; i++) {
    node.push(`${i + 1} ${pts[2 * i].toString()} ${pts[2 * i + 1].toString()} ${pm ? pm[i] : 0}`);
  }
  fs.writeFileSync(`${prefix}.node`, node.join('\n') + '\n');

  const nt = out.numberoftriangles;
  const corners = out.numberofcorners;
  const tl = out.trianglelist;
  const ele = [`${nt} 3 0`];
  for (let i = 0; i < nt; i++) {
    ele.push(`${i + 1} ${tl[corners * i] + 1} ${tl[corners * i + 1] + 1} ${tl[corners * i + 2] + 1}`);
  }
  fs.writeFileSync(`${prefix}.ele`, ele.join('\n') + '\n');

  const ns = out.numberofsegments;
  const sl = out.segmentlist;
  const sm = out.segmentmarkerlist;
  const poly = ['0 2 0 1', `${ns} 1`];
  for (let i = 0; i < ns; i++) poly.push(`${i + 1} ${sl[2 * i] + 1} ${sl[2 * i + 1] + 1} ${sm ? sm[i] : 0}`);
  const nh = out.numberofholes;
  const hl = out.holelist;
  poly.push(`${nh}`);
  for (let i = 0; i < nh; i++) poly.push(`${i + 1} ${hl[2 * i].toString()} ${hl[2 * i + 1].toString()}`);
  fs.writeFileSync(`${prefix}.poly`, poly.join('\n') + '\n');
}

// Triangle's switches as the wasm build needs them: zero-based (z) and quiet (Q)
// unless the caller asked for verbose output.
function wasmSwitches(switches) {
  let s = switches.replace(/^-/, '');
  if (!s.includes('z')) s += 'z';
  if (!s.includes('Q') && !s.includes('V')) s += 'Q';
  return s;
}

async function main() {
  const [input, switches, prefix] = process.argv.slice(2);
  if (!input || !switches || !prefix) usage('three arguments needed');
  const pslg = readPoly(input);
  const inputPoints = pslg.points.length / 2;

  await Triangle.init(path.join(path.dirname(require.resolve('triangle-wasm')), 'triangle.out.wasm'));
  const io = Triangle.makeIO({
    pointlist: pslg.points,
    pointmarkerlist: pslg.markers,
    segmentlist: pslg.segments,
    segmentmarkerlist: pslg.segmentMarkers,
    holelist: pslg.holes.length ? pslg.holes : null,
  });
  const out = Triangle.makeIO();
  try {
    Triangle.triangulate(wasmSwitches(switches), io, out);
  } catch (e) {
    process.stderr.write(`triangle.js: Triangle failed: ${e && e.message ? e.message : e}\n`);
    process.exit(1);
  }
  if (path.dirname(prefix)) fs.mkdirSync(path.dirname(prefix), { recursive: true });
  writeOutput(prefix, out);
  process.stdout.write(`points added ${out.numberofpoints - inputPoints}\n`);
  Triangle.freeIO(io, true);
  Triangle.freeIO(out);
}

main();
