// Live plots on plain canvases: a few series against simulated time, with a vertical mark at
// each impact. Drawn by hand rather than with a plotting library: three small line charts do
// not earn a dependency (docs/web.md, library choices).

/// Samples kept per plot: 20 s at 60 samples per second.
const kCapacity = 1200;

export class Plot {
    /// `series`: [{label, colour}]; `unit` is printed after the axis numbers.
    constructor(canvas, title, unit, series) {
        this.canvas = canvas;
        this.title = title;
        this.unit = unit;
        this.series = series;
        this.clear();
    }

    clear() {
        this.times = [];
        this.values = this.series.map(() => []);
        this.marks = [];
    }

    add(time, values) {
        this.times.push(time);
        values.forEach((value, k) => this.values[k].push(value));
        if (this.times.length > kCapacity) {
            this.times.shift();
            this.values.forEach((list) => list.shift());
        }
    }

    mark(time) {
        this.marks.push(time);
        while (this.marks.length > 0 && this.marks[0] < this.times[0]) {
            this.marks.shift();
        }
    }

    /// The range of the kept values, never empty.
    range() {
        let low = Infinity;
        let high = -Infinity;
        for (const list of this.values) {
            for (const value of list) {
                low = Math.min(low, value);
                high = Math.max(high, value);
            }
        }
        if (!Number.isFinite(low)) {
            return [0, 1];
        }
        const pad = Math.max(1e-9, 0.08 * (high - low));
        return [low - pad, high + pad];
    }

    draw() {
        const canvas = this.canvas;
        const width = (canvas.width = canvas.clientWidth);
        const height = (canvas.height = canvas.clientHeight);
        const g = canvas.getContext('2d');
        g.fillStyle = '#161616';
        g.fillRect(0, 0, width, height);
        g.font = '11px sans-serif';
        g.fillStyle = '#ccc';
        g.fillText(this.title, 6, 12);
        if (this.times.length < 2) {
            return;
        }
        const [t0, t1] = [this.times[0], Math.max(this.times[this.times.length - 1], this.times[0] + 1e-9)];
        const [low, high] = this.range();
        const left = 44;
        const x = (t) => left + ((t - t0) / (t1 - t0)) * (width - left - 6);
        const y = (v) => height - 14 - ((v - low) / (high - low)) * (height - 32);
        g.fillStyle = '#999';
        g.fillText(`${high.toPrecision(3)} ${this.unit}`, 2, 26);
        g.fillText(`${low.toPrecision(3)}`, 2, height - 16);
        g.fillText(`t = ${t0.toFixed(2)} s`, left, height - 2);
        g.fillText(`${t1.toFixed(2)} s`, width - 50, height - 2);
        // impacts: thin grey lines under the series
        g.strokeStyle = '#5a5a5a';
        for (const time of this.marks) {
            g.beginPath();
            g.moveTo(x(time), 16);
            g.lineTo(x(time), height - 14);
            g.stroke();
        }
        this.series.forEach((series, k) => {
            g.strokeStyle = series.colour;
            g.beginPath();
            this.values[k].forEach((value, i) => {
                if (i === 0) g.moveTo(x(this.times[i]), y(value));
                else g.lineTo(x(this.times[i]), y(value));
            });
            g.stroke();
            g.fillStyle = series.colour;
            g.fillText(series.label, width - 120 + 0 * k, 12 + 12 * k);
        });
    }
}
