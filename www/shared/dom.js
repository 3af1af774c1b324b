// @ts-check
/**
 * The page's one element lookup: the element with an id, of the kind the code uses it as, or an
 * Error that names what is missing. index.html and the code that wires it can drift apart (an
 * id renamed, an <input> made a <select>); this says so where the element is looked up, not
 * later as "cannot read properties of null" somewhere else. And its one way to make an element
 * with a class and a text.
 */

/**
 * The element `#id` of `root`, which must exist and be a `type` (HTMLElement when none is
 * given); otherwise it throws an Error naming the id.
 * @template {Element} [T=HTMLElement]
 * @param {Document | DocumentFragment} root the page's document (or a shadow root, a fragment)
 * @param {string} id
 * @param {abstract new (...args: any[]) => T} [type] HTMLInputElement, HTMLSelectElement, ...
 * @returns {T}
 */
export function byId(root, id, type) {
  const found = root.getElementById(id);
  if (!found) throw new Error(`the page has no #${id}`);
  const want = type ?? /** @type {abstract new (...args: any[]) => T} */ (/** @type {unknown} */ (HTMLElement));
  if (!(found instanceof want)) throw new Error(`#${id} is a <${found.localName}>, not an ${want.name}`);
  return found;
}

/**
 * Calls `show` once, the first time `el` comes within `margin` (above or below) of the screen:
 * for what the page fetches only when someone can see it, not at start (the study's tables and
 * figures; issue 46). An element hidden (display: none) is not near: it waits until it shows.
 * @param {Element} el @param {() => void} show @param {string} [margin] a CSS length, e.g. '300px'
 */
export function whenNear(el, show, margin = '0px') {
  let done = false;
  const seen = new IntersectionObserver((entries) => {
    if (done || !entries.some((e) => e.isIntersecting)) return;
    done = true;
    seen.disconnect();
    show();
  }, { rootMargin: `${margin} 0px ${margin} 0px` });
  seen.observe(el);
}

/**
 * A new `tag` element of `doc`, with `className` and `text` when given.
 * @param {Document} doc @param {string} tag @param {string} [className] @param {string} [text]
 * @returns {HTMLElement}
 */
export function make(doc, tag, className, text) {
  const el = doc.createElement(tag);
  if (className) el.className = className;
  if (text !== undefined) el.textContent = text;
  return el;
}
