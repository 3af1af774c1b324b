// @ts-check
/**
 * The guided tour (Learn): the chapters of chapters.js in a box beside the playground (a side
 * column on a wide screen, a sheet at the bottom of a phone's), with Back and Next. Opening a
 * chapter sets the playground up (stage.js), outlines the control it asks about and scrolls
 * to it. Every chapter has its own link, `?chapter=N` (1-based): a query, so it never meets the
 * share link's `#...` and both can be in one address. Leaving the tour leaves the playground
 * as the chapter set it.
 */
import { withStats } from '../shared/simple-words.js';
import { byId } from '../shared/dom.js';
import { NOT_YET } from '../shared/families.js';
import { messageOf } from '../workers/kit.js';
import { CHAPTERS } from './chapters.js';
import { FIGURES, figureSrc } from './figures.js';
import { stage } from './stage.js';

/** How long after a chapter opens its controls are brought into view again, once the page has settled (ms). */
const SETTLE_MS = 1000;
/** Room kept under a control the tour points to (px): the page settles, and lines above it grow. */
const SLACK_PX = 48;
/** Where the box is a sheet at the bottom of the screen (tour.css says the same width). */
const SHEET_MEDIA = '(max-width: 860px)';

/** The address's query parameter that names a chapter. */
export const CHAPTER_PARAM = 'chapter';

/**
 * @param {string} search a location's query (`?chapter=4`)
 * @returns {number} the chapter's index (0-based), or -1 when there is none or it is not a chapter
 */
export function chapterOf(search) {
  const text = new URLSearchParams(search).get(CHAPTER_PARAM);
  const n = Number(text);
  return text !== null && Number.isInteger(n) && n >= 1 && n <= CHAPTERS.length ? n - 1 : -1;
}

export class Tour {
  /**
   * @param {Document} doc
   * @param {import('./stage.js').Playground} page
   * @param {{show: (id: string) => void}} study  shows a figure in the study panel
   * @param {{exercise: (index: number, revealed: () => void) => HTMLElement | null, tools: () => HTMLElement,
   *   speedsShown: (index: number) => boolean} | null} [classroom]
   *   each chapter's task (asked before its “Notice”, its figure and its race show), the teacher's tools, and whether a
   *   chapter's question leaves the page's speeds shown (../classroom/)
   */
  constructor(doc, page, study, classroom = null) {
    this.doc = doc;
    this.page = page;
    this.study = study;
    this.classroom = classroom;
    this.index = -1;
    /** Whether the chapter shown keeps its race at the start line until its question is answered. */
    this.raceHeld = false;
    /** Counts chapter openings, so that a slow one never overwrites a newer one. */
    this.opening = 0;
    this.box = this.build();
    byId(doc, 'tour-open', HTMLButtonElement).addEventListener('click', () => this.open(Math.max(0, this.index)));
  }

