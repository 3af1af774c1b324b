// @ts-check
/**
 * Words for a class: the “Simple words” switch in the header hides formulas, statistics and
 * figures for the expert (elements marked `formula`, `stats` or `expert`; classroom.css), says a
 * label in plain words where it has them (`data-simple`: "f (Hz)" becomes "beats per second"),
 * and is kept in the browser; the
 * glossary's words are links where they appear (`a.term`), which open the glossary at their
 * entry, and links within the page (`a.jump`) scroll there without touching the address (its
 * `#...` is the share link's); and {@link withStats} marks a caption's statistics so that the switch can hide them.
 * In simple words a word the page cannot do without is explained where it appears: an element
 * with `data-explain` shows it after itself, in brackets (classroom.css; a glossary word's link
 * gets one from {@link EXPLAIN}); and the lines the page writes as it goes (the drawing's
 * status, the module's details, the speeds) are read by {@link simplify}, which marks in them
 * what a 14-year-old does not need (a drawing's rows as a code, evaluations per second: hidden)
 * and what needs a word (a terrain's name: the same hills every time, or new ones every walk).
 * Marking changes no text: the expert's view and its tests read the same words.
 */

import { byId } from './dom.js';

const KEY = 'vsr-playground/simple-words';

/** A parenthesis that holds a p-value: "(Holm p 0.017)", "(p 0.55; p: see the glossary)". */
const STATS = /\s*\([^()]*\bp\b[^()]*\)/g;

/**
 * Words of the glossary that text made by the page uses (captions, a task's answer, the gene
 * count), each with its entry in index.html's glossary: {@link withTerms} links them.
 */
const TERMS = {
  'see the glossary': 'g-p', Holm: 'g-p', 'mlp-comm': 'g-mlp', mlp: 'g-mlp', tanh: 'g-tanh', softmax: 'g-softmax',
  saturates: 'g-saturate', bias: 'g-network', weights: 'g-network', network: 'g-network', median: 'g-iqr',
};
/**
 * What a glossary word means, in a few words: said after it in simple words (its link's
 * `data-explain`), so that the word is explained where it appears, not only in the glossary.
 * @type {Partial<Record<keyof typeof TERMS, string>>}
 */
export const EXPLAIN = {
  bias: 'one more number, added in',
  weights: 'the numbers each reading is multiplied by',
  tanh: 'a squashing of any number into −1 to +1',
  softmax: 'a squashing into shares that add up to 1',
  saturates: 'sits at +1 or −1',
  median: 'the middle one',
  Holm: 'a correction for testing many pairs at once',
};

/** The terms as whole words, the longest first (mlp-comm before mlp). */
const TERM_WORDS = new RegExp(`(?<![\\w-])(${Object.keys(TERMS).sort((a, b) => b.length - a.length).join('|')})(?![\\w-])`, 'g');

/**
 * `text` as nodes, the first use of each glossary word ({@link TERMS}) a link to its entry.
 * @param {Document} doc @param {string} text @param {Set<string>} [done] words already linked (by an earlier part)
 * @returns {(string | HTMLElement)[]}
 */
export function withTerms(doc, text, done = new Set()) {
  /** @type {(string | HTMLElement)[]} */
  const out = [];
  let at = 0;
  for (const m of text.matchAll(TERM_WORDS)) {
    const id = TERMS[/** @type {keyof typeof TERMS} */ (m[1])];
    if (done.has(m[1])) continue;
    done.add(m[1]);
    out.push(text.slice(at, m.index));
    const a = doc.createElement('a');
    a.className = 'term';
    a.href = `#${id}`;
    a.textContent = m[1];
    const explain = EXPLAIN[/** @type {keyof typeof TERMS} */ (m[1])];
    if (explain) a.dataset.explain = explain;
    out.push(a);
    at = (m.index ?? 0) + m[1].length;
  }
  out.push(text.slice(at));
  return out.filter((x) => x !== '');
}

