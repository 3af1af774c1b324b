// @ts-check
/**
 * The classroom: each tour chapter's task (exercises.js) under its text, asked before it is
 * shown: the student answers (a choice or a number), then Reveal runs it in the page (lab.js)
 * and shows the answer, with why, beside the student's; the chapter's “Notice” waits until
 * then. Two tools for the teacher in the tour's box: “Print worksheet” (a sheet generated in the
 * page: every chapter's task, room to write, the chapter's link as text; printed alone by
 * classroom.css) and “Answer keys” (every key, computed as a student's reveal computes it).
 */
import { messageOf } from '../workers/kit.js';
import { CHAPTERS } from '../tour/chapters.js';
import { exerciseOf } from './exercises.js';
import { keepGuess } from './guess-lock.js';
import { GUIDE, LESSON, LESSON_SHEET, lessonChapters, lessonChaptersWords, lessonPlanNodes, lessonStepWords, lessonTimes } from './lesson-plan.js';
import { loadQr, qrBox } from './qr.js';
import { addressField, chapterLink, onlyHere, pageAddress } from './sheet-address.js';
import { EXAMPLE_CODE } from './challenge/code.js';
import { withTerms } from '../shared/simple-words.js';
import { make } from '../shared/dom.js';

/** How often a Reveal that had to wait checks whether it still must (ms), and what it says then. */
const WAIT_CHECK_MS = 500;
const WAIT_OVER = 'Your run has ended: press Reveal.';

export class Classroom {
  /** @param {Document} doc @param {import('./lab.js').Lab} lab */
  constructor(doc, lab) {
    this.doc = doc;
    this.lab = lab;
    /** The student's answers by chapter, kept while the page is open. @type {Map<number, string>} */
    this.answers = new Map();
    /** The chapters whose guess is locked (guess-lock.js). @type {Set<number>} */
    this.locked = new Set();
    /**
     * The address the class opens, shared by the lesson's sheet and the worksheet: this page's,
     * until the teacher types the class's in either (sheet-address.js). @type {string}
     */
    this.classAddress = pageAddress(location.href);
    // “For teachers” in the page's header: the 50-minute lesson, with the way to the rest.
    doc.getElementById('teacher-open')?.addEventListener('click', () => { void loadQr(); this.lesson(); });
  }

