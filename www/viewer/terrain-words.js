// @ts-check
/**
 * A terrain the core refused, said in a student's words: what the usual terrains are, with
 * examples. The rule itself is the core's (crate/engine/src/simulation/terrain.rs, through the wasm
 * core's checkTerrain), whose exact words come with it, folded, for those who want them.
 * What the examples mean, as terrain.rs builds them: hilly-H-W-SEED is a random walk, a corner
 * about every W m, each one higher or lower than the last by a random amount of typical size H m;
 * steppy-H-W-SEED the same as flat runs with a step between them; SEED picks which random
 * ground; uphill-DEG and downhill-DEG a slope of DEG degrees.
 */

/**
 * @param {string} typed what was typed @param {string} rule why the core refused it, in its words
 * @returns {{words: string, detail: string}}
 */
export function terrainRefused(typed, rule) {
  return {
    words: `${typed.trim() ? `“${typed.trim()}” is not a terrain` : 'No terrain is typed'}. Try flat (level ground); hilly-1-10-0 (hills: about every 10 m the ground`
      + ' goes up or down by about 1 m; the last number picks one of many such grounds, and the same number always gives the'
      + ' same ground); steppy-1-10-0 (the same, in steps); uphill-10 or downhill-10 (a slope of 10°).',
    detail: rule.replace(/^invalid terrain: /, ''),
  };
}
