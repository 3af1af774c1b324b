// @ts-check
/**
 * The body-search part of the page's message protocol (the rest, and the evaluation workers'
 * messages, are in protocol.js). Defined here once; the panel and the coordinator import
 * these names instead of spelling strings.
 */

/*
 * Body search in the page: the page (codesign/panel.js) drives a body-search coordinator worker
 * (codesign/coordinator.js), which owns the wasm `Codesign` (as `vsr codesign`) and a pool of
 * the same evaluation workers (runs/pool.js, runs/evaluator.js: each job carries its own `shape`).
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
 * A message from the page to the body-search coordinator (the list above).
 * @typedef {{type: typeof ToCodesign.START, settings: CodesignSettings, workers: number, module: string | null}
 *   | {type: typeof ToCodesign.STOP}
 *   | {type: typeof ToCodesign.ENTRY, cell: [number, number], ticket: number}
 *   | {type: typeof ToCodesign.CRASH_WORKER, index: number}} ToCodesignMessage
 */

/**
 * A message from the body-search coordinator to the page (the list above).
 * @typedef {{type: typeof FromCodesign.STARTED, planned: number, workers: number, layout: Layout}
 *   | {type: typeof FromCodesign.ITERATION, record: IterationRecord, evaluations: number, planned: number,
 *       gallery: GalleryEntry[], seconds: number}
 *   | {type: typeof FromCodesign.ENTRY, cell: [number, number], ticket: number, entry: Entry, message?: undefined}
 *   | {type: typeof FromCodesign.ENTRY, cell: [number, number], ticket: number, entry: null, message: string}
 *   | {type: typeof FromCodesign.RECOVERED, message: string}
 *   | {type: typeof FromCodesign.DONE, stopped: boolean, runFile: string | null}
 *   | {type: typeof FromCodesign.ERROR, message: string}} FromCodesignMessage
 */

/**
 * The archive's shape, as `Codesign.layout()` returns it.
 * @typedef {object} Layout
 * @property {number} columns    size bins
 * @property {number} rows       feet bins
 * @property {number} minVoxels
 * @property {number} maxVoxels
 * @property {number} sizeBin    voxels per size bin
 * @property {number} maxFeet    the last feet bin holds this many feet or more
 */

/**
 * An iteration's record in the search's file, as `Codesign.tell` returns it (non-finite values null).
 * @typedef {object} IterationRecord
 * @property {number} iteration
 * @property {number} evaluations  so far, this iteration included
 * @property {number | null} best  the archive's best fitness (m/s)
 * @property {number} filled       archive cells filled
 * @property {number} qd_score     the sum of the elites' positive fitness values
 * @property {number} kept         children that took a cell this iteration
 * @property {number} wall_seconds
 */

/**
 * A body with its brain: entry `index` of the search's file `source` (JSON text), as a plain run
 * file's best (`Codesign.entry`).
 * @typedef {{controller: string, shape: string, genome: number[], fitness: number, index: number, source: string}} Entry
 */

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
