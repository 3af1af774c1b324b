// @ts-check
/**
 * The page's state as text: for a link (`#shape=...&controller=...&genome=...`) and for the
 * browser's storage. The state is the drawing, the chosen controller, the viewer's terrain and
 * phase gait, the run settings, and the genome that drives the robot (base64 of its float32 values,
 * little-endian, so every bit survives) with where it came from, the episode length it was
 * trained on, its training figure and whether it is a one-shot transplant (so that the speed
 * note says after a reload what it said before). Reading checks everything
 * with the core and returns a message instead of a state when anything is wrong, but for the
 * brain: a damaged brain is dropped and the rest kept. A part left out (a part this page does
 * not know, a second copy pasted after the link) is said, never dropped in silence; `&amp;` (an
 * e-mail tool's `&`) is read as `&`. A state is shared only if its link reads back (shareProblem).
 */
import { checkGait, checkGenome, checkShape, checkTerrain, checkTrainingTerrain } from '../workers/core.js';
import { messageOf } from '../workers/kit.js';
import { plain } from '../shared/message.js';
import { size } from '../shared/format.js';

/**
 * @typedef {object} PageState
 * @property {string} rows         the drawing, rows top first
 * @property {string} controller   the family chosen for Evolve
 * @property {string} terrain      the viewer's terrain
 * @property {string | null} gait   the viewer's phase gait, "F,PHI" (null: the page's default)
 * @property {Record<string, string>} run  run settings: population, seconds, budget, seed, terrain
 * @property {KeptBrain | null} brain what drives the robot
 */

/**
 * @typedef {object} KeptBrain
 * @property {string} controller
 * @property {Float32Array} genome
 * @property {string} label
 * @property {string | null} module  the pretrained file it came from (for fine-tuning)
 * @property {number | null} seconds the episode length it was trained on, over which the viewer measures it (null: not known)
 * @property {KeptTrained | null} trained its training figure (null: none, or not known)
 * @property {boolean} oneShot       a module transplanted onto this body, not fine-tuned yet
 */

/**
 * A brain's training figure as a link holds it (robot/brain.js: Trained): its speed (m/s), the
 * training terrain and, for a body search's, how many walks on fresh terrains the speed is the mean of.
 * @typedef {{speed: number, terrain: string, walks?: number}} KeptTrained
 */

/** The run settings a state carries (the workers are this computer's, never shared). */
export const RUN_KEYS = Object.freeze(['population', 'seconds', 'budget', 'seed', 'terrain']);

/** The parts of a brain in a link: read only with its genome. */
const BRAIN_PARTS = Object.freeze(['brain', 'genome', 'label', 'module', 'brain-seconds', 'brain-speed', 'brain-terrain', 'brain-walks', 'one-shot']);
/** Every part a link may hold (encodeState writes them, decodeState reads them): any other is left out, and said. */
const PARTS = Object.freeze(['shape', 'controller', 'view', 'gait', ...RUN_KEYS.map(runPart), ...BRAIN_PARTS]);

/** The link's name of a run setting. @param {string} key */
function runPart(key) { return key === 'terrain' ? 'train' : key; }

/** @param {PageState} state @returns {string} URL-hash parameters (without '#') */
export function encodeState(state) {
  const p = new URLSearchParams();
  p.set('shape', state.rows);
  p.set('controller', state.controller);
  p.set('view', state.terrain);
  if (state.gait) p.set('gait', state.gait);
  for (const k of RUN_KEYS) if (state.run[k] !== undefined) p.set(runPart(k), state.run[k]);
  if (state.brain) {
    p.set('brain', state.brain.controller);
    p.set('genome', genomeToBase64(state.brain.genome));
    p.set('label', state.brain.label);
    if (state.brain.module) p.set('module', state.brain.module);
    if (state.brain.seconds !== null) p.set('brain-seconds', String(state.brain.seconds));
    const trained = state.brain.trained;
    if (trained && Number.isFinite(trained.speed)) {
      p.set('brain-speed', String(trained.speed));
      p.set('brain-terrain', trained.terrain);
      if (trained.walks) p.set('brain-walks', String(trained.walks)); // the mean of this many (a body search's)
    }
    if (state.brain.oneShot) p.set('one-shot', '1');
  }
  return p.toString();
}

/**
 * Reads a state and checks all of it: the robot (valid, and within the grid), the controller,
 * the terrains, the phase gait, every run setting, the genome (the core's checks) and its episode length. A
 * draft (the kept state of a drawing not finished yet) may be an invalid robot; it then has no
 * brain.
 * @param {string} text URL-hash parameters (with or without '#')
 * @param {string[]} controllers the families the page knows
 * @param {{width: number, height: number}} grid the editor's grid
 * @param {boolean} [draft] accept an unfinished drawing
 * @returns {Promise<{state: PageState, damaged?: string, dropped: string[]} | {error: string}>} a damaged brain
 *   (`damaged` says how) is dropped: the rest of the state, all valid, is kept; `dropped`: the
 *   other parts left out, each a sentence saying which and why
 */
