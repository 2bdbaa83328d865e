// The impulse tool: one button per impulse experiment of the handouts (part 2 task 2, part 3
// task 1), applied to the chosen body as the viewer's tool applies it.
import { scenarios } from './scenarios.js';

/// Handout files holding impulse experiments, and the label prefix of each (as the viewer's).
const kExperimentFiles = [
    ['part2_task2_impulses', 'part 2 task 2'],
    ['part3_task1_impulse', 'part 3 task 1'],
];

/// Every experiment of the bundled handout files.
export function loadExperiments(module) {
    const experiments = [];
    for (const [name, label] of kExperimentFiles) {
        const entry = scenarios.find((candidate) => candidate.name === name);
        if (entry) {
            experiments.push(...module.impulseExperiments(entry.text, entry.file, label));
        }
    }
    return experiments;
}

const format = (v) => `(${v.map((c) => c.toFixed(3)).join(', ')})`;

/// Applies one experiment to body `index`; returns the line the tool shows.
export function applyExperiment(sim, index, experiment, startFromExperiment) {
    if (startFromExperiment) {
        sim.setVelocities(index, experiment.startVelocity, experiment.startAngularVelocity);
    }
    const describe = (impulse, offset) =>
        `${experiment.label}: J = ${format(impulse)} N s at r = ${format(offset)} m`;
    if (experiment.targetVelocity !== null) {
        const solved = sim.applyTarget(index, experiment.targetVelocity,
            experiment.targetAngularVelocity, experiment.label);
        return solved.problem === '' ? describe(solved.impulse, solved.offset)
            : `${experiment.label}: not reachable: ${solved.problem}`;
    }
    sim.applyImpulse(index, experiment.impulse, experiment.offset, experiment.label);
    return describe(experiment.impulse, experiment.offset);
}