  /**
   * Chapter `index`'s task, to go under its text; `revealed` is called once its answer is
   * shown (the tour then shows what it held back). Null for a chapter without a task, or whose task cannot be asked yet.
   * @param {number} index @param {() => void} revealed @returns {HTMLElement | null}
   */
  exercise(index, revealed) {
    const doc = this.doc;
    const ex = exerciseOf(index);
    if (!ex || ex.unavailable?.(this.lab)) return null;
    const box = make(doc, 'section', 'exercise');
    box.dataset.testid = 'tour-exercise';
    box.dataset.chapter = String(index + 1);
    const ask = make(doc, 'p', 'exercise-ask', ex.simple ? '' : ex.ask);
    if (ex.simple) ask.append(make(doc, 'span', 'expert', ex.ask), make(doc, 'span', 'simple-only', ex.simple)); // one shown (classroom.css)
    box.append(make(doc, 'h3', 'exercise-title', 'Predict first'), ask);
    /** @type {() => string} */
    let given;
    const reveal = /** @type {HTMLButtonElement} */ (make(doc, 'button', 'primary', 'Reveal'));
    reveal.type = 'button';
    reveal.dataset.testid = 'tour-reveal';
    reveal.title = 'Answer first: then the page runs it and shows what happens, and why';
    const kept = this.answers.get(index) ?? '';
    if (ex.choices) {
      const list = make(doc, 'div', 'exercise-choices');
      list.setAttribute('role', 'radiogroup');
      ex.choices.forEach((text, i) => {
        const label = make(doc, 'label', 'exercise-choice');
        const input = /** @type {HTMLInputElement} */ (doc.createElement('input'));
        input.type = 'radio';
        input.name = `exercise-${index}`;
        input.value = String(i);
        input.checked = kept === String(i);
        label.append(input, ` ${text}`);
        list.append(label);
      });
      box.append(list);
      given = () => /** @type {HTMLInputElement | null} */ (list.querySelector('input:checked'))?.value ?? '';
    } else {
      const label = make(doc, 'label', 'exercise-number', 'My guess ');
      const input = /** @type {HTMLInputElement} */ (doc.createElement('input'));
      input.type = 'number';
      input.step = 'any';
      input.value = kept;
      input.setAttribute('aria-label', 'My guess');
      label.append(input, ` ${ex.unit ?? ''}`);
      box.append(label);
      given = () => input.value.trim();
    }
    const result = make(doc, 'div', 'exercise-result');
    result.dataset.testid = 'tour-answer';
    result.setAttribute('aria-live', 'polite');
    result.hidden = true;
    const ready = () => {
      const answered = given() !== '';
      reveal.disabled = !answered || box.dataset.state === 'revealing';
      if (answered) this.answers.set(index, given());
    };
    box.addEventListener('input', ready);
    box.addEventListener('change', ready);
    const hint = make(doc, 'span', 'exercise-hint', 'answer first, then reveal');
    const bar = make(doc, 'div', 'exercise-bar');
    bar.append(reveal, hint);
    box.append(bar, result);
    reveal.addEventListener('click', async () => {
      const mine = given();
      if (mine === '') return;
      const wait = ex.wait?.(this.lab) ?? '';
      if (wait) {
        const said = make(doc, 'p', 'exercise-wait', wait);
        result.replaceChildren(said);
        result.hidden = false;
        // Once nothing holds it back any more (the run ended), the line says so.
        const timer = setInterval(() => {
          if (!said.isConnected) { clearInterval(timer); return; }
          if (ex.wait?.(this.lab)) return;
          clearInterval(timer);
          said.textContent = WAIT_OVER;
        }, WAIT_CHECK_MS);
        return;
      }
      box.dataset.state = 'revealing';
      reveal.disabled = true;
      reveal.textContent = 'Running it…';
      try {
        const key = await ex.key(this.lab);
        const right = Number(mine) === key.answer;
        // A number guessed within a fifth of the answer (or 1) is close: said so, not marked right.
        const close = !ex.choices && !right && Math.abs(Number(mine) - key.answer) <= Math.max(1, 0.2 * Math.abs(key.answer));
        const yours = ex.choices ? ex.choices[Number(mine)] : `${mine} ${ex.unit ?? ''}`.trim();
        const [kind, mark] = right ? ['exercise-right', '✓ Right.'] : close ? ['exercise-close', '≈ Close.'] : ['exercise-wrong', '✗ Not this time.'];
        result.replaceChildren(
          make(doc, 'p', kind, `${mark} You said: ${yours}.`),
          make(doc, 'p', 'exercise-key', `The page's answer: ${key.shown}.`),
          make(doc, 'p', 'exercise-why'));
        if (key.simpleWhy) { // both written, one shown (classroom.css): the expert's, or the same in simple words
          const expert = make(doc, 'span', 'expert');
          expert.append(...withTerms(doc, key.why));
          result.lastElementChild?.append(expert, make(doc, 'span', 'simple-only', key.simpleWhy));
        } else {
          result.lastElementChild?.append(...withTerms(doc, key.why));
        }
        if (ex.try) result.append(make(doc, 'p', 'exercise-try', `Now try it: ${ex.try}`));
        result.hidden = false;
        box.dataset.state = 'revealed';
        box.dataset.right = String(right);
        box.dataset.close = String(close);
        revealed();
        result.scrollIntoView({ block: 'nearest' });
      } catch (error) {
        result.replaceChildren(make(doc, 'p', 'exercise-wrong', `The page could not run it: ${messageOf(error)}`));
        result.hidden = false;
        box.dataset.state = 'failed';
      }
      reveal.textContent = 'Reveal';
      reveal.disabled = false;
    });
    ready();
    if (ex.lock) keepGuess({ box, index, locked: this.locked, given, showing: () => ex.lock?.(this.lab) ?? null });
    return box;
  }

  /** Whether chapter `index`'s question leaves the page's speeds shown (it is not about them). @param {number} index */
  speedsShown(index) { return exerciseOf(index)?.speedsShown === true; }

