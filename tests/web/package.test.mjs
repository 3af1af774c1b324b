// @ts-check
/**
 * The web package (node --test; needs `make wasm`): scripts/web-package.mjs lays it out in a
 * temporary folder with a package.json that names its files and types; the JS API of
 * docs/embed.md runs from it in Node (make a robot, step it, read its voxels, evaluate a genome:
 * bit-identical to `vsr evaluate` when the CLI is built); and `<vsr-robot>` from it walks in a
 * page of another origin, one script tag and nothing else (a CDN's case).
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { assemble } from '../../scripts/web-package.mjs';
import { serve } from '../../scripts/serve.mjs';
import { BIN, ROOT, openBare, start } from './harness.mjs';

const RUN = path.join(ROOT, 'pretrained', 'biped-4x3-attention.json');
/** @type {string} */ let out;
/** @type {{files: string[], manifest: Record<string, any>}} */ let pkg;

before(async () => {
  out = await mkdtemp(path.join(tmpdir(), 'vsr-web-package-'));
  pkg = await assemble(out);
});
after(async () => { await rm(out, { recursive: true, force: true }); });

test('the package names its files, its types and its version (Cargo.toml\'s)', async () => {
  const manifest = JSON.parse(await readFile(path.join(out, 'package.json'), 'utf8'));
  const cargo = await readFile(path.join(ROOT, 'Cargo.toml'), 'utf8');
  assert.equal(manifest.name, 'vsr-playground');
  assert.equal(manifest.version, /^version = "([^"]+)"/m.exec(cargo)?.[1]);
  assert.deepEqual(manifest.files, pkg.files);
  for (const file of [...manifest.files, 'README.md']) assert.ok(existsSync(path.join(out, file)), `${file} is in the package`);
  for (const file of ['pkg/vsr.js', 'pkg/vsr_bg.wasm', 'pkg/vsr.d.ts', 'embed/vsr-robot.js', 'workers/simulation-worker.js', 'viewer/renderer.js']) {
    assert.ok(manifest.files.includes(file), `files lists ${file}`);
  }
  assert.equal(manifest.types, 'pkg/vsr.d.ts');
  const types = await readFile(path.join(out, manifest.types), 'utf8');
  for (const name of ['class Episode', 'static fromRunFile', 'step(steps: number)', 'corners(): Float32Array', 'export function evaluate(']) {
    assert.ok(types.includes(name), `the types declare ${name}`);
  }
});

test('the JS API from the package in Node: make a robot, step it, read its voxels, evaluate a genome', async () => {
  const api = await import(pathToFileURL(path.join(out, 'pkg', 'vsr.js')).href);
  await api.default({ module_or_path: await readFile(path.join(out, 'pkg', 'vsr_bg.wasm')) });
  const runFile = await readFile(RUN, 'utf8');
  const gait = new api.Episode('1111-1111-1001', 'flat', 0.5, 1.5);
  const robot = api.Episode.fromRunFile(runFile, 'hilly-1-10-0', '');
  const x0 = robot.centreX;
  robot.step(60);
  assert.ok(Math.abs(robot.time - 1) < 1e-12, `60 steps are 1 s: ${robot.time}`);
  assert.equal(robot.voxelCount, 10);
  const corners = robot.corners();
  assert.equal(corners.length, 8 * 10);
  assert.ok(corners.every(Number.isFinite));
  assert.equal(robot.areaRatios().length, 10);
  robot.step(240);
  assert.ok(robot.centreX - x0 > 2, `it walks: ${robot.centreX - x0} m in 5 s`);
  assert.equal(robot.frame().corners.length, 80);
  gait.free();
  robot.free();
  assert.throws(() => new api.Episode('101', 'flat', 0.5, 1.5), /separate pieces/);

  const genome = api.runGenome(runFile);
  const result = api.evaluate('biped-4x3', 'attention', 'hilly-1-10-0', genome, 30, 0);
  assert.equal(result.steps, 1801);
  assert.ok(result.velocity > 2, `the pretrained biped walks: ${result.velocity} m/s`);
  if (existsSync(BIN)) {
    const out = execFileSync(BIN, ['evaluate', '--genome', RUN, '--terrain', 'hilly-1-10-0', '--seconds', '30'], { encoding: 'utf8' });
    const cli = JSON.parse(out.trim().split('\n').pop() ?? '{}');
    assert.equal(result.velocity, cli.velocity, 'evaluate is vsr evaluate, bit for bit');
    assert.equal(result.distance, cli.distance);
    console.log(`# evaluate = vsr evaluate: ${result.velocity} m/s`);
  } else {
    console.log(`# ${BIN} not built: evaluate was not compared with vsr evaluate`);
  }
  assert.throws(() => api.evaluate('biped-4x3', 'attention', 'flat', genome.subarray(0, 5), 30, 0), /genes/);
});

test('<vsr-robot> from the package walks in a page of another origin, with one script tag', async () => {
  const env = await start();
  const element = await serve({ root: out, port: 0, mounts: {} });
  const pageDir = await mkdtemp(path.join(tmpdir(), 'vsr-embed-page-'));
  try {
    await writeFile(path.join(pageDir, 'index.html'), `<!doctype html><title>a blog post</title><link rel="icon" href="data:,">
      <script type="module" src="${element.url}embed/vsr-robot.js"></script>
      <p>A robot:</p><vsr-robot module="/pretrained/biped-4x3-attention.json" style="width: 500px"></vsr-robot>`);
    const page = await serve({ root: pageDir, port: 0 });
    try {
      assert.notEqual(new URL(page.url).origin, new URL(element.url).origin);
      const { page: tab, problems } = await openBare(env.browser, page.url);
      await tab.waitForFunction(() => Number.isFinite(/** @type {any} */ (document.querySelector('vsr-robot')).x), undefined, { timeout: 30_000 });
      const x0 = await tab.evaluate(() => /** @type {any} */ (document.querySelector('vsr-robot')).x);
      await tab.waitForFunction((x0) => /** @type {any} */ (document.querySelector('vsr-robot')).x > x0 + 2, x0, { timeout: 30_000 });
      const box = await tab.locator('vsr-robot').boundingBox();
      assert.deepEqual([box?.width, box?.height], [500, 250], 'sized by CSS, 2:1 by default');
      assert.deepEqual(problems, []);
      await tab.context().close();
    } finally {
      page.server.close();
    }
  } finally {
    element.server.close();
    await env.close();
    await rm(pageDir, { recursive: true, force: true });
  }
});
