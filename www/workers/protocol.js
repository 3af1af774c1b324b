// @ts-check
/**
 * The message protocol between the page (main.js) and the simulation worker
 * (simulation-worker.js), and the layout of every frame buffer. Defined here once; both sides
 * import these names instead of spelling strings.
 *
 * Page -> worker
 *   {type: 'load', params}   build a new episode from {@link EpisodeParams}: the body
 *                            `params.shape` driven by the phase gait, or by `params.brain`
 *                            (a controller family and its genome; sensor noise seed 0); on
 *                            failure (bad input, a genome that does not fit) the worker
 *                            answers 'error' and keeps its previous episode
 *   {type: 'start'}          run (paced by `speed`)
 *   {type: 'pause'}          stop stepping; the last frame stays on screen
 *   {type: 'reset'}          rebuild the current episode from its parameters (t = 0)
 *   {type: 'speed', speed}   simulated seconds per wall second; 0 means as fast as possible
 *   {type: 'freeze', frozen} freeze every voxel's attention matrix where it is now (true) or
 *                            release it (false); a brain without attention answers 'error'
 *   {type: 'length', seconds} the episode's length from now on (its speed is measured over it)
 *   {type: 'wait-at', seconds} step no further than simulated time `seconds` until told a later
 *                            one (Infinity: no limit; a new episode starts with none): the race
 *                            keeps its lanes in step with it
 *
 * Worker -> page
 *   {type: 'ready', physics}             the wasm module is instantiated; physics: the
 *                                        core's constants the drawing needs, {@link Physics}
 *                                        (defaults().physics, crate/engine/src/experiment/playground.rs),
 *                                        sent here so that no copy of them lives in the page
 *   {type: 'loaded', params, carried, voxels, controller, cells, terrainXs, terrainYs, attentionTerms}
 *                                        a new episode replaced the previous one;
 *                                        carried: it took the edited robot's posture and motion;
 *                                        controller: 'phase gait', 'attention', 'mlp', ...;
 *                                        cells (Uint32Array, 2n): voxel i's grid column at 2i
 *                                        (from the left) and row at 2i + 1 (from the bottom);
 *                                        attentionTerms: the four numbers a, b, c, d that fix
 *                                        every matrix of `params.brain`'s attention,
 *                                        A[r][c] = tanh(a s_r s_c + b s_r + c s_c + d)
 *                                        (null without an attention brain)
 *   {type: 'frame', ...Frame}            the latest state, buffers transferred
 *   {type: 'state', running}             the run/pause state changed
 *   {type: 'error', message, fatal}      bad input (fatal = false: nothing changed) or a
 *                                        crash of the wasm module (fatal = true: the page
 *                                        must start a new worker)
 *
 * Frame buffers (all Float32Array, n = number of voxels, lengths in floats; the same
 * layouts are documented on the Rust getters in crate/wasm/src/episode.rs):
 *   corners  8n   voxel i at 8i: outer corner points x, y in order SW, SE, NE, NW (m)
 *   areas     n   voxel i at i: area / rest area, physics.areaContracted .. areaExpanded
 *   bodies  12n   voxel i at 12i: four rigid corner squares (physics.cornerSide wide) as centre x,
 *                 centre y, angle (rad), in order SW, SE, NE, NW
 *   attention 16n or 0   voxel i at 16i: its attention matrix, 4 rows of 4 (row-major),
 *                 rows (queries) and columns (keys) in SENSOR_NAMES order, values -1 .. 1;
 *                 empty when the controller has no attention (phase gait, MLP, MLP-Comm, and theirs for any body)
 * Terrain (sent once per episode, Float64Array): polyline xs, ys in m, y up, walls included.
 */

/** Message types sent by the page to the worker. */
export const ToWorker = Object.freeze({
  LOAD: 'load',
  START: 'start',
  PAUSE: 'pause',
  RESET: 'reset',
  SPEED: 'speed',
  FREEZE: 'freeze',
  LENGTH: 'length',
  WAIT_AT: 'wait-at',
});

