// @ts-check
/**
 * Freeze the attention (the paper's Fig. 6, live): a button that freezes every voxel's
 * attention matrix where it is now (the core's freeze, the one the ablation uses; the worker
 * does it) and releases it, and a line with the robot's speed over the seconds before
 * freezing and over the latest seconds frozen, and what the two mean in words. Both speeds
 * are the same measure: the centre's forward distance over the time it took (as fitness,
 * over a window). Only an attention brain can be frozen.
 */
import { byId } from '../shared/dom.js';
import { decimal, NONE } from '../shared/format.js';
import { hasAttention } from '../shared/families.js';
/** Seconds of walking before the freeze that its "before" speed is measured over. */
export const BEFORE_WINDOW_S = 5;

/** Seconds of frozen walking its "frozen" speed is measured over (the latest ones). */
export const AFTER_WINDOW_S = 2;

/** @typedef {{t: number, x: number}} Sample  simulated time (s) and the centre's x (m) */

export class FreezeControl {
  /**
   * @param {Document} doc
   * @param {(frozen: boolean) => void} send asks the simulation worker to freeze or release
   */
  constructor(doc, send) {
    this.button = byId(doc, 'freeze-attention', HTMLButtonElement);
    this.report = byId(doc, 'freeze-report');
    this.send = send;
    /** Recent samples, the last {@link BEFORE_WINDOW_S} s. @type {Sample[]} */
    this.recent = [];
    /** The moment of freezing, the speed before it and over how long, while frozen. @type {{at: Sample, before: number, window: number} | null} */
    this.mark = null;
    this.frozen = false;
    this.button.addEventListener('click', () => this.send(!this.frozen));
    this.loaded('phase gait');
  }

  /** A new episode (frozen matrices do not carry over). @param {string} controller what drives it */
  loaded(controller) {
    this.recent = [];
    this.mark = null;
    this.setFrozen(false);
    const can = hasAttention(controller);
    this.button.disabled = !can;
    this.button.title = can
      ? 'Freeze every voxel\'s attention matrix as it is now (as the paper\'s ablation does), and watch the speed'
      : 'Only a robot with an attention brain has attention to freeze';
    this.report.textContent = '';
    this.show(NaN, NaN);
  }

  /** @param {import('../workers/protocol.js').Frame} frame */
  setFrame(frame) {
    const now = { t: frame.time, x: frame.centreX };
    if (!Number.isFinite(now.t) || !Number.isFinite(now.x)) return;
    if (this.recent.length > 0 && now.t < this.recent[this.recent.length - 1].t) this.recent = [];
    this.recent.push(now);
    while (this.recent.length > 2 && now.t - this.recent[1].t >= BEFORE_WINDOW_S) this.recent.shift();
    if (frame.frozen && !this.mark) {
      const from = this.recent[0];
      this.mark = { at: now, before: speedBetween(from, now), window: now.t - from.t };
    } else if (!frame.frozen && this.mark) {
      this.mark = null;
    }
    this.setFrozen(Boolean(frame.frozen));
    if (!this.mark) return;
    const { at, before, window } = this.mark;
    const seconds = now.t - at.t;
    // The pace frozen: over the last seconds, once the robot has coasted out of its last steps.
    const from = this.recent.find((s) => s.t >= Math.max(at.t, now.t - AFTER_WINDOW_S)) ?? at;
    const after = speedBetween(from, now);
    this.report.textContent = `Before freezing: ${metres(before)} over the last ${decimal(window, 1)} s. `
      + `Frozen for ${decimal(seconds, 1)} s: ${seconds > 0 ? `${metres(after)} over the last ${decimal(now.t - from.t, 1)} s` : '…'}. `
      + verdict(before, after, seconds);
    this.show(before, after);
  }

  /** @param {boolean} frozen */
  setFrozen(frozen) {
    this.frozen = frozen;
    this.button.textContent = frozen ? 'Release the attention' : 'Freeze the attention';
    this.button.setAttribute('aria-pressed', String(frozen));
  }

  /** @param {number} before @param {number} after the speeds shown (NaN: none), kept for tests in data- */
  show(before, after) {
    this.report.hidden = !this.report.textContent;
    this.report.dataset.before = String(before);
    this.report.dataset.after = String(after);
  }
}

/** Seconds frozen before the speeds are compared in words (a step or two of a gait). */
export const VERDICT_AFTER_S = 4;
/** Below this speed before freezing (m/s) the robot was not walking, and freezing says little. */
const WALKING = 0.2;

/** Under this share of its speed before (a tenth), frozen, it nearly stops. */
const NEARLY_STOPS = 0.1;

/**
 * What the two speeds say, in words: whether the robot needed its attention to change. A robot
 * that nearly stops rocks on the spot, its speed over the last seconds a little above or below
 * zero: one wording for all of it (no percentage that changes sign, or “stops” that turns into
 * “keeps 2%”), the words of the classroom's freeze task (“less than a tenth as fast”).
 * @param {number} before @param {number} after speeds (m/s) @param {number} seconds frozen for
 * @returns {string}
 */
export function verdict(before, after, seconds) {
  if (!(seconds >= VERDICT_AFTER_S)) return 'Watch a few seconds more…';
  if (!(before >= WALKING)) return 'It was hardly walking before, so this says little: freeze a robot while it walks.';
  if (!(after >= NEARLY_STOPS * before)) {
    return 'Frozen, it nearly stops (less than a tenth of its speed before, rocking on the spot): its changing attention is what made it walk.';
  }
  const kept = Math.round((100 * after) / before);
  if (kept < 34) return `Frozen, it keeps only ${kept}% of its speed: its changing attention is what made it walk.`;
  if (kept < 80) return `Frozen, it keeps ${kept}% of its speed: its changing attention helps, but it walks partly without it.`;
  return `Frozen, it keeps ${kept}% of its speed: this robot walks about as well without changing its attention.`;
}

/** @param {number} v a speed (m/s) @returns {string} */
function metres(v) {
  return Number.isFinite(v) ? `${decimal(v)} m/s` : NONE;
}

/**
 * The centre's forward speed between two samples (m/s): distance over time.
 * @param {Sample} from @param {Sample} to
 */
export function speedBetween(from, to) {
  return to.t > from.t ? (to.x - from.x) / (to.t - from.t) : NaN;
}
