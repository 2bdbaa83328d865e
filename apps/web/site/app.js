// The page: loads the module, wires the controls, steps the run in real time (times the time
// scale) with the scenario's fixed dt, and offers window.tumble, the API the tests and the
// browser console use (docs/web.md).
import createTumble from './tumble_web.js';
import { scenarios } from './scenarios.js';
import { View3d } from './view3d.js';
import { Plot } from './plots.js';
import { palette, css } from './palette.js';
import { permalinkFragment, readPermalink } from './permalink.js';
import { loadExperiments, applyExperiment } from './impulse_tool.js';

/// The scenario the page opens with, as `tumble view` does.
const kDefaultScenario = 'part3_task4_friction';
/// Most steps one frame takes: a slow machine falls behind real time instead of freezing.
const kMaxStepsPerFrame = 200;
/// Characters the log pane keeps.
const kLogLimit = 400000;

const $ = (id) => document.getElementById(id);
const module = await createTumble();
const sim = new module.Simulation();
const view = new View3d($('view'));
const plots = {
    height: new Plot($('plot-height'), 'height', 'm', [{ label: 'y', colour: '#6cf' }]),
    speed: new Plot($('plot-speed'), 'speeds', '', [
        { label: '|v| m/s', colour: '#6cf' }, { label: '|w| rad/s', colour: css(palette.frictionImpulse) }]),
    energy: new Plot($('plot-energy'), 'energies', 'J', [
        { label: 'kinetic', colour: '#f66' }, { label: 'potential', colour: '#6c6' },
        { label: 'total', colour: '#eee' }]),
};
const run = { file: '', playing: false, timeScale: 1, accumulator: 0, lastFrame: null };

function selectedBody() {
    return Number($('body').value || 0);
}

function samplePlots() {
    if (sim.bodyCount() === 0) return;
    const s = sim.state(selectedBody());
    const t = sim.time();
    plots.height.add(t, [s[1]]);
    plots.speed.add(t, [Math.hypot(s[7], s[8], s[9]), Math.hypot(s[10], s[11], s[12])]);
    plots.energy.add(t, [s[13], s[14], s[13] + s[14]]);
}

function flushLog() {
    const text = sim.takeLog();
    if (text === '') return;
    const log = $('log');
    const atBottom = log.scrollTop + log.clientHeight >= log.scrollHeight - 4;
    log.textContent = (log.textContent + text).slice(-kLogLimit);
    if (atBottom) log.scrollTop = log.scrollHeight;
}

/// Called after the run starts again (load or reset): fresh view, plots, log.
function restarted() {
    run.accumulator = 0;
    view.build(sim);
    Object.values(plots).forEach((plot) => plot.clear());
    $('log').textContent = '';
    flushLog();
    samplePlots();
}

function fillBodies() {
    const select = $('body');
    select.textContent = '';
    for (let i = 0; i < sim.bodyCount(); i++) {
        if (!sim.isStatic(i)) select.add(new Option(sim.bodyName(i), String(i)));
    }
}

/// Loads the editor's text as scenario `file`; returns '' or the CLI's one-line error.
function load(text, file) {
    $('editor').value = text;
    const error = sim.load(text, file);
    $('error').textContent = error;
    if (error !== '') return error;
    run.file = file;
    fillBodies();
    restarted();
    history.replaceState(null, '', permalinkFragment(file, text));
    $('permalink').href = location.href;
    return '';
}

function pick(name) {
    const entry = scenarios.find((candidate) => candidate.name === name);
    $('scenario').value = name;
    return load(entry.text, entry.file);
}

/// One fixed step, noting its impacts for the arrows and the plots' marks.
function advance() {
    if (sim.step() > 0) {
        const impacts = sim.lastCollisions();
        view.noteImpacts(impacts);
        for (const impact of impacts) {
            if (impact.body === selectedBody()) Object.values(plots).forEach((p) => p.mark(impact.time));
        }
    }
}

function setPlaying(playing) {
    run.playing = playing;
    run.lastFrame = null;
    $('play').textContent = playing ? 'pause' : 'play';
}

