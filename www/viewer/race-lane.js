// @ts-check
/**
 * One robot of the race: its own simulation worker (workers/simulation-worker.js, the viewer's: the wasm core
 * steps it), its own lane (a canvas drawn by a Renderer whose camera follows it) and its
 * label: the brain, its live speed (the mean forward speed since the start, as fitness
 * defines it) and the distance walked. The race (race.js) loads and starts every lane.
 */
import { spawn } from '../workers/kit.js';
import { FromWorker, ToWorker, frameIsConsistent } from '../workers/protocol.js';
import { Renderer } from './renderer.js';
import { decimal } from '../shared/format.js';

/**
 * @typedef {object} Racer  what a lane runs
 * @property {string} label       its brain, in words
 * @property {string} shape       rows
 * @property {string} controller
 * @property {Float32Array} genome
 */

export class Lane {
  /**
   * @param {HTMLElement} parent where the lane goes
   * @param {Racer} racer
   * @param {{loaded: (lane: Lane) => void, finished: (lane: Lane) => void, remove: (lane: Lane) => void,
   *   failed: (lane: Lane, text: string) => void}} hooks
   */
  constructor(parent, racer, hooks) {
    const doc = parent.ownerDocument;
    this.racer = racer;
    this.hooks = hooks;
    this.root = doc.createElement('div');
    this.root.className = 'race-robot';
    this.root.dataset.testid = 'race-robot';
    this.root.dataset.controller = racer.controller;
    const head = doc.createElement('div');
    head.className = 'race-head';
    this.name = doc.createElement('span');
    this.name.className = 'race-name';
    this.name.textContent = racer.label;
    this.speed = doc.createElement('output');
    this.speed.dataset.testid = 'race-speed';
    this.speed.title = 'Mean forward speed since the start: distance walked over time, as fitness measures it';
    this.distance = doc.createElement('output');
    this.distance.className = 'race-distance';
    const remove = doc.createElement('button');
    remove.type = 'button';
    remove.className = 'close';
    remove.textContent = '×';
    remove.title = 'Take this robot out of the race';
    remove.setAttribute('aria-label', `Take ${racer.label} out of the race`);
    remove.addEventListener('click', () => hooks.remove(this));
    this.place = doc.createElement('output');
    this.place.className = 'race-place';
    this.place.dataset.testid = 'race-place';
    this.place.title = 'Its place in the race: by distance walked from the start line';
    head.append(this.place, this.name, this.speed, this.distance, remove);
    // The race's shared scale: the bar is this robot's distance, the leader's bar is full.
    const track = doc.createElement('div');
    track.className = 'race-track';
    track.title = 'Distance walked, against the leader\'s (a full bar)';
    this.mark = doc.createElement('div');
    this.mark.className = 'race-mark';
    track.append(this.mark);
    this.canvas = doc.createElement('canvas');
    this.canvas.setAttribute('aria-label', `${racer.label} walking`);
    this.root.append(head, track, this.canvas);
    parent.append(this.root);
    this.renderer = new Renderer(this.canvas);
    this.loaded = false;
    this.finished = false;
    /** 'idle', 'started' (asked to run), 'running' (the worker said so): a stop then is the finish. */
    this.phase = 'idle';
    /** A frame came since the lane was last drawn. */
    this.dirty = true;
    /** The centre's x at the start line (m). */
    this.start = NaN;
    /** Simulated time of its latest frame (s), and the time its worker waits at (Infinity: none). */
    this.time = 0;
    this.waitingAt = Infinity;
    /** Metres walked from the start line (NaN until the robot has moved off it). */
    this.walked = NaN;
    /** Every frame's simulated time (s) and metres walked, since the start line. @type {{t: number, walked: number}[]} */
    this.track = [];
    this.worker = spawn('workers/simulation-worker.js', (msg) => this.onMessage(msg), (text) => hooks.failed(this, text));
    this.show(NaN, NaN, NaN);
  }

  /**
   * Builds the robot afresh at the start line, paused.
   * @param {string} terrain @param {number} seconds the race's length @param {number} speed simulated s per wall s
   */
  load(terrain, seconds, speed) {
    this.loaded = false;
    this.finished = false;
    this.phase = 'idle';
    this.start = NaN;
    this.track = [];
    this.time = 0;
    this.waitingAt = Infinity; // a new episode waits for nothing
    this.worker.postMessage({ type: ToWorker.PAUSE });
    this.worker.postMessage({ type: ToWorker.SPEED, speed });
    const brain = { controller: this.racer.controller, genome: this.racer.genome };
    this.worker.postMessage({ type: ToWorker.LOAD,
      params: { shape: this.racer.shape, terrain, brain, frequency: 0, phase: 0, keepPlace: false, until: seconds } });
  }

