// @ts-check
/**
 * The class's entries: every line of the teacher's compare box read with the page's own link
 * reader (keep/share.js), or as a short code (code.js), checked against the challenge's
 * rules (rules.js), a link's robot measured again by the page on the challenge's terrain
 * for its episode (lab.js: the speed a link claims is never trusted), then put in order.
 *
 * A short code is ranked at once by the speed the student's page measured, which it holds: that
 * speed is said as claimed, not checked. Checking it (checkCode) evolves the robot again here with
 * the challenge's run (13 to 27 s on a school laptop), compares the genome's check and measures it
 * again: from then on its speed is this page's own. A code checked once is not evolved again
 * (the caller keeps its genome, store.js).
 *
 * What the table says of an entry, and whether it gets a place:
 * - a rule broken (another body, more voxels, a budget over the challenge's), or a link that
 *   cannot be read or measured: no place, listed after the places with why;
 * - the same link pasted again: measured and placed once, under its first name; each later
 *   copy listed after the places as "the same link as <name>";
 * - for the teacher to judge, placed but said: no brain (the phase gait's clock, the student's
 *   own, drives it), a pretrained module unchanged or a brain built on one (evolved elsewhere
 *   first), a link made at another address of the page, and the same robot (body and genome,
 *   or body and clock) under two names (it races once).
 */
import { messageOf } from '../../workers/kit.js';
import { decodeState } from '../../keep/share.js';
import { genomeCheck, looksLikeCode, normalCode, readCode } from './code.js';
import { bodyProblem, budgetProblem, runSettings } from './rules.js';
import { decimal } from '../../shared/format.js';

/**
 * @typedef {object} Entry  one line of the compare box, read and measured
 * @property {string} name @property {string} rows @property {string} brain @property {number} speed  (NaN: not measured)
 * @property {string} problem  why it has no place ('' when it has one)
 * @property {string[]} notes  what the teacher should know of it, place or not
 * @property {string} robot  its body and genome, to find the same robot under another name ('' when unread)
 * @property {string} same  the name of the same robot raced in its place ('' when it races itself)
 * @property {{controller: string, genome: Float32Array} | null} genome
 * @property {string} code  a short code's one spelling ('' for a link)
 * @property {boolean} claimed  its speed is the one its code claims, not measured here (a code not checked yet)
 * @property {number} check  a short code's genome check (to compare once evolved again)
 */

/**
 * What an entry needs of the page: the lab (walks), the page's defaults, and the genomes of the
 * short codes checked before (by a code's one spelling; their robots are not evolved again).
 * @typedef {{lab: import('../lab.js').Lab, defaults: import('../../workers/core.js').Defaults,
 *   checked?: (code: string) => Float32Array | null}} Tools
 */

/**
 * The compare box's lines: a name (optional) and a link each.
 * @param {string} text @returns {{name: string, link: string}[]}
 */
