// @ts-check
/**
 * The drawing: which cells of the editor's grid hold a voxel, with undo and redo. Cells
 * are (x, y) with x from the left and y from the bottom. Its rows (top first, `1111-1111-
 * 1001`) are the cells' bounding box: where the drawing sits on the grid does not change
 * the robot. A new shape (a preset, typed rows, a shared link) is placed at the bottom-left.
 */
import { size } from '../shared/format.js';

/** Most steps kept for undo. */
const MAX_HISTORY = 200;

export class Drawing {
  /** @param {number} width @param {number} height the grid, in cells */
  constructor(width, height) {
    this.width = width;
    this.height = height;
    /** @type {Set<number>} filled cells as y * width + x */
    this.cells = new Set();
    /** @type {Set<number>[]} */
    this.undoStack = [];
    /** @type {Set<number>[]} */
    this.redoStack = [];
    /** The state before the stroke under way, or null. @type {Set<number> | null} */
    this.strokeStart = null;
  }

  /** @param {number} x @param {number} y */
  has(x, y) { return this.cells.has(y * this.width + x); }

  /** @param {number} x @param {number} y */
  inside(x, y) { return x >= 0 && y >= 0 && x < this.width && y < this.height; }

  /** Begins a stroke: every change until `endStroke` is one undo step. */
  beginStroke() { this.strokeStart = new Set(this.cells); }

  /** Ends the stroke; returns whether it changed anything. */
  endStroke() {
    const before = this.strokeStart;
    this.strokeStart = null;
    if (!before || sameSet(before, this.cells)) return false;
    this.remember(before);
    return true;
  }

  /**
   * Fills or empties one cell (inside a stroke, or as its own undo step).
   * @param {number} x @param {number} y @param {boolean} filled
   * @returns {boolean} whether the cell changed
   */
  set(x, y, filled) {
    if (!this.inside(x, y) || this.has(x, y) === filled) return false;
    const before = this.strokeStart ? null : new Set(this.cells);
    if (filled) this.cells.add(y * this.width + x); else this.cells.delete(y * this.width + x);
    if (before) this.remember(before);
    return true;
  }

  /**
   * The rows the drawing would have with one cell changed, without changing anything.
   * @param {number} x @param {number} y @param {boolean} filled
   */
  rowsWith(x, y, filled) {
    const saved = this.cells;
    this.cells = new Set(saved);
    if (filled) this.cells.add(y * this.width + x); else this.cells.delete(y * this.width + x);
    const rows = this.rows();
    this.cells = saved;
    return rows;
  }

  /** Empties the grid (one undo step). */
  clear() { this.replace(new Set()); }

  /**
   * Replaces the drawing by `rows` (top first) at the bottom-left (one undo step).
   * @param {string} rows
   * @returns {string} '' or why the rows do not fit the grid
   */
  setRows(rows) {
    const lines = rows.trim().split('-').map((r) => r.trim());
    const height = lines.length;
    const width = Math.max(...lines.map((r) => r.length));
    if (lines.some((r) => !/^[01]+$/.test(r))) return 'rows hold only 1 (voxel) and 0 (empty), separated by -';
    const ragged = lines.findIndex((r) => r.length !== lines[0].length);
    if (ragged > 0) return `every row needs the same number of cells: row ${ragged + 1} has ${lines[ragged].length}, row 1 has ${lines[0].length}`;
    if (width > this.width || height > this.height) {
      return `that shape is ${size(width, height)} cells; the grid holds at most ${size(this.width, this.height)}`;
    }
    const next = new Set();
    lines.forEach((line, r) => {
      for (let x = 0; x < line.length; x++) if (line[x] === '1') next.add((height - 1 - r) * this.width + x);
    });
    this.replace(next);
    return '';
  }

  /** The drawing's rows, top first, cropped to its cells ('' when empty). */
  rows() {
    const box = this.box();
    if (!box) return '';
    const lines = [];
    for (let y = box.top; y >= box.bottom; y--) {
      let line = '';
      for (let x = box.left; x <= box.right; x++) line += this.has(x, y) ? '1' : '0';
      lines.push(line);
    }
    return lines.join('-');
  }

  /** The cells' bounding box, or null when empty. */
  box() {
    if (this.cells.size === 0) return null;
    const xs = [...this.cells].map((c) => c % this.width);
    const ys = [...this.cells].map((c) => Math.floor(c / this.width));
    return { left: Math.min(...xs), right: Math.max(...xs), bottom: Math.min(...ys), top: Math.max(...ys) };
  }

  /** The drawing's place on the grid: its bottom-left cell (0, 0 when empty). */
  origin() {
    const box = this.box();
    return box ? { left: box.left, bottom: box.bottom } : { left: 0, bottom: 0 };
  }

  undo() { return this.travel(this.undoStack, this.redoStack); }

  redo() { return this.travel(this.redoStack, this.undoStack); }

  get canUndo() { return this.undoStack.length > 0; }

  get canRedo() { return this.redoStack.length > 0; }

  /** @param {Set<number>} next */
  replace(next) {
    if (sameSet(next, this.cells)) return;
    this.remember(this.cells);
    this.cells = next;
  }

  /** @param {Set<number>} before */
  remember(before) {
    this.undoStack.push(new Set(before));
    if (this.undoStack.length > MAX_HISTORY) this.undoStack.shift();
    this.redoStack = [];
  }

  /** @param {Set<number>[]} from @param {Set<number>[]} to */
  travel(from, to) {
    const state = from.pop();
    if (!state) return false;
    to.push(this.cells);
    this.cells = state;
    return true;
  }
}

/** @param {Set<number>} a @param {Set<number>} b */
function sameSet(a, b) {
  return a.size === b.size && [...a].every((v) => b.has(v));
}
