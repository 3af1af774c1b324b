// @ts-check
/**
 * The module list: the controllers in pretrained/ (from its manifest: source shape,
 * controller, budget, validation median), run files imported from disk, and the runs
 * finished in this page. A module can be put on the drawn robot ("Load onto my robot": the
 * core's transplant for attention) or opened with its own body. Files are checked by
 * the core when read; a bad file shows a message and changes nothing.
 */
import { describeRun } from '../workers/core.js';
import { byId } from '../shared/dom.js';
import { fetchOk, messageOf } from '../workers/kit.js';
import { keepModules, loadKeptModules } from '../keep/storage.js';
import { HELDOUT_SHORT, HELDOUT_SIMPLE, LIST_SPEED_SIMPLE, SPEED_MARK, bodySimple, bodyWords, brainWords, heldOutLong, shortLabel, simpleLabel, unseenWords } from './names.js';
import { lineageNote } from './lineage.js';
import { count, decimal } from '../shared/format.js';
import { NOT_YET, familyName, isAnyBody } from '../shared/families.js';
import { heldOut, isStudyAnyBody } from '../shared/held-out.js';

/** Where the served pretrained run files are (scripts/serve.mjs mounts pretrained/). */
const PRETRAINED_DIR = 'pretrained/';
/** The list's group of brains for any body (one genome drives every body). */
export const ANY_BODY_GROUP = 'one brain for any body';
/** The study's brain for any body, while pretrained/ has none: said in the list and under the family menu. */
export { NOT_YET };
/** The list's stand-in for the study's brain for any body until its manifest lists one (never chosen: disabled). */
const PENDING = 'pending:attention-any';
/** What the list and its details say in place of speeds while {@link ModuleList.quiet}. */
const HUSHED = 'Speeds are kept back until you reveal your answer to the tour\'s question';

/**
 * @typedef {{key: string, label: string, text: string, short?: string}} Module  a run file and its name (`label`, in full:
 *   the driver line and a share link say it; `short`, what the list shows when the full name would not fit)
 */

/**
 * @typedef {object} ModuleHooks
 * @property {(module: Module) => void} loadOnto  put the module on the drawn robot
 * @property {(module: Module) => void} openOwn   replace the drawing by the module's body
 * @property {(text: string, source?: string) => void} message  shows an error (about `source`: '' takes it away)
 * @property {(info: {controller: string} | null) => void} [described]  the chosen module is described (null: none)
 */

export class ModuleList {
  /**
   * @param {Document} doc @param {ModuleHooks} hooks @param {number} attentionGenes the core's attention block size
   * @param {{name: string, rows: string}[]} [presets] the core's named bodies, to name a module's body in words
   */
  constructor(doc, hooks, attentionGenes, presets = []) {
    this.attentionGenes = attentionGenes;
    this.presets = presets;
    this.select = byId(doc, 'module', HTMLSelectElement);
    this.fileInput = byId(doc, 'run-import', HTMLInputElement);
    this.details = byId(doc, 'module-details');
    this.loadButton = byId(doc, 'module-load', HTMLButtonElement);
    this.hooks = hooks;
    /** Run files already read, by key. @type {Map<string, Module>} */
    this.held = new Map();
    /** Descriptions asked: only the latest one's answer is shown. */
    this.described = 0;
    /** What the selected module is, once described (null: none chosen). @type {{shape: string, controller: string} | null} */
    this.info = null;
    /** Each module's full name, by key (the list shows a short one: see {@link shortLabel}). @type {Map<string, string>} */
    this.labels = new Map();
    /** Whether the list keeps its speeds to itself (while the tour's question waits for an answer: {@link quiet}). */
    this.hushed = false;
    /** Each pretrained module's mean speed on the study's unseen terrains (m/s), by key: the list's number. @type {Map<string, number>} */
    this.unseen = new Map();
    /**
     * A brain for any body's figures on the held-out bodies the study walked it on (the list's number is their median),
     * with how many runs it was chosen from, by key. @type {Map<string, {set: import('../shared/held-out.js').HeldOut, runs: number}>}
     */
    this.heldOuts = new Map();
    /** The study run each pretrained module is (its name in the study's tables), by key. @type {Map<string, string>} */
    this.studyRunOf = new Map();
    /** The study's runs, once listed (study.js), to say beside a module where its run stopped at another budget. */
    this.studyRuns = /** @type {import('./lineage.js').Stop[]} */ ([]);
    /** Whether the page said that storage could not keep its modules (said once). */
    this.keepWarned = false;
    /** The study's brain for any body (attention) in pretrained/, once listed: its key ('' while the study trains it). */
    this.studyAnyBody = '';
    /** Resolves once the pretrained modules are listed (or could not be). */
    this.listed = new Promise((resolve) => { this.doneListing = resolve; });
    byId(doc, 'module-load', HTMLButtonElement).addEventListener('click', () => this.withSelected(hooks.loadOnto));
    byId(doc, 'module-open', HTMLButtonElement).addEventListener('click', () => this.withSelected(hooks.openOwn));
    this.select.addEventListener('change', () => this.describe());
    // The switch “Simple words” names the study's modules in plain words (or back): each option written again.
    new MutationObserver(() => { for (const option of this.select.options) this.name(option); })
      .observe(doc.documentElement, { attributes: true, attributeFilter: ['data-words'] });
    this.fileInput.addEventListener('change', () => this.importFile());
  }