/** Message types sent by the worker to the page. */
export const FromWorker = Object.freeze({
  READY: 'ready',
  LOADED: 'loaded',
  FRAME: 'frame',
  STATE: 'state',
  ERROR: 'error',
});

/**
 * A message from the page to the simulation worker (the list above).
 * @typedef {{type: typeof ToWorker.LOAD, params: EpisodeParams}
 *   | {type: typeof ToWorker.START}
 *   | {type: typeof ToWorker.PAUSE}
 *   | {type: typeof ToWorker.RESET}
 *   | {type: typeof ToWorker.SPEED, speed: number}
 *   | {type: typeof ToWorker.FREEZE, frozen: boolean}
 *   | {type: typeof ToWorker.LENGTH, seconds: number}
 *   | {type: typeof ToWorker.WAIT_AT, seconds: number}} ToWorkerMessage
 */

/**
 * A message from the simulation worker to the page (the list above).
 * @typedef {{type: typeof FromWorker.READY, physics: Physics}
 *   | {type: typeof FromWorker.LOADED, params: LoadedParams, carried: boolean, voxels: number,
 *       controller: string, cells: Uint32Array, terrainXs: Float64Array, terrainYs: Float64Array,
 *       attentionTerms: number[] | null}
 *   | ({type: typeof FromWorker.FRAME} & Frame)
 *   | {type: typeof FromWorker.STATE, running: boolean}
 *   | {type: typeof FromWorker.ERROR, message: string, fatal: boolean}} FromWorkerMessage
 */

/** Floats per voxel in `corners`: 4 corner points x, y. */
export const CORNER_FLOATS = 8;
/** Floats per voxel in `areas`. */
export const AREA_FLOATS = 1;
/** Floats per voxel in `bodies`: 4 corner squares x, y, angle. */
export const BODY_FLOATS = 12;
/** Floats per voxel in `attention`: a 4 x 4 matrix. */
export const ATTENTION_FLOATS = 16;
/** A voxel's sensors, in the order of its readings and of its attention rows and columns. */
export const SENSOR_NAMES = Object.freeze(['area', 'vx', 'vy', 'touch']);

/**
 * @typedef {object} Physics  the simulation's constants, from the core (the worker's 'ready')
 * @property {number} timeStep        simulation time step (s)
 * @property {number} areaContracted  area ratio of a fully contracted voxel (u = +1)
 * @property {number} areaExpanded    area ratio of a fully expanded voxel (u = -1)
 * @property {number} cornerSide      width of a rigid corner square (m)
 */

/**
 * @typedef {object} EpisodeParams
 * @property {string} shape      the body as rows, top first (`1111-1111-1001`)
 * @property {string} [terrain]  terrain name (`hilly-1-10-0`; none: the viewer's default)
 * @property {number} [frequency] gait frequency f (Hz), used without a brain (none: the core's default)
 * @property {number} [phase]    gait phase phi (rad per column), used without a brain (none: the core's default)
 * @property {Brain | null} brain  the controller that drives the body, or null for the gait
 * @property {string} [runFile]  a run file's JSON text: its best individual drives its own body
 *                               (`shape` '' or that body's rows), as `vsr evaluate` runs it
 * @property {number} [until]    seconds: the episode ends there, at the step `vsr evaluate`
 *                               ends an episode of that length (a race); none: it walks on
 * @property {number} [seconds]  the episode's length (s): its speed is measured over it, as a
 *                               fitness evaluation measures it; the robot walks on after it
 *                               (unless `until` stops it)
 * @property {Shift | false} [keepPlace] an edit of the walking robot: build it in the posture
 *                               and motion of the current one (its cells the current ones
 *                               shifted by the Shift), not at rest on the start line
 */

