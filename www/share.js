// @ts-check
/**
 * The page's state as text: for a link (`#shape=...&controller=...&genome=...`) and for the
 * browser's storage. The state is the drawing, the chosen controller, the viewer's terrain,
 * the run settings, and the genome that drives the robot (base64 of its float32 values,
 * little-endian, so every bit survives) with where it came from. Reading checks everything
 * with the core and returns a message instead of a state when anything is wrong.
 */
import { checkGenome, checkShape } from './core.js';
import { messageOf } from './kit.js';

/**
 * @typedef {object} PageState
 * @property {string} rows         the drawing, rows top first
 * @property {string} controller   the family chosen for Evolve
 * @property {string} terrain      the viewer's terrain
 * @property {Record<string, string>} run  run settings: population, seconds, budget, seed, terrain
 * @property {{controller: string, genome: Float32Array, label: string, module: string | null} | null} brain
 *   what drives the robot; module = the pretrained file it came from (for fine-tuning)
 */

const RUN_KEYS = ['population', 'seconds', 'budget', 'seed', 'terrain'];

/** @param {PageState} state @returns {string} URL-hash parameters (without '#') */
export function encodeState(state) {
  const p = new URLSearchParams();
  p.set('shape', state.rows);
  p.set('controller', state.controller);
  p.set('view', state.terrain);
  for (const k of RUN_KEYS) if (state.run[k] !== undefined) p.set(k === 'terrain' ? 'train' : k, state.run[k]);
  if (state.brain) {
    p.set('brain', state.brain.controller);
    p.set('genome', genomeToBase64(state.brain.genome));
    p.set('label', state.brain.label);
    if (state.brain.module) p.set('module', state.brain.module);
  }
  return p.toString();
}

/**
 * @param {string} text URL-hash parameters (with or without '#')
 * @param {string[]} controllers the families the page knows
 * @returns {{state: PageState} | {error: string}}
 */
export function decodeState(text, controllers) {
  try {
    const p = new URLSearchParams(text.replace(/^#/, ''));
    const rows = p.get('shape') ?? '';
    const check = checkShape(rows);
    if (!check.ok) return { error: `its robot is not valid: ${check.message}` };
    const controller = p.get('controller') ?? controllers[0];
    if (!controllers.includes(controller)) return { error: `unknown controller "${controller}"` };
    /** @type {Record<string, string>} */
    const run = {};
    for (const k of RUN_KEYS) {
      const v = p.get(k === 'terrain' ? 'train' : k);
      if (v !== null) run[k] = v;
    }
    let brain = null;
    const genomeText = p.get('genome');
    if (genomeText !== null) {
      const kind = p.get('brain') ?? '';
      if (!controllers.includes(kind)) return { error: `unknown controller "${kind}" for its genome` };
      const genome = base64ToGenome(genomeText);
      checkGenome(kind, rows, genome);
      const module = p.get('module');
      brain = { controller: kind, genome, label: p.get('label') ?? `${kind} from a link`, module: module && /^pretrained\/[\w.-]+\.json$/.test(module) ? module : null };
    }
    return { state: { rows, controller, terrain: p.get('view') ?? '', run, brain } };
  } catch (error) {
    return { error: messageOf(error) };
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
  if (binary.length % 4 !== 0) throw new Error(`its genome has ${binary.length} bytes, not a whole number of float32 values`);
  const view = new DataView(new ArrayBuffer(binary.length));
  for (let i = 0; i < binary.length; i++) view.setUint8(i, binary.charCodeAt(i));
  return Float32Array.from({ length: binary.length / 4 }, (_, i) => view.getFloat32(i * 4, true));
}
