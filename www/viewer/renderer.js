// @ts-check
/**
 * Draws one frame on a canvas: the terrain polyline filled below, the voxels as quads
 * coloured by area ratio (red contracted, yellow rest, green expanded), their rigid
 * corner squares outlined, a metre grid and scale, with a camera following the robot.
 * World units are metres with y up; the canvas transform does the flip. The core's constants
 * (area limits, corner size) come from the simulation worker's 'ready' ({@link Renderer.setPhysics});
 * the robot is drawn once they are known. The canvas's data-camera-still says whether the
 * camera has reached where it heads (to half a pixel): the view of a held robot is settled.
 */
import { BODY_FLOATS, CORNER_FLOATS } from '../workers/protocol.js';
import { voxelAt } from './voxel-pick.js';
import { plainNumber } from '../shared/format.js';

/** Metres of world visible across the canvas width (at least). */
const VIEW_WIDTH_M = 48;
/** Metres of world visible from bottom to top (at least). */
const VIEW_HEIGHT_M = 22;
/** Camera smoothing time constants (s), larger is lazier: vertical is lazier so hops don't shake the view. */
const CAMERA_LAG_X_S = 0.3;
const CAMERA_LAG_Y_S = 1.0;
/** The view spans at least this many times the robot's size. */
const ROBOT_VIEW_FACTOR = 2.5;
const RED = [214, 48, 49];
const YELLOW = [246, 200, 30];
const GREEN = [39, 160, 80];

/**
 * Colour of a voxel with area ratio `a`: red fully contracted, yellow at 1, green fully expanded.
 * @param {number} a @param {import('../workers/protocol.js').Physics} physics
 * @returns {string} a CSS rgb() colour
 */
