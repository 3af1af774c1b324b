// @ts-check
/**
 * The teacher's ranking table: the placed entries, fastest first, then the entries without a
 * place, each with why in its note (entries.js decides which is which). A speed a short
 * code claims (not checked here yet) says “claimed” beside it; a measured one does not.
 */
import { decimal } from '../../shared/format.js';

const HEAD = Object.freeze(['place', 'name', 'body', 'brain', 'speed', 'note']);

/**
 * Fills `table` with the ranking.
 * @param {HTMLTableElement} table @param {{placed: import('./entries.js').Entry[], others: import('./entries.js').Entry[]}} ranking
 * @param {string} caption which rules the class was ranked by
 */
export function showRanking(table, ranking, caption) {
  const doc = /** @type {Document} */ (table.ownerDocument);
  table.replaceChildren();
  table.hidden = false;
  table.createCaption().textContent = caption;
  const head = table.createTHead().insertRow();
  for (const h of HEAD) {
    const th = doc.createElement('th');
    th.scope = 'col';
    th.textContent = h;
    head.append(th);
  }
  const body = table.createTBody();
  const rows = [...ranking.placed.map((e, i) => ({ e, place: String(i + 1) })), ...ranking.others.map((e) => ({ e, place: '–' }))];
  for (const { e, place } of rows) {
    const row = body.insertRow();
    row.dataset.testid = 'challenge-entry';
    row.dataset.problem = String(e.problem !== '');
    row.dataset.claimed = String(e.claimed);
    const measured = Number.isFinite(e.speed);
    const note = [e.problem, ...e.notes].filter((n) => n !== '').join('; ');
    for (const c of [place, e.name, e.rows || '–', e.brain || '–', measured ? `${decimal(e.speed)} m/s${e.claimed ? ' claimed' : ''}` : '–', note]) row.insertCell().textContent = c;
    // A body may break between its rows, after each "-", and nowhere else.
    row.cells[2].replaceChildren(...e.rows.split('-').flatMap((part, i) => (i ? ['-', doc.createElement('wbr'), part] : [part])));
    if (!e.rows) row.cells[2].textContent = '–';
    if (measured) row.cells[4].dataset.value = String(e.speed);
  }
}
