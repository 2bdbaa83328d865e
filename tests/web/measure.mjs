// The figures of docs/web.md: the page's weight (raw and gzip), the frame time of pyramid_55
// played in real time, and screenshots of the page.
import { readdirSync, readFileSync, statSync, mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { frames } from './browser.mjs';

/// Every file under `dir`, with its raw and gzip (level 9) size.
function files(dir, prefix = '') {
    return readdirSync(dir).flatMap((name) => {
        const path = join(dir, name);
        if (statSync(path).isDirectory()) return files(path, `${prefix}${name}/`);
        const data = readFileSync(path);
        return [{ name: `${prefix}${name}`, raw: data.length, gzip: gzipSync(data, { level: 9 }).length }];
    });
}

const kib = (bytes) => `${(bytes / 1024).toFixed(1)} KiB`;

function printWeight(site) {
    const list = files(site).sort((a, b) => b.raw - a.raw);
    console.log('page weight (file, raw, gzip -9):');
    for (const file of list) console.log(`  ${file.name}  ${kib(file.raw)}  ${kib(file.gzip)}`);
    const raw = list.reduce((sum, file) => sum + file.raw, 0);
    const gzip = list.reduce((sum, file) => sum + file.gzip, 0);
    console.log(`  total  ${kib(raw)}  ${kib(gzip)}`);
}

/// Plays `name` at time scale 1 for `seconds` of wall time; prints the work per frame (steps,
/// drawing, plots) and how far simulated time kept up with the clock.
async function playFor(page, name, seconds) {
    await page.evaluate((scenario) => { window.tumble.pick(scenario); window.tumble.resetFrameStats(); }, name);
    const start = await page.evaluate(() => { window.tumble.play(); return performance.now(); });
    await new Promise((resolve) => setTimeout(resolve, seconds * 1000));
    const result = await page.evaluate((begin) => {
        window.tumble.pause();
        return { wall: (performance.now() - begin) / 1000, simulated: window.tumble.time(),
            stats: window.tumble.frameStats() };
    }, start);
    const { stats } = result;
    console.log(`${name}: ${stats.frames} frames in ${result.wall.toFixed(2)} s ` +
        `(${(stats.frames / result.wall).toFixed(1)} frames/s), work per frame mean ` +
        `${stats.meanMs.toFixed(2)} ms, 95th percentile ${stats.p95Ms.toFixed(2)} ms, max ` +
        `${stats.maxMs.toFixed(2)} ms; simulated ${result.simulated.toFixed(3)} s`);
}

/// The engine's share of 60 Hz frames: the first 2 s of `name` stepped frame by frame (1/60 s
/// of simulated time each, no drawing), after a first run that lets V8 finish compiling the
/// WebAssembly (its first second runs on the baseline compiler).
async function stepTime(page, name) {
    const result = await page.evaluate((scenario) => {
        window.tumble.pick(scenario);
        window.tumble.runSteps(Math.round(2 / window.tumble.simulation.dt()));
        window.tumble.pick(scenario);
        const perFrame = Math.max(1, Math.round(1 / 60 / window.tumble.simulation.dt()));
        const times = [];
        for (let frame = 0; frame < 120; frame++) times.push(window.tumble.timeSteps(perFrame));
        const mean = times.reduce((sum, t) => sum + t, 0) / times.length;
        const over = times.filter((t) => t > 1000 / 60).length;
        return { mean, max: Math.max(...times), over, perFrame };
    }, name);
    console.log(`${name}: stepping per 60 Hz frame (${result.perFrame} steps), first 2 s: mean ` +
        `${result.mean.toFixed(2)} ms, max ${result.max.toFixed(2)} ms, ${result.over} of 120 ` +
        'frames over 16.7 ms');
}

export async function measure(page, site, outDir) {
    printWeight(site);
    await stepTime(page, 'pyramid_55');
    await stepTime(page, 'part3_task4_friction');
    await playFor(page, 'pyramid_55', 5);
    await playFor(page, 'part3_task4_friction', 3);
    mkdirSync(outDir, { recursive: true });
    // the friction scenario at t = 1.5 s: the cuboid mid-tumble, the plots and log filled
    await page.evaluate(() => { window.tumble.pick('part3_task4_friction'); window.tumble.runSteps(360); });
    await frames(page, 5);
    await page.screenshot({ path: join(outDir, 'web_page.png') });
    await page.evaluate(() => { window.tumble.pick('pyramid_55'); window.tumble.runSteps(240); });
    await frames(page, 5);
    await page.screenshot({ path: join(outDir, 'web_pyramid.png') });
    console.log(`screenshots in ${outDir}`);
}
