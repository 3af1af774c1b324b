// @ts-check
/**
 * The grid editor: draws the {@link Drawing} on a canvas and edits it with a mouse, a pen
 * or a finger. Press and drag to add voxels; drag with the right button, or in erase mode,
 * to remove them. When the drawing is in several pieces each piece gets its own colour.
 * Calls `onStroke` after each finished stroke and `onPaint` after each changed cell.
 */

const PIECE_COLOURS = ['#2f6fb0', '#d9822b', '#8e44ad', '#16a085', '#c0392b', '#7f8c8d'];
const ONE_PIECE = '#3d7a4f';
const GRID_LINE = '#d0d7de';
const BACKGROUND = '#fbfcfd';

export class Editor {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {import('./drawing.js').Drawing} drawing
   * @param {{onPaint: () => void, onStroke: () => void, onLocked: () => void}} hooks
   */
  constructor(canvas, drawing, hooks) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    this.drawing = drawing;
    this.hooks = hooks;
    this.erase = false;
    this.locked = false;
    /** Pieces to colour (cells in the cropped drawing's coordinates), or null for one piece. @type {[number, number][][] | null} */
    this.pieces = null;
    /** @type {{fill: boolean, pointer: number} | null} the stroke under way */
    this.stroke = null;
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', (e) => this.up(e));
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  /** @param {[number, number][][] | null} pieces */
  setPieces(pieces) {
    this.pieces = pieces && pieces.length > 1 ? pieces : null;
    this.draw();
  }

  /** @param {boolean} locked no editing while true (a run uses the body) */
  setLocked(locked) {
    this.locked = locked;
    this.canvas.classList.toggle('locked', locked);
    this.draw();
  }

  /** @param {PointerEvent} e @returns {[number, number] | null} the cell under the pointer */
  cellAt(e) {
    const rect = this.canvas.getBoundingClientRect();
    const side = rect.width / this.drawing.width;
    const x = Math.floor((e.clientX - rect.left) / side);
    const y = this.drawing.height - 1 - Math.floor((e.clientY - rect.top) / side);
    return this.drawing.inside(x, y) ? [x, y] : null;
  }

  /** @param {PointerEvent} e */
  down(e) {
    if (this.locked) { this.hooks.onLocked(); return; }
    if (this.stroke || (e.button !== 0 && e.button !== 2)) return;
    e.preventDefault();
    this.canvas.setPointerCapture(e.pointerId);
    this.stroke = { fill: e.button === 0 && !this.erase, pointer: e.pointerId };
    this.drawing.beginStroke();
    this.paint(e);
  }

  /** @param {PointerEvent} e */
  move(e) {
    if (this.stroke && e.pointerId === this.stroke.pointer) this.paint(e);
  }

  /** @param {PointerEvent} e */
  up(e) {
    if (!this.stroke || e.pointerId !== this.stroke.pointer) return;
    this.stroke = null;
    if (this.drawing.endStroke()) this.hooks.onStroke();
  }

  /** @param {PointerEvent} e */
  paint(e) {
    const cell = this.cellAt(e);
    if (cell && this.stroke && this.drawing.set(cell[0], cell[1], this.stroke.fill)) {
      this.hooks.onPaint();
      this.draw();
    }
  }

  draw() {
    const { canvas, ctx, drawing } = this;
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth;
    const side = width / drawing.width;
    const height = side * drawing.height;
    canvas.style.height = `${height}px`;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.fillStyle = BACKGROUND;
    ctx.fillRect(0, 0, width, height);
    const colour = this.colours();
    for (const c of drawing.cells) {
      const x = c % drawing.width;
      const y = Math.floor(c / drawing.width);
      ctx.fillStyle = colour.get(c) ?? ONE_PIECE;
      ctx.fillRect(x * side + 1, (drawing.height - 1 - y) * side + 1, side - 2, side - 2);
    }
    ctx.strokeStyle = GRID_LINE;
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let x = 0; x <= drawing.width; x++) { ctx.moveTo(x * side, 0); ctx.lineTo(x * side, height); }
    for (let y = 0; y <= drawing.height; y++) { ctx.moveTo(0, y * side); ctx.lineTo(width, y * side); }
    ctx.stroke();
  }

  /** @returns {Map<number, string>} a colour per cell when there are several pieces */
  colours() {
    const map = new Map();
    const box = this.drawing.box();
    if (!this.pieces || !box) return map;
    this.pieces.forEach((piece, i) => {
      for (const [x, y] of piece) {
        map.set((y + box.bottom) * this.drawing.width + x + box.left, PIECE_COLOURS[i % PIECE_COLOURS.length]);
      }
    });
    return map;
  }
}
