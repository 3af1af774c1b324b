// @ts-check
/**
 * A robot's short code in a class challenge, for a student to type instead of a 700-character
 * share link (the link stays, exact, beside it). A challenge fixes every setting of the run
 * (challenge-rules.js) and a run is the same bits on every computer for the same settings, so a
 * robot evolved for the challenge is its body and brain family alone: the code holds those, and
 * a check of the brain's genes (10 bits of a hash). The teacher's page evolves the robot again
 * from the code with the challenge's run (evolveAgain: the page's own GA coordinator) and
 * compares the check: a typo, a run stopped early or a robot made otherwise is found, never
 * ranked as someone else's robot.
 *
 * The code: Crockford's base32 (no I, L, O or U; typed in any case, O read as 0, I and L as 1),
 * in groups of four: 2 bits for the brain family, the body's width - 1 (5 bits) and height - 1
 * (4 bits), its cells row by row from the top, the check (10 bits).
 */
import { runGenome } from '../workers/core.js';
import { spawn } from '../workers/kit.js';
import { FromCoordinator, MAX_EVALUATORS, ToCoordinator } from '../workers/protocol.js';

const ALPHABET = '0123456789ABCDEFGHJKMNPQRSTVWXYZ';
/** The brain families a code can name, by number. */
const FAMILIES = ['attention', 'mlp', 'mlp-comm'];

/** A 10-bit check of a genome's bits (FNV-1a of its bytes). @param {Float32Array} genome */
export function genomeCheck(genome) {
  const bytes = new Uint8Array(genome.buffer, genome.byteOffset, genome.byteLength);
  let h = 0x811c9dc5;
  for (const b of bytes) h = Math.imul(h ^ b, 0x01000193) >>> 0;
  return (h ^ (h >>> 10) ^ (h >>> 20)) & 0x3ff;
}

/**
 * The short code of a robot, or null when it cannot have one (a brain family or a body too
 * large for a code). @param {string} rows @param {string} controller @param {Float32Array} genome
 * @returns {string | null}
 */
export function robotCode(rows, controller, genome) {
  const family = FAMILIES.indexOf(controller);
  const lines = rows.split('-');
  const width = lines[0]?.length ?? 0;
  if (family < 0 || width < 1 || width > 32 || lines.length > 16 || lines.some((l) => l.length !== width)) return null;
  const bits = [...toBits(family, 2), ...toBits(width - 1, 5), ...toBits(lines.length - 1, 4),
    ...lines.join('').split('').map((c) => (c === '1' ? 1 : 0)), ...toBits(genomeCheck(genome), 10)];
  while (bits.length % 5) bits.push(0);
  let text = '';
  for (let i = 0; i < bits.length; i += 5) text += ALPHABET[bits.slice(i, i + 5).reduce((v, b) => 2 * v + b, 0)];
  return text.match(/.{1,4}/g)?.join('-') ?? text;
}

/** @param {number} value @param {number} n @returns {number[]} its n low bits, the highest first */
function toBits(value, n) {
  return Array.from({ length: n }, (_, i) => (value >> (n - 1 - i)) & 1);
}

/** Whether a line of the class's box looks like a short code (not a link). @param {string} text */
export function looksLikeCode(text) {
  return /^[0-9A-Za-z]{4}(-[0-9A-Za-z]{1,4})+$/.test(text.trim());
}

/**
 * A short code read back: the body, the brain family and the check, or what is wrong with it.
 * @param {string} text @returns {{rows: string, controller: string, check: number} | {error: string}}
 */
export function readCode(text) {
  const clean = text.trim().toUpperCase().replace(/[-\s]/g, '').replace(/O/g, '0').replace(/[IL]/g, '1');
  /** @type {number[]} */
  const bits = [];
  for (const c of clean) {
    const v = ALPHABET.indexOf(c);
    if (v < 0) return { error: `“${c}” is not a letter of a code` };
    bits.push(...toBits(v, 5));
  }
  const take = (/** @type {number} */ n) => bits.splice(0, n).reduce((v, b) => 2 * v + b, 0);
  if (bits.length < 21) return { error: 'too short: a letter is missing' };
  const controller = FAMILIES[take(2)];
  const width = take(5) + 1;
  const height = take(4) + 1;
  if (!controller) return { error: 'not a code of this page (a letter is wrong)' };
  if (bits.length < width * height + 10) return { error: 'too short for the body it starts with: a letter is missing or wrong' };
  const cells = bits.splice(0, width * height).join('');
  const check = take(10);
  if (bits.length >= 5 || bits.some((b) => b !== 0)) return { error: 'too long: a letter too many, or a wrong one' };
  const rows = Array.from({ length: height }, (_, i) => cells.slice(i * width, (i + 1) * width)).join('-');
  return { rows, controller, check };
}

/**
 * Evolves a robot again with a challenge's run, as the student's page did (the page's GA
 * coordinator, all this computer's cores: the same bits for any number of workers), and gives
 * its best genome. @param {import('../workers/protocol.js').EvolveSettings} settings
 * @returns {Promise<Float32Array>}
 */
export function evolveAgain(settings) {
  const workers = Math.max(1, Math.min(MAX_EVALUATORS, navigator.hardwareConcurrency || 1));
  return new Promise((resolve, reject) => {
    const worker = spawn('runs/coordinator.js', (msg) => {
      if (msg.type === FromCoordinator.ERROR) { worker.terminate(); reject(new Error(msg.message)); }
      if (msg.type === FromCoordinator.DONE) {
        worker.terminate();
        if (msg.runFile === null || msg.stopped) reject(new Error('the run did not finish'));
        else runGenome(msg.runFile).then(resolve, reject);
      }
    }, (text) => { worker.terminate(); reject(new Error(`the run stopped: ${text}`)); });
    worker.postMessage({ type: ToCoordinator.START, settings, workers, source: null });
  });
}
