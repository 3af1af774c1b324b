// @ts-check
/**
 * The body-search panel ("Search bodies for this brain"): starts a body search (as `vsr
 * codesign`) from the drawing, the module's own body or a 3 x 3 box, with the chosen module's
 * brain frozen or fine-tuned, or a brain from scratch, in a body-search coordinator worker
 * (codesign/coordinator.js) on the run settings' workers; shows its progress and the live
 * gallery (gallery.js); a click on a body loads it with its brain into the editor, where it
 * walks (and the page's Share link shares it; Fine-tune trains its attention brain on the
 * drawing); the first and the last best race side by side.
 * Problems (a wrong module, a drawing that is no body) are said in words that stay.
 */
import { foundBody } from '../robot/brain.js';
import { byId } from '../shared/dom.js';
import { download } from '../shared/export.js';
import { messageOf, spawn } from '../workers/kit.js';
import { plain } from '../shared/message.js';
import { FromCodesign, ToCodesign } from '../workers/codesign-protocol.js';
import { Gallery, paintLegend } from './gallery.js';
import { BOX_WORDS, planSearch, QUICK, searchWords } from './plan.js';
import { familyName } from '../shared/families.js';
import { count } from '../shared/format.js';
import { bestEntry, exportName, summaryWords } from './summary.js';
import { voxelCount } from '../runs/estimate.js';

/** Where the panel's problems are said (under its buttons, main.js places them), and a refused search's status. */
const SOURCE = 'codesign';
const NOT_STARTED = 'The search did not start: the message under the buttons says why.';

/**
 * @typedef {object} CodesignHooks
 * @property {() => {rows: string, ok: boolean, message: string}} body   the drawing now, and its check
 * @property {() => Promise<import('../modules/modules.js').Module | null>} module  the module chosen in "3 · Give it a brain"
 * @property {() => string} controller     the family chosen there (for a brain from scratch)
 * @property {() => {seed: string, terrain: string, workers: string}} run  the run settings' seed, terrain, workers
 * @property {(brain: import('../robot/brain.js').Brain) => Promise<void>} open  loads a body with its brain into the editor
 * @property {(racers: import('../viewer/race-lane.js').Racer[]) => void} race  races these robots (the race emptied first)
 * @property {() => void} share             shares the robot on the page as a link
 * @property {(text: string, source?: string) => void} message  an error, in words that stay until closed ('' with a source: its error goes)
 */

/** @typedef {import('../workers/codesign-protocol.js').Entry} Entry  a body with its brain, entry `index` of the search's file `source` */
/** @typedef {import('../workers/kit.js').WorkerOf<'codesign/coordinator.js'>} Coordinator */

export class CodesignPanel {
  /** @param {Document} doc @param {CodesignHooks} hooks */
  constructor(doc, hooks) {
    this.hooks = hooks;
    this.brain = byId(doc, 'codesign-brain', HTMLSelectElement);
    this.moduleKind('');
    this.from = byId(doc, 'codesign-from', HTMLSelectElement);
    this.from.querySelector('option[value="box"]')?.replaceChildren(BOX_WORDS);
    for (const n of doc.querySelectorAll('.codesign-batch')) n.textContent = String(QUICK.batch); // the legend's round, as planned
    this.budget = byId(doc, 'codesign-budget', HTMLInputElement);
    this.seconds = byId(doc, 'codesign-seconds', HTMLInputElement);
    this.buttons = {
      start: byId(doc, 'codesign-start', HTMLButtonElement), stop: byId(doc, 'codesign-stop', HTMLButtonElement),
      race: byId(doc, 'codesign-race', HTMLButtonElement), share: byId(doc, 'codesign-share', HTMLButtonElement),
      export: byId(doc, 'codesign-export', HTMLButtonElement),
    };
    this.progress = byId(doc, 'codesign-progress');
    /** The dot between the progress and the status, shown once there is a progress to say. */
    this.sep = byId(doc, 'codesign-sep');
    this.summary = byId(doc, 'codesign-summary');
    this.status = byId(doc, 'codesign-status');
    this.gallery = new Gallery(byId(doc, 'codesign-gallery'), (cell) => this.load(cell));
    paintLegend(byId(doc, 'codesign-scale'), byId(doc, 'codesign-no-speed'));
    /** @type {Coordinator | null} */
    this.coordinator = null;
    this.running = false;
    this.starting = false;
    /** The latest search's settings. @type {import('../workers/codesign-protocol.js').CodesignSettings | null} */
    this.settings = null;
    /** The coordinator said the search started (errors before that: 'did not start'). */
    this.started = false;
    /**
     * The latest search's last round (its summary says how long it took once it ends).
     * @type {Extract<import('../workers/codesign-protocol.js').FromCodesignMessage, {type: 'iteration'}> | null}
     */
    this.lastRound = null;
    /** The latest search's run file (when it ended). @type {string | null} */
    this.runFile = null;
    /** What the latest search evolved, in words (labels of its bodies). */
    this.what = '';
    /** The best cell after the first round and now, and their entries once fetched. */
    this.bests = { firstCell: /** @type {[number, number] | null} */ (null), lastCell: /** @type {[number, number] | null} */ (null),
      first: /** @type {Entry | null} */ (null), last: /** @type {Entry | null} */ (null) };
    /** The cell loaded last (Share shares it). @type {[number, number] | null} */
    this.chosen = null;
    this.tickets = 0;
    /** Entries asked of the coordinator, by ticket. @type {Map<number, (entry: Entry | null, message?: string) => void>} */
    this.asked = new Map();
    this.setQuick();
    this.wire();
    this.update();
  }