  /** The teacher's tools: a row of buttons for the tour's box. */
  tools() {
    const doc = this.doc;
    const bar = make(doc, 'div', 'tour-class');
    // Folded and named for the teacher: the keys hold every chapter's answer.
    const fold = make(doc, 'details', 'tour-teacher');
    fold.addEventListener('toggle', () => void loadQr(), { once: true }); // the lesson sheet's QR code, drawn at once
    const summary = make(doc, 'summary', '', 'For the teacher: lesson plan, worksheet, keys');
    summary.dataset.testid = 'tour-teacher';
    const tools = make(doc, 'div', 'tour-teacher-tools');
    const print = /** @type {HTMLButtonElement} */ (make(doc, 'button', '', 'Print worksheet'));
    print.type = 'button';
    print.dataset.testid = 'worksheet-open';
    print.title = 'A sheet for a class: every chapter\'s task, room to write, the chapter\'s link';
    print.addEventListener('click', () => this.worksheet(true));
    const keys = /** @type {HTMLButtonElement} */ (make(doc, 'button', '', 'Answer keys and lesson plan'));
    keys.type = 'button';
    keys.dataset.testid = 'teacher-keys-open';
    keys.title = 'Every task\'s answer, computed by the page now, with why';
    keys.addEventListener('click', () => this.keys());
    const lesson = /** @type {HTMLButtonElement} */ (make(doc, 'button', '', LESSON_SHEET));
    lesson.type = 'button';
    lesson.dataset.testid = 'lesson-open';
    lesson.title = 'One lesson for a class of 30, minute by minute: what you project, what the students do';
    lesson.addEventListener('click', () => this.lesson());
    tools.append(lesson, print, keys);
    fold.append(summary, tools);
    bar.append(fold);
    return bar;
  }

  /** An overlay sheet with a title, a Print and a Close button. @param {string} id @param {string} title */
  sheet(id, title) {
    const doc = this.doc;
    for (const open of doc.querySelectorAll('.class-sheet')) open.remove(); // one sheet at a time
    const sheet = make(doc, 'section', 'class-sheet');
    sheet.id = id;
    sheet.setAttribute('role', 'dialog');
    sheet.setAttribute('aria-label', title);
    const bar = make(doc, 'div', 'class-sheet-bar');
    const print = /** @type {HTMLButtonElement} */ (make(doc, 'button', 'primary', 'Print'));
    print.type = 'button';
    print.addEventListener('click', () => { doc.body.dataset.printing = id; print.ownerDocument.defaultView?.print(); });
    const close = /** @type {HTMLButtonElement} */ (make(doc, 'button', '', 'Close'));
    close.type = 'button';
    close.addEventListener('click', () => { sheet.remove(); delete doc.body.dataset.printing; });
    bar.append(print, close);
    sheet.append(bar, make(doc, 'h1', '', title));
    doc.body.append(sheet);
    doc.body.dataset.printing = id; // the browser's own Print prints this sheet while it is open
    return sheet;
  }

  /**
   * The worksheet, and the print dialog when `print` (not when the page's address opens only
   * on this computer: the teacher types the class's first, sheet-address.js): every chapter, or
   * only the chapters `only` (0-based: the 50-minute lesson's). @param {boolean} print @param {number[]} [only]
   */
  worksheet(print, only) {
    const doc = this.doc;
    const sheet = this.sheet('worksheet', only ? `VSR Playground: predict, then try (${lessonChaptersWords()}, then the class challenge)` : 'VSR Playground: predict, then try');
    sheet.dataset.testid = 'worksheet';
    sheet.dataset.chapters = only ? 'lesson' : 'all';
    const base = this.classAddress;
    /** @type {HTMLElement[]} */
    const links = [];
    sheet.querySelector('.class-sheet-bar')?.prepend(addressField(doc, base, (href) => {
      this.classAddress = href;
      links.forEach((link, i) => { link.textContent = chapterLink(shown[i], href); });
    }));
    sheet.append(make(doc, 'p', 'sheet-name', 'Name: ______________________________   Date: ______________'),
      make(doc, 'p', 'sheet-how', 'For each chapter: open its link, read it, write your prediction before you press Reveal, then try it and write what happened.'));
    /** @type {number[]} */
    const shown = [];
    CHAPTERS.forEach((chapter, i) => {
      if (only && !only.includes(i)) return;
      shown.push(i);
      const ex = exerciseOf(i);
      const part = make(doc, 'section', 'sheet-task');
      const link = make(doc, 'p', 'sheet-link', chapterLink(i, base));
      links.push(link);
      part.append(make(doc, 'h2', '', `Chapter ${i + 1}. ${chapter.title}`), link,
        make(doc, 'p', 'sheet-ask', ex?.ask ?? chapter.task));
      const notYet = ex?.unavailable?.(this.lab) ?? '';
      if (notYet) part.append(make(doc, 'p', 'sheet-do', `${notYet} Skip this chapter for now.`));
      else if (ex) part.append(make(doc, 'p', 'sheet-do', `Do: ${chapter.task}`));
      if (!ex || notYet) {
        // a chapter without a task: its “Do”, and room to write
      } else if (ex.choices) {
        const list = make(doc, 'ul', 'sheet-choices');
        for (const c of ex.choices) list.append(make(doc, 'li', '', `☐ ${c}`));
        part.append(list);
      } else {
        part.append(make(doc, 'p', 'sheet-guess', `My guess: ____________ ${ex.unit ?? ''}`));
      }
      const write = make(doc, 'div', 'sheet-write'); // ruled lines (borders: a printer drops backgrounds)
      for (let line = 0; line < 3; line++) write.append(make(doc, 'div', 'sheet-line'));
      part.append(make(doc, 'p', 'sheet-lines', 'What happened, and why:'), write);
      sheet.append(part);
    });
    sheet.append(challengeBox(doc));
    sheet.scrollIntoView({ block: 'start' });
    if (print && !onlyHere(base)) setTimeout(() => doc.defaultView?.print(), 0);
    return sheet;
  }

