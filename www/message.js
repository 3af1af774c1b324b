// @ts-check
/**
 * The one place where the page speaks to the person: a box fixed at the bottom of the screen
 * (so that it never moves what is being drawn on), with a close button. Errors and notes go
 * away by themselves after a while or at the next successful action; a validation message
 * stays while the drawing is not a robot; a 'lasting' message (a link that could not be
 * opened) stays until the person closes it or another message takes its place: clearing
 * passes it by. The core's category prefixes ("invalid input: ") are dropped: the sentence
 * after them says what is wrong.
 */

/** How long an error and a note stay up (ms). */
const ERROR_MS = 15_000;
const NOTE_MS = 6_000;

/** @typedef {'error' | 'note' | 'validation' | 'lasting'} Kind */

export class MessageBox {
  /** @param {HTMLElement} box @param {HTMLElement} text @param {HTMLButtonElement} close */
  constructor(box, text, close) {
    this.box = box;
    this.text = text;
    this.timer = 0;
    close.addEventListener('click', () => this.dismiss());
  }

  /** The close button: hides whatever is shown, a lasting message too. */
  dismiss() {
    window.clearTimeout(this.timer);
    this.text.textContent = '';
    this.box.hidden = true;
    this.box.dataset.kind = '';
  }

  /**
   * Shows `words` (a message, '' to clear) of a kind.
   * @param {string} words @param {Kind} [kind]
   */
  show(words, kind = 'error') {
    const sentence = plain(words);
    if (sentence === '' && this.kind === 'lasting') return; // only the person closes it
    window.clearTimeout(this.timer);
    this.text.textContent = sentence;
    this.box.hidden = sentence === '';
    this.box.dataset.kind = sentence === '' ? '' : kind;
    if (sentence !== '' && kind !== 'validation' && kind !== 'lasting') {
      this.timer = window.setTimeout(() => this.clear(), kind === 'note' ? NOTE_MS : ERROR_MS);
    }
  }

  /** Clears the message if it is of one of these kinds (all when none is given). @param {...Kind} kinds */
  clear(...kinds) {
    const kind = /** @type {Kind} */ (this.box.dataset.kind);
    if (kinds.length === 0 || kinds.includes(kind)) this.show('');
  }

  /** @returns {Kind | ''} the kind shown now */
  get kind() {
    return /** @type {Kind | ''} */ (this.box.dataset.kind ?? '');
  }
}

/** A message without the core's category prefix. @param {string} words */
export function plain(words) {
  return words.replace(/^(invalid input|invalid shape): /, '').trim();
}
