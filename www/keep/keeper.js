// @ts-check
/**
 * Keeping and sharing the page's state: kept in the browser's storage shortly after each
 * change (drafts too), put in a link by Share (address bar and clipboard), and read back at
 * start-up (a link first, else what was kept) or when a link is pasted into this tab. Every
 * state read is checked in full (share.js) before anything changes; a refused link says why
 * and what is shown instead, and a link whose brain is damaged, or any other part of it left
 * out, opens without it and says so, until the person closes the message. Share makes only a
 * link that opens: while the state cannot be shared (a drawing that is not a whole robot, a
 * setting a link would refuse), the Share button is off and its tooltip says why.
 *
 * The latest state wins: a link in the address bar is read once. Once opened (or refused) it
 * leaves the address bar, and Share's link leaves it at the next change, so that a reload
 * shows the kept state, with every later edit, never an older link; the link shown beside Share
 * goes too.
 */
import { messageOf } from '../workers/kit.js';
import { plain } from '../shared/message.js';
import { decodeState, encodeState, shareProblem } from './share.js';
import { keep, loadKept } from './storage.js';

/** Wait after the last change before keeping the state (ms). */
const KEEP_DELAY_MS = 300;

/**
 * @typedef {object} KeeperHooks
 * @property {() => import('./share.js').PageState} state  the state now
 * @property {(state: import('./share.js').PageState) => Promise<string>} apply  shows a state; '' or why not
 * @property {() => string} shown                             the robot shown now, in words
 * @property {() => boolean} running                          a run uses the robot
 * @property {() => string} lost                              what a link leaves behind, a sentence ('' if nothing)
 * @property {(text: string, kind?: import('../shared/message.js').Kind) => void} say
 * @property {(state: import('./share.js').PageState) => unknown} [shared]  a link was made of `state` (a class challenge's short code)
 */

export class Keeper {
  /**
   * @param {import('../workers/core.js').Defaults} defaults
   * @param {{link: HTMLInputElement, button: HTMLButtonElement}} share where a shared link is shown, and the Share button
   * @param {KeeperHooks} hooks
   */
  constructor(defaults, { link: linkField, button }, hooks) {
    this.defaults = defaults;
    this.linkField = linkField;
    this.hooks = hooks;
    this.timer = 0;
    /** The Share button: off while the state cannot be shared. */
    this.button = button;
    /** Its tooltip while it can share. */
    this.title = button.title;
    /** States asked whether they can be shared: only the latest answer sets the button. */
    this.asked = 0;
    /** The latest state asked (its link) and the answer: '' or why it cannot be shared. */
    this.verdict = { text: '', why: Promise.resolve('') };
  }

