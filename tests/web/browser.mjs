// Headless Chromium (Debian's chromium, driven by puppeteer-core) with the page loaded.
import puppeteer from 'puppeteer-core';

/// Flags for a headless run on a machine without a GPU: WebGL on SwiftShader (software), and no
/// sandbox, which a root CI container cannot set up.
const kFlags = ['--no-sandbox', '--headless=new', '--use-angle=swiftshader',
    '--enable-unsafe-swiftshader', '--window-size=1400,900'];

/// Opens `url` and waits for the page's window.tumble API; resolves to {browser, page}.
export async function openPage(chromium, url) {
    const browser = await puppeteer.launch({ executablePath: chromium, args: kFlags,
        headless: true, defaultViewport: { width: 1400, height: 900 } });
    const page = await browser.newPage();
    const problems = [];
    page.on('pageerror', (error) => problems.push(String(error)));
    page.on('console', (message) => {
        if (message.type() === 'error') problems.push(message.text());
    });
    await page.goto(url, { waitUntil: 'load' });
    try {
        await page.waitForFunction(() => window.tumble?.ready === true, { timeout: 60000 });
    } catch (error) {
        await browser.close();
        throw new Error(`the page did not start: ${problems.join('; ') || error.message}`);
    }
    return { browser, page, problems };
}

/// Waits for `count` animation frames of the page, so what it draws is on screen.
export function frames(page, count) {
    return page.evaluate((n) => new Promise((resolve) => {
        const next = (left) => (left === 0 ? resolve() : requestAnimationFrame(() => next(left - 1)));
        next(n);
    }), count);
}

/// Statistics of PNG screenshots, decoded by the browser itself: for each, its size, the number
/// of strongly coloured pixels (the cuboid's faces and the markers; sky, ground and grid are
/// grey) and of distinct colours; and the number of pixels that differ between the first and
/// each later one (by more than 24 in a channel).
export async function pictureStats(page, pngs) {
    return page.evaluate(async (list) => {
        const decode = async (base64) => {
            const blob = await (await fetch(`data:image/png;base64,${base64}`)).blob();
            const bitmap = await createImageBitmap(blob);
            const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
            const g = canvas.getContext('2d');
            g.drawImage(bitmap, 0, 0);
            return { width: bitmap.width, height: bitmap.height,
                data: g.getImageData(0, 0, bitmap.width, bitmap.height).data };
        };
        const images = [];
        for (const base64 of list) images.push(await decode(base64));
        return images.map((image) => {
            const { data } = image;
            let coloured = 0;
            let changed = 0;
            const distinct = new Set();
            const first = images[0].data;
            for (let i = 0; i < data.length; i += 4) {
                const max = Math.max(data[i], data[i + 1], data[i + 2]);
                const min = Math.min(data[i], data[i + 1], data[i + 2]);
                if (max > 60 && (max - min) / max > 0.4) coloured++;
                distinct.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
                if (Math.abs(data[i] - first[i]) > 24 || Math.abs(data[i + 1] - first[i + 1]) > 24 ||
                    Math.abs(data[i + 2] - first[i + 2]) > 24) changed++;
            }
            return { width: image.width, height: image.height, pixels: data.length / 4,
                coloured, distinctColours: distinct.size, changedFromFirst: changed };
        });
    }, pngs.map((png) => Buffer.from(png).toString('base64')));
}
