// @ts-check
/**
 * Draws one frame on a canvas: the terrain polyline filled below, the voxels as quads
 * coloured by area ratio (red contracted, yellow rest, green expanded), their rigid
 * corner squares outlined, a metre grid and scale, with a camera following the robot.
 * World units are metres with y up; the canvas transform does the flip.
 */
import { AREA_CONTRACTED, AREA_EXPANDED, BODY_FLOATS, CORNER_BODY_SIDE, CORNER_FLOATS } from './protocol.js';

/** Metres of world visible across the canvas width (at least). */
const VIEW_WIDTH_M = 48;
/** Metres of world visible from bottom to top (at least). */
const VIEW_HEIGHT_M = 22;
/** Camera smoothing time constants (s), larger is lazier: vertical is lazier so hops don't shake the view. */
const CAMERA_LAG_X_S = 0.3;
const CAMERA_LAG_Y_S = 1.0;
const RED = [214, 48, 49];
const YELLOW = [246, 200, 30];
const GREEN = [39, 160, 80];

/**
 * Colour of a voxel with area ratio `a`: red at 0.775, yellow at 1, green at 1.225.
 * @param {number} a
 * @returns {string} a CSS rgb() colour
 */
export function areaColour(a) {
  const t = Math.min(1, Math.max(0, (a - AREA_CONTRACTED) / (AREA_EXPANDED - AREA_CONTRACTED)));
  const [from, to, u] = t < 0.5 ? [RED, YELLOW, t * 2] : [YELLOW, GREEN, t * 2 - 1];
  const c = from.map((v, i) => Math.round(v + (to[i] - v) * u));
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}