export async function decodeState(text, controllers, grid, draft = false) {
  try {
    const { params, dropped } = firstCopy(text);
    const p = new URLSearchParams(params);
    const rows = p.get('shape') ?? '';
    const lines = rows.split('-');
    if (!/^[01]+(-[01]+)*$/.test(rows)) return { error: `its robot "${rows.slice(0, 40)}" is not rows of 0 and 1` };
    if (lines.length > grid.height || lines.some((l) => l.length > grid.width)) {
      return { error: `its robot does not fit the ${size(grid.width, grid.height)} drawing grid` };
    }
    const check = await checkShape(rows);
    if (!check.ok && !(draft && check.pieces.length > 0)) return { error: `its robot is not valid: ${check.message}` };
    const controller = p.get('controller') ?? controllers[0];
    if (!controllers.includes(controller)) return { error: `unknown controller "${controller}"` };
    const view = p.get('view') ?? '';
    const viewProblem = view ? await checkTerrain(view) : '';
    if (viewProblem) return { error: viewProblem };
    const gait = p.get('gait'); // links made before it was shared have none
    const gaitProblem = gait === null ? '' : await checkGait(gait);
    if (gaitProblem) return { error: gaitProblem };
    /** @type {Record<string, string>} */
    const run = {};
    for (const k of RUN_KEYS) {
      const v = p.get(runPart(k));
      if (v === null) continue;
      const problem = k === 'terrain' ? await checkTrainingTerrain(v) : settingProblem(k, v);
      if (problem) return { error: problem };
      run[k] = v;
    }
    const read = check.ok && p.get('genome') !== null ? await readBrain(p, rows, controllers) : { brain: null };
    const state = { rows, controller, terrain: view, gait, run, brain: 'brain' in read ? read.brain : null };
    dropped.push(...leftOut(p, state));
    return 'error' in read ? { state, damaged: read.error, dropped } : { state, dropped };
  } catch (error) {
    return { error: messageOf(error) };
  }
}

/**
 * The link's parameters as they were made: `&amp;` read as `&` (nothing is lost), and whatever
 * follows the link's end (a second `http://`, `https://` or `#`: it was pasted twice, or
 * another link after it) cut off and said. @param {string} text
 * @returns {{params: string, dropped: string[]}}
 */
