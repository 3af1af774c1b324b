// @ts-check
/**
 * A class challenge without a server. The teacher fixes the rules (challenge-rules.js) and makes
 * a challenge link; opening it sets the playground up for a student. A student's entry is an
 * ordinary share link. The teacher pastes the class's links (one a line, a name before each if
 * wanted) into the compare box, and the page ranks them (challenge-entries.js) by the rules of
 * the link the teacher made (or of the challenge link the page was opened from): never by the
 * form or the drawing as they are when Rank is pressed, which may have changed since. The rules
 * made and the links pasted are kept for the teacher's next visit (challenge-store.js). The best
 * four with a brain race side by side.
 */
import { checkTerrain, runGenome } from '../workers/core.js';
import { byId } from '../shared/dom.js';
import { messageOf } from '../workers/kit.js';
import { terrainRefused } from '../viewer/terrain-words.js';
import { linesOf, rankEntries } from './challenge-entries.js';
import { evolveAgain, looksLikeCode, readCode, robotCode } from './challenge-code.js';
import { bodyProblem, challengeLink, rankingWords, rulesFrom, rulesOf, rulesWords, runOf, runSettings, sameRules } from './challenge-rules.js';
import { loadQr, qrBox } from './qr.js';
import { onlyHere } from './sheet-address.js';
import { durationWords } from '../runs/progress.js';
import { keepChallenge, loadChallenge } from './challenge-store.js';
import { showRanking } from './challenge-table.js';

/** @typedef {import('./challenge-rules.js').Rules} Rules */
/** @typedef {import('./challenge-entries.js').Entry} Entry */

