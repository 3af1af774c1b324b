// @ts-check
/**
 * A robot's short code in a class challenge, for a student to type instead of a 700-character
 * share link (the link stays, exact, beside it). A challenge fixes every setting of the run
 * (rules.js) and a run is the same bits on every computer for the same settings, so a
 * robot evolved for the challenge is its body and brain family alone: the code holds those, the
 * speed the student's page measured (over the challenge's walk, as the teacher's page measures
 * it), a check of the brain's genes (10 bits of a hash) and a last letter that checks the code's
 * other letters (a typo is found at once, 31 times in 32).
 *
 * The teacher's page ranks a code at once by the speed it claims, said as claimed, and checks it
 * when asked (the best four first, every code if the teacher wants): it evolves the robot again
 * from the code with the challenge's run (evolve.js) and compares the check; a checked
 * robot is measured again, so its speed is the teacher's page's own.
 *
 * The code: Crockford's base32 (no I, L, O or U; typed in any case, O read as 0, I and L as 1),
 * in groups of four: 2 bits for the brain family, the body's width - 1 (5 bits) and height - 1
 * (4 bits), its cells row by row from the top, the speed in cm/s + 2048 (12 bits), the genome's
 * check (10 bits), zeros to a whole letter, then the check letter. No browser needed: Node reads it too.
 */

const ALPHABET = '0123456789ABCDEFGHJKMNPQRSTVWXYZ';
/** The brain families a code can name, by number. */
const FAMILIES = ['attention', 'mlp', 'mlp-comm'];
/** The speed's bits, and the value that stands for 0 m/s (so −20.48 to +20.47 m/s, by the cm/s). */
const SPEED_BITS = 12;
const SPEED_ZERO = 2048;
/** Bits of a code before its body's cells, and after them (speed and genome check). */
const HEAD_BITS = 11;
const TAIL_BITS = SPEED_BITS + 10;

/**
 * A real code: the biped 1111-1111-1001 with the attention brain evolved in the challenge of seed
 * 3, 200 evaluations of 5-s walks (0.20 m/s on hilly-1-10-0), as the browser test's student made
 * it (tests/web/lesson.test.mjs). The example the page, the worksheet and docs/teaching.md show;
 * the test checks that every example reads back.
 */
export const EXAMPLE_CODE = '0SFZ-60MS-0V';

/** A 10-bit check of a genome's bits (FNV-1a of its bytes). @param {Float32Array} genome */
export function genomeCheck(genome) {
  const bytes = new Uint8Array(genome.buffer, genome.byteOffset, genome.byteLength);
  let h = 0x811c9dc5;
  for (const b of bytes) h = Math.imul(h ^ b, 0x01000193) >>> 0;
  return (h ^ (h >>> 10) ^ (h >>> 20)) & 0x3ff;
}

/** The check letter of a code's other letters (their values): 5 bits of an FNV-1a hash. @param {number[]} values */
function checkLetter(values) {
  let h = 0x811c9dc5;
  for (const v of values) h = Math.imul(h ^ v, 0x01000193) >>> 0;
  return (h ^ (h >>> 5) ^ (h >>> 10) ^ (h >>> 15) ^ (h >>> 20) ^ (h >>> 25)) & 0x1f;
}

/** How many letters a code of a body `width` × `height` has (its check letter included). @param {number} width @param {number} height */
export function codeLength(width, height) {
  return Math.ceil((HEAD_BITS + width * height + TAIL_BITS) / 5) + 1;
}

/** The form of a code of `letters` letters, in groups of four: XXXX-XXXX-XX. @param {number} letters */
export function codeForm(letters) {
  return 'X'.repeat(letters).match(/.{1,4}/g)?.join('-') ?? '';
}

/** A speed as the code holds it (cm/s, within what its bits hold). @param {number} speed m/s */
export function codeSpeed(speed) {
  return Math.min(2 ** SPEED_BITS - 1, Math.max(0, Math.round(speed * 100) + SPEED_ZERO));
}

