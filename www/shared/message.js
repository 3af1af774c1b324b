// @ts-check
/**
 * The one place where the page speaks to the person: a list in the page's flow under its
 * header (so that it covers no control), each message with its own close button.
 * - An error stays until the person closes it: no timer takes it away. The same error said
 *   again is shown once, as the newest.
 * - An error about an input has a source ('rows', 'run-settings', 'import', ...): a newer
 *   message from that source replaces it, and it goes once that input is valid (drop). Errors
 *   without a source (a crashed worker, a damaged link) only go by their close button. A source
 *   may have a place of its own (a typed field's, right under it: typed-field.js). An error may
 *   carry its exact rule, folded under it for those who want it.
 * - A note ("Link copied") goes away by itself after a while; a newer note replaces it.
 * - A pinned note (a challenge's rules) looks like a note and stays until it is closed.
 * - The validation message (the drawing is not a robot yet) stays while that is so: the
 *   drawing's check replaces or clears it. It is shown under the drawing grid, so that its
 *   coming and going never moves the grid being drawn on.
 * The core's category prefixes ("invalid input: ") are dropped: the sentence after them says
 * what is wrong.
 */

/** How long a note stays up (ms). */
const NOTE_MS = 6_000;

/** @typedef {'error' | 'note' | 'pinned' | 'validation'} Kind */

export class MessageBox {
  /**
   * @param {HTMLElement} box the list of messages, hidden while empty (its room is kept)
   * @param {HTMLElement} [drawingBox] where the validation message goes (else in `box`)
   */
  constructor(box, drawingBox = box) {
    this.box = box;
    this.drawingBox = drawingBox;
    /** @type {Map<HTMLElement, number>} the notes' timers */
    this.timers = new Map();
    /** @type {Map<string, HTMLElement>} the sources whose errors have a place of their own */
    this.places = new Map();
  }

  /** Errors of `source` go in `box` from now on (a typed field's own, next to it). @param {string} source @param {HTMLElement} box */
  place(source, box) {
    this.places.set(source, box);
  }

  /**
   * Shows `words` (nothing when empty) of a kind, in place of the message of its source.
   * @param {string} words @param {Kind} [kind] @param {string} [source] the input it is about
   * @param {string} [detail] the exact rule, folded under the words
   */
  show(words, kind = 'error', source, detail) {
    const sentence = plain(words);
    if (kind !== 'error') this.clear(kind); // one note, one pinned note, one validation message at a time
    if (source) this.drop(source);
    if (sentence === '') return;
    for (const old of this.entries()) {
      if (old.dataset.kind === kind && old.firstChild?.textContent === sentence) this.remove(old);
    }
    const entry = document.createElement('div');
    entry.className = 'message';
    entry.dataset.kind = kind;
    if (source) entry.dataset.source = source;
    entry.setAttribute('role', kind === 'note' || kind === 'pinned' ? 'status' : 'alert');
    const text = document.createElement('span');
    text.textContent = sentence;
    const close = document.createElement('button');
    close.type = 'button';
    close.className = 'message-close';
    close.dataset.testid = 'message-close';
    close.title = 'Dismiss';
    close.setAttribute('aria-label', 'Dismiss this message');
    close.textContent = '\u00d7';
    close.addEventListener('click', () => this.remove(entry));
    entry.append(text, close);
    if (detail) {
      const more = document.createElement('details');
      const summary = document.createElement('summary');
      summary.textContent = 'The exact rule';
      more.append(summary, detail);
      entry.append(more);
    }
    const box = kind === 'validation' ? this.drawingBox : (source && this.places.get(source)) || this.box;
    box.append(entry);
    box.hidden = false;
    // An error under its field: the least scroll that shows it all (the field, just above it, stays in view).
    if (kind === 'error' && box !== this.box) entry.scrollIntoView({ block: 'nearest' });
    // Another said while the person is further down the page: brought into view to be read.
    else if (kind === 'error' && box.getBoundingClientRect().bottom < 0) box.scrollIntoView({ block: 'nearest' });
    if (kind === 'note') this.timers.set(entry, window.setTimeout(() => this.remove(entry), NOTE_MS));
  }

  /**
   * Takes away the notes, the pinned note or the validation message (errors only go by their
   * close button). @param {Exclude<Kind, 'error'>} kind
   */
  clear(kind) {
    for (const entry of this.entries()) if (entry.dataset.kind === kind) this.remove(entry);
  }

  /** Takes away the message of `source` (its input is valid now). @param {string} source */
  drop(source) {
    for (const entry of this.entries()) if (entry.dataset.source === source) this.remove(entry);
  }

  /** @returns {HTMLElement[]} the messages shown, oldest first */
  entries() {
    const boxes = [...new Set([this.box, this.drawingBox, ...this.places.values()])];
    return /** @type {HTMLElement[]} */ (boxes.flatMap((b) => [...b.children]));
  }

  /** @param {HTMLElement} entry */
  remove(entry) {
    window.clearTimeout(this.timers.get(entry));
    this.timers.delete(entry);
    const box = entry.parentElement;
    entry.remove();
    if (box) box.hidden = box.children.length === 0;
  }
}

/** A message without the core's category prefix. @param {string} words */
export function plain(words) {
  return words.replace(/^(invalid input|invalid shape): /, '').trim();
}