function firstCopy(text) {
  const whole = text.replace(/^#/, '').replace(/&(amp;)+/g, '&');
  const end = whole.search(/https?:\/\/|#/);
  if (end < 0) return { params: whole, dropped: [] };
  const params = whole.slice(0, end);
  const rest = whole.slice(end);
  const again = rest.slice(rest.indexOf('#') + 1).startsWith(params);
  return { params, dropped: [again ? 'This link was pasted twice: only its first copy was read.'
    : `Something was pasted after this link ("${rest.slice(0, 40)}"): only the link was read.`] };
}

/**
 * The parts of link `p` that `state` (read from it) leaves out, each a sentence saying which and
 * why: parts this page does not know, second copies of a part, a brain's parts without its
 * genome, a module that is not one of this page's.
 * @param {URLSearchParams} p @param {PageState} state @returns {string[]}
 */
function leftOut(p, state) {
  const said = [];
  const seen = new Set();
  for (const key of p.keys()) {
    const name = `"${key.slice(0, 30)}"`;
    if (!PARTS.includes(key)) said.push(`Its part ${name} was left out: this page knows no such part.`);
    else if (seen.has(key)) said.push(`Its second ${name} was left out: only the first is read.`);
    seen.add(key);
  }
  const orphans = BRAIN_PARTS.filter((k) => k !== 'genome' && p.has(k));
  if (p.get('genome') === null && orphans.length > 0) {
    const many = orphans.length > 1;
    said.push(`Its ${orphans.map((k) => `"${k}"`).join(', ')} ${many ? 'were' : 'was'} left out: ${many ? 'they describe' : 'it describes'} a brain, but the link holds no genome.`);
  }
  const module = p.get('module');
  if (state.brain && module !== null && state.brain.module === null) {
    said.push(`Its module "${module.slice(0, 40)}" was left out: it is not one of this page's pretrained modules, so this brain cannot be fine-tuned from it.`);
  }
  return said;
}

/**
 * '' or why `state` cannot be shared, in words: a link must open what it shares, so the drawing
 * must be a whole robot and the link made of it must read back (decodeState) in full.
 * @param {PageState} state @param {string[]} controllers @param {{width: number, height: number}} grid
 * @returns {Promise<string>}
 */
export async function shareProblem(state, controllers, grid) {
  const check = state.rows ? await checkShape(state.rows) : null;
  if (!check || check.voxels === 0) return 'a link opens your drawing, and it is empty: draw a robot (or Undo) to share it';
  if (!check.ok) {
    const what = check.pieces.length > 1 ? `in ${check.pieces.length} separate pieces` : `not a robot yet (${plain(check.message)})`;
    return `a link opens your drawing, and it is ${what}: make it one whole robot (or Undo) to share it`;
  }
  const read = await decodeState(encodeState(state), controllers, grid);
  if ('error' in read) return `its link would not open (${plain(read.error)}): fix that to share it`;
  if (read.damaged) return `its brain would not open from a link (${read.damaged})`;
  return '';
}

/**
 * The brain of a state, checked (the core's checks of its genome for the robot `rows`).
 * @param {URLSearchParams} p @param {string} rows @param {string[]} controllers
 * @returns {Promise<{brain: KeptBrain} | {error: string}>}
 */
async function readBrain(p, rows, controllers) {
  try {
    const kind = p.get('brain') ?? '';
    if (!controllers.includes(kind)) return { error: `unknown controller "${kind.slice(0, 20)}" for its genome` };
    const genome = base64ToGenome(p.get('genome') ?? '');
    await checkGenome(kind, rows, genome);
    const module = p.get('module');
    const seconds = p.get('brain-seconds'); // links made before it was kept have none
    const secondsProblem = seconds === null ? '' : settingProblem('seconds', seconds);
    if (secondsProblem) return { error: `its ${secondsProblem}` };
    const notes = await trainingNotes(p);
    if ('error' in notes) return { error: `its ${notes.error}` };
    return { brain: { controller: kind, genome, label: p.get('label') ?? `${kind} from a link`,
      module: module && /^pretrained\/[\w.-]+\.json$/.test(module) ? module : null, seconds: seconds === null ? null : Number(seconds),
      ...notes } };
  } catch (error) {
    return { error: plain(messageOf(error)) };
  }
}

/**
 * The brain's training figure (speed and terrain, both or neither) and one-shot flag, checked;
 * links made before they were kept have none (no figure, not one-shot).
 * @param {URLSearchParams} p
 * @returns {Promise<{trained: KeptTrained | null, oneShot: boolean} | {error: string}>}
 */
async function trainingNotes(p) {
  const speed = p.get('brain-speed');
  const terrain = p.get('brain-terrain');
  const oneShot = p.get('one-shot');
  if (oneShot !== null && oneShot !== '1') return { error: `one-shot flag "${oneShot.slice(0, 20)}" is not 1` };
  if ((speed === null) !== (terrain === null)) return { error: 'training speed and training terrain do not come together (one is missing)' };
  const walks = p.get('brain-walks');
  if (speed === null || terrain === null) {
    return walks === null ? { trained: null, oneShot: oneShot === '1' } : { error: 'a number of training walks without a training speed' };
  }
  if (speed.trim() === '' || !Number.isFinite(Number(speed))) return { error: `training speed "${speed.slice(0, 20)}" is not a number` };
  if (walks !== null && !/^[1-9]\d{0,8}$/.test(walks)) return { error: `training walks "${walks.slice(0, 20)}" is not a whole number of at least 1` };
  const problem = await checkTrainingTerrain(terrain);
  if (problem) return { error: `training terrain: ${problem}` };
  return { trained: { speed: Number(speed), terrain, ...(walks === null ? {} : { walks: Number(walks) }) }, oneShot: oneShot === '1' };
}

/**
 * '' or what is wrong with a run setting read from a link (the training terrain is the core's
 * check, asked apart).
 * @param {string} key @param {string} value
 */
function settingProblem(key, value) {
  const n = Number(value);
  switch (key) {
    case 'population': return Number.isInteger(n) && n >= 1 && n <= 100_000 ? '' : `population "${value}" is not a whole number from 1`;
    case 'seconds': return n > 0 && n <= 3600 ? '' : `episode seconds "${value}" are not in (0, 3600]`;
    case 'budget': return Number.isInteger(n) && n >= 1 && n <= 10_000_000 ? '' : `budget "${value}" is not a whole number of evaluations from 1 to 10,000,000`;
    case 'seed': return Number.isSafeInteger(n) && n >= 0 ? '' : `seed "${value}" is not a whole number from 0 to 2^53 - 1`;
    default: return '';
  }
}

/** @param {Float32Array} genome @returns {string} base64url of its little-endian bytes */
export function genomeToBase64(genome) {
  const bytes = new Uint8Array(genome.length * 4);
  const view = new DataView(bytes.buffer);
  genome.forEach((g, i) => view.setFloat32(i * 4, g, true));
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** @param {string} text base64url @returns {Float32Array} */
export function base64ToGenome(text) {
  let binary;
  try {
    binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  } catch {
    throw new Error('its genome is not valid base64');
  }
  if (binary.length % 4 !== 0) throw new Error(`its genome is damaged (${binary.length} bytes, not a whole number of genes)`);
  const view = new DataView(new ArrayBuffer(binary.length));
  for (let i = 0; i < binary.length; i++) view.setUint8(i, binary.charCodeAt(i));
  return Float32Array.from({ length: binary.length / 4 }, (_, i) => view.getFloat32(i * 4, true));
}
