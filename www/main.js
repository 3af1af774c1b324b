// @ts-check
/**
 * Page wiring: makes the page's parts and connects them. The robot (robot/robot.js: the drawn body
 * and the brain that drives it) is shown by the viewer, edited by the editor and its controls
 * (robot/draw-controls.js), evolved or fine-tuned by the run panel (whose bests it follows,
 * robot/run-follow.js), given modules by the module list, raced side by side, kept across reloads
 * and shared as a link (keep/keeper.js), and set up by the guided tour and the study panel; bodies
 * are searched around a brain by the body-search panel (codesign/).
 */
import { finetuneWords, lostInLink, whyNoFinetune } from './robot/brain.js';
import { ready } from './workers/core.js';
import { rowsField, wireDrawControls } from './robot/draw-controls.js';
import { byId, whenNear } from './shared/dom.js';
import { Drawing } from './robot/drawing.js';
import { Editor } from './robot/editor.js';
import { Keeper } from './keep/keeper.js';
import { messageOf } from './workers/kit.js';
import { Measurer } from './robot/measure.js';
import { MessageBox } from './shared/message.js';
import { Challenge } from './classroom/challenge/challenge.js';
import { Classroom } from './classroom/classroom.js';
import { Lab } from './classroom/lab.js';
import { simplify, wireWords } from './shared/simple-words.js';
import { CodesignPanel } from './codesign/panel.js';
import { SearchEstimate } from './codesign/estimate.js';
import { BOX, searchWords } from './codesign/plan.js';
import { ModuleList, NOT_YET } from './modules/modules.js';
import { Race } from './viewer/race.js';
import { Robot } from './robot/robot.js';
import { pageState } from './robot/state.js';
import { RunFollower } from './robot/run-follow.js';
import { RunEstimate, estimateSeconds, voxelCount } from './runs/estimate.js';
import { RunPanel } from './runs/panel.js';
import { SpeedNote } from './robot/speed-note.js';
import { fillResults } from './tour/results.js';
import { StudyPanel } from './tour/study.js';
import { Tour } from './tour/tour.js';
import { Viewer } from './viewer/viewer.js';
import { editWalking } from './robot/walking-edit.js';
import { familyName, hasAttention, isAnyBody } from './shared/families.js';
import { SteadyRoom } from './shared/steady.js';

const messages = new MessageBox(byId(document, 'message'), byId(document, 'shape-message'));
const defaults = await ready.catch((error) => {
  messages.show(`The simulator could not load: ${messageOf(error)}`);
  throw error;
});
/**
 * An error for the person: it stays until closed, or, with a source (the input it is about),
 * until that source says something else ('' once the input is valid).
 * @param {string} text @param {string} [source]
 */
const showMessage = (text, source) => messages.show(text, 'error', source);
const drawing = new Drawing(defaults.grid.width, defaults.grid.height);
const controllerSelect = byId(document, 'controller', HTMLSelectElement);