export class Renderer {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    /** @type {{xs: Float64Array, ys: Float64Array} | null} */
    this.terrain = null;
    /** @type {import('./protocol.js').Frame | null} */
    this.frame = null;
    this.camera = { x: 17, y: 6 };
    this.snapCamera = true;
    this.lastDraw = 0;
  }

  /** Shows a new terrain and snaps the camera on the next frame. @param {Float64Array} xs @param {Float64Array} ys */
  setTerrain(xs, ys) {
    this.terrain = { xs, ys };
    this.snapCamera = true;
  }

  /** @param {import('./protocol.js').Frame} frame the latest frame to draw */
  setFrame(frame) {
    this.frame = frame;
  }

  /** Draws the scene; call once per animation frame. @param {number} nowMs */
  draw(nowMs) {
    const { canvas, ctx } = this;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(canvas.clientWidth * dpr);
    const h = Math.round(canvas.clientHeight * dpr);
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    this.followRobot((nowMs - this.lastDraw) / 1000);
    this.lastDraw = nowMs;
    const s = Math.min(w / VIEW_WIDTH_M, h / VIEW_HEIGHT_M);
    const view = { s, left: this.camera.x - w / 2 / s, right: this.camera.x + w / 2 / s,
      bottom: this.camera.y - h / 2 / s, top: this.camera.y + h / 2 / s };
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#e8f1f8';
    ctx.fillRect(0, 0, w, h);
    ctx.setTransform(s, 0, 0, -s, w / 2 - s * this.camera.x, h / 2 + s * this.camera.y);
    this.drawGrid(view);
    this.drawTerrain(view);
    if (this.frame) this.drawRobot(this.frame, s);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    this.drawLabels(view, dpr);
  }

  /** @param {number} dt wall seconds since the last draw */
  followRobot(dt) {
    if (!this.frame) return;
    const target = { x: this.frame.centreX, y: this.frame.centreY };
    const smooth = (/** @type {number} */ lag) => (this.snapCamera ? 1 : 1 - Math.exp(-Math.max(0, dt) / lag));
    this.camera.x += (target.x - this.camera.x) * smooth(CAMERA_LAG_X_S);
    this.camera.y += (target.y - this.camera.y) * smooth(CAMERA_LAG_Y_S);
    this.snapCamera = false;
  }

  /** Faint vertical lines every 5 m so that motion shows even on flat ground. */
  drawGrid(/** @type {View} */ view) {
    const { ctx } = this;
    ctx.strokeStyle = 'rgba(40, 70, 100, 0.15)';
    ctx.lineWidth = 1 / view.s;
    ctx.beginPath();
    for (let x = Math.ceil(view.left / 5) * 5; x <= view.right; x += 5) {
      ctx.moveTo(x, view.bottom);
      ctx.lineTo(x, view.top);
    }
    ctx.stroke();
  }

  /** The visible part of the terrain polyline, filled down to the bottom of the view. */
  drawTerrain(/** @type {View} */ view) {
    if (!this.terrain) return;
    const { xs, ys } = this.terrain;
    const first = Math.max(0, lowerBound(xs, view.left) - 1);
    const last = Math.min(xs.length - 1, lowerBound(xs, view.right));
    const { ctx } = this;
    ctx.beginPath();
    ctx.moveTo(xs[first], view.bottom - 1);
    for (let i = first; i <= last; i++) ctx.lineTo(xs[i], ys[i]);
    ctx.lineTo(xs[last], view.bottom - 1);
    ctx.closePath();
    ctx.fillStyle = '#9c8b73';
    ctx.fill();
    ctx.strokeStyle = '#4d4030';
    ctx.lineWidth = 2 / view.s;
    ctx.stroke();
  }

  /** Voxel quads coloured by area ratio, then the corner squares outlined on top. */
  drawRobot(/** @type {import('./protocol.js').Frame} */ frame, /** @type {number} */ s) {
    const { ctx } = this;
    const { corners, areas, bodies, voxels } = frame;
    ctx.lineWidth = 1.2 / s;
    ctx.strokeStyle = 'rgba(30, 30, 30, 0.7)';
    for (let i = 0; i < voxels; i++) {
      const c = i * CORNER_FLOATS;
      ctx.beginPath();
      ctx.moveTo(corners[c], corners[c + 1]);
      for (let k = 2; k < CORNER_FLOATS; k += 2) ctx.lineTo(corners[c + k], corners[c + k + 1]);
      ctx.closePath();
      ctx.fillStyle = areaColour(areas[i]);
      ctx.fill();
      ctx.stroke();
    }
    ctx.strokeStyle = 'rgba(20, 20, 20, 0.55)';
    ctx.beginPath();
    for (let b = 0; b < voxels * BODY_FLOATS; b += 3) squarePath(ctx, bodies[b], bodies[b + 1], bodies[b + 2]);
    ctx.stroke();
  }

  /** Screen-space labels: grid metres along the top and a metre scale bar. */
  drawLabels(/** @type {View} */ view, /** @type {number} */ dpr) {
    const { ctx, canvas } = this;
    ctx.fillStyle = 'rgba(30, 50, 70, 0.8)';
    ctx.font = `${12 * dpr}px system-ui, sans-serif`;
    for (let x = Math.ceil(view.left / 10) * 10; x <= view.right; x += 10) {
      ctx.fillText(`${x} m`, (x - view.left) * view.s + 3 * dpr, 14 * dpr);
    }
    const metres = niceLength(120 * dpr / view.s);
    const px = metres * view.s;
    const x0 = 16 * dpr;
    const y0 = canvas.height - 16 * dpr;
    ctx.fillStyle = '#fff';
    ctx.fillRect(x0 - 6 * dpr, y0 - 22 * dpr, px + 12 * dpr, 30 * dpr);
    ctx.fillStyle = '#222';
    ctx.fillRect(x0, y0 - 3 * dpr, px, 3 * dpr);
    ctx.fillRect(x0, y0 - 8 * dpr, 2 * dpr, 8 * dpr);
    ctx.fillRect(x0 + px - 2 * dpr, y0 - 8 * dpr, 2 * dpr, 8 * dpr);
    ctx.fillText(`${metres} m`, x0, y0 - 10 * dpr);
  }
}

/** @typedef {{s: number, left: number, right: number, bottom: number, top: number}} View */

/**
 * Adds the outline of a rigid corner square centred at (x, y) rotated by `angle`.
 * @param {CanvasRenderingContext2D} ctx @param {number} x @param {number} y @param {number} angle
 */
function squarePath(ctx, x, y, angle) {
  const h = CORNER_BODY_SIDE / 2;
  const cos = Math.cos(angle) * h;
  const sin = Math.sin(angle) * h;
  ctx.moveTo(x - cos + sin, y - sin - cos);
  ctx.lineTo(x + cos + sin, y + sin - cos);
  ctx.lineTo(x + cos - sin, y + sin + cos);
  ctx.lineTo(x - cos - sin, y - sin + cos);
  ctx.closePath();
}

/** Index of the first element of sorted `xs` that is >= `x`. @param {Float64Array} xs @param {number} x */
function lowerBound(xs, x) {
  let lo = 0;
  let hi = xs.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (xs[mid] < x) lo = mid + 1; else hi = mid;
  }
  return lo;
}

/** The largest 1, 2 or 5 x 10^k not above `max`. @param {number} max */
function niceLength(max) {
  const p = 10 ** Math.floor(Math.log10(max));
  return [5, 2, 1].map((m) => m * p).find((v) => v <= max) ?? p;
}
