// @ts-check
/**
 * What the page says about the robot, in words: the drawing's check (the line under the grid
 * and, for a drawing that is not a robot yet, the message that says why), the robot that walks
 * while the drawing is not one, and what drives it. Plain functions of the robot's state, so
 * robot.js only decides when to say them.
 */
import { plain } from '../shared/message.js';
import { familyName } from '../shared/families.js';

/** @typedef {import('./brain.js').Brain} Brain */

/**
 * The line under the grid for the drawing `rows` and its check (null: it could not be
 * checked), and the message to show when it is not a robot ('' when it is).
 * @param {string} rows @param {import('../workers/core.js').ShapeCheck | null} check
 * @returns {{status: string, problem: string}}
 */
export function checkWords(rows, check) {
  if (!check) return { status: 'Not checked: change the drawing to check it again', problem: '' };
  if (check.ok) return { status: `${check.voxels} voxel${check.voxels === 1 ? '' : 's'} · ${rows}`, problem: '' };
  const many = check.pieces.length > 1;
  return {
    status: many ? `Not a robot yet: ${check.pieces.length} separate pieces` : 'Not a robot yet: no voxels',
    problem: `Your drawing is not a robot yet: ${plain(check.message)}${many ? `; each of its ${check.pieces.length} pieces has its own colour` : ''}. `
      + 'Evolve and Fine-tune are off until it is.',
  };
}

/**
 * The robot that walks while the drawing is not one (its last whole body), in words ('' before
 * the first). @param {Brain | null} brain @param {string} walkingRows the body the viewer walks
 */
export function walkingWords(brain, walkingRows) {
  const walking = brain?.rows ?? walkingRows;
  if (!walking) return '';
  const voxels = [...walking].filter((c) => c === '1').length;
  return `the robot walking is your last whole drawing: ${voxels} voxels${brain ? `, ${brain.genome.length} genes` : ''}`;
}

/**
 * Writes `text` into `el` with every speed's number in a `.speed-figure` span: while a tour
 * question holds its answer back the page covers those numbers with a grey bar (tour.css), as it
 * hides the viewer's speeds. @param {HTMLElement} el @param {string} text
 */
export function showWithSpeeds(el, text) {
  const doc = el.ownerDocument;
  const parts = text.split(/(-?\d+(?:\.\d+)?)(?= m\/s)/); // odd places: the numbers
  el.replaceChildren(...parts.map((part, i) => {
    if (i % 2 === 0) return doc.createTextNode(part);
    const figure = doc.createElement('span');
    figure.className = 'speed-figure';
    figure.textContent = part;
    return figure;
  }));
}

/**
 * What drives the robot and, while the drawing (`check`) is not a robot, that the one walking
 * is the last whole one. @param {Brain | null} brain @param {import('../workers/core.js').ShapeCheck} check @param {string} walkingRows
 */
export function driverWords(brain, check, walkingRows) {
  const drives = brain ? `Driven by: ${brain.label} (${familyName(brain.controller)}, ${brain.genome.length} genes).`
    : 'Driven by: the phase gait (no brain yet: evolve one, or load a module).';
  const yours = check.voxels > 0 ? `Your drawing (${check.voxels} voxels) is not a robot yet` : 'Your drawing is empty';
  const drawn = !check.ok && walkingRows ? ` ${yours}, so ${walkingWords(brain, walkingRows)}.` : '';
  return drives + drawn;
}