// The parts call the robot only once the page runs, after it is made below.
/** @type {Robot} */
let robot;
/** @type {RunFollower} */
let follower;
/** @type {Challenge | null} a challenge link's rules, checked as the student draws (made below) */
let challenge = null;
const editor = new Editor(byId(document, 'editor', HTMLCanvasElement), drawing, {
  onPaint: () => robot.updateCheck(),
  onStroke: () => robot.bodyChanged(),
  onLocked: () => messages.show('A run is using this robot: pause or stop it to edit the drawing.', 'note'),
});
const viewer = new Viewer(document, {
  message: showMessage,
  messages,
  clicked: (pick) => editWalking(robot, pick),
  missed: () => messages.show('Click a voxel to remove it, or a spot right next to one (its own width away at most) to add one there.', 'note'),
});
const keeper = new Keeper(defaults, {
  link: byId(document, 'share-link', HTMLInputElement), button: byId(document, 'share', HTMLButtonElement),
}, {
  state: () => pageState(robot),
  apply: (state) => robot.restore(state),
  shown: () => `${drawing.rows()} (${robot.check.voxels} voxels) driven by ${robot.brain ? robot.brain.label : 'the phase gait'}`,
  running: () => robot.running,
  lost: () => lostInLink(robot?.brain ?? null),
  say: (text, kind = 'error') => messages.show(text, kind),
  shared: (state) => challenge?.shared(state),
});
const speedNote = new SpeedNote(byId(document, 'speed-note'), new Measurer(defaults.viewNoiseSeed));
// The lines over the run's buttons that a run's newest best writes again: their room kept while it runs (Stop stays put).
const steady = new SteadyRoom(['live-figures', 'driver', 'speed-note', 'freeze-report'].map((id) => byId(document, id)));
const modules = new ModuleList(document, {
  loadOnto: (module) => robot.loadModule(module),
  openOwn: (module) => robot.openModule(module),
  message: showMessage,
  described: (info) => bodySearch?.moduleKind(info?.controller ?? ''), // the body search words its brains for the module
}, defaults.attentionGenes, defaults.presets);
const race = new Race(document, { module: () => modules.selected(), terrain: () => viewer.terrain.value.trim(), message: showMessage });
const runs = new RunPanel(document, defaults, {
  body: () => { // the panel asks before the robot is made; a drawing that breaks a challenge's rules is not evolved
    const why = challenge?.problem(drawing.rows()) ?? '';
    return { rows: drawing.rows(), ok: (robot?.check.ok ?? false) && !why, why: why && `your robot breaks the challenge's rules (${why}): change the drawing to keep them` };
  },
  controller: () => controllerSelect.value,
  source: () => (robot?.brain && hasAttention(robot.brain.controller) ? robot.brain.source : null),
  sourceKind: () => robot?.brain?.controller ?? 'attention',
  whyNoFinetune: () => whyNoFinetune(robot?.brain ?? null),
  finetuneWords: () => finetuneWords(robot?.brain ?? null),
  best: (genome, fitness, settings, kind) => follower.best(genome, fitness, settings, kind),
  finished: (run) => follower.finished(run),
  generation: (top, generation, settings, kind, mode) => race.keepGeneration(top, generation, settings, kind, mode),
  running: (on) => {
    robot.running = on;
    steady.hold(on);
    editor.setLocked(on);
    robot.updateButtons();
    if (!on) robot.remeasure(); // measured once the workers are free
  },
  message: showMessage,
  note: (text) => messages.show(text, 'note'),
});
const estimate = new RunEstimate(byId(document, 'run-estimate'), runs.form, () => runs.pace, () => drawing.rows(), defaults.quick,
  () => runs.compare.checked);
runs.compare.addEventListener('change', () => estimate.refresh());
const rows = rowsField(document, drawing, editor, messages, () => robot.bodyChanged());
robot = new Robot(document, { defaults, drawing, editor, viewer, messages, speedNote, runs, rows,
  keep: () => { keeper.schedule(); challenge?.watch(drawing.rows()); }, familyShown: showAnyBodyNote });
follower = new RunFollower(robot, modules, () => runs.mode === 'finetune');
messages.place('codesign', byId(document, 'codesign-message')); // the body search's problems, under its buttons
messages.place('watch', byId(document, 'watch-message')); // what a click in the gallery did, above the robot it brought
const bodySearch = new CodesignPanel(document, {
  body: () => ({ rows: drawing.rows(), ok: robot.check.ok, message: robot.check.message }),
  module: () => modules.selected(),
  controller: () => controllerSelect.value,
  run: () => ({ seed: runs.inputs.seed.value, terrain: runs.inputs.terrain.value, workers: runs.inputs.workers.value }),
  open: async (brain) => { // the body found walks above: brought into view to be watched
    const drawn = drawing.rows();
    await robot.openBrain(() => brain);
    const replaced = drawn !== brain.rows && drawing.rows() === brain.rows;
    if (replaced) {
      const finetune = isAnyBody(brain.controller)
        ? ' Fine-tune, under “Run”, can train it further for this body or one you draw (from all its genes, its attention kept).'
        : ' Fine-tune, under “Run”, can train its attention for this body or one you draw (the rest of its brain starts again).';
      messages.show('The body you clicked, with its brain, now stands in “1 · Draw” in place of your drawing: Undo there brings '
        + 'the shape of your drawing back, driven by this brain.' + (brain.source ? finetune : ''),
      'note', 'watch');
    }
    // The robot in view, with the note just above it (on a phone the top of the page is far away).
    byId(document, replaced ? 'watch-message' : 'scene').scrollIntoView({ block: replaced ? 'start' : 'nearest', behavior: 'instant' });
  },
  race: (racers) => {
    race.clear();
    for (const racer of racers) race.add(racer);
    race.section.scrollIntoView({ block: 'start', behavior: 'instant' });
  },
  share: () => keeper.share(),
  message: showMessage,
});
/** The body search's brain, in words, before it starts. */
function searchBrain() {
  const kind = byId(document, 'codesign-brain', HTMLSelectElement).value;
  if (kind === 'scratch') return `a new ${familyName(controllerSelect.value)} brain, evolved from scratch with the body`;
  const option = modules.select.selectedOptions[0];
  if (!option?.value) return 'no module chosen yet (under “3 · Give it a brain”)';
  const name = `the module “${option.text.replace(/ · .*$/, '')}”`;
  // Said before the search refuses it (the core's rule: only an attention module or a brain for any body drives other bodies).
  const family = modules.info?.controller ?? '';
  if (family && family !== 'attention' && !isAnyBody(family)) {
    return `${name} is ${familyName(family)}: only an attention module or a brain for any body can drive other bodies; choose one, or “a new brain, from scratch”`;
  }
  if (!isAnyBody(family)) return `${name}, ${kind === 'frozen' ? 'its attention kept' : 'every gene evolving from it'}`;
  const named = name.includes(familyName(family)) ? name : `${name} (${familyName(family)})`; // an imported file's name does not say
  return `${named}, ${searchWords(/** @type {'frozen' | 'finetune'} */ (kind), family).short}`;
}
// The body search's estimate: its start body (the module's own once it is described; else the drawing stands for it).
const startRows = () => ({ box: BOX, module: modules.info?.shape ?? drawing.rows() })[byId(document, 'codesign-from', HTMLSelectElement).value] ?? drawing.rows();
new SearchEstimate(byId(document, 'codesign-estimate'), () => ({ evaluations: Number(byId(document, 'codesign-budget', HTMLInputElement).value),
  seconds: Number(byId(document, 'codesign-seconds', HTMLInputElement).value),
  rows: startRows(), workers: Number(runs.inputs.workers.value) || 1, running: bodySearch.running,
  brain: searchBrain() }), () => estimate.currentPace());