/**
 * @typedef {EpisodeParams & {terrain: string, frequency: number, phase: number}} LoadedParams  the
 *   parameters of the episode the worker runs ('loaded'): those asked, with the core's defaults
 *   for the terrain and the gait where none was given
 */

/**
 * @typedef {object} Shift  an edit of the body `from`, and how it moved the bounding box: a
 *                          cell (x, y) of the edited body (from the bottom left) was
 *                          (x - dx, y - dy) of `from`
 * @property {string} from  the rows of the body that was edited (the worker carries the pose
 *                          over only from a robot with these rows)
 * @property {number} dx
 * @property {number} dy
 */

/**
 * @typedef {object} Brain
 * @property {string} controller  'attention' | 'mlp' | 'mlp-comm', or one for any body: 'attention-any' | 'mlp-any' | 'mlp-comm-any'
 * @property {Float32Array} genome its parameters, for this body
 */

/**
 * @typedef {object} Frame
 * @property {number} time         simulated seconds
 * @property {number} voxels       number of voxels n
 * @property {number} centreX      mean x of voxel centres (m)
 * @property {number} centreY      mean y of voxel centres (m)
 * @property {number} velocity     mean forward speed so far (m/s), as fitness defines it
 * @property {boolean} frozen      the attention matrices are frozen ('freeze')
 * @property {number} distance     the centre's x since the start (m), as the fitness measures it
 * @property {number} episodeSpeed `velocity` at the end of the episode (`seconds`), the
 *                                 number `vsr evaluate` prints; NaN until the episode ended
 * @property {number} simPerWall   simulated s per wall s while running (achieved)
 * @property {number} simPerCompute simulated s per s spent inside `step` (engine speed)
 * @property {Float32Array} corners 8n floats, see the layout above
 * @property {Float32Array} areas   n floats
 * @property {Float32Array} bodies  12n floats
 * @property {Float32Array} attention 16n floats, or none
 */

/**
 * Checks that a frame's buffers have the documented lengths.
 * @param {Frame} frame
 * @returns {boolean}
 */
export function frameIsConsistent(frame) {
  const n = frame.voxels;
  return frame.corners.length === CORNER_FLOATS * n
    && frame.areas.length === AREA_FLOATS * n
    && frame.bodies.length === BODY_FLOATS * n
    && (frame.attention.length === 0 || frame.attention.length === ATTENTION_FLOATS * n);
}

/*
 * The core's answers (defaults, checks, transplant, remap) come from the core worker
 * (core-worker.js), asked through core.js with kit.js's requester: {id, name, args} ->
 * {id, value} or {id, error, fatal} (the classroom's measuring worker, classroom/lab-worker.js,
 * answers the same way).
 *
 * Evolution in the page: the page (runs/panel.js) drives a GA coordinator worker
 * (runs/coordinator.js), which owns the wasm `Evolution` and a pool of evaluation workers
 * (runs/evaluator.js), each owning its own wasm module.
 *
 * Page -> coordinator
 *   {type: 'start', settings, workers, source}
 *                                       begin a run of {@link EvolveSettings} with `workers`
 *                                       evaluation workers: from scratch (source null, as
 *                                       `vsr evolve`), or fine-tuning the best of the run file
 *                                       `source.text` (JSON text, as `vsr finetune --from`;
 *                                       of a body search's file, its body `source.entry`, as
 *                                       `--entry`, or its best for null); bad settings
 *                                       answer 'error'
 *   {type: 'pause'} / {type: 'resume'}  stop / go on handing out jobs (jobs under way finish)
 *   {type: 'step'}                      while paused: run one more generation, then pause
 *   {type: 'stop'}                      end the run now; the unfinished generation is dropped
 *   {type: 'run-file'}                  send the run so far ('run-file' answer)
 *   {type: 'crash-worker', index}       make evaluation worker `index` fail as if it crashed
 *                                       (for tests and demonstrations of the recovery)
 *
 * Coordinator -> page
 *   {type: 'started', planned, workers}  the run began; planned = evaluations it will take
 *   {type: 'generation', record, evaluations, planned, evalsPerSecond, best, top}
 *                                        a generation was told: record is the run file's
 *                                        generation record (null for non-finite values);
 *                                        best = {fitness, genome (Float32Array)} when its best
 *                                        beat every earlier generation's, else null; top =
 *                                        {fitness, genome} of this generation's best evaluation
 *                                        (kept by the page to race generations)
 *   {type: 'state', paused, stepping, underWay}
 *                                        pause state changed, or (underWay 0) the last
 *                                        evaluation under way when paused came back: it holds
 *   {type: 'run-file', runFile}          the run so far (JSON text, format 'vsr-run'), or null
 *   {type: 'recovered', message}         an evaluation worker died; a new one re-runs its job
 *   {type: 'done', stopped, runFile}     the run ended (budget spent, or stopped); runFile is
 *                                        null when not even generation 0 was told
 *   {type: 'error', message}             bad settings or a failed evaluation; the run ended
 *
 * Coordinator -> evaluator
 *   {type: 'job', slot, job, genome}     evaluate {@link EvolveJob} `job` with `genome`
 *                                        (Float32Array, transferred); slot = its job index
 *   {type: 'crash'}                      fail as a crash would (see 'crash-worker')
 * Evaluator -> coordinator
 *   {type: 'ready'}                      the wasm module is instantiated
 *   {type: 'result', slot, fitness}      fitness in m/s, NaN for an exploded episode
 *   {type: 'error', message}             the job was malformed, or wasm failed to load
 */