  setQuick() { [this.budget.value, this.seconds.value] = [String(QUICK.budget), String(QUICK.seconds)]; }

  /**
   * The module chosen under “3 · Give it a brain” is of the family `kind` ('' when none): the
   * menu says what each brain keeps of it (a brain for any body kept whole: bodies only).
   * @param {string} kind
   */
  moduleKind(kind) {
    for (const option of this.brain.options) {
      option.textContent = searchWords(/** @type {'frozen' | 'finetune' | 'scratch'} */ (option.value), kind).menu;
    }
  }

  wire() {
    const b = this.buttons;
    b.start.addEventListener('click', () => this.start());
    b.stop.addEventListener('click', () => this.coordinator?.postMessage({ type: ToCodesign.STOP }));
    b.race.addEventListener('click', () => this.raceFirstLast());
    b.share.addEventListener('click', () => { if (this.chosen) this.load(this.chosen, true); });
    b.export.addEventListener('click', () => { if (this.runFile) download(this.runFile, exportName(JSON.parse(this.runFile).config)); });
    this.brain.addEventListener('change', () => this.update());
  }

  /**
   * Chooses the brain and the start body (the tour's set-up); a search under way is left alone.
   * @param {{brain: string, from: string}} settings
   */
  setUp(settings) {
    if (this.running) return;
    this.brain.value = settings.brain;
    this.from.value = settings.from;
    this.setQuick();
    this.update();
  }

  /** Starts a search with the panel's settings; a problem is said in words (under the buttons) and starts nothing. */
  async start() {
    if (this.running || this.starting) return;
    this.starting = true;
    this.update();
    let plan;
    try {
      plan = await planSearch(
        { brain: this.brain.value, from: this.from.value, budget: this.budget.value, seconds: this.seconds.value }, this.hooks);
    } catch (error) {
      plan = { error: `the body search could not be set up: ${messageOf(error)}` };
    } finally {
      this.starting = false;
    }
    if ('error' in plan) { this.refuse(plan.error); return; }
    this.hooks.message('', SOURCE); // a refusal said before
    this.coordinator?.terminate(); // the previous search's archive
    this.asked.clear();
    this.runFile = null;
    this.chosen = null;
    this.bests = { firstCell: null, lastCell: null, first: null, last: null };
    const { settings, module, kind, workers } = plan;
    this.settings = settings;
    const from = { box: `from ${BOX_WORDS}`, drawing: 'from your drawing', module: 'from the module\'s own body' }[this.from.value] ?? '';
    this.what = `${settings.brain === 'scratch' ? `${familyName(settings.controller ?? '')} from scratch`
      : `${module?.label.replace(/ \([^()]*\)$/, '')}, ${searchWords(settings.brain, kind).short}`}, bodies ${from}`;
    const coordinator = spawn('codesign/coordinator.js', (msg) => this.onMessage(coordinator, msg),
      (text) => this.end(coordinator, `the body search stopped: ${text}`, 'failed'));
    this.coordinator = coordinator;
    this.running = true;
    this.started = false;
    this.lastRound = null;
    this.progress.textContent = `0 of ${count(settings.budget)} evaluations`;
    this.setStatus('starting…');
    this.summary.textContent = '';
    this.summary.dataset.updateMs = '0';
    coordinator.postMessage({ type: ToCodesign.START, settings, workers, module: module?.text ?? null });
    this.update();
  }

  /** A search that cannot start: says why. @param {string} why */
  refuse(why) {
    this.hooks.message(`The body search did not start: ${why}`, SOURCE);
    if (this.summary.textContent) this.summary.textContent = this.summary.textContent.replace(/^(Your last search: )?/, 'Your last search: '); // whose gallery
    this.setStatus(NOT_STARTED, 'not');
    this.update();
  }

  /** @param {Coordinator} from @param {import('../workers/codesign-protocol.js').FromCodesignMessage} msg */
  onMessage(from, msg) {
    if (from !== this.coordinator) return;
    switch (msg.type) {
      case FromCodesign.STARTED:
        this.started = true;
        this.gallery.setLayout(msg.layout);
        this.setStatus(`searching on ${msg.workers} worker${msg.workers === 1 ? '' : 's'}`);
        this.status.title = `bodies searched for ${this.what}`;
        break;
      case FromCodesign.ITERATION: this.onIteration(msg); break;
      case FromCodesign.ENTRY: {
        const answer = this.asked.get(msg.ticket);
        this.asked.delete(msg.ticket);
        answer?.(msg.entry, msg.message);
        break;
      }
      case FromCodesign.RECOVERED: this.hooks.message(msg.message); break;
      case FromCodesign.DONE: this.onDone(msg); break;
      case FromCodesign.ERROR:
        this.end(from, this.started ? `The body search failed: ${plain(msg.message)}` : `The body search did not start: ${plain(msg.message)}`,
          this.started ? 'failed' : NOT_STARTED);
        break;
      default: console.warn('unknown message from the body-search coordinator', msg);
    }
  }

