// @ts-check
/**
 * Downloads from the page: a run file under a name that says what it holds, and tables as CSV
 * (a run's generations, a race's distances) for a class to graph in a spreadsheet.
 */

/** A download name that says what the run file holds. @param {string} runFile */
export function runFileName(runFile) {
  const { config } = JSON.parse(runFile);
  return `${config.source ? `finetuned-${config.controller}` : `evolved-${config.controller}`}-seed${config.seed}.json`;
}

/** Saves `text` as the file `name`. @param {string} text @param {string} name @param {string} [type] its media type */
export function download(text, name, type = 'application/json') {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/**
 * A table as CSV (RFC 4180: a header row, commas, CRLF line ends; a cell with a comma, a quote
 * or a line break quoted). A number is written in full (every digit JavaScript keeps), a
 * missing one (NaN, null) as an empty cell.
 * @param {string[]} header @param {(string | number | null)[][]} rows @returns {string}
 */
export function csv(header, rows) {
  const cell = (/** @type {string | number | null} */ v) => {
    if (typeof v === 'number') return Number.isFinite(v) ? String(v) : '';
    if (v === null) return '';
    return /[",\r\n]/.test(v) ? `"${v.replace(/"/g, '""')}"` : v;
  };
  return [header, ...rows].map((row) => row.map(cell).join(',')).join('\r\n') + '\r\n';
}

/** Saves a table as the CSV file `name`. @param {string} name @param {string[]} header @param {(string | number | null)[][]} rows */
export function downloadCsv(name, header, rows) {
  download(csv(header, rows), name, 'text/csv');
}
