// @ts-check
/**
 * A student's page under a challenge's rules: the page opened from a challenge link (rules.js)
 * shows the rules, and sets the playground up for them (the view, the run fixed, the body if
 * everyone uses one). A drawing that breaks the rules is said under the grid and beside Evolve,
 * and Evolve is off until it keeps them (problem, read by the run panel). After Share, the
 * robot's short code (code.js) under the link, when the robot is the challenge's run of its body.
 */
import { runGenome } from '../../workers/core.js';
import { byId } from '../../shared/dom.js';
import { messageOf } from '../../workers/kit.js';
import { robotCode } from './code.js';
import { bodyProblem, rulesOf, rulesParts, rulesWords, runOf, runSettings } from './rules.js';
import { decimal } from '../../shared/format.js';

/** @typedef {import('./rules.js').Rules} Rules */

export class StudentPage {
  /**
   * @param {Document} doc @param {import('../lab.js').Lab} lab
   * @param {{rows: () => string, setView: (terrain: string) => void,
   *   fixRun: (values: Record<string, string>) => void, setBody: (rows: string) => Promise<void>,
   *   message: (text: string) => void, pin: (text: string) => void, refresh: () => void,
   *   lastRun: () => {runFile: string | null, settings: import('../../workers/protocol.js').EvolveSettings | null, mode: string}}} page
   *   fixRun: the run settings every student's run uses, locked;
   *   refresh: the page's buttons set again (Evolve is off while the drawing breaks the rules);
   *   lastRun: the page's latest finished run (its run file), its settings and mode
   */
  constructor(doc, lab, page) {
    this.lab = lab;
    this.page = page;
    this.section = byId(doc, 'challenge-panel');
    this.rulesLine = byId(doc, 'challenge-rules');
    /** The student's short code, under the share link (code.js). */
    this.codeLine = byId(doc, 'challenge-code');
    /** What Evolve says while a student's drawing breaks the rules (beside the run's buttons). */
    this.runBlocked = byId(doc, 'run-blocked');
    /** The line under the grid that says which rule a student's drawing breaks, while it does. */
    this.warning = byId(doc, 'rule-warning');
    /** The grid, outlined while the drawing breaks the rules (the line under it may be off a phone's screen). */
    this.grid = byId(doc, 'editor');
    /** @type {Rules | null} the rules of the challenge link this page was opened from (a student's page) */
    this.opened = rulesOf(location.search);
  }

  /** Opens a challenge link's rules: shows them and sets the playground up. */
  async begin() {
    const r = this.opened;
    if (!r) return;
    this.section.dataset.mode = 'student';
    this.showRules(r);
    // The rules at the top as well, where a student opening the link looks first (the panel is far down).
    this.page.pin(`${rulesWords(r)} (The rules are also under “Class challenge”, further down.)`);
    this.page.setView(r.terrain);
    this.page.fixRun(runOf(r)); // everyone's run the same, trained over the walks it is measured on
    if (r.body) await this.page.setBody(r.body).catch((error) => this.page.message(`the challenge's body: ${messageOf(error)}`));
    this.watch(this.page.rows()); // the drawing kept from an earlier visit may already break the rules
    this.page.refresh();
  }

  /** A new challenge made on this page: its drawing is the teacher's, no longer held to the rules it was opened with. */
  leave() {
    this.opened = null;
    this.warning.hidden = true;
    this.grid.classList.remove('breaks-rules');
    this.runBlocked.hidden = true;
    this.page.refresh(); // Evolve free again: this page's drawing is the teacher's
  }

  /**
   * A student's drawing changed: a body that breaks the challenge's rules is said at once, under
   * the grid, for as long as it does (not only in the teacher's table). @param {string} rows
   */
  watch(rows) {
    if (!this.opened || this.section.dataset.mode !== 'student') return;
    const problem = this.problem(rows);
    // Under the grid, not above it: a line that appeared above would move the grid under the student's finger.
    this.warning.textContent = problem ? `Your robot breaks the challenge's rules: ${problem}. Your teacher's ranking will not count it, and Evolve is off until it keeps them: change the drawing (Undo goes back a step).` : '';
    this.warning.hidden = !problem;
    this.grid.classList.toggle('breaks-rules', problem !== '');
    // Beside Evolve as well, for as long as the drawing breaks them (the run panel turns Evolve off: main.js).
    this.runBlocked.textContent = problem ? `Evolve is off: your robot breaks the challenge's rules (${problem}). Change the drawing under “1 · Draw” to keep them.` : '';
    this.runBlocked.hidden = !problem;
  }

