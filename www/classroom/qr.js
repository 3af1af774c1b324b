// @ts-check
/**
 * A QR code of a link, for the projector: a phone's camera or a laptop's opens the link without
 * typing it. The code is made by uqr (an npm library: scripts/serve.mjs serves it at
 * /vendor/uqr.js, `make site` copies it into the site) and drawn as an SVG of black squares on
 * a white border, sharp at any size; "Show large" puts it over the whole screen, with the link
 * in words under it, until Close or Escape. uqr is fetched when a code is first wanted (only the
 * teacher's boxes show one: {@link loadQr} when one opens), not with the page's first screen.
 */

import { ONLY_HERE, onlyHere } from './sheet-address.js';

const SVG = 'http://www.w3.org/2000/svg';

/** @typedef {typeof import('../vendor/uqr.js').encode} Encode */
/** uqr, once asked for. @type {Promise<Encode> | null} */
let library = null;
/** uqr's encoder, once it is here. @type {Encode | null} */
let encoder = null;

/** Fetches uqr (once), so that the codes a teacher's box makes are drawn at once. @returns {Promise<Encode>} */
export function loadQr() {
  library ??= import('../vendor/uqr.js').then((m) => { encoder = m.encode; return m.encode; });
  return library;
}

/**
 * The QR code of `text` as an SVG element, `size` CSS pixels wide: drawn at once when uqr is
 * here, else as soon as it is (the element is the same).
 * @param {Document} doc @param {string} text @param {number} size @returns {SVGSVGElement}
 */
export function qrSvg(doc, text, size) {
  const svg = /** @type {SVGSVGElement} */ (doc.createElementNS(SVG, 'svg'));
  svg.setAttribute('width', String(size));
  svg.setAttribute('height', String(size));
  svg.setAttribute('shape-rendering', 'crispEdges');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', `QR code of ${text}`);
  const draw = (/** @type {Encode} */ encode) => {
    const { data } = encode(text, { ecc: 'M', border: 4 });
    const n = data.length;
    svg.setAttribute('viewBox', `0 0 ${n} ${n}`);
    const back = doc.createElementNS(SVG, 'rect');
    back.setAttribute('width', String(n));
    back.setAttribute('height', String(n));
    back.setAttribute('fill', '#fff');
    let d = '';
    data.forEach((row, y) => row.forEach((dark, x) => { if (dark) d += `M${x} ${y}h1v1h-1z`; }));
    const dots = doc.createElementNS(SVG, 'path');
    dots.setAttribute('d', d);
    dots.setAttribute('fill', '#000');
    svg.replaceChildren(back, dots);
  };
  if (encoder) draw(encoder);
  else loadQr().then(draw, () => svg.setAttribute('aria-label', `The QR code could not be drawn; the link: ${text}`));
  return svg;
}

/**
 * A small QR code of `link` with a "Show large" button that shows it over the whole screen.
 * @param {Document} doc @param {string} link @param {string} what what the link opens, in words (the large view's title)
 * @returns {HTMLElement}
 */
export function qrBox(doc, link, what) {
  const box = doc.createElement('div');
  box.className = 'qr-box';
  box.dataset.testid = 'qr';
  box.dataset.link = link;
  const large = doc.createElement('button');
  large.type = 'button';
  large.textContent = 'Show large (for the projector)';
  large.dataset.testid = 'qr-large';
  large.addEventListener('click', () => showLarge(doc, link, what));
  box.append(qrSvg(doc, link, 132), large);
  return box;
}

/**
 * The QR code over the whole screen, the link in words under it, and a warning when the link
 * opens only on this computer (as the small view's note says it). @param {Document} doc @param {string} link @param {string} what
 */
function showLarge(doc, link, what) {
  doc.querySelector('.qr-large')?.remove();
  const view = doc.createElement('div');
  view.className = 'qr-large';
  view.dataset.testid = 'qr-large-view';
  view.setAttribute('role', 'dialog');
  view.setAttribute('aria-label', what);
  const title = doc.createElement('h2');
  title.textContent = what;
  const words = doc.createElement('p');
  words.className = 'qr-large-link';
  words.textContent = link;
  const close = doc.createElement('button');
  close.type = 'button';
  close.textContent = 'Close';
  const side = Math.max(160, Math.min(innerWidth, innerHeight) - 220);
  view.append(title, qrSvg(doc, link, side), words);
  if (onlyHere(link)) {
    const note = doc.createElement('p');
    note.className = 'qr-large-note';
    note.dataset.testid = 'qr-large-note';
    note.textContent = `${ONLY_HERE}: your students cannot open it.`;
    view.append(note);
  }
  view.append(close);
  const end = () => { view.remove(); doc.removeEventListener('keydown', onKey); };
  const onKey = (/** @type {KeyboardEvent} */ e) => { if (e.key === 'Escape') end(); };
  close.addEventListener('click', end);
  doc.addEventListener('keydown', onKey);
  doc.body.append(view);
  close.focus();
}
