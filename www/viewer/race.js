// @ts-check
/**
 * Side by side: up to four robots race on the same terrain, each in its own lane and its
 * own simulation worker, all started together, for the length of a training episode (they
 * stop where `vsr evaluate` ends one, so the speed shown at the end is that command's
 * figure). Any brain can race: the module chosen in the module list (pretrained, imported,
 * finished here), the current run's best so far, or the best of any generation of the
 * current run, which the page keeps for every generation (race generation 1 against 10
 * against 50 and see evolution at work). Adding or removing a robot restarts the race.
 */
import { describeRun, runGenome } from '../workers/core.js';
import { byId } from '../shared/dom.js';
import { downloadCsv } from '../shared/export.js';
import { messageOf } from '../workers/kit.js';
import { Lane, standings, walkedAt } from './race-lane.js';
import { decimal } from '../shared/format.js';
import { familyName } from '../shared/families.js';

/** Most robots in one race. */
export const MAX_RACERS = 4;
/**
 * Which measurement a lane's speed is, said under the race's line: this race's walk on one
 * terrain, not the module list's mean over the study's ten unseen terrains (issue 46: mlp-comm
 * at 3.63 m/s in the list and 5.85 m/s in chapter 6's race are both true).
 */
export const RACE_SPEEDS = 'Speeds: this race only (one walk on this ground), not the list\'s average over 10 new terrains.';

/**
 * How far (simulated s) a robot may walk ahead of the slowest one still racing: every lane has
 * its own worker, and a worker the machine holds back (a busy computer, another tab) would
 * fall behind for good; the others wait for it, so the race shows every robot at the same moment.
 */
export const LEAD_S = 0.2;

/** Simulated seconds between two rows of the race's table (CSV). */
export const TABLE_STEP_S = 0.5;

/** @typedef {import('./race-lane.js').Racer} Racer */
/** @typedef {{generation: number, fitness: number, genome: Float32Array}} GenerationBest */

/**
 * @typedef {object} RaceHooks
 * @property {() => Promise<import('../modules/modules.js').Module | null>} module  the module chosen in the list
 * @property {() => string} terrain                                        the terrain to race on
 * @property {(text: string, kind?: string) => void} message
 */

export class Race {
  /** @param {Document} doc @param {RaceHooks} hooks */
  constructor(doc, hooks) {
    this.hooks = hooks;
    this.section = byId(doc, 'race-panel');
    this.lanesBox = byId(doc, 'race-lanes');
    this.status = byId(doc, 'race-status');
    this.seconds = byId(doc, 'race-seconds', HTMLInputElement);
    this.speed = byId(doc, 'race-speed-select', HTMLSelectElement);
    this.generation = byId(doc, 'race-generation', HTMLSelectElement);
    const button = (/** @type {string} */ id) => byId(doc, id, HTMLButtonElement);
    this.buttons = { add: button('race-add'), best: button('race-best'), generation: button('race-add-generation'),
      firstLast: button('race-first-last'), restart: button('race-restart'), clear: button('race-clear'), csv: button('race-csv') };
    /** @type {Lane[]} */
    this.lanes = [];
    /** The current run's best evaluation of every generation, and what it evolved. */
    this.run = { bests: /** @type {GenerationBest[]} */ ([]), shape: '', controller: '', what: '', mode: '' };
    this.terrainName = '';
    /** Whether the robots wait at the start line (a tour question asks first; Restart starts them). */
    this.held = false;
    this.wire();
    this.update();
    requestAnimationFrame(/** @this {Race} @param {number} now */ function loop(now) {
      for (const lane of this.lanes) lane.draw(now);
      this.keepInStep();
      const places = standings(this.lanes.map((l) => l.walked));
      this.lanes.forEach((lane, i) => lane.stand(places[i]));
      requestAnimationFrame(loop.bind(this));
    }.bind(this));
  }

  /** Lets each running robot walk up to {@link LEAD_S} past the slowest running one. */
  keepInStep() {
    const racing = this.lanes.filter((l) => l.phase !== 'idle');
    const slowest = Math.min(...racing.map((l) => l.time));
    for (const lane of racing) lane.waitAt(racing.length > 1 ? slowest + LEAD_S : Infinity);
  }

