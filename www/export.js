// @ts-check
/** Downloading a run file from the page, under a name that says what it holds. */

/** A download name that says what the run file holds. @param {string} runFile */
export function runFileName(runFile) {
  const { config } = JSON.parse(runFile);
  return `${config.source ? `finetuned-${config.controller}` : `evolved-${config.controller}`}-seed${config.seed}.json`;
}

/** Saves `text` as the file `name`. @param {string} text @param {string} name */
export function download(text, name) {
  const url = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
