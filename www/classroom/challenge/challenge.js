// @ts-check
/**
 * A class challenge without a server. The teacher fixes the rules (rules.js) and makes
 * a challenge link; opening it sets the playground up for a student. A student's entry is an
 * ordinary share link. The teacher pastes the class's links (one a line, a name before each if
 * wanted) into the compare box, and the page ranks them (entries.js) by the rules of
 * the link the teacher made (or of the challenge link the page was opened from): never by the
 * form or the drawing as they are when Rank is pressed, which may have changed since. A student
 * may hand in a short code instead (code.js): ranked at once by the speed it claims,
 * said as claimed; Rank then checks the best four (each evolved again here, 13 to 27 s on a
 * school laptop, said before it starts, its progress shown, stoppable), and “Check every code”
 * the rest. The rules made, the links and codes pasted and the codes checked are kept for the
 * teacher's next visit (store.js) until “Clear the class's entries”. The best four
 * with a brain race side by side. A student's drawing that breaks the rules is said under the
 * grid, and Evolve is off until it keeps them (problem, read by the run panel).
 */
import { checkTerrain, runGenome } from '../../workers/core.js';
import { byId } from '../../shared/dom.js';
import { messageOf } from '../../workers/kit.js';
import { terrainRefused } from '../../viewer/terrain-words.js';
import { checkCode, linesOf, order, rankEntries, unchecked } from './entries.js';
import { EXAMPLE_CODE, looksLikeCode, normalCode, readCode, robotCode } from './code.js';
import { evolveAgain } from './evolve.js';
import { RUN_DEFAULTS, bodyProblem, challengeLink, rankingWords, rulesFrom, rulesOf, rulesParts, rulesWords, runOf, runSettings, sameRules } from './rules.js';
import { loadQr, qrBox } from '../qr.js';
import { onlyHere } from '../sheet-address.js';
import { durationWords } from '../../runs/progress.js';
import { decimal } from '../../shared/format.js';
import { checkKey, genomeOf, genomeText, keepChallenge, loadChallenge } from './store.js';
import { showRanking } from './table.js';

/** @typedef {import('./rules.js').Rules} Rules */
/** @typedef {import('./entries.js').Entry} Entry */

/** How many of the best Rank checks at once: the race's four. */
const BEST = 4;

