// @ts-check
/**
 * Page wiring. The drawing is the one source of truth for the body: the editor draws it,
 * the viewer walks it, and runs evolve it. The brain (a controller family and its genome
 * for the drawn body) drives it: none (the phase gait), a transplanted module, an evolved
 * best, or the genome of a shared link. When the body changes, the brain's genome follows
 * it by grid position (the core's remap). The state is kept across reloads and can be
 * shared as a link.
 */
import { bestSoFar, followEdit, ownBody, runResult, transplanted } from './brain.js';
import { checkShape, ready } from './core.js';
import { Drawing } from './drawing.js';
import { Editor } from './editor.js';
import { messageOf } from './kit.js';
import { MessageBox, plain } from './message.js';
import { ModuleList } from './modules.js';
import { SENSOR_NAMES } from './protocol.js';
import { Race } from './race.js';
import { RunPanel } from './run-panel.js';
import { Keeper } from './keeper.js';
import { Measurer } from './measure.js';
import { SpeedNote } from './speed-note.js';
import { StudyPanel } from './tour/study.js';
import { Tour } from './tour/tour.js';
import { Viewer } from './viewer.js';

/** Least wall time between two switches of the viewer to a newer best (ms). */
const FOLLOW_INTERVAL_MS = 3000;

/** @typedef {import('./brain.js').Brain} Brain */

const el = (/** @type {string} */ id) => /** @type {any} */ (document.getElementById(id));
const messages = new MessageBox(el('message'), el('message-text'), el('message-close'));
const defaults = await ready.catch((error) => {
  messages.show(`The simulator could not load: ${messageOf(error)}`);
  throw error;
});
const drawing = new Drawing(defaults.grid.width, defaults.grid.height);
const rowsInput = /** @type {HTMLInputElement} */ (el('rows'));
const controllerSelect = /** @type {HTMLSelectElement} */ (el('controller'));
const presetSelect = /** @type {HTMLSelectElement} */ (el('preset'));
/** @type {Brain | null} */
let brain = null;
/** The last check of the drawing. @type {import('./core.js').ShapeCheck} */
let check = checkShape('');
let edits = 0;
/**
 * The next body change is an edit of the walking robot: rebuild it where it stands, in its
 * posture and motion; the edit's shift of the bounding box, or false.
 * @type {import('./protocol.js').Shift | false}
 */
let keepPlace = false;
/** A brain set aside by choosing another controller family, back if that family is chosen again. @type {Brain | null} */
let shelved = null;
let running = false;
let follow = { last: -Infinity, timer: 0, pending: /** @type {(() => void) | null} */ (null) };

const editor = new Editor(el('editor'), drawing, {
  onPaint: () => updateCheck(),
  onStroke: () => bodyChanged(),
  onLocked: () => messages.show('A run is using this robot: pause or stop it to edit the drawing.', 'note'),
});
const viewer = new Viewer(document, {
  message: showMessage,
  loaded: () => messages.clear('error'),
  clicked: (pick) => editWalking(pick),
});
const keeper = new Keeper(defaults, el('share-link'), {
  state: pageState,
  apply: restore,
  shown: () => `${drawing.rows()} (${check.voxels} voxels) driven by ${brain ? brain.label : 'the phase gait'}`,
  running: () => running,
  say: (text, kind = 'error') => messages.show(text, kind),
});
const speedNote = new SpeedNote(el('speed-note'), new Measurer(defaults.viewNoiseSeed));
const modules = new ModuleList(document, { loadOnto: loadModule, openOwn: openModule, message: showMessage }, defaults.attentionGenes);
const race = new Race(document, { module: () => modules.selected(), terrain: () => viewer.terrain.value.trim(), message: showMessage });
const runs = new RunPanel(document, defaults, {
  body: () => ({ rows: drawing.rows(), ok: check.ok }),
  controller: () => controllerSelect.value,
  source: () => (brain && brain.controller === 'attention' ? brain.source : null),
  best: onBest,
  finished: onFinished,
  generation: (top, generation, settings, kind, mode) => race.keepGeneration(top, generation, settings, kind, mode),
  running: (on) => {
    running = on;
    editor.setLocked(on);
    updateButtons();
    if (!on) speedNote.show(brain, viewer.terrain.value.trim(), episodeSeconds()); // measured once the workers are free
  },
  message: showMessage,
  note: (text) => messages.show(text, 'note'),
});

