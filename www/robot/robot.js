// @ts-check
/**
 * The robot of the page: its body and its brain. The drawing is the one source of truth for
 * the body: the editor draws it, the viewer walks it, and runs evolve it. The brain (a
 * controller family and its genome for the drawn body) drives it: none (the phase gait), a
 * transplanted module, an evolved best, or the genome of a shared link. When the body
 * changes, the brain's genome follows it by grid position (the core's remap). Its state is
 * what the page keeps across reloads and shares as a link (state.js); a click on the
 * walking robot edits it (walking-edit.js). The core answers from its worker (workers/core.js): brain
 * changes apply one at a time, in the order asked, each on the drawing as it was when asked.
 */
import { followEdit, ownBody, transplanted } from './brain.js';
import { checkShape } from '../workers/core.js';
import { byId } from '../shared/dom.js';
import { showGeneCount } from './gene-count.js';
import { messageOf } from '../workers/kit.js';
import { applyState } from './state.js';
import { familyName } from '../shared/families.js';
import { checkWords, driverWords, showWithSpeeds, walkingWords } from './words.js';

/** @typedef {import('./brain.js').Brain} Brain */

/** The check of a drawing not checked (yet, or the core could not answer): not a robot. @type {import('../workers/core.js').ShapeCheck} */
const UNCHECKED = { ok: false, message: '', voxels: 0, pieces: [], params: [] };

/**
 * @typedef {object} RobotParts  what the robot is shown and edited with (main.js makes them)
 * @property {import('../workers/core.js').Defaults} defaults
 * @property {import('./drawing.js').Drawing} drawing
 * @property {import('./editor.js').Editor} editor
 * @property {import('../viewer/viewer.js').Viewer} viewer
 * @property {import('../shared/message.js').MessageBox} messages
 * @property {import('../shared/typed-field.js').TypedField} rows  the rows typed as text (draw-controls.js)
 * @property {import('./speed-note.js').SpeedNote} speedNote
 * @property {import('../runs/panel.js').RunPanel} runs
 * @property {() => void} keep  the state changed: keep it (and its link) soon
 * @property {(kind: string) => void} [familyShown]  the family menu shows `kind` (chosen, or the brain's)
 */

export class Robot {
  /** @param {Document} doc @param {RobotParts} parts */
  constructor(doc, parts) {
    this.parts = parts;
    this.doc = doc;
    this.controllerSelect = byId(this.doc, 'controller', HTMLSelectElement);
    this.presetSelect = byId(this.doc, 'preset', HTMLSelectElement);
    /** @type {Brain | null} */
    this.brain = null;
    /** The latest check of the drawing shown (none yet: not a robot). @type {import('../workers/core.js').ShapeCheck} */
    this.check = UNCHECKED;
    /** Checks asked: only the latest one's answer is shown. */
    this.checks = 0;
    /** The changes of the brain asked so far, done one after the other. @type {Promise<unknown>} */
    this.queue = Promise.resolve();
    this.edits = 0;
    /** A brain set aside by choosing another controller family, back if that family is chosen again. @type {Brain | null} */
    this.shelved = null;
    /** A run uses the robot: its drawing is locked. */
    this.running = false;
    /** The body the viewer walks (the last whole drawing; '' before the first). */
    this.walkingRows = '';
  }

  /** @param {string} text an error for the person (it stays until closed) */
  error(text) {
    this.parts.messages.show(text, 'error');
  }

  /**
   * Runs `task` after every change asked before it: the brain changes one at a time, in order.
   * @template T @param {() => Promise<T> | T} task @returns {Promise<T>}
   */
  serial(task) {
    const done = this.queue.then(task);
    this.queue = done.catch(() => {});
    return done;
  }

  /**
   * Shows the drawing's rows at once and re-checks it (the core's check): words, pieces,
   * parameter count, buttons, once the core answers.
   * @returns {Promise<import('../workers/core.js').ShapeCheck>} the check of the drawing now
   */
  updateCheck() {
    const rows = this.parts.drawing.rows();
    this.parts.rows.value = rows; // the field shows what the page uses: its message about typed rows goes
    this.presetSelect.value = this.parts.defaults.presets.find((p) => p.rows === rows)?.rows ?? '';
    const ticket = ++this.checks;
    const checked = checkShape(rows);
    checked.then((check) => { if (ticket === this.checks) this.showCheck(rows, check); }, (error) => {
      this.error(`the drawing could not be checked: ${messageOf(error)}`);
      if (ticket === this.checks) this.showCheck(rows, null);
    });
    return checked;
  }

