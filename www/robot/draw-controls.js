// @ts-check
/**
 * The controls of “1 · Draw” around the editor's grid: the presets, undo and redo (also
 * Ctrl+Z, Ctrl+Shift+Z and Ctrl+Y), clear, erase mode for touch screens, and the rows typed
 * as text (`rowsField`, a typed field: rows refused stay typed, marked and said under the
 * field, until the field holds rows again). Each change of the drawing is handed to the page
 * (`changed`), none while a run uses the robot.
 */
import { byId } from '../shared/dom.js';
import { Drawing } from './drawing.js';
import { TypedField } from '../shared/typed-field.js';

/**
 * @param {Document} doc
 * @param {import('../workers/core.js').Defaults} defaults
 * @param {import('./drawing.js').Drawing} drawing
 * @param {import('./editor.js').Editor} editor
 * @param {{changed: () => void, running: () => boolean}} hooks
 */
export function wireDrawControls(doc, defaults, drawing, editor, hooks) {
  const presetSelect = byId(doc, 'preset', HTMLSelectElement);
  const redraw = () => { editor.draw(); hooks.changed(); };
  for (const p of defaults.presets) presetSelect.append(new Option(p.name, p.rows));
  presetSelect.addEventListener('change', () => {
    if (!presetSelect.value) return;
    drawing.setRows(presetSelect.value);
    redraw();
  });
  const undo = () => { if (!hooks.running() && drawing.undo()) redraw(); };
  const redo = () => { if (!hooks.running() && drawing.redo()) redraw(); };
  byId(doc, 'undo', HTMLButtonElement).addEventListener('click', undo);
  byId(doc, 'redo', HTMLButtonElement).addEventListener('click', redo);
  byId(doc, 'clear', HTMLButtonElement).addEventListener('click', () => { drawing.clear(); redraw(); });
  const erase = byId(doc, 'erase', HTMLButtonElement);
  erase.addEventListener('click', () => {
    editor.erase = !editor.erase;
    erase.setAttribute('aria-pressed', String(editor.erase));
  });
  doc.addEventListener('keydown', (e) => {
    const typing = e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement;
    if (typing || !(e.ctrlKey || e.metaKey)) return;
    const key = e.key.toLowerCase();
    if (key === 'z' && !e.shiftKey) { e.preventDefault(); undo(); }
    if ((key === 'z' && e.shiftKey) || key === 'y') { e.preventDefault(); redo(); }
  });
}

/**
 * The rows typed as text: a typed field whose rule is the drawing's, tried on a blank drawing of
 * the same grid; accepted rows become the drawing (`changed` is then told). The page shows the
 * drawing's rows through the field's `value` (robot.js), which settles it.
 * @param {Document} doc @param {import('./drawing.js').Drawing} drawing
 * @param {import('./editor.js').Editor} editor @param {import('../shared/message.js').MessageBox} messages
 * @param {() => void} changed
 */
export function rowsField(doc, drawing, editor, messages, changed) {
  const rows = (/** @type {string} */ text) => text.trim() || '0'; // nothing typed: an empty drawing
  return new TypedField(byId(doc, 'rows', HTMLInputElement), messages, {
    problem: (text) => new Drawing(drawing.width, drawing.height).setRows(rows(text)),
    use: (text) => { drawing.setRows(rows(text)); editor.draw(); changed(); },
  });
}
