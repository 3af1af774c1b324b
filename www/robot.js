// @ts-check
/**
 * The robot of the page: its body and its brain. The drawing is the one source of truth for
 * the body: the editor draws it, the viewer walks it, and runs evolve it. The brain (a
 * controller family and its genome for the drawn body) drives it: none (the phase gait), a
 * transplanted module, an evolved best, or the genome of a shared link. When the body
 * changes, the brain's genome follows it by grid position (the core's remap). Its state is
 * what the page keeps across reloads and shares as a link (pageState, restore).
 */
import { followEdit, ownBody, transplanted } from './brain.js';
import { checkShape } from './core.js';
import { showGeneCount } from './gene-count.js';
import { messageOf } from './kit.js';
import { plain } from './message.js';

/** @typedef {import('./brain.js').Brain} Brain */

/**
 * @typedef {object} RobotParts  what the robot is shown and edited with (main.js makes them)
 * @property {import('./core.js').Defaults} defaults
 * @property {import('./drawing.js').Drawing} drawing
 * @property {import('./editor.js').Editor} editor
 * @property {import('./viewer.js').Viewer} viewer
 * @property {import('./message.js').MessageBox} messages
 * @property {import('./speed-note.js').SpeedNote} speedNote
 * @property {import('./run-panel.js').RunPanel} runs
 * @property {() => void} keep  the state changed: keep it (and its link) soon
 */

export class Robot {
  /** @param {Document} doc @param {RobotParts} parts */
  constructor(doc, parts) {
    this.parts = parts;
    this.el = (/** @type {string} */ id) => /** @type {any} */ (doc.getElementById(id));
    this.rowsInput = /** @type {HTMLInputElement} */ (this.el('rows'));
    this.controllerSelect = /** @type {HTMLSelectElement} */ (this.el('controller'));
    this.presetSelect = /** @type {HTMLSelectElement} */ (this.el('preset'));
    /** @type {Brain | null} */
    this.brain = null;
    /** The last check of the drawing. @type {import('./core.js').ShapeCheck} */
    this.check = checkShape('');
    this.edits = 0;
    /**
     * The next body change is an edit of the walking robot: rebuild it where it stands, in its
     * posture and motion; the edit's shift of the bounding box, or false.
     * @type {import('./protocol.js').Shift | false}
     */
    this.keepPlace = false;
    /** A brain set aside by choosing another controller family, back if that family is chosen again. @type {Brain | null} */
    this.shelved = null;
    /** A run uses the robot: its drawing is locked. */
    this.running = false;
  }

  /** @param {string} text an error for the person, or '' to clear it */
  error(text) {
    this.parts.messages.show(text, 'error');
  }

  /** Re-checks the drawing: words, pieces, parameter count, buttons. */
  updateCheck() {
    const { drawing, editor, messages, defaults } = this.parts;
    const rows = drawing.rows();
    const check = checkShape(rows);
    this.check = check;
    editor.setPieces(check.ok ? null : check.pieces);
    this.rowsInput.value = rows;
    const status = this.el('shape-status');
    if (check.ok) {
      status.textContent = `${check.voxels} voxel${check.voxels === 1 ? '' : 's'} · ${rows}`;
      messages.clear('validation', 'error');
    } else {
      const pieces = check.pieces.length > 1 ? `; each of its ${check.pieces.length} pieces has its own colour` : '';
      status.textContent = check.pieces.length > 1 ? `Not a robot yet: ${check.pieces.length} separate pieces` : 'Not a robot yet: no voxels';
      messages.show(`Your drawing is not a robot yet: ${plain(check.message)}${pieces}. Evolve and Fine-tune are off until it is.`, 'validation');
    }
    status.dataset.ok = String(check.ok);
    this.presetSelect.value = defaults.presets.find((p) => p.rows === rows)?.rows ?? '';
    this.updateParams();
    this.updateButtons();
  }

  /** Says how many genes the chosen family has for this body, and what they are. */
  updateParams() {
    showGeneCount(this.el('param-count'), this.check, this.controllerSelect.value, this.parts.defaults.attentionGenes);
  }

  updateButtons() {
    const { drawing, runs } = this.parts;
    const running = this.running;
    this.el('undo').disabled = running || !drawing.canUndo;
    this.el('redo').disabled = running || !drawing.canRedo;
    this.el('clear').disabled = running;
    this.presetSelect.disabled = running;
    this.rowsInput.disabled = running;
    this.el('module-load').disabled = running || !this.check.ok;
    this.el('module-open').disabled = running;
    runs.update();
  }

  /** The drawing's place on the grid (its bottom-left cell). */
  origin() {
    const box = this.parts.drawing.box();
    return box ? { left: box.left, bottom: box.bottom } : { left: 0, bottom: 0 };
  }

  /** The drawing changed (a stroke, undo, a preset, typed rows, an edit of the walking robot). */
  bodyChanged() {
    this.updateCheck();
    if (!this.check.ok) { this.parts.keep(); return; }
    const rows = this.parts.drawing.rows();
    const brain = this.brain;
    if (brain && brain.rows !== rows) {
      try {
        this.brain = followEdit(brain, rows, this.origin(), this.seed(), ++this.edits);
      } catch (error) {
        this.error(`the controller could not follow the edit: ${messageOf(error)}`);
        this.brain = null;
      }
    } else if (brain) {
      this.brain = { ...brain, origin: this.origin() };
    }
    this.showBrain();
    this.parts.keep();
  }

