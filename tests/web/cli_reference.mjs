// The CLI's side of the comparisons: `tumble run --csv` rows, and the one-line error of a bad
// scenario file.
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

/// Rows of `tumble run FILE --csv` (run in `cwd`, with `extra` options): [{time, body, values}],
/// values being the 15 numbers after time and body.
export function csvRows(cli, cwd, file, extra = []) {
    const dir = mkdtempSync(join(tmpdir(), 'tumble-web-'));
    const csv = join(dir, 'run.csv');
    execFileSync(cli, ['run', file, '--quiet', '--csv', csv, ...extra], { cwd, stdio: 'ignore' });
    const lines = readFileSync(csv, 'utf8').trim().split('\n').slice(1);
    return lines.map((line) => {
        const fields = line.split(',');
        return { time: Number(fields[0]), body: fields[1], values: fields.slice(2).map(Number) };
    });
}

/// What `tumble run FILE` prints on stderr for `text` saved as FILE (a relative path), run in a
/// fresh folder; the exit code must be 2 (a bad scenario).
export function cliError(cli, file, text) {
    const dir = mkdtempSync(join(tmpdir(), 'tumble-web-'));
    mkdirSync(join(dir, file, '..'), { recursive: true });
    writeFileSync(join(dir, file), text);
    const result = spawnSync(cli, ['run', file, '--quiet'], { cwd: dir, encoding: 'utf8' });
    if (result.status !== 2) {
        throw new Error(`tumble run ${file} exited with ${result.status}, expected 2`);
    }
    return result.stderr.trim();
}

/// The console lines of `tumble run FILE` (run in `cwd`).
export function consoleLines(cli, cwd, file) {
    return execFileSync(cli, ['run', file], { cwd, encoding: 'utf8' }).split('\n');
}