  /**
   * The 50-minute lesson (lesson-plan.js), minute by minute, with the QR code of the address the
   * class opens (this page's, or the one the teacher types: an address that opens only on this
   * computer is said).
   */
  lesson() {
    const doc = this.doc;
    const sheet = this.sheet('lesson', `${LESSON.name}, for ${LESSON.who}`);
    sheet.dataset.testid = 'lesson';
    const base = this.classAddress;
    const qr = make(doc, 'div', 'lesson-qr');
    const showQr = (/** @type {string} */ href) => qr.replaceChildren(qrBox(doc, href, 'Open this page'), make(doc, 'p', 'sheet-link', href));
    sheet.querySelector('.class-sheet-bar')?.prepend(addressField(doc, base, (href) => { this.classAddress = href; showQr(href); }));
    showQr(base);
    sheet.append(this.teacherLinks(), make(doc, 'p', 'sheet-how', 'Before the lesson: open the page once on every laptop (it is then kept there and works without the network), '
      + 'and make the challenge link (Class challenge, For the teacher, at the bottom of the page) so that its QR code is ready.'), qr);
    const table = make(doc, 'table', 'lesson-table');
    table.dataset.testid = 'lesson-table';
    const head = make(doc, 'tr');
    for (const h of ['Minutes', 'Step', 'You project', 'Students do']) head.append(make(doc, 'th', '', h));
    const body = make(doc, 'tbody');
    const times = lessonTimes();
    LESSON.steps.forEach((step, i) => {
      const row = make(doc, 'tr');
      row.append(make(doc, 'td', '', times[i]), make(doc, 'td', '', lessonStepWords(step)), make(doc, 'td', '', step.projects), make(doc, 'td', '', step.students));
      body.append(row);
    });
    const thead = make(doc, 'thead');
    thead.append(head);
    table.append(thead, body);
    sheet.append(table, make(doc, 'p', 'sheet-how', 'Chapters 8 to 11 (a transplanted brain, a search for bodies, your own robot, one brain for every body) are for another lesson or for home: '
      + 'the full worksheet has every chapter\'s link. Two lessons of 45 minutes instead? The answer keys\' sheet and the guide have that plan too.'));
    sheet.scrollIntoView({ block: 'start' });
    return sheet;
  }

  /**
   * The way from the lesson's sheet to the rest of the teacher's material: the lesson's worksheet
   * (its chapters only), the full one, the answer keys, the teachers' guide.
   */
  teacherLinks() {
    const doc = this.doc;
    const nav = make(doc, 'nav', 'lesson-links');
    nav.setAttribute('aria-label', 'The teacher\'s material');
    nav.dataset.testid = 'lesson-links';
    /** @param {string} text @param {string} id @param {string} title @param {() => void} act */
    const button = (text, id, title, act) => {
      const b = /** @type {HTMLButtonElement} */ (make(doc, 'button', '', text));
      b.type = 'button';
      b.dataset.testid = id;
      b.title = title;
      b.addEventListener('click', act);
      return b;
    };
    const guide = /** @type {HTMLAnchorElement} */ (make(doc, 'a', '', 'Teachers\' guide'));
    guide.href = GUIDE.href;
    guide.target = '_blank';
    guide.rel = 'noopener';
    guide.dataset.testid = 'lesson-guide';
    nav.append(
      button(`Worksheet for this lesson (${lessonChaptersWords()}, challenge)`, 'lesson-worksheet', 'The worksheet of this lesson\'s chapters and the challenge box, one per student', () => this.worksheet(true, lessonChapters())),
      button(`Full worksheet (all ${CHAPTERS.length} chapters)`, 'lesson-worksheet-all', 'Every chapter\'s task, for another lesson or for home', () => this.worksheet(true)),
      button('Answer keys', 'lesson-keys', 'Every task\'s answer, computed by the page now, with why', () => void this.keys()),
      guide);
    return nav;
  }