/**
 * Under the family menu, while it shows a brain for any body: where the study's is (or that it
 * is not ready yet), and what a person can do meanwhile. @param {string} kind the family shown
 */
function showAnyBodyNote(kind) {
  const note = byId(document, 'any-body-note');
  note.hidden = !isAnyBody(kind);
  if (note.hidden) return;
  const driving = Boolean(modules.studyAnyBody) && robot?.brain?.module === modules.studyAnyBody;
  if (driving) {
    note.textContent = 'Your robot walks with the study\'s brain for any body (attention, trained on many bodies), every gene as trained: '
      + 'add or remove voxels and it keeps walking, with the same genes. Fine-tune trains it further for this body.';
    return;
  }
  const study = modules.studyAnyBody
    ? 'The study\'s brain for any body (attention, trained on many bodies) is in the module list, under “one brain for any body”: '
      + 'choose it and press “Load onto my robot”, and it walks on your drawing at once, with no evolution.'
    : `The study's brain for any body (attention, trained on many bodies): ${NOT_YET}.`;
  note.textContent = `${study} Evolve trains one on your drawing; then add or remove voxels and it keeps walking, with the same genes.`;
}

/** The viewer's terrain changed: the speed is measured on it, and it is kept. */
function terrainChanged() {
  robot.remeasure();
  keeper.schedule();
}

function wire() {
  wireDrawControls(document, defaults, drawing, editor, {
    changed: () => robot.bodyChanged(),
    running: () => robot.running,
  });
  for (const c of defaults.controllers) controllerSelect.append(new Option(familyName(c), c));
  controllerSelect.addEventListener('change', () => robot.controllerChosen());
  byId(document, 'share').addEventListener('click', () => keeper.share());
  byId(document, 'glossary-open').addEventListener('click', () => {
    const glossary = byId(document, 'glossary', HTMLDetailsElement);
    glossary.open = true;
    glossary.scrollIntoView({ behavior: 'smooth' });
  });
  for (const input of Object.values(runs.inputs)) input.addEventListener('change', () => keeper.schedule());
  viewer.terrain.listen(terrainChanged);
  runs.inputs.seconds.addEventListener('change', () => {
    if (robot.brain?.seconds) return; // a trained brain walks the episodes it was trained on
    viewer.setSeconds(robot.episodeSeconds());
    robot.remeasure();
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
    return robot.bodyChanged();
  });
  modules.listPretrained().then(() => {
    if (robot.brain?.module) modules.choose(robot.brain.module);
    showAnyBodyNote(controllerSelect.value); // the study's brain for any body is listed, or not yet
  });
  // How long a run will take, before the first: this computer's speed on the quick settings' episodes, for the drawn body.
  // (Three seconds after the page opened: its own start-up, wasm compiled in every worker, is done by then and does not
  // slow the measure, and the measure's two seconds of the cores do not slow the page's first moments.)
  setTimeout(() => estimate.measure(drawing.rows(), robot.check, defaults.quick.seconds, defaults.trainingTerrain), 3000);
  window.addEventListener('hashchange', () => keeper.openLink());
  window.addEventListener('beforeunload', (event) => {
    if (robot.running) event.preventDefault(); // the browser asks: leaving ends the run (its best so far is kept)
  });
}

