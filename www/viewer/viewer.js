// @ts-check
/**
 * The viewer: the simulation worker that walks the robot, the scene canvas, the live
 * figures and the attention maps (one of them read enlarged), with Play / Hold / Restart,
 * Freeze the attention, speed and terrain. It shows
 * whatever body and brain the page gives it; the worker answers 'loaded' or 'error' and a
 * refused load leaves the previous robot walking. Its terrain is a typed field (shared/typed-field.js):
 * a terrain the core refuses stays typed, said in a student's words, and the robot walks on
 * the last one accepted. Messages: workers/protocol.js.
 */
import { AttentionPanel } from './attention.js';
import { AttentionReader } from './attention-reader.js';
import { checkTerrain } from '../workers/core.js';
import { byId } from '../shared/dom.js';
import { familyName, hasAttention } from '../shared/families.js';
import { FreezeControl } from './freeze.js';
import { spawn } from '../workers/kit.js';
import { FromWorker, ToWorker, frameIsConsistent } from '../workers/protocol.js';
import { Readout } from './readout.js';
import { Renderer } from './renderer.js';
import { terrainRefused } from './terrain-words.js';
import { TypedField } from '../shared/typed-field.js';

/** Workers restarted after a crash before the page gives up. */
const MAX_RESTARTS = 3;

/**
 * @typedef {object} ViewerHooks
 * @property {(text: string) => void} message  shows an error
 * @property {import('../shared/message.js').MessageBox} messages  where a terrain typed is refused
 * @property {(pick: {voxel: number, dx: number, dy: number}) => void} clicked  a click on or next to a voxel
 * @property {() => void} missed  a click on the scene neither on nor next to a voxel
 */

export class Viewer {
  /** @param {Document} doc @param {ViewerHooks} hooks */
  constructor(doc, hooks) {
    this.hooks = hooks;
    this.canvas = byId(doc, 'scene', HTMLCanvasElement);
    this.renderer = new Renderer(this.canvas);
    /**
     * The hold at an episode's end: whether every walk holds there ({@link Viewer#holdAtEnd}),
     * and whether this walk is held there now (a new walk, Play or Restart goes on). The readout
     * reads it for its words.
     */
    this.hold = { atEnd: false, now: false };
    this.readout = new Readout(doc, this.hold);
    this.attention = new AttentionPanel(byId(doc, 'attention-panel'), byId(doc, 'attention', HTMLCanvasElement));
    this.reader = new AttentionReader(doc, (voxel) => { this.renderer.highlight = voxel; this.attention.selected = voxel; this.attention.dirty = true; });
    this.freeze = new FreezeControl(doc, (frozen) => this.worker.postMessage({ type: ToWorker.FREEZE, frozen }));
    this.status = byId(doc, 'status');
    this.buttons = {
      play: byId(doc, 'sim-play', HTMLButtonElement), hold: byId(doc, 'sim-hold', HTMLButtonElement),
      restart: byId(doc, 'sim-restart', HTMLButtonElement),
    };
    this.speed = byId(doc, 'speed', HTMLSelectElement);
    /** The terrain: its `value` is the one walked on, whatever is typed. */
    this.terrain = new TypedField(byId(doc, 'terrain', HTMLInputElement), hooks.messages, {
      problem: async (text) => { const rule = await checkTerrain(text); return rule && terrainRefused(text, rule); },
      use: () => this.reload(),
    });
    this.gait = { frequency: byId(doc, 'frequency', HTMLInputElement), phase: byId(doc, 'phase', HTMLInputElement) };
    /** The episode the worker runs now (the last one that loaded). @type {import('../workers/protocol.js').LoadedParams | null} */
    this.current = null;
    /** The episode asked for last (kept across a worker restart). @type {import('../workers/protocol.js').EpisodeParams | null} */
    this.wanted = null;
    this.running = true;
    this.restarts = 0;
    this.worker = this.startWorker();
    this.wire();
    requestAnimationFrame(/** @this {Viewer} @param {number} now */ function loop(now) {
      this.renderer.draw(now);
      this.attention.draw();
      requestAnimationFrame(loop.bind(this));
    }.bind(this));
  }

  wire() {
    const { buttons } = this;
    buttons.play.addEventListener('click', () => { this.held(false); this.worker.postMessage({ type: ToWorker.START }); });
    buttons.hold.addEventListener('click', () => this.worker.postMessage({ type: ToWorker.PAUSE }));
    buttons.restart.addEventListener('click', () => { this.worker.postMessage({ type: ToWorker.RESET }); this.goOn(); });
    this.speed.addEventListener('change', () => this.worker.postMessage({ type: ToWorker.SPEED, speed: Number(this.speed.value) }));
    for (const input of Object.values(this.gait)) input.addEventListener('change', () => this.reload());
    this.canvas.addEventListener('click', (e) => {
      const pick = this.renderer.pick(e.clientX, e.clientY);
      if (pick) this.hooks.clicked(pick); else this.hooks.missed();
    });
    this.attention.canvas.addEventListener('click', (e) => {
      const voxel = this.attention.pick(e.clientX, e.clientY);
      if (voxel >= 0) this.reader.open(voxel, this.attention.cells[2 * voxel], this.attention.cells[2 * voxel + 1]);
    });
  }