  /**
   * Shows the check of the drawing `rows`; null: it could not be checked, so it is not taken for a robot.
   * @param {string} rows @param {import('../workers/core.js').ShapeCheck | null} check
   */
  showCheck(rows, check) {
    const { editor, messages } = this.parts;
    this.check = check ?? UNCHECKED;
    editor.setPieces(check && !check.ok ? check.pieces : null);
    const status = byId(this.doc, 'shape-status');
    const { status: line, problem } = checkWords(rows, check);
    status.textContent = line;
    if (problem) messages.show(problem, 'validation');
    else if (check) messages.clear('validation');
    status.dataset.ok = String(this.check.ok);
    this.updateParams();
    this.updateButtons();
  }

  /** Says how many genes the chosen family has for this body, and what they are; and what drives the robot. */
  updateParams() {
    showGeneCount(byId(this.doc, 'param-count'), this.check, this.controllerSelect.value, this.parts.defaults.attentionGenes,
      walkingWords(this.brain, this.walkingRows));
    this.parts.familyShown?.(this.controllerSelect.value);
    showWithSpeeds(byId(this.doc, 'driver'), driverWords(this.brain, this.check, this.walkingRows));
  }

  updateButtons() {
    const { drawing, runs } = this.parts;
    const running = this.running;
    byId(this.doc, 'undo', HTMLButtonElement).disabled = running || !drawing.canUndo;
    byId(this.doc, 'redo', HTMLButtonElement).disabled = running || !drawing.canRedo;
    byId(this.doc, 'clear', HTMLButtonElement).disabled = running;
    this.presetSelect.disabled = running;
    this.parts.rows.input.disabled = running;
    byId(this.doc, 'module-load', HTMLButtonElement).disabled = running || !this.check.ok;
    byId(this.doc, 'module-open', HTMLButtonElement).disabled = running;
    runs.update();
  }

  /**
   * The drawing changed (a stroke, undo, a preset, typed rows, an edit of the walking robot):
   * it is checked, and the brain follows the new body.
   * @param {import('../workers/protocol.js').Shift | false} [keepPlace] an edit of the walking robot:
   *   rebuild it where it stands, in its posture and motion (the edit's shift of the bounding box)
   * @returns {Promise<void>} once the robot walks the drawing (a problem is shown)
   */
  bodyChanged(keepPlace = false) {
    const change = this.change(keepPlace);
    return this.serial(() => this.follow(change)).catch((error) => this.error(messageOf(error)));
  }

  /** The drawing as it is now, and its check asked. @param {import('../workers/protocol.js').Shift | false} keepPlace */
  change(keepPlace) {
    return { rows: this.parts.drawing.rows(), origin: this.parts.drawing.origin(), seed: this.seed(), keepPlace, checked: this.updateCheck() };
  }

  /** The brain follows the body of `change` (the core's remap) and the viewer walks it. @param {ReturnType<Robot['change']>} change */
  async follow({ rows, origin, seed, keepPlace, checked }) {
    if (!(await checked.catch(() => UNCHECKED)).ok) { this.parts.keep(); return; } // a failed check is said by updateCheck
    const brain = this.brain;
    if (brain && brain.rows !== rows) {
      try {
        this.brain = await followEdit(brain, rows, origin, seed, ++this.edits);
      } catch (error) {
        this.error(`the controller could not follow the edit: ${messageOf(error)}`);
        this.brain = null;
      }
    } else if (brain) {
      this.brain = { ...brain, origin };
    }
    this.showBrain(rows, keepPlace);
    this.parts.keep();
  }

  /**
   * Sends the body and its brain to the viewer and says what drives it.
   * @param {string} [rows] the body (the brain's, else the drawing)
   * @param {import('../workers/protocol.js').Shift | false} [keepPlace] see {@link Robot.bodyChanged}
   */
  showBrain(rows = this.brain?.rows ?? this.parts.drawing.rows(), keepPlace = false) {
    const { viewer, speedNote, runs } = this.parts;
    const brain = this.brain;
    if (brain) { this.controllerSelect.value = brain.controller; this.shelved = null; }
    this.updateParams();
    const seconds = this.episodeSeconds();
    viewer.show(rows, brain ? { controller: brain.controller, genome: brain.genome } : null, keepPlace, seconds);
    this.walkingRows = rows;
    speedNote.show(brain, viewer.terrain.value.trim(), seconds, !this.running);
    runs.showWalking(brain?.run === true);
    byId(this.doc, 'gait', HTMLDetailsElement).hidden = brain !== null; // its settings drive only a robot with no brain
    showWithSpeeds(byId(this.doc, 'driver'), driverWords(this.brain, this.check, this.walkingRows));
    this.updateButtons();
  }