export class Challenge {
  /**
   * @param {Document} doc @param {import('./lab.js').Lab} lab
   * @param {{defaults: import('../workers/core.js').Defaults, rows: () => string, setView: (terrain: string) => void,
   *   fixRun: (values: Record<string, string>) => void, setBody: (rows: string) => Promise<void>,
   *   race: import('../viewer/race.js').Race, message: (text: string) => void, pin: (text: string) => void,
   *   runSeconds: (settings: import('../workers/protocol.js').EvolveSettings) => number,
   *   lastRun: () => {runFile: string | null, settings: import('../workers/protocol.js').EvolveSettings | null, mode: string}}} page
   *   fixRun: the run settings every student's run uses, locked; runSeconds: how long a run takes here (NaN: not known);
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
    /** The student's short code, under the share link (challenge-code.js). */
    this.codeLine = byId(doc, 'challenge-code');
    this.box = byId(doc, 'challenge-compare', HTMLTextAreaElement);
    this.status = byId(doc, 'challenge-status');
    this.table = byId(doc, 'challenge-table', HTMLTableElement);
    this.rankButton = byId(doc, 'challenge-rank', HTMLButtonElement);
    this.raceButton = byId(doc, 'challenge-race', HTMLButtonElement);
    /** The line under the grid that says which rule a student's drawing breaks, while it does. */
    this.warning = byId(doc, 'rule-warning');
    /** The grid, outlined while the drawing breaks the rules (the line under it may be off a phone's screen). */
    this.grid = byId(doc, 'editor');
    /** @type {Entry[]} the placed entries of the last ranking, fastest first */
    this.ranked = [];
    /** @type {Rules | null} the rules of the last ranking */
    this.rankedBy = null;
    /** @type {Rules | null} the rules of the challenge link this page was opened from (a student's page) */
    this.opened = rulesOf(location.search);
    const kept = loadChallenge();
    /** @type {Rules | null} the rules of the challenge link the teacher made, as they were when it was made */
    this.made = kept.rules;
    /** Whether the last keep failed (said once, not at every key). */
    this.unkept = false;
    byId(doc, 'challenge-make', HTMLButtonElement).addEventListener('click', () => { this.make().catch((error) => this.say(`The challenge link could not be made: ${messageOf(error)}`)); });
    this.rankButton.addEventListener('click', () => this.rank());
    this.raceButton.addEventListener('click', () => this.raceBest());
    this.box.addEventListener('input', () => this.keep());
    this.raceButton.disabled = true;
    this.restore(kept.links);
  }

  /** The form's rules, with the robot drawn now if everyone is to use it. @returns {Rules} */
  formRules() {
    const f = this.form;
    return rulesFrom({ terrain: f.terrain.value, seconds: f.seconds.value, voxels: f.voxels.value,
      body: f.fixed.checked ? this.page.rows() : null, budget: f.budget.value, seed: f.seed.value });
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
    if (made && !this.opened) {
      const f = this.form;
      f.terrain.value = made.terrain;
      f.seconds.value = String(made.seconds);
      f.voxels.value = made.voxels === null ? '' : String(made.voxels);
      f.budget.value = made.budget;
      f.seed.value = made.seed;
      f.fixed.checked = made.body !== null;
      this.showMade(made);
    }
    if (this.opened || (!made && !links)) return;
    const count = linesOf(links).length;
    const back = [made ? 'the challenge link you made' : '', count ? `the class's ${count} link${count === 1 ? '' : 's'}` : ''].filter(Boolean).join(' and ');
    this.say(`Back from your last visit: ${back}.${count ? ' Press “Rank the class” to measure and rank them again.' : ''}`);
    this.teacher.open = true;
  }

  /** Keeps the made rules and the pasted links for the next visit; says once if it cannot. */
  keep() {
    const why = keepChallenge({ rules: this.made, links: this.box.value });
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
    this.rulesLine.textContent = rulesWords(r);
    this.rulesLine.hidden = false;
    // The rules at the top as well, where a student opening the link looks first (the panel is far down).
    this.page.pin(`${rulesWords(r)} (The rules are also under “Class challenge”, further down.)`);
    this.page.setView(r.terrain);
    this.page.fixRun(runOf(r)); // everyone's run the same, trained over the walks it is measured on
    if (r.body) await this.page.setBody(r.body).catch((error) => this.page.message(`the challenge's body: ${messageOf(error)}`));
  }

  /**
   * A student's drawing changed: a body that breaks the challenge's rules is said at once, under
   * the grid, for as long as it does (not only in the teacher's table). @param {string} rows
   */
  watch(rows) {
    if (!this.opened || this.section.dataset.mode !== 'student') return;
    const problem = rows ? bodyProblem(rows, this.opened) : '';
    // Under the grid, not above it: a line that appeared above would move the grid under the student's finger.
    this.warning.textContent = problem ? `Your robot breaks the challenge's rules: ${problem}. Your teacher's ranking will not count it: change the drawing (Undo goes back a step).` : '';
    this.warning.hidden = !problem;
    this.grid.classList.toggle('breaks-rules', problem !== '');
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
   * @param {import('../keep/share.js').PageState} state what the link holds
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
    const code = why || !brain ? null : robotCode(state.rows, brain.controller, brain.genome);
    this.codeLine.dataset.code = code ?? '';
    this.codeLine.textContent = code
      ? `Your short code: ${code}. Give your teacher this code (or the link): their page evolves your robot again from it, exactly.`
      : `No short code for this robot (${why || 'a body too large for a code'}): send your teacher the link.`;
    this.codeLine.hidden = false;
  }

  /** Shows the made challenge's link, its QR code and rules. @param {Rules} r */
  showMade(r) {
    this.linkOut.value = challengeLink(r);
    this.linkBox.hidden = false;
    const here = onlyHere(this.linkOut.value);
    this.addressNote.textContent = here ? 'This link opens only on this computer (its address is this computer\'s own): '
      + 'your students cannot open it. Open this page at the address your class uses (the site on your school\'s server, or the published one), then make the link there.' : '';
    this.addressNote.hidden = !here;
    this.qr.replaceChildren(qrBox(this.section.ownerDocument, this.linkOut.value, 'Open the class challenge'));
    this.qr.hidden = false;
    this.rulesLine.textContent = `What your students will see: ${rulesWords(r)}`;
    this.rulesLine.hidden = false;
  }

  /** Reads, measures and ranks every line of the compare box. */
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
    this.section.dataset.state = 'ranking';
    this.rankButton.disabled = true;
    // Short codes are evolved again here, one run each: how long that takes, said before it starts.
    const codes = [...new Set(linesOf(this.box.value).map((l) => l.link).filter(looksLikeCode).map((c) => c.toUpperCase()))];
    const seconds = codes.reduce((sum, c) => {
      const read = readCode(c);
      return 'error' in read ? sum : sum + this.page.runSeconds(runSettings(rules, read.rows, read.controller));
    }, 0);
    const evolving = codes.length === 0 ? ''
      : ` ${codes.length} short code${codes.length === 1 ? '' : 's'}: each robot evolved again here with the challenge's run`
        + `${Number.isFinite(seconds) && seconds > 0 ? `, about ${durationWords(seconds)} in all on this computer` : ''}.`;
    this.say(`Measuring the class's robots over ${rules.seconds} s on ${rules.terrain}…${evolving}`);
    try {
      const ranking = await rankEntries(this.box.value, rules, { lab: this.lab, defaults: this.page.defaults, evolve: evolveAgain,
        say: (text) => this.say(`${text}${evolving}`) });
      this.ranked = ranking.placed;
      this.rankedBy = rules;
      showRanking(this.table, ranking, `${source}: ${rankingWords(rules)}.${changed}`);
      // The race takes robots with a brain: when no placed robot has one, the button says why it is off.
      this.say(ranking.placed.length && !this.racers(ranking.placed).length
        ? 'No placed robot has a brain (the phase gait\'s clock drives them all), so there is nothing for “Race the best four” to race.' : '');
    } catch (error) {
      this.say(`The class could not be ranked: ${messageOf(error)}`);
    } finally {
      this.rankButton.disabled = false;
      this.raceButton.disabled = this.racers(this.ranked).length === 0;
      this.section.dataset.state = 'ranked';
    }
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