  /** Lists the pretrained modules; a failure is reported, the list stays usable. */
  async listPretrained() {
    try {
      const manifest = await fetchOk(`${PRETRAINED_DIR}manifest.json`).then((r) => r.json());
      for (const m of manifest.modules ?? []) {
        if (isAnyBody(m.controller)) { this.listAnyBody(m); continue; }
        // Manifest written by `vsr campaign export`: the mean over the unseen validation set, the
        // figure the study panel and its box plots show for the same run.
        const mean = Number(m.validation?.unseen?.mean);
        const speed = Number.isFinite(mean) ? `, ${unseenWords(mean)}` : '';
        const from = m.finetuned_from ? ` fine-tuned from ${m.finetuned_from}` : '';
        // The budget, as the study's lists and the tour say it (a run passes it a little: the details say by how much).
        const budget = count(m.budget ?? m.evaluations);
        const label = `${m.controller} on ${m.shape}${from} (evolved with a budget of ${budget} evaluations${speed})`;
        const group = `${m.finetuned_from ? 'fine-tuned' : 'from scratch'}, ${budget} evaluations`;
        const short = shortLabel(m.finetuned_from ? `${m.finetuned_from} → ${m.shape}` : `${m.controller} on ${m.shape}`, mean);
        this.list(PRETRAINED_DIR + m.file, label, short, group, mean, simpleLabel(m, mean));
        const run = /--out \S*?([^/\s]+)\.json/.exec(m.command ?? '')?.[1];
        if (run) this.studyRunOf.set(PRETRAINED_DIR + m.file, run);
      }
      for (const b of manifest.bodies ?? []) {
        // A body search's best body with its brain (`vsr campaign export` of a [[codesign]] group).
        const mean = Number(b.validation?.unseen?.mean);
        const speed = Number.isFinite(mean) ? `, ${unseenWords(mean)}` : '';
        const how = brainWords(b.condition);
        const label = `a body found by the body search: ${b.voxels} voxels, ${b.controller} ${how.long}${speed}`;
        const short = shortLabel(`${b.voxels} voxels, ${b.controller} ${how.short}`, mean);
        this.list(PRETRAINED_DIR + b.file, label, short, 'found by a body search', mean,
          shortLabel(`a body of ${b.voxels} voxels found by a search`, mean, ` ${LIST_SPEED_SIMPLE}`).replace(SPEED_MARK, ': '));
      }
      if (!this.studyAnyBody) this.listPending();
      this.describe();
    } catch (error) {
      this.hooks.message(`could not list the pretrained modules: ${messageOf(error)}`);
    }
    // The modules made here on earlier visits, after the pretrained ones (a damaged one is left out).
    for (const module of loadKeptModules()) await this.add(module, false, false).catch(() => {});
    this.doneListing?.(undefined);
  }

