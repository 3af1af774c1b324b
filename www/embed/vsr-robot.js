// @ts-check
/**
 * `<vsr-robot>`: a walking soft robot in any page, with one script tag and no build step.
 *
 *   <script type="module" src="embed/vsr-robot.js"></script>
 *   <vsr-robot shape="1111-1111-1001" module="pretrained/biped-4x3-attention.json"
 *              terrain="hilly-1-10-0"></vsr-robot>
 *
 * Attributes (each change rebuilds the robot): `shape` a body as rows, top first, or a preset
 * (`biped-4x3`); `module` a run file's URL, relative to the page (its best individual drives its
 * own body; without a module the phase gait drives `shape`); `terrain` (`flat`,
 * `hilly-1-10-0`; none: the playground's viewer terrain). The simulation runs in the
 * playground's own simulation worker (workers/simulation-worker.js), one per element, and is
 * drawn by the playground's Renderer on the element's own canvas, sized by CSS (block, 2:1 by
 * default). A click (or Enter / Space) holds the robot and plays it again; a robot out of sight
 * is paused. A wrong attribute shows the core's message in place of the robot until it is
 * fixed. For scripts: `x` (the centre's x, m), `distance` (m walked since the start), `time` (s), `velocity` (m/s,
 * as fitness defines it), `running` and `error` ('' or the message shown). docs/embed.md.
 */
import { messageOf, spawn } from '../workers/kit.js';
import { FromWorker, ToWorker, frameIsConsistent } from '../workers/protocol.js';
import { Renderer } from '../viewer/renderer.js';

/** The attributes that say which robot walks. */
const ATTRIBUTES = ['shape', 'module', 'terrain'];

const STYLE = `
:host { display: block; position: relative; aspect-ratio: 2 / 1; min-height: 6rem; overflow: hidden;
  border-radius: 6px; background: #e8f1f8; cursor: pointer; font: 0.9rem/1.4 system-ui, sans-serif; }
@supports not (aspect-ratio: 2 / 1) { :host { height: 16rem; } }
:host([hidden]) { display: none; }
:host(:focus-visible) { outline: 3px solid #2f6fb0; outline-offset: 2px; }
canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; }
.held { position: absolute; top: 0.5rem; right: 0.5rem; padding: 0.1rem 0.5rem; border-radius: 4px;
  background: rgba(255, 255, 255, 0.85); color: #223; }
.error { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
  padding: 1rem; box-sizing: border-box; background: #fff4f2; color: #8a1c12; border: 2px solid #d9534f;
  border-radius: 6px; text-align: center; overflow: auto; cursor: default; }
[hidden] { display: none !important; }
`;