/** @param {string} text an error for the person, or '' to clear it */
function showMessage(text) {
  messages.show(text, 'error');
}

/** Validation of the drawing, shown in the message area too. @param {string} text */
function showValidation(text) {
  if (text) messages.show(text, 'validation'); else messages.clear('validation', 'error');
}

/** Re-checks the drawing: words, pieces, parameter count, buttons. */
function updateCheck() {
  const rows = drawing.rows();
  check = checkShape(rows);
  editor.setPieces(check.ok ? null : check.pieces);
  rowsInput.value = rows;
  const status = el('shape-status');
  if (check.ok) {
    status.textContent = `${check.voxels} voxel${check.voxels === 1 ? '' : 's'} · ${rows}`;
    showValidation('');
  } else {
    const pieces = check.pieces.length > 1 ? `; each of its ${check.pieces.length} pieces has its own colour` : '';
    status.textContent = check.pieces.length > 1 ? `Not a robot yet: ${check.pieces.length} separate pieces` : 'Not a robot yet: no voxels';
    showValidation(`Your drawing is not a robot yet: ${plain(check.message)}${pieces}. Evolve and Fine-tune are off until it is.`);
  }
  status.dataset.ok = String(check.ok);
  presetSelect.value = defaults.presets.find((p) => p.rows === rows)?.rows ?? '';
  updateParams();
  updateButtons();
}

function updateParams() {
  const kind = controllerSelect.value;
  const genes = check.params.find(([k]) => k === kind)?.[1] ?? 0;
  const n = check.voxels;
  const detail = kind === 'attention' && n > 0
    ? `: ${defaults.attentionGenes} for the attention block, shared by every voxel, and ${genes - defaults.attentionGenes} for the outputs, `
      + `one set of weights per voxel position (each voxel adds ${SENSOR_NAMES.length}, one per sensor)` : '';
  el('param-count').textContent = n > 0 ? `${genes} genes${detail}` : '';
  el('param-count').title = 'Genes: the numbers evolution changes. Every voxel runs the same small network; '
    + 'what differs between voxels is only the output weights of its position.';
  el('param-count').dataset.value = String(genes);
}

function updateButtons() {
  el('undo').disabled = running || !drawing.canUndo;
  el('redo').disabled = running || !drawing.canRedo;
  el('clear').disabled = running;
  presetSelect.disabled = running;
  rowsInput.disabled = running;
  el('module-load').disabled = running || !check.ok;
  el('module-open').disabled = running;
  runs.update();
}

/** The drawing's place on the grid (its bottom-left cell). */
function origin() {
  const box = drawing.box();
  return box ? { left: box.left, bottom: box.bottom } : { left: 0, bottom: 0 };
}

/** The drawing changed (a stroke, undo, a preset, typed rows, an edit of the walking robot). */
function bodyChanged() {
  updateCheck();
  if (!check.ok) { keeper.schedule(); return; }
  const rows = drawing.rows();
  if (brain && brain.rows !== rows) {
    try {
      brain = followEdit(brain, rows, origin(), seed(), ++edits);
    } catch (error) {
      showMessage(`the controller could not follow the edit: ${messageOf(error)}`);
      brain = null;
    }
  } else if (brain) {
    brain = { ...brain, origin: origin() };
  }
  showBrain();
  keeper.schedule();
}

/** Sends the drawing and its brain to the viewer and says what drives it. */
function showBrain() {
  if (brain) { controllerSelect.value = brain.controller; shelved = null; }
  updateParams();
  const seconds = episodeSeconds();
  viewer.show(drawing.rows(), brain ? { controller: brain.controller, genome: brain.genome } : null, keepPlace, seconds);
  speedNote.show(brain, viewer.terrain.value.trim(), seconds, !running);
  runs.showWalking(brain?.run === true);
  el('gait').hidden = brain !== null; // its settings drive only a robot with no brain
  keepPlace = false;
  el('driver').textContent = brain
    ? `Driven by: ${brain.label} (${brain.controller}, ${brain.genome.length} genes).`
    : 'Driven by: the phase gait (no brain yet: evolve one, or load a module).';
  updateButtons();
}

