// @ts-check
/**
 * The simulation worker (a module worker). It owns the wasm `Episode` (driven by the
 * phase gait or by a controller's genome: the same handle either way), steps it in
 * short slices so that control messages are handled promptly, and posts frames whose
 * buffers are transferred, not copied. Message types and buffer layouts: protocol.js.
 */
import init, { Episode, attentionTerms, defaults, start as installPanicHook } from '../pkg/vsr.js';
import { loadWasm, messageOf, typeText, workerScope } from './kit.js';
import { FromWorker, ToWorker } from './protocol.js';
import { hasAttention } from '../shared/families.js';

/** Longest run of stepping before yielding to the message queue (ms). */
const SLICE_BUDGET_MS = 8;
/** Minimum wall time between two posted frames (ms): about the display rate. */
const FRAME_INTERVAL_MS = 1000 / 60;
/** Steps per call into wasm inside a slice; small enough to respect the budget. */
const STEPS_PER_CALL = 4;
/** If pacing falls further behind than this (simulated s), the lag is dropped. */
const MAX_LAG_S = 0.25;
/** Window over which the speed figures are measured (wall ms). */
const RATE_WINDOW_MS = 500;

const scope = workerScope('workers/simulation-worker.js');

/** The simulation time step (s), the core's: it paces the stepping. */
let dt = NaN;
/** The core's constants, once the module is loaded (the page's drawing gets them in 'ready'). */
const ready = loadWasm(init, installPanicHook).then(() => {
  const physics = /** @type {import('./protocol.js').Physics} */ (defaults().physics);
  dt = physics.timeStep;
  return physics;
});

/** @type {Episode | null} */
let episode = null;
/** @type {import('./protocol.js').LoadedParams | null} */
let params = null;
let running = false;
/** Simulated seconds per wall second; 0 = as fast as possible. */
let speed = 1;
/** Simulated time (s) not to step past (the race's lanes wait for the slowest); Infinity: none. */
let waitAt = Infinity;
/** Pacing anchor: wall time (ms) and simulated time (s) when running (re)started. */
let anchor = { wall: 0, sim: 0 };
/** Speed measurement window. */
let rate = { wall: 0, sim: 0, compute: 0, simPerWall: NaN, simPerCompute: NaN };
let lastFramePosted = -Infinity;
let tickScheduled = false;
/**
 * While a robot with attention is held before its first step (loaded, or edited, while Hold is
 * on), each voxel's matrix as that step will work it out from what the voxel feels now: the maps
 * show at once, not blank until Play. Null once the robot steps. @type {Float32Array | null}
 */
let preview = null;
const yieldChannel = new MessageChannel();
yieldChannel.port1.onmessage = () => tick();

scope.onmessage = async (event) => {
  try {
    await ready;
  } catch (error) {
    reportError(messageOf(error), true);
    return;
  }
  try {
    handle(event.data);
  } catch (error) {
    reportError(messageOf(error), error instanceof WebAssembly.RuntimeError);
  }
};

/** @param {import('./protocol.js').ToWorkerMessage} msg */
function handle(msg) {
  switch (msg.type) {
    case ToWorker.LOAD: if (msg.params) load(msg.params); break;
    case ToWorker.RESET: if (params) load({ ...params, keepPlace: false }); break;
    case ToWorker.START: setRunning(true); break;
    case ToWorker.PAUSE: setRunning(false); break;
    case ToWorker.SPEED: speed = Math.max(0, Number(msg.speed) || 0); restartClocks(); break;
    case ToWorker.FREEZE: if (episode) { episode.freezeAttention(Boolean(msg.frozen)); postFrame(); } break;
    case ToWorker.WAIT_AT: waitAt = Number(msg.seconds) >= 0 ? Number(msg.seconds) : Infinity; schedule(); break;
    case ToWorker.LENGTH:
      if (episode && params) { episode.measureOver(Number(msg.seconds)); params = { ...params, seconds: Number(msg.seconds) }; }
      break;
    default: reportError(`unknown message type ${typeText(msg)}`, false);
  }
}

/**
 * Replaces the episode. Bad parameters or a genome that does not fit throw before anything
 * is replaced, so the previous robot keeps running and the error goes back to the page.
 * Parameters left out (terrain, gait) take the core's defaults.
 * @param {import('./protocol.js').EpisodeParams} asked
 */
function load(asked) {
  const { gait, viewTerrain } = defaults();
  const next = { terrain: viewTerrain, frequency: gait.frequency, phase: gait.phase, ...asked };
  // An edit of the walking robot rebuilds it where it stands, in its posture and motion, if
  // the robot walking is the one that was edited (not after a restart or a refused load).
  const edit = next.keepPlace && episode ? next.keepPlace : null;
  const left = edit && episode ? episode.leftEdge() : NaN;
  const build = () => (next.runFile ? Episode.fromRunFile(next.runFile, next.terrain, next.shape)
    : next.brain ? Episode.fromGenome(next.shape, next.terrain, next.brain.controller, next.brain.genome, left)
    : Episode.gaitAt(next.shape, next.terrain, next.frequency, next.phase, left));
  const fresh = build();
  const carried = Boolean(edit && episode && edit.from === episode.shape && next.terrain === params?.terrain);
  if (carried && edit && episode) fresh.carryPose(episode, edit.dx, edit.dy);
  preview = null;
  if (!running && hasAttention(fresh.controller)) {
    // Held: a copy takes the first step (this robot stays where it is) and lends its matrices.
    const probe = build();
    try {
      if (carried && edit && episode) probe.carryPose(episode, edit.dx, edit.dy);
      probe.step(1);
      preview = probe.attention();
    } catch { /* no preview: the maps fill in at the first step */ } finally { probe.free(); }
  }
  if (next.seconds !== undefined && next.seconds > 0) fresh.measureOver(next.seconds); // the speed over the episode, taken when it ends
  episode?.free();
  episode = fresh;
  params = next;
  waitAt = Infinity;
  const terrainXs = fresh.terrainXs();
  const terrainYs = fresh.terrainYs();
  const cells = fresh.voxelCells();
  const terms = next.brain && hasAttention(next.brain.controller) ? Array.from(attentionTerms(next.brain.genome)) : null;
  scope.postMessage({
    type: FromWorker.LOADED, params, carried, voxels: fresh.voxelCount, controller: fresh.controller,
    cells, terrainXs, terrainYs, attentionTerms: terms,
  }, [cells.buffer, terrainXs.buffer, terrainYs.buffer]);
  restartClocks();
  postFrame();
  schedule();
}