function frame(now) {
    if (run.playing && sim.loaded() && !sim.finished()) {
        // wall time since the last frame, times the time scale, in whole fixed steps
        const elapsed = run.lastFrame === null ? 0 : Math.min(0.25, (now - run.lastFrame) / 1000);
        run.accumulator += elapsed * run.timeScale;
        let steps = 0;
        while (run.accumulator >= sim.dt() && !sim.finished() && steps < kMaxStepsPerFrame) {
            advance();
            run.accumulator -= sim.dt();
            steps++;
        }
        if (steps === kMaxStepsPerFrame) run.accumulator = 0;
        samplePlots();
    }
    if (sim.finished() && run.playing) setPlaying(false);
    run.lastFrame = now;
    view.update(sim);
    view.render();
    Object.values(plots).forEach((plot) => plot.draw());
    flushLog();
    $('clock').textContent = `t = ${sim.time().toFixed(3)} s`;
    requestAnimationFrame(frame);
}

function wireControls() {
    for (const entry of scenarios) $('scenario').add(new Option(entry.name, entry.name));
    $('scenario').addEventListener('change', () => pick($('scenario').value));
    $('run').addEventListener('click', () => load($('editor').value, run.file || 'scenarios/edited.toml'));
    $('play').addEventListener('click', () => setPlaying(!run.playing));
    $('step').addEventListener('click', () => { setPlaying(false); advance(); samplePlots(); });
    $('reset').addEventListener('click', () => { sim.reset(); restarted(); });
    $('timescale').addEventListener('change', () => { run.timeScale = Number($('timescale').value); });
    $('body').addEventListener('change', () => Object.values(plots).forEach((p) => p.clear()));
    for (const experiment of loadExperiments(module)) {
        const button = document.createElement('button');
        button.textContent = experiment.label;
        button.addEventListener('click', () => {
            if (!sim.loaded()) return;
            $('impulse-result').textContent =
                applyExperiment(sim, selectedBody(), experiment, $('from-start').checked);
        });
        $('experiments').append(button);
    }
}

window.tumble = {
    module, simulation: sim, scenarios: scenarios.map((entry) => entry.name),
    pick, load, play: () => setPlaying(true), pause: () => setPlaying(false),
    /// Takes up to `count` steps at once (not in real time), as the play loop takes them.
    runSteps: (count) => {
        let taken = 0;
        for (; taken < count && !sim.finished(); taken++) {
            advance();
            if (sim.stepCount() % 4 === 0) samplePlots();
        }
        return taken;
    },
    time: () => sim.time(), stepCount: () => sim.stepCount(),
    /// Every dynamic body: name and the `tumble run --csv` columns after time and name.
    bodies: () => [...Array(sim.bodyCount()).keys()].filter((i) => !sim.isStatic(i))
        .map((i) => ({ name: sim.bodyName(i), state: sim.state(i) })),
    /// Wall time of `count` steps of the loaded run taken at once, without drawing, ms.
    timeSteps: (count) => {
        const start = performance.now();
        sim.runSteps(count);
        return performance.now() - start;
    },
    /// Wall time of `count` whole frames drawn back to back, each 1/60 s of simulated time:
    /// steps, scene update, drawing and plots, waiting for the GPU to finish (a one-pixel
    /// read-back), ms per frame.
    timeFrames: (count) => {
        const perFrame = Math.max(1, Math.round(1 / 60 / sim.dt()));
        const gl = view.renderer.getContext();
        const pixel = new Uint8Array(4);
        const times = [];
        for (let i = 0; i < count; i++) {
            const start = performance.now();
            for (let k = 0; k < perFrame; k++) advance();
            samplePlots();
            view.update(sim);
            view.render();
            Object.values(plots).forEach((plot) => plot.draw());
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
            times.push(performance.now() - start);
        }
        return times;
    },
    errorText: () => $('error').textContent,
    /// The log pane's text, with the lines of steps not yet drawn.
    logText: () => { flushLog(); return $('log').textContent; },
};

wireControls();
const linked = readPermalink(location.hash);
if (linked !== null) {
    const match = scenarios.find((entry) => entry.file === linked.file);
    if (match) $('scenario').value = match.name;
    load(linked.text, linked.file);
} else {
    pick(kDefaultScenario);
}
window.tumble.ready = true;
requestAnimationFrame(frame);
