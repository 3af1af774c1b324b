// @ts-check
/**
 * What a point of the scene is on or next to: a voxel of the robot, or the empty cell beside
 * one, in the voxel's own (deformed, rotated) axes. The renderer turns a click into a point.
 */
import { CORNER_FLOATS } from '../workers/protocol.js';

/**
 * The voxel at world point (wx, wy) (m) (`dx`, `dy` 0), or the empty cell next to voxel
 * `voxel` in grid direction (dx, dy); null when nowhere near.
 * @param {import('../workers/protocol.js').Frame} frame @param {number} wx @param {number} wy
 * @returns {{voxel: number, dx: number, dy: number} | null}
 */
export function voxelAt(frame, wx, wy) {
  let best = null;
  for (let i = 0; i < frame.voxels; i++) {
    const c = frame.corners.subarray(i * CORNER_FLOATS, (i + 1) * CORNER_FLOATS);
    const cx = (c[0] + c[2] + c[4] + c[6]) / 4;
    const cy = (c[1] + c[3] + c[5] + c[7]) / 4;
    // The voxel's own axes: east = SE - SW, north = NW - SW, each about one cell long.
    const ex = (c[2] - c[0] + c[4] - c[6]) / 2;
    const ey = (c[3] - c[1] + c[5] - c[7]) / 2;
    const nx = (c[6] - c[0] + c[4] - c[2]) / 2;
    const ny = (c[7] - c[1] + c[5] - c[3]) / 2;
    const u = ((wx - cx) * ex + (wy - cy) * ey) / (ex * ex + ey * ey);
    const v = ((wx - cx) * nx + (wy - cy) * ny) / (nx * nx + ny * ny);
    const d = Math.max(Math.abs(u), Math.abs(v));
    if (d < 1.5 && (!best || d < best.d)) best = { voxel: i, u, v, d };
  }
  if (!best) return null;
  if (best.d <= 0.5) return { voxel: best.voxel, dx: 0, dy: 0 };
  return Math.abs(best.u) > Math.abs(best.v)
    ? { voxel: best.voxel, dx: Math.sign(best.u), dy: 0 }
    : { voxel: best.voxel, dx: 0, dy: Math.sign(best.v) };
}
