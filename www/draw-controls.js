// @ts-check
/**
 * The controls of “1 · Draw” around the editor's grid: the presets, undo and redo (also
 * Ctrl+Z, Ctrl+Shift+Z and Ctrl+Y), clear, erase mode for touch screens, and the rows typed
 * as text. Each change of the drawing is handed to the page (`changed`), none while a run
 * uses the robot.
 */

/**
 * @param {Document} doc
 * @param {import('./core.js').Defaults} defaults
 * @param {import('./drawing.js').Drawing} drawing
 * @param {import('./editor.js').Editor} editor
 * @param {{changed: () => void, running: () => boolean, message: (text: string) => void}} hooks
 *   message: about the rows typed ('' takes it away)
 */
export function wireDrawControls(doc, defaults, drawing, editor, hooks) {
  const el = (/** @type {string} */ id) => /** @type {any} */ (doc.getElementById(id));
  const presetSelect = /** @type {HTMLSelectElement} */ (el('preset'));
  const rowsInput = /** @type {HTMLInputElement} */ (el('rows'));
  const redraw = () => { hooks.message(''); editor.draw(); hooks.changed(); }; // the rows are valid again
  for (const p of defaults.presets) presetSelect.append(new Option(p.name, p.rows));
  presetSelect.addEventListener('change', () => {
    if (!presetSelect.value) return;
    drawing.setRows(presetSelect.value);
    redraw();
  });
  const undo = () => { if (!hooks.running() && drawing.undo()) redraw(); };
  const redo = () => { if (!hooks.running() && drawing.redo()) redraw(); };
  el('undo').addEventListener('click', undo);
  el('redo').addEventListener('click', redo);
  el('clear').addEventListener('click', () => { drawing.clear(); redraw(); });
  el('erase').addEventListener('click', () => {
    editor.erase = !editor.erase;
    el('erase').setAttribute('aria-pressed', String(editor.erase));
  });
  doc.addEventListener('keydown', (e) => {
    const typing = e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement;
    if (typing || !(e.ctrlKey || e.metaKey)) return;
    const key = e.key.toLowerCase();
    if (key === 'z' && !e.shiftKey) { e.preventDefault(); undo(); }
    if ((key === 'z' && e.shiftKey) || key === 'y') { e.preventDefault(); redo(); }
  });
  rowsInput.addEventListener('change', () => {
    const problem = drawing.setRows(rowsInput.value.trim() || '0');
    if (problem) { hooks.message(problem); rowsInput.value = drawing.rows(); return; }
    redraw();
  });
}