  /** A new brain drives the robot (null: the phase gait), after the changes asked before. @param {Brain | null} brain */
  drive(brain) {
    return this.serial(() => this.setBrain(brain)).catch((error) => this.error(messageOf(error)));
  }

  /** @param {Brain | null} brain */
  setBrain(brain) {
    this.brain = brain;
    this.showBrain();
    this.parts.keep();
  }

  /** The viewer's episode (s): the one its brain was trained on, else the run settings'. */
  episodeSeconds() {
    const typed = Number(this.parts.runs.inputs.seconds.value);
    return this.brain?.seconds ?? (typed > 0 && typed <= 3600 ? typed : this.parts.defaults.quick.seconds);
  }

  /** Measures the walking brain's speed again (the terrain or the episode changed). */
  remeasure() {
    this.parts.speedNote.show(this.brain, this.parts.viewer.terrain.value.trim(), this.episodeSeconds());
  }

  /**
   * Another controller family was chosen: the robot's brain belongs to one family, so a brain of
   * another family is set aside (the phase gait drives the robot until a run gives it one), and
   * comes back when its family is chosen again.
   */
  controllerChosen() {
    return this.serial(() => this.chooseController(this.controllerSelect.value)).catch((error) => this.error(messageOf(error)));
  }

  /** @param {string} kind */
  chooseController(kind) {
    const { brain, shelved } = this;
    if (brain && brain.controller !== kind) {
      this.brain = null;
      this.showBrain();
      this.shelved = brain;
      const [was, now] = [familyName(brain.controller), familyName(kind)];
      this.parts.messages.show(`The ${was} brain is set aside (choose “${was}” again to get it back); `
        + `the phase gait drives the robot until you evolve a ${now} controller.`, 'note');
    } else if (!brain && shelved && shelved.controller === kind && shelved.rows === this.parts.drawing.rows()) {
      this.brain = shelved;
      this.showBrain();
    }
    this.updateParams();
    this.parts.keep();
  }

  /** @returns {number} the run seed in the form (0 when not a number) */
  seed() {
    const s = Number(this.parts.runs.inputs.seed.value);
    return Number.isSafeInteger(s) && s >= 0 ? s : 0;
  }

  /**
   * Puts a module on the drawn robot (the core's transplant for attention).
   * @param {import('../modules/modules.js').Module} module @returns {Promise<void>} once done (a problem is shown)
   */
  loadModule(module) {
    if (!this.check.ok) { this.error('draw a valid robot first'); return Promise.resolve(); }
    const [rows, origin, seed] = [this.parts.drawing.rows(), this.parts.drawing.origin(), this.seed()];
    return this.serial(async () => {
      const brain = await transplanted(module, rows, origin, seed);
      this.setBrain(brain);
    }).catch((error) => this.error(messageOf(error)));
  }

  /**
   * Replaces the drawing by the module's own body and genome.
   * @param {import('../modules/modules.js').Module} module @returns {Promise<void>} once done (a problem is shown)
   */
  openModule(module) {
    return this.openBrain(() => ownBody(module, { left: 0, bottom: 0 }), 'this module\'s body'); // drawn at the bottom-left
  }

  /**
   * Replaces the drawing by a brain's own body (`brain.rows`), the brain driving it: a module
   * opened, a body found by the body search.
   * @param {() => Promise<Brain> | Brain} make the brain, made in its turn @param {string} [what] the body, in words
   * @returns {Promise<void>} once done (a problem is shown)
   */
  openBrain(make, what = 'this body') {
    const { drawing, editor } = this.parts;
    return this.serial(async () => {
      const next = await make();
      const problem = drawing.setRows(next.rows);
      if (problem) { this.error(`${what} does not fit the grid: ${problem}`); return; }
      this.brain = next;
      editor.draw();
      await this.follow(this.change(false));
    }).catch((error) => this.error(messageOf(error)));
  }

  /** Draws `rows`, driven by the phase gait; rejects when they do not fit. @param {string} rows */
  setBody(rows) {
    return this.serial(async () => {
      const problem = this.parts.drawing.setRows(rows);
      if (problem) throw new Error(problem);
      this.brain = null;
      this.shelved = null;
      this.parts.editor.draw();
      await this.follow(this.change(false));
    });
  }

  /**
   * Shows a state from a link or storage, in its turn; a robot that does not fit the grid is refused.
   * @param {import('../keep/share.js').PageState} state @returns {Promise<string>} '' or why nothing was shown
   */
  restore(state) {
    return this.serial(() => applyState(this, state)).catch((error) => messageOf(error));
  }
}
