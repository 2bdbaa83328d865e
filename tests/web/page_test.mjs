// The page's test (tests/web, docs/web.md): headless Chromium loads build-web/site and checks
// through window.tumble that the browser runs the CLI's engine: the same numbers as
// `tumble run --csv` to 1e-12, the same one-line error for a bad file, and a 3D view that shows
// the cuboid and moves.
//   node tests/web/page_test.mjs SITE CLI CHROMIUM [--measure OUT_DIR]
// --measure also plays pyramid_55 in real time and prints its frame times, and writes the
// screenshots of docs/web.md into OUT_DIR.
import { readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve } from './static_server.mjs';
import { openPage, frames, pictureStats } from './browser.mjs';
import { csvRows, cliError, consoleLines } from './cli_reference.mjs';
import { measure } from './measure.mjs';

const [site, cliPath, chromium, option, outDir] = process.argv.slice(2);
const cli = resolve(cliPath);
const repo = fileURLToPath(new URL('../..', import.meta.url));
/// The browser must give the CLI's numbers: both are the same C++ on IEEE doubles.
const kTolerance = 1e-12;

/// Steps the page's run of `name` to the CLI row time `time` and returns the largest difference
/// over every body and column (the time included).
async function compareWithCli(page, name, time, extra) {
    const rows = csvRows(cli, repo, `scenarios/${name}.toml`, extra);
    const times = [...new Set(rows.map((row) => row.time))];
    const step = times.findIndex((t) => Math.abs(t - time) < 1e-9);
    if (step < 0) throw new Error(`the CLI's CSV of ${name} has no row at t = ${time}`);
    const atTime = rows.filter((row) => row.time === times[step]);
    const browser = await page.evaluate((scenario, steps) => {
        const error = window.tumble.pick(scenario);
        window.tumble.runSteps(steps);
        return { error, time: window.tumble.time(), bodies: window.tumble.bodies() };
    }, name, step);
    if (browser.error !== '') throw new Error(`${name} does not load in the page: ${browser.error}`);
    if (browser.bodies.length !== atTime.length) {
        throw new Error(`${browser.bodies.length} bodies in the page, ${atTime.length} in the CSV`);
    }
    let largest = Math.abs(browser.time - times[step]);
    atTime.forEach((row, i) => {
        const body = browser.bodies[i];
        if (body.name !== row.body) throw new Error(`body ${i}: ${body.name} vs ${row.body}`);
        row.values.forEach((value, k) => {
            largest = Math.max(largest, Math.abs(body.state[k] - value));
        });
    });
    if (!(largest <= kTolerance)) {
        throw new Error(`largest difference ${largest} at t = ${time} s exceeds ${kTolerance}`);
    }
    return `${atTime.length} bodies, ${atTime[0].values.length + 1} columns at t = ${time} s, ` +
        `largest difference ${largest}`;
}

/// Types `text` into the editor of scenario `name`, presses Run and compares the error line
/// with what `tumble run` prints for the same file.
async function compareError(page, name, edit) {
    const file = `scenarios/${name}.toml`;
    const text = edit(readFileSync(join(repo, file), 'utf8'));
    const expected = cliError(cli, file, text);
    await page.evaluate((scenario) => window.tumble.pick(scenario), name);
    await page.$eval('#editor', (editor, value) => { editor.value = value; }, text);
    await page.click('#run');
    const shown = await page.$eval('#error', (element) => element.textContent);
    if (shown !== expected) throw new Error(`page: "${shown}"\n  CLI:  "${expected}"`);
    if (!expected.startsWith(`tumble: error: ${file}:`)) throw new Error(`unexpected CLI line ${expected}`);
    return shown;
}

/// Screenshots of the 3D view at t = 0 and t = 1 s of the friction scenario: the cuboid's
/// coloured faces must show, and the picture must change as it falls.
async function checkScreenshots(page) {
    await page.evaluate(() => window.tumble.pick('part3_task4_friction'));
    await frames(page, 3);
    const view = await page.$('#view');
    const first = await view.screenshot();
    await page.evaluate(() => window.tumble.runSteps(240));
    await frames(page, 3);
    const second = await view.screenshot();
    const [a, b] = await pictureStats(page, [first, second]);
    const problems = [];
    for (const [label, shot] of [['t = 0', a], ['t = 1 s', b]]) {
        if (shot.coloured < 0.002 * shot.pixels) problems.push(`${label}: ${shot.coloured} coloured pixels`);
        if (shot.distinctColours < 10) problems.push(`${label}: ${shot.distinctColours} colours (blank?)`);
    }
    if (b.changedFromFirst < 0.002 * b.pixels) problems.push(`only ${b.changedFromFirst} pixels changed`);
    if (problems.length > 0) throw new Error(problems.join('; '));
    return `${a.width}x${a.height}: coloured pixels ${a.coloured} and ${b.coloured}, ` +
        `${b.changedFromFirst} changed`;
}

