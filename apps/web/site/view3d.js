// The 3D view: the bodies in the viewer's face colours, static geometry tinted grey, the
// touching vertices (red) and their average (yellow), and the impulse arrows of each body's last
// impact (normal yellow, friction orange); orbit and zoom with the mouse (three.js OrbitControls).
import * as THREE from 'three';
import { OrbitControls } from './vendor/OrbitControls.js';
import { faceColours, palette } from './palette.js';

/// Impulse arrow length per N s, m (the viewer's default impulseScale).
const kImpulseScale = 0.15;
const colour = (triple) => new THREE.Color(...triple);

function cuboidMesh(size, tint) {
    const materials = faceColours.map((face) => new THREE.MeshLambertMaterial({
        color: colour(face.map((c, i) => c * tint[i])),
    }));
    const geometry = new THREE.BoxGeometry(size[0], size[1], size[2]);
    const mesh = new THREE.Mesh(geometry, materials);
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry),
        new THREE.LineBasicMaterial({ color: colour(palette.edge) }));
    mesh.add(edges);
    return mesh;
}

/// A plane patch: a large square on the plane through `point` with normal `normal`.
function planeMesh(point, normal, extent, tint) {
    const geometry = new THREE.PlaneGeometry(extent, extent);
    const material = new THREE.MeshLambertMaterial({
        color: colour(palette.ground.map((c, i) => c * tint[i])), side: THREE.DoubleSide,
    });
    const mesh = new THREE.Mesh(geometry, material);
    mesh.position.set(...point);
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), new THREE.Vector3(...normal));
    return mesh;
}

export class View3d {
    constructor(canvas) {
        this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
        this.scene = new THREE.Scene();
        this.scene.background = colour(palette.skyTop);
        this.camera = new THREE.PerspectiveCamera(45, 1, 0.05, 500);
        this.controls = new OrbitControls(this.camera, canvas);
        this.scene.add(new THREE.HemisphereLight(0xffffff, 0x555555, 1.2));
        const sun = new THREE.DirectionalLight(0xffffff, 1.1);
        sun.position.set(4, 10, 6);
        this.scene.add(sun);
        this.world = new THREE.Group();
        this.scene.add(this.world);
        this.overlay = new THREE.Group();
        this.scene.add(this.overlay);
        this.markerGeometry = new THREE.SphereGeometry(1, 12, 8);
        this.markerMaterials = new Map();
        this.lastImpacts = new Map();
    }

    /// Builds the meshes of a freshly loaded scenario and aims the camera at its bodies.
    build(sim) {
        this.world.clear();
        this.lastImpacts.clear();
        this.meshes = [];
        // the camera frames every body and the ground below them
        const bounds = new THREE.Box3();
        const geometry = sim.staticGeometry();
        let smallest = Infinity;
        for (let i = 0; i < sim.bodyCount(); i++) {
            const fixed = sim.isStatic(i);
            const size = sim.size(i);
            const mesh = cuboidMesh(size, fixed ? palette.staticTint : [1, 1, 1]);
            this.world.add(mesh);
            this.meshes.push(mesh);
            const s = sim.state(i);
            const reach = 0.5 * Math.hypot(...size);
            if (!fixed) smallest = Math.min(smallest, ...size);
            bounds.expandByPoint(new THREE.Vector3(s[0] - reach, s[1] - reach, s[2] - reach));
            bounds.expandByPoint(new THREE.Vector3(s[0] + reach, s[1] + reach, s[2] + reach));
            if (geometry.ground !== null) bounds.expandByPoint(new THREE.Vector3(s[0], geometry.ground, s[2]));
        }
        const centre = bounds.getCenter(new THREE.Vector3());
        // a 16 mm die and a 10 m pile are both framed: no floor in metres, only against a
        // degenerate scene
        const radius = Math.max(0.05, 0.6 * bounds.getSize(new THREE.Vector3()).length());
        if (geometry.ground !== null) {
            this.world.add(planeMesh([centre.x, geometry.ground, centre.z], [0, 1, 0],
                8 * radius, [1, 1, 1]));
            const grid = new THREE.GridHelper(8 * radius, 8 * Math.ceil(radius),
                colour(palette.gridMajor), colour(palette.gridMinor));
            grid.position.set(centre.x, geometry.ground + 1e-3, centre.z);
            this.world.add(grid);
        }
        for (const plane of geometry.planes) {
            this.world.add(planeMesh(plane.point, plane.normal, 2 * radius, palette.staticTint));
        }
        // markers sized to the scene, but never hiding a small body's vertices
        this.markerSize = Math.min(0.02 * radius, 0.06 * smallest);
        this.camera.near = 0.005 * radius;
        this.camera.far = 200 * radius;
        this.camera.updateProjectionMatrix();
        this.controls.target.copy(centre);
        this.camera.position.set(centre.x + 1.1 * radius, centre.y + 0.8 * radius,
            centre.z + 1.7 * radius);
        this.controls.update();
        this.update(sim);
    }

    /// Moves the meshes to the bodies' poses and redraws contacts and impulse arrows.
    update(sim) {
        for (let i = 0; i < this.meshes.length; i++) {
            const s = sim.state(i);
            this.meshes[i].position.set(s[0], s[1], s[2]);
            this.meshes[i].quaternion.set(s[4], s[5], s[6], s[3]);
        }
        this.overlay.clear();
        for (const contact of sim.touching()) {
            for (const point of contact.points) {
                this.addMarker(point, palette.contactVertex, this.markerSize);
            }
            this.addMarker(contact.average, palette.contactAverage, 1.3 * this.markerSize);
        }
        for (const impact of this.lastImpacts.values()) {
            this.addArrow(impact.average, impact.normalImpulse, palette.normalImpulse);
            this.addArrow(impact.average, impact.frictionImpulse, palette.frictionImpulse);
        }
    }

    /// Keeps the last impact of each body, whose impulses the arrows show.
    noteImpacts(impacts) {
        for (const impact of impacts) {
            this.lastImpacts.set(impact.body, impact);
        }
    }

    addMarker(position, triple, radius) {
        // one material per colour, made once: markers are made anew every frame
        const key = triple.join();
        if (!this.markerMaterials.has(key)) {
            this.markerMaterials.set(key, new THREE.MeshBasicMaterial({ color: colour(triple),
                depthTest: false }));
        }
        const marker = new THREE.Mesh(this.markerGeometry, this.markerMaterials.get(key));
        marker.position.set(...position);
        marker.scale.setScalar(radius);
        marker.renderOrder = 1;
        this.overlay.add(marker);
    }

    /// An arrow ending at `point`, as long as the impulse times kImpulseScale.
    addArrow(point, impulse, triple) {
        const vector = new THREE.Vector3(...impulse).multiplyScalar(kImpulseScale);
        const length = vector.length();
        if (length < 1e-6) {
            return;
        }
        const tail = new THREE.Vector3(...point).sub(vector);
        this.overlay.add(new THREE.ArrowHelper(vector.normalize(), tail, length,
            colour(triple).getHex(), Math.min(0.3 * length, 0.25), Math.min(0.15 * length, 0.12)));
    }

    render() {
        const canvas = this.renderer.domElement;
        const width = canvas.clientWidth;
        const height = canvas.clientHeight;
        if (canvas.width !== width || canvas.height !== height) {
            this.renderer.setSize(width, height, false);
            this.camera.aspect = width / Math.max(1, height);
            this.camera.updateProjectionMatrix();
        }
        this.renderer.render(this.scene, this.camera);
    }
}