/** @param {boolean} run */
function setRunning(run) {
  running = run;
  restartClocks();
  if (!run) postFrame(); // held: the page shows the robot as it stopped, not the last frame sent
  scope.postMessage({ type: FromWorker.STATE, running });
  schedule();
}

function restartClocks() {
  const now = performance.now();
  anchor = { wall: now, sim: episode ? episode.time : 0 };
  rate = { wall: now, sim: anchor.sim, compute: 0, simPerWall: NaN, simPerCompute: NaN };
}

function schedule() {
  if (running && episode && !tickScheduled) {
    tickScheduled = true;
    yieldChannel.port2.postMessage(null);
  }
}

/** One slice: step toward the paced target (or for the budget), maybe post a frame. */
function tick() {
  tickScheduled = false;
  if (!running || !episode) return;
  try {
    stepSlice(episode);
  } catch (error) {
    running = false;
    scope.postMessage({ type: FromWorker.STATE, running });
    reportError(messageOf(error), error instanceof WebAssembly.RuntimeError);
    return;
  }
  const now = performance.now();
  if (params?.until && episode.stepsLeft(params.until) === 0) { setRunning(false); return; }
  if (now - lastFramePosted >= FRAME_INTERVAL_MS) postFrame();
  if (stepsBeforeWait(episode) === 0) {
    anchor = { wall: now, sim: episode.time }; // waiting owes no steps: it goes on at its pace
    setTimeout(schedule, FRAME_INTERVAL_MS / 2);
  } else if (speed > 0 && targetSteps(episode, now) === 0) {
    setTimeout(schedule, FRAME_INTERVAL_MS / 2);
  } else {
    schedule();
  }
}

/** @param {Episode} ep */
function stepSlice(ep) {
  preview = null; // it steps: its own matrices from now on
  const begin = performance.now();
  let budget = speed > 0 ? targetSteps(ep, begin) : Infinity;
  if (params?.until) budget = Math.min(budget, ep.stepsLeft(params.until));
  budget = Math.min(budget, stepsBeforeWait(ep));
  while (budget > 0 && performance.now() - begin < SLICE_BUDGET_MS) {
    const n = Math.min(STEPS_PER_CALL, budget);
    ep.step(n);
    budget -= n;
  }
  rate.compute += performance.now() - begin;
}

/** Steps left before the time the page said to wait at (Infinity when it said none). @param {Episode} ep */
function stepsBeforeWait(ep) {
  return Number.isFinite(waitAt) ? Math.max(0, Math.floor((waitAt - ep.time) / dt + 1e-6)) : Infinity;
}

/**
 * Steps still owed to keep simulated time at `speed` x wall time; drops the lag when
 * the machine cannot keep up, instead of spiralling.
 * @param {Episode} ep
 * @param {number} now
 */
function targetSteps(ep, now) {
  const want = anchor.sim + ((now - anchor.wall) / 1000) * speed;
  if (want - ep.time > MAX_LAG_S) anchor = { wall: now, sim: ep.time };
  return Math.max(0, Math.floor((Math.min(want, ep.time + MAX_LAG_S) - ep.time) / dt + 1e-6));
}

function postFrame() {
  if (!episode) return;
  const now = performance.now();
  lastFramePosted = now;
  updateRates(episode, now);
  // The core's part of the frame (crate/wasm/src/controlled.rs, `frame`); the rest is added here.
  const frame = /** @type {Omit<import('./protocol.js').Frame, 'velocity' | 'frozen' | 'simPerWall' | 'simPerCompute'>} */ (episode.frame());
  if (preview && preview.length === frame.attention.length) frame.attention = preview.slice(); // (sent away: a copy each time)
  scope.postMessage({
    type: FromWorker.FRAME, ...frame, velocity: episode.velocity, frozen: episode.attentionFrozen,
    simPerWall: running ? rate.simPerWall : NaN, simPerCompute: rate.simPerCompute,
  }, [frame.corners.buffer, frame.areas.buffer, frame.bodies.buffer, frame.attention.buffer]);
}

/** @param {Episode} ep @param {number} now */
function updateRates(ep, now) {
  const wall = now - rate.wall;
  if (wall < RATE_WINDOW_MS) return;
  const sim = ep.time - rate.sim;
  rate.simPerWall = sim / (wall / 1000);
  rate.simPerCompute = rate.compute > 0 ? sim / (rate.compute / 1000) : NaN;
  rate.wall = now;
  rate.sim = ep.time;
  rate.compute = 0;
}

/** @param {string} message @param {boolean} fatal */
function reportError(message, fatal) {
  scope.postMessage({ type: FromWorker.ERROR, message, fatal });
}

ready.then(
  (physics) => scope.postMessage({ type: FromWorker.READY, physics }),
  (error) => reportError(messageOf(error), true),
);