/// The acceptance of issue 19: pick part 3 task 4, press play, and the log says where the
/// cuboid comes to rest, in the words and numbers of `tumble run`.
async function playToRest(page) {
    const expected = consoleLines(cli, repo, 'scenarios/part3_task4_friction.toml')
        .filter((line) => line.includes('came to rest'));
    if (expected.length === 0) throw new Error('tumble run prints no rest line');
    await page.select('#scenario', 'part3_task4_friction');
    await page.click('#play');
    // the rest line comes when the body has been slow for sleep_time (0.5 s): at 3.35 s
    await page.waitForFunction(() => window.tumble.time() >= 3.5, { timeout: 60000, polling: 100 });
    await page.click('#play');
    const text = await page.evaluate(() => window.tumble.logText());
    const shown = text.split('\n').filter((line) => line.includes('came to rest'));
    if (shown.join('\n') !== expected.join('\n')) {
        const time = await page.evaluate(() => window.tumble.time());
        throw new Error(`page: ${JSON.stringify(shown)}, CLI: ${JSON.stringify(expected)} ` +
            `(t = ${time} s, log of ${text.length} characters ending ${JSON.stringify(text.slice(-300))})`);
    }
    return shown.join('; ');
}

/// A link whose fragment carries an edited scenario opens with that text in the editor, run.
async function openPermalink(page) {
    const file = 'scenarios/part3_task4_friction.toml';
    const text = readFileSync(join(repo, file), 'utf8').replace('mass = 2.0', 'mass = 3.0');
    const fragment = '#' + new URLSearchParams({ file, toml: text }).toString();
    const linked = await page.browser().newPage();
    try {
        await linked.goto(page.url().replace(/#.*$/, '') + fragment, { waitUntil: 'load' });
        await linked.waitForFunction(() => window.tumble?.ready === true, { timeout: 60000 });
        const editor = await linked.$eval('#editor', (element) => element.value);
        const log = await linked.evaluate(() => window.tumble.logText());
        if (editor !== text) throw new Error('the editor does not hold the linked text');
        if (!log.includes('body rb: mass = 3.000000 kg')) throw new Error(`the run is not the linked one: ${log.slice(0, 300)}`);
    } finally {
        await linked.close();
    }
    return 'the edited mass (3 kg) is in the editor and in the run';
}

/// The impulse tool's "part 3 task 1" button at t = 2 s of part3_task1_impulse applies what the
/// file schedules for t = 2 s: the log's lines equal `tumble run`'s, but for the label.
async function impulseButton(page) {
    const lines = consoleLines(cli, repo, 'scenarios/part3_task1_impulse.toml');
    const start = lines.findIndex((line) => line.includes('impulse[0] on rb'));
    if (start < 0) throw new Error('tumble run prints no impulse[0]');
    const expected = [lines[start].replace('impulse[0]', 'part 3 task 1'),
        ...lines.slice(start + 1, start + 4)];
    await page.evaluate(() => { window.tumble.pick('part3_task1_impulse'); window.tumble.runSteps(480); });
    await page.evaluate(() => window.tumble.logText());
    const buttons = await page.$$eval('#experiments button', (list) => list.map((b) => b.textContent));
    const index = buttons.indexOf('part 3 task 1');
    if (index < 0) throw new Error(`no "part 3 task 1" button among ${buttons.join(', ')}`);
    await (await page.$$('#experiments button'))[index].click();
    const log = (await page.evaluate(() => window.tumble.logText())).split('\n');
    const at = log.findIndex((line) => line.includes('part 3 task 1 on rb'));
    const shown = at < 0 ? [] : log.slice(at, at + 4);
    if (shown.join('\n') !== expected.join('\n')) {
        throw new Error(`page:\n${shown.join('\n')}\nCLI:\n${expected.join('\n')}`);
    }
    return await page.$eval('#impulse-result', (element) => element.textContent);
}

const cases = [
    ['friction scenario equals tumble run --csv at t = 3 s',
        (page) => compareWithCli(page, 'part3_task4_friction', 3, [])],
    ['stack scenario equals tumble run --csv at t = 2 s',
        (page) => compareWithCli(page, 'stack_10', 2, ['--duration', '2'])],
    ['an unknown key shows the CLI error line',
        (page) => compareError(page, 'part3_task4_friction', (text) => text.replace('[world]', '[world]\nbogus = 1'))],
    ['a TOML syntax error shows the CLI error line',
        (page) => compareError(page, 'part3_task4_friction', (text) => `${text}\n[[body]\n`)],
    ['the 3D view shows the cuboid and changes over time', checkScreenshots],
    ['play shows the rest line of tumble run', playToRest],
    ['a permalink opens its scenario text', openPermalink],
    ['the impulse tool applies the handout impulse as tumble run does', impulseButton],
];

const { server, url } = await serve(site);
const { browser, page, problems } = await openPage(chromium, url);
let failed = 0;
try {
    for (const [name, check] of cases) {
        try {
            console.log(`[ OK ] ${name}: ${await check(page)}`);
        } catch (error) {
            failed++;
            console.log(`[FAIL] ${name}: ${error.message}`);
        }
    }
    if (problems.length > 0) {
        failed++;
        console.log(`[FAIL] the page reported errors: ${problems.join('; ')}`);
    }
    if (option === '--measure') await measure(page, site, outDir);
} finally {
    await browser.close();
    server.close();
}
console.log(failed === 0 ? 'web: all cases passed' : `web: ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
