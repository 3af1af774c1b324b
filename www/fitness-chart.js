// @ts-check
/**
 * The evolution chart: best and median fitness (m/s) of each generation's survivors, as two
 * lines on a small canvas, generation on x. Non-finite values (exploded episodes) are skipped.
 */

const PAD = { left: 40, right: 10, top: 10, bottom: 22 };
const FONT = '11px system-ui, sans-serif';
const BEST_COLOUR = 'rgb(200, 45, 40)';
const MEDIAN_COLOUR = 'rgb(49, 99, 190)';
const AXIS_COLOUR = '#5b6b78';

export class FitnessChart {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    /** @type {{best: number, median: number}[]} one entry per generation */
    this.points = [];
  }

  /** Forgets every generation (a new run). */
  clear() {
    this.points = [];
    this.draw();
  }

  /** Adds a generation's figures (null or NaN for non-finite). @param {number | null} best @param {number | null} median */
  add(best, median) {
    this.points.push({ best: best ?? NaN, median: median ?? NaN });
    this.draw();
  }

  draw() {
    const { canvas, ctx } = this;
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const values = this.points.flatMap((p) => [p.best, p.median]).filter(Number.isFinite);
    const low = Math.min(0, ...values);
    const high = Math.max(0.1, ...values);
    const n = Math.max(2, this.points.length);
    const x = (/** @type {number} */ i) => PAD.left + (i / (n - 1)) * (width - PAD.left - PAD.right);
    const y = (/** @type {number} */ v) => height - PAD.bottom - ((v - low) / (high - low)) * (height - PAD.top - PAD.bottom);
    this.axes(width, height, low, high, y);
    this.line((p) => p.median, MEDIAN_COLOUR, x, y);
    this.line((p) => p.best, BEST_COLOUR, x, y);
    ctx.fillStyle = AXIS_COLOUR;
    ctx.textAlign = 'right';
    ctx.fillText(`generation ${Math.max(0, this.points.length - 1)}`, width - PAD.right, height - 6);
  }

  /**
   * @param {number} width @param {number} height @param {number} low @param {number} high
   * @param {(v: number) => number} y
   */
  axes(width, height, low, high, y) {
    const { ctx } = this;
    ctx.font = FONT;
    ctx.strokeStyle = '#d0d7de';
    ctx.fillStyle = AXIS_COLOUR;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (const v of [low, 0, high]) {
      ctx.beginPath();
      ctx.moveTo(PAD.left, y(v));
      ctx.lineTo(width - PAD.right, y(v));
      ctx.stroke();
      ctx.fillText(`${v.toFixed(2)}`, PAD.left - 4, y(v));
    }
    ctx.textBaseline = 'alphabetic';
  }

  /**
   * @param {(p: {best: number, median: number}) => number} pick
   * @param {string} colour
   * @param {(i: number) => number} x
   * @param {(v: number) => number} y
   */
  line(pick, colour, x, y) {
    const { ctx } = this;
    ctx.strokeStyle = colour;
    ctx.lineWidth = 2;
    ctx.beginPath();
    let drawing = false;
    this.points.forEach((p, i) => {
      const v = pick(p);
      if (!Number.isFinite(v)) { drawing = false; return; }
      if (drawing) ctx.lineTo(x(i), y(v)); else ctx.moveTo(x(i), y(v));
      drawing = true;
    });
    ctx.stroke();
    ctx.lineWidth = 1;
  }
}