  wire() {
    const b = this.buttons;
    b.add.addEventListener('click', () => this.addModule());
    b.best.addEventListener('click', () => this.addGeneration(-1));
    b.generation.addEventListener('click', () => this.addGeneration(Number(this.generation.value)));
    b.firstLast.addEventListener('click', () => this.firstMiddleLast());
    b.restart.addEventListener('click', () => { this.held = false; this.restart(); });
    b.clear.addEventListener('click', () => this.clear());
    b.csv.addEventListener('click', () => {
      const { header, rows } = this.table();
      downloadCsv(`race-${this.terrainName}-${this.seconds.value}s.csv`, header, rows);
    });
    this.speed.addEventListener('change', () => this.restart());
  }

  /** Adds the module chosen in the module list, on its own body with its own genome. */
  async addModule() {
    try {
      const module = await this.hooks.module();
      if (!module) { this.hooks.message('choose a module in the list first (3 · Give it a brain, Transplant a module)'); return; }
      await this.addRunFile(module);
    } catch (error) {
      this.hooks.message(`could not race this module: ${messageOf(error)}`);
    }
  }

  /**
   * Adds a module on its own body with its own genome (rejects with a readable Error when its
   * run file is malformed). @param {import('../modules/modules.js').Module} module @returns {Promise<void>}
   */
  async addRunFile(module) {
    const [info, genome] = await Promise.all([describeRun(module.text), runGenome(module.text)]);
    this.add({ label: module.label.replace(/ \([^()]*\)$/, ''), shape: info.shape, controller: info.controller, genome });
  }

  /** Takes every robot out of the race. */
  clear() {
    for (const lane of this.lanes) lane.dispose();
    this.lanes = [];
    this.restart();
  }

  /**
   * Adds the best of generation `generation` of the current run (-1: its best so far).
   * @param {number} generation
   */
  addGeneration(generation) {
    const { bests } = this.run;
    if (bests.length === 0) { this.hooks.message('evolve or fine-tune first: the race takes the bests of the current run'); return; }
    const pick = generation < 0
      ? bests.reduce((a, b) => (b.fitness > a.fitness ? b : a))
      : bests.find((b) => b.generation === generation);
    if (!pick) { this.hooks.message(`the current run has no generation ${generation}`); return; }
    const which = generation < 0 ? `best so far (generation ${pick.generation})` : `generation ${pick.generation}'s best`;
    this.add({ label: `${this.run.what}, ${which}`, shape: this.run.shape, controller: this.run.controller, genome: pick.genome });
  }

  /**
   * The generations {@link firstMiddleLast} races: the first, the middle one and the last of
   * the current run (fewer when it has fewer).
   * @param {GenerationBest[]} bests @returns {number[]}
   */
  static firstMiddleLastOf(bests) {
    const gens = bests.map((b) => b.generation);
    return [...new Set([gens[0], gens[Math.floor((gens.length - 1) / 2)], gens[gens.length - 1]])].filter((g) => g !== undefined);
  }

  /** Races the current run's first generation's best against its middle and last ones' (the race emptied first). */
  firstMiddleLast() {
    if (this.run.bests.length === 0) { this.hooks.message('evolve or fine-tune first: the race takes the bests of the current run'); return; }
    for (const lane of this.lanes) lane.dispose();
    this.lanes = [];
    for (const g of Race.firstMiddleLastOf(this.run.bests)) this.addGeneration(g);
    this.section.scrollIntoView({ block: 'start', behavior: 'instant' });
  }

  /** @param {Racer} racer */
  add(racer) {
    if (this.lanes.length >= MAX_RACERS) {
      this.hooks.message(`a race holds ${MAX_RACERS} robots: take one out (×) first`);
      return;
    }
    const lane = new Lane(this.lanesBox, racer, {
      loaded: () => this.startIfLoaded(),
      finished: () => this.update(),
      remove: (l) => { l.dispose(); this.lanes = this.lanes.filter((x) => x !== l); this.restart(); },
      failed: (l, text) => { this.hooks.message(`${l.racer.label} cannot race: ${text}`); l.dispose(); this.lanes = this.lanes.filter((x) => x !== l); this.restart(); },
    });
    this.lanes.push(lane);
    this.restart();
  }

