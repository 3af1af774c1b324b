// @ts-check
/**
 * A class challenge without a server. The teacher fixes the rules (a terrain, an episode, a
 * largest body or one fixed body, the run's budget and seed) in a challenge link
 * (`?challenge=1&terrain=...`: a query, so it never meets the share link's `#...`); opening it
 * sets the playground up for them. A student's entry is an ordinary share link. The teacher
 * pastes the class's links (one a line, a name before each if wanted) into the compare box:
 * every link is read with the page's own link reader (share.js), its robot measured again by
 * the page on the challenge's terrain for its episode (lab.js: the speed the link claims is
 * never trusted), and ranked; a damaged, foreign or rule-breaking link is named in the table
 * and the rest are kept. The best four with a brain race side by side.
 */
import { messageOf } from '../kit.js';
import { decodeState } from '../share.js';
import { count, decimal } from '../format.js';

/** The challenge link's query parameters. */
const KEYS = Object.freeze(['terrain', 'seconds', 'voxels', 'body', 'budget', 'seed']);

/** @typedef {{terrain: string, seconds: number, voxels: number | null, body: string | null, budget: string, seed: string}} Rules */
/**
 * @typedef {object} Entry  one line of the compare box, read and measured
 * @property {string} name @property {string} rows @property {string} brain @property {number} speed
 * @property {string} problem  why it is not ranked ('' when it is)
 * @property {{controller: string, genome: Float32Array} | null} genome
 */

/**
 * The rules a challenge link holds, or null when the address has none.
 * @param {string} search a location's query @returns {Rules | null}
 */
export function rulesOf(search) {
  const p = new URLSearchParams(search);
  if (!p.has('challenge')) return null;
  const voxels = Number(p.get('voxels'));
  return { terrain: p.get('terrain') || 'hilly-1-10-0', seconds: Number(p.get('seconds')) || 30,
    voxels: Number.isInteger(voxels) && voxels > 0 ? voxels : null, body: p.get('body') || null,
    budget: p.get('budget') || '2000', seed: p.get('seed') || '1' };
}

/** The challenge link of `rules` on this page. @param {Rules} rules */
export function challengeLink(rules) {
  const url = new URL(location.href);
  url.search = '';
  url.hash = '';
  url.searchParams.set('challenge', '1');
  for (const k of KEYS) {
    const v = rules[/** @type {keyof Rules} */ (k)];
    if (v !== null && v !== '') url.searchParams.set(k, String(v));
  }
  return url.href;
}

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

/**
 * Why a body breaks the rules `r` ('' when it keeps them): the one check of the teacher's
 * ranking and of the student's drawing. @param {string} rows @param {Rules} r
 */
export function bodyProblem(rows, r) {
  const voxels = rows.split('').filter((c) => c === '1').length;
  if (r.body && rows !== r.body) return `not the challenge's body (${r.body})`;
  if (r.voxels && voxels > r.voxels) return `${voxels} voxels, more than the challenge's ${r.voxels}`;
  return '';
}

export class Challenge {
  /**
   * @param {Document} doc @param {import('./lab.js').Lab} lab
   * @param {{defaults: import('../core.js').Defaults, rows: () => string, setView: (terrain: string) => void,
   *   setRun: (values: Record<string, string>) => void, setBody: (rows: string) => Promise<void>,
   *   race: import('../race.js').Race, message: (text: string) => void, pin: (text: string) => void}} page
   */
  constructor(doc, lab, page) {
    this.doc = doc;
    this.lab = lab;
    this.page = page;
    const el = (/** @type {string} */ id) => /** @type {any} */ (doc.getElementById(id));
    this.section = /** @type {HTMLElement} */ (el('challenge-panel'));
    this.rulesLine = /** @type {HTMLElement} */ (el('challenge-rules'));
    this.form = { terrain: el('challenge-terrain'), seconds: el('challenge-seconds'), voxels: el('challenge-voxels'),
      fixed: el('challenge-fixed'), budget: el('challenge-budget'), seed: el('challenge-seed') };
    this.linkOut = /** @type {HTMLInputElement} */ (el('challenge-link'));
    this.box = /** @type {HTMLTextAreaElement} */ (el('challenge-compare'));
    this.table = /** @type {HTMLTableElement} */ (el('challenge-table'));
    this.raceButton = /** @type {HTMLButtonElement} */ (el('challenge-race'));
    /** @type {Entry[]} */
    this.ranked = [];
    this.rules = rulesOf(location.search);
    /** The line under the grid that says which rule a student's drawing breaks, while it does. */
    this.warning = /** @type {HTMLElement} */ (el('rule-warning'));
    el('challenge-make').addEventListener('click', () => this.make());
    el('challenge-rank').addEventListener('click', () => this.rank());
    this.raceButton.addEventListener('click', () => this.raceBest());
    this.raceButton.disabled = true;
  }