  /** Builds the box (hidden until the tour opens). */
  build() {
    const doc = this.doc;
    const box = doc.createElement('aside');
    box.id = 'tour-box';
    box.hidden = true;
    box.setAttribute('aria-labelledby', 'tour-chapter');
    box.innerHTML = `
      <div class="tour-head">
        <label class="tour-count">Learn · chapter <select id="tour-pick" aria-label="Go to chapter"></select> of ${CHAPTERS.length}</label>
        <button type="button" id="tour-fold" class="tour-fold" aria-expanded="true" title="Fold the text away (Back and Next stay)">Hide text</button>
        <button type="button" id="tour-close" class="close" aria-label="Leave the tour" title="Leave the tour (the playground stays as it is)">&times;</button>
      </div>
      <h2 id="tour-chapter" data-testid="tour-chapter"></h2>
      <div id="tour-body" class="tour-body" aria-live="polite"></div>
      <nav class="tour-nav">
        <button type="button" id="tour-back" data-testid="tour-back">&larr; Back</button>
        <a id="tour-link" class="tour-link" title="This chapter's own link: send it, and it opens here">link to this chapter</a>
        <button type="button" id="tour-next" data-testid="tour-next" class="primary">Next &rarr;</button>
      </nav>`;
    if (this.classroom) box.querySelector('.tour-nav')?.before(this.classroom.tools());
    doc.body.append(box);
    const pick = byId(doc, 'tour-pick', HTMLSelectElement);
    CHAPTERS.forEach((c, i) => pick.append(new Option(`${i + 1}`, String(i))));
    pick.title = CHAPTERS.map((c, i) => `${i + 1}. ${c.title}`).join('\n');
    pick.addEventListener('change', () => this.open(Number(pick.value)));
    byId(doc, 'tour-back', HTMLButtonElement).addEventListener('click', () => this.open(this.index - 1));
    byId(doc, 'tour-next', HTMLButtonElement).addEventListener('click', () => this.open(this.index + 1));
    byId(doc, 'tour-close', HTMLButtonElement).addEventListener('click', () => this.close());
    byId(doc, 'tour-fold', HTMLButtonElement).addEventListener('click', () => this.fold(!box.classList.contains('folded')));
    // On a phone the sheet covers the lower half: a touch on the page (to do the task, or to
    // scroll to its result) folds the text away, Back and Next stay; a new chapter unfolds it.
    doc.addEventListener('pointerdown', (event) => {
      if (!box.hidden && matchMedia(SHEET_MEDIA).matches && !box.contains(/** @type {Node} */ (event.target))) this.fold(true);
    }, true);
    return box;
  }

  /** Opens the chapter of the page's address, if it names one. */
  begin() {
    const index = chapterOf(location.search);
    if (index >= 0) this.open(index);
    else if (new URLSearchParams(location.search).has(CHAPTER_PARAM)) {
      this.page.message(`there is no chapter “${new URLSearchParams(location.search).get(CHAPTER_PARAM)}”: the tour has ${CHAPTERS.length} chapters, 1 to ${CHAPTERS.length} (Learn opens the first)`);
    }
  }

  /**
   * Opens chapter `index` (0-based) and sets the playground up for it.
   * @param {number} index
   */
  async open(index) {
    if (index < 0 || index >= CHAPTERS.length) return;
    const started = performance.now();
    const ticket = ++this.opening;
    this.index = index;
    // A chapter about the study's brain for any body first learns whether pretrained/ has it (the module list says).
    const pending = CHAPTERS[index].setup.anyBody ? (await this.page.studyAnyBody()) === '' : false;
    if (ticket !== this.opening) return;
    this.show(CHAPTERS[index], pending);
    this.box.dataset.state = 'setting';
    this.page.race.hold(this.raceHeld);
    this.page.holdAtEpisodeEnd(true);
    try {
      await stage(this.page, CHAPTERS[index]);
      if (ticket !== this.opening) return;
      this.box.dataset.state = 'ready';
      this.box.dataset.openedMs = (performance.now() - started).toFixed(0);
      this.point(CHAPTERS[index].target);
      // The page settles after a chapter opens (the speed line fills in): point again once,
      // unless the visitor has scrolled or moved on meanwhile.
      const scrolled = scrollY;
      setTimeout(() => { if (ticket === this.opening && scrollY === scrolled) this.point(CHAPTERS[index].target); }, SETTLE_MS);
    } catch (error) {
      if (ticket !== this.opening) return;
      this.box.dataset.state = 'failed';
      this.page.message(`this chapter could not set the playground up: ${messageOf(error)}`);
    }
  }

