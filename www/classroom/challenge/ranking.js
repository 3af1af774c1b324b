// @ts-check
/**
 * The class's ranking, on the teacher's page. The teacher pastes the class's links (one a line,
 * a name before each if wanted) into the compare box, and the page ranks them (entries.js) by the
 * rules it is given (challenge.js: the link the teacher made, or the challenge link the page was
 * opened from), never by the form or the drawing as they are when Rank is pressed, which may have
 * changed since. A short code (code.js) is ranked at once by the speed it claims, said as
 * claimed; Rank then checks the best four (each evolved again here, 13 to 27 s on a school laptop,
 * said under the box before it starts, its progress shown, stoppable), and “Check every code” the
 * rest. The codes checked are kept with the links (store.js, through challenge.js) until “Clear
 * the class's entries”. The best four with a brain race side by side.
 */
import { byId } from '../../shared/dom.js';
import { messageOf } from '../../workers/kit.js';
import { checkCode, linesOf, order, rankEntries, unchecked } from './entries.js';
import { EXAMPLE_CODE, looksLikeCode, normalCode, readCode } from './code.js';
import { evolveAgain } from './evolve.js';
import { bodyProblem, rankingWords, runSettings } from './rules.js';
import { durationWords } from '../../runs/progress.js';
import { checkKey, genomeOf, genomeText } from './store.js';
import { showRanking } from './table.js';

/** @typedef {import('./rules.js').Rules} Rules */
/** @typedef {import('./entries.js').Entry} Entry */

/** How many of the best Rank checks at once: the race's four. */
const BEST = 4;

export class Ranking {
  /**
   * @param {Document} doc @param {import('../lab.js').Lab} lab
   * @param {{defaults: import('../../workers/core.js').Defaults, setView: (terrain: string) => void,
   *   race: import('../../viewer/race.js').Race,
   *   runSeconds: (settings: import('../../workers/protocol.js').EvolveSettings) => number}} page
   *   runSeconds: how long a run takes here (NaN: not known)
   * @param {{rules: () => {rules: Rules, source: string}, changed: () => string, keep: () => void, say: (text: string) => void}} teacher
   *   rules: the rules the class is ranked by, and where they come from in words; changed: what the
   *   caption adds when the form differs from the link made ('' when not); keep: the links and the
   *   codes checked kept for the next visit; say: a line for the teacher above the table
   * @param {Record<string, string>} checked the genomes of the short codes checked on an earlier visit, by checkKey
   */
  constructor(doc, lab, page, teacher, checked) {
    this.lab = lab;
    this.page = page;
    this.teacher = teacher;
    this.section = byId(doc, 'challenge-panel');
    this.box = byId(doc, 'challenge-compare', HTMLTextAreaElement);
    this.table = byId(doc, 'challenge-table', HTMLTableElement);
    this.rankButton = byId(doc, 'challenge-rank', HTMLButtonElement);
    this.raceButton = byId(doc, 'challenge-race', HTMLButtonElement);
    /** Checks every short code not checked yet; stops the checking; forgets the class's entries. */
    this.checkButton = byId(doc, 'challenge-check', HTMLButtonElement);
    this.stopButton = byId(doc, 'challenge-stop', HTMLButtonElement);
    this.clearButton = byId(doc, 'challenge-clear', HTMLButtonElement);
    /** How long ranking the box's lines will take, said as they are pasted. */
    this.estimate = byId(doc, 'challenge-estimate');
    this.box.placeholder = `Ana ${EXAMPLE_CODE}\nBen https://…#shape=…`; // a real code (code.js)
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
    /** @type {Record<string, string>} the genomes of the short codes checked here, by checkKey */
    this.checked = checked;
    /** @type {ReturnType<typeof setTimeout> | undefined} the estimate said again once this computer's pace is known */
    this.estimateTimer = undefined;
    /** How long a short code took to check here, on average (s; 0 before the first). */
    this.tookPerCode = 0;
    this.rankButton.addEventListener('click', () => this.rank());
    this.raceButton.addEventListener('click', () => this.raceBest());
    this.checkButton.addEventListener('click', () => this.checkAll());
    this.stopButton.addEventListener('click', () => this.checking?.abort());
    this.clearButton.addEventListener('click', () => this.clear());
    this.box.addEventListener('input', () => { this.teacher.keep(); this.showEstimate(); });
    this.raceButton.disabled = true;
    this.checkButton.disabled = true;
    this.stopButton.hidden = true;
  }

  /** The class's lines from the teacher's last visit, back in the compare box. @param {string} links */
  restore(links) {
    if (links) this.box.value = links;
    setTimeout(() => this.showEstimate(), 0); // the lines kept, counted (once the form holds the kept rules)
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
    const { rules } = this.teacher.rules();
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
    const { rules, source } = this.teacher.rules();
    if (linesOf(this.box.value).length === 0) {
      this.teacher.say('Paste your students\' links in the box first, one a line (a name before each if you like).');
      return;
    }
    const changed = this.teacher.changed(); // a form (or drawing) changed since the link was made does not count, and the caption says so
    this.teacher.keep();
    this.busy(true);
    this.teacher.say(`Measuring the class's robots over ${rules.seconds} s on ${rules.terrain}…`);
    try {
      const ranking = await rankEntries(this.box.value, rules, this.tools(rules));
      this.entries = [...ranking.placed, ...ranking.others];
      this.rankedBy = rules;
      this.caption = `${source}: ${rankingWords(rules)}.${changed}`;
      this.show();
      await this.checkCodes(rules, BEST);
    } catch (error) {
      this.teacher.say(`The class could not be ranked: ${messageOf(error)}`);
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
      this.teacher.say(`The codes could not be checked: ${messageOf(error)}`);
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
      this.teacher.say(`Checking ${entry.name}'s short code: evolving the robot again here with the challenge's run (${done + 1} of ${done + left}`
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
      this.teacher.keep();
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
    this.teacher.say(`${done}${claims}${race}`.trim());
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
    this.teacher.keep();
    this.showEstimate();
    this.busy(false);
    this.teacher.say(`Cleared: the class's ${count} line${count === 1 ? '' : 's'} and the codes checked are forgotten, here and for your next visit; the challenge link stays.`);
  }

  /** The best four of `placed` with a brain, each robot once. @param {Entry[]} placed */
  racers(placed) {
    return placed.filter((e) => e.genome && !e.same).slice(0, 4);
  }

  /** Races the best four entries that have a brain, on the challenge's terrain. */
  raceBest() {
    const r = this.rankedBy ?? this.teacher.rules().rules;
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