  /**
   * Lists a brain for any body of the manifest (`vsr campaign export` of an `[[any_body]]` group,
   * an entry of `modules` whose controller is a family for any body; `shape` names what it was
   * trained on, `bodies` how many when given), in its own group, named for a newcomer.
   * @param {any} m the manifest's entry
   */
  listAnyBody(m) {
    // Its speed: the median over the held-out bodies the study walked it on (it has no one body, so no `validation`).
    const set = heldOut(m.any_body);
    const median = set ? set.median : NaN;
    const speed = set ? `, ${heldOutLong(set)}` : '';
    // One training body (the study's biped-only condition) is named, as the other modules' bodies are.
    const one = m.bodies === 1 ? this.presets.find((p) => p.rows === m.rows)?.name : undefined;
    const on = one ? `one body alone, ${one}` : Number.isInteger(m.bodies) ? `${m.bodies} bodies at once` : `the bodies of ${m.shape}`;
    const name = familyName(m.controller);
    const label = `a brain for any body (${name}), trained on ${on} (evolved with a budget of ${count(m.budget ?? m.evaluations)} evaluations${speed})`;
    const key = PRETRAINED_DIR + m.file;
    if (set) this.heldOuts.set(key, { set, runs: Number.isInteger(m.chosen_from) ? m.chosen_from : 0 });
    const trained = one ?? (Number.isInteger(m.bodies) ? `${m.bodies} bodies` : m.shape);
    const simple = one ? `${bodySimple(one)} alone` : trained;
    this.list(key, label, shortLabel(`${name}, trained on ${trained}`, median, ` ${HELDOUT_SHORT}`), ANY_BODY_GROUP, median,
      shortLabel(`one brain for any body, trained on ${simple}`, median, ` ${HELDOUT_SIMPLE}`).replace(SPEED_MARK, ': '));
    if (isStudyAnyBody(m) && !this.studyAnyBody) this.studyAnyBody = key;
  }

  /** The study's brain for any body is not in pretrained/ yet: the list says so, in its place (it cannot be chosen). */
  listPending() {
    this.list(PENDING, `The study's brain for any body (attention, trained on many bodies): ${NOT_YET}`,
      `attention, any body: ${NOT_YET}`, ANY_BODY_GROUP);
    const option = [...this.select.options].find((o) => o.value === PENDING);
    if (option) option.disabled = true;
  }

  /** Keeps the modules made on the page (runs, imported files) for the next visit; a problem is said once. */
  keepMine() {
    const mine = [...this.held.values()].filter((m) => /^(run|disk):/.test(m.key))
      .map(({ key, label, short, text }) => ({ key, label, short, text }));
    const problem = keepModules(mine);
    if (problem && !this.keepWarned) this.hooks.message(problem);
    this.keepWarned ||= problem !== '';
  }

  /**
   * Lists a module under `group` (made when first used), its `short` name shown and its full
   * `label` on hover (and in {@link labels}).
   * @param {string} key @param {string} label @param {string} short @param {string} group
   * @param {number} [mean] its mean speed on the unseen terrains (m/s), the number in `short`
   * @param {string} [simple] its name in simple words (shown while “Simple words” is on), if it has one
   */
  list(key, label, short, group, mean = NaN, simple = '') {
    const groups = /** @type {HTMLOptGroupElement[]} */ ([...this.select.querySelectorAll('optgroup')]);
    let into = groups.find((g) => g.label === group);
    if (!into) {
      into = this.select.ownerDocument.createElement('optgroup');
      into.label = group;
      this.select.append(into);
    }
    const existing = [...this.select.options].find((o) => o.value === key);
    const option = existing ?? new Option(short, key);
    option.dataset.short = short;
    if (simple) option.dataset.plain = simple;
    this.labels.set(key, label);
    if (Number.isFinite(mean)) this.unseen.set(key, mean);
    this.name(option);
    if (!existing) into.append(option);
  }

