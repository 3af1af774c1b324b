// @ts-check
/**
 * How the page writes numbers, the one place for it: counts grouped by thousands (30,000),
 * decimals with the minus sign (−2.8, not -2.8; never −0.00), a value's sign spelled out when it
 * matters (+0.71), and sizes with the times sign (3 × 3). What a file or a link carries (CSV,
 * run files, share links, data-value) keeps plain ASCII numbers: only the words on screen use
 * these.
 */

/** The minus sign U+2212 (a hyphen is a dash, not a minus). */
export const MINUS = '\u2212';

/** What a number that is not there reads as. */
export const NONE = '–';

/** A count, grouped by thousands: 30,000. @param {number} n */
export function count(n) {
  return Number.isFinite(n) ? n.toLocaleString('en') : NONE;
}

/**
 * A number as short as it goes, for an axis or a ruler: at most `digits` decimals (no trailing
 * zeros), grouped by thousands, with the minus sign: 30,000, 0.5, −10. @param {number} v @param {number} [digits]
 */
export function plainNumber(v, digits = 2) {
  if (!Number.isFinite(v)) return NONE;
  const text = v.toLocaleString('en', { maximumFractionDigits: digits });
  return text === '-0' ? '0' : text.replace('-', MINUS);
}

/**
 * A decimal with `digits` digits and the minus sign; one that rounds to zero is 0 (not −0.00);
 * not a number: –. @param {number | null | undefined} v @param {number} [digits]
 */
export function decimal(v, digits = 2) {
  if (v === null || v === undefined || !Number.isFinite(v)) return NONE;
  const text = v.toFixed(digits);
  return /^-0\.?0*$/.test(text) ? text.slice(1) : text.replace('-', MINUS);
}

/** A decimal with its sign always written: +0.71, −0.71. @param {number} v @param {number} [digits] */
export function signed(v, digits = 2) {
  const text = decimal(v, digits);
  return text === NONE || text.startsWith(MINUS) ? text : `+${text}`;
}

/** A size in cells or voxels, width by height: 3 × 3. @param {number} width @param {number} height */
export function size(width, height) {
  return `${width} × ${height}`;
}