/** Message types sent by the page to the GA coordinator. */
export const ToCoordinator = Object.freeze({
  START: 'start',
  PAUSE: 'pause',
  RESUME: 'resume',
  STEP: 'step',
  STOP: 'stop',
  RUN_FILE: 'run-file',
  CRASH_WORKER: 'crash-worker',
});

/** Message types sent by the GA coordinator to the page. */
export const FromCoordinator = Object.freeze({
  STARTED: 'started',
  GENERATION: 'generation',
  STATE: 'state',
  RUN_FILE: 'run-file',
  RECOVERED: 'recovered',
  DONE: 'done',
  ERROR: 'error',
});

/** Message types between the coordinator and its evaluation workers. */
export const EvaluatorMessage = Object.freeze({
  JOB: 'job',
  CRASH: 'crash',
  READY: 'ready',
  RESULT: 'result',
  ERROR: 'error',
});

/**
 * What a fine-tuning run starts from (as `vsr finetune --from FILE [--entry I]`).
 * @typedef {object} FinetuneSource
 * @property {string} text          a run file, or a body search's file (JSON text)
 * @property {number | null} entry  the body of the body search's file (its archive entry), null: its best
 */

/**
 * A generation's record in a run file, as `Evolution.tell` returns it (non-finite values null).
 * @typedef {object} GenerationRecord
 * @property {number} generation   0: the initial population
 * @property {number} evaluations  so far, this generation included
 * @property {number | null} best  the best survivor's fitness (m/s)
 * @property {number | null} q3
 * @property {number | null} median
 * @property {number | null} q1
 * @property {number | null} worst
 * @property {number} wall_seconds
 */

/** @typedef {{fitness: number, genome: Float32Array}} Scored  a genome and its fitness (m/s) */

/**
 * A message from the page to the GA coordinator (the list above).
 * @typedef {{type: typeof ToCoordinator.START, settings: EvolveSettings, workers: number, source: FinetuneSource | null}
 *   | {type: typeof ToCoordinator.PAUSE}
 *   | {type: typeof ToCoordinator.RESUME}
 *   | {type: typeof ToCoordinator.STEP}
 *   | {type: typeof ToCoordinator.STOP}
 *   | {type: typeof ToCoordinator.RUN_FILE}
 *   | {type: typeof ToCoordinator.CRASH_WORKER, index: number}} ToCoordinatorMessage
 */

