// @ts-check
/**
 * A guess kept as it was given: a task whose answer the page itself starts to show (chapter
 * 5's run prints each generation's best as it goes) locks the student's guess once that
 * begins (`Exercise.lock`, exercises.js), so what Reveal grades is a prediction, not a
 * reading. A guess not given before then stays open (nothing to keep); a locked guess stays
 * locked while the page is open, the chapter left and opened again included.
 */

/** What the box says under a locked guess. */
export const LOCKED = 'Your guess is locked in: you gave it before your run began showing its speeds.';
/** How often the box looks whether its guess must lock (ms). */
const LOOK_MS = 500;

/**
 * Locks the guess inputs of `box` now if `locked` holds its chapter, else once `showing()`
 * gives something new (not null: chapter 5's latest run of its own) while the guess in the box
 * was given before it came; then adds the line saying so. A guess given while the page already
 * showed the answer is not locked: it was no prediction.
 * @param {{box: HTMLElement, index: number, locked: Set<number>, given: () => string, showing: () => object | null}} at
 */
export function keepGuess({ box, index, locked, given, showing }) {
  const lock = () => {
    for (const input of box.querySelectorAll('input')) input.disabled = true;
    const said = box.ownerDocument.createElement('p');
    said.className = 'exercise-locked';
    said.dataset.testid = 'tour-guess-locked';
    said.textContent = LOCKED;
    box.querySelector('.exercise-bar')?.before(said);
  };
  if (locked.has(index)) { lock(); return; }
  let shown = showing(); // what the page showed when the box last looked
  let predicted = false; // whether the guess was given by then
  const timer = setInterval(() => {
    if (!box.isConnected) { clearInterval(timer); return; }
    const now = showing();
    if (now === shown || now === null) {
      shown = now;
      predicted = given() !== '';
      return;
    }
    if (!predicted) { shown = now; return; }
    clearInterval(timer);
    locked.add(index);
    lock();
  }, LOOK_MS);
}
