// The report in a real browser (run by tests/cli/browser.rs; see docs/testing.md).
//
//   node check.mjs --report DIR/index.html --latex FILE --screenshot OUT.png
//                  --claims N --failing id1,id2,... --figures N [--top TOP.png]
//
// Debian's Chromium, headless, driven by playwright-core (no browser download), opens the
// report from the file system and fails (exit status 1, one line per problem) on: a console
// error or a page error; no #verdicts table, or a row count other than --claims; an errata
// section missing one of --failing; a figure count other than --figures, or a figure whose SVG
// has an empty bounding box (not rendered); filters that do not filter. Every line of the LaTeX
// file (the output of `verify --latex`) and a fixed known-good line are rendered with KaTeX
// (throwOnError: true): a parse error fails. Then a full-page screenshot is saved (and, with
// --top, one of the top of the page at 1280x1600 for the README, and TOP-errata.png,
// TOP-figures.png: the first 1400 px of those sections).
import { chromium } from 'playwright-core';
import katex from 'katex';
import { readFileSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

function options(argv) {
  const o = {};
  for (let i = 0; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || i + 1 >= argv.length) {
      throw new Error(`bad argument ${argv[i]} (usage: see the head of check.mjs)`);
    }
    o[argv[i].slice(2)] = argv[i + 1];
  }
  for (const k of ['report', 'latex', 'screenshot', 'claims', 'failing', 'figures']) {
    if (!(k in o)) throw new Error(`missing --${k}`);
  }
  return o;
}

const o = options(process.argv.slice(2));
const problems = [];

// KaTeX: a fixed known-good line (so this step always renders something), then every
// non-empty line of verify --latex.
const KNOWN_GOOD = String.raw`x = \frac{-b \pm \sqrt{b^{2} - 4ac}}{2a}, \quad \cos\beta = \frac{1 - \tau^{2}}{1 + \tau^{2}}`;
const latexLines = readFileSync(o.latex, 'utf8').split('\n').map((l) => l.trim()).filter((l) => l !== '' && !l.startsWith('%')); // '%' lines: the document's comments (id, verdict, part)
let rendered = 0;
for (const [i, line] of [[0, KNOWN_GOOD], ...latexLines.map((l, j) => [j + 1, l])]) {
  try {
    katex.renderToString(line, { throwOnError: true, displayMode: true, strict: 'error' });
    rendered++;
  } catch (e) {
    problems.push(`KaTeX: ${i === 0 ? 'the known-good line' : `${o.latex}:${i}`}: ${e.message.split('\n')[0]}`);
  }
}
// The KaTeX step must be able to fail: a malformed line is refused.
try {
  katex.renderToString(String.raw`\frac{1}{`, { throwOnError: true });
  problems.push('KaTeX accepted a malformed line');
} catch (e) {
  // expected
}

