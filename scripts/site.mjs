// @ts-check
/**
 * `make site`: the playground as one folder any static web server hosts, at any sub-path
 * (GitHub Pages, a school's server, `python3 -m http.server`), and that works offline after the
 * first visit. Writes target/site/ (SITE_OUT overrides):
 *
 *   index.html            the page (www/index.html), its own files' addresses pointing into app-V/
 *   app-V/                www/ as the page loads it: its scripts, styles, workers and the wasm
 *                         core (www/pkg: run `make wasm` first), with the npm libraries it imports
 *                         (vendor/); V is the site's version, a hash of every file of the site, so
 *                         a browser never keeps an old script beside a new core
 *   sw.js                 the service worker (www/offline/service-worker.js) with the version and
 *                         the list of files it keeps for offline use (every file of the site but
 *                         the study's run files, which it keeps once opened, and the link
 *                         preview's image, app-V/preview.png, which only a link preview reads)
 *   pretrained/           manifest.json and the modules and bodies it lists
 *   study/                the study's tables, figures and claim file the page shows, and the run
 *                         file of every run the study panel lists (the page's own lists decide:
 *                         tour/figures.js, tour/study-runs.js, tour/claim.js)
 *   docs/NAME.html        every guide the page links, and every guide those link, rendered from
 *                         docs/NAME.md (scripts/docs-html.mjs), with the images they show
 *
 * Every address in it is relative, so the folder works at any sub-path. Nothing else is copied.
 * SITE_SOURCE_URL (e.g. https://github.com/OWNER/REPO/blob/SHA, set by the Pages workflow) is
 * where a guide's links to other files of the repository point; without it they are plain words.
 * SITE_URL (the site's own address, set by the Pages workflow) makes the link preview's image
 * (og:image) a whole address, as link previews want; without it, it is relative.
 *
 *   node scripts/site.mjs            # or `make site`
 *
 * Also importable: `buildSite({ out })` returns what it wrote.
 */
