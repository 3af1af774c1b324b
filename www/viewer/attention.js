// @ts-check
/**
 * The attention panel: each voxel's 4 x 4 attention matrix as a small heat map, the maps
 * laid out like the robot's grid (top row on top). Rows are queries and columns keys, in
 * sensor order area, vx, vy, touch; blue is -1, white 0, red +1. Hidden when the
 * controller has no attention. Redraws only when a new frame arrived. `pick` finds the map
 * under a click (the attention reader opens on it) and the `selected` one is outlined.
 */
import { ATTENTION_FLOATS, SENSOR_NAMES } from '../workers/protocol.js';

/** Largest and smallest side of one matrix cell (CSS px). */
const MAX_CELL_PX = 22;
const MIN_CELL_PX = 6;
/** Room for the row labels left of a map, the column labels above it (CSS px), and gaps. */
const ROW_LABEL_PX = 38;
const COL_LABEL_PX = 34;
const GAP_PX = 14;
/** Gap between bare maps, and the smallest cell that still gets labels (CSS px). */
const COMPACT_GAP_PX = 5;
const LABELLED_CELL_PX = 12;
const FONT = '11px system-ui, sans-serif';
const NEGATIVE = [49, 99, 190];
const POSITIVE = [200, 45, 40];
const SIDE = Math.sqrt(ATTENTION_FLOATS);

/**
 * Colour of an attention value: blue at -1, white at 0, red at +1.
 * @param {number} a
 * @returns {string} a CSS rgb() colour
 */
export function attentionColour(a) {
  const t = Math.min(1, Math.abs(a));
  const to = a < 0 ? NEGATIVE : POSITIVE;
  const c = to.map((v) => Math.round(255 + (v - 255) * t));
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}

export class AttentionPanel {
  /** @param {HTMLElement} section shown only when there is attention @param {HTMLCanvasElement} canvas */
  constructor(section, canvas) {
    this.section = section;
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    /** Voxel grid cells, 2 per voxel (column, row from the bottom). @type {Uint32Array} */
    this.cells = new Uint32Array(0);
    this.columns = 0;
    this.rows = 0;
    /** @type {Float32Array} */
    this.attention = new Float32Array(0);
    this.dirty = false;
    /** The last drawn layout, for {@link AttentionPanel.pick}. */
    this.geometry = { pitchX: 0, pitchY: 0, rowLabel: 0, colLabel: 0, cell: 0 };
    /** The voxel being read (its map outlined), or -1. */
    this.selected = -1;
  }

  /**
   * The voxel whose map is at (clientX, clientY), or -1.
   * @param {number} clientX @param {number} clientY
   */
  pick(clientX, clientY) {
    const rect = this.canvas.getBoundingClientRect();
    const { pitchX, pitchY, rowLabel, colLabel, cell } = this.geometry;
    if (cell === 0) return -1;
    const x = clientX - rect.left;
    const y = clientY - rect.top;
    const column = Math.floor(x / pitchX);
    const row = this.rows - 1 - Math.floor(y / pitchY);
    const inX = x - column * pitchX - rowLabel;
    const inY = y - (this.rows - 1 - row) * pitchY - colLabel;
    const slack = cell; // a near miss on the labels or the gap still picks the map
    if (inX < -slack || inY < -slack || inX > SIDE * cell + slack || inY > SIDE * cell + slack) return -1;
    for (let v = 0; v < this.cells.length / 2; v++) {
      if (this.cells[2 * v] === column && this.cells[2 * v + 1] === row) return v;
    }
    return -1;
  }

  /**
   * A new episode: lays the maps out like its voxels. A brain with attention keeps the panel
   * shown until its first frame brings the maps (hidden for that moment, the panel's room went to
   * the robot's view, and everything under it moved up and back at every new walk: a run's Stop
   * under the click of a newer best's walk); another brain's episode hides it at once.
   * @param {Uint32Array} cells column, row per voxel @param {boolean} [attends] its brain has attention
   */
  setLayout(cells, attends = false) {
    this.cells = cells;
    this.columns = 0;
    this.rows = 0;
    for (let i = 0; i < cells.length; i += 2) {
      this.columns = Math.max(this.columns, cells[i] + 1);
      this.rows = Math.max(this.rows, cells[i + 1] + 1);
    }
    this.attention = new Float32Array(0);
    if (!attends) this.show(false);
  }

