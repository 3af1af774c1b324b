// @ts-check
/**
 * The run chart: fitness (m/s) against evaluations, one line per series (best so far,
 * a generation's median, a from-scratch run beside a fine-tuning run), with ticks on both
 * axes and a legend. Non-finite values (exploded episodes) leave a gap.
 */
import { plainNumber } from '../shared/format.js';

const PAD = { left: 46, right: 12, top: 12, bottom: 34 };
const FONT = '11px system-ui, sans-serif';
const AXIS_COLOUR = '#5b6b78';
const GRID_COLOUR = '#e3e8ee';

/** @typedef {{label: string, colour: string, dashed: boolean, points: {x: number, y: number}[]}} Series */

export class FitnessChart {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    /** @type {Map<string, Series>} */
    this.series = new Map();
    this.maxX = 1;
    /** The frame a requested draw waits for (0: none). */
    this.pending = 0;
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  /** Forgets every series; `maxX` is the planned evaluations. @param {number} maxX */
  clear(maxX = 1) {
    this.series.clear();
    this.maxX = Math.max(1, maxX);
    this.draw();
  }

  /** Widens the x axis to at least `maxX` evaluations. @param {number} maxX */
  extend(maxX) {
    this.maxX = Math.max(this.maxX, maxX);
  }

  /**
   * Adds a point to a series (created on first use).
   * @param {string} key @param {{label: string, colour: string, dashed?: boolean}} style
   * @param {number} x evaluations @param {number | null} y m/s (null: a gap)
   */
  add(key, style, x, y) {
    let s = this.series.get(key);
    if (!s) { s = { label: style.label, colour: style.colour, dashed: style.dashed ?? false, points: [] }; this.series.set(key, s); }
    s.points.push({ x, y: y ?? NaN });
    this.extend(x);
  }

  /**
   * Draws the chart at the next frame, once however many points came before it: a run of short
   * episodes sends dozens of generations a second, and a redraw for each (every point again)
   * took the page's whole time, so that a click on Stop waited for seconds. The series' names
   * are said at once.
   */
  request() {
    this.canvas.dataset.series = [...this.series.keys()].join(',');
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => { this.pending = 0; this.draw(); });
  }

  draw() {
    const { canvas, ctx } = this;
    if (this.pending) { cancelAnimationFrame(this.pending); this.pending = 0; }
    canvas.dataset.series = [...this.series.keys()].join(',');
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (width === 0 || height === 0) return;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const ys = [...this.series.values()].flatMap((s) => s.points.map((p) => p.y)).filter(Number.isFinite);
    const yTicks = ticks(Math.min(0, ...ys), Math.max(0.5, ...ys));
    const xMax = this.maxX; // the planned evaluations: the run ends at the right edge
    const xTicks = ticks(0, xMax).filter((v) => v <= xMax);
    const [low, high] = [yTicks[0], yTicks[yTicks.length - 1]];
    const x = (/** @type {number} */ v) => PAD.left + (v / xMax) * (width - PAD.left - PAD.right);
    const y = (/** @type {number} */ v) => height - PAD.bottom - ((v - low) / (high - low)) * (height - PAD.top - PAD.bottom);
    ctx.font = FONT;
    ctx.lineWidth = 1;
    ctx.strokeStyle = GRID_COLOUR;
    ctx.fillStyle = AXIS_COLOUR;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (const v of yTicks) {
      line(ctx, PAD.left, y(v), width - PAD.right, y(v));
      ctx.fillText(format(v), PAD.left - 5, y(v));
    }
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    for (const v of xTicks) {
      line(ctx, x(v), PAD.top, x(v), height - PAD.bottom);
      const label = format(v); // kept inside the canvas (30,000 at the right edge)
      ctx.fillText(label, Math.min(x(v), width - ctx.measureText(label).width / 2 - 1), height - PAD.bottom + 4);
    }
    ctx.fillText('evaluations', (PAD.left + width - PAD.right) / 2, height - 14);
    ctx.save();
    ctx.translate(11, (PAD.top + height - PAD.bottom) / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText('m/s', 0, -6);
    ctx.restore();
    for (const s of this.series.values()) this.plot(s, x, y);
    this.legend(width);
  }

  /** @param {Series} s @param {(v: number) => number} x @param {(v: number) => number} y */
  plot(s, x, y) {
    const { ctx } = this;
    ctx.strokeStyle = s.colour;
    ctx.lineWidth = 2;
    ctx.setLineDash(s.dashed ? [5, 4] : []);
    ctx.beginPath();
    let drawing = false;
    for (const p of s.points) {
      if (!Number.isFinite(p.y)) { drawing = false; continue; }
      if (drawing) ctx.lineTo(x(p.x), y(p.y)); else ctx.moveTo(x(p.x), y(p.y));
      drawing = true;
    }
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.lineWidth = 1;
  }

  /** @param {number} width */
  legend(width) {
    const { ctx } = this;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    let left = PAD.left + 8;
    for (const s of this.series.values()) {
      ctx.fillStyle = s.colour;
      ctx.fillRect(left, PAD.top + 4, 14, 3);
      ctx.fillStyle = AXIS_COLOUR;
      ctx.fillText(s.label, left + 18, PAD.top + 6);
      left += 26 + ctx.measureText(s.label).width;
      if (left > width - 60) break;
    }
  }
}

/** @param {CanvasRenderingContext2D} ctx @param {number} x0 @param {number} y0 @param {number} x1 @param {number} y1 */
function line(ctx, x0, y0, x1, y1) {
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
}

/**
 * About five round ticks covering [low, high], the first <= low and the last >= high.
 * @param {number} low @param {number} high @returns {number[]}
 */
export function ticks(low, high) {
  const span = Math.max(high - low, 1e-9);
  const raw = span / 5;
  const p = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * p).find((v) => v >= raw) ?? 10 * p;
  const out = [];
  for (let v = Math.floor(low / step) * step; v < high + step - 1e-9 * step; v += step) out.push(Math.round(v / step) * step);
  if (out.length < 2) out.push(out[0] + step);
  return out;
}

/** A tick's label: 30,000 evaluations, −0.5 m/s (shared/format.js). @param {number} v */
function format(v) {
  return plainNumber(v);
}
