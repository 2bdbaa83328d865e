// The permalink: the scenario's file name and its whole text in the URL fragment, so a link
// carries an edited experiment with it (nothing is sent to a server: fragments never are).

/// "#file=scenarios%2Fx.toml&toml=..." for a scenario text.
export function permalinkFragment(file, text) {
    const parameters = new URLSearchParams({ file, toml: text });
    return '#' + parameters.toString();
}

/// The {file, text} a fragment carries, or null when it carries no scenario.
export function readPermalink(fragment) {
    const parameters = new URLSearchParams(fragment.replace(/^#/, ''));
    const text = parameters.get('toml');
    if (text === null) {
        return null;
    }
    return { file: parameters.get('file') || 'scenarios/linked.toml', text };
}