  /** @param {boolean} run */
  run(run) {
    this.phase = run ? 'started' : 'idle';
    this.worker.postMessage({ type: run ? ToWorker.START : ToWorker.PAUSE });
  }

  /** Lets it walk up to simulated time `seconds`, no further (Infinity: to the finish). @param {number} seconds */
  waitAt(seconds) {
    if (seconds === this.waitingAt) return;
    this.waitingAt = seconds;
    this.worker.postMessage({ type: ToWorker.WAIT_AT, seconds });
  }

  /** @param {import('../workers/protocol.js').FromWorkerMessage} msg */
  onMessage(msg) {
    switch (msg.type) {
      case FromWorker.READY: this.renderer.setPhysics(msg.physics); break;
      case FromWorker.LOADED:
        this.renderer.setTerrain(msg.terrainXs, msg.terrainYs, true);
        this.loaded = true;
        this.hooks.loaded(this);
        break;
      case FromWorker.FRAME:
        if (!frameIsConsistent(msg)) break;
        this.renderer.setFrame(msg);
        this.dirty = true;
        this.show(msg.velocity, msg.time, msg.centreX);
        break;
      case FromWorker.STATE:
        if (msg.running && this.phase === 'started') this.phase = 'running';
        if (!msg.running && this.phase === 'running') {
          this.phase = 'idle';
          this.finished = true;
          this.hooks.finished(this);
        }
        break;
      case FromWorker.ERROR: this.hooks.failed(this, msg.message); break;
      default: break;
    }
  }

  /** @param {number} velocity @param {number} time @param {number} x */
  show(velocity, time, x) {
    if (!Number.isFinite(this.start) || time === 0) this.start = x;
    if (Number.isFinite(this.start)) this.renderer.origin = this.start; // the ruler reads as the distance
    if (Number.isFinite(time)) this.time = time;
    this.speed.dataset.value = String(velocity);
    this.speed.dataset.time = String(time);
    this.speed.textContent = Number.isFinite(velocity) && time > 0 ? `${decimal(velocity)} m/s` : '– m/s';
    const walked = x - this.start;
    this.walked = time > 0 ? walked : NaN; // at the start line nobody has a place yet
    if (Number.isFinite(walked) && Number.isFinite(time)) {
      const last = this.track[this.track.length - 1];
      if (last && time < last.t) this.track = []; // loaded again: a new race
      if (!last || time > last.t) this.track.push({ t: time, walked });
    }
    this.distance.textContent = Number.isFinite(walked) ? `${decimal(walked, 1)} m in ${decimal(time, 1)} s` : '';
  }

  /**
   * Its standing in the race ({@link standings}): a place (0: none yet) and its share of the
   * leader's distance. @param {{place: number, share: number}} standing
   */
  stand({ place, share }) {
    this.place.dataset.value = String(place);
    this.place.textContent = place > 0 ? ordinal(place) : '';
    this.mark.style.width = `${(100 * share).toFixed(1)}%`;
    this.mark.dataset.value = String(share);
  }

  /** Draws the lane if a new frame came (a finished robot costs nothing). @param {number} now */
  draw(now) {
    if (!this.dirty && this.canvas.width === Math.round(this.canvas.clientWidth * (window.devicePixelRatio || 1))) return;
    this.dirty = false;
    this.renderer.draw(now);
  }

  dispose() {
    this.worker.terminate();
    this.root.remove();
  }
}

/**
 * The places of robots that walked `walked` metres (NaN: not started), ties sharing a place,
 * and each one's share of the leader's distance (0 when nobody went forwards yet). With a
 * single robot there is no race: no places.
 * @param {number[]} walked @returns {{place: number, share: number}[]}
 */
export function standings(walked) {
  const started = walked.filter(Number.isFinite);
  const lead = Math.max(0, ...started);
  return walked.map((w) => ({
    place: started.length > 1 && Number.isFinite(w) ? 1 + started.filter((o) => o > w).length : 0,
    share: lead > 0 && Number.isFinite(w) ? Math.max(0, w) / lead : 0,
  }));
}

/** 1st, 2nd, 3rd, 4th. @param {number} n */
function ordinal(n) {
  return `${n}${({ 1: 'st', 2: 'nd', 3: 'rd' })[n] ?? 'th'}`;
}

/**
 * Metres walked at simulated time `t` on a lane's track, between the two frames around it
 * (NaN before its first frame or after its last: it is not there yet).
 * @param {{t: number, walked: number}[]} track @param {number} t
 */
export function walkedAt(track, t) {
  const after = track.findIndex((s) => s.t >= t);
  if (after < 0) return NaN;
  const b = track[after];
  if (b.t === t || after === 0) return b.t === t ? b.walked : NaN;
  const a = track[after - 1];
  return a.walked + ((b.walked - a.walked) * (t - a.t)) / (b.t - a.t);
}
