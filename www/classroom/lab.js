// @ts-check
/**
 * What a task's answer key may compute (exercises.js), each number run by the page or read
 * from a committed file at the moment it is asked: walks in the lab worker (lab-worker.js: the
 * core's own episode), the core's checks and transplant (workers/core.js), the committed run files
 * (pretrained/, study/), the page's latest run (its best of every generation, kept by the
 * race), and a brain measured on the robot walking now, as “Your robot's speed” measures it (robot/measure.js).
 */
import { checkShape, describeRun, runGenome, transplant } from '../workers/core.js';
import { fetchOk, requester } from '../workers/kit.js';

const ask = requester('classroom/lab-worker.js', 'the classroom\'s measuring worker');

/** @typedef {import('./lab-worker.js').Walk} Walk */
/** @typedef {{generation: number, fitness: number, evaluations?: number}} GenerationBest */
/** @typedef {{bests: GenerationBest[], shape: string, controller: string, mode: string, running: boolean}} LatestRun  the page's latest run (viewer/race.js keeps it) and whether it is still going */
/**
 * @typedef {object} LabPage  what the lab asks the page (main.js)
 * @property {import('../workers/core.js').Defaults} defaults
 * @property {() => LatestRun} latestRun
 * @property {() => number} raceSeconds
 * @property {() => string} studyAnyBody  the study's brain for any body in pretrained/: its key ('' while the study trains it)
 * @property {() => {rows: string, terrain: string}} walkingBody  the body the viewer walks now, and the viewer's terrain
 * @property {(what: import('../robot/measure.js').Measured) => Promise<number>} measure  a brain's speed, measured as “Your robot's speed” is
 */

export class Lab {
  /** @param {LabPage} page */
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

  /** The study's brain for any body in pretrained/: its key, '' while the study still trains it. */
  studyAnyBody() { return this.page.studyAnyBody(); }

  /** The manifest's entry of the pretrained module `key` (its `any_body` figures among them), or null. @param {string} key */
  async manifestEntry(key) {
    const manifest = JSON.parse(await this.file('pretrained/manifest.json'));
    return (manifest.modules ?? []).find((/** @type {{file: string}} */ m) => `pretrained/${m.file}` === key) ?? null;
  }

  /** The body the viewer walks now, and the viewer's terrain. */
  walkingBody() { return this.page.walkingBody(); }

  /**
   * A brain's speed on a body, measured as the page measures “Your robot's speed” under the robot (the viewer's sensor noise).
   * @param {import('../robot/measure.js').Measured} what
   */
  measure(what) { return this.page.measure(what); }
}
