// @ts-check
/**
 * Reading attention: one voxel's attention matrix enlarged, live, as a table whose rows are
 * named by query and columns by key (the voxel's sensors, in the order the controller reads
 * them: area, vx, vy, touch), each value shown on hover, with what a row means and why most
 * entries sit at -1 or +1. Opened by a click (or tap) on a voxel's map in the attention
 * panel; the page highlights that voxel on the robot while the reader is open.
 */
import { attentionColour } from './attention.js';
import { byId } from '../shared/dom.js';
import { ATTENTION_FLOATS, SENSOR_NAMES } from '../workers/protocol.js';
import { decimal, signed } from '../shared/format.js';

const SIDE = SENSOR_NAMES.length;
/** What each reading is, for the row and column titles. */
const SENSES = Object.freeze({
  area: 'how squeezed or stretched the voxel is',
  vx: 'its sideways speed',
  vy: 'its up-down speed',
  touch: 'whether it touches the ground',
});

/** @typedef {{voxel: number, column: number, row: number} | null} Choice */

export class AttentionReader {
  /**
   * @param {Document} doc
   * @param {(voxel: number) => void} highlight marks the voxel on the robot (-1: none)
   */
  constructor(doc, highlight) {
    this.section = byId(doc, 'attention-reader');
    this.title = byId(doc, 'attention-reader-title');
    this.hover = byId(doc, 'attention-hover');
    this.terms = byId(doc, 'attention-terms');
    this.highlight = highlight;
    /** @type {Choice} */
    this.choice = null;
    /** The value under the pointer: [row, column], or null. @type {[number, number] | null} */
    this.pointed = null;
    /** @type {HTMLTableCellElement[]} */
    this.cells = [];
    this.buildTable(byId(doc, 'attention-matrix', HTMLTableElement));
    byId(doc, 'attention-reader-close', HTMLButtonElement).addEventListener('click', () => this.close());
  }

  /** @param {HTMLTableElement} table */
  buildTable(table) {
    const doc = table.ownerDocument;
    const head = table.createTHead().insertRow();
    const corner = doc.createElement('th');
    corner.textContent = 'query ↓ · key →';
    corner.dataset.simple = 'asks ↓ · listens to →'; // simple words (shared/simple-words.js)
    corner.className = 'corner';
    head.append(corner);
    for (const name of SENSOR_NAMES) {
      const th = doc.createElement('th');
      th.scope = 'col';
      th.textContent = name;
      th.title = `key: ${name}, ${SENSES[/** @type {keyof typeof SENSES} */ (name)]}`;
      head.append(th);
    }
    const body = table.createTBody();
    SENSOR_NAMES.forEach((name, r) => {
      const tr = body.insertRow();
      const th = doc.createElement('th');
      th.scope = 'row';
      th.textContent = name;
      th.title = `query: ${name}, ${SENSES[/** @type {keyof typeof SENSES} */ (name)]}`;
      tr.append(th);
      for (let c = 0; c < SIDE; c++) {
        const td = tr.insertCell();
        td.dataset.query = name;
        td.dataset.key = SENSOR_NAMES[c];
        const point = () => { this.pointed = [r, c]; };
        td.addEventListener('pointerenter', point);
        td.addEventListener('pointerdown', point);
        td.addEventListener('pointerleave', () => { this.pointed = null; });
        this.cells.push(td);
      }
    });
  }

  /**
   * Opens the reader on voxel `voxel` at grid cell (column, row from the bottom).
   * @param {number} voxel @param {number} column @param {number} row
   */
  open(voxel, column, row) {
    this.choice = { voxel, column, row };
    this.title.textContent = `Voxel ${voxel + 1}: column ${column + 1}, row ${row + 1} from the bottom left`;
    this.section.hidden = false;
    this.section.dataset.voxel = String(voxel);
    this.highlight(voxel);
    this.section.scrollIntoView({ block: 'nearest', behavior: 'instant' }); // it opens under the maps, maybe below the screen
  }

  close() {
    this.choice = null;
    this.section.hidden = true;
    delete this.section.dataset.voxel;
    this.highlight(-1);
  }

  /**
   * A new episode: the reader stays on the same voxel if the robot still has it.
   * @param {number} voxels @param {number[] | null} terms the brain's a, b, c, d, or null
   */
  setEpisode(voxels, terms) {
    if (this.choice && this.choice.voxel >= voxels) this.close();
    else if (this.choice) this.highlight(this.choice.voxel);
    this.terms.textContent = terms
      ? `For this brain a = ${decimal(terms[0], 1)}, b = ${decimal(terms[1], 1)}, c = ${decimal(terms[2], 1)}, d = ${decimal(terms[3], 1)}.`
      : '';
  }

  /** @param {Float32Array} attention every voxel's matrix (16 per voxel), or empty */
  setFrame(attention) {
    if (!this.choice) return;
    const at = this.choice.voxel * ATTENTION_FLOATS;
    if (attention.length < at + ATTENTION_FLOATS) return;
    this.cells.forEach((td, i) => {
      const v = attention[at + i];
      const text = signed(v);
      td.style.background = attentionColour(v);
      td.style.color = Math.abs(v) > 0.6 ? '#fff' : '#1d2730';
      td.textContent = text;
      td.dataset.value = String(v);
      td.title = `query ${td.dataset.query}, key ${td.dataset.key}: ${text}`;
    });
    if (this.pointed) {
      const [r, c] = this.pointed;
      const v = attention[at + r * SIDE + c];
      this.hover.textContent = `Row ${SENSOR_NAMES[r]} (query), column ${SENSOR_NAMES[c]} (key): ${signed(v, 3)}`;
    }
  }
}
