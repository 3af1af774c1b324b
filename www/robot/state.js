// @ts-check
/**
 * The robot's state as the page keeps it across reloads and shares it as a link (keep/share.js
 * writes and reads it as text): the drawing, the chosen family, the viewer's terrain and phase
 * gait, the run settings and the brain that fits the drawing (with the episode length it was
 * trained on, its training figure and whether it is a one-shot transplant: the speed note's
 * words);
 * and showing such a state on the robot.
 */
import { describeRun } from '../workers/core.js';
import { messageOf } from '../workers/kit.js';

/** @param {import('./robot.js').Robot} robot @returns {import('../keep/share.js').PageState} */
export function pageState(robot) {
  const { drawing, viewer, runs } = robot.parts;
  const brain = robot.brain;
  return {
    rows: drawing.rows(), controller: robot.controllerSelect.value, terrain: viewer.terrain.value,
    gait: gaitOf(viewer), run: runs.values(),
    brain: brain && brain.rows === drawing.rows()
      ? { controller: brain.controller, genome: brain.genome, label: brain.label, module: brain.module, seconds: brain.seconds ?? null,
        trained: brain.trained ?? null, oneShot: brain.oneShot ?? false } : null,
  };
}

/**
 * The viewer's phase gait as "F,PHI", or null while its inputs do not hold two numbers (a
 * half-typed gait is not kept: the rest of the state must stay readable).
 * @param {import('../viewer/viewer.js').Viewer} viewer
 */
function gaitOf(viewer) {
  const { frequency, phase } = viewer.gait;
  return Number.isFinite(frequency.valueAsNumber) && Number.isFinite(phase.valueAsNumber) ? `${frequency.value},${phase.value}` : null;
}

/**
 * Shows `state` on the robot, a change of its brain (run it in its turn: Robot.restore); a
 * robot that does not fit the grid is refused.
 * @param {import('./robot.js').Robot} robot @param {import('../keep/share.js').PageState} state
 * @returns {Promise<string>} '' or why nothing was shown
 */
export async function applyState(robot, state) {
  const { drawing, editor, viewer, runs, defaults } = robot.parts;
  const problem = drawing.setRows(state.rows);
  if (problem) return problem;
  drawing.undoStack = [];
  if (defaults.controllers.includes(state.controller)) robot.controllerSelect.value = state.controller;
  if (state.terrain) viewer.terrain.value = state.terrain;
  if (state.gait) [viewer.gait.frequency.value, viewer.gait.phase.value] = state.gait.split(',').map((v) => v.trim());
  runs.setValues(state.run);
  robot.brain = null;
  if (state.brain) {
    const brain = { ...state.brain, rows: state.rows, origin: robot.parts.drawing.origin(), source: /** @type {import('./brain.js').Source | null} */ (null) };
    robot.brain = brain;
    if (state.brain.module) {
      try {
        const text = await fetch(state.brain.module).then((r) => (r.ok ? r.text() : Promise.reject(new Error(`HTTP ${r.status}`))));
        brain.source = { text, entry: null };
        brain.seconds ??= await describeRun(text).then((info) => info.seconds, () => null); // kept before its seconds were: the module's
      } catch (error) {
        robot.error(`the module ${state.brain.module} could not be fetched, so this robot cannot be fine-tuned: ${messageOf(error)}`);
      }
    }
  }
  editor.draw();
  await robot.follow(robot.change(false));
  return '';
}
