// @ts-check
/**
 * A tiny static file server for www/ (module workers need http, and wasm needs the
 * application/wasm type for streaming compilation). Serves on 127.0.0.1 only, GET and
 * HEAD only. The repository's pretrained/ run files are also served, read-only, at
 * /pretrained/ (the page lists them from /pretrained/manifest.json), without a copy; so
 * are its docs/ at /docs/ (the page links the study's results) and study/ at /study/ (the
 * page shows the study's figures and walks its runs' bests). A guide asked as /docs/NAME.html is
 * rendered from docs/NAME.md (scripts/docs-html.mjs, as `make site` renders it), and the npm
 * libraries the page uses are served from node_modules/ at /vendor/ (VENDOR; `make site` copies
 * them). `make site` (scripts/site.mjs) builds the same page as a folder any static server hosts.
 *
 *   node scripts/serve.mjs          # http://127.0.0.1:8080, or PORT=9000 node ...
 *
 * Also importable: `serve({ root, port: 0 })` gives a free port for tests.
 */
import { createReadStream } from 'node:fs';
import { readFile, stat } from 'node:fs/promises';
import { createServer } from 'node:http';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { isGuide, renderDoc } from './docs-html.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
/** The folder served by default. */
export const WWW = path.resolve(HERE, '..', 'www');
/** Folders served under a URL prefix instead of from `root`. */
export const MOUNTS = Object.freeze({
  '/pretrained/': path.resolve(HERE, '..', 'pretrained'),
  '/docs/': path.resolve(HERE, '..', 'docs'), // the study's results, linked from the page
  '/study/': path.resolve(HERE, '..', 'study'), // the study's figures, runs and table of runs
});

/** The npm libraries the page imports, by the address it imports them at, and the file each is. */
export const VENDOR = Object.freeze({
  '/vendor/uqr.js': path.resolve(HERE, '..', 'node_modules', 'uqr', 'dist', 'index.mjs'), // QR codes (the class challenge)
});

/** Content types by file extension. */
const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.ts': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.csv': 'text/csv; charset=utf-8',
};

/** The headers of every answer. */
const HEADERS = Object.freeze({
  'cache-control': 'no-store',
  // Cross-origin isolation: finer performance.now() in the worker (the engine-speed
  // figure) and SharedArrayBuffer for later multi-worker runs. Everything is same-origin.
  'cross-origin-opener-policy': 'same-origin',
  'cross-origin-embedder-policy': 'require-corp',
  // Other origins may load these files (an embedded <vsr-robot> from this server).
  'access-control-allow-origin': '*',
});

/**
 * Starts serving `root` (and `mounts`) on 127.0.0.1.
 * @param {{root?: string, port?: number, mounts?: Record<string, string>}} [options]
 *   port 0 picks a free port; mounts maps URL prefixes ending in '/' to folders
 * @returns {Promise<{server: import('node:http').Server, url: string}>}
 */
export function serve({ root = WWW, port = 8080, mounts = MOUNTS } = {}) {
  const server = createServer((req, res) => {
    handle(root, mounts, req, res).catch((error) => {
      res.writeHead(500, { 'content-type': 'text/plain' });
      res.end(String(error));
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => {
      const address = /** @type {import('node:net').AddressInfo} */ (server.address());
      resolve({ server, url: `http://127.0.0.1:${address.port}/` });
    });
  });
}

/**
 * @param {string} root
 * @param {Record<string, string>} mounts
 * @param {import('node:http').IncomingMessage} req
 * @param {import('node:http').ServerResponse} res
 */
async function handle(root, mounts, req, res) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    res.writeHead(405, { allow: 'GET, HEAD' }).end();
    return;
  }
  let urlPath;
  try { // an address that is no path ('//', a lone '%') is the asker's mistake, not the server's
    urlPath = decodeURIComponent(new URL(`http://localhost${req.url ?? '/'}`).pathname);
  } catch {
    res.writeHead(400, { 'content-type': 'text/plain' }).end(`bad request: ${req.url}`);
    return;
  }
  const guide = /^\/docs\/([^/]+)\.html$/.exec(urlPath);
  if (guide && mounts['/docs/'] && isGuide(`docs/${guide[1]}.md`)) {
    const md = await readFile(path.join(mounts['/docs/'], `${guide[1]}.md`), 'utf8').catch(() => null);
    if (md !== null) {
      const html = renderDoc(`docs/${guide[1]}.md`, md, { inSite: (file) => file.startsWith('docs/') || file.startsWith('study/') || file.startsWith('pretrained/') });
      res.writeHead(200, { ...HEADERS, 'content-type': MIME['.html'], 'content-length': Buffer.byteLength(html) });
      res.end(req.method === 'HEAD' ? undefined : html);
      return;
    }
  }
  const vendored = VENDOR[/** @type {keyof typeof VENDOR} */ (urlPath)];
  const prefix = vendored ? undefined : Object.keys(mounts).find((p) => urlPath.startsWith(p));
  const base = prefix ? mounts[prefix] : root;
  let file = vendored ?? path.resolve(base, '.' + (prefix ? urlPath.slice(prefix.length - 1) : urlPath));
  if (!vendored && file !== base && !file.startsWith(base + path.sep)) {
    res.writeHead(403).end('forbidden');
    return;
  }
  let info = await stat(file).catch(() => null);
  if (info?.isDirectory()) {
    file = path.join(file, 'index.html');
    info = await stat(file).catch(() => null);
  }
  if (!info?.isFile()) {
    res.writeHead(404, { 'content-type': 'text/plain' }).end(`not found: ${urlPath}`);
    return;
  }
  res.writeHead(200, {
    ...HEADERS,
    'content-type': MIME[/** @type {keyof MIME} */ (path.extname(vendored ? 'vendored.js' : file).toLowerCase())] ?? 'application/octet-stream',
    'content-length': info.size,
  });
  if (req.method === 'HEAD') res.end();
  else createReadStream(file).pipe(res);
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  const port = Number(process.env.PORT ?? 8080);
  const { url } = await serve({ port });
  console.log(`Serving www/ (and pretrained/) at ${url}  (Ctrl-C to stop)`);
}
