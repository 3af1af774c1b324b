// @ts-check
/**
 * Following a run on the robot ("walk the best so far"): each new best seen during a run
 * drives the robot, at most every few seconds and once the one walking finished its episode,
 * so that each one walks a while and its speed is an episode's; when the run
 * ends, its run file becomes a module of the list (to watch, race, export, fine-tune further)
 * and its result drives the robot.
 */
import { bestSoFar, runResult } from './brain.js';
import { messageOf } from '../workers/kit.js';
import { shortLabel } from '../modules/names.js';
import { decimal } from '../shared/format.js';
import { familyName } from '../shared/families.js';

/** Least wall time between two switches of the viewer to a newer best (ms). */
const FOLLOW_INTERVAL_MS = 3000;

export class RunFollower {
  /**
   * @param {import('./robot.js').Robot} robot
   * @param {import('../modules/modules.js').ModuleList} modules
   * @param {() => boolean} finetuning the run under way fine-tunes a module
   */
  constructor(robot, modules, finetuning) {
    this.robot = robot;
    this.modules = modules;
    this.finetuning = finetuning;
    this.last = -Infinity;
    this.timer = 0;
    /** @type {(() => void) | null} */
    this.pending = null;
  }

  /**
   * A new best seen during a run: it drives the robot, now or once the last one walked a while.
   * @param {Float32Array} genome @param {number} fitness
   * @param {import('../workers/protocol.js').EvolveSettings} settings @param {string} kind
   */
  best(genome, fitness, settings, kind) {
    const robot = this.robot;
    const apply = () => {
      this.last = performance.now();
      this.pending = null;
      if (settings.shape !== robot.parts.drawing.rows()) return;
      robot.drive(bestSoFar(genome, fitness, settings, kind, this.finetuning(), robot.brain?.source ?? null, robot.parts.drawing.origin()));
    };
    window.clearTimeout(this.timer);
    this.pending = apply;
    this.applyWhenDue();
  }

  /**
   * Applies the pending best once the last one walked a while and, if it is a best seen during
   * the run, finished its episode: the speed under the robot is then an episode's speed, the
   * measure of the training figure beside it, not the first seconds of a walk from standing.
   */
  applyWhenDue() {
    if (!this.pending) return;
    const wait = this.last + FOLLOW_INTERVAL_MS - performance.now();
    const walking = this.robot.brain?.trained?.single === true && !this.robot.parts.viewer.readout.ended;
    if (wait <= 0 && !walking) { this.pending(); return; }
    this.timer = window.setTimeout(() => this.applyWhenDue(), Math.max(wait, 250));
  }

  /**
   * A run ended: its run file becomes a module and, with "walk the best so far", its result
   * drives the robot: the run file's best, the best of the final population by its latest
   * evaluation (what `vsr` reports and replays), which can be below the best single evaluation
   * seen on the way (fitness is re-measured on fresh terrains).
   * @param {import('../runs/panel.js').FinishedRun} run
   */
  finished(run) {
    const robot = this.robot;
    window.clearTimeout(this.timer);
    this.pending = null;
    let best;
    try {
      best = JSON.parse(run.runFile).best;
    } catch (error) {
      robot.error(`the run file could not be read: ${messageOf(error)}`);
      return;
    }
    const what = { evolve: 'evolved', finetune: 'fine-tuned', scratch: 'from scratch' }[run.mode];
    const family = familyName(best.controller);
    const label = `${what} ${family}, seed ${run.settings.seed}: ${decimal(best.fitness)} m/s in training`;
    const module = { key: `run:${run.mode}:${run.settings.seed}:${best.controller}:${run.settings.shape}`, label: `${label} (this page)`, text: run.runFile,
      short: shortLabel(`${what} ${family}, seed ${run.settings.seed}`, best.fitness, ' in training') }; // not the unseen terrains' mean of the study's modules
    this.modules.add(module, run.mode !== 'scratch') // the comparison is listed; the fine-tuned module stays chosen
      .catch((error) => robot.error(`the finished run could not be listed: ${messageOf(error)}`));
    const peak = Number.isFinite(run.peak) ? `; its best single evaluation on the way: ${decimal(run.peak)} m/s` : '';
    const result = `the best of its last generation, ${decimal(best.fitness)} m/s in training${peak}`;
    if (run.mode === 'scratch' || !run.follow || run.settings.shape !== robot.parts.drawing.rows()) {
      const which = run.mode === 'scratch' ? 'The from-scratch comparison' : 'The run';
      robot.parts.messages.show(`${which} ${run.stopped ? 'stopped' : 'finished'}: its result (${result}) is in the module list`
        + `${run.mode === 'scratch' && run.follow ? '; the robot walks on with the fine-tuned result' : ''}.`, 'note');
      return;
    }
    robot.drive(runResult(best, run.runFile, run.settings, robot.parts.drawing.origin(), `the ${what} run's result: ${result}`, run.mode === 'finetune'));
  }
}
