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

/// Whole frames of `name` (1/60 s of simulated time each: steps, scene, drawing, plots), drawn
/// back to back over its first 2 s after a first pass that lets V8 finish compiling.
async function frameTime(page, name) {
    const times = await page.evaluate((scenario) => {
        window.tumble.pick(scenario);
        window.tumble.timeFrames(120);
        window.tumble.pick(scenario);
        return window.tumble.timeFrames(120);
    }, name);
    const sorted = [...times].sort((a, b) => a - b);
    const mean = times.reduce((sum, t) => sum + t, 0) / times.length;
    const over = times.filter((t) => t > 1000 / 60).length;
    console.log(`${name}: whole frame (1/60 s simulated), first 2 s: mean ${mean.toFixed(2)} ms, ` +
        `median ${sorted[60].toFixed(2)} ms, 95th percentile ${sorted[113].toFixed(2)} ms, max ` +
        `${sorted[119].toFixed(2)} ms, ${over} of 120 frames over 16.7 ms`);
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
    await frameTime(page, 'pyramid_55');
    await frameTime(page, 'part3_task4_friction');
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
