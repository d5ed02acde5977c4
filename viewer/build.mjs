// Builds the viewer (docs/viewer.md): bundles src/main.js with its npm dependencies (uPlot) by
// esbuild into <outdir>/assets/ under content-hashed names, and writes <outdir>/index.html
// naming them. Usage: node build.mjs [outdir] (default: ../build/viewer).
import * as esbuild from 'esbuild';
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { basename, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const outdir = resolve(process.argv[2] ?? resolve(here, '../build/viewer'));
rmSync(outdir, { recursive: true, force: true });
mkdirSync(resolve(outdir, 'assets'), { recursive: true });

const result = await esbuild.build({
  entryPoints: [resolve(here, 'src/main.js')],
  bundle: true,
  minify: true,
  format: 'esm',
  target: ['es2020'],
  outdir: resolve(outdir, 'assets'),
  entryNames: '[name]-[hash]',
  metafile: true,
  logLevel: 'warning',
});
const outputs = Object.keys(result.metafile.outputs).map((p) => basename(p));
const js = outputs.find((name) => name.endsWith('.js'));
const css = outputs.find((name) => name.endsWith('.css'));
if (!js || !css) throw new Error(`esbuild wrote no script or style: ${outputs.join(', ')}`);
const html = readFileSync(resolve(here, 'src/index.html'), 'utf8')
  .replace('%APP_JS%', `/assets/${js}`)
  .replace('%APP_CSS%', `/assets/${css}`);
writeFileSync(resolve(outdir, 'index.html'), html);
console.log(`viewer built into ${outdir}: index.html, assets/${js}, assets/${css}`);
