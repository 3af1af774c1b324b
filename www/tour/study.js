// @ts-check
/**
 * The study in the page: our reproduction's figures (figures.js; the files `vsr report`
 * writes, served from study/report/), one at a time with what it shows and what the paper
 * found, and under it the runs it is drawn from (the tables of figures.js): one click walks the
 * chosen run's best robot in the viewer, on its own body (its run file, study/runs/<run>.json,
 * becomes a module of the list, so it can also race or be transplanted). Its tables, claim and
 * figure are fetched when needed, not at start (issue 46): when the panel comes near the screen,
 * a figure is asked for (the tour, the findings) or the module list needs the runs ({@link StudyPanel#load}).
 */
import { withStats } from '../shared/simple-words.js';
import { byId, whenNear } from '../shared/dom.js';
import { fetchOk, messageOf } from '../workers/kit.js';
import { shortLabel, unseenWords } from '../modules/names.js';
import { CLAIM_TABLE, FIGURES, STUDY_DIR, TABLES, figureSrc } from './figures.js';
import { parseCampaign, runsOf } from './study-runs.js';
import { fillClaim, loadClaim } from './claim.js';
import { lineageNote } from '../modules/lineage.js';
import { count } from '../shared/format.js';

/** @typedef {import('./study-runs.js').StudyRun} StudyRun  a row of the campaign table */

/** The runs of one of the study's tables, fetched. @param {string} name @returns {Promise<StudyRun[]>} */
async function table(name) {
  const response = await fetchOk(`${STUDY_DIR}${name}`, name);
  return parseCampaign(await response.text(), name);
}

/** A run in words. @param {StudyRun} r */
export function describe(r) {
  const [, source = r.source, sourceSeed = String(r.seed)] = r.source.match(/^(.*)-\d+-s(\d+)$/) ?? [];
  const how = r.kind === 'finetune' ? `fine-tuned from ${source}${sourceSeed === String(r.seed) ? '' : ` (its seed ${sourceSeed})`}`
    : `from scratch, ${count(r.evals)} evaluations`;
  const speed = Number.isFinite(r.unseen) ? `: ${unseenWords(r.unseen)}` : '';
  return `${r.controller} on ${r.shape}, ${how}, seed ${r.seed}${speed}`;
}

export class StudyPanel {
  /**
   * @param {Document} doc
   * @param {{module: (key: string, label?: string, short?: string) => Promise<import('../modules/modules.js').Module>,
   *   openModule: (module: import('../modules/modules.js').Module) => void, message: (text: string) => void}} page
   */
  constructor(doc, page) {
    this.page = page;
    this.section = byId(doc, 'study-panel');
    this.pick = byId(doc, 'study-figure', HTMLSelectElement);
    this.image = byId(doc, 'study-image', HTMLImageElement);
    this.link = byId(doc, 'study-full', HTMLAnchorElement);
    this.caption = byId(doc, 'study-caption');
    this.runPick = byId(doc, 'study-run', HTMLSelectElement);
    this.watch = byId(doc, 'study-watch', HTMLButtonElement);
    this.runNote = byId(doc, 'study-run-note');
    this.runBar = byId(doc, 'study-run-bar');
    this.claim = byId(doc, 'study-claim');
    /** @type {StudyRun[]} */
    this.runs = [];
    /** The tables' reading, once asked for ({@link load}). @type {Promise<void> | null} */
    this.loading = null;
    this.listFigures(false);
    this.pick.addEventListener('change', () => this.open());
    this.watch.addEventListener('click', () => this.watchRun());
    this.runPick.addEventListener('change', () => this.noteRun());
    whenNear(this.section, () => void this.open(), '300px');
  }

  /**
   * Reads the study's tables (and the claim's, once its test is complete) and says the claim's
   * state, once: the first call fetches, every call resolves when they are read (or could not be).
   * @returns {Promise<void>}
   */
  load() {
    this.loading ??= Promise.all(TABLES.map(table))
      .then((tables) => { this.runs = tables.flat(); })
      .catch((error) => this.page.message(`the study's runs could not be listed: ${messageOf(error)}`))
      .then(() => Promise.all([fillClaim(this.claim), this.addClaim()]))
      .then(() => undefined);
    return this.loading;
  }

  /** The panel as someone sees it: its tables read, then the chosen figure and its runs. */
  async open() {
    await this.load();
    await this.showFigure();
  }

  /** Lists the figures, those of the claim's test only when it is `complete`; the chosen one stays chosen. @param {boolean} complete */
  listFigures(complete) {
    const chosen = this.pick.value;
    this.pick.replaceChildren(...FIGURES.filter((f) => complete || !f.claim).map((f) => new Option(f.title, f.id)));
    if (chosen) this.pick.value = chosen;
  }

  /** Once the test of the paper's own claim is complete, lists its figures and runs (until then, the line above says how far it is). */
  async addClaim() {
    const claim = await loadClaim().catch(() => null); // the line above says why it could not be read
    if (!claim?.complete) return;
    try {
      this.runs.push(...await table(CLAIM_TABLE));
    } catch (error) {
      this.page.message(`the runs of the claim's test could not be listed: ${messageOf(error)}`);
    }
    this.listFigures(true);
  }

  /** Shows the figure `id` and scrolls to it (from a tour chapter). @param {string} id */
  async show(id) {
    this.pick.value = id;
    await this.open();
    this.section.scrollIntoView({ block: 'start', behavior: 'instant' });
  }

  /** Shows the chosen figure and lists its runs, the fastest of its first brain chosen. */
  async showFigure() {
    const fig = FIGURES.find((f) => f.id === this.pick.value) ?? FIGURES[0];
    const src = figureSrc(fig);
    this.image.src = src;
    this.image.alt = fig.title;
    this.link.href = src;
    this.caption.replaceChildren(...withStats(this.section.ownerDocument, `${fig.read} ${fig.paper}`));
    const runs = runsOf(fig, this.runs);
    this.runPick.replaceChildren(...runs.map((r) => new Option(describe(r), r.run)));
    this.watch.disabled = runs.length === 0;
    this.runBar.hidden = fig.runs.length === 0;
    this.noteRun();
  }

  /** Says beside the chosen run where the same run stopped at another budget, and why their bests differ. */
  noteRun() {
    const fig = FIGURES.find((f) => f.id === this.pick.value);
    this.runNote.textContent = fig?.runs.length === 0 ? fig.elsewhere ?? '' : lineageNote(this.runs, this.runPick.value);
    this.runNote.hidden = !this.runNote.textContent;
  }

  /** Walks the chosen run's best robot in the viewer, on its own body. */
  async watchRun() {
    const run = this.runs.find((r) => r.run === this.runPick.value);
    if (!run) return;
    try {
      const module = await this.page.module(`${STUDY_DIR}runs/${run.run}.json`, `study: ${describe(run)}`,
        shortLabel(`${run.controller} on ${run.shape}, seed ${run.seed}`, run.unseen));
      await this.page.openModule(module);
      byId(this.section.ownerDocument, 'watch-panel').scrollIntoView({ block: 'start', behavior: 'instant' });
    } catch (error) {
      this.page.message(`could not open the run ${run.run}: ${messageOf(error)}`);
    }
  }
}
