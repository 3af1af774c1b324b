// @ts-check
/**
 * The page's one element lookup: the element with an id, of the kind the code uses it as, or an
 * Error that names what is missing. index.html and the code that wires it can drift apart (an
 * id renamed, an <input> made a <select>); this says so where the element is looked up, not
 * later as "cannot read properties of null" somewhere else.
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