/** The viewer's episode (s): the one its brain was trained on, else the run settings'. */
function episodeSeconds() {
  const typed = Number(runs.inputs.seconds.value);
  return brain?.seconds ?? (typed > 0 && typed <= 3600 ? typed : defaults.quick.seconds);
}

/**
 * Another controller family was chosen: the robot's brain belongs to one family, so a brain of
 * another family is set aside (the phase gait drives the robot until a run gives it one), and
 * comes back when its family is chosen again.
 */
function controllerChosen() {
  const kind = controllerSelect.value;
  if (brain && brain.controller !== kind) {
    const aside = brain;
    brain = null;
    showBrain();
    shelved = aside;
    messages.show(`The ${aside.controller} brain is set aside (choose ${aside.controller} again to get it back); `
      + `the phase gait drives the robot until you evolve a ${kind} controller.`, 'note');
  } else if (!brain && shelved && shelved.controller === kind && shelved.rows === drawing.rows()) {
    brain = shelved;
    showBrain();
  }
  updateParams();
  keeper.schedule();
}

/** @returns {number} the run seed in the form (0 when not a number) */
function seed() {
  const s = Number(runs.inputs.seed.value);
  return Number.isSafeInteger(s) && s >= 0 ? s : 0;
}

/** A click on the walking robot: remove that voxel, or add one next to it. @param {{voxel: number, dx: number, dy: number}} pick */
function editWalking(pick) {
  if (running) { messages.show('A run is using this robot: stop it to edit the robot.', 'note'); return; }
  const box = drawing.box();
  if (!box || !check.ok) return;
  const cells = [];
  for (let y = box.bottom; y <= box.top; y++) for (let x = box.left; x <= box.right; x++) if (drawing.has(x, y)) cells.push([x, y]);
  const cell = cells[pick.voxel];
  if (!cell) return;
  const [x, y] = [cell[0] + pick.dx, cell[1] + pick.dy];
  const adding = pick.dx !== 0 || pick.dy !== 0;
  if (!drawing.inside(x, y)) { showMessage('that cell is outside the drawing grid'); return; }
  if (adding && drawing.has(x, y)) return;
  const after = checkShape(drawing.rowsWith(x, y, adding));
  if (!after.ok) {
    showMessage(after.pieces.length === 0 ? 'A robot needs at least one voxel; not done'
      : `Removing that voxel would split the robot into ${after.pieces.length} pieces; not done`);
    return;
  }
  const from = drawing.rows();
  drawing.set(x, y, adding);
  const moved = drawing.box();
  keepPlace = moved ? { from, dx: box.left - moved.left, dy: box.bottom - moved.bottom } : false;
  editor.draw();
  bodyChanged();
}

/** Puts a module on the drawn robot (the core's transplant for attention). @param {import('./modules.js').Module} module */
function loadModule(module) {
  if (!check.ok) { showMessage('draw a valid robot first'); return; }
  try {
    brain = transplanted(module, drawing.rows(), origin(), seed());
    showMessage('');
    showBrain();
    keeper.schedule();
  } catch (error) {
    showMessage(messageOf(error));
  }
}

/** Replaces the drawing by the module's own body and genome. @param {import('./modules.js').Module} module */
function openModule(module) {
  try {
    const next = ownBody(module, { left: 0, bottom: 0 }); // drawn at the bottom-left
    const problem = drawing.setRows(next.rows);
    if (problem) { showMessage(`this module's body does not fit the grid: ${problem}`); return; }
    brain = next;
    showMessage('');
    editor.draw();
    bodyChanged();
  } catch (error) {
    showMessage(messageOf(error));
  }
}

/**
 * A new best seen during a run ("walk the best so far"): it drives the robot, at most every
 * few seconds so that each one walks a while.
 * @param {Float32Array} genome @param {number} fitness
 * @param {import('./protocol.js').EvolveSettings} settings @param {string} kind
 */