  /** Keeps the state shortly (changes in a burst are kept once). */
  schedule() {
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => {
      const now = this.hooks.state();
      this.updateButton(now);
      const state = encodeState(now);
      const problem = keep(state);
      if (problem) this.hooks.say(problem);
      else if (location.hash.length > 1 && location.hash.slice(1) !== state) dropLink();
      // A shown link that no longer opens this robot goes: nobody copies an older robot by mistake.
      if (!this.linkField.hidden && !this.linkField.value.endsWith(`#${state}`)) {
        this.linkField.hidden = true;
        this.linkField.value = '';
        delete this.linkField.dataset.value;
      }
    }, KEEP_DELAY_MS);
  }

  /**
   * Turns Share off, its tooltip saying why, while `state` cannot be shared; on otherwise.
   * @param {import('./share.js').PageState} state
   */
  async updateButton(state) {
    const ticket = ++this.asked;
    const why = await this.whyNot(state);
    if (ticket !== this.asked) return;
    this.button.disabled = why !== '';
    this.button.title = why ? `Share link is off: ${why}.` : this.title;
  }

  /**
   * '' or why `state` cannot be shared, asked once for each state (a check that failed is asked again).
   * @param {import('./share.js').PageState} state @returns {Promise<string>}
   */
  whyNot(state) {
    const text = encodeState(state);
    if (this.verdict.text !== text) {
      const why = shareProblem(state, this.defaults.controllers, this.defaults.grid).catch((error) => {
        if (this.verdict.why === why) this.verdict.text = '';
        return `it could not be checked (${messageOf(error)})`;
      });
      this.verdict = { text, why };
    }
    return this.verdict.why;
  }

  /**
   * Shows the state of the link this page was opened with, else the kept one, else calls
   * `fallback` (the page's first robot); a refused link says so, and what is shown instead.
   * @param {() => Promise<void>} fallback resolves once the first robot is shown
   */
  async restore(fallback) {
    const { controllers, grid } = this.defaults;
    const fromLink = location.hash.length > 1 ? await decodeState(location.hash, controllers, grid) : null;
    let refused = '';
    let shown = false;
    if (fromLink && 'state' in fromLink) {
      refused = await this.hooks.apply(fromLink.state);
      shown = refused === '';
    } else if (fromLink && 'error' in fromLink) {
      refused = fromLink.error;
    }
    const kept = loadKept();
    const fromStorage = !shown && kept ? await decodeState(kept, controllers, grid, true) : null;
    // Why what was kept from the last visit is not shown ('' when it is, or when nothing was kept).
    let keptWhy = fromStorage && 'error' in fromStorage ? fromStorage.error : '';
    if (fromStorage && 'state' in fromStorage) {
      keptWhy = await this.hooks.apply(fromStorage.state);
      shown = keptWhy === '';
    }
    if (!shown) await fallback();
    if (fromLink) dropLink(); // read once: from now on the kept state is the page's
    const example = `the example robot ${this.defaults.presets[0].name}`;
    if (refused) this.refuse(refused, shown ? 'the robot you had here before' : example);
    else if (fromLink && 'state' in fromLink) this.opened(fromLink);
    else if (keptWhy) this.hooks.say(`What this page kept from your last visit could not be opened (${plain(keptWhy)}): ${example} is shown instead.`);
  }

  /** A link pasted into this tab (only the part after '#' changed): open it, unless a run goes on. */
  async openLink() {
    if (location.hash.length <= 1) return;
    if (this.hooks.running()) { this.hooks.say('Stop the run before opening another robot.'); return; }
    const opened = await decodeState(location.hash, this.defaults.controllers, this.defaults.grid);
    const problem = 'error' in opened ? opened.error : await this.hooks.apply(opened.state);
    dropLink();
    if (problem) this.refuse(problem, 'the robot you had before');
    else if ('state' in opened) this.opened(opened);
  }

  /**
   * The Share button: the state in the address bar and on the clipboard, if its link opens it;
   * else it says why there is no link.
   */
  async share() {
    const state = this.hooks.state();
    const why = await this.whyNot(state);
    if (why) { this.hooks.say(`No link was made: ${why}.`); return; }
    const url = `${location.origin}${location.pathname}#${encodeState(state)}`;
    history.replaceState(null, '', url);
    this.linkField.value = url;
    this.linkField.dataset.value = url;
    this.linkField.hidden = false;
    this.linkField.select();
    this.hooks.shared?.(state);
    try {
      await navigator.clipboard.writeText(url);
      this.hooks.say(`Link copied: it opens this robot, its settings and its controller.${this.hooks.lost()}`, 'note');
    } catch {
      this.hooks.say(`Here is the link (selected): copy it to share this robot.${this.hooks.lost()}`, 'note');
    }
  }

  /** @param {string} why @param {string} instead whose robot is shown instead */
  refuse(why, instead) {
    this.hooks.say(`This link could not be opened: ${plain(why)}. It may have been cut short or changed on the way; `
      + `ask for it again. Shown instead: ${instead}, ${this.hooks.shown()}.`);
  }

  /**
   * A link opened: says what was left out of it (a damaged brain, other parts), if anything.
   * @param {{damaged?: string, dropped: string[]}} read
   */
  opened({ damaged, dropped }) {
    if (damaged !== undefined) {
      this.hooks.say(`The brain in this link is damaged (${damaged}): the robot and settings are opened without it, `
        + `${this.hooks.shown()}. Ask for the link again to get the brain.`);
    }
    if (dropped.length > 0) this.hooks.say(`${dropped.join(' ')} Shown: ${this.hooks.shown()}.`);
  }
}

/** Takes the link out of the address bar (no reload, no new history entry). */
function dropLink() {
  history.replaceState(null, '', `${location.pathname}${location.search}`);
}
