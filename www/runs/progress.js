// @ts-check
/**
 * A run's progress as the page shows it: the live figures (generation, evaluations, best so
 * far, the generation's best and median, evaluations per second; each raw number in
 * data-value for tests) and the chart against evaluations: best and median of an evolution,
 * or fine-tuning against the from-scratch run that follows it, drawn as a second line; and the
 * same figures as a table, a row per generation, for the CSV download.
 */
import { byId } from '../shared/dom.js';
import { FitnessChart } from './fitness-chart.js';
import { count, decimal as fixed } from '../shared/format.js';

const STYLE = {
  best: { label: 'best of generation', colour: 'rgb(200, 45, 40)' },
  median: { label: 'median', colour: 'rgb(49, 99, 190)' },
  finetune: { label: 'fine-tune (best so far)', colour: 'rgb(200, 45, 40)' },
  scratch: { label: 'from scratch (best so far)', colour: 'rgb(90, 90, 90)', dashed: true },
};

/** Which run of a fine-tune and its comparison the figures are, shown before them. @type {Record<string, string>} */
const PHASE = { finetune: 'Fine-tuning:', scratch: 'From scratch, the comparison:' };

/** What each run of a table is, in its CSV's first column. @type {Record<string, string>} */
const RUN_WORDS = { evolve: 'evolve', finetune: 'fine-tune', scratch: 'from scratch' };

/** The columns of the table (CSV): a row per generation. */
export const TABLE_HEADER = ['run', 'generation', 'evaluations', 'best (m/s)', 'median (m/s)', 'best so far (m/s)'];

/** The figures that start empty with every run. */
const FIGURES = ['generation', 'evaluations', 'best', 'genBest', 'median'];

export class RunProgress {
  /** @param {Document} doc the page */
  constructor(doc) {
    /** @type {Record<string, HTMLElement>} */
    this.out = {
      generation: byId(doc, 'run-generation'), evaluations: byId(doc, 'run-evaluations'), best: byId(doc, 'run-best'),
      genBest: byId(doc, 'run-gen-best'), median: byId(doc, 'run-median'), rate: byId(doc, 'run-rate'),
      caption: byId(doc, 'run-caption'), progress: byId(doc, 'run-progress'), phase: byId(doc, 'run-phase'),
    };
    this.chart = new FitnessChart(byId(doc, 'run-chart', HTMLCanvasElement));
    /** A row per generation of the latest run (and of its from-scratch comparison), as {@link TABLE_HEADER}. @type {(string | number)[][]} */
    this.table = [];
  }

  /** A run is starting: its figures are empty until it reports. */
  reset() {
    for (const key of FIGURES) show(this.out[key], NaN, '–');
    show(this.out.rate, NaN, '');
    this.out.rate.dataset.took = 'NaN';
  }

  /**
   * The run started: `planned` evaluations; a from-scratch comparison extends the chart of the
   * fine-tuning before it. @param {number} planned @param {string} mode
   */
  started(planned, mode) {
    if (mode !== 'scratch') { this.chart.clear(planned); this.table = []; } else this.chart.extend(planned);
    // The comparison's figures replace the fine-tuning's: its result stays in words beside them.
    const tuned = mode === 'scratch' ? this.table.filter((row) => row[0] === RUN_WORDS.finetune).at(-1) : undefined;
    this.out.phase.textContent = tuned
      ? `From scratch, the comparison (fine-tuning ended at ${fixed(Number(tuned[3]))} m/s, its last generation's best, the brain it keeps, after ${count(Number(tuned[2]))} evaluations):`
      : PHASE[mode] ?? '';
    this.out.phase.hidden = !this.out.phase.textContent;
    show(this.out.evaluations, 0, `0 / ${count(planned)}`);
  }

  /**
   * A generation's figures.
   * @param {{record: import('../workers/protocol.js').GenerationRecord, evaluations: number, planned: number, evalsPerSecond: number}} msg
   * @param {number} generations generations after generation 0 the run takes
   * @param {number} bestSoFar the best evaluation of the run so far
   * @param {'evolve' | 'finetune' | 'scratch'} mode
   */
  generation(msg, generations, bestSoFar, mode) {
    const { record } = msg;
    // Speeds to 4 decimals (0.1 mm/s) for a spreadsheet, not 17 digits; the run file keeps every digit.
    const speed = (/** @type {number | null | undefined} */ v) => (v === null || v === undefined ? NaN : Math.round(v * 1e4) / 1e4);
    this.table.push([RUN_WORDS[mode] ?? mode, record.generation, msg.evaluations, speed(record.best), speed(record.median), speed(bestSoFar)]);
    show(this.out.generation, record.generation, `${record.generation} of ${generations}`);
    show(this.out.evaluations, msg.evaluations, `${count(msg.evaluations)} / ${count(msg.planned)}`);
    show(this.out.best, bestSoFar, `${fixed(bestSoFar)} m/s`);
    show(this.out.genBest, record.best ?? NaN, `${fixed(record.best)} m/s`);
    show(this.out.median, record.median ?? NaN, `${fixed(record.median)} m/s`);
    show(this.out.rate, msg.evalsPerSecond, `${fixed(msg.evalsPerSecond, 1)} evaluations/s`
      + timeLeft((msg.planned - msg.evaluations) / msg.evalsPerSecond));
    this.out.rate.dataset.took = String(msg.evaluations / msg.evalsPerSecond); // seconds so far, pauses excluded
    if (mode === 'evolve') {
      this.chart.add('best', STYLE.best, msg.evaluations, record.best);
      this.chart.add('median', STYLE.median, msg.evaluations, record.median);
    } else {
      this.chart.add(mode, STYLE[mode], msg.evaluations, bestSoFar);
    }
    this.chart.request();
  }

  /** The run ended: how long it took (pauses excluded) beside its pace, on screen. */
  ended() {
    const took = Number(this.out.rate.dataset.took);
    if (took > 0 && Number.isFinite(took)) {
      this.out.rate.textContent = `${fixed(Number(this.out.rate.dataset.value), 1)} evaluations/s · took ${durationWords(took)}`;
    }
  }

  /**
   * Whether the figures are the walking robot's: if it has another brain than the last run's,
   * they are said to be the last run's. @param {boolean} other
   */
  otherBrain(other) {
    this.out.progress.dataset.other = String(other);
    this.out.caption.textContent = other ? 'These figures are the last run\'s: the robot walking now has another brain.' : '';
  }
}

/**
 * A duration in words: seconds under a minute, then minutes and seconds under ten minutes,
 * then minutes, then hours and minutes. @param {number} seconds (> 0) @returns {string}
 */
export function durationWords(seconds) {
  const s = Math.ceil(seconds);
  if (s < 60) return `${s} s`;
  const m = Math.floor(s / 60);
  if (m < 10) return `${m} min ${s % 60} s`;
  if (m < 120) return `${Math.round(s / 60)} min`;
  return `${Math.floor(m / 60)} h ${m % 60} min`;
}

/**
 * The time a run has left at its pace so far, in words ('' when done or unknown).
 * @param {number} seconds @returns {string}
 */
export function timeLeft(seconds) {
  return seconds > 0 && Number.isFinite(seconds) ? ` · about ${durationWords(seconds)} to go` : '';
}

/** Shows a figure, with its raw number in data-value for tests. @param {HTMLElement} el @param {number} value @param {string} text */
function show(el, value, text) {
  el.dataset.value = String(value);
  el.textContent = text;
}