function onBest(genome, fitness, settings, kind) {
  const apply = () => {
    follow.last = performance.now();
    follow.pending = null;
    if (settings.shape !== drawing.rows()) return;
    brain = bestSoFar(genome, fitness, settings, kind, runs.mode === 'finetune', brain?.source ?? null, origin());
    showBrain();
    keeper.schedule();
  };
  window.clearTimeout(follow.timer);
  const wait = follow.last + FOLLOW_INTERVAL_MS - performance.now();
  if (wait <= 0) { apply(); return; }
  follow.pending = apply;
  follow.timer = window.setTimeout(() => follow.pending?.(), wait);
}

/**
 * A run ended: its run file becomes a module (to watch, export, fine-tune further) and, with
 * "walk the best so far", its result drives the robot: the run file's best, the best of the
 * final population by its latest evaluation (what `vsr` reports and replays), which can be
 * below the best single evaluation seen on the way (fitness is re-measured on fresh terrains).
 * @param {import('./run-panel.js').FinishedRun} run
 */
function onFinished(run) {
  window.clearTimeout(follow.timer);
  follow.pending = null;
  let best;
  try {
    best = JSON.parse(run.runFile).best;
  } catch (error) {
    showMessage(`the run file could not be read: ${messageOf(error)}`);
    return;
  }
  const what = { evolve: 'evolved', finetune: 'fine-tuned', scratch: 'from scratch' }[run.mode];
  const label = `${what} ${best.controller}, seed ${run.settings.seed}: ${best.fitness.toFixed(2)} m/s`;
  try {
    const module = { key: `run:${run.mode}:${run.settings.seed}:${best.controller}:${run.settings.shape}`, label: `${label} (this page)`, text: run.runFile };
    modules.add(module, run.mode !== 'scratch'); // the comparison is listed; the fine-tuned module stays chosen
  } catch (error) {
    showMessage(`the finished run could not be listed: ${messageOf(error)}`);
  }
  const peak = Number.isFinite(run.peak) ? `; its best single evaluation on the way: ${run.peak.toFixed(2)} m/s` : '';
  const result = `the best of its last generation, ${best.fitness.toFixed(2)} m/s in training${peak}`;
  if (run.mode === 'scratch' || !run.follow || run.settings.shape !== drawing.rows()) {
    messages.show(`The run ${run.stopped ? 'stopped' : 'finished'}: its result (${result}) is in the module list.`, 'note');
    return;
  }
  brain = runResult(best, run.runFile, run.settings, origin(), `the ${what} run's result: ${result}`);
  showBrain();
  keeper.schedule();
}

/** @returns {import('./share.js').PageState} */
function pageState() {
  return {
    rows: drawing.rows(), controller: controllerSelect.value, terrain: viewer.terrain.value, run: runs.values(),
    brain: brain && brain.rows === drawing.rows()
      ? { controller: brain.controller, genome: brain.genome, label: brain.label, module: brain.module } : null,
  };
}

/**
 * Shows a state from a link or storage; a robot that does not fit the grid is refused.
 * @param {import('./share.js').PageState} state
 * @returns {Promise<string>} '' or why nothing was shown
 */
async function restore(state) {
  const problem = drawing.setRows(state.rows);
  if (problem) return problem;
  drawing.undoStack = [];
  if (defaults.controllers.includes(state.controller)) controllerSelect.value = state.controller;
  if (state.terrain) viewer.terrain.value = state.terrain;
  runs.setValues(state.run);
  brain = null;
  if (state.brain) {
    brain = { ...state.brain, rows: state.rows, origin: origin(), source: null };
    if (state.brain.module) {
      try {
        const text = await fetch(state.brain.module).then((r) => (r.ok ? r.text() : Promise.reject(new Error(`HTTP ${r.status}`))));
        brain.source = text;
      } catch (error) {
        showMessage(`the module ${state.brain.module} could not be fetched, so this robot cannot be fine-tuned: ${messageOf(error)}`);
      }
    }
  }
  editor.draw();
  bodyChanged();
  return '';
}