  /** @param {import('../workers/protocol.js').Frame} frame the latest frame (its `attention` may be empty) */
  setFrame(frame) {
    const has = frame.attention.length > 0 && frame.attention.length === (this.cells.length / 2) * ATTENTION_FLOATS;
    this.attention = has ? frame.attention : new Float32Array(0);
    this.show(has);
    this.dirty = has;
  }

  /** @param {boolean} visible */
  show(visible) {
    if (this.section.hidden === !visible) return;
    this.section.hidden = !visible;
  }

  /** Draws the maps if a new frame arrived; call once per animation frame. */
  draw() {
    if (!this.dirty) return;
    this.dirty = false;
    const { canvas, ctx } = this;
    const dpr = window.devicePixelRatio || 1;
    const room = this.section.clientWidth || 600;
    // Labels on every map while they fit; otherwise bare maps (the legend names the order).
    const labelled = Math.floor((room / this.columns - ROW_LABEL_PX - GAP_PX) / SIDE) >= LABELLED_CELL_PX;
    const [rowLabel, colLabel, gap] = labelled ? [ROW_LABEL_PX, COL_LABEL_PX, GAP_PX] : [0, 0, COMPACT_GAP_PX];
    const fit = Math.floor((room / this.columns - rowLabel - gap) / SIDE);
    const cell = Math.max(MIN_CELL_PX, Math.min(MAX_CELL_PX, fit));
    const pitchX = rowLabel + SIDE * cell + gap;
    const pitchY = colLabel + SIDE * cell + gap;
    const width = this.columns * pitchX;
    const height = this.rows * pitchY;
    this.geometry = { pitchX, pitchY, rowLabel, colLabel, cell };
    if (canvas.width !== Math.round(width * dpr) || canvas.height !== Math.round(height * dpr)) {
      canvas.width = Math.round(width * dpr);
      canvas.height = Math.round(height * dpr);
      canvas.style.width = `${width}px`;
      canvas.style.height = `${height}px`;
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, width, height);
    ctx.font = FONT;
    for (let v = 0; v < this.cells.length / 2; v++) {
      const x = this.cells[2 * v] * pitchX + rowLabel;
      const y = (this.rows - 1 - this.cells[2 * v + 1]) * pitchY + colLabel;
      this.drawMap(this.attention.subarray(v * ATTENTION_FLOATS, (v + 1) * ATTENTION_FLOATS), x, y, cell, labelled);
      if (v === this.selected) {
        ctx.strokeStyle = '#2f6fb0';
        ctx.lineWidth = 3;
        ctx.strokeRect(x - 2.5, y - 2.5, SIDE * cell + 5, SIDE * cell + 5);
      }
    }
  }

  /**
   * One voxel's matrix with its top-left corner at (x, y), row labels on the left and
   * column labels (vertical) above.
   * @param {Float32Array} a 16 values, row-major @param {number} x @param {number} y @param {number} cell
   * @param {boolean} labelled
   */
  drawMap(a, x, y, cell, labelled) {
    const { ctx } = this;
    for (let r = 0; r < SIDE; r++) {
      for (let c = 0; c < SIDE; c++) {
        ctx.fillStyle = attentionColour(a[r * SIDE + c]);
        ctx.fillRect(x + c * cell, y + r * cell, cell, cell);
      }
    }
    ctx.strokeStyle = 'rgba(30, 40, 50, 0.6)';
    ctx.lineWidth = 1;
    ctx.strokeRect(x + 0.5, y + 0.5, SIDE * cell - 1, SIDE * cell - 1);
    if (!labelled) return;
    ctx.fillStyle = 'rgba(30, 50, 70, 0.85)';
    ctx.textBaseline = 'middle';
    ctx.textAlign = 'right';
    SENSOR_NAMES.forEach((name, r) => ctx.fillText(name, x - 3, y + (r + 0.5) * cell));
    ctx.save();
    ctx.rotate(-Math.PI / 2);
    ctx.textAlign = 'left';
    // Rotated a quarter turn: text runs upward from just above the map.
    SENSOR_NAMES.forEach((name, c) => ctx.fillText(name, -(y - 3), x + (c + 0.5) * cell));
    ctx.restore();
  }
}