export class VsrRobot extends HTMLElement {
  static get observedAttributes() { return ATTRIBUTES; }

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    const doc = this.ownerDocument;
    const style = doc.createElement('style');
    style.textContent = STYLE;
    this.canvas = doc.createElement('canvas');
    this.badge = doc.createElement('span');
    this.badge.className = 'held';
    this.badge.textContent = '▶ held: click to play';
    this.badge.hidden = true;
    this.errorBox = doc.createElement('div');
    this.errorBox.className = 'error';
    this.errorBox.setAttribute('role', 'alert');
    this.errorBox.hidden = true;
    root.append(style, this.canvas, this.badge, this.errorBox);
    this.renderer = new Renderer(this.canvas);
    /** @type {import('../workers/kit.js').WorkerOf<'workers/simulation-worker.js'> | null} */
    this.worker = null;
    /** Which load the answers belong to: a newer attribute change makes older fetches moot. */
    this.generation = 0;
    this.held = matchMedia('(prefers-reduced-motion: reduce)').matches;
    this.visible = true;
    this.loaded = false;
    this.running = false;
    this.dirty = false;
    this.error = '';
    this.x = NaN;
    this.time = NaN;
    this.velocity = NaN;
    this.distance = NaN;
    this.frameRequest = 0;
    this.pending = false;
    this.addEventListener('click', (e) => { if (!this.error) { e.preventDefault(); this.toggle(); } });
    this.addEventListener('keydown', (e) => {
      if ((e.key === 'Enter' || e.key === ' ') && !this.error) { e.preventDefault(); this.toggle(); }
    });
    this.visibility = typeof IntersectionObserver === 'function'
      ? new IntersectionObserver((entries) => {
        this.visible = entries[entries.length - 1].isIntersecting;
        this.pace();
      })
      : null;
  }

  connectedCallback() {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'button');
    this.visibility?.observe(this);
    const loop = (/** @type {number} */ now) => { this.draw(now); this.frameRequest = requestAnimationFrame(loop); };
    this.frameRequest = requestAnimationFrame(loop);
    this.reload();
  }

  disconnectedCallback() {
    cancelAnimationFrame(this.frameRequest);
    this.visibility?.disconnect();
    this.worker?.terminate();
    this.worker = null;
    this.generation++;
  }

  attributeChangedCallback() {
    if (this.isConnected) this.reload();
  }

  /** Rebuilds the robot once, however many attributes changed together. */
  reload() {
    if (this.pending) return;
    this.pending = true;
    queueMicrotask(() => { this.pending = false; if (this.isConnected) this.load(); });
  }

  async load() {
    const generation = ++this.generation;
    const shape = (this.getAttribute('shape') ?? '').trim();
    const module = (this.getAttribute('module') ?? '').trim();
    const terrain = this.getAttribute('terrain');
    this.setAttribute('aria-label', `A soft robot${shape ? ` (${shape})` : ''} walking${terrain ? ` on ${terrain}` : ''}: press to hold or play`);
    if (!shape && !module) {
      this.fail('no robot: give a shape (rows, top first, such as shape="1111-1111-1001", or a preset such as shape="biped-4x3") or a module file (module="...json")');
      return;
    }
    /** @type {import('../workers/protocol.js').EpisodeParams} */
    const params = { shape, brain: null };
    if (terrain !== null) params.terrain = terrain.trim();
    if (module) {
      try {
        params.runFile = await read(new URL(module, this.ownerDocument.baseURI));
      } catch (error) {
        if (generation === this.generation) this.fail(`could not read the module file "${module}": ${messageOf(error)}`);
        return;
      }
      if (generation !== this.generation) return;
    }
    this.ensureWorker().postMessage({ type: ToWorker.LOAD, params });
  }

  /** @returns {import('../workers/kit.js').WorkerOf<'workers/simulation-worker.js'>} this element's simulation worker, started if needed */
  ensureWorker() {
    if (this.worker) return this.worker;
    const worker = spawn('workers/simulation-worker.js', (msg) => { if (this.worker === worker) this.onMessage(msg); },
      (text) => { if (this.worker === worker) this.crashed(text); });
    this.worker = worker;
    this.loaded = false;
    return worker;
  }

  /** @param {import('../workers/protocol.js').FromWorkerMessage} msg a message from the simulation worker */
  onMessage(msg) {
    switch (msg.type) {
      case FromWorker.READY: this.renderer.setPhysics(msg.physics); break;
      case FromWorker.LOADED:
        this.loaded = true;
        this.show('');
        this.renderer.setTerrain(msg.terrainXs, msg.terrainYs, true);
        this.pace();
        break;
      case FromWorker.FRAME:
        if (!frameIsConsistent(msg)) break;
        this.renderer.setFrame(msg);
        this.dirty = true;
        this.x = msg.centreX;
        this.time = msg.time;
        this.velocity = msg.velocity;
        this.distance = msg.distance;
        if (Number.isFinite(msg.distance)) this.renderer.origin = msg.centreX - msg.distance; // the ruler counts from the start
        break;
      case FromWorker.STATE: this.running = msg.running; break;
      case FromWorker.ERROR:
        if (msg.fatal) this.crashed(msg.message);
        else this.fail(msg.message);
        break;
      default: break;
    }
  }

  /** Shows `text` in place of the robot and stops stepping. @param {string} text */
  fail(text) {
    this.loaded = false;
    this.show(`vsr-robot: ${text}`);
    this.pace();
  }

  /** The worker died: a new one starts at the next attribute change. @param {string} text */
  crashed(text) {
    this.worker?.terminate();
    this.worker = null;
    this.running = false;
    this.fail(`the simulation stopped (${text}); change an attribute to start it again`);
  }

  /** @param {string} text the message in place of the robot, '' for the robot */
  show(text) {
    this.error = text;
    this.errorBox.textContent = text;
    this.errorBox.hidden = text === '';
    this.canvas.hidden = text !== '';
    this.badge.hidden = text !== '' || !this.held;
  }

  /** Holds a walking robot, or plays a held one. */
  toggle() {
    this.held = !this.held;
    this.badge.hidden = !this.held || this.error !== '';
    this.pace();
  }

  /** Tells the worker to step while the robot is loaded, in sight and not held. */
  pace() {
    const run = this.loaded && this.visible && !this.held;
    this.worker?.postMessage({ type: run ? ToWorker.START : ToWorker.PAUSE });
  }

  /** Draws when a new frame came or the element was resized. @param {number} now */
  draw(now) {
    const dpr = window.devicePixelRatio || 1;
    const resized = this.canvas.width !== Math.round(this.canvas.clientWidth * dpr)
      || this.canvas.height !== Math.round(this.canvas.clientHeight * dpr);
    if (!this.renderer.frame || this.error || (!this.dirty && !resized)) return;
    this.dirty = false;
    this.renderer.draw(now);
  }
}

/** A file's text, or a readable Error. @param {URL} url */
async function read(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${response.status} ${response.statusText || 'error'}`.trim());
  return response.text();
}

if (!customElements.get('vsr-robot')) customElements.define('vsr-robot', VsrRobot);
