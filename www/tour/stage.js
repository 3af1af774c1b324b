// @ts-check
/**
 * Sets the playground up as a chapter says (chapters.js), with the page's own functions
 * (main.js hands them over as a {@link Playground}; nothing here simulates, transplants or
 * draws): stops a run under way, sets the terrain, the phase gait, the run settings, the body
 * and its brain (the study's brain for any body, when the chapter asks for it and pretrained/ has it), the race and the
 * body search's brain; then waits until the viewer walks exactly that robot.
 */
import { messageOf } from '../workers/kit.js';

/** Longest wait for the viewer to walk the chapter's robot (ms). */
const WALK_TIMEOUT_MS = 10_000;

/**
 * @typedef {object} Playground  the page's functions the tour uses (main.js)
 * @property {import('../workers/core.js').Defaults} defaults
 * @property {() => boolean} running                 a run uses the robot
 * @property {() => Promise<void>} stopRun            stops it; resolves once stopped
 * @property {(rows: string) => Promise<void>} setBody  draws rows, driven by the phase gait
 * @property {(key: string, label?: string, short?: string) => Promise<import('../modules/modules.js').Module>} module  reads and
 *   chooses a module (one not listed yet is added under `label`, shown as `short`: modules/modules.js, read)
 * @property {(module: import('../modules/modules.js').Module) => Promise<void>} openModule   on its own body
 * @property {(module: import('../modules/modules.js').Module) => Promise<void>} loadModule   onto the drawn body
 * @property {() => Promise<string>} studyAnyBody  the study's brain for any body: its key once pretrained/ is listed ('' while
 *   the study still trains it)
 * @property {(terrain: string, gait: {frequency: number, phase: number}) => void} setView
 * @property {(values: Record<string, string>, compare: boolean) => void} setRun
 * @property {(kind: string) => Promise<unknown>} setController
 * @property {() => import('../workers/protocol.js').EpisodeParams | null} wanted  the episode the page asked the viewer for last
 * @property {() => import('../workers/protocol.js').EpisodeParams | null} walking  the episode the viewer walks now
 * @property {import('../viewer/race.js').Race} race
 * @property {(settings: {brain: string, from: string}) => void} setCodesign  the body search's brain and start body
 * @property {(on: boolean) => void} quietModules  whether the module list keeps its speeds back (a question waits)
 * @property {(on: boolean) => void} holdAtEpisodeEnd  whether the walk holds when its episode ends (the tour: what is
 *   measured is what is seen)
 * @property {(text: string) => void} message
 */

/**
 * Sets the playground up for `chapter`; resolves once the viewer walks its robot.
 * @param {Playground} page @param {import('./chapters.js').Chapter} chapter
 */
export async function stage(page, chapter) {
  const { setup } = chapter;
  if (page.running()) await page.stopRun();
  page.setView(setup.terrain, setup.gait ?? page.defaults.gait);
  if (setup.run) page.setRun(setup.run, setup.compare ?? false);
  const brain = setup.brain ? await page.module(setup.brain.module) : null;
  if (setup.rows !== null && setup.brain?.on !== 'own') await page.setBody(setup.rows);
  if (setup.controller) await page.setController(setup.controller);
  if (brain && setup.brain?.on === 'own') await page.openModule(brain);
  if (brain && setup.brain?.on === 'drawn') await page.loadModule(brain);
  const anyBody = setup.anyBody ? await page.studyAnyBody() : '';
  if (anyBody) await page.loadModule(await page.module(anyBody));
  if (setup.race) await race(page, setup.race);
  if (setup.codesign) page.setCodesign(setup.codesign);
  await walking(page);
}

/** Empties the race and enters `keys` (modules on their own bodies). @param {Playground} page @param {string[]} keys */
async function race(page, keys) {
  page.race.clear();
  for (const key of keys) {
    try {
      await page.race.addRunFile(await page.module(key));
    } catch (error) {
      page.message(`could not race ${key}: ${messageOf(error)}`);
    }
  }
}

/** Resolves once the viewer walks the episode the page asked for last. @param {Playground} page */
function walking(page) {
  const wanted = page.wanted();
  const since = performance.now();
  return new Promise((resolve, reject) => {
    const look = () => {
      if (sameEpisode(page.walking(), wanted)) resolve(undefined);
      else if (performance.now() - since > WALK_TIMEOUT_MS) reject(new Error('the robot did not start walking'));
      else requestAnimationFrame(look);
    };
    look();
  });
}

/**
 * Whether two episodes walk the same robot: body, terrain, brain (bit for bit).
 * @param {ReturnType<Playground['walking']>} a @param {ReturnType<Playground['walking']>} b
 */
export function sameEpisode(a, b) {
  if (!a || !b || a.shape !== b.shape || a.terrain !== b.terrain) return false;
  if (!a.brain || !b.brain) return a.brain === b.brain;
  const [x, y] = [a.brain.genome, b.brain.genome];
  return a.brain.controller === b.brain.controller && x.length === y.length && x.every((g, i) => Object.is(g, y[i]));
}