  /** The teacher view: every task with its key, computed one after another. */
  async keys() {
    const doc = this.doc;
    const sheet = this.sheet('teacher-keys', 'Answer keys: predict, then try');
    sheet.dataset.testid = 'teacher-keys';
    sheet.dataset.state = 'computing';
    sheet.append(make(doc, 'p', 'sheet-how', 'Each answer is computed now by this page, as a student\'s Reveal computes it: the numbers come from walks the page just ran or from the study\'s files.'),
      make(doc, 'p', 'sheet-plan'));
    sheet.lastElementChild?.append(...lessonPlanNodes(doc));
    const rows = CHAPTERS.map((chapter, i) => {
      const part = make(doc, 'section', 'sheet-task');
      const key = make(doc, 'p', 'sheet-key', 'computing…');
      key.dataset.testid = 'teacher-key';
      const ex = exerciseOf(i);
      part.append(make(doc, 'h2', '', `Chapter ${i + 1}. ${chapter.title}`), make(doc, 'p', 'sheet-ask', ex?.ask ?? chapter.task));
      if (!ex) key.textContent = 'No task in this chapter: its “Do” above.';
      else if (ex.unavailable?.(this.lab)) key.textContent = `${ex.unavailable(this.lab)} Its task is not asked yet.`;
      else if (ex.choices) part.append(make(doc, 'p', 'sheet-choices-inline', `Choices: ${ex.choices.join(' · ')}`));
      part.append(key);
      sheet.append(part);
      return key;
    });
    for (const [i, row] of rows.entries()) {
      const ex = exerciseOf(i);
      if (!ex || ex.unavailable?.(this.lab)) continue;
      try {
        const key = await ex.key(this.lab);
        row.replaceChildren(make(doc, 'b', '', `Answer: ${key.shown}. `), ...withTerms(doc, key.why));
        row.dataset.answer = String(key.answer);
      } catch (error) {
        row.textContent = `could not be computed: ${messageOf(error)}`;
      }
    }
    sheet.dataset.state = 'done';
  }
}

/**
 * The worksheet's box for the class challenge: the short code the student's page shows after
 * “Share link” (a box a letter, in the code's groups of four: enough for a body of 8 × 5), its
 * speed, and where to write that the link was sent instead. @param {Document} doc
 */
function challengeBox(doc) {
  const part = make(doc, 'section', 'sheet-challenge');
  part.dataset.testid = 'worksheet-challenge';
  const code = make(doc, 'p', 'sheet-code');
  code.setAttribute('aria-label', 'Boxes to write the short code in, a letter a box');
  for (let group = 0; group < 4; group++) {
    // A group of four boxes wraps as a whole on a narrow screen, its dash after it (never alone at a line's start).
    const four = make(doc, 'span', 'sheet-code-group');
    for (let letter = 0; letter < 4; letter++) four.append(make(doc, 'span', 'sheet-code-box'));
    if (group < 3) four.append(make(doc, 'span', 'sheet-code-dash', '–'));
    code.append(four);
  }
  part.append(make(doc, 'h2', '', 'Class challenge: my robot'),
    make(doc, 'p', 'sheet-ask', `After “Share link”, my page shows my robot's short code (like ${EXAMPLE_CODE}). `
      + 'I copy it here, one letter or number in each box (a short code leaves the last boxes empty), and give it to my teacher:'),
    code,
    make(doc, 'p', 'sheet-guess', 'Its speed, as my page says: ____________ m/s'),
    make(doc, 'p', 'sheet-guess', 'My name, as my teacher will list it: ______________________'),
    make(doc, 'p', 'sheet-how', 'No short code? My page says why, under “Share link”. Then I send my teacher the link instead, and tick this box: ☐'));
  return part;
}