  /**
   * Keeps every speed out of the list and its details while `on` (a tour question about speeds
   * waits for its answer: the list would give it away), and shows them again after.
   * @param {boolean} on
   */
  quiet(on) {
    if (on === this.hushed) return;
    this.hushed = on;
    for (const option of this.select.options) this.name(option);
    this.describe();
  }

  /** Writes an option's name: its short name and full title, or, while {@link quiet}, both without speeds. @param {HTMLOptionElement} option */
  name(option) {
    // In simple words, a study module by its plain name (the small walker, moved to the big walker: … on new ground).
    const simple = option.ownerDocument.documentElement.dataset.words === 'simple' ? option.dataset.plain : undefined;
    if (simple) { option.text = this.hushed ? simple.split(': ')[0] : simple; }
    const short = option.dataset.short ?? option.text;
    if (!simple) option.text = this.hushed ? short.split(SPEED_MARK)[0] : short;
    option.title = this.hushed ? HUSHED : this.labels.get(option.value) ?? short;
  }

  /** The study's runs are listed: a module's note says where its run stopped at another budget. @param {import('./lineage.js').Stop[]} runs */
  setStudyRuns(runs) {
    this.studyRuns = runs;
    this.describe();
  }

  /**
   * Adds (or replaces) a module held in the page and, unless `choose` is false, selects it;
   * rejects with a readable Error (adding nothing) when its run file is malformed. A module made
   * on the page (a run, an imported file) is kept for the next visit, unless `keep` is false.
   * @param {Module} module @param {boolean} [choose] @param {boolean} [keep] @returns {Promise<void>}
   */
  async add(module, choose = true, keep = true) {
    await describeRun(module.text);
    this.held.delete(module.key); // a module made again is the newest
    this.held.set(module.key, module);
    this.list(module.key, module.label, module.short ?? module.label, 'opened, imported or run here');
    if (keep) this.keepMine();
    if (!choose) return;
    this.select.value = module.key;
    this.describe();
  }

  /** Selects the module `key` if it is listed (the one a restored robot came from). @param {string} key */
  choose(key) {
    if (![...this.select.options].some((o) => o.value === key)) return;
    this.select.value = key;
    this.describe();
  }

  /** @returns {Promise<Module | null>} the selected module, read */
  async selected() {
    const key = this.select.value;
    if (!key) return null;
    const held = this.held.get(key);
    if (held) return held;
    const text = await fetchOk(key).then((r) => r.text());
    const module = { key, label: this.labels.get(key) ?? this.select.selectedOptions[0]?.text ?? key, text };
    this.held.set(key, module);
    return module;
  }

  /** @param {(module: Module) => void} action */
  async withSelected(action) {
    try {
      const module = await this.selected();
      if (module) action(module); else this.hooks.message('choose a module first');
    } catch (error) {
      this.hooks.message(`could not read the module: ${messageOf(error)}`);
    }
  }