  /**
   * Why a student's drawing may not be evolved in the challenge this page was opened from ('' when
   * it may, or when there is no challenge). @param {string} rows
   */
  problem(rows) {
    if (!this.opened || this.section.dataset.mode !== 'student' || !rows) return '';
    return bodyProblem(rows, this.opened);
  }

  /**
   * After Share in a challenge: the robot's short code under the link, when the robot is the
   * challenge's run of its body (the page's latest run, from scratch with the challenge's
   * settings, finished, its best the brain shared); else why it has none (the link still counts).
   * @param {import('../../keep/share.js').PageState} state what the link holds
   */
  async shared(state) {
    const r = this.opened;
    if (!r || this.section.dataset.mode !== 'student') return;
    const last = this.page.lastRun();
    const brain = state.brain;
    const want = runSettings(r, state.rows, brain?.controller ?? '');
    const sameRun = last.settings !== null && Object.entries(want).every(([k, v]) => String(last.settings?.[/** @type {keyof typeof want} */ (k)]) === String(v));
    /** @type {{generations?: {evaluations: number}[]} | null} */
    let file = null;
    try { file = last.runFile ? JSON.parse(last.runFile) : null; } catch { file = null; }
    const spent = file?.generations?.at(-1)?.evaluations ?? 0;
    /** @param {Float32Array} g */
    const same = (g) => !!brain && g.length === brain.genome.length && g.every((x, i) => Object.is(x, brain.genome[i]));
    const why = !brain ? 'your robot has no brain yet: press Evolve first'
      : brain.module ? 'its brain was not evolved here for the challenge'
        : this.lab.latestRun().running ? 'the run is still going: share again once it has finished'
          : !last.runFile || last.mode !== 'evolve' || !sameRun ? 'its brain is not the challenge\'s run of the body drawn now (was the body changed after the run?)'
            : spent < want.budget ? 'the run was stopped before its end: press Evolve again and let it finish'
              : !same(await runGenome(last.runFile)) ? 'its brain is not the run\'s result (was it edited?)' : '';
    // The speed in the code: the robot walked as the teacher's page walks it (the challenge's terrain and walk).
    const speed = why || !brain ? NaN
      : await this.lab.walk({ rows: state.rows, terrain: r.terrain, seconds: r.seconds, brain: { controller: brain.controller, genome: brain.genome } })
        .then((w) => w.speed, () => NaN);
    const code = why || !brain ? null : robotCode(state.rows, brain.controller, brain.genome, speed);
    this.codeLine.dataset.code = code ?? '';
    if (code) {
      // The code itself large and in a typewriter's letters, where a student copying it looks (0 and O read the same: code.js).
      const letters = this.section.ownerDocument.createElement('span');
      letters.className = 'short-code';
      letters.textContent = code;
      this.codeLine.replaceChildren('Your short code: ', letters, ` (your robot's speed over ${r.seconds} s on ${r.terrain}: ${decimal(speed)} m/s, in the code). `
        + 'Give your teacher this code (or the link): their page ranks it by that speed and can check it by evolving your robot again, exactly.');
    } else {
      this.codeLine.textContent = `No short code for this robot (${why || (Number.isFinite(speed) ? 'a body too large for a code' : 'its speed could not be measured')}): send your teacher the link.`;
    }
    this.codeLine.hidden = false;
  }

  /**
   * The rules where a student reads them, short enough for a phone: the goal, three numbered
   * steps, and the details folded. @param {Rules} r @param {string} [lead] words before them (the teacher's)
   */
  showRules(r, lead = '') {
    const doc = this.section.ownerDocument;
    const { goal, steps, details } = rulesParts(r);
    const head = doc.createElement('p');
    head.className = 'challenge-goal';
    head.textContent = `${lead}${goal}`;
    const list = doc.createElement('ol');
    list.className = 'challenge-steps';
    list.append(...steps.map((step) => { const li = doc.createElement('li'); li.textContent = step; return li; }));
    const more = doc.createElement('details');
    more.className = 'challenge-details';
    const summary = doc.createElement('summary');
    summary.textContent = 'The details';
    const text = doc.createElement('p');
    text.textContent = details;
    more.append(summary, text);
    this.rulesLine.replaceChildren(head, list, more);
    this.rulesLine.hidden = false;
  }
}