/**
 * A message from the GA coordinator to the page (the list above).
 * @typedef {{type: typeof FromCoordinator.STARTED, planned: number, workers: number}
 *   | {type: typeof FromCoordinator.GENERATION, record: GenerationRecord, evaluations: number, planned: number,
 *       evalsPerSecond: number, best: Scored | null, top: Scored}
 *   | {type: typeof FromCoordinator.STATE, paused: boolean, stepping: boolean, underWay: number}
 *   | {type: typeof FromCoordinator.RUN_FILE, runFile: string | null}
 *   | {type: typeof FromCoordinator.RECOVERED, message: string}
 *   | {type: typeof FromCoordinator.DONE, stopped: boolean, runFile: string | null}
 *   | {type: typeof FromCoordinator.ERROR, message: string}} FromCoordinatorMessage
 */

/**
 * A message from a coordinator to an evaluation worker (the list above).
 * @typedef {{type: typeof EvaluatorMessage.JOB, slot: number, job: EvolveJob, genome: Float32Array}
 *   | {type: typeof EvaluatorMessage.CRASH}} ToEvaluatorMessage
 */

/**
 * A message from an evaluation worker to its coordinator (the list above).
 * @typedef {{type: typeof EvaluatorMessage.READY}
 *   | {type: typeof EvaluatorMessage.RESULT, slot: number, fitness: number}
 *   | {type: typeof EvaluatorMessage.ERROR, message: string}} FromEvaluatorMessage
 */

/** A request to a worker that answers requests (kit.js: requester): `answers[name](...args)`. @typedef {{id: number, name: string, args: unknown[]}} Request */
/**
 * Its answer: the value, or why not in words (fatal: its wasm module crashed, a new worker must
 * take the next requests).
 * @typedef {{id: number, value: unknown} | {id: number, error: string, fatal: boolean}} Answer
 */

/**
 * Every worker by its file (relative to www/): the messages it is sent (`in`) and those it
 * posts (`out`). kit.js types both sides with it: `spawn(file, ...)` and `workerScope(file)`.
 * @typedef {{
 *   'workers/simulation-worker.js': {in: ToWorkerMessage, out: FromWorkerMessage},
 *   'runs/coordinator.js': {in: ToCoordinatorMessage, out: FromCoordinatorMessage},
 *   'runs/evaluator.js': {in: ToEvaluatorMessage, out: FromEvaluatorMessage},
 *   'codesign/coordinator.js': {in: import('./codesign-protocol.js').ToCodesignMessage,
 *     out: import('./codesign-protocol.js').FromCodesignMessage},
 *   'workers/core-worker.js': {in: Request, out: Answer},
 *   'classroom/lab-worker.js': {in: Request, out: Answer},
 * }} WorkerMessages
 */

/**
 * @typedef {object} EvolveSettings  a run's settings, the options of `vsr evolve` / `vsr finetune`
 * @property {string} shape       rows
 * @property {string} controller  'attention' | 'mlp' | 'mlp-comm' | 'attention-any' | 'mlp-any' | 'mlp-comm-any' (a fine-tuning run: its source's)
 * @property {number} seed        run seed, integer 0 .. 2^53 - 1
 * @property {number} seconds     simulated seconds per evaluation
 * @property {string} terrain     training terrain family (`hilly-1-10`) or name (`flat`)
 * @property {number} population  mu = lambda
 * @property {number} budget      evaluations
 */

/**
 * @typedef {object} EvolveJob  one evaluation, as `Evolution.ask()` describes it
 * @property {number} generation
 * @property {number} index       position in the generation (fitness goes back there)
 * @property {string} shape       rows
 * @property {string} controller
 * @property {string} terrain     full terrain name (`hilly-1-10-4821`)
 * @property {string} noiseSeed   sensor-noise seed, a decimal string (64 bits)
 * @property {number} seconds
 */

/** Largest number of evaluation workers the page starts. */
export const MAX_EVALUATORS = 16;