import { createHash } from 'node:crypto';
import { existsSync } from 'node:fs';
import { mkdir, readFile, readdir, rename, rm, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { isGuide, linkedFiles, pageOf, renderDoc } from './docs-html.mjs';
import { VENDOR } from './serve.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
export const ROOT = path.resolve(HERE, '..');
const WWW = path.join(ROOT, 'www');
/** The service worker's source in www/, and its name at the site's root (its scope is the whole site). */
const SERVICE_WORKER = 'offline/service-worker.js';
export const SW_NAME = 'sw.js';

/** Files of www/ that are not the page: the embedding example (docs/embed.md), and what wasm-pack writes for npm. */
const NOT_THE_PAGE = [/^embed\//, /^pkg\/(README\.md|package\.json|\.gitignore)$/, /\.d\.ts$/, new RegExp(`^${SERVICE_WORKER}$`)];

/** @param {string} dir @param {string} [under] @returns {Promise<string[]>} files under `dir`, posix paths relative to it */
async function walk(dir, under = '') {
  /** @type {string[]} */
  const files = [];
  for (const entry of await readdir(path.join(dir, under), { withFileTypes: true })) {
    const rel = under ? `${under}/${entry.name}` : entry.name;
    if (entry.isDirectory()) files.push(...await walk(dir, rel));
    else if (entry.isFile()) files.push(rel);
  }
  return files.sort();
}

/** @param {string} file a repository path @returns {Promise<Buffer>} */
function repoFile(file) {
  return readFile(path.join(ROOT, file)).catch(() => { throw new Error(`${file} is missing: the site needs it`); });
}

/**
 * The study's files the page reads: its tables, figures and claim file, and the runs its study
 * panel lists, as the page's own modules name them.
 * @returns {Promise<string[]>} repository paths
 */
async function studyFiles() {
  const { FIGURES, TABLES, CLAIM_TABLE, STUDY_DIR, figureSrc } = await import(pathToFileURL(path.join(WWW, 'tour/figures.js')).href);
  const { parseCampaign, runsOf } = await import(pathToFileURL(path.join(WWW, 'tour/study-runs.js')).href);
  const { CLAIM_FILE } = await import(pathToFileURL(path.join(WWW, 'tour/claim.js')).href);
  const tables = [...TABLES, CLAIM_TABLE];
  /** @type {import('../www/tour/study-runs.js').StudyRun[]} */
  const rows = [];
  for (const t of tables) rows.push(...parseCampaign((await repoFile(`${STUDY_DIR}${t}`)).toString('utf8'), t));
  const runs = new Set(FIGURES.flatMap((/** @type {any} */ f) => runsOf(f, rows).map((/** @type {{run: string}} */ r) => `${STUDY_DIR}runs/${r.run}.json`)));
  return [...tables.map((t) => `${STUDY_DIR}${t}`), CLAIM_FILE, ...FIGURES.map(figureSrc), ...[...runs].sort()];
}

/** The pretrained modules: the manifest and every file it lists. @returns {Promise<string[]>} */
async function pretrainedFiles() {
  const manifest = JSON.parse((await repoFile('pretrained/manifest.json')).toString('utf8'));
  return ['pretrained/manifest.json', ...[...(manifest.modules ?? []), ...(manifest.bodies ?? [])].map((m) => `pretrained/${m.file}`)];
}

/**
 * The guides the page links (a `docs/NAME.md` or `docs/NAME.html` in its files), and every guide
 * and image those link, in turn.
 * @param {Map<string, Buffer>} page the page's files by path in www/
 * @returns {Promise<{guides: string[], shown: string[]}>} guides and other linked files, repository paths
 */
async function docFiles(page) {
  const queue = new Set();
  for (const [file, bytes] of page) {
    if (!/\.(js|html)$/.test(file)) continue;
    for (const m of bytes.toString('utf8').matchAll(/\bdocs\/([\w.-]+)\.(?:md|html)\b/g)) {
      if (existsSync(path.join(ROOT, 'docs', `${m[1]}.md`))) queue.add(`docs/${m[1]}.md`);
    }
  }
  const guides = new Set();
  const shown = new Set();
  for (const doc of queue) {
    if (guides.has(doc)) continue;
    guides.add(doc);
    for (const { file } of linkedFiles(doc, (await repoFile(doc)).toString('utf8'))) {
      if (!existsSync(path.join(ROOT, file))) continue;
      if (isGuide(file)) queue.add(file);
      else if (/^(docs|study|pretrained)\//.test(file)) shown.add(file);
    }
  }
  return { guides: [...guides].sort(), shown: [...shown].sort() };
}

/**
 * The page's index.html for the site: its own files' addresses (style sheets, the main
 * script) into the versioned folder, and the site's version for offline.js.
 * @param {string} html @param {Map<string, Buffer>} page @param {string} app the versioned folder, e.g. 'app-1a2b/' @param {string} version
 * @param {string} [url] the site's own address (SITE_URL, ending in /), if known
 */
function siteIndex(html, page, app, version, url = '') {
  const out = html.replace(/\b(href|src)="([^"#:?]+)"/g, (all, attr, ref) => (page.has(ref) ? `${attr}="${app}${ref}"` : all))
    // The link preview's image: relative, or at the site's address when it is known (a preview reader wants a whole address).
    .replace(/(<meta (?:property|name)="(?:og|twitter):image" content=")([^"#:?]+)"/g, (all, head, ref) => (page.has(ref) ? `${head}${url}${app}${ref}"` : all));
  const meta = `<meta name="vsr-site" content="${version}">${url ? `\n  <meta property="og:url" content="${url}">` : ''}`;
  return out.replace('<meta charset="utf-8">', `<meta charset="utf-8">\n  ${meta}`);
}

/** The page's preview image for link previews (index.html's og:image), not kept for offline use. */
export const PREVIEW = 'preview.png';

/**
 * Builds the site into `out` (replaced whole).
 * @param {{out?: string, source?: string, url?: string, salt?: string, log?: (line: string) => void}} [options] salt: mixed
 *   into the version (a test's second build of the same files, as a new version); url: the site's address (SITE_URL), for
 *   the link preview's image
 * @returns {Promise<{out: string, version: string, files: string[], bytes: number, precache: string[]}>}
 */
export async function buildSite({ out = process.env.SITE_OUT ?? path.join(ROOT, 'target', 'site'), source = process.env.SITE_SOURCE_URL ?? '',
  url = process.env.SITE_URL ?? '', salt = '', log = console.log } = {}) {
  if (!existsSync(path.join(WWW, 'pkg', 'vsr_bg.wasm'))) throw new Error('www/pkg/vsr_bg.wasm is missing: build the wasm core first (`make wasm`)');
  /** The page's files by path in www/ (index.html apart), the vendored libraries with them. @type {Map<string, Buffer>} */
  const page = new Map();
  for (const file of await walk(WWW)) {
    if (file === 'index.html' || NOT_THE_PAGE.some((re) => re.test(file))) continue;
    page.set(file, await readFile(path.join(WWW, file)));
  }
  for (const [url, file] of Object.entries(VENDOR)) page.set(url.replace(/^\//, ''), await readFile(file));

  /** The data files by their path in the site (= their repository path). @type {Map<string, Buffer>} */
  const data = new Map();
  for (const file of [...await pretrainedFiles(), ...await studyFiles()]) data.set(file, await repoFile(file));
  const { guides, shown } = await docFiles(page);
  for (const file of shown) data.set(file, await repoFile(file));
  const inSite = (/** @type {string} */ file) => data.has(file) || guides.includes(file);
  for (const doc of guides) data.set(pageOf(doc), Buffer.from(renderDoc(doc, (await repoFile(doc)).toString('utf8'), { inSite, source })));

  // Every module a tour chapter opens is in the site (the page would 404 on it otherwise).
  const { CHAPTERS } = await import(pathToFileURL(path.join(WWW, 'tour/chapters.js')).href);
  for (const ch of CHAPTERS) {
    for (const m of [ch.setup?.brain?.module, ...(ch.setup?.race ?? [])].filter(Boolean)) {
      if (!data.has(m)) throw new Error(`chapter "${ch.title}" opens ${m}, which the site does not hold`);
    }
  }

  const index = await readFile(path.join(WWW, 'index.html'), 'utf8');
  const worker = await readFile(path.join(WWW, SERVICE_WORKER), 'utf8');
  const hash = createHash('sha256').update(salt);
  for (const [name, bytes] of [...page, ...data, ['index.html', Buffer.from(index)], [SW_NAME, Buffer.from(worker)]]) {
    hash.update(`${name}\0${bytes.length}\0`);
    hash.update(/** @type {Buffer} */ (bytes));
  }
  const version = hash.digest('hex').slice(0, 12);
  const app = `app-${version}/`;

  /** The site's files by path. @type {Map<string, Buffer>} */
  const site = new Map();
  site.set('index.html', Buffer.from(siteIndex(index, page, app, version, url && `${url.replace(/\/*$/, '')}/`)));
  for (const [file, bytes] of page) site.set(app + file, bytes);
  for (const [file, bytes] of data) site.set(file, bytes);
  // Kept for offline use on the first visit: everything but the study's run files (kept once opened).
  const precache = ['./', ...[...site.keys()].filter((f) => f !== 'index.html' && f !== app + PREVIEW && !/^study\/runs\//.test(f))].sort();
  site.set(SW_NAME, Buffer.from(`self.VSR_SITE = ${JSON.stringify({ version, precache })};\n${worker}`));

  const staging = `${out}.tmp`;
  await rm(staging, { recursive: true, force: true });
  for (const [file, bytes] of site) {
    await mkdir(path.dirname(path.join(staging, file)), { recursive: true });
    await writeFile(path.join(staging, file), bytes);
  }
  await rm(out, { recursive: true, force: true });
  await rename(staging, out);
  const bytes = [...site.values()].reduce((sum, b) => sum + b.length, 0);
  const kept = precache.reduce((sum, f) => sum + (site.get(f === './' ? 'index.html' : f)?.length ?? 0), 0);
  log(`site ${version}: ${site.size} files, ${(bytes / 1e6).toFixed(1)} MB in ${path.relative(process.cwd(), out) || out}`
    + ` (${guides.length} guides; kept offline on the first visit: ${(kept / 1e6).toFixed(1)} MB)`);
  return { out, version, files: [...site.keys()].sort(), bytes, precache };
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  try {
    await buildSite();
  } catch (error) {
    console.error(`make site: ${error instanceof Error ? error.message : error}`);
    process.exit(1);
  }
}