  /** The rules in force: the challenge link's, else the form's. @returns {Rules} */
  current() {
    if (this.rules) return this.rules;
    const f = this.form;
    const voxels = Number(f.voxels.value);
    return { terrain: f.terrain.value.trim() || 'hilly-1-10-0', seconds: Number(f.seconds.value) || 30,
      voxels: Number.isInteger(voxels) && voxels > 0 ? voxels : null, body: f.fixed.checked ? this.page.rows() : null,
      budget: f.budget.value.trim() || '2000', seed: f.seed.value.trim() || '1' };
  }

  /** The rules in words. @param {Rules} r */
  words(r) {
    const body = r.body ? `the body ${r.body}` : r.voxels ? `any body of at most ${r.voxels} voxels` : 'any body';
    return `Challenge: ${body}; speed measured over ${r.seconds} s on ${r.terrain}; evolve with ${Number.isFinite(Number(r.budget)) ? count(Number(r.budget)) : r.budget} evaluations, seed ${r.seed} (the number that fixes evolution's random draws). `
      + `Under your robot the speed is over the page's episode; your teacher measures it again over ${r.seconds} s on ${r.terrain}, so it may differ. `
      + 'When your robot walks, press “Share link” and send the link to your teacher.';
  }

  /** Opens a challenge link's rules: shows them and sets the playground up. */
  async begin() {
    const r = this.rules;
    if (!r) return;
    this.section.dataset.mode = 'student';
    this.rulesLine.textContent = this.words(r);
    this.rulesLine.hidden = false;
    // The rules at the top as well, where a student opening the link looks first (the panel is far down).
    this.page.pin(`${this.words(r)} (The rules are also under “Class challenge”, further down.)`);
    this.page.setView(r.terrain);
    this.page.setRun({ budget: r.budget, seed: r.seed });
    if (r.body) await this.page.setBody(r.body).catch((error) => this.page.message(`the challenge's body: ${messageOf(error)}`));
  }

  /**
   * A student's drawing changed: a body that breaks the challenge's rules is said at once, under
   * the grid, for as long as it does (not only in the teacher's table). @param {string} rows
   */
  watch(rows) {
    if (!this.rules || this.section.dataset.mode !== 'student') return;
    const problem = rows ? bodyProblem(rows, this.rules) : '';
    // Under the grid, not above it: a line that appeared above would move the grid under the student's finger.
    this.warning.textContent = problem ? `Your robot breaks the challenge's rules: ${problem}. Your teacher's ranking will not count it: change the drawing (Undo goes back a step).` : '';
    this.warning.hidden = !problem;
  }

  /** Makes the challenge link of the form's rules. */
  make() {
    this.rules = null;
    const r = this.current();
    this.linkOut.value = challengeLink(r);
    this.linkOut.hidden = false;
    this.rulesLine.textContent = this.words(r);
    this.rulesLine.hidden = false;
  }

  /** Reads, measures and ranks every line of the compare box. */
  async rank() {
    const r = this.current();
    const lines = linesOf(this.box.value);
    this.section.dataset.state = 'ranking';
    /** @type {Entry[]} */
    const entries = [];
    for (const { name, link } of lines) entries.push(await this.entry(name, link, r));
    const ok = entries.filter((e) => !e.problem).sort((a, b) => b.speed - a.speed);
    this.ranked = ok;
    this.show([...ok, ...entries.filter((e) => e.problem)], r);
    this.raceButton.disabled = ok.filter((e) => e.genome).length === 0;
    this.section.dataset.state = 'ranked';
  }

