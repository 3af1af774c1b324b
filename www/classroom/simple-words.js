// @ts-check
/**
 * Words for a class: the “Simple words” switch in the header hides formulas and statistics
 * (elements marked `formula` or `stats`; classroom.css), and is kept in the browser; the
 * glossary's words are links where they appear (`a.term`), which open the glossary at their
 * entry, and links within the page (`a.jump`) scroll there without touching the address (its
 * `#...` is the share link's); and {@link withStats} marks a caption's statistics so that the switch can hide them.
 */

const KEY = 'vsr-playground/simple-words';

/** A parenthesis that holds a p-value: "(Holm p 0.017)", "(p 0.55; p: see the glossary)". */
const STATS = /\s*\([^()]*\bp\b[^()]*\)/g;

/**
 * `text` as nodes, each parenthesis holding a p-value in a `span.stats` (hidden in simple words).
 * @param {Document} doc @param {string} text @returns {(string | HTMLElement)[]}
 */
export function withStats(doc, text) {
  /** @type {(string | HTMLElement)[]} */
  const out = [];
  let at = 0;
  for (const m of text.matchAll(STATS)) {
    out.push(text.slice(at, m.index));
    const span = doc.createElement('span');
    span.className = 'stats';
    span.textContent = m[0];
    out.push(span);
    at = (m.index ?? 0) + m[0].length;
  }
  out.push(text.slice(at));
  return out.filter((x) => x !== '');
}

/** Wires the switch and the glossary links. @param {Document} doc */
export function wireWords(doc) {
  const box = /** @type {HTMLInputElement | null} */ (doc.getElementById('simple-words'));
  const set = (/** @type {boolean} */ on) => {
    if (on) doc.documentElement.dataset.words = 'simple'; else delete doc.documentElement.dataset.words;
  };
  if (box) {
    let kept = false;
    try { kept = localStorage.getItem(KEY) === '1'; } catch { /* storage off: the switch starts off */ }
    box.checked = kept;
    set(kept);
    box.addEventListener('change', () => {
      set(box.checked);
      try { localStorage.setItem(KEY, box.checked ? '1' : '0'); } catch { /* not kept */ }
    });
  }
  // The address's #... is the share link's, so a link within the page scrolls without changing it.
  doc.addEventListener('click', (event) => {
    const link = /** @type {HTMLElement} */ (event.target)?.closest?.('a.term, a.jump');
    if (!(link instanceof HTMLAnchorElement)) return;
    const entry = doc.getElementById(link.hash.slice(1));
    if (!entry) return;
    event.preventDefault();
    const glossary = /** @type {HTMLDetailsElement | null} */ (doc.getElementById('glossary'));
    if (glossary && glossary.contains(entry)) glossary.open = true;
    entry.scrollIntoView({ block: link.classList.contains('term') ? 'center' : 'start' });
    entry.classList.add('term-shown');
    setTimeout(() => entry.classList.remove('term-shown'), 2000);
  });
}
