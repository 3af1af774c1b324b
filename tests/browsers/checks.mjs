// @ts-check
/**
 * The checks that the page works, with the same results, in a browser other than Chromium,
 * on any {@link import('./tab.mjs').Tab}: the default robot walks; a tiny evolution in the
 * page's own workers gives `vsr evolve`'s run bit for bit (every generation's statistics but
 * its wall time, and the best genome); the viewer's speed over a pretrained module's episode
 * is `vsr evaluate`'s; the quick evolution (quick.mjs) finishes, the page having said before
 * how long it would take; the page said no error. Prints the figures and how long each took.
 * Needs `make wasm` (www/pkg) and target/release/vsr (VSR_BIN).
 */
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { serve } from '../../scripts/serve.mjs';
import { TINY, evolveInPage, evolveNative, statistics } from '../web/evolution.mjs';
import { BIN, ROOT } from '../web/harness.mjs';
import { quickEvolution } from './quick.mjs';
import { waitFor } from './tab.mjs';

const ATTENTION = 'pretrained/biped-4x3-attention.json';
const TERRAIN = 'hilly-1-10-7';

/**
 * Serves the page, opens it in the browser `launch` starts, and runs every check there.
 * @param {() => Promise<import('./tab.mjs').Tab & {problems?: string[]}>} launch
 */
export async function checkBrowser(launch) {
  assert.ok(existsSync(path.join(ROOT, 'www', 'pkg', 'vsr_bg.wasm')), 'www/pkg is missing: run make wasm');
  assert.ok(existsSync(BIN), `${BIN} is missing: cargo build --release --bin vsr (or set VSR_BIN)`);
  const started = Date.now();
  const served = await serve({ port: 0 });
  const tmp = await mkdtemp(path.join(os.tmpdir(), 'vsr-browsers-'));
  const tab = await launch();
  try {
    const say = timer(tab.name);
    await tab.goto(served.url);
    const walk = await walks(tab);
    say(`the default robot walks: "${walk.status}", simulated time ${walk.from.toFixed(2)} s, then ${walk.to.toFixed(2)} s a second later`);
    const evolved = await evolution(tab, tmp);
    say(`a tiny evolution (${TINY.budget} evaluations, 2 workers) is vsr evolve's bit for bit: best fitness ${evolved.best} in both, ${evolved.generations} generations, ${evolved.genes} genes`);
    const speed = await episodeSpeed(tab);
    say(`the viewer's speed over ${speed.seconds} s on ${TERRAIN} is vsr evaluate's: ${speed.viewed} m/s against ${speed.cli} m/s`);
    await tab.run(() => localStorage.clear(), undefined);
    await tab.goto(served.url); // afresh: a first visit's quick settings, fitted to this computer
    await walks(tab);
    const quick = await quickEvolution(tab);
    assert.ok(quick.evaluations > 0, 'the quick evolution ran');
    say(`the quick evolution: "${quick.estimate}" before it; it took ${quick.took.toFixed(1)} s for ${quick.evaluations} evaluations `
      + `on ${quick.workers} workers (${quick.rate.toFixed(1)} evaluations/s; the page said "${quick.said}")`);
    const messages = await tab.run(() => [...document.querySelectorAll('.message[data-kind="error"]')].map((m) => m.textContent), undefined);
    assert.deepEqual(messages, [], 'the page said no error');
    assert.deepEqual(tab.problems ?? [], [], 'no console or page error');
    console.log(`${tab.name}: all checks took ${((Date.now() - started) / 1000).toFixed(1)} s`);
  } finally {
    await tab.close();
    served.server.close();
    await rm(tmp, { recursive: true, force: true });
  }
}

/** Prints a figure line with the seconds since the last. @param {string} name */
function timer(name) {
  let last = Date.now();
  return (/** @type {string} */ line) => {
    console.log(`${name}: ${line} (${((Date.now() - last) / 1000).toFixed(1)} s)`);
    last = Date.now();
  };
}

/** The status once a robot is on screen, and its simulated time advancing. @param {import('./tab.mjs').Tab} tab */
async function walks(tab) {
  const status = await waitFor(tab, () => {
    const text = document.getElementById('status')?.textContent ?? '';
    return /voxels/.test(text) && text;
  }, undefined, 'the robot on screen', 60_000);
  const simTime = () => Number(document.getElementById('sim-time')?.dataset.value);
  const from = await waitFor(tab, simTime, undefined, 'a simulated time above 0');
  await new Promise((resolve) => setTimeout(resolve, 1_000));
  const to = await tab.run(simTime, undefined);
  assert.ok(to > from, `the simulated time goes on: ${from} s, then ${to} s a second later`);
  return { status, from, to };
}

/** The tiny evolution in the page against `vsr evolve`. @param {import('./tab.mjs').Tab} tab @param {string} tmp */
async function evolution(tab, tmp) {
  const { run } = await tab.run(evolveInPage, /** @type {[typeof TINY, number, boolean]} */ ([TINY, 2, false]));
  const native = await evolveNative(path.join(tmp, 'native.json'));
  assert.equal(run.timing.threads, 2);
  assert.equal(run.generations.length, 2, 'population 6, 18 evaluations: generations 0 and 1');
  assert.deepEqual(statistics(run), statistics(native), 'every generation as vsr evolve runs it');
  assert.deepEqual(run.best.genome, native.best.genome, 'the best genome as vsr evolve finds it');
  assert.equal(run.best.fitness, native.best.fitness);
  return { best: run.best.fitness, generations: run.generations.length, genes: run.best.genome.length };
}

/**
 * The pretrained attention module opened on its own body, on TERRAIN, as fast as possible:
 * the viewer's speed over its episode, and `vsr evaluate`'s.
 * @param {import('./tab.mjs').Tab} tab
 */
async function episodeSpeed(tab) {
  await tab.fill('#terrain', TERRAIN);
  await waitFor(tab, (file) => document.querySelector(`[data-testid="pretrained"] option[value="${file}"]`) !== null, ATTENTION, 'the pretrained modules listed');
  await tab.select('[data-testid="pretrained"]', ATTENTION);
  await tab.click('#module-open');
  await waitFor(tab, () => document.getElementById('status')?.textContent === '10 voxels, attention', undefined, 'the module on its own body');
  await tab.select('#speed', '0');
  await waitFor(tab, () => document.getElementById('robot-speed')?.dataset.ended === 'true', undefined, 'the episode\'s end', 300_000);
  const viewed = await tab.run(() => Number(document.getElementById('robot-speed')?.dataset.value), undefined);
  const said = await tab.run(() => document.getElementById('robot-speed')?.textContent ?? '', undefined);
  const seconds = JSON.parse(await readFile(path.join(ROOT, ATTENTION), 'utf8')).config.seconds;
  assert.match(String(said), new RegExp(`over its ${seconds}-s episode on ${TERRAIN}`));
  const cli = JSON.parse(execFileSync(BIN, ['evaluate', '--genome', path.join(ROOT, ATTENTION), '--terrain', TERRAIN,
    '--seconds', String(seconds)], { encoding: 'utf8' })).velocity;
  assert.equal(viewed, cli, `viewer ${viewed} m/s, vsr evaluate ${cli} m/s`);
  return { seconds, viewed, cli };
}
