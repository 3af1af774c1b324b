// @ts-check
/**
 * Page wiring: the controls, the controller source, the Evolve panel (evolve.js, whose
 * best individual drives the robot like any run file), the simulation worker and the
 * animation loop. The worker owns the simulation; this thread only sends commands and
 * draws the latest frame it received (see protocol.js for the messages).
 */
import { AttentionPanel } from './attention.js';
import { EvolvePanel } from './evolve.js';
import { DEFAULT_PARAMS, FromWorker, SHAPE_PRESETS, ToWorker, frameIsConsistent } from './protocol.js';
import { Readout } from './readout.js';
import { Renderer } from './renderer.js';
import { SourcePicker } from './sources.js';

/** Workers restarted after a crash before the page gives up. */
const MAX_RESTARTS = 3;

const form = /** @type {HTMLFormElement} */ (byId('controls'));
const inputs = {
  shape: /** @type {HTMLInputElement} */ (byId('shape')),
  terrain: /** @type {HTMLInputElement} */ (byId('terrain')),
  frequency: /** @type {HTMLInputElement} */ (byId('frequency')),
  phase: /** @type {HTMLInputElement} */ (byId('phase')),
};
const speedSelect = /** @type {HTMLSelectElement} */ (byId('speed'));
const buttons = { start: byId('start'), pause: byId('pause'), reset: byId('reset') };
const message = byId('message');
const status = byId('status');
const renderer = new Renderer(/** @type {HTMLCanvasElement} */ (byId('scene')));
const readout = new Readout(document);
const attention = new AttentionPanel(byId('attention-panel'), /** @type {HTMLCanvasElement} */ (byId('attention')));
const picker = new SourcePicker(/** @type {HTMLSelectElement} */ (byId('source')),
  /** @type {HTMLInputElement} */ (byId('run-file')), pickSource, showMessage);
/** Picker key of the evolved best (one option, relabelled at each switch). */
const EVOLVED_KEY = 'evolved';
new EvolvePanel(document, {
  shape: () => inputs.shape.value.trim(),
  watch: (text, label) => pickSource({ key: EVOLVED_KEY, label, text }),
  message: showMessage,
});

/** Parameters of the episode the worker runs now (the last one that loaded). */
/** @type {import('./protocol.js').EpisodeParams} */
let current = { ...DEFAULT_PARAMS };
let running = true;
let restarts = 0;
let worker = startWorker();

/** @returns {Worker} a new simulation worker, told to load `current` */
function startWorker() {
  const w = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  w.onmessage = (event) => onWorkerMessage(event.data);
  w.onerror = (event) => showMessage(`the simulation worker failed: ${event.message || 'see the console'}`);
  w.postMessage({ type: ToWorker.SPEED, speed: Number(speedSelect.value) });
  w.postMessage({ type: ToWorker.LOAD, params: current });
  if (running) w.postMessage({ type: ToWorker.START });
  return w;
}

/** @param {any} msg a message from the worker */
function onWorkerMessage(msg) {
  switch (msg.type) {
    case FromWorker.READY: setStatus('ready'); break;
    case FromWorker.LOADED:
      current = msg.params;
      renderer.setTerrain(msg.terrainXs, msg.terrainYs);
      attention.setLayout(msg.cells);
      readout.reset();
      showSource();
      setStatus(`${msg.voxels} voxels, ${msg.controller}`);
      break;
    case FromWorker.FRAME:
      if (frameIsConsistent(msg)) { renderer.setFrame(msg); readout.update(msg); attention.setFrame(msg); }
      break;
    case FromWorker.STATE: running = msg.running; updateButtons(); break;
    case FromWorker.ERROR: onWorkerError(msg.message, msg.fatal); break;
    default: console.warn('unknown message from the worker', msg);
  }
}

/** @param {string} text @param {boolean} fatal */
function onWorkerError(text, fatal) {
  showMessage(text);
  picker.show(current.runFile); // a refused source must not look chosen
  if (!fatal) return;
  worker.terminate();
  if (restarts++ < MAX_RESTARTS) worker = startWorker();
}

/** @returns {import('./protocol.js').EpisodeParams} the parameters typed in the form */
function formParams() {
  return {
    shape: inputs.shape.value.trim(),
    terrain: inputs.terrain.value.trim(),
    frequency: inputs.frequency.valueAsNumber,
    phase: inputs.phase.valueAsNumber,
    runFile: current.runFile,
  };
}

/** Asks the worker for the episode in the form; it answers 'loaded' or 'error'. */
function applyForm() {
  showMessage('');
  worker.postMessage({ type: ToWorker.LOAD, params: formParams() });
}

/**
 * Drives the robot with a new source: a run file on its own shape, or the phase gait
 * on the shape in the form.
 * @param {import('./protocol.js').RunFileSource | null} runFile
 */
function pickSource(runFile) {
  showMessage('');
  const params = { ...formParams(), runFile, shape: runFile ? '' : inputs.shape.value.trim() };
  worker.postMessage({ type: ToWorker.LOAD, params });
}

/** Shows the source of the running episode: the picker, its shape, and the gait fields' use. */
function showSource() {
  picker.show(current.runFile);
  inputs.shape.value = current.shape;
  for (const input of [inputs.frequency, inputs.phase]) input.disabled = current.runFile !== null;
}

/** @param {string} text an error for the person, or '' to clear it */
function showMessage(text) {
  message.textContent = text;
  message.hidden = text === '';
}

/** @param {string} text */
function setStatus(text) {
  status.textContent = text;
}

function updateButtons() {
  buttons.start.toggleAttribute('disabled', running);
  buttons.pause.toggleAttribute('disabled', !running);
  document.body.dataset.running = String(running);
}

/** @param {string} id */
function byId(id) {
  const el = document.getElementById(id);
  if (!el) throw new Error(`the page has no #${id}`);
  return el;
}

function fillPresets() {
  const list = byId('shape-presets');
  for (const preset of SHAPE_PRESETS) list.append(new Option(preset));
  inputs.shape.value = DEFAULT_PARAMS.shape;
  inputs.terrain.value = DEFAULT_PARAMS.terrain;
  inputs.frequency.value = String(DEFAULT_PARAMS.frequency);
  inputs.phase.value = String(DEFAULT_PARAMS.phase);
}

fillPresets();
updateButtons();
// Enter in a field commits it, which fires 'change'; submitting must not load twice.
form.addEventListener('submit', (event) => event.preventDefault());
for (const input of Object.values(inputs)) input.addEventListener('change', applyForm);
inputs.shape.addEventListener('input', () => {
  if (SHAPE_PRESETS.includes(inputs.shape.value)) applyForm();
});
speedSelect.addEventListener('change', () => worker.postMessage({ type: ToWorker.SPEED, speed: Number(speedSelect.value) }));
buttons.start.addEventListener('click', () => worker.postMessage({ type: ToWorker.START }));
buttons.pause.addEventListener('click', () => worker.postMessage({ type: ToWorker.PAUSE }));
buttons.reset.addEventListener('click', () => { showMessage(''); worker.postMessage({ type: ToWorker.RESET }); });
requestAnimationFrame(function loop(now) {
  renderer.draw(now);
  attention.draw();
  requestAnimationFrame(loop);
});
picker.listPretrained();
