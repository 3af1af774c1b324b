// uqr (npm), the QR codes of the class challenge: scripts/serve.mjs serves it as vendor/uqr.js
// from node_modules, `make site` copies it there (scripts/site.mjs). Its types, for the page's
// type check (tsconfig.json).
export * from 'uqr';
