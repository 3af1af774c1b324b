// @ts-check
/**
 * A text field the person types into and the page checks before using it: the drawing's rows,
 * the viewer's terrain. What the page uses is the field's accepted text (`value`): the last
 * one it accepted, typed or written there by the page. Typed text that is refused stays in the
 * field, to be corrected, marked (aria-invalid, drawn in red), and is said in a message right
 * under the field, so that it is read where the person looks and the page does not move away
 * from the field (on a phone too). That message stays until it is closed, replaced by the next
 * one about the field, or the field holds a valid value again: typed and accepted, or written
 * there by the page through this field's `value` (a stroke on the grid, a preset, Undo, a
 * tour's chapter, a link), since the page writes into the field only what it uses. The page
 * writes through `value` only, never into the input itself.
 */

/** Why a text is refused: words, or words and the exact rule (folded under them). @typedef {string | {words: string, detail: string}} Refusal */

export class TypedField {
  /**
   * @param {HTMLInputElement} input
   * @param {import('./message.js').MessageBox} messages
   * @param {{problem: (text: string) => Refusal | Promise<Refusal>, use: (text: string) => void}} rule
   *   problem: '' when the text can be used, else why not (it changes nothing); use: uses an accepted text
   */
  constructor(input, messages, rule) {
    this.input = input;
    this.messages = messages;
    this.rule = rule;
    this.source = input.id;
    /** The text the page uses. */
    this.accepted = input.value;
    /** Counts what happened to the field: a check's answer counts only if nothing happened since it was asked. */
    this.ticket = 0;
    /** @type {((text: string) => void)[]} called with each accepted text typed, after `use` */
    this.listeners = [];
    const box = document.createElement('div');
    box.id = `${input.id}-message`;
    box.className = 'messages field-message';
    box.dataset.testid = box.id;
    box.setAttribute('role', 'region');
    box.setAttribute('aria-label', `About the ${input.id} typed`);
    box.hidden = true;
    (input.closest('label') ?? input).after(box);
    input.setAttribute('aria-describedby', box.id);
    messages.place(this.source, box);
    input.addEventListener('change', () => this.changed());
  }

  /** The accepted text (what the page uses), not what is typed. */
  get value() { return this.accepted; }

  /** Writes `text` into the field as the page's own: accepted. @param {string} text */
  set value(text) { this.input.value = text; this.settle(text); }

  /** Also calls `listener` with each accepted text typed. @param {(text: string) => void} listener */
  listen(listener) { this.listeners.push(listener); }

  /** The person changed the text: it is checked, then used, or refused and kept to be corrected. */
  async changed() {
    const text = this.input.value;
    const ticket = ++this.ticket;
    const refusal = await this.rule.problem(text);
    if (ticket !== this.ticket) return; // written or typed again since
    if (!refusal) {
      this.settle(text);
      this.rule.use(text);
      for (const listener of this.listeners) listener(text);
      return;
    }
    this.input.setAttribute('aria-invalid', 'true');
    const { words, detail } = typeof refusal === 'string' ? { words: refusal, detail: undefined } : refusal;
    this.messages.show(words, 'error', this.source, detail);
  }

  /** The field holds `text`, valid: its mark and message go. @param {string} text */
  settle(text) {
    this.ticket++;
    this.accepted = text;
    this.input.removeAttribute('aria-invalid');
    this.messages.drop(this.source);
  }
}