  /**
   * Keeps each generation's best evaluation of the run under way (a new run starts afresh).
   * @param {{fitness: number, genome: Float32Array}} top @param {number} generation
   * @param {import('../workers/protocol.js').EvolveSettings} settings @param {string} kind @param {string} mode
   */
  keepGeneration(top, generation, settings, kind, mode) {
    if (generation === 0) {
      const what = { evolve: 'evolved', finetune: 'fine-tuned', scratch: 'from scratch' }[mode] ?? mode;
      this.run = { bests: [], shape: settings.shape, controller: kind, what: `${what} ${familyName(kind)} (seed ${settings.seed})`, mode };
      this.generation.replaceChildren();
    }
    if (!top || !Number.isFinite(top.fitness)) return;
    this.run.bests.push({ generation, fitness: top.fitness, genome: top.genome });
    this.generation.append(new Option(`generation ${generation} (${decimal(top.fitness)} m/s in training)`, String(generation)));
    this.update();
  }

  /**
   * The race as a table: every {@link TABLE_STEP_S} s of simulated time (and at the finish),
   * each robot's distance from the start line in metres (empty where it has not got to yet).
   * @returns {{header: string[], rows: (number | null)[][]}}
   */
  table() {
    const header = ['time (s)', ...this.lanes.map((l, i) => `${i + 1}. ${l.racer.label}: distance (m)`)];
    const end = Math.max(0, ...this.lanes.map((l) => l.track[l.track.length - 1]?.t ?? 0));
    const times = [];
    for (let k = 0; k * TABLE_STEP_S <= end + 1e-9; k++) times.push(k * TABLE_STEP_S);
    if (end > 0 && end - times[times.length - 1] > 1e-9) times.push(end);
    return { header, rows: times.map((t) => [t, ...this.lanes.map((l) => (t === 0 ? 0 : walkedAt(l.track, t)))]) };
  }

  /** Every robot back to the start line, paused until all are built; then all start together. */
  restart() {
    const seconds = Number(this.seconds.value);
    if (!(seconds > 0 && seconds <= 600)) { this.hooks.message(`the race lasts from 1 to 600 s, not "${this.seconds.value}"`); return; }
    this.terrainName = this.hooks.terrain();
    for (const lane of this.lanes) lane.load(this.terrainName, seconds, Number(this.speed.value));
    this.update();
  }

  /**
   * Keeps the robots at the start line (`on`), or starts them: a question about the race is
   * answered before it is run. @param {boolean} on
   */
  hold(on) {
    if (this.held === on) return;
    this.held = on;
    if (on) this.restart(); else this.startIfLoaded();
    this.update();
  }

  startIfLoaded() {
    if (this.held || this.lanes.length === 0 || !this.lanes.every((l) => l.loaded)) return;
    for (const lane of this.lanes) lane.run(true);
    this.update();
  }

  update() {
    const n = this.lanes.length;
    const b = this.buttons;
    b.add.disabled = n >= MAX_RACERS;
    b.best.disabled = n >= MAX_RACERS || this.run.bests.length === 0;
    b.generation.disabled = b.best.disabled;
    b.firstLast.disabled = this.run.bests.length < 2;
    this.generation.disabled = this.run.bests.length === 0;
    b.restart.disabled = n === 0;
    b.clear.disabled = n === 0;
    b.csv.disabled = n === 0;
    const done = n > 0 && this.lanes.every((l) => l.finished);
    this.section.dataset.state = n === 0 ? 'empty' : done ? 'finished' : this.held ? 'waiting' : 'racing';
    this.status.textContent = n === 0
      ? 'No robot in the race yet.'
      : `${n} robot${n === 1 ? '' : 's'} on ${this.terrainName}, ${this.seconds.value} s${done ? ': finished'
        : this.held ? ': waiting at the start line until you reveal your answer (Restart race starts them now)' : ''}. ${RACE_SPEEDS}`;
  }
}