  /**
   * One line: its link read with the page's link reader, checked against the rules, measured.
   * @param {string} name @param {string} link @param {Rules} r @returns {Promise<Entry>}
   */
  async entry(name, link, r) {
    const entry = { name, rows: '', brain: '', speed: NaN, problem: '', genome: null };
    const hash = link.indexOf('#');
    if (hash < 0) return { ...entry, problem: 'not a share link of this page (it has no robot after #)' };
    try {
      const url = new URL(link, location.href);
      if (url.origin !== location.origin || url.pathname !== location.pathname) {
        return { ...entry, problem: `a link to another page (${url.host}${url.pathname}), not this playground's` };
      }
    } catch { return { ...entry, problem: 'not a link' }; }
    const read = await decodeState(link.slice(hash), this.page.defaults.controllers, this.page.defaults.grid);
    if ('error' in read) return { ...entry, problem: `damaged link: ${read.error}` };
    const { state } = read;
    const brain = state.brain;
    // A brain that is a pretrained module, unchanged, was not evolved for the challenge: said, for the teacher to judge.
    const pretrained = brain ? await this.lab.pretrainedWith(brain.genome).catch(() => '') : '';
    const named = { ...entry, rows: state.rows,
      brain: brain ? `${brain.controller}${pretrained ? ` (the pretrained module ${pretrained.replace(/\.json$/, '')}, unchanged: not evolved here)` : ''}` : 'no brain (phase gait)',
      genome: brain ? { controller: brain.controller, genome: brain.genome } : null };
    if (read.damaged) return { ...named, problem: `its brain is damaged: ${read.damaged}` };
    const broken = bodyProblem(state.rows, r);
    if (broken) return { ...named, problem: broken };
    try {
      const walk = await this.lab.walk({ rows: state.rows, terrain: r.terrain, seconds: r.seconds,
        ...(named.genome ? { brain: named.genome } : { gait: this.page.defaults.gait }) });
      return { ...named, speed: walk.speed };
    } catch (error) {
      return { ...named, problem: `could not be measured: ${messageOf(error)}` };
    }
  }

  /** The table: ranked entries, then those with a problem. @param {Entry[]} rows @param {Rules} r */
  show(rows, r) {
    const doc = this.doc;
    const t = this.table;
    t.replaceChildren();
    t.hidden = false;
    t.createCaption().textContent = `Speeds measured again by this page: ${r.seconds} s on ${r.terrain}.`;
    const head = t.createTHead().insertRow();
    for (const h of ['place', 'name', 'body', 'brain', 'speed']) {
      const th = doc.createElement('th');
      th.textContent = h;
      head.append(th);
    }
    const body = t.createTBody();
    let place = 0;
    for (const e of rows) {
      const row = body.insertRow();
      row.dataset.testid = 'challenge-entry';
      row.dataset.problem = String(e.problem !== '');
      const cells = e.problem
        ? ['–', e.name, e.rows || '–', e.brain || '–', e.problem]
        : [String(++place), e.name, e.rows, e.brain, `${decimal(e.speed)} m/s`];
      for (const c of cells) row.insertCell().textContent = c;
      if (!e.problem) row.cells[4].dataset.value = String(e.speed);
    }
  }

  /** Races the best four entries that have a brain, on the challenge's terrain. */
  raceBest() {
    const r = this.current();
    this.page.setView(r.terrain);
    const race = this.page.race;
    race.clear();
    race.seconds.value = String(r.seconds);
    for (const e of this.ranked.filter((x) => x.genome).slice(0, 4)) {
      const g = /** @type {{controller: string, genome: Float32Array}} */ (e.genome);
      race.add({ label: e.name, shape: e.rows, controller: g.controller, genome: g.genome });
    }
    race.section.scrollIntoView({ block: 'start', behavior: 'instant' });
  }
}