  /** Walks the robot again from the start (the terrain or the gait changed). */
  reload() {
    if (this.wanted) this.show(this.wanted.shape, this.wanted.brain, false);
  }

  /** @returns {import('../workers/kit.js').WorkerOf<'workers/simulation-worker.js'>} a new simulation worker, told to load the wanted episode */
  startWorker() {
    const w = spawn('workers/simulation-worker.js', (msg) => this.onMessage(msg), () => this.onError('The simulation worker crashed; a new one took over.', true));
    w.postMessage({ type: ToWorker.SPEED, speed: Number(this.speed.value) });
    if (this.wanted) w.postMessage({ type: ToWorker.LOAD, params: this.wanted });
    if (this.running) w.postMessage({ type: ToWorker.START });
    return w;
  }

  /**
   * Walks `rows` driven by `brain` (or the phase gait when null), from the start line or, with
   * `keepPlace` (an edit's shift), in the posture and motion of the robot walking now.
   * Its speed is measured over an episode of `seconds`.
   * @param {string} rows @param {import('../workers/protocol.js').Brain | null} brain
   * @param {import('../workers/protocol.js').Shift | false} [keepPlace] @param {number} [seconds]
   */
  show(rows, brain, keepPlace = false, seconds = this.wanted?.seconds ?? NaN) {
    this.wanted = {
      shape: rows, terrain: this.terrain.value.trim(), brain, keepPlace, seconds,
      frequency: this.gait.frequency.valueAsNumber, phase: this.gait.phase.valueAsNumber,
    };
    this.worker.postMessage({ type: ToWorker.LOAD, params: this.wanted });
    this.goOn();
  }

  /**
   * Whether every walk holds when its episode ends (the tour: the robot stops where its speed
   * was measured, so what a class sees is what the numbers say), or walks on (the page's way).
   * @param {boolean} on
   */
  holdAtEnd(on) {
    this.hold.atEnd = on;
    if (!on) this.goOn();
  }

  /** Walks on if the viewer held the walk at its episode's end. */
  goOn() {
    if (!this.hold.now) return;
    this.held(false);
    this.worker.postMessage({ type: ToWorker.START });
  }

  /** Whether the viewer holds the walk at its episode's end now (the readout says so). @param {boolean} on */
  held(on) {
    this.hold.now = on;
  }

  /** The episode's length from now on, without restarting the walk. @param {number} seconds */
  setSeconds(seconds) {
    if (this.wanted) this.wanted = { ...this.wanted, seconds };
    this.readout.episode.seconds = seconds;
    this.worker.postMessage({ type: ToWorker.LENGTH, seconds });
  }

  /** @param {import('../workers/protocol.js').FromWorkerMessage} msg a message from the worker */
  onMessage(msg) {
    switch (msg.type) {
      case FromWorker.READY: this.renderer.setPhysics(msg.physics); break;
      case FromWorker.LOADED:
        this.current = msg.params;
        this.renderer.setTerrain(msg.terrainXs, msg.terrainYs, !msg.carried);
        this.attention.setLayout(msg.cells, hasAttention(msg.controller));
        this.reader.setEpisode(msg.voxels, msg.attentionTerms);
        this.freeze.loaded(msg.controller);
        this.readout.reset(msg.params, msg.carried);
        this.status.textContent = `${msg.voxels} voxels, ${familyName(msg.controller)}`;
        for (const input of Object.values(this.gait)) input.disabled = msg.params.brain !== null;
        break;
      case FromWorker.FRAME:
        if (frameIsConsistent(msg)) {
          if (this.hold.atEnd && this.running && !this.hold.now && !this.readout.ended && Number.isFinite(msg.episodeSpeed)) {
            this.held(true);
            this.worker.postMessage({ type: ToWorker.PAUSE });
          }
          this.renderer.setFrame(msg); this.readout.update(msg); this.attention.setFrame(msg);
          if (Number.isFinite(this.readout.origin)) this.renderer.origin = this.readout.origin; // the ruler reads as the distance
          this.reader.setFrame(msg.attention); this.freeze.setFrame(msg);
        }
        break;
      case FromWorker.STATE:
        this.running = msg.running;
        if (!this.running) this.readout.flush();
        this.updateButtons();
        break;
      case FromWorker.ERROR: this.onError(msg.message, msg.fatal); break;
      default: console.warn('unknown message from the simulation worker', msg);
    }
  }

  /** @param {string} text @param {boolean} fatal */
  onError(text, fatal) {
    this.hooks.message(text);
    if (!fatal) {
      const refused = this.wanted;
      this.wanted = this.current;
      // A terrain the page set (a link, a kept state) and the core refused: the one walked on instead.
      if (this.current && refused?.terrain !== this.current.terrain) this.terrain.value = this.current.terrain;
      return;
    }
    this.worker.terminate();
    if (this.restarts++ < MAX_RESTARTS) this.worker = this.startWorker();
  }

  updateButtons() {
    this.buttons.play.disabled = this.running;
    this.buttons.hold.disabled = !this.running;
    document.body.dataset.running = String(this.running);
  }
}
