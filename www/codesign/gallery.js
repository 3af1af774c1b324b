// @ts-check
/**
 * The body-search gallery: the archive as a grid, body size (voxels) across and number of feet
 * up, each filled cell its best body drawn small on a canvas (no element per voxel), coloured
 * by its speed on one scale (red 0 m/s, yellow half the fastest, green the fastest found so far;
 * the legend's strip is painted from the same scale), the bodies found in the latest iteration
 * outlined. A click on a body hands its cell to the page, which loads it.
 */
import { decimal } from '../shared/format.js';

/** @typedef {import('../workers/codesign-protocol.js').GalleryEntry} GalleryEntry */
/** @typedef {import('../workers/codesign-protocol.js').Layout} Layout */

/** Canvas size of one body (CSS pixels). */
const BODY_W = 72;
const BODY_H = 44;

/**
 * The speed scale, the one place its colours are: red at 0 m/s (or less), yellow at half the
 * fastest, green at the fastest found so far (mixed in between: orange, yellow-green).
 */
const SCALE = [[205, 45, 40], [235, 185, 30], [40, 160, 70]];
/** A body that fell over (no speed). */
export const NO_SPEED = 'rgb(150, 150, 150)';

/** The scale's colour at `t` (0: 0 m/s, 1: the fastest). @param {number} t */
function scaleAt(t) {
  const x = Math.max(0, Math.min(1, t)) * (SCALE.length - 1);
  const i = Math.min(SCALE.length - 2, Math.floor(x));
  const f = x - i;
  const [r, g, b] = SCALE[i].map((v, k) => Math.round(v + f * (SCALE[i + 1][k] - v)));
  return `rgb(${r}, ${g}, ${b})`;
}

/** A speed as a colour on the scale: `best` is green. @param {number | null} speed @param {number} best */
export function speedColour(speed, best) {
  if (speed === null || !Number.isFinite(speed)) return NO_SPEED;
  return scaleAt(best > 0 ? speed / best : 0);
}

/**
 * Paints the legend from the scale: `strip` as the scale from 0 m/s to the fastest, `none` as
 * a body with no speed. @param {HTMLElement | null} strip @param {HTMLElement | null} none
 */
export function paintLegend(strip, none) {
  if (strip) strip.style.background = `linear-gradient(to right, ${[0, 0.25, 0.5, 0.75, 1].map(scaleAt).join(', ')})`;
  if (none) none.style.background = NO_SPEED;
}

/** The voxel counts of size column `c`, in words. @param {Layout} layout @param {number} c */
export function sizeWords(layout, c) {
  const low = layout.minVoxels + c * layout.sizeBin;
  const high = Math.min(low + layout.sizeBin - 1, layout.maxVoxels);
  return high === low ? String(low) : `${low}–${high}`;
}

/** Feet row `r` (0: one foot), in words. @param {Layout} layout @param {number} r */
export function feetWords(layout, r) {
  const n = r + 1;
  if (n === layout.maxFeet) return `${n}+ feet`;
  return n === 1 ? '1 foot' : `${n} feet`;
}

export class Gallery {
  /** @param {HTMLElement} box @param {(cell: [number, number], entry: GalleryEntry) => void} pick */
  constructor(box, pick) {
    this.box = box;
    this.pick = pick;
    /** @type {Layout | null} */
    this.layout = null;
    /** The cells' elements by "size,feet". @type {Map<string, HTMLElement>} */
    this.cells = new Map();
    /** What each filled cell shows now, to redraw only what changed. @type {Map<string, string>} */
    this.drawn = new Map();
    /** The cell loaded last (marked). */
    this.chosen = '';
    /** The scroll hint above the grid. @type {HTMLElement | null} */
    this.hint = null;
    addEventListener('resize', () => this.fitHint());
  }

  /** Builds the empty grid for `layout`. @param {Layout} layout */
  setLayout(layout) {
    this.layout = layout;
    this.cells.clear();
    this.drawn.clear();
    this.chosen = '';
    const grid = document.createElement('div');
    grid.className = 'codesign-grid';
    grid.style.gridTemplateColumns = `auto repeat(${layout.columns}, ${BODY_W + 8}px)`;
    for (let r = layout.rows - 1; r >= 0; r--) { // most feet at the top
      const label = document.createElement('div');
      label.className = 'axis feet';
      label.textContent = feetWords(layout, r);
      grid.append(label);
      for (let c = 0; c < layout.columns; c++) {
        const empty = document.createElement('div');
        empty.className = 'codesign-empty';
        empty.title = `no body yet with ${sizeWords(layout, c)} voxels and ${feetWords(layout, r)}`;
        grid.append(empty);
        this.cells.set(`${c},${r}`, empty);
      }
    }
    grid.append(document.createElement('div'));
    for (let c = 0; c < layout.columns; c++) {
      const label = document.createElement('div');
      label.className = 'axis size';
      label.textContent = sizeWords(layout, c);
      grid.append(label);
    }
    const across = document.createElement('p');
    across.className = 'axis-title';
    across.textContent = 'across: body size (number of voxels) · up: number of feet (separate pieces of the bottom row) · '
      + 'under each body: its speed in training (m/s), then × how many walks that speed is the mean of (more walks, a surer speed)';
    // On a narrow screen the larger bodies are off to the right: said above the grid.
    const hint = document.createElement('p');
    hint.className = 'axis-title scroll-hint';
    hint.textContent = 'Larger bodies are further right: scroll sideways →';
    this.box.replaceChildren(hint, grid, across);
    this.hint = hint;
    this.fitHint();
  }

