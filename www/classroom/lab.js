// @ts-check
/**
 * What a task's answer key may compute (exercises.js), each number run by the page or read
 * from a committed file at the moment it is asked: walks in the lab worker (lab-worker.js: the
 * core's own episode), the core's checks and transplant (workers/core.js), the committed run files
 * (pretrained/, study/), and the page's latest run (its best of every generation, kept by the
 * race).
 */
import { checkShape, describeRun, runGenome, transplant } from '../workers/core.js';
import { fetchOk, requester } from '../workers/kit.js';

const ask = requester('classroom/lab-worker.js', 'the classroom\'s measuring worker');

/** @typedef {import('./lab-worker.js').Walk} Walk */
/** @typedef {{generation: number, fitness: number, evaluations?: number}} GenerationBest */
/** @typedef {{bests: GenerationBest[], shape: string, controller: string, mode: string, running: boolean}} LatestRun  the page's latest run (viewer/race.js keeps it) and whether it is still going */

export class Lab {
  /**
   * @param {{defaults: import('../workers/core.js').Defaults, latestRun: () => LatestRun, raceSeconds: () => number}} page
   */
  constructor(page) {
    this.page = page;
    this.defaults = page.defaults;
    /** @type {Map<string, Promise<string>>} */
    this.files = new Map();
  }

  /**
   * Walks a robot; see lab-worker.js for what comes back.
   * @param {Walk} walk @returns {Promise<{speed: number, before?: number, frozen?: number, saturatedPer16?: number, movedByRow?: number[], voxels?: number}>}
   */
  walk(walk) { return ask('walk', walk); }

  /** A committed file's text (fetched once). @param {string} path served with the page */
  file(path) {
    if (!this.files.has(path)) {
      this.files.set(path, fetchOk(path, path).then((r) => r.text()));
    }
    return /** @type {Promise<string>} */ (this.files.get(path));
  }

  /** A run file's best on its own body. @param {string} path */
  async module(path) {
    const text = await this.file(path);
    const [info, genome] = await Promise.all([describeRun(text), runGenome(text)]);
    return { rows: info.shape, controller: info.controller, genome, seconds: info.seconds, info };
  }

  /**
   * The pretrained module (its file name) whose best genome is exactly `genome`, or '' if none is.
   * @param {Float32Array} genome
   */
  async pretrainedWith(genome) {
    const manifest = JSON.parse(await this.file('pretrained/manifest.json'));
    for (const { file } of /** @type {{file: string}[]} */ (manifest.modules)) {
      const mod = await this.module(`pretrained/${file}`);
      if (mod.genome.length === genome.length && mod.genome.every((g, i) => Object.is(g, genome[i]))) return file;
    }
    return '';
  }

  /** A run file's best generation by generation. @param {string} path @returns {Promise<GenerationBest[]>} */
  async history(path) {
    const run = JSON.parse(await this.file(path));
    return run.generations.map((/** @type {{generation: number, best: number, evaluations: number}} */ g) => ({ generation: g.generation, fitness: g.best, evaluations: g.evaluations }));
  }

  /** The core's transplant of a module onto `rows`. @param {string} path @param {string} rows @param {number} seed */
  async transplant(path, rows, seed) { return transplant(await this.file(path), rows, seed); }

  /** The core's check of a drawing. @param {string} rows */
  check(rows) { return checkShape(rows); }

  /** The page's latest run: its body, brain, mode and best of each generation (none before any run). */
  latestRun() { return this.page.latestRun(); }

  /** How long the race lasts (s), as its form says. */
  raceSeconds() { return this.page.raceSeconds(); }
}
