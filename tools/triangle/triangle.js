#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
// Runs Shewchuk's Triangle (the triangle-wasm 1.0.0 build) on a .poly file, the
// way the native `triangle` command does, for lepp's comparisons.
//
//   node triangle.js IN.poly SWITCHES OUT_PREFIX      e.g.  node triangle.js square400.poly -pq30 out/sq
//   node triangle.js IN.node SWITCHES OUT_PREFIX      a point set (no -p), e.g. -cq30
//
// The input is read as Triangle's own file reader reads it (first vertex's
// number sets 0- or 1-based numbering, missing attributes and markers are 0,
// extra fields ignored, regions after the holes).
// Writes OUT_PREFIX.node, OUT_PREFIX.ele and OUT_PREFIX.poly (1-based, Triangle's
// formats) and prints "points added N" (output vertices minus input vertices)
// on stdout. Triangle is given segment markers 1..n (the file's own markers are
// dropped), so each output segment's marker is the input segment id + 1: the
// reading lepp's read_mesh gives it. Input vertices keep their numbers (no -j).
// Exit status: 0 ok, 2 bad input or usage, 1 Triangle failed, 77 triangle-wasm
// not installed.
//
//   node triangle.js --serve      many cases, one process (lepp audit's comparisons)
//
// reads one case per line on stdin, a JSON array [IN, SWITCHES, OUT_PREFIX], runs
// it as above and answers one line on stdout: "STATUS POINTS_ADDED MESSAGE"
// (STATUS as the exit status above, POINTS_ADDED -1 unless 0). Ends at the end
// of stdin. Starting node and loading the wasm costs far more than a small case.
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

// A failed case: its exit status and message (one process ends with it, the server answers it).
class CaseError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

function usage(message) {
  throw new CaseError(2, `triangle.js: ${message}\nusage: node triangle.js IN.poly SWITCHES OUT_PREFIX`);
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
  throw new CaseError(2, `triangle.js: ${file}: ${what}`);
}

// Reads vertices starting at lines[at] as Triangle's readnodes() does: the
// first vertex's number (0 or 1) sets the numbering, later numbers are not
// read; attributes and the marker default to 0 when missing; fields beyond
// them are ignored. Returns {points, attributes, nattr, markers, first, next, count}.
function readVertices(file, lines, at) {
  if (at >= lines.length) bad(file, 'missing vertex header');
  const head = lines[at].map(Number);
  const n = head[0];
  const dim = head.length > 1 ? head[1] : 2;
  const nattr = head.length > 2 ? head[2] : 0;
  const nmark = head.length > 3 ? head[3] : 0;
  if (!(n >= 0) || (n > 0 && dim !== 2)) bad(file, 'bad vertex header');
  const points = [];
  const attributes = [];
  const markers = [];
  let first = 1;
  for (let i = 0; i < n; i++) {
    const row = lines[at + 1 + i];
    if (!row || row.length < 3) bad(file, `vertex ${i + 1} missing or short`);
    if (i === 0 && (Number(row[0]) === 0 || Number(row[0]) === 1)) first = Number(row[0]);
    points.push(Number(row[1]), Number(row[2]));
    for (let a = 0; a < nattr; a++) attributes.push(row.length > 3 + a ? Number(row[3 + a]) : 0);
    markers.push(nmark > 0 && row.length > 3 + nattr ? Number(row[3 + nattr]) || 0 : 0);
  }
  return { points, attributes, nattr, markers, first, next: at + 1 + n, count: n };
}

// A .poly as Triangle's readpoly/readholes read it (segments with a bad
// endpoint are skipped with a warning, as Triangle does), or a .node alone (no
// segments). Regions are read when the section is there.
function readPoly(file) {
  const lines = readLines(file);
  let v = readVertices(file, lines, 0);
  let at = v.next;
  const segments = [];
  const segmentMarkers = [];
  const holes = [];
  const regions = [];
  if (/\.node$/.test(file)) return { ...v, segments, segmentMarkers, holes, regions };
  if (v.count === 0) {
    // The vertices live in the .node file beside the .poly.
    const nodeFile = file.replace(/\.poly$/, '.node');
    v = readVertices(nodeFile, readLines(nodeFile), 0);
  }
  if (at >= lines.length) bad(file, 'missing segment header');
  const nseg = Number(lines[at][0]);
  for (let i = 0; i < nseg; i++) {
    const row = lines[at + 1 + i];
    if (!row || row.length < 3) bad(file, `segment ${i + 1} missing or short`);
    const a = Number(row[1]) - v.first;
    const b = Number(row[2]) - v.first;
    if (!(a >= 0 && a < v.count && b >= 0 && b < v.count)) {
      process.stderr.write(`triangle.js: warning: ${file}: segment ${i + 1} has an invalid endpoint; skipped\n`);
      continue;
    }
    segments.push(a, b);
    segmentMarkers.push(i + 1);
  }
  at += 1 + nseg;
  if (at < lines.length) {
    const nholes = Number(lines[at][0]);
    for (let i = 0; i < nholes; i++) {
      const row = lines[at + 1 + i];
      if (!row || row.length < 3) bad(file, `hole ${i + 1} missing or short`);
      holes.push(Number(row[1]), Number(row[2]));
    }
    at += 1 + nholes;
  }
  if (at < lines.length) {
    const nregions = Number(lines[at][0]);
    for (let i = 0; i < nregions; i++) {
      const row = lines[at + 1 + i];
      if (!row || row.length < 4) bad(file, `region ${i + 1} missing or short`);
      // With one value, Triangle takes it as both the attribute and the area bound.
      regions.push(Number(row[1]), Number(row[2]), Number(row[3]), Number(row.length > 4 ? row[4] : row[3]));
    }
  }
  return { ...v, segments, segmentMarkers, holes, regions };
}