function areaColour(a, { areaContracted: lo, areaExpanded: hi }) {
  const t = Math.min(1, Math.max(0, (a - lo) / (hi - lo)));
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
    /** @type {import('../workers/protocol.js').Frame | null} */
    this.frame = null;
    this.camera = { x: 17, y: 6 };
    /** The last drawn view, for {@link Renderer.pick}. @type {(View & {w: number, h: number, dpr: number}) | null} */
    this.view = null;
    this.snapCamera = true;
    this.lastDraw = 0;
    /** Where the ruler counts from (m): the walk's start, so it reads as the distance figure. */
    this.origin = 0;
    /** A voxel outlined on the robot (the one the attention reader shows), or -1. */
    this.highlight = -1;
    /** The core's constants, from the simulation worker. @type {import('../workers/protocol.js').Physics | null} */
    this.physics = null;
  }

  /** The core's constants, as the simulation worker sent them ('ready'). @param {import('../workers/protocol.js').Physics} physics */
  setPhysics(physics) {
    this.physics = physics;
  }

  /**
   * Shows a new terrain and, unless `snap` is false (an edit of the robot where it stands),
   * snaps the camera onto the robot on the next frame.
   * @param {Float64Array} xs @param {Float64Array} ys @param {boolean} [snap]
   */
  setTerrain(xs, ys, snap = true) {
    this.terrain = { xs, ys };
    if (snap) this.snapCamera = true;
  }

  /** @param {import('../workers/protocol.js').Frame} frame the latest frame to draw */
  setFrame(frame) {
    this.frame = frame;
  }

  /** Draws the scene; call once per animation frame. @param {number} nowMs */
  draw(nowMs) {
    const { canvas, ctx } = this;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(canvas.clientWidth * dpr);
    const h = Math.round(canvas.clientHeight * dpr);
    if (w === 0 || h === 0) return;
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    this.followRobot((nowMs - this.lastDraw) / 1000);
    this.lastDraw = nowMs;
    const box = this.frame ? robotBox(this.frame) : null;
    const s = Math.min(w / Math.max(VIEW_WIDTH_M, ROBOT_VIEW_FACTOR * (box ? box.right - box.left : 0)),
      h / Math.max(VIEW_HEIGHT_M, ROBOT_VIEW_FACTOR * (box ? box.top - box.bottom : 0)));
    if (box && this.frame && Number.isFinite(box.left) && s > 0) {
      this.camera = inView(this.camera, box, w / s, h / s);
      const rest = inView({ x: this.frame.centreX, y: this.frame.centreY }, box, w / s, h / s);
      const still = String(Math.max(Math.abs(rest.x - this.camera.x), Math.abs(rest.y - this.camera.y)) * s < 0.5);
      if (canvas.dataset.cameraStill !== still) canvas.dataset.cameraStill = still;
    }
    const view = { s, left: this.camera.x - w / 2 / s, right: this.camera.x + w / 2 / s,
      bottom: this.camera.y - h / 2 / s, top: this.camera.y + h / 2 / s };
    this.view = { ...view, w, h, dpr };
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#e8f1f8';
    ctx.fillRect(0, 0, w, h);
    ctx.setTransform(s, 0, 0, -s, w / 2 - s * this.camera.x, h / 2 + s * this.camera.y);
    this.drawGrid(view);
    this.drawTerrain(view);
    if (this.frame && this.physics) this.drawRobot(this.frame, s, this.physics);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    this.drawLabels(view, dpr);
  }

  /** @param {number} dt wall seconds since the last draw */
  followRobot(dt) {
    if (!this.frame) return;
    const target = { x: this.frame.centreX, y: this.frame.centreY };
    if (!Number.isFinite(this.camera.x) || !Number.isFinite(this.camera.y)) this.snapCamera = true;
    const smooth = (/** @type {number} */ lag) => (this.snapCamera ? 1 : 1 - Math.exp(-Math.max(0, dt) / lag));
    this.camera.x += (target.x - this.camera.x) * smooth(CAMERA_LAG_X_S);
    this.camera.y += (target.y - this.camera.y) * smooth(CAMERA_LAG_Y_S);
    this.snapCamera = false;
  }

  /**
   * What a click at (clientX, clientY) points at: a voxel of the robot (`voxel`), or the
   * empty cell next to voxel `voxel` in grid direction (dx, dy); null when nowhere near.
   * @param {number} clientX @param {number} clientY
   * @returns {{voxel: number, dx: number, dy: number} | null}
   */
  pick(clientX, clientY) {
    const { frame, view } = this;
    if (!frame || !view) return null;
    const rect = this.canvas.getBoundingClientRect();
    const px = (clientX - rect.left) * view.dpr;
    const py = (clientY - rect.top) * view.dpr;
    return voxelAt(frame, view.left + px / view.s, view.top - py / view.s);
  }

  /** Faint vertical lines every 5 m so that motion shows even on flat ground. */
  drawGrid(/** @type {View} */ view) {
    const { ctx } = this;
    ctx.strokeStyle = 'rgba(40, 70, 100, 0.15)';
    ctx.lineWidth = 1 / view.s;
    ctx.beginPath();
    const o = this.origin;
    for (let x = o + Math.ceil((view.left - o) / 5) * 5; x <= view.right; x += 5) {
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

  /**
   * Voxel quads coloured by area ratio, then the corner squares outlined on top.
   * @param {import('../workers/protocol.js').Frame} frame @param {number} s @param {import('../workers/protocol.js').Physics} physics
   */
  drawRobot(frame, s, physics) {
    const { ctx } = this;
    const { corners, areas, bodies, voxels } = frame;
    ctx.lineWidth = 1.2 / s;
    ctx.strokeStyle = 'rgba(30, 30, 30, 0.7)';
    for (let i = 0; i < voxels; i++) {
      voxelPath(ctx, corners, i);
      ctx.fillStyle = areaColour(areas[i], physics);
      ctx.fill();
      ctx.stroke();
    }
    ctx.strokeStyle = 'rgba(20, 20, 20, 0.55)';
    ctx.beginPath();
    for (let b = 0; b < voxels * BODY_FLOATS; b += 3) squarePath(ctx, bodies[b], bodies[b + 1], bodies[b + 2], physics.cornerSide);
    ctx.stroke();
    if (this.highlight >= 0 && this.highlight < voxels) {
      voxelPath(ctx, corners, this.highlight);
      ctx.strokeStyle = '#2f6fb0';
      ctx.lineWidth = 5 / s;
      ctx.stroke();
    }
  }

  /** Screen-space labels: metres from the start along the top and a metre scale bar. */
  drawLabels(/** @type {View} */ view, /** @type {number} */ dpr) {
    const { ctx, canvas } = this;
    ctx.fillStyle = 'rgba(30, 50, 70, 0.8)';
    ctx.font = `${12 * dpr}px system-ui, sans-serif`;
    // Every 10 m, or every 20, 50, 100 m where a narrow canvas would run the labels together.
    const room = ctx.measureText('−100 m').width + 10 * dpr;
    const step = [10, 20, 50, 100].find((m) => m * view.s >= room) ?? 100;
    for (let d = Math.ceil((view.left - this.origin) / step) * step; this.origin + d <= view.right; d += step) {
      const text = d === 0 ? 'start' : `${plainNumber(d)} m`;
      const x = (this.origin + d - view.left) * view.s + 3 * dpr;
      if (x + ctx.measureText(text).width <= canvas.width) ctx.fillText(text, x, 14 * dpr); // a label cut by the edge is left out
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
    ctx.fillText(`${plainNumber(metres)} m`, x0, y0 - 10 * dpr);
  }
}

/** @typedef {{s: number, left: number, right: number, bottom: number, top: number}} View */

/** Starts a path around voxel `i`'s quad. @param {CanvasRenderingContext2D} ctx @param {Float32Array} corners @param {number} i */
function voxelPath(ctx, corners, i) {
  const c = i * CORNER_FLOATS;
  ctx.beginPath();
  ctx.moveTo(corners[c], corners[c + 1]);
  for (let k = 2; k < CORNER_FLOATS; k += 2) ctx.lineTo(corners[c + k], corners[c + k + 1]);
  ctx.closePath();
}

/**
 * Adds the outline of a rigid corner square of width `side` centred at (x, y) rotated by `angle`.
 * @param {CanvasRenderingContext2D} ctx @param {number} x @param {number} y @param {number} angle @param {number} side
 */
function squarePath(ctx, x, y, angle, side) {
  const h = side / 2;
  const cos = Math.cos(angle) * h;
  const sin = Math.sin(angle) * h;
  ctx.moveTo(x - cos + sin, y - sin - cos);
  ctx.lineTo(x + cos + sin, y + sin - cos);
  ctx.lineTo(x + cos - sin, y + sin + cos);
  ctx.lineTo(x - cos - sin, y - sin + cos);
  ctx.closePath();
}

/**
 * The camera place nearest `at` that shows the whole robot with a margin, however fast it goes
 * (the smoothing alone would let a fast robot slide off the edge).
 * @param {{x: number, y: number}} at @param {{left: number, right: number, bottom: number, top: number}} box
 * @param {number} viewW @param {number} viewH metres visible
 */
function inView(at, box, viewW, viewH) {
  const mx = Math.min(viewW * 0.15, Math.max(0, (viewW - (box.right - box.left)) / 2));
  const my = Math.min(viewH * 0.15, Math.max(0, (viewH - (box.top - box.bottom)) / 2));
  return { x: clamp(at.x, box.right + mx - viewW / 2, box.left - mx + viewW / 2), y: clamp(at.y, box.top + my - viewH / 2, box.bottom - my + viewH / 2) };
}

/** @param {number} v @param {number} lo @param {number} hi */
function clamp(v, lo, hi) {
  return lo > hi ? (lo + hi) / 2 : Math.min(hi, Math.max(lo, v));
}

/** The axis-aligned box around a frame's voxels (m). @param {import('../workers/protocol.js').Frame} frame */
function robotBox(frame) {
  const box = { left: Infinity, right: -Infinity, bottom: Infinity, top: -Infinity };
  const { corners } = frame;
  for (let k = 0; k < corners.length; k += 2) {
    box.left = Math.min(box.left, corners[k]);
    box.right = Math.max(box.right, corners[k]);
    box.bottom = Math.min(box.bottom, corners[k + 1]);
    box.top = Math.max(box.top, corners[k + 1]);
  }
  return box;
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