/**
 * `text` as nodes, each parenthesis holding a p-value in a `span.stats` (hidden in simple words),
 * the glossary's words linked ({@link withTerms}).
 * @param {Document} doc @param {string} text @returns {(string | HTMLElement)[]}
 */
export function withStats(doc, text) {
  /** @type {(string | HTMLElement)[]} */
  const out = [];
  const done = new Set();
  let at = 0;
  for (const m of text.matchAll(STATS)) {
    out.push(...withTerms(doc, text.slice(at, m.index), done));
    const span = doc.createElement('span');
    span.className = 'stats';
    span.append(...withTerms(doc, m[0], done));
    out.push(span);
    at = (m.index ?? 0) + m[0].length;
  }
  out.push(...withTerms(doc, text.slice(at), done));
  return out.filter((x) => x !== '');
}

/**
 * What {@link simplify} marks in a line the page writes: `hide` (a span.expert, gone in simple
 * words) or `explain` (a span with data-explain, its meaning said after it in simple words).
 * @type {{pattern: RegExp, hide?: true, explain?: string}[]}
 */
export const SIMPLER = [
  // A drawing as its rows of 1 and 0 (1111-1111-1001): the drawing on screen says it better.
  { pattern: /\s*\(rows [01]+(?:-[01]+)+\)|\s·\s[01]+(?:-[01]+)+(?=$|\s)/g, hide: true },
  // How many walks a second the computer measures: how long the run has left says what matters.
  { pattern: /\d[\d,.]* evaluations\/s(?: · )?/g, hide: true },
  // A terrain by its name: one ground, the same every time, or a family that draws new ground for every walk.
  { pattern: /\bhilly-\d+(?:\.\d+)?-\d+(?:\.\d+)?-\d+\b/g, explain: 'the same hills every time' },
  { pattern: /\bhilly-\d+(?:\.\d+)?-\d+(?:\.\d+)?(?![\d.-])/g, explain: 'new hills drawn for every walk' },
  { pattern: /\bsteppy-\d+(?:\.\d+)?-\d+(?:\.\d+)?-\d+\b/g, explain: 'the same steps every time' },
  // The phase gait's clock by its letters (unless the sentence says it already).
  { pattern: /φ(?!,? the delay| \(rad)/g, explain: 'the delay from column to column' },
  { pattern: /\bf(?= (?:and φ|\d[\d.]* Hz))/g, explain: 'beats per second' },
  // A brain's size: its genes, the numbers evolution tunes (unless a bracket after them says so).
  { pattern: /\b\d[\d,]* genes\b(?! \()/g, explain: 'the numbers evolution tunes' },
  { pattern: /\bone-shot\b/gi, explain: 'before any training on its new body' },
  { pattern: /\bfine-tun(?:e|ed|ing)\b(?! \()/gi, explain: 'trained a little more for the new body' },
  { pattern: /\bquartiles?\b/g, explain: 'the edges of the middle half of the runs' },
  { pattern: /\bon \d+ workers?\b/g, explain: 'parts of this computer walking brains at the same time' },
  // The three speeds of a brain: which one is your robot's, and what the other two are.
  { pattern: /\bYour robot's speed(?=: )/g, explain: 'the one that counts: your short code and the class ranking use it' },
  { pattern: /\bIn training(?=: )/g, explain: 'how fast it walked while it learned, on other hills: not your robot\'s speed' },
  { pattern: /“Best so far”/g, explain: 'its one fastest walk while it learned' },
  // The matrix's expert names for its rows and columns: its plain words stand beside them.
  { pattern: /\s\((?:query|key)\)/g, hide: true },
];

/**
 * Marks, in the text of `el`, now and whenever the page writes it again, what {@link SIMPLER}
 * names (and `more`, rules for this element only): wraps each match in a span (hidden, or
 * explained, in simple words). The text itself (textContent) stays as written.
 * @param {HTMLElement} el @param {typeof SIMPLER} [more]
 */
export function simplify(el, more = []) {
  const rules = [...more, ...SIMPLER];
  const doc = el.ownerDocument;
  const mark = () => {
    const walk = doc.createTreeWalker(el, NodeFilter.SHOW_TEXT);
    /** @type {Text[]} */
    const texts = [];
    while (walk.nextNode()) {
      const node = /** @type {Text} */ (walk.currentNode);
      if (!node.parentElement?.closest('.simpler, option, select, textarea')) texts.push(node);
    }
    // A word is explained once in an element: the first time it appears there.
    const explained = new Set([...el.querySelectorAll('.simpler[data-explain]')].map((e) => /** @type {HTMLElement} */ (e).dataset.explain));
    for (const node of texts) {
      const text = node.data;
      /** @type {{at: number, end: number, rule: typeof SIMPLER[number]}[]} */
      const found = [];
      for (const rule of rules) {
        for (const m of text.matchAll(rule.pattern)) {
          const at = m.index ?? 0;
          if (!m[0] || found.some((f) => at < f.end && at + m[0].length > f.at)) continue;
          if (rule.explain && explained.has(rule.explain)) continue;
          if (rule.explain) explained.add(rule.explain);
          found.push({ at, end: at + m[0].length, rule });
        }
      }
      if (found.length === 0) continue;
      found.sort((a, b) => a.at - b.at);
      /** @type {(string | HTMLElement)[]} */
      const parts = [];
      let at = 0;
      for (const f of found) {
        parts.push(text.slice(at, f.at));
        const span = doc.createElement('span');
        span.className = f.rule.hide ? 'simpler expert' : 'simpler';
        if (f.rule.explain) span.dataset.explain = f.rule.explain;
        span.textContent = text.slice(f.at, f.end);
        parts.push(span);
        at = f.end;
      }
      parts.push(text.slice(at));
      node.replaceWith(...parts.filter((x) => x !== ''));
    }
  };
  const seen = new MutationObserver(() => {
    seen.disconnect();
    mark();
    seen.observe(el, { childList: true, characterData: true, subtree: true });
  });
  mark();
  seen.observe(el, { childList: true, characterData: true, subtree: true });
}

/** Wires the switch and the glossary links. @param {Document} doc */
export function wireWords(doc) {
  const box = byId(doc, 'simple-words', HTMLInputElement);
  const set = (/** @type {boolean} */ on) => {
    if (on) doc.documentElement.dataset.words = 'simple'; else delete doc.documentElement.dataset.words;
    for (const el of doc.querySelectorAll('[data-simple]')) {
      if (!(el instanceof HTMLElement)) continue;
      el.dataset.expert ??= el.textContent ?? '';
      el.textContent = on ? el.dataset.simple ?? '' : el.dataset.expert;
    }
  };
  let kept = false;
  try { kept = localStorage.getItem(KEY) === '1'; } catch { /* storage off: the switch starts off */ }
  box.checked = kept;
  set(kept);
  box.addEventListener('change', () => {
    set(box.checked);
    try { localStorage.setItem(KEY, box.checked ? '1' : '0'); } catch { /* not kept */ }
  });
  // The address's #... is the share link's, so a link within the page scrolls without changing it.
  doc.addEventListener('click', (event) => {
    const link = /** @type {HTMLElement} */ (event.target)?.closest?.('a.term, a.jump');
    if (!(link instanceof HTMLAnchorElement)) return;
    const entry = doc.getElementById(link.hash.slice(1));
    if (!entry) return;
    event.preventDefault();
    const glossary = byId(doc, 'glossary', HTMLDetailsElement);
    if (glossary.contains(entry)) glossary.open = true;
    entry.scrollIntoView({ block: link.classList.contains('term') ? 'center' : 'start' });
    entry.classList.add('term-shown');
    setTimeout(() => entry.classList.remove('term-shown'), 2000);
  });
}