export class Challenge {
  /**
   * @param {Document} doc @param {import('../lab.js').Lab} lab
   * @param {{defaults: import('../../workers/core.js').Defaults, rows: () => string, setView: (terrain: string) => void,
   *   fixRun: (values: Record<string, string>) => void, setBody: (rows: string) => Promise<void>,
   *   race: import('../../viewer/race.js').Race, message: (text: string) => void, pin: (text: string) => void,
   *   runSeconds: (settings: import('../../workers/protocol.js').EvolveSettings) => number, refresh: () => void,
   *   lastRun: () => {runFile: string | null, settings: import('../../workers/protocol.js').EvolveSettings | null, mode: string}}} page
   *   fixRun: the run settings every student's run uses, locked; runSeconds: how long a run takes here (NaN: not known);
   *   refresh: the page's buttons set again (Evolve is off while the drawing breaks the rules);
   *   lastRun: the page's latest finished run (its run file), its settings and mode
   */
  constructor(doc, lab, page) {
    this.lab = lab;
    this.page = page;
    this.section = byId(doc, 'challenge-panel');
    this.teacher = /** @type {HTMLDetailsElement} */ (this.section.querySelector('details.challenge-teacher'));
    this.teacher.addEventListener('toggle', () => void loadQr(), { once: true }); // the challenge link's QR code, drawn at once
    this.rulesLine = byId(doc, 'challenge-rules');
    this.form = { terrain: byId(doc, 'challenge-terrain', HTMLInputElement), seconds: byId(doc, 'challenge-seconds', HTMLInputElement), voxels: byId(doc, 'challenge-voxels', HTMLInputElement),
      fixed: byId(doc, 'challenge-fixed', HTMLInputElement), budget: byId(doc, 'challenge-budget', HTMLInputElement), seed: byId(doc, 'challenge-seed', HTMLInputElement) };
    this.linkOut = byId(doc, 'challenge-link', HTMLInputElement);
    this.linkBox = byId(doc, 'challenge-link-box');
    /** The made link's QR code, for the projector, and the line that says when no student can open the link. */
    this.qr = byId(doc, 'challenge-qr');
    this.addressNote = byId(doc, 'challenge-address-note');
    /** The student's short code, under the share link (code.js). */
    this.codeLine = byId(doc, 'challenge-code');
    this.box = byId(doc, 'challenge-compare', HTMLTextAreaElement);
    this.status = byId(doc, 'challenge-status');
    this.table = byId(doc, 'challenge-table', HTMLTableElement);
    this.rankButton = byId(doc, 'challenge-rank', HTMLButtonElement);
    this.raceButton = byId(doc, 'challenge-race', HTMLButtonElement);
    /** Checks every short code not checked yet; stops the checking; forgets the class's entries. */
    this.checkButton = byId(doc, 'challenge-check', HTMLButtonElement);
    this.stopButton = byId(doc, 'challenge-stop', HTMLButtonElement);
    this.clearButton = byId(doc, 'challenge-clear', HTMLButtonElement);
    /** How long ranking the box's lines will take, said as they are pasted. */
    this.estimate = byId(doc, 'challenge-estimate');
    /** What Evolve says while a student's drawing breaks the rules (beside the run's buttons). */
    this.runBlocked = byId(doc, 'run-blocked');
    this.box.placeholder = `Ana ${EXAMPLE_CODE}\nBen https://…#shape=…`; // a real code (code.js)
    /** The line under the grid that says which rule a student's drawing breaks, while it does. */
    this.warning = byId(doc, 'rule-warning');
    /** The grid, outlined while the drawing breaks the rules (the line under it may be off a phone's screen). */
    this.grid = byId(doc, 'editor');
    /** @type {Entry[]} the placed entries of the last ranking, fastest first */
    this.ranked = [];
    /** @type {Entry[]} every entry of the last ranking, placed or not */
    this.entries = [];
    /** The last ranking's caption. */
    this.caption = '';
    /** @type {AbortController | null} the checking under way */
    this.checking = null;
    /** @type {Rules | null} the rules of the last ranking */
    this.rankedBy = null;
    /** @type {Rules | null} the rules of the challenge link this page was opened from (a student's page) */
    this.opened = rulesOf(location.search);
    /** @type {{population: number, train: string}} the run the form's challenge fixes beyond the form's fields (a new link keeps them) */
    this.formRun = { population: RUN_DEFAULTS.population, train: RUN_DEFAULTS.train };
    const kept = loadChallenge();
    /** @type {Rules | null} the rules of the challenge link the teacher made, as they were when it was made */
    this.made = kept.rules;
    /** @type {Record<string, string>} the genomes of the short codes checked here, by checkKey */
    this.checked = kept.checked ?? {};
    /** Whether the last keep failed (said once, not at every key). */
    this.unkept = false;
    /** @type {ReturnType<typeof setTimeout> | undefined} the estimate said again once this computer's pace is known */
    this.estimateTimer = undefined;
    /** How long a short code took to check here, on average (s; 0 before the first). */
    this.tookPerCode = 0;
    byId(doc, 'challenge-make', HTMLButtonElement).addEventListener('click', () => { this.make().catch((error) => this.say(`The challenge link could not be made: ${messageOf(error)}`)); });
    this.rankButton.addEventListener('click', () => this.rank());
    this.raceButton.addEventListener('click', () => this.raceBest());
    this.checkButton.addEventListener('click', () => this.checkAll());
    this.stopButton.addEventListener('click', () => this.checking?.abort());
    this.clearButton.addEventListener('click', () => this.clear());
    this.box.addEventListener('input', () => { this.keep(); this.showEstimate(); });
    this.raceButton.disabled = true;
    this.checkButton.disabled = true;
    this.stopButton.hidden = true;
    this.restore(kept.links);
  }