  /** Sends the drawing and its brain to the viewer and says what drives it. */
  showBrain() {
    const { drawing, viewer, speedNote, runs } = this.parts;
    const brain = this.brain;
    if (brain) { this.controllerSelect.value = brain.controller; this.shelved = null; }
    this.updateParams();
    const seconds = this.episodeSeconds();
    viewer.show(drawing.rows(), brain ? { controller: brain.controller, genome: brain.genome } : null, this.keepPlace, seconds);
    speedNote.show(brain, viewer.terrain.value.trim(), seconds, !this.running);
    runs.showWalking(brain?.run === true);
    this.el('gait').hidden = brain !== null; // its settings drive only a robot with no brain
    this.keepPlace = false;
    this.el('driver').textContent = brain
      ? `Driven by: ${brain.label} (${brain.controller}, ${brain.genome.length} genes).`
      : 'Driven by: the phase gait (no brain yet: evolve one, or load a module).';
    this.updateButtons();
  }

  /** A new brain drives the robot (null: the phase gait). @param {Brain | null} brain */
  drive(brain) {
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
    const kind = this.controllerSelect.value;
    const { brain, shelved } = this;
    if (brain && brain.controller !== kind) {
      this.brain = null;
      this.showBrain();
      this.shelved = brain;
      this.parts.messages.show(`The ${brain.controller} brain is set aside (choose ${brain.controller} again to get it back); `
        + `the phase gait drives the robot until you evolve a ${kind} controller.`, 'note');
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

  /** A click on the walking robot: remove that voxel, or add one next to it. @param {{voxel: number, dx: number, dy: number}} pick */
  editWalking(pick) {
    const { drawing, editor, messages } = this.parts;
    if (this.running) { messages.show('A run is using this robot: stop it to edit the robot.', 'note'); return; }
    const box = drawing.box();
    if (!box || !this.check.ok) return;
    const cells = [];
    for (let y = box.bottom; y <= box.top; y++) for (let x = box.left; x <= box.right; x++) if (drawing.has(x, y)) cells.push([x, y]);
    const cell = cells[pick.voxel];
    if (!cell) return;
    const [x, y] = [cell[0] + pick.dx, cell[1] + pick.dy];
    const adding = pick.dx !== 0 || pick.dy !== 0;
    if (!drawing.inside(x, y)) { this.error('that cell is outside the drawing grid'); return; }
    if (adding && drawing.has(x, y)) return;
    const after = checkShape(drawing.rowsWith(x, y, adding));
    if (!after.ok) {
      this.error(after.pieces.length === 0 ? 'A robot needs at least one voxel; not done'
        : `Removing that voxel would split the robot into ${after.pieces.length} pieces; not done`);
      return;
    }
    const from = drawing.rows();
    drawing.set(x, y, adding);
    const moved = drawing.box();
    this.keepPlace = moved ? { from, dx: box.left - moved.left, dy: box.bottom - moved.bottom } : false;
    editor.draw();
    this.bodyChanged();
  }

  /** Puts a module on the drawn robot (the core's transplant for attention). @param {import('./modules.js').Module} module */
  loadModule(module) {
    if (!this.check.ok) { this.error('draw a valid robot first'); return; }
    try {
      const brain = transplanted(module, this.parts.drawing.rows(), this.origin(), this.seed());
      this.error('');
      this.drive(brain);
    } catch (error) {
      this.error(messageOf(error));
    }
  }

  /** Replaces the drawing by the module's own body and genome. @param {import('./modules.js').Module} module */
  openModule(module) {
    const { drawing, editor } = this.parts;
    try {
      const next = ownBody(module, { left: 0, bottom: 0 }); // drawn at the bottom-left
      const problem = drawing.setRows(next.rows);
      if (problem) { this.error(`this module's body does not fit the grid: ${problem}`); return; }
      this.brain = next;
      this.error('');
      editor.draw();
      this.bodyChanged();
    } catch (error) {
      this.error(messageOf(error));
    }
  }

  /** Draws `rows`, driven by the phase gait. @param {string} rows */
  setBody(rows) {
    const problem = this.parts.drawing.setRows(rows);
    if (problem) throw new Error(problem);
    this.brain = null;
    this.shelved = null;
    this.parts.editor.draw();
    this.bodyChanged();
  }

  /** @returns {import('./share.js').PageState} */
  pageState() {
    const { drawing, viewer, runs } = this.parts;
    const brain = this.brain;
    return {
      rows: drawing.rows(), controller: this.controllerSelect.value, terrain: viewer.terrain.value, run: runs.values(),
      brain: brain && brain.rows === drawing.rows()
        ? { controller: brain.controller, genome: brain.genome, label: brain.label, module: brain.module } : null,
    };
  }

  /**
   * Shows a state from a link or storage; a robot that does not fit the grid is refused.
   * @param {import('./share.js').PageState} state
   * @returns {Promise<string>} '' or why nothing was shown
   */
  async restore(state) {
    const { drawing, editor, viewer, runs, defaults } = this.parts;
    const problem = drawing.setRows(state.rows);
    if (problem) return problem;
    drawing.undoStack = [];
    if (defaults.controllers.includes(state.controller)) this.controllerSelect.value = state.controller;
    if (state.terrain) viewer.terrain.value = state.terrain;
    runs.setValues(state.run);
    this.brain = null;
    if (state.brain) {
      const brain = { ...state.brain, rows: state.rows, origin: this.origin(), source: /** @type {string | null} */ (null) };
      this.brain = brain;
      if (state.brain.module) {
        try {
          const text = await fetch(state.brain.module).then((r) => (r.ok ? r.text() : Promise.reject(new Error(`HTTP ${r.status}`))));
          brain.source = text;
        } catch (error) {
          this.error(`the module ${state.brain.module} could not be fetched, so this robot cannot be fine-tuned: ${messageOf(error)}`);
        }
      }
    }
    editor.draw();
    this.bodyChanged();
    return '';
  }
}