/**
 * The playground as the tour and the study panel set it up (www/tour/): the page's own functions.
 * @type {import('./tour/stage.js').Playground}
 */
const playground = {
  defaults,
  running: () => robot.running,
  stopRun: () => new Promise((resolve) => {
    runs.buttons.stop.click();
    const wait = () => (robot.running ? setTimeout(wait, 50) : resolve(undefined));
    wait();
  }),
  setBody: (rows) => robot.setBody(rows),
  module: (key, label, short) => modules.read(key, label, short),
  openModule: (module) => robot.openModule(module),
  loadModule: (module) => robot.loadModule(module),
  studyAnyBody: () => modules.listed.then(() => modules.studyAnyBody),
  setView(terrain, gait) {
    viewer.terrain.value = terrain;
    viewer.gait.frequency.value = String(gait.frequency);
    viewer.gait.phase.value = String(gait.phase);
  },
  setRun(values, compare) {
    runs.setValues(values);
    runs.compare.checked = compare;
    keeper.schedule();
  },
  setController(kind) { controllerSelect.value = kind; return robot.controllerChosen(); },
  wanted: () => viewer.wanted,
  walking: () => viewer.current,
  race,
  setCodesign: (settings) => bodySearch.setUp(settings),
  holdAtEpisodeEnd: (on) => viewer.holdAtEnd(on),
  quietModules: (on) => modules.quiet(on),
  message: showMessage,
};
/** The classroom's measure of a brain on the robot walking, the one “Your robot's speed” uses (made when first asked). @type {Measurer | null} */
let labMeasurer = null;
const lab = new Lab({ defaults, latestRun: () => ({ ...race.run, running: robot.running }), raceSeconds: () => Number(race.seconds.value),
  studyAnyBody: () => modules.studyAnyBody,
  walkingBody: () => ({ rows: robot.walkingRows, terrain: viewer.terrain.value.trim() }),
  measure: (what) => (labMeasurer ??= new Measurer(defaults.viewNoiseSeed)).measure(what) });
const study = new StudyPanel(document, playground);
// The module list's note on a study run's other stops needs the study's tables: read once the note can be seen (or the list is used),
// watched from when the list is made (while the page fills in, the note passes through the first screen).
const studyRuns = () => void study.load().then(() => modules.setStudyRuns(study.runs));
modules.listed.then(() => whenNear(byId(document, 'module-details'), studyRuns));
modules.select.addEventListener('change', studyRuns);
const tour = new Tour(document, playground, study, new Classroom(document, lab));
fillResults(byId(document, 'results-plain-body'), (id) => study.show(id));
wireWords(document);
// The lines the page writes as it goes, marked for simple words: a drawing's code and evaluations per second hidden, a terrain's name explained.
for (const id of ['shape-status', 'module-details', 'driver', 'speed-note', 'robot-speed', 'run-rate', 'run-plan', 'study-run-note', 'freeze-report', 'challenge-rules',
  'tour-box', 'param-count', 'run-status', 'attention-hover', 'race-status']) {
  simplify(byId(document, id));
}
// The race's brains by their names: what each is, beside it.
simplify(byId(document, 'race-lanes'), [
  { pattern: /\bmlp-comm\b/g, explain: 'its voxels send messages' },
  { pattern: /\bmlp\b(?!-)/g, explain: 'no attention, no messages' },
]);
challenge = new Challenge(document, lab, {
  defaults, rows: () => drawing.rows(), race, message: showMessage, pin: (text) => messages.show(text, 'pinned'),
  setView: (terrain) => { viewer.terrain.value = terrain; viewer.reload(); terrainChanged(); },
  fixRun: (values) => { runs.form.fix(values, 'the challenge'); runs.inputs.seconds.dispatchEvent(new Event('change')); }, // walked and kept as if typed
  runSeconds: (s) => estimateSeconds({ evaluations: s.budget + s.population, seconds: s.seconds, voxels: voxelCount(s.shape),
    workers: Number(runs.inputs.workers.value) || 1 }, estimate.currentPace()),
  lastRun: () => ({ runFile: runs.runFile, settings: runs.runSettings, mode: runs.mode }),
  setBody: (rows) => robot.setBody(rows),
  refresh: () => robot.updateButtons(),
});

start().then(() => challenge.begin()).then(() => tour.begin());