  /**
   * The form's rules, with the robot drawn now if everyone is to use it; the population and the
   * training terrain (not in the form) those of the challenge the form shows. @returns {Rules}
   */
  formRules() {
    const f = this.form;
    return rulesFrom({ terrain: f.terrain.value, seconds: f.seconds.value, voxels: f.voxels.value,
      body: f.fixed.checked ? this.page.rows() : null, budget: f.budget.value, seed: f.seed.value, ...this.formRun });
  }

  /** The challenge in force in the form: what a new link starts from. @param {Rules} r */
  showInForm(r) {
    const f = this.form;
    f.terrain.value = r.terrain;
    f.seconds.value = String(r.seconds);
    f.voxels.value = r.voxels === null ? '' : String(r.voxels);
    f.budget.value = r.budget;
    f.seed.value = r.seed;
    f.fixed.checked = r.body !== null;
    this.formRun = { population: r.population, train: r.train };
  }

  /**
   * The rules a class is ranked by, and where they come from, in words: the challenge link's
   * this page was opened from, else the teacher's made link's, else (no link yet) the form's.
   * @returns {{rules: Rules, source: string}}
   */
  rankingRules() {
    if (this.opened) return { rules: this.opened, source: 'Ranked by the rules of the challenge link this page was opened from' };
    if (this.made) return { rules: this.made, source: 'Ranked by the rules of the challenge link you made' };
    return { rules: this.formRules(), source: 'No challenge link made yet, so ranked by the rules in the form above' };
  }

  /** The teacher's challenge from their last visit, back in the form and the compare box. @param {string} links */
  restore(links) {
    if (links) this.box.value = links;
    const made = this.made;
    setTimeout(() => this.showEstimate(), 0); // the lines kept, counted (once the form holds the kept rules)
    // The form shows the challenge in force, never its defaults: the link this page was opened from (a teacher may open
    // it on the projector's laptop, to show its QR code and rank the class), else the one made here.
    if (this.opened) {
      this.showInForm(this.opened);
      this.showLink(this.opened);
      // The teacher's own link, opened again (on the projector's laptop): its QR code and link in sight at once.
      if (made && sameRules(this.opened, made)) this.teacher.open = true;
    } else if (made) {
      this.showInForm(made);
      this.showMade(made);
    }
    if (this.opened || (!made && !links)) return;
    const count = linesOf(links).length;
    const checks = Object.keys(this.checked).length;
    const back = [made ? 'the challenge link you made' : '', count ? `the class's ${count} link${count === 1 ? '' : 's'} and code${count === 1 ? '' : 's'}` : '',
      checks ? `${checks} short code${checks === 1 ? '' : 's'} already checked (not evolved again)` : ''].filter(Boolean).join(', ');
    this.say(`Back from your last visit: ${back}.${count ? ' Press “Rank the class” to rank them again, or “Clear the class\'s entries” to start a new class.' : ''}`);
    this.teacher.open = true;
  }

  /** Keeps the made rules and the pasted links for the next visit; says once if it cannot. */
  keep() {
    const why = keepChallenge({ rules: this.made, links: this.box.value, checked: this.checked });
    if (why && !this.unkept) this.say(`Note: ${why}.`);
    this.unkept = why !== '';
  }

