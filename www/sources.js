// @ts-check
/**
 * The controller source picker: "Phase gait", a pretrained run file listed in
 * pretrained/manifest.json (fetched over http), a run file loaded from disk, or the best
 * individual evolved in the page (evolve.js). It only
 * reads files into {@link RunFileSource}s; the worker validates them, so a malformed file
 * is reported by the worker and the robot that runs keeps running.
 */

/** Picker key of the phase gait. */
export const GAIT_KEY = 'gait';
/** Where the served pretrained run files are listed (scripts/serve.mjs mounts pretrained/). */
const PRETRAINED_DIR = 'pretrained/';
/** Key prefix of a file loaded from disk (one such option at a time). */
const DISK_PREFIX = 'disk:';

/** @typedef {import('./protocol.js').RunFileSource} RunFileSource */

export class SourcePicker {
  /**
   * @param {HTMLSelectElement} select the source list
   * @param {HTMLInputElement} fileInput an <input type=file> for run files from disk
   * @param {(source: RunFileSource | null) => void} onPick called with the chosen run file,
   *   or null for the phase gait
   * @param {(text: string) => void} onError called when a file cannot be fetched or read
   */
  constructor(select, fileInput, onPick, onError) {
    this.select = select;
    this.fileInput = fileInput;
    this.onPick = onPick;
    this.onError = onError;
    /** The key of the source that drives the robot now (shown when a pick fails). */
    this.shown = GAIT_KEY;
    /**
     * Sources with an option that cannot be fetched again: the file from disk (one at a
     * time) and the page's evolved best, by key.
     * @type {Map<string, RunFileSource>}
     */
    this.held = new Map();
    select.append(new Option('Phase gait', GAIT_KEY));
    select.addEventListener('change', () => { this.pickSelected(); });
    fileInput.addEventListener('change', () => { this.pickFile(); });
  }

  /**
   * Adds one option per module of the pretrained manifest.
   * @returns {Promise<void>} resolves once listed; a failure is reported through onError
   */
  async listPretrained() {
    try {
      const manifest = await fetchOk(`${PRETRAINED_DIR}manifest.json`).then((r) => r.json());
      for (const m of manifest.modules ?? []) {
        const median = Number(m.validation_median);
        const speed = Number.isFinite(median) ? `, ${median.toFixed(2)} m/s` : '';
        const label = `${String(m.file).replace(/\.json$/, '')} (${m.controller}${speed})`;
        this.select.append(new Option(label, PRETRAINED_DIR + m.file));
      }
    } catch (error) {
      this.onError(`could not list the pretrained controllers: ${messageOf(error)}`);
    }
  }

  /**
   * Shows `source` as the current choice (adding an option for a file from disk).
   * @param {RunFileSource | null} source the source that drives the robot now
   */
  show(source) {
    const key = source?.key ?? GAIT_KEY;
    const existing = [...this.select.options].find((o) => o.value === key);
    if (source && existing) existing.text = source.label; // e.g. a newer evolved best
    if (source && !existing) {
      for (const o of [...this.select.options]) {
        if (key.startsWith(DISK_PREFIX) && o.value.startsWith(DISK_PREFIX)) { o.remove(); this.held.delete(o.value); }
      }
      this.select.append(new Option(source.label, key));
    }
    if (source && !key.startsWith(PRETRAINED_DIR)) this.held.set(key, source);
    this.select.value = key;
    this.shown = key;
  }

  async pickSelected() {
    const key = this.select.value;
    if (key === GAIT_KEY) { this.onPick(null); return; }
    const held = this.held.get(key);
    if (held) { this.onPick(held); return; }
    const label = this.select.selectedOptions[0]?.text ?? key;
    try {
      const text = await fetchOk(key).then((r) => r.text());
      this.onPick({ key, label, text });
    } catch (error) {
      this.select.value = this.shown;
      this.onError(`could not fetch ${key}: ${messageOf(error)}`);
    }
  }

  async pickFile() {
    const file = this.fileInput.files?.[0];
    if (!file) return;
    this.fileInput.value = ''; // choosing the same file again fires 'change' again
    try {
      const text = await file.text();
      this.onPick({ key: DISK_PREFIX + file.name, label: `${file.name} (from disk)`, text });
    } catch (error) {
      this.onError(`could not read ${file.name}: ${messageOf(error)}`);
    }
  }
}

/** @param {string} url @returns {Promise<Response>} the response, or throws on an HTTP error */
async function fetchOk(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  return response;
}

/** @param {unknown} error */
function messageOf(error) {
  return error instanceof Error ? error.message : String(error);
}