export function linesOf(text) {
  return text.split('\n').map((l, i) => ({ line: l.trim(), number: i + 1 })).filter(({ line }) => line !== '').map(({ line, number }) => {
    // The link starts at its address or its #; a line with neither is read as a name and a
    // (broken) link, its last word, so that the table still says whose line it was.
    const found = line.search(/https?:\/\/|#/);
    const at = found >= 0 ? found : line.search(/\S+$/);
    const name = (at > 0 ? line.slice(0, at) : '').replace(/[\s:,-]+$/, '').trim();
    return { name: name || `line ${number} (no name)`, link: line.slice(Math.max(at, 0)) };
  });
}

/** The same page whatever its address's last step: `/` and `/index.html`. @param {string} path */
const pageOf = (path) => path.replace(/index\.html$/, '');

/** @param {string} name @returns {Entry} an entry with nothing read yet */
function blank(name) {
  return { name, rows: '', brain: '', speed: NaN, problem: '', notes: [], robot: '', same: '', genome: null, code: '', claimed: false, check: 0 };
}

/**
 * Every line read, checked and measured (a link pasted again is measured once), then in order:
 * the placed entries fastest first, then the others.
 * @param {string} text the compare box @param {import('./rules.js').Rules} r @param {Tools} tools
 * @returns {Promise<{placed: Entry[], others: Entry[]}>}
 */
export async function rankEntries(text, r, tools) {
  /** @type {Entry[]} */
  const entries = [];
  /** @type {Map<string, string>} a link's robot part → the name it was first pasted under */
  const pasted = new Map();
  for (const { name, link } of linesOf(text)) {
    const key = link.includes('#') ? link.slice(link.indexOf('#')) : looksLikeCode(link) ? normalCode(link) : link;
    const first = pasted.get(key);
    if (first !== undefined) {
      entries.push({ ...blank(name), problem: `the same link as ${first}: counted once, in ${first}'s row` });
      continue;
    }
    pasted.set(key, name);
    entries.push(await readEntry(name, link, r, tools));
  }
  return order(entries);
}

/**
 * Entries in order: the placed ones fastest first (a claimed speed as it claims), then the
 * others; the same robot under two names said (notes made afresh).
 * @param {Entry[]} entries @returns {{placed: Entry[], others: Entry[]}}
 */
export function order(entries) {
  for (const e of entries) { e.notes = e.notes.filter((n) => !SAME.test(n)); e.same = ''; }
  const placed = entries.filter((e) => !e.problem).sort((a, b) => b.speed - a.speed);
  const others = entries.filter((e) => e.problem);
  markSameRobots([...placed, ...others]);
  return { placed, others };
}

/** The notes markSameRobots writes (taken away before it writes them again). */
const SAME = /^(the same robot as .* under another name|raced once, as .*)$/;

/** Short codes in `placed` whose speed is claimed, not checked: the best first. @param {Entry[]} placed */
export function unchecked(placed) {
  return placed.filter((e) => e.claimed);
}

/**
 * Checks a short code's claimed entry: its robot evolved again with the challenge's run (or its
 * genome checked before), its check compared, then measured here. Gives the entry as it now is.
 * @param {Entry} entry @param {import('./rules.js').Rules} r @param {Tools} tools
 * @param {(settings: import('../../workers/protocol.js').EvolveSettings) => Promise<Float32Array>} evolve
 * @returns {Promise<Entry>}
 */
export async function checkCode(entry, r, { lab, defaults, checked }, evolve) {
  const claim = entry.speed;
  const base = { ...entry, claimed: false, notes: entry.notes.filter((n) => n !== CLAIMED) };
  /** @type {Float32Array} */
  let genome;
  const kept = checked?.(entry.code) ?? null;
  try {
    genome = kept ?? await evolve(runSettings(r, entry.rows, entry.brain));
  } catch (error) {
    if (error instanceof Error && error.name === 'AbortError') throw error; // stopped by the teacher: the entry stays claimed
    return { ...base, speed: NaN, problem: `could not be evolved again: ${messageOf(error)}` };
  }
  if (genomeCheck(genome) !== entry.check) {
    return { ...base, speed: NaN, problem: 'its check letters do not match the robot its body makes with the challenge\'s run '
      + `(a letter typed wrong, a run stopped early, or a robot made another way): ask ${entry.name} for the link` };
  }
  const brain = { controller: entry.brain, genome };
  const measured = { ...base, genome: brain, robot: robotKey(entry.rows, brain, defaults.gait),
    notes: [CHECKED, ...base.notes.filter((n) => n !== CHECKED)] };
  try {
    const walk = await lab.walk({ rows: entry.rows, terrain: r.terrain, seconds: r.seconds, brain });
    const differs = Math.abs(walk.speed - claim) > 0.005;
    return { ...measured, speed: walk.speed,
      notes: differs ? [...measured.notes, `its code claimed ${decimal(claim)} m/s: the speed measured here counts`] : measured.notes };
  } catch (error) {
    return { ...measured, speed: NaN, problem: `could not be measured: ${messageOf(error)}` };
  }
}

/** What the table says of a code's speed, claimed or checked. */
export const CLAIMED = 'short code: its speed as the student\'s page measured it, claimed, not checked here yet';
export const CHECKED = 'short code: checked (evolved again here with the challenge\'s run, the same robot to the bit, measured here)';

/**
 * The same robot (body and genome) under two names: each says so; the first in order races, the rest do not.
 * @param {Entry[]} ordered
 */
function markSameRobots(ordered) {
  /** @type {Map<string, Entry[]>} */
  const groups = new Map();
  for (const e of ordered) if (e.robot) groups.set(e.robot, [...(groups.get(e.robot) ?? []), e]);
  for (const group of groups.values()) {
    if (group.length < 2) continue;
    const [first] = group;
    for (const e of group) {
      const others = group.filter((o) => o !== e).map((o) => o.name).join(', ');
      e.notes.push(`the same robot as ${others} (same body and brain) under another name`);
      if (e !== first) e.same = first.name;
    }
    for (const e of group.slice(1)) if (!e.problem && e.genome) e.notes.push(`raced once, as ${first.name}`);
  }
}

/**
 * One line: its link read with the page's link reader, checked against the rules, measured.
 * @param {string} name @param {string} link @param {import('./rules.js').Rules} r @param {Tools} tools
 * @returns {Promise<Entry>}
 */
async function readEntry(name, link, r, tools) {
  if (looksLikeCode(link)) return readCodeEntry(name, link, r, tools);
  const { lab, defaults } = tools;
  const entry = blank(name);
  const hash = link.indexOf('#');
  if (hash < 0) {
    return { ...entry, problem: /[?&]challenge=/.test(link)
      ? `this is the challenge link, not a robot: ask ${name} to press “Share link” and send that link`
      : 'not a share link of this page (it has no robot after #), nor a short code' };
  }
  /** @type {URL} */
  let url;
  try { url = new URL(link, location.href); } catch { return { ...entry, problem: 'not a link' }; }
  const read = await decodeState(link.slice(hash), defaults.controllers, defaults.grid);
  if ('error' in read) return { ...entry, problem: `damaged link: ${read.error}` };
  const { state } = read;
  const brain = state.brain;
  // A brain that is a pretrained module, unchanged, was not evolved for the challenge; one built on a module was
  // evolved elsewhere first: both said, for the teacher to judge.
  const pretrained = brain ? await lab.pretrainedWith(brain.genome).catch(() => '') : '';
  const genome = brain ? { controller: brain.controller, genome: brain.genome } : null;
  const gait = state.gait ? gaitOf(state.gait) : defaults.gait; // the student's own clock, as their page walked it
  const notes = [
    url.origin + pageOf(url.pathname) === location.origin + pageOf(location.pathname) ? '' : `made at another address (${url.host}${url.pathname}), read all the same`,
    brain || read.damaged ? '' : 'no brain: the clock of the phase gait drives it, nothing evolved',
    pretrained ? `the pretrained module ${pretrained.replace(/\.json$/, '')}, unchanged: not evolved here`
      : brain?.module ? `built on the pretrained module ${brain.module.replace(/^pretrained\/|\.json$/g, '')}, evolved elsewhere${brain.oneShot ? ', transplanted and not fine-tuned' : ', then fine-tuned'}` : '',
  ].filter(Boolean);
  const named = { ...entry, rows: state.rows, brain: brain ? brain.controller : 'no brain (phase gait)', genome, notes };
  if (read.damaged) {
    return { ...named, brain: '', genome: null, problem: `its brain did not come through whole (${read.damaged}): the link seems cut short; ask ${name} to copy it again with “Share link”` };
  }
  const broken = bodyProblem(state.rows, r);
  if (broken) return { ...named, problem: broken };
  const measured = { ...named, robot: robotKey(state.rows, genome, gait), problem: budgetProblem(state.run.budget, r) };
  try {
    const walk = await lab.walk({ rows: state.rows, terrain: r.terrain, seconds: r.seconds,
      ...(genome ? { brain: genome } : { gait }) });
    return { ...measured, speed: walk.speed };
  } catch (error) {
    return { ...measured, problem: `could not be measured: ${messageOf(error)}` };
  }
}

/**
 * One line that is a short code: read, its body checked against the rules, placed by the speed
 * it claims (or, checked before, measured here at once).
 * @param {string} name @param {string} text @param {import('./rules.js').Rules} r @param {Tools} tools
 * @returns {Promise<Entry>}
 */
async function readCodeEntry(name, text, r, tools) {
  const entry = blank(name);
  const code = readCode(text);
  if ('error' in code) return { ...entry, problem: `not a short code (${code.error}): ask ${name} to type it again, or to send the link` };
  const named = { ...entry, rows: code.rows, brain: code.controller, code: normalCode(text), check: code.check };
  const broken = bodyProblem(code.rows, r);
  if (broken) return { ...named, problem: broken };
  const claimed = { ...named, speed: code.speed, claimed: true, notes: [CLAIMED] };
  if (tools.checked?.(claimed.code)) return checkCode(claimed, r, tools, () => Promise.reject(new Error('no evolution')));
  return claimed;
}

/** A share link's phase gait, "F,PHI" (checked by the link reader). @param {string} text */
function gaitOf(text) {
  const [frequency, phase] = text.split(',').map(Number);
  return { frequency, phase };
}

/**
 * A robot as text: its body and its brain's every bit, or the clock of its phase gait.
 * @param {string} rows @param {{controller: string, genome: Float32Array} | null} genome
 * @param {{frequency: number, phase: number}} gait
 */
function robotKey(rows, genome, gait) {
  if (!genome) return `${rows} gait ${gait.frequency} ${gait.phase}`;
  const bytes = new Uint8Array(genome.genome.buffer, genome.genome.byteOffset, genome.genome.byteLength);
  return `${rows} ${genome.controller} ${bytes.join('.')}`;
}
