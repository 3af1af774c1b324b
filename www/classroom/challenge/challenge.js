// @ts-check
/**
 * A class challenge without a server, and the teacher making it. The teacher fixes the rules in
 * the form (rules.js) and makes a challenge link, with its QR code for the projector; opening it
 * sets the playground up for a student (student.js). A student's entry is an ordinary share link
 * or a short code, and the class is ranked (ranking.js) by the rules of the link the teacher made
 * (or of the challenge link the page was opened from). The rules made, the links and codes pasted
 * and the codes checked are kept for the teacher's next visit (store.js) until “Clear the class's
 * entries”. This class wires the three together for main.js.
 */
import { checkTerrain } from '../../workers/core.js';
import { byId } from '../../shared/dom.js';
import { messageOf } from '../../workers/kit.js';
import { linesOf } from './entries.js';
import { RUN_DEFAULTS, challengeLink, rulesFrom, sameRules } from './rules.js';
import { loadQr, qrBox } from '../qr.js';
import { onlyHere } from '../sheet-address.js';
import { terrainRefused } from '../../viewer/terrain-words.js';
import { keepChallenge, loadChallenge } from './store.js';
import { Ranking } from './ranking.js';
import { StudentPage } from './student.js';

/** @typedef {import('./rules.js').Rules} Rules */

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
    this.page = page;
    this.section = byId(doc, 'challenge-panel');
    this.teacher = /** @type {HTMLDetailsElement} */ (this.section.querySelector('details.challenge-teacher'));
    this.teacher.addEventListener('toggle', () => void loadQr(), { once: true }); // the challenge link's QR code, drawn at once
    this.form = { terrain: byId(doc, 'challenge-terrain', HTMLInputElement), seconds: byId(doc, 'challenge-seconds', HTMLInputElement), voxels: byId(doc, 'challenge-voxels', HTMLInputElement),
      fixed: byId(doc, 'challenge-fixed', HTMLInputElement), budget: byId(doc, 'challenge-budget', HTMLInputElement), seed: byId(doc, 'challenge-seed', HTMLInputElement) };
    this.linkOut = byId(doc, 'challenge-link', HTMLInputElement);
    this.linkBox = byId(doc, 'challenge-link-box');
    /** The made link's QR code, for the projector, and the line that says when no student can open the link. */
    this.qr = byId(doc, 'challenge-qr');
    this.addressNote = byId(doc, 'challenge-address-note');
    this.status = byId(doc, 'challenge-status');
    /** The student's side: the rules of the challenge link this page was opened from, and the drawing held to them. */
    this.student = new StudentPage(doc, lab, page);
    /** @type {{population: number, train: string}} the run the form's challenge fixes beyond the form's fields (a new link keeps them) */
    this.formRun = { population: RUN_DEFAULTS.population, train: RUN_DEFAULTS.train };
    const kept = loadChallenge();
    /** @type {Rules | null} the rules of the challenge link the teacher made, as they were when it was made */
    this.made = kept.rules;
    /** Whether the last keep failed (said once, not at every key). */
    this.unkept = false;
    /** The class's ranking, by the rules in force. */
    this.ranking = new Ranking(doc, lab, page, {
      rules: () => this.rankingRules(), changed: () => this.changedNote(), keep: () => this.keep(), say: (text) => this.say(text),
    }, kept.checked ?? {});
    byId(doc, 'challenge-make', HTMLButtonElement).addEventListener('click', () => { this.make().catch((error) => this.say(`The challenge link could not be made: ${messageOf(error)}`)); });
    this.restore(kept.links);
  }

  /** @returns {Rules | null} the rules of the challenge link this page was opened from (a student's page) */
  get opened() { return this.student.opened; }

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

  /** What a ranking's caption adds when the form (or the robot drawn now) differs from the link made ('' when not). */
  changedNote() {
    return this.made && !this.opened && !sameRules(this.formRules(), this.made)
      ? ' The form above (or the robot drawn now) differs from your link: it counts only once you make a new link.' : '';
  }

  /** The teacher's challenge from their last visit, back in the form and the compare box. @param {string} links */
  restore(links) {
    this.ranking.restore(links);
    const made = this.made;
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
    const checks = Object.keys(this.ranking.checked).length;
    const back = [made ? 'the challenge link you made' : '', count ? `the class's ${count} link${count === 1 ? '' : 's'} and code${count === 1 ? '' : 's'}` : '',
      checks ? `${checks} short code${checks === 1 ? '' : 's'} already checked (not evolved again)` : ''].filter(Boolean).join(', ');
    this.say(`Back from your last visit: ${back}.${count ? ' Press “Rank the class” to rank them again, or “Clear the class\'s entries” to start a new class.' : ''}`);
    this.teacher.open = true;
  }

  /** Keeps the made rules and the pasted links for the next visit; says once if it cannot. */
  keep() {
    const why = keepChallenge({ rules: this.made, links: this.ranking.box.value, checked: this.ranking.checked });
    if (why && !this.unkept) this.say(`Note: ${why}.`);
    this.unkept = why !== '';
  }

  /** A line for the teacher above the table ('' hides it). @param {string} text */
  say(text) {
    this.status.textContent = text;
    this.status.hidden = text === '';
  }

  /** Opens a challenge link's rules (a student's page). */
  begin() { return this.student.begin(); }

  /** A student's drawing changed (student.js). @param {string} rows */
  watch(rows) { this.student.watch(rows); }

  /** Why a student's drawing may not be evolved ('' when it may; student.js). @param {string} rows */
  problem(rows) { return this.student.problem(rows); }

  /** After Share in a challenge: the robot's short code (student.js). @param {import('../../keep/share.js').PageState} state */
  shared(state) { return this.student.shared(state); }

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
    this.student.leave(); // a new challenge made here, not the one the page was opened from
    this.made = this.formRules();
    this.showMade(this.made);
    this.keep();
    const copied = await navigator.clipboard?.writeText(this.linkOut.value).then(() => true, () => false) ?? false;
    this.say(copied ? 'Challenge link made and copied: paste it where your class will find it (a chat, a message, the board).'
      : 'Challenge link made: copy it from the field below and send it to your class.');
  }

  /** Shows the made challenge's link, its QR code and rules. @param {Rules} r */
  showMade(r) {
    this.showLink(r);
    this.student.showRules(r, 'What your students will see: ');
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
}