  /** @param {Extract<import('../workers/codesign-protocol.js').FromCodesignMessage, {type: 'iteration'}>} msg */
  onIteration(msg) {
    const t0 = performance.now();
    const { record, gallery } = msg;
    this.gallery.show(gallery, record.iteration);
    this.progress.textContent = `${count(msg.evaluations)} of ${count(msg.planned)} evaluations`;
    const best = bestEntry(gallery);
    this.lastRound = msg;
    this.summary.textContent = summaryWords(this.what, msg, false);
    this.summary.dataset.filled = String(gallery.length);
    this.summary.dataset.best = String(best?.fitness ?? '');
    if (best) {
      if (record.iteration === 0) this.bests.firstCell = best.cell;
      this.bests.lastCell = best.cell;
    }
    if (record.iteration === 0 && best) this.ask(best.cell, (entry) => { this.bests.first = entry; this.update(); });
    // The longest gallery update so far (ms), for the tests: the page's main thread must stay free.
    this.summary.dataset.updateMs = String(Math.max(Number(this.summary.dataset.updateMs ?? 0), performance.now() - t0));
  }

  /** @param {{stopped: boolean, runFile: string | null}} msg */
  onDone(msg) {
    if (this.lastRound) this.summary.textContent = summaryWords(this.what, this.lastRound, true);
    this.running = false;
    this.runFile = msg.runFile;
    this.setStatus(msg.stopped ? 'stopped' : 'finished');
    const last = this.bests.lastCell;
    if (last) this.ask(last, (entry) => { this.bests.last = entry; this.update(); });
    this.update();
  }

  /** The search ended with a problem: says it, and ends the coordinator. @param {Coordinator} which @param {string} error @param {string} status */
  end(which, error, status) {
    if (which !== this.coordinator) return;
    which.terminate();
    this.coordinator = null;
    this.running = false;
    this.hooks.message(error, SOURCE);
    this.setStatus(status);
    this.update();
  }

  /** Asks the coordinator for the body in `cell` with its brain. @param {[number, number]} cell @param {(entry: Entry | null, message?: string) => void} answer */
  ask(cell, answer) {
    if (!this.coordinator) return;
    const ticket = ++this.tickets;
    this.asked.set(ticket, answer);
    this.coordinator.postMessage({ type: ToCodesign.ENTRY, cell, ticket });
  }

  /**
   * Loads the body of `cell` with its brain into the editor (it walks there), then shares it
   * as a link when asked. @param {[number, number]} cell @param {boolean} [share]
   */
  load(cell, share = false) {
    this.ask(cell, async (entry, message) => {
      if (!entry) { this.hooks.message(`that body could not be loaded: ${message ?? 'it is no longer in the gallery'}`); return; }
      this.chosen = cell;
      this.gallery.choose(cell);
      const walks = this.lastRound?.gallery.find((/** @type {{cell: number[]}} */ g) => g.cell.join() === cell.join())?.measurements;
      await this.hooks.open(foundBody(entry, this.settings, this.what, walks));
      document.body.dataset.codesignLoaded = entry.shape;
      this.update();
      if (share) this.hooks.share();
    });
  }

  /** Races the best body after the first round against the best at the end. */
  raceFirstLast() {
    const { first, last } = this.bests;
    if (!first || !last) return;
    const racer = (/** @type {Entry} */ e, /** @type {string} */ when) => ({
      label: `${when}, ${voxelCount(e.shape)} voxels (${this.what})`, shape: e.shape, controller: e.controller, genome: new Float32Array(e.genome),
    });
    this.hooks.race([racer(first, 'best after the first round'), racer(last, 'best at the end')]);
  }

  /**
   * Says where the search is, after its progress (the dot between them only once there is a
   * progress). @param {string} text @param {string} [state] body's data-codesign (default: the first word)
   */
  setStatus(text, state = text === NOT_STARTED ? 'not' : text.split(' ')[0].replace('…', '')) {
    this.status.textContent = text;
    if (text === NOT_STARTED) this.progress.textContent = ''; // no evaluations to count
    this.sep.hidden = !this.progress.textContent;
    document.body.dataset.codesign = state;
  }

  /** Enables what applies now. */
  update() {
    const b = this.buttons;
    b.start.disabled = this.running || this.starting;
    b.stop.disabled = !this.running;
    b.race.disabled = !this.bests.first || !this.bests.last;
    b.share.disabled = this.chosen === null || this.coordinator === null;
    b.export.disabled = this.runFile === null;
    for (const input of [this.brain, this.from, this.budget, this.seconds]) input.disabled = this.running;
  }
}
