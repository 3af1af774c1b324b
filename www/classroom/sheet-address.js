// @ts-check
/**
 * The address the worksheet's links open. By default the page's own; but a teacher who opened
 * the page on their own computer (`make run`: 127.0.0.1) would print links no student's device
 * can open, so the sheet shows the address in a field (on screen, not printed), says so when it
 * is this computer's, and rewrites every link when the teacher types the class's address.
 */

/** The page's address without its query and fragment. @param {string} href @returns {string} */
export function pageAddress(href) {
  const url = new URL(href);
  url.search = '';
  url.hash = '';
  return url.href;
}

/** The address of chapter `index` (0-based) at `base` (a page address). @param {number} index @param {string} base */
export function chapterLink(index, base) {
  const url = new URL(base);
  url.search = '';
  url.hash = '';
  url.searchParams.set('chapter', String(index + 1));
  return url.href;
}

/** Whether `href` can be opened only on the computer that serves it. @param {string} href */
export function onlyHere(href) {
  const url = new URL(href);
  return url.protocol === 'file:' || /^(localhost|127(\.\d+){3}|\[::1\]|0\.0\.0\.0)$/.test(url.hostname);
}

/** What a note says of an address {@link onlyHere}: the sheet's field, the large QR code (qr.js). */
export const ONLY_HERE = 'This address opens only on this computer';

/**
 * The field and its note, for the sheet's bar: `changed` gets every valid address typed (an
 * address that is not one is said under the field, and the links stay as they were).
 * @param {Document} doc @param {string} base the address to begin with
 * @param {(base: string) => void} changed
 * @returns {HTMLElement}
 */
export function addressField(doc, base, changed) {
  const box = doc.createElement('div');
  box.className = 'sheet-address';
  const label = doc.createElement('label');
  label.textContent = 'Links open at ';
  const input = doc.createElement('input');
  input.type = 'url';
  input.value = base;
  input.dataset.testid = 'worksheet-address';
  input.title = 'The address your students open: the sheet\'s links are printed with it';
  label.append(input);
  const note = doc.createElement('p');
  note.className = 'sheet-address-note';
  note.dataset.testid = 'worksheet-address-note';
  const say = (/** @type {string} */ href) => {
    note.textContent = onlyHere(href)
      ? `${ONLY_HERE}: type the address your students open, then Print.`
      : '';
  };
  input.addEventListener('input', () => {
    let href;
    try {
      href = pageAddress(input.value.trim());
    } catch {
      note.textContent = `“${input.value}” is not an address (it begins with https://): the links are unchanged.`;
      return;
    }
    say(href);
    changed(href);
  });
  say(base);
  box.append(label, note);
  return box;
}