// %.17g, as Triangle's writers print reals.
function g17(x) {
  if (Number.isInteger(x) && Math.abs(x) < 1e17) return x.toString();
  const s = x.toPrecision(17);
  // toPrecision pads with zeros where %g would not: trim them.
  if (s.includes('e')) return s.replace(/\.?0+e/, 'e').replace(/e([+-])(\d)$/, 'e$10$2');
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
}

// The output files as Triangle's writenodes/writeelements/writepoly write them
// (1-based): .node with attributes and markers, .ele with triangle attributes,
// .poly with no vertices (they are in the .node), its segments, holes, regions.
function writeOutput(prefix, out, regions) {
  const np = out.numberofpoints;
  const pts = out.pointlist;
  const na = out.numberofpointattributes;
  const pa = out.pointattributelist;
  const pm = out.pointmarkerlist;
  const node = [`${np}  2  ${na}  1`];
  for (let i = 0; i < np; i++) {
    let line = `${i + 1}    ${g17(pts[2 * i])}  ${g17(pts[2 * i + 1])}`;
    for (let a = 0; a < na; a++) line += `  ${g17(pa[na * i + a])}`;
    node.push(`${line}    ${pm ? pm[i] : 0}`);
  }
  node.push('# Generated by triangle.js (triangle-wasm)');
  fs.writeFileSync(`${prefix}.node`, node.join('\n') + '\n');

  const nt = out.numberoftriangles;
  const corners = out.numberofcorners;
  const tl = out.trianglelist;
  const nta = out.numberoftriangleattributes;
  const ta = out.triangleattributelist;
  const ele = [`${nt}  ${corners}  ${nta}`];
  for (let i = 0; i < nt; i++) {
    let line = `${i + 1}`;
    for (let c = 0; c < corners; c++) line += `  ${tl[corners * i + c] + 1}`;
    for (let a = 0; a < nta; a++) line += `  ${g17(ta[nta * i + a])}`;
    ele.push(line);
  }
  ele.push('# Generated by triangle.js (triangle-wasm)');
  fs.writeFileSync(`${prefix}.ele`, ele.join('\n') + '\n');

  const ns = out.numberofsegments;
  const sl = out.segmentlist;
  const sm = out.segmentmarkerlist;
  const poly = [`0  2  ${na}  1`, `${ns}  1`];
  for (let i = 0; i < ns; i++) poly.push(`${i + 1}    ${sl[2 * i] + 1}  ${sl[2 * i + 1] + 1}    ${sm ? sm[i] : 0}`);
  const nh = out.numberofholes;
  const hl = out.holelist;
  poly.push(`${nh}`);
  for (let i = 0; i < nh; i++) poly.push(`${i + 1}   ${g17(hl[2 * i])}  ${g17(hl[2 * i + 1])}`);
  if (regions.length) {
    poly.push(`${regions.length / 4}`);
    for (let i = 0; i < regions.length / 4; i++)
      poly.push(`${i + 1}   ${regions.slice(4 * i, 4 * i + 4).map(g17).join('  ')}`);
  }
  poly.push('# Generated by triangle.js (triangle-wasm)');
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

// One case: reads IN, runs Triangle with SWITCHES, writes PREFIX.*; returns the points added.
function runCase(input, switches, prefix) {
  if (!input || !switches || !prefix) usage('three arguments needed');
  const pslg = readPoly(input);
  const inputPoints = pslg.points.length / 2;
  const io = Triangle.makeIO({
    pointlist: pslg.points,
    pointattributelist: pslg.nattr > 0 ? pslg.attributes : null,
    pointmarkerlist: pslg.markers,
    segmentlist: pslg.segments.length ? pslg.segments : null,
    segmentmarkerlist: pslg.segments.length ? pslg.segmentMarkers : null,
    holelist: pslg.holes.length ? pslg.holes : null,
    regionlist: pslg.regions.length ? pslg.regions : null,
  });
  const out = Triangle.makeIO();
  try {
    try {
      Triangle.triangulate(wasmSwitches(switches), io, out);
    } catch (e) {
      throw new CaseError(1, `triangle.js: Triangle failed: ${e && e.message ? e.message : e}`);
    }
    if (path.dirname(prefix)) fs.mkdirSync(path.dirname(prefix), { recursive: true });
    writeOutput(prefix, out, pslg.regions);
    return out.numberofpoints - inputPoints;
  } finally {
    Triangle.freeIO(io, true);
    Triangle.freeIO(out);
  }
}

// --serve: one case per line of stdin, one answer per line of stdout.
function serve() {
  const readline = require('readline');
  const lines = readline.createInterface({ input: process.stdin, terminal: false });
  lines.on('line', (line) => {
    let answer;
    try {
      const [input, switches, prefix] = JSON.parse(line);
      answer = `0 ${runCase(input, switches, prefix)} ok`;
    } catch (e) {
      const status = e instanceof CaseError ? e.status : 2;
      answer = `${status} -1 ${String(e && e.message ? e.message : e).replace(/\s+/g, ' ')}`;
    }
    process.stdout.write(answer + '\n');
  });
}

async function main() {
  const args = process.argv.slice(2);
  await Triangle.init(path.join(path.dirname(require.resolve('triangle-wasm')), 'triangle.out.wasm'));
  if (args[0] === '--serve') {
    serve();
    return;
  }
  try {
    const added = runCase(args[0], args[1], args[2]);
    process.stdout.write(`points added ${added}\n`);
  } catch (e) {
    process.stderr.write(`${e && e.message ? e.message : e}\n`);
    process.exit(e instanceof CaseError ? e.status : 1);
  }
}

main();
