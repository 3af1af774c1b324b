// @ts-check
/**
 * The live figures under the canvas: simulated time, the robot's distance from its start,
 * its speed, its pace over the last second, and the speed of the simulation. Distance and
 * speed are the core's, the fitness's own measure (workers/protocol.js, Frame): the speed is the
 * mean forward velocity since the start and, once the episode's length is reached, over the
 * whole episode, the number training and `vsr evaluate` compute. After an edit of the walking
 * robot the distance runs on from where it was; the speed counts from the edit. Each <output>
 * also carries its raw number in `data-value` so that tests read numbers, not formatted text.
 */
import { byId } from '../shared/dom.js';
import { decimal } from '../shared/format.js';

/** Window over which the velocity is measured (simulated s). */
const VELOCITY_WINDOW_S = 1;
/** Least wall time between two updates of the figures (ms). */
const SHOW_INTERVAL_MS = 200;

export class Readout {
  /**
   * @param {Document} doc
   * @param {{ atEnd: boolean, now: boolean }} hold the viewer's hold at the episode's end (whether
   *   a walk holds there, and whether it holds now): read here for the words after the clock
   */
  constructor(doc, hold) {
    this.fields = {
      time: byId(doc, 'sim-time'),
      x: byId(doc, 'robot-x'),
      velocity: byId(doc, 'robot-v'),
      speed: byId(doc, 'robot-speed'),
      simPerWall: byId(doc, 'sim-rate'),
      simPerCompute: byId(doc, 'engine-rate'),
    };
    /** Recent (time, x) samples, oldest first. @type {{t: number, x: number}[]} */
    this.history = [];
    /** When the figures were last written (ms). */
    this.shownAt = -Infinity;
    /** The latest frame received. @type {import('../workers/protocol.js').Frame | null} */
    this.latest = null;
    /**
     * The episode walking: its length (none: not measured over one) and terrain, and whether it went on from an edit.
     * @type {{seconds: number | undefined, terrain: string, edited: boolean}}
     */
    this.episode = { seconds: NaN, terrain: '', edited: false };
    /**
     * Where the walk started: the centre's x after the first step of its first episode (m),
     * NaN until then. Edits of the walking robot keep it, so the distance runs on across them.
     */
    this.origin = NaN;
    this.hold = hold;
  }

  /**
   * A new episode starts: forgets the pace history; an edit of the walking robot (`carried`)
   * keeps where the walk started.
   * @param {import('../workers/protocol.js').LoadedParams} params @param {boolean} carried
   */
  reset(params, carried) {
    if (!carried) this.origin = NaN;
    this.episode = { seconds: params.seconds, terrain: params.terrain, edited: carried };
    this.history = [];
    this.latest = null;
    this.shownAt = -Infinity;
  }

  /** @param {import('../workers/protocol.js').Frame} frame */
  update(frame) {
    const last = this.history[this.history.length - 1];
    if (last && frame.time < last.t) this.history = [];
    this.history.push({ t: frame.time, x: frame.centreX });
    while (this.history.length > 2 && frame.time - this.history[1].t >= VELOCITY_WINDOW_S) this.history.shift();
    // Text changes make the browser lay the page out again: a few times a second is enough.
    this.latest = frame;
    const now = performance.now();
    if (now - this.shownAt < SHOW_INTERVAL_MS) return;
    this.shownAt = now;
    this.write(frame);
  }

  /** Whether the episode walking now is over (its speed is the episode's). */
  get ended() {
    return Number.isFinite(this.latest?.episodeSpeed);
  }

  /** Shows the latest frame now (the simulation stopped: its last state must be on screen). */
  flush() {
    if (this.latest) this.write(this.latest);
  }

  /** Writes a frame's figures. @param {import('../workers/protocol.js').Frame} frame */
  write(frame) {
    const first = this.history[0];
    const velocity = frame.time > first.t ? (frame.centreX - first.x) / (frame.time - first.t) : NaN;
    const { seconds, terrain, edited } = this.episode;
    // A fresh walk's distance is the core's; an edited robot's runs on from the walk's start.
    if (!this.episode.edited) this.origin = frame.centreX - frame.distance;
    const x = this.episode.edited && Number.isFinite(this.origin) ? frame.centreX - this.origin : frame.distance;
    const ended = Number.isFinite(frame.episodeSpeed);
    // Past the episode the clock runs on: said beside it, so "275 s" never stands against "10-s episode".
    show(this.fields.time, frame.time, ended ? `${decimal(frame.time)} s (its ${seconds}-s episode is over; ${this.hold.now ? 'Play walks on, Restart walks it again' : this.hold.atEnd ? 'walking on past it; Restart walks it again' : 'it walks on'})`
      : `${decimal(frame.time)} s`);
    show(this.fields.x, x, `${decimal(x)} m`);
    const speed = ended ? frame.episodeSpeed : frame.velocity;
    const over = edited ? `since the edit, ${seconds}-s episode` : `${seconds}-s episode`;
    show(this.fields.speed, speed, ended
      ? `${decimal(speed)} m/s over its ${over} on ${terrain}`
      : `${decimal(speed)} m/s so far (${over} on ${terrain})`);
    this.fields.speed.dataset.ended = String(ended);
    show(this.fields.velocity, velocity, `${decimal(velocity)} m/s`);
    show(this.fields.simPerWall, frame.simPerWall, `${decimal(frame.simPerWall)}x`);
    show(this.fields.simPerCompute, frame.simPerCompute, `${Math.round(frame.simPerCompute)}x`);
  }
}

/**
 * A figure, or a dash while it has no value (before the first frame, a pace while the walk is
 * held): never "…", which reads as a figure still coming.
 * @param {HTMLElement} el @param {number} value @param {string} text
 */
function show(el, value, text) {
  el.dataset.value = String(value);
  el.textContent = Number.isFinite(value) ? text : '–';
}
