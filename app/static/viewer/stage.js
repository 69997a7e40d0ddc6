// The three.js stage: renderer, camera, orbit controls, lights, grid, and `world`, a group
// in the robot's root frame (URDF: z up, metres). The scene is z up like the robot (the
// camera's up is +z), so everything placed in `world` uses the API's coordinates unchanged
// and the gizmo's X, Y, Z handles are the robot's x, y, z.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class Stage {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(0xf2f4f7);
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 100);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(1.6, 1.6, 1.2);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.set(0, 0, 0.4);
    this.controls.addEventListener('change', () => this.render());

    const sky = new THREE.HemisphereLight(0xffffff, 0x8090a0, 2.0);
    sky.position.set(0, 0, 1);
    this.scene.add(sky);
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(3, 2, 5);
    this.scene.add(sun);
    const grid = new THREE.GridHelper(2, 20, 0x9aa4b0, 0xd0d6de);
    grid.rotation.x = Math.PI / 2; // into the x-y plane
    this.scene.add(grid);

    this.world = new THREE.Group();
    this.world.name = 'world';
    this.scene.add(this.world);
    this.world.add(new THREE.AxesHelper(0.15));

    this._pending = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.container;
    if (!w || !h) return;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  // Render on demand (next animation frame), not continuously.
  render() {
    if (this._pending) return;
    this._pending = true;
    requestAnimationFrame(() => {
      this._pending = false;
      this.controls.update();
      this.renderer.render(this.scene, this.camera);
    });
  }

  // Frame the camera on an object (its bounding box).
  frame(object) {
    const box = new THREE.Box3().setFromObject(object);
    if (box.isEmpty()) return;
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), 0.3);
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(new THREE.Vector3(0.9, 0.9, 0.6).multiplyScalar(size));
    this.camera.near = size / 100;
    this.camera.far = size * 100;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  // Screen position (CSS pixels, page coordinates) of a point given in `world` coordinates.
  screenOf(point) {
    const v = this.world.localToWorld(new THREE.Vector3(...point)).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return [rect.left + ((v.x + 1) / 2) * rect.width, rect.top + ((1 - v.y) / 2) * rect.height];
  }
}