  /** Shows the scroll hint only when the grid is wider than its box. */
  fitHint() {
    if (this.hint) this.hint.hidden = this.box.scrollWidth <= this.box.clientWidth + 1;
  }

  /**
   * Shows the archive: each entry in its cell, coloured against the best, the ones found in
   * iteration `newest` outlined. @param {GalleryEntry[]} entries @param {number} newest
   */
  show(entries, newest) {
    const best = Math.max(0, ...entries.map((e) => e.fitness ?? -Infinity));
    for (const entry of entries) {
      const key = entry.cell.join(',');
      const old = this.cells.get(key);
      if (!old) continue;
      const isNew = entry.found === newest;
      const look = `${entry.shape}|${entry.fitness}|${best}|${isNew}|${this.chosen === key}`;
      if (this.drawn.get(key) === look) continue;
      this.drawn.set(key, look);
      const button = old instanceof HTMLButtonElement ? old : this.makeButton(key, old);
      button.onclick = () => this.pick(entry.cell, entry);
      button.classList.toggle('newest', isNew);
      button.classList.toggle('chosen', this.chosen === key);
      const speed = entry.fitness === null ? 'fell over (no speed)' : `${decimal(entry.fitness)} m/s`;
      button.title = `${entry.voxels} voxels, ${entry.feet} ${entry.feet === 1 ? 'foot' : 'feet'}: ${speed}`
        + ` (measured ${entry.measurements} time${entry.measurements === 1 ? '' : 's'}; found in round ${entry.found + 1})`
        + `${isNew ? ', new in the latest round' : ''}. Click to watch it walk.`;
      button.setAttribute('aria-label', button.title);
      const [canvas, label] = /** @type {[HTMLCanvasElement, HTMLElement]} */ ([button.children[0], button.children[1]]);
      label.textContent = entry.fitness === null ? decimal(entry.fitness) : `${decimal(entry.fitness)} ×${entry.measurements}`;
      drawBody(canvas, entry.shape, speedColour(entry.fitness, best));
    }
    this.fitHint();
  }

  /** Marks the cell loaded into the editor. @param {[number, number]} cell */
  choose(cell) {
    const key = cell.join(',');
    for (const [k, el] of this.cells) el.classList.toggle('chosen', k === key);
    this.chosen = key;
  }

  /** Replaces an empty cell by a body button. @param {string} key @param {HTMLElement} empty */
  makeButton(key, empty) {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'codesign-body';
    button.dataset.testid = 'codesign-body';
    button.dataset.cell = key;
    const canvas = document.createElement('canvas');
    const label = document.createElement('span');
    button.append(canvas, label);
    empty.replaceWith(button);
    this.cells.set(key, button);
    return button;
  }
}

/**
 * Draws the body `rows` (top first, '1' a voxel) centred on `canvas`, in `colour`.
 * @param {HTMLCanvasElement} canvas @param {string} rows @param {string} colour
 */
export function drawBody(canvas, rows, colour) {
  const dpr = globalThis.devicePixelRatio || 1;
  canvas.width = Math.round(BODY_W * dpr);
  canvas.height = Math.round(BODY_H * dpr);
  canvas.style.width = `${BODY_W}px`;
  canvas.style.height = `${BODY_H}px`;
  const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, BODY_W, BODY_H);
  const lines = rows.split('-');
  const width = Math.max(...lines.map((l) => l.length));
  const side = Math.max(2, Math.min(12, Math.floor(Math.min((BODY_W - 4) / width, (BODY_H - 4) / lines.length))));
  const x0 = (BODY_W - width * side) / 2;
  const y0 = (BODY_H - lines.length * side) / 2;
  ctx.fillStyle = colour;
  ctx.strokeStyle = 'rgba(0, 0, 0, 0.35)';
  ctx.lineWidth = 1;
  lines.forEach((line, r) => {
    for (let c = 0; c < line.length; c++) {
      if (line[c] !== '1') continue;
      ctx.fillRect(x0 + c * side, y0 + r * side, side, side);
      ctx.strokeRect(x0 + c * side + 0.5, y0 + r * side + 0.5, side - 1, side - 1);
    }
  });
}