  /** A line for the teacher above the table ('' hides it). @param {string} text */
  say(text) {
    this.status.textContent = text;
    this.status.hidden = text === '';
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
   * Makes the challenge link of the form's rules (a terrain the core refuses is said, and no link
   * made): from now on, the rules the class is ranked by. The link is copied where the browser lets it.
   */
  async make() {
    const terrain = this.form.terrain.value.trim();
    const rule = await checkTerrain(terrain);
    if (rule) {
      this.say(`No challenge link made: ${terrainRefused(terrain, rule).words}`);
      return;
    }
    this.opened = null; // a new challenge made here, not the one the page was opened from
    this.warning.hidden = true;
    this.grid.classList.remove('breaks-rules');
    this.runBlocked.hidden = true;
    this.page.refresh(); // Evolve free again: this page's drawing is the teacher's
    this.made = this.formRules();
    this.showMade(this.made);
    this.keep();
    const copied = await navigator.clipboard?.writeText(this.linkOut.value).then(() => true, () => false) ?? false;
    this.say(copied ? 'Challenge link made and copied: paste it where your class will find it (a chat, a message, the board).'
      : 'Challenge link made: copy it from the field below and send it to your class.');
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

  /** Shows the made challenge's link, its QR code and rules. @param {Rules} r */
  showMade(r) {
    this.showLink(r);
    this.showRules(r, 'What your students will see: ');
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

  /** Shows a challenge's link and its QR code, for the class. @param {Rules} r */
  showLink(r) {
    this.linkOut.value = challengeLink(r);
    this.linkBox.hidden = false;
    const here = onlyHere(this.linkOut.value);
    this.addressNote.textContent = here ? 'This link opens only on this computer (its address is this computer\'s own): '
      + 'your students cannot open it. Open this page at the address your class uses (the site on your school\'s server, or the published one), then make the link there.' : '';
    this.addressNote.hidden = !here;
    this.qr.replaceChildren(qrBox(this.section.ownerDocument, this.linkOut.value, 'Open the class challenge'));
    this.qr.hidden = false;
  }

  /** The tools an entry needs, with the codes checked before under the rules `r`. @param {Rules} r */
  tools(r) {
    return { lab: this.lab, defaults: this.page.defaults, checked: (/** @type {string} */ code) => {
      const text = this.checked[checkKey(r, code)];
      return text ? genomeOf(text) : null;
    } };
  }

  /**
   * How long a short code takes to check here (s; NaN: not known yet): the challenge's run of its
   * body, at this computer's pace (measured a few seconds after the page opens), or as the codes
   * checked so far took. @param {Rules} r @param {string} rows @param {string} controller
   */
  codeSeconds(r, rows, controller) {
    return this.tookPerCode > 0 ? this.tookPerCode : this.page.runSeconds(runSettings(r, rows, controller));
  }

  /**
   * The box's lines counted, and how long ranking them takes, said under the box as they are
   * pasted (before anything starts).
   */
  showEstimate() {
    const lines = linesOf(this.box.value);
    if (lines.length === 0) { this.estimate.hidden = true; return; }
    const { rules } = this.rankingRules();
    const codes = [...new Set(lines.map((l) => l.link).filter(looksLikeCode).map(normalCode))];
    const links = lines.length - lines.filter((l) => looksLikeCode(l.link)).length;
    /** @type {number[]} */
    const toCheck = [];
    let checkedBefore = 0;
    for (const c of codes) {
      const read = readCode(c);
      if ('error' in read || bodyProblem(read.rows, rules)) continue;
      if (this.checked[checkKey(rules, c)]) checkedBefore++;
      else toCheck.push(this.codeSeconds(rules, read.rows, read.controller));
    }
    const best = toCheck.slice(0, BEST).reduce((a, b) => a + b, 0);
    const all = toCheck.reduce((a, b) => a + b, 0);
    const time = (/** @type {number} */ s) => (Number.isFinite(s) ? `about ${durationWords(s)}` : 'time not known yet (this computer\'s pace is measured a few seconds after the page opens)');
    const parts = [`${lines.length} line${lines.length === 1 ? '' : 's'}: ${codes.length} short code${codes.length === 1 ? '' : 's'}`
      + `${checkedBefore ? ` (${checkedBefore} checked before)` : ''}, ${links} link${links === 1 ? '' : 's'} or other line${links === 1 ? '' : 's'}.`,
    `“Rank the class” takes seconds to measure the links and place the codes by the speeds their pages claim${toCheck.length
      ? `, then checks the best ${Math.min(BEST, toCheck.length)} code${Math.min(BEST, toCheck.length) === 1 ? '' : 's'} by evolving ${Math.min(BEST, toCheck.length) === 1 ? 'its robot' : 'their robots'} again here: ${time(best)} (you can stop it).` : '.'}`,
    toCheck.length > BEST ? `Checking every code (“Check every code”): ${time(all)} in all.` : ''];
    this.estimate.textContent = parts.filter(Boolean).join(' ');
    // This computer's pace is measured a few seconds after the page opens: the time said once it is known.
    clearTimeout(this.estimateTimer);
    if (toCheck.length && !Number.isFinite(all)) this.estimateTimer = setTimeout(() => this.showEstimate(), 1000);
    this.estimate.dataset.seconds = String(best);
    this.estimate.hidden = false;
  }

  /** Reads, measures and ranks every line of the compare box, then checks the best short codes. */
  async rank() {
    const { rules, source } = this.rankingRules();
    if (linesOf(this.box.value).length === 0) {
      this.say('Paste your students\' links in the box first, one a line (a name before each if you like).');
      return;
    }
    // A form (or drawing) changed since the link was made does not count, and the caption says so.
    const changed = this.made && !this.opened && !sameRules(this.formRules(), this.made)
      ? ' The form above (or the robot drawn now) differs from your link: it counts only once you make a new link.' : '';
    this.keep();
    this.busy(true);
    this.say(`Measuring the class's robots over ${rules.seconds} s on ${rules.terrain}…`);
    try {
      const ranking = await rankEntries(this.box.value, rules, this.tools(rules));
      this.entries = [...ranking.placed, ...ranking.others];
      this.rankedBy = rules;
      this.caption = `${source}: ${rankingWords(rules)}.${changed}`;
      this.show();
      await this.checkCodes(rules, BEST);
    } catch (error) {
      this.say(`The class could not be ranked: ${messageOf(error)}`);
    } finally {
      this.busy(false);
    }
  }

  /** Checks every short code not checked yet (the best first). */
  async checkAll() {
    const rules = this.rankedBy;
    if (!rules) return;
    this.busy(true);
    try {
      await this.checkCodes(rules, Infinity);
    } catch (error) {
      this.say(`The codes could not be checked: ${messageOf(error)}`);
    } finally {
      this.busy(false);
    }
  }

  /** While the page ranks or checks: the buttons that would start another off, Stop on. @param {boolean} on */
  busy(on) {
    this.section.dataset.state = on ? 'ranking' : 'ranked';
    this.rankButton.disabled = on;
    this.clearButton.disabled = on;
    this.raceButton.disabled = on || this.racers(this.ranked).length === 0;
    this.checkButton.disabled = on || unchecked(this.ranked).length === 0;
    if (!on) this.stopButton.hidden = true;
  }

  /**
   * Checks the short codes claimed among the best `upTo` placed (Infinity: every one), the best
   * first, each evolved again here: the table after each, the progress and time left said, Stop
   * keeping the rest as claimed. @param {Rules} rules @param {number} upTo
   */
  async checkCodes(rules, upTo) {
    const next = () => unchecked(this.ranked.slice(0, upTo))[0];
    if (!next()) { this.sayRanked(''); return; }
    const stopper = new AbortController();
    this.checking = stopper;
    this.stopButton.hidden = false;
    this.stopButton.disabled = false;
    let done = 0;
    let stopped = false;
    for (let entry = next(); entry; entry = next()) {
      const waiting = unchecked(this.ranked.slice(0, upTo));
      const left = waiting.length;
      const total = waiting.reduce((sum, e) => sum + this.codeSeconds(rules, e.rows, e.brain), 0);
      this.say(`Checking ${entry.name}'s short code: evolving the robot again here with the challenge's run (${done + 1} of ${done + left}`
        + `${Number.isFinite(total) ? `, about ${durationWords(total)} left` : ''})… “Stop checking” keeps the rest as claimed.`);
      const began = performance.now();
      /** @type {Entry} */
      let now;
      try {
        now = await checkCode(entry, rules, this.tools(rules), (settings) => evolveAgain(settings, stopper.signal));
      } catch (error) {
        if (error instanceof Error && error.name === 'AbortError') { stopped = true; break; }
        throw error;
      }
      done++;
      const took = (performance.now() - began) / 1000;
      this.tookPerCode = this.tookPerCode > 0 ? (this.tookPerCode * (done - 1) + took) / done : took;
      if (now.genome && !now.problem) this.checked[checkKey(rules, entry.code)] = genomeText(now.genome.genome);
      this.entries = this.entries.map((e) => (e === entry ? now : e));
      this.keep();
      this.show();
    }
    this.checking = null;
    this.sayRanked(stopped ? `Stopped after ${done} check${done === 1 ? '' : 's'}.` : `${done} short code${done === 1 ? '' : 's'} checked.`);
  }

  /** The last ranking in the table, in order. */
  show() {
    const ranking = order(this.entries);
    this.ranked = ranking.placed;
    const all = [...ranking.placed, ...ranking.others];
    const claimed = all.filter((e) => e.claimed).length;
    const measured = all.filter((e) => !e.claimed && Number.isFinite(e.speed)).length;
    const speeds = ` Speeds: ${measured} measured by this page${claimed ? `, ${claimed} claimed by the student's page (a short code not checked yet: “claimed” beside its speed)` : ''}.`;
    showRanking(this.table, ranking, `${this.caption}${speeds}`);
  }

  /** The line after a ranking: what was done, and what is left to check. @param {string} done */
  sayRanked(done) {
    const left = unchecked(this.ranked);
    const rules = this.rankedBy;
    const seconds = rules ? left.reduce((sum, e) => sum + this.codeSeconds(rules, e.rows, e.brain), 0) : NaN;
    const claims = left.length ? ` ${left.length} speed${left.length === 1 ? ' is' : 's are'} claimed, not checked: “Check every code” checks `
      + `${left.length === 1 ? 'it' : 'them'}${Number.isFinite(seconds) ? ` (about ${durationWords(seconds)})` : ''}.` : '';
    // The race takes robots with a brain: when no placed robot has one, the button says why it is off.
    const race = this.ranked.length && !this.racers(this.ranked).length && !left.length
      ? ' No placed robot has a brain (the phase gait\'s clock drives them all), so there is nothing for “Race the best four” to race.' : '';
    this.say(`${done}${claims}${race}`.trim());
  }

  /** Forgets the class's entries, the table and the codes checked (the challenge link stays), once the teacher confirms. */
  clear() {
    const count = linesOf(this.box.value).length;
    const view = this.section.ownerDocument.defaultView;
    if (count && !view?.confirm(`Forget the class's ${count} line${count === 1 ? '' : 's'} and every code checked? The challenge link stays.`)) return;
    this.box.value = '';
    this.checked = {};
    this.entries = [];
    this.ranked = [];
    this.table.replaceChildren();
    this.table.hidden = true;
    this.keep();
    this.showEstimate();
    this.busy(false);
    this.say(`Cleared: the class's ${count} line${count === 1 ? '' : 's'} and the codes checked are forgotten, here and for your next visit; the challenge link stays.`);
  }

  /** The best four of `placed` with a brain, each robot once. @param {Entry[]} placed */
  racers(placed) {
    return placed.filter((e) => e.genome && !e.same).slice(0, 4);
  }

  /** Races the best four entries that have a brain, on the challenge's terrain. */
  raceBest() {
    const r = this.rankedBy ?? this.rankingRules().rules;
    this.page.setView(r.terrain);
    const race = this.page.race;
    race.clear();
    race.seconds.value = String(r.seconds);
    for (const e of this.racers(this.ranked)) {
      const g = /** @type {{controller: string, genome: Float32Array}} */ (e.genome);
      race.add({ label: e.name, shape: e.rows, controller: g.controller, genome: g.genome });
    }
    race.section.scrollIntoView({ block: 'start', behavior: 'instant' });
  }
}
