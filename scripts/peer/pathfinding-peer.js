#!/usr/bin/env node
// PathFinding.js peer for `make bench`: solves Moving AI problems with PF.AStarFinder
// (DiagonalMovement.OnlyWhenNoObstacles = no corner cutting, octile heuristic) and prints, per problem,
// "index<TAB>length<TAB>microseconds" (length -1 when no path). Only findPath is timed; the grid clone
// each query needs (findPath mutates the grid) is made before the clock starts.
//
// usage: node pathfinding-peer.js --modules DIR MAP.map PROBLEMS.tsv
//   DIR          folder holding node_modules/pathfinding (the bench installs it into build/peer)
//   PROBLEMS.tsv lines "index sx sy gx gy" (x = column, y = row from the top)
'use strict';
const fs = require('fs');
const path = require('path');

function fail(message) {
  process.stderr.write('pathfinding-peer: ' + message + '\n');
  process.exit(2);
}

const args = process.argv.slice(2);
if (args.length !== 4 || args[0] !== '--modules') fail('usage: --modules DIR MAP.map PROBLEMS.tsv');
let PF;
try {
  PF = require(path.resolve(args[1], 'node_modules', 'pathfinding'));
} catch (e) {
  fail('cannot load pathfinding from ' + args[1] + ' (' + e.message + ')');
}

// Moving AI .map: '.' and 'G' passable, everything else blocked; CRLF tolerated.
function readMap(file) {
  const lines = fs.readFileSync(file, 'utf8').split(/\r?\n/);
  let i = 0, width = 0, height = 0;
  for (; i < lines.length && lines[i].trim() !== 'map'; ++i) {
    const w = lines[i].trim().split(/\s+/);
    if (w[0] === 'width') width = parseInt(w[1], 10);
    if (w[0] === 'height') height = parseInt(w[1], 10);
  }
  if (!(width > 0 && height > 0) || i >= lines.length) fail(file + ': not a Moving AI map');
  const matrix = [];
  for (let r = 0; r < height; ++r) {
    const row = lines[i + 1 + r];
    if (row === undefined || row.length < width) fail(file + ': short map row ' + r);
    const cells = new Array(width);
    for (let c = 0; c < width; ++c) cells[c] = (row[c] === '.' || row[c] === 'G') ? 0 : 1;
    matrix.push(cells);
  }
  return matrix;
}

function pathLength(p) {
  let len = 0;
  for (let k = 1; k < p.length; ++k) {
    const diagonal = p[k][0] !== p[k - 1][0] && p[k][1] !== p[k - 1][1];
    len += diagonal ? Math.SQRT2 : 1;
  }
  return len;
}

const base = new PF.Grid(readMap(args[2]));
const problems = fs.readFileSync(args[3], 'utf8').split(/\r?\n/).filter((l) => l.trim() !== '')
  .map((l) => l.trim().split(/\s+/).map(Number));
const finder = new PF.AStarFinder({
  diagonalMovement: PF.DiagonalMovement.OnlyWhenNoObstacles,
  heuristic: PF.Heuristic.octile,
});

// One untimed warm-up query so the JIT has compiled the search before the clock runs.
if (problems.length > 0) {
  const [, sx, sy, gx, gy] = problems[0];
  finder.findPath(sx, sy, gx, gy, base.clone());
}
const out = [];
for (const [index, sx, sy, gx, gy] of problems) {
  const grid = base.clone();
  const t0 = process.hrtime.bigint();
  const p = finder.findPath(sx, sy, gx, gy, grid);
  const t1 = process.hrtime.bigint();
  const len = p.length > 0 ? pathLength(p) : -1;
  out.push(index + '\t' + len.toFixed(8) + '\t' + (Number(t1 - t0) / 1000).toFixed(1));
}
process.stdout.write(out.join('\n') + '\n');