function wire() {
  for (const p of defaults.presets) presetSelect.append(new Option(p.name, p.rows));
  for (const c of defaults.controllers) controllerSelect.append(new Option(c));
  presetSelect.addEventListener('change', () => {
    if (!presetSelect.value) return;
    drawing.setRows(presetSelect.value);
    editor.draw();
    bodyChanged();
  });
  const undo = () => { if (!running && drawing.undo()) { editor.draw(); bodyChanged(); } };
  const redo = () => { if (!running && drawing.redo()) { editor.draw(); bodyChanged(); } };
  el('undo').addEventListener('click', undo);
  el('redo').addEventListener('click', redo);
  el('clear').addEventListener('click', () => { drawing.clear(); editor.draw(); bodyChanged(); });
  el('erase').addEventListener('click', () => {
    editor.erase = !editor.erase;
    el('erase').setAttribute('aria-pressed', String(editor.erase));
  });
  document.addEventListener('keydown', (e) => {
    const typing = e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement;
    if (typing || !(e.ctrlKey || e.metaKey)) return;
    const key = e.key.toLowerCase();
    if (key === 'z' && !e.shiftKey) { e.preventDefault(); undo(); }
    if ((key === 'z' && e.shiftKey) || key === 'y') { e.preventDefault(); redo(); }
  });
  rowsInput.addEventListener('change', () => {
    const problem = drawing.setRows(rowsInput.value.trim() || '0');
    if (problem) { showMessage(problem); rowsInput.value = drawing.rows(); return; }
    editor.draw();
    bodyChanged();
  });
  controllerSelect.addEventListener('change', controllerChosen);
  el('share').addEventListener('click', () => keeper.share());
  el('glossary-open').addEventListener('click', () => { el('glossary').open = true; el('glossary').scrollIntoView({ behavior: 'smooth' }); });
  for (const input of Object.values(runs.inputs)) input.addEventListener('change', () => keeper.schedule());
  viewer.terrain.addEventListener('change', () => { speedNote.show(brain, viewer.terrain.value.trim(), episodeSeconds()); keeper.schedule(); });
  runs.inputs.seconds.addEventListener('change', () => {
    if (brain?.seconds) return; // a trained brain walks the episodes it was trained on
    viewer.setSeconds(episodeSeconds());
    speedNote.show(brain, viewer.terrain.value.trim(), episodeSeconds());
  });
}

async function start() {
  wire();
  viewer.terrain.value = defaults.viewTerrain;
  viewer.gait.frequency.value = String(defaults.gait.frequency);
  viewer.gait.phase.value = String(defaults.gait.phase);
  await keeper.restore(() => { // a link first, else what was kept, else the first preset
    drawing.setRows(defaults.presets[0].rows);
    drawing.undoStack = [];
    editor.draw();
    bodyChanged();
  });
  modules.listPretrained().then(() => { if (brain?.module) modules.choose(brain.module); });
  window.addEventListener('hashchange', () => keeper.openLink());
  window.addEventListener('beforeunload', (event) => {
    if (running) event.preventDefault(); // the browser asks: leaving ends the run (its best so far is kept)
  });
}

/** The playground as the tour and the study panel set it up (www/tour/): the page's own functions. */
const playground = {
  defaults,
  running: () => running,
  stopRun: () => new Promise((resolve) => {
    runs.buttons.stop.click();
    const wait = () => (running ? setTimeout(wait, 50) : resolve(undefined));
    wait();
  }),
  /** @param {string} rows drawn, driven by the phase gait */
  setBody(rows) {
    const problem = drawing.setRows(rows);
    if (problem) throw new Error(problem);
    brain = null;
    shelved = null;
    editor.draw();
    bodyChanged();
  },
  module: (/** @type {string} */ key, /** @type {string | undefined} */ label) => modules.read(key, label),
  openModule,
  loadModule,
  /** @param {string} terrain @param {{frequency: number, phase: number}} gait */
  setView(terrain, gait) {
    viewer.terrain.value = terrain;
    viewer.gait.frequency.value = String(gait.frequency);
    viewer.gait.phase.value = String(gait.phase);
  },
  /** @param {Record<string, string>} values @param {boolean} compare */
  setRun(values, compare) {
    runs.setValues(values);
    runs.compare.checked = compare;
    keeper.schedule();
  },
  /** @param {string} kind */
  setController(kind) { controllerSelect.value = kind; controllerChosen(); },
  wanted: () => viewer.wanted,
  walking: () => viewer.current,
  race,
  message: showMessage,
};
const tour = new Tour(document, playground, new StudyPanel(document, playground));

start().then(() => tour.begin());