const profile = mkdtempSync(join(tmpdir(), 'exactcheck-chromium-'));
// A fresh, empty profile directory (playwright passes it as --user-data-dir).
const browser = await chromium.launchPersistentContext(profile, {
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1280, height: 1000 },
  args: [
    '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
  ],
});
try {
  const page = await browser.newPage();
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('request', (r) => {
    if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) {
      problems.push(`network request: ${r.url()}`);
    }
  });
  await page.goto(pathToFileURL(resolve(o.report)).href, { waitUntil: 'load' });

  const facts = await page.evaluate(() => {
    const table = document.querySelector('table#verdicts');
    const rows = table ? [...table.tBodies[0].rows] : [];
    const errata = document.querySelector('#errata');
    const figures = [...document.querySelectorAll('#figures figure')].map((f) => {
      const svg = f.querySelector('svg');
      if (!svg) return { id: f.id, width: 0, height: 0 };
      const b = svg.getBBox();
      const r = svg.getBoundingClientRect();
      return { id: f.id, width: Math.min(b.width, r.width), height: Math.min(b.height, r.height) };
    });
    const ids = [...document.querySelectorAll('[id]')].map((e) => e.id);
    return {
      table: !!table,
      rows: rows.length,
      rowsWithData: rows.filter((r) => r.dataset.source && r.dataset.verdict).length,
      filtersShown: !document.getElementById('filters')?.hidden,
      errata: errata ? [...errata.querySelectorAll('article.erratum')].map((a) => a.dataset.claim) : null,
      figures,
      duplicateIds: ids.filter((id, i) => ids.indexOf(id) !== i),
      regressions: document.querySelectorAll('#regressions table.regress').length,
      // Every erratum's formulas are MathML, rendered natively: each <math> must take space.
      maths: [...document.querySelectorAll('#errata math')].map((m) => {
        const r = m.getBoundingClientRect();
        return { claim: m.closest('article')?.dataset.claim, width: r.width, height: r.height };
      }),
      erratumFormulas: [...document.querySelectorAll('#errata article.erratum')].map((a) => ({
        claim: a.dataset.claim,
        formulas: a.querySelectorAll('math').length,
      })),
    };
  });

  if (!facts.table) problems.push('no table#verdicts');
  if (facts.rows !== Number(o.claims)) problems.push(`#verdicts has ${facts.rows} rows, expected ${o.claims}`);
  if (facts.rowsWithData !== facts.rows) problems.push('a row of #verdicts lacks data-source or data-verdict');
  if (!facts.filtersShown) problems.push('the filters stayed hidden (the script did not run)');
  if (facts.errata === null) {
    problems.push('no #errata section');
  } else {
    for (const id of o.failing.split(',').filter((x) => x)) {
      if (!facts.errata.includes(id)) problems.push(`errata: ${id} is missing`);
    }
  }
  if (facts.figures.length !== Number(o.figures)) {
    problems.push(`${facts.figures.length} figures, expected ${o.figures}`);
  }
  for (const f of facts.figures) {
    if (!(f.width > 0 && f.height > 0)) problems.push(`figure ${f.id}: empty bounding box (not rendered)`);
  }
  for (const m of facts.maths) {
    if (!(m.width > 0 && m.height > 0)) problems.push(`erratum ${m.claim}: a MathML formula did not render`);
  }
  for (const e of facts.erratumFormulas) {
    if (e.formulas === 0) problems.push(`erratum ${e.claim}: no formula (counter-example or residual)`);
  }
  if (facts.duplicateIds.length) problems.push(`duplicate ids: ${[...new Set(facts.duplicateIds)].join(', ')}`);
  if (Number(o.figures) > 0 && facts.regressions === 0) problems.push('no regression table');

  // The filters filter: choose the first source and the verdict `fails`.
  if (facts.table && facts.filtersShown) {
    const firstSource = await page.$eval('#filter-source option:nth-child(2)', (e) => e.value);
    await page.selectOption('#filter-source', firstSource);
    await page.selectOption('#filter-verdict', 'fails');
    const visible = await page.$$eval('#verdicts tbody tr', (rows) =>
      rows.filter((r) => !r.hidden).map((r) => [r.dataset.source, r.dataset.verdict]));
    const expected = await page.$$eval('#verdicts tbody tr', (rows, s) =>
      rows.filter((r) => r.dataset.source === s && r.dataset.verdict === 'fails').length, firstSource);
    if (visible.length !== expected || visible.some(([s, v]) => s !== firstSource || v !== 'fails')) {
      problems.push(`the filters show ${visible.length} rows for ${firstSource}/fails, expected ${expected}`);
    }
    await page.selectOption('#filter-source', '');
    await page.selectOption('#filter-verdict', '');
  }

  await page.screenshot({ path: o.screenshot, fullPage: true });
  if (o.top) {
    await page.setViewportSize({ width: 1280, height: 1600 });
    await page.screenshot({ path: o.top, fullPage: false });
    // The top 1400 px of the errata and of the figures, beside TOP.png (the README shows them).
    for (const section of ['errata', 'figures']) {
      const box = await page.evaluate((id) => {
        const r = document.getElementById(id).getBoundingClientRect();
        return { y: r.top + window.scrollY, height: r.height };
      }, section);
      await page.screenshot({
        path: o.top.replace(/\.png$/, `-${section}.png`),
        fullPage: true,
        clip: { x: 0, y: box.y, width: 1280, height: Math.min(1400, box.height) },
      });
    }
  }
  console.log(`browser: ${facts.rows} rows, ${facts.errata ? facts.errata.length : 0} errata, ${facts.figures.filter((f) => f.width > 0 && f.height > 0).length} of ${facts.figures.length} figures rendered, ${facts.regressions} regression tables, ${facts.maths.length} MathML formulas; KaTeX rendered ${rendered} line(s) (${latexLines.length} from ${o.latex}); screenshot ${o.screenshot}`);
} finally {
  await browser.close();
  rmSync(profile, { recursive: true, force: true });
}

if (problems.length) {
  for (const p of problems) console.error(`browser check: ${p}`);
  process.exit(1);
}
