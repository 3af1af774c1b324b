// @ts-check
/**
 * Editing the walking robot: a click (or tap) on one of its voxels removes it, a click next to
 * it adds one there, and the robot is rebuilt where it stands, in its posture and motion, its
 * brain following the edit (Robot.bodyChanged with the edit's shift). An edit that would leave
 * no robot (no voxel, or pieces) is refused with a message.
 */
import { checkShape } from '../workers/core.js';
import { messageOf } from '../workers/kit.js';

/**
 * @param {import('./robot.js').Robot} robot
 * @param {{voxel: number, dx: number, dy: number}} pick the voxel clicked, or the cell next to it (the renderer's pick)
 * @returns {Promise<void>}
 */
export async function editWalking(robot, pick) {
  const { drawing, editor, messages } = robot.parts;
  if (robot.running) { messages.show('A run is using this robot: stop it to edit the robot.', 'note'); return; }
  const box = drawing.box();
  if (!box || !robot.check.ok) return;
  const cells = [];
  for (let y = box.bottom; y <= box.top; y++) for (let x = box.left; x <= box.right; x++) if (drawing.has(x, y)) cells.push([x, y]);
  const cell = cells[pick.voxel];
  if (!cell) return;
  const [x, y] = [cell[0] + pick.dx, cell[1] + pick.dy];
  const adding = pick.dx !== 0 || pick.dy !== 0;
  if (!drawing.inside(x, y)) { robot.error('that cell is outside the drawing grid'); return; }
  if (adding && drawing.has(x, y)) return;
  const from = drawing.rows();
  let after;
  try {
    after = await checkShape(drawing.rowsWith(x, y, adding));
  } catch (error) {
    robot.error(`the edit could not be checked: ${messageOf(error)}`);
    return;
  }
  if (robot.running || drawing.rows() !== from) return; // the drawing changed meanwhile: this click is moot
  if (!after.ok) {
    robot.error(after.pieces.length === 0 ? 'A robot needs at least one voxel; not done'
      : `Removing that voxel would split the robot into ${after.pieces.length} pieces; not done`);
    return;
  }
  drawing.set(x, y, adding);
  const moved = drawing.box();
  editor.draw();
  await robot.bodyChanged(moved ? { from, dx: box.left - moved.left, dy: box.bottom - moved.bottom } : false);
}
