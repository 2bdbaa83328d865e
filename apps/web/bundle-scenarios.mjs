// Writes every scenario file of a folder into one ES module for the page's picker:
//   node apps/web/bundle-scenarios.mjs scenarios build-web/site/scenarios.js
// The export is [{name, file, text}], handout files (part*) first, each group by name, as the
// viewer's picker orders them.
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const [folder, output] = process.argv.slice(2);
const names = readdirSync(folder).filter((name) => name.endsWith('.toml'));
const handout = (name) => (name.startsWith('part') ? 0 : 1);
names.sort((a, b) => handout(a) - handout(b) || (a < b ? -1 : a > b ? 1 : 0));
const entries = names.map((name) => ({
    name: name.replace(/\.toml$/, ''),
    file: `${folder}/${name}`,
    text: readFileSync(join(folder, name), 'utf8'),
}));
writeFileSync(output, `export const scenarios = ${JSON.stringify(entries, null, 1)};\n`);
