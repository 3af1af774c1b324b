// @ts-check
/**
 * The guides in docs/ as readable web pages: one Markdown file in, one HTML page out, rendered
 * by marked (GitHub's flavour: tables, heading anchors as GitHub makes them, so `RESULTS.md#x`
 * links keep working). Used by `make site` (scripts/site.mjs writes docs/NAME.html for every
 * guide the page links, and every guide those link) and by the developer's server
 * (scripts/serve.mjs answers /docs/NAME.html from docs/NAME.md), so a guide reads the same in
 * both.
 *
 * Links between guides become links between their pages (`lessons.md#x` -> `lessons.html#x`);
 * a link to a file the site holds (a study figure, docs/img/) stays as it is; a link to any
 * other file of the repository (a campaign file, the code) points at the repository's copy when
 * a source address is given (`SITE_SOURCE_URL`, set by the GitHub Pages workflow), else it is
 * shown as its words alone, never as a link that would 404.
 */
import path from 'node:path';
import { Marked } from 'marked';
import { gfmHeadingId } from 'marked-gfm-heading-id';

/** Folders of the repository that the site and the developer's server serve beside the page. */
export const SITE_FOLDERS = Object.freeze(['docs/', 'study/', 'pretrained/']);

/**
 * Where a link of a guide goes, as a repository path (posix, from the repository's root) and
 * its fragment, or null for a link that leaves the repository (another site, a mail) or stays
 * in the page (`#x`).
 * @param {string} doc the guide's repository path, e.g. 'docs/teaching.md' @param {string} href
 * @returns {{file: string, fragment: string} | null}
 */
export function linkTarget(doc, href) {
  if (/^[a-z][a-z0-9+.-]*:/i.test(href) || href.startsWith('#') || href.startsWith('//') || href === '') return null;
  const at = href.indexOf('#');
  const [target, fragment] = at < 0 ? [href, ''] : [href.slice(0, at), href.slice(at)];
  let file;
  try { file = decodeURI(target); } catch { file = target; }
  file = path.posix.normalize(path.posix.join(path.posix.dirname(doc), file));
  if (file.startsWith('../')) return null; // outside the repository: nothing to say about it
  return { file, fragment };
}

/** The page a guide becomes: docs/NAME.md -> docs/NAME.html. @param {string} file */
export function pageOf(file) {
  return file.replace(/\.md$/, '.html');
}

/** Whether a repository path is a guide (docs/NAME.md). @param {string} file */
export function isGuide(file) {
  return /^docs\/[^/]+\.md$/.test(file);
}

/**
 * The repository files a guide links or shows (guides, figures, images), with the links'
 * words: read with marked's own lexer.
 * @param {string} doc its repository path @param {string} markdown
 * @returns {{file: string, image: boolean}[]}
 */
export function linkedFiles(doc, markdown) {
  /** @type {{file: string, image: boolean}[]} */
  const found = [];
  const marked = new Marked();
  marked.walkTokens(marked.lexer(markdown), (token) => {
    if (token.type !== 'link' && token.type !== 'image') return;
    const target = linkTarget(doc, token.href);
    if (target) found.push({ file: target.file, image: token.type === 'image' });
  });
  return found;
}

/** @param {string} text */
function escapeHtml(text) {
  return text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c] ?? c);
}

/** The guides' look: readable lines, tables with rules, figures no wider than the screen. */
const STYLE = `
  body { font: 17px/1.55 system-ui, -apple-system, "Segoe UI", sans-serif; color: #1d232a; background: #fff;
    max-width: 52rem; margin: 0 auto; padding: 1rem 1.25rem 4rem; }
  header.doc-bar { display: flex; gap: 1rem; align-items: baseline; flex-wrap: wrap; border-bottom: 1px solid #d5dbe1;
    padding-bottom: .5rem; margin-bottom: 1rem; font-size: .95rem; }
  a { color: #0b5cad; }
  h1, h2, h3 { line-height: 1.25; margin-top: 1.8em; }
  h1 { margin-top: .6em; }
  code { font: .9em/1.4 ui-monospace, "SFMono-Regular", Menlo, Consolas, monospace; background: #f1f3f5; padding: .05em .3em; border-radius: 3px; }
  pre { background: #f1f3f5; padding: .75rem 1rem; overflow-x: auto; border-radius: 4px; }
  pre code { background: none; padding: 0; }
  table { border-collapse: collapse; margin: 1rem 0; display: block; overflow-x: auto; }
  th, td { border: 1px solid #c9d1d9; padding: .3rem .6rem; text-align: left; vertical-align: top; }
  th { background: #f1f3f5; }
  img { max-width: 100%; height: auto; }
  blockquote { border-left: 4px solid #d5dbe1; margin-left: 0; padding-left: 1rem; color: #4a5561; }
  @media print { header.doc-bar { display: none; } body { max-width: none; } table { display: table; font-size: .85em; } tr { break-inside: avoid; } }
  /* A phone: tight cells, so that a table of a few columns (the teachers' guide's lesson) fits
     without a sideways scroll; a wider one still scrolls in its own box. */
  @media (max-width: 600px) { body { padding: 1rem .75rem 4rem; } table { font-size: .85em; } th, td { padding: .25rem .35rem; } }
`;

/**
 * A guide as a whole HTML page: its words rendered by marked, its links pointing where they
 * work on the site (see the file's comment).
 * @param {string} doc its repository path, e.g. 'docs/teaching.md'
 * @param {string} markdown its text
 * @param {{inSite: (file: string) => boolean, source?: string}} where inSite: whether the site
 *   (or the server) has a repository file; source: the repository's address for the others
 * @returns {string}
 */
export function renderDoc(doc, markdown, { inSite, source = '' }) {
  /** @type {Set<object>} links that lead nowhere on the site: shown as their words */
  const dead = new Set();
  const marked = new Marked({ gfm: true });
  marked.use(gfmHeadingId());
  marked.use({
    walkTokens(token) {
      if (token.type !== 'link' && token.type !== 'image') return;
      const target = linkTarget(doc, token.href);
      if (!target) return;
      const relative = (/** @type {string} */ file) => path.posix.relative(path.posix.dirname(doc), file) + target.fragment;
      if (isGuide(target.file) && inSite(target.file)) token.href = relative(pageOf(target.file));
      else if (inSite(target.file)) token.href = relative(target.file);
      else if (source) token.href = `${source.replace(/\/$/, '')}/${target.file}${target.fragment}`;
      else dead.add(token);
    },
    renderer: {
      link(token) {
        if (!dead.has(token)) return false; // marked's own rendering
        return `<span class="doc-file" title="${escapeHtml(token.href)} (in the repository, not on this site)">${this.parser.parseInline(token.tokens)}</span>`;
      },
      image(token) {
        if (!dead.has(token)) return false;
        return `<em>[${escapeHtml(token.text)}]</em>`;
      },
    },
  });
  const body = /** @type {string} */ (marked.parse(markdown));
  const title = /^#\s+(.+)$/m.exec(markdown)?.[1]?.replace(/[*_`]/g, '') ?? path.posix.basename(doc);
  return `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>${escapeHtml(title)} · VSR Playground</title>
  <link rel="icon" href="data:,">
  <style>${STYLE}</style>
</head>
<body>
  <header class="doc-bar"><a href="../" data-testid="doc-home">← VSR Playground</a><span>${escapeHtml(path.posix.basename(doc))}</span></header>
  <main data-testid="doc">
${body}
  </main>
</body>
</html>
`;
}
