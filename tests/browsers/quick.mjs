// @ts-check
/**
 * The quick evolution as a visitor starts it, in any browser (a {@link import('./tab.mjs').Tab}):
 * the default biped, *Quick settings*, *Evolve* on the default workers; how long the page said
 * it would take before it started, and how long it took (the page's own clock, from the click
 * to "finished"). `make test-browsers` prints it for Firefox and WebKitGTK (checks.mjs);
 * docs/playground.md quotes it.
 */
import { waitFor } from './tab.mjs';

/**
 * Runs the quick evolution in the page open in `tab` (the default robot walking).
 * @param {import('./tab.mjs').Tab} tab
 * @returns {Promise<{estimate: string, estimated: number, took: number, evaluations: number, workers: number, rate: number, said: string}>}
 *   the estimate in words and in seconds, the seconds it took, its evaluations, workers and
 *   evaluations per second, and what the page said when it ended (its pace, how long it took)
 */
export async function quickEvolution(tab) {
  const said = () => {
    const out = document.getElementById('run-estimate');
    return out && !out.hidden && out.textContent ? out.textContent : '';
  };
  // The page measures this computer's speed in its first seconds, then says how long a run will take.
  await waitFor(tab, said, undefined, 'an estimate of the quick run before it starts', 60_000);
  await tab.click('#run-quick');
  await new Promise((resolve) => setTimeout(resolve, 1_500)); // the estimate follows the form every second
  const estimate = await tab.run(said, undefined);
  const estimated = await tab.run(() => Number(document.getElementById('run-estimate')?.dataset.value), undefined);
  const workers = await tab.run(() => Number(/** @type {HTMLInputElement} */ (document.getElementById('run-workers')).value), undefined);
  await tab.run(() => {
    /** @type {any} */ (window).quickStarted = performance.now();
    document.getElementById('run-evolve')?.click();
  }, undefined);
  const took = await waitFor(tab, () => (document.body.dataset.run === 'finished'
    ? (performance.now() - /** @type {any} */ (window).quickStarted) / 1000 : 0), undefined, 'the quick evolution to finish', 900_000);
  const [evaluations, rate, after] = await tab.run(() => [Number(document.getElementById('run-evaluations')?.dataset.value),
    Number(document.getElementById('run-rate')?.dataset.value), document.getElementById('run-rate')?.textContent ?? ''], undefined);
  return { estimate, estimated, took, evaluations, workers, rate, said: after };
}
