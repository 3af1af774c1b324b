// @ts-check
/**
 * The class's entries: every line of the teacher's compare box read with the page's own link
 * reader (share.js), checked against the challenge's rules (challenge-rules.js), its robot
 * measured again by the page on the challenge's terrain for its episode (lab.js: the speed the
 * link claims is never trusted), then put in order.
 *
 * What the table says of an entry, and whether it gets a place:
 * - a rule broken (another body, more voxels, a budget over the challenge's), or a link that
 *   cannot be read or measured: no place, listed after the places with why;
 * - the same link pasted again: measured and placed once, under its first name; each later
 *   copy listed after the places as "the same link as <name>";
 * - for the teacher to judge, placed but said: a pretrained module unchanged (not evolved for
 *   the challenge), and the same robot (body and genome) under two names (it races once).
 */
import { messageOf } from '../kit.js';
import { decodeState } from '../share.js';
import { bodyProblem, budgetProblem } from './challenge-rules.js';

/**
 * @typedef {object} Entry  one line of the compare box, read and measured
 * @property {string} name @property {string} rows @property {string} brain @property {number} speed  (NaN: not measured)
 * @property {string} problem  why it has no place ('' when it has one)
 * @property {string[]} notes  what the teacher should know of it, place or not
 * @property {string} robot  its body and genome, to find the same robot under another name ('' when unread)
 * @property {string} same  the name of the same robot raced in its place ('' when it races itself)
 * @property {{controller: string, genome: Float32Array} | null} genome
 */

/** What an entry needs of the page. @typedef {{lab: import('./lab.js').Lab, defaults: import('../core.js').Defaults}} Tools */

/**
 * The compare box's lines: a name (optional) and a link each.
 * @param {string} text @returns {{name: string, link: string}[]}
 */
export function linesOf(text) {
  return text.split('\n').map((l) => l.trim()).filter((l) => l !== '').map((line, i) => {
    // The link starts at its address or its #; a line with neither is read as a name and a
    // (broken) link, its last word, so that the table still says whose line it was.
    const found = line.search(/https?:\/\/|#/);
    const at = found >= 0 ? found : line.search(/\S+$/);
    const name = (at > 0 ? line.slice(0, at) : '').replace(/[\s:,-]+$/, '').trim();
    return { name: name || `entry ${i + 1}`, link: line.slice(Math.max(at, 0)) };
  });
}

/** @param {string} name @returns {Entry} an entry with nothing read yet */
function blank(name) {
  return { name, rows: '', brain: '', speed: NaN, problem: '', notes: [], robot: '', same: '', genome: null };
}

/**
 * Every line read, checked and measured (a link pasted again is measured once), then in order:
 * the placed entries fastest first, then the others.
 * @param {string} text the compare box @param {import('./challenge-rules.js').Rules} r @param {Tools} tools
 * @returns {Promise<{placed: Entry[], others: Entry[]}>}
 */
export async function rankEntries(text, r, tools) {
  /** @type {Entry[]} */
  const entries = [];
  /** @type {Map<string, string>} a link's robot part → the name it was first pasted under */
  const pasted = new Map();
  for (const { name, link } of linesOf(text)) {
    const key = link.includes('#') ? link.slice(link.indexOf('#')) : link;
    const first = pasted.get(key);
    if (first !== undefined) {
      entries.push({ ...blank(name), problem: `the same link as ${first}: counted once, in ${first}'s row` });
      continue;
    }
    pasted.set(key, name);
    entries.push(await readEntry(name, link, r, tools));
  }
  const placed = entries.filter((e) => !e.problem).sort((a, b) => b.speed - a.speed);
  const others = entries.filter((e) => e.problem);
  markSameRobots([...placed, ...others]);
  return { placed, others };
}

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
    for (const e of group.slice(1)) if (!e.problem) e.notes.push(`raced once, as ${first.name}`);
  }
}

/**
 * One line: its link read with the page's link reader, checked against the rules, measured.
 * @param {string} name @param {string} link @param {import('./challenge-rules.js').Rules} r @param {Tools} tools
 * @returns {Promise<Entry>}
 */
async function readEntry(name, link, r, { lab, defaults }) {
  const entry = blank(name);
  const hash = link.indexOf('#');
  if (hash < 0) return { ...entry, problem: 'not a share link of this page (it has no robot after #)' };
  try {
    const url = new URL(link, location.href);
    if (url.origin !== location.origin || url.pathname !== location.pathname) {
      return { ...entry, problem: `a link to another page (${url.host}${url.pathname}), not this playground's` };
    }
  } catch { return { ...entry, problem: 'not a link' }; }
  const read = await decodeState(link.slice(hash), defaults.controllers, defaults.grid);
  if ('error' in read) return { ...entry, problem: `damaged link: ${read.error}` };
  const { state } = read;
  const brain = state.brain;
  // A brain that is a pretrained module, unchanged, was not evolved for the challenge: said, for the teacher to judge.
  const pretrained = brain ? await lab.pretrainedWith(brain.genome).catch(() => '') : '';
  const genome = brain ? { controller: brain.controller, genome: brain.genome } : null;
  const named = { ...entry, rows: state.rows, brain: brain ? brain.controller : 'no brain (phase gait)', genome,
    notes: pretrained ? [`the pretrained module ${pretrained.replace(/\.json$/, '')}, unchanged: not evolved here`] : [] };
  if (read.damaged) return { ...named, problem: `its brain is damaged: ${read.damaged}` };
  const broken = bodyProblem(state.rows, r);
  if (broken) return { ...named, problem: broken };
  const measured = { ...named, robot: robotKey(state.rows, genome), problem: budgetProblem(state.run.budget, r) };
  try {
    const walk = await lab.walk({ rows: state.rows, terrain: r.terrain, seconds: r.seconds,
      ...(genome ? { brain: genome } : { gait: defaults.gait }) });
    return { ...measured, speed: walk.speed };
  } catch (error) {
    return { ...measured, problem: `could not be measured: ${messageOf(error)}` };
  }
}

/**
 * A robot as text: its body and its brain's every bit (the phase gait is the page's, the same for all).
 * @param {string} rows @param {{controller: string, genome: Float32Array} | null} genome
 */
function robotKey(rows, genome) {
  if (!genome) return `${rows} gait`;
  const bytes = new Uint8Array(genome.genome.buffer, genome.genome.byteOffset, genome.genome.byteLength);
  return `${rows} ${genome.controller} ${bytes.join('.')}`;
}