  /**
   * Shows a chapter's words; a `pending` one (its brain not trained yet) says so in place of its task and notice, and asks nothing.
   * @param {import('./chapters.js').Chapter} chapter @param {boolean} [pending]
   */
  show(chapter, pending = false) {
    const doc = this.doc;
    const i = this.index;
    this.box.hidden = false;
    doc.body.classList.add('touring');
    this.box.dataset.chapter = String(i + 1);
    byId(doc, 'tour-chapter').textContent = chapter.title;
    byId(doc, 'tour-pick', HTMLSelectElement).value = String(i);
    const body = byId(doc, 'tour-body');
    this.fold(false);
    body.scrollTop = 0;
    const { simple } = chapter; // its words for a 14-year-old, shown instead while “Simple words” is on (classroom.css)
    // A chapter with a question holds back what would answer it (its notice, its figure, its
    // race) until the answer is revealed.
    const notice = paragraph(doc, chapter.notice, 'Notice', 'tour-notice', simple?.notice);
    const figure = chapter.figure ? this.figure(chapter.figure) : null;
    body.replaceChildren(...chapter.text.map((t) => paragraph(doc, t, undefined, simple ? 'expert' : undefined)),
      ...(simple?.text ?? []).map((t) => paragraph(doc, t, undefined, 'simple-only')));
    if (pending) {
      // No module, no number: nothing to predict or to hold back.
      const words = (/** @type {string | undefined} */ then) => `The study's brain for any body: ${NOT_YET}. ${then ?? ''}`.trim();
      const p = paragraph(doc, words(chapter.pending), undefined, 'tour-pending', simple ? words(simple.pending) : undefined);
      p.dataset.testid = 'tour-pending';
      body.append(p);
      this.holdAnswers(false, false);
      this.raceHeld = false;
    } else this.showTask(chapter, notice, figure);
    this.nav(i);
  }

  /**
   * Shows a chapter's task: its question first when it has one (the notice and the figure held back until the answer is revealed).
   * @param {import('./chapters.js').Chapter} chapter @param {HTMLElement} notice @param {HTMLElement | null} figure
   */
  showTask(chapter, notice, figure) {
    const doc = this.doc;
    const i = this.index;
    const body = byId(doc, 'tour-body');
    const held = figure ? [notice, figure] : [notice];
    const task = this.classroom?.exercise(i, () => {
      for (const el of held) el.hidden = false;
      if (this.index === i) this.holdAnswers(false);
    });
    if (task) for (const el of held) el.hidden = true;
    // So does the rest of the page: the robot's and the module list's speeds, the study's figures and findings.
    this.holdAnswers(Boolean(task) && !this.classroom?.speedsShown(i), false);
    this.raceHeld = Boolean(task && chapter.setup.race);
    if (task) body.append(task);
    body.append(paragraph(doc, chapter.task, 'Do', 'tour-task', chapter.simple?.task), ...held);
  }

  /** Back, Next, the address and the chapter's link, for chapter `i` (0-based). @param {number} i */
  nav(i) {
    const doc = this.doc;
    byId(doc, 'tour-back', HTMLButtonElement).disabled = i === 0;
    const next = byId(doc, 'tour-next', HTMLButtonElement);
    next.disabled = i === CHAPTERS.length - 1;
    next.title = i < CHAPTERS.length - 1 ? CHAPTERS[i + 1].title : 'The last chapter';
    const url = new URL(location.href);
    url.searchParams.set(CHAPTER_PARAM, String(i + 1));
    history.replaceState(history.state, '', url);
    const link = byId(doc, 'tour-link', HTMLAnchorElement);
    url.hash = '';
    link.href = url.href;
  }

  /** A study figure beside the chapter. @param {string} id */
  figure(id) {
    const doc = this.doc;
    const fig = FIGURES.find((f) => f.id === id);
    const box = doc.createElement('figure');
    if (!fig) return box;
    const src = figureSrc(fig);
    box.innerHTML = '<a target="_blank" rel="noopener" title="Open the figure full size"><img alt=""></a><figcaption></figcaption>';
    /** @type {HTMLAnchorElement} */ (box.querySelector('a')).href = src;
    const img = /** @type {HTMLImageElement} */ (box.querySelector('img'));
    img.src = src;
    img.alt = fig.title;
    const caption = /** @type {HTMLElement} */ (box.querySelector('figcaption'));
    caption.replaceChildren(...withStats(doc, `Our study: ${fig.title}. ${fig.read} ${fig.paper} `));
    const watch = doc.createElement('button');
    watch.type = 'button';
    watch.textContent = fig.runs.length ? 'Watch its robots' : 'Show it in “The study” below';
    watch.title = fig.runs.length ? 'Show this figure in “The study” below, where each run\'s best robot can walk' : 'Show this figure in “The study” below';
    watch.addEventListener('click', () => this.study.show(id));
    caption.append(watch);
    return box;
  }

