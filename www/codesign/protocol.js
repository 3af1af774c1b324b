// @ts-check
/**
 * The body-search part of the page's message protocol (the rest, and the evaluation workers'
 * messages, are in ../protocol.js). Defined here once; the panel and the coordinator import
 * these names instead of spelling strings.
 */

/*
 * Body search in the page: the page (codesign/panel.js) drives a body-search coordinator worker
 * (codesign/coordinator.js), which owns the wasm `Codesign` (as `vsr codesign`) and a pool of
 * the same evaluation workers (pool.js, evaluator.js: each job carries its own `shape`).
 *
 * Page -> body-search coordinator
 *   {type: 'start', settings, workers, module}  begin a search of {@link CodesignSettings} with
 *                                       `workers` evaluation workers; module: the pretrained
 *                                       module's run file (JSON text) for 'frozen' and
 *                                       'finetune', else null; bad settings or a module that
 *                                       cannot drive other bodies answer 'error' in words
 *   {type: 'stop'}                      end the search now; the unfinished iteration is dropped
 *   {type: 'entry', cell, ticket}       send the body in archive cell `cell` ([size bin, feet
 *                                       bin]) with its brain ('entry' answer, same ticket); the
 *                                       archive stays after the search ended
 *   {type: 'crash-worker', index}       as for an evolution
 *
 * Body-search coordinator -> page
 *   {type: 'started', planned, workers, layout}  layout: {columns, rows, minVoxels, sizeBin, maxFeet}
 *   {type: 'iteration', record, evaluations, planned, gallery, seconds}
 *                                        an iteration was told: record is the run file's
 *                                        iteration record ({iteration, evaluations, best,
 *                                        filled, qd_score, kept, wall_seconds}); gallery: the
 *                                        archive in cell order ({@link GalleryEntry}[])
 *   {type: 'entry', cell, ticket, entry, message} entry: {controller, shape, genome
 *                                        (number[]), fitness, index, source}: entry `index`
 *                                        of the search's file so far (`source`, JSON text),
 *                                        or null and why
 *   {type: 'recovered', message}         an evaluation worker died; a new one re-runs its job
 *   {type: 'done', stopped, runFile}     the search ended; runFile: the co-design run file
 *                                        (format 'vsr-codesign'), null before iteration 0
 *   {type: 'error', message}             bad settings, a wrong module, a failed evaluation
 */

/** Message types sent by the page to the body-search coordinator. */
export const ToCodesign = Object.freeze({
  START: 'start',
  STOP: 'stop',
  ENTRY: 'entry',
  CRASH_WORKER: 'crash-worker',
});

/** Message types sent by the body-search coordinator to the page. */
export const FromCodesign = Object.freeze({
  STARTED: 'started',
  ITERATION: 'iteration',
  ENTRY: 'entry',
  RECOVERED: 'recovered',
  DONE: 'done',
  ERROR: 'error',
});

/**
 * @typedef {object} CodesignSettings  a body search's settings, the options of `vsr codesign`
 * @property {'frozen' | 'finetune' | 'scratch'} brain
 * @property {string} [controller]  the family for 'scratch' (default attention)
 * @property {string} [start]       the start body's rows (default: the module's own body, or a 3 x 3 box)
 * @property {number} seed
 * @property {number} seconds       simulated seconds per evaluation
 * @property {string} terrain       training terrain family or name
 * @property {number} budget        evaluations
 * @property {number} [batch]       new bodies per iteration
 * @property {[number, number]} [grid]   the search grid, width and height (cells)
 * @property {[number, number]} [voxels] voxel-count bounds, min and max
 */

/**
 * @typedef {object} GalleryEntry  one archive cell's best body
 * @property {[number, number]} cell  [size bin, feet bin]
 * @property {number} voxels
 * @property {number} feet
 * @property {string} shape      rows
 * @property {number | null} fitness  m/s (null: exploded)
 * @property {number} measurements
 * @property {number} found      the iteration it was found in
 */
