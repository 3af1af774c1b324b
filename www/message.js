// @ts-check
/**
 * The one place where the page speaks to the person: a list fixed at the bottom of the screen
 * (so that it never moves what is being drawn on), each message with its own close button.
 * - An error (bad input, a dying worker, a failed request, a link that could not be opened)
 *   stays until the person closes it: no timer, no later success and no other message takes
 *   it away. The same error said again is shown once, as the newest.
 * - A note ("Link copied") goes away by itself after a while; a newer note replaces it.
 * - The validation message (the drawing is not a robot yet) stays while that is so: the
 *   drawing's check replaces or clears it.
 * The core's category prefixes ("invalid input: ") are dropped: the sentence after them says
 * what is wrong.
 */

/** How long a note stays up (ms). */
const NOTE_MS = 6_000;

/** @typedef {'error' | 'note' | 'validation'} Kind */

export class MessageBox {
  /** @param {HTMLElement} box the list of messages, hidden while empty */
  constructor(box) {
    this.box = box;
    /** @type {Map<HTMLElement, number>} the notes' timers */
    this.timers = new Map();
  }

  /**
   * Shows `words` (nothing when empty) of a kind.
   * @param {string} words @param {Kind} [kind]
   */
  show(words, kind = 'error') {
    const sentence = plain(words);
    if (kind !== 'error') this.clear(kind); // one note, one validation message at a time
    if (sentence === '') return;
    for (const old of this.entries()) {
      if (old.dataset.kind === kind && old.firstChild?.textContent === sentence) this.remove(old);
    }
    const entry = document.createElement('p');
    entry.className = 'message';
    entry.dataset.kind = kind;
    entry.setAttribute('role', kind === 'note' ? 'status' : 'alert');
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
    this.box.append(entry);
    this.box.hidden = false;
    if (kind === 'note') this.timers.set(entry, window.setTimeout(() => this.remove(entry), NOTE_MS));
  }

  /** Takes away the notes or the validation message (errors only go by their close button). @param {'note' | 'validation'} kind */
  clear(kind) {
    for (const entry of this.entries()) if (entry.dataset.kind === kind) this.remove(entry);
  }

  /** @returns {HTMLElement[]} the messages shown, oldest first */
  entries() {
    return /** @type {HTMLElement[]} */ ([...this.box.children]);
  }

  /** @param {HTMLElement} entry */
  remove(entry) {
    window.clearTimeout(this.timers.get(entry));
    this.timers.delete(entry);
    entry.remove();
    this.box.hidden = this.box.children.length === 0;
  }
}

/** A message without the core's category prefix. @param {string} words */
export function plain(words) {
  return words.replace(/^(invalid input|invalid shape): /, '').trim();
}