  /** Shows what the selected module is. */
  async describe() {
    const ticket = ++this.described;
    try {
      const module = await this.selected();
      const info = module ? await describeRun(module.text) : null;
      if (ticket !== this.described) return; // another module was chosen meanwhile
      this.info = info;
      this.hooks.described?.(info);
      if (!info) { this.details.textContent = ''; return; }
      const body = (/** @type {string} */ rows) => bodyWords(rows, this.presets);
      const onBodies = info.bodies > 1 ? `on ${count(info.bodies)} bodies at once${info.bodySet ? ` (the body set ${info.bodySet.split(/[\\/]/).pop()})` : ''}` : `on ${body(info.shape)}`;
      const rows = info.foundBySearch ? `drives ${body(info.shape)} found by a body search`
        : `was ${info.finetunedFrom ? 'fine-tuned' : 'evolved'} ${onBodies}`
          + `${info.finetunedFrom ? ` from ${info.anyBody ? 'all the genes' : 'the attention'} of a brain trained on ${body(info.finetunedFrom)},` : ''}`;
      const took = info.evaluations > info.budget
        ? ` (it took ${count(info.evaluations)}: a ${info.foundBySearch ? 'search finishes its last round' : 'run finishes its last generation'})` : '';
      const what = info.anyBody ? `brain for any body (${familyName(info.controller)}), ${count(info.genes)} genes for every body,` : `${info.controller} brain of ${count(info.genes)} genes`;
      const walked = info.bodies > 1 ? ' (the mean over the bodies one evaluation walks)' : '';
      this.details.textContent = `This ${what} ${rows} with seed ${info.seed} and a budget of `
        + `${count(info.budget)} evaluations${took}, in ${info.seconds}-s episodes on ${info.terrain}`
        + (this.hushed ? `. ${HUSHED}.` : `; in training it walked ${decimal(info.fitness)} m/s${walked}.`);
      const lineage = lineageNote(this.studyRuns, this.studyRunOf.get(module?.key ?? '') ?? '');
      const unseen = this.unseen.get(module?.key ?? '');
      const { set, runs } = this.heldOuts.get(module?.key ?? '') ?? { set: null, runs: 0 };
      const typical = set && Number.isFinite(set.typical) && runs > 1
        ? ` It is the study's choice of ${runs} runs (by their speed on their own training bodies): the middle run's brain walked ${decimal(set.typical)} m/s there.` : '';
      const where = set ? ` The study walked it on ${set.bodies} bodies it never trained on, each on ${set.terrains}: the median of their mean speeds is ${decimal(set.median)} m/s, the speed beside it in the list; ${set.above} of the ${set.bodies} averaged more than 1 m/s.${typical}`
        : unseen === undefined ? '' : ` On ten terrains it never trained on, it averages ${decimal(unseen)} m/s, the speed beside it in the list.`;
      if (!this.hushed) this.details.textContent += lineage ? ` ${lineage}` : where;
      this.loadButton.title = info.anyBody
        ? 'Put it on your robot: all its genes, as trained (a brain for any body: every voxel works out its own weights from its place in the body)'
        : info.controller === 'attention'
          ? `Put it on your robot: it keeps its ${this.attentionGenes} attention genes (the block every voxel shares); `
            + 'the rest of its brain (each voxel position\'s output weights) is drawn new for your body'
          : `An ${info.controller} module's genes belong to the voxels of its own body: it goes only onto that same body`;
    } catch (error) {
      if (ticket === this.described) { this.details.textContent = ''; this.hooks.described?.(null); }
    }
  }

  /**
   * The module `key` (a served run file: pretrained/ or the study's runs), read and chosen in
   * the list; one not listed yet is added under `label` (the list shows `short`, if given).
   * @param {string} key @param {string} [label] @param {string} [short] @returns {Promise<Module>}
   */
  async read(key, label = key, short = undefined) {
    await this.listed;
    if ([...this.select.options].some((o) => o.value === key)) {
      this.choose(key);
      const module = await this.selected();
      if (module) return module;
    }
    const text = await fetchOk(key).then((r) => r.text());
    await this.add({ key, label, text, short });
    return /** @type {Module} */ (this.held.get(key));
  }

  async importFile() {
    const file = this.fileInput.files?.[0];
    if (!file) return;
    this.fileInput.value = ''; // choosing the same file again fires 'change' again
    try {
      const text = await file.text();
      await this.add({ key: `disk:${file.name}`, label: `${file.name} (imported)`, text });
      this.hooks.message('', 'import'); // an earlier file's message goes
    } catch (error) {
      this.hooks.message(`${file.name} is not a run file this page can read: ${messageOf(error)}`, 'import');
    }
  }
}