/**
 * The short code of a robot, or null when it cannot have one (a brain family or a body too
 * large for a code). @param {string} rows @param {string} controller @param {Float32Array} genome
 * @param {number} speed what the student's page measured (m/s, over the challenge's walk)
 * @returns {string | null}
 */
export function robotCode(rows, controller, genome, speed) {
  const family = FAMILIES.indexOf(controller);
  const lines = rows.split('-');
  const width = lines[0]?.length ?? 0;
  if (family < 0 || width < 1 || width > 32 || lines.length > 16 || lines.some((l) => l.length !== width) || !Number.isFinite(speed)) return null;
  const bits = [...toBits(family, 2), ...toBits(width - 1, 5), ...toBits(lines.length - 1, 4),
    ...lines.join('').split('').map((c) => (c === '1' ? 1 : 0)), ...toBits(codeSpeed(speed), SPEED_BITS), ...toBits(genomeCheck(genome), 10)];
  while (bits.length % 5) bits.push(0);
  /** @type {number[]} */
  const values = [];
  for (let i = 0; i < bits.length; i += 5) values.push(bits.slice(i, i + 5).reduce((v, b) => 2 * v + b, 0));
  values.push(checkLetter(values));
  const text = values.map((v) => ALPHABET[v]).join('');
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

/** A code as typed, in its one spelling (capitals, O as 0, I and L as 1, in groups of four). @param {string} text */
export function normalCode(text) {
  const clean = text.trim().toUpperCase().replace(/[-\s]/g, '').replace(/O/g, '0').replace(/[IL]/g, '1');
  return clean.match(/.{1,4}/g)?.join('-') ?? clean;
}

/**
 * A short code read back: the body, the brain family, the speed its page measured and the
 * genome's check, or what is wrong with it (a wrong length says the form expected).
 * @param {string} text @returns {{rows: string, controller: string, speed: number, check: number} | {error: string}}
 */
export function readCode(text) {
  const clean = normalCode(text).replace(/-/g, '');
  /** @type {number[]} */
  const values = [];
  for (const c of clean) {
    const v = ALPHABET.indexOf(c);
    if (v < 0) return { error: `“${c}” is not a letter of a code (a code has the digits and the letters A to Z but U)` };
    values.push(v);
  }
  const shortest = codeLength(1, 1);
  if (values.length < shortest) {
    return { error: `too short: ${values.length} letters, and a code has at least ${shortest} (a 4 × 3 body's has ${codeLength(4, 3)}: ${codeForm(codeLength(4, 3))}, like ${EXAMPLE_CODE})` };
  }
  const bits = values.slice(0, -1).flatMap((v) => toBits(v, 5));
  const take = (/** @type {number} */ n) => bits.splice(0, n).reduce((v, b) => 2 * v + b, 0);
  const controller = FAMILIES[take(2)];
  const width = take(5) + 1;
  const height = take(4) + 1;
  const want = codeLength(width, height);
  if (!controller) return { error: 'not a code of this page (a letter is wrong)' };
  if (values.length !== want) {
    return { error: `${values.length < want ? 'too short' : 'too long'}: ${values.length} letters, and a code whose first letters name a body of `
      + `${width} × ${height} voxels, as this one's do, has ${want}: ${codeForm(want)} (a letter ${values.length < want ? 'missing' : 'too many'}, or a wrong one at the start); `
      + `a 4 × 3 body's code has ${codeLength(4, 3)}: ${codeForm(codeLength(4, 3))}, like ${EXAMPLE_CODE}` };
  }
  if (checkLetter(values.slice(0, -1)) !== values.at(-1)) return { error: 'a letter is typed wrong (the last letter, a check of the others, does not match)' };
  const cells = bits.splice(0, width * height).join('');
  const speed = (take(SPEED_BITS) - SPEED_ZERO) / 100;
  const check = take(10);
  if (bits.some((b) => b !== 0)) return { error: 'a letter is typed wrong (its last bits should be zeros)' };
  const rows = Array.from({ length: height }, (_, i) => cells.slice(i * width, (i + 1) * width)).join('-');
  return { rows, controller, speed, check };
}
