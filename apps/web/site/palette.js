// The viewer's colours (apps/viewer/palette.hpp), as three.js colour triples in [0, 1].

/// One colour per cuboid face, in three.js BoxGeometry's face order (+x, -x, +y, -y, +z, -z),
/// which is also CuboidFace's order.
export const faceColours = [
    [0.88, 0.24, 0.20], // +x red
    [0.16, 0.66, 0.82], // -x teal
    [0.95, 0.78, 0.16], // +y yellow
    [0.52, 0.30, 0.84], // -y violet
    [0.26, 0.74, 0.30], // +z green
    [0.96, 0.50, 0.12], // -z orange
];

export const palette = {
    background: [0.06, 0.06, 0.06],
    edge: [0.08, 0.08, 0.10],
    staticTint: [0.45, 0.45, 0.47],
    skyTop: [0.40, 0.45, 0.52],
    skyHorizon: [0.78, 0.80, 0.83],
    ground: [0.74, 0.75, 0.76],
    gridMinor: [0.62, 0.63, 0.65],
    gridMajor: [0.46, 0.47, 0.50],
    contactVertex: [1.0, 0.15, 0.15],
    contactAverage: [1.0, 0.92, 0.10],
    normalImpulse: [0.98, 0.86, 0.18],
    frictionImpulse: [0.95, 0.35, 0.10],
};

/// A CSS colour for a palette triple.
export function css(triple) {
    const [r, g, b] = triple.map((c) => Math.round(c * 255));
    return `rgb(${r}, ${g}, ${b})`;
}