  /**
   * Outlines the controls a chapter asks about (a folded <details> among them is opened) and
   * brings them into view (above the sheet on a phone): all of them when they fit on the screen
   * together, else the last (the control to use) with as much of the others above it as fits, or
   * the first if it stands alone.
   * @param {string} selector
   */
  point(selector) {
    for (const el of this.doc.querySelectorAll('.tour-target')) el.classList.remove('tour-target');
    const targets = /** @type {HTMLElement[]} */ ([...this.doc.querySelectorAll(selector)]);
    for (const el of targets) {
      el.classList.add('tour-target');
      if (el instanceof HTMLDetailsElement) el.open = true;
    }
    const first = targets[0];
    if (!first) return;
    const sheet = this.box.getBoundingClientRect();
    const bottom = sheet.top > innerHeight / 3 ? sheet.top : innerHeight; // a sheet at the bottom hides what is under it
    const rects = targets.map((el) => el.getBoundingClientRect());
    const top = Math.min(...rects.map((r) => r.top));
    const end = Math.max(...rects.map((r) => r.bottom));
    const margin = 12;
    // All in view, and not at the very bottom, where a line the page adds above can push it under.
    if (top >= 0 && end <= bottom - SLACK_PX) return;
    if (end - top <= bottom - 2 * margin) { // they fit: in the middle of what shows
      scrollBy({ top: (top + end) / 2 - bottom / 2, behavior: 'instant' });
      return;
    }
    const last = rects[rects.length - 1];
    if (rects.length > 1 && last.height <= bottom - SLACK_PX - margin) {
      // The control to use (the last) near the bottom; above it, as much of the others as fits.
      scrollBy({ top: last.bottom - bottom + SLACK_PX, behavior: 'instant' });
      return;
    }
    const rect = rects[0];
    const tall = bottom < innerHeight || rect.height > bottom / 2; // a sheet below, or a target too tall to centre
    if (rect.top < 0 || rect.top > bottom - 40) first.scrollIntoView({ block: tall ? 'start' : 'center', behavior: 'instant' });
  }

  /** Folds the chapter's text away, or back. @param {boolean} folded */
  fold(folded) {
    this.box.classList.toggle('folded', folded);
    const button = byId(this.doc, 'tour-fold', HTMLButtonElement);
    button.setAttribute('aria-expanded', String(!folded));
    button.textContent = folded ? 'Show text' : 'Hide text';
  }

  /**
   * While `on`, the page keeps back what would answer the chapter's question before the student
   * does: the robot's speeds under the viewer, the module list's speeds, the study panel's
   * figures and the findings in plain words (tour.css), and, with `race`, the chapter's race at
   * its start line.
   * @param {boolean} on @param {boolean} [race] whether the race is let go too
   */
  holdAnswers(on, race = true) {
    this.doc.body.toggleAttribute('data-answer-held', on);
    this.page.quietModules(on);
    if (race) this.page.race.hold(on);
  }

  /** Leaves the tour: the playground stays as the chapter set it. */
  close() {
    this.opening++;
    this.holdAnswers(false);
    this.page.holdAtEpisodeEnd(false);
    this.box.hidden = true;
    this.doc.body.classList.remove('touring');
    for (const el of this.doc.querySelectorAll('.tour-target')) el.classList.remove('tour-target');
    const url = new URL(location.href);
    url.searchParams.delete(CHAPTER_PARAM);
    history.replaceState(history.state, '', url);
  }
}

/**
 * @param {Document} doc @param {string} text @param {string} [lead] a bold first word
 * @param {string} [className] @param {string} [simple] the same in simple words: both written, one shown (classroom.css)
 */
function paragraph(doc, text, lead, className, simple) {
  const p = doc.createElement('p');
  if (className) p.className = className;
  if (lead) {
    const b = doc.createElement('b');
    b.textContent = `${lead}: `;
    p.append(b);
  }
  if (simple === undefined) { p.append(text); return p; }
  const expert = doc.createElement('span');
  expert.className = 'expert';
  expert.textContent = text;
  const plain = doc.createElement('span');
  plain.className = 'simple-only';
  plain.textContent = simple;
  p.append(expert, plain);
  return p;
}
