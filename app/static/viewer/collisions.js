// Collisions and a scene's obstacles. A picker lists the stored scenes (GET /scenes; "none"
// by default); the picked scene's obstacles (GET /scenes/{name}) are drawn semi-transparent
// in the robot's root frame. With "check collisions" on, every configuration change asks
// POST /robots/{id}/collisions {q, scene?}: the links of the pairs in collision are drawn
// red, so are the obstacles in collision, and the readout lists the pairs.
//
// Obstacle shapes (the API's conventions, app/kinematics/obstacles.py), centred on
// pose.position and turned by pose.orientation [x, y, z, w] (root ← obstacle):
// box `size` = full edge lengths along the local x, y, z; sphere `radius`; cylinder
// `radius` and full height `length` along the local z; capsule `radius` and `length` of
// the segment between the hemisphere centres, along the local z.
import * as THREE from 'three';
import { Latest } from './latest.js';

const COLOUR = { free: 0x5b8def, hit: 0xe02020 };
const OPACITY = 0.4;

// A three.js mesh of an obstacle (GET /scenes/{name} wire form), in the root frame.
export function obstacleMesh(o) {
  let geometry;
  if (o.shape === 'box') {
    geometry = new THREE.BoxGeometry(...o.size);
  } else if (o.shape === 'sphere') {
    geometry = new THREE.SphereGeometry(o.radius, 32, 16);
  } else if (o.shape === 'cylinder') {
    geometry = new THREE.CylinderGeometry(o.radius, o.radius, o.length, 32);
  } else if (o.shape === 'capsule') {
    geometry = new THREE.CapsuleGeometry(o.radius, o.length, 8, 32);
  } else {
    throw new Error(`obstacle ${o.name}: unknown shape ${o.shape}`);
  }
  // three.js builds cylinders and capsules along its y axis; the API's are along z
  if (o.shape === 'cylinder' || o.shape === 'capsule') geometry.rotateX(Math.PI / 2);
  const material = new THREE.MeshPhongMaterial({
    color: COLOUR.free, transparent: true, opacity: OPACITY, depthWrite: false,
  });
  const mesh = new THREE.Mesh(geometry, material);
  mesh.name = `obstacle:${o.name}`;
  mesh.userData.obstacle = o;
  mesh.position.fromArray(o.pose.position);
  mesh.quaternion.fromArray(o.pose.orientation);
  return mesh;
}

export class CollisionsPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.section = document.getElementById('panel-collisions');
    this.section.innerHTML = `<h2>Collisions</h2>
      <label>Scene <select id="scene-picker"><option value="">none</option></select>
        <button id="scene-refresh" type="button" title="List the scenes again">↻</button></label>
      <label><input id="collision-toggle" type="checkbox"> check collisions</label>
      <p id="collision-readout" style="white-space: pre-line"></p>`;
    this.picker = document.getElementById('scene-picker');
    this.toggle = document.getElementById('collision-toggle');
    this.readout = document.getElementById('collision-readout');
    this.scene = null; // GET /scenes/{name} answer of the drawn scene
    this.lastAnswer = null; // {q, scene, answer} of the last POST /collisions answer
    this.obstacles = new THREE.Group();
    this.obstacles.name = 'scene-obstacles';
    viewer.stage.world.add(this.obstacles);
    this.loader = new Latest((name) => this._loadScene(name), (e) => viewer.report(e));
    this.check = new Latest((q, scene) => this._check(q, scene), (e) => viewer.report(e));
    this.lister = new Latest(() => this.listScenes(), (e) => viewer.report(e));
    const refresh = document.getElementById('scene-refresh');
    refresh.addEventListener('click', () => this.lister.request());
    this.picker.addEventListener('change', () => this.loader.request(this.picker.value));
    this.toggle.addEventListener('change', () => this.update());
  }

  // Fill the picker from GET /scenes, keeping the current choice when it still exists.
  async listScenes() {
    const { scenes } = await this.viewer.api.get('/scenes');
    const current = this.picker.value;
    const options = scenes.map((s) => new Option(`${s.name} (${s.obstacles})`, s.name));
    this.picker.replaceChildren(new Option('none', ''), ...options);
    this.picker.value = scenes.some((s) => s.name === current) ? current : '';
  }

  build() {
    this.lister.request();
    this.lastAnswer = null;
    this.readout.textContent = '';
  }

  update() {
    const v = this.viewer;
    if (!this.toggle.checked) {
      v.robot?.highlight([]);
      this._colour(new Set());
      this.readout.textContent = '';
      v.stage.render();
      return;
    }
    if (v.robot) this.check.request(v.q.slice(), this.scene ? this.scene.name : null);
  }

  async _loadScene(name) {
    const scene = name ? await this.viewer.api.get(`/scenes/${encodeURIComponent(name)}`) : null;
    if (this.picker.value !== name) return; // another scene was picked meanwhile
    this.obstacles.children.slice().forEach((m) => {
      m.removeFromParent();
      m.geometry.dispose();
      m.material.dispose();
    });
    this.scene = scene;
    (scene?.obstacles || []).forEach((o) => this.obstacles.add(obstacleMesh(o)));
    this.viewer.stage.render();
    this.update();
  }

  async _check(q, scene) {
    const v = this.viewer;
    const body = scene ? { q, scene } : { q };
    const answer = await v.ask('/collisions', body);
    if (!answer || !this.toggle.checked || this.check.next !== null) return; // stale, or off
    this.lastAnswer = { q, scene, answer };
    const hits = answer.pairs.filter((p) => p.in_collision);
    const links = new Set();
    const obstacles = new Set();
    for (const p of hits) {
      links.add(p.a);
      (p.kind === 'self' ? links : obstacles).add(p.b);
    }
    v.robot.highlight([...links]);
    this._colour(obstacles);
    this.readout.textContent = hits.length === 0
      ? `no collision (${answer.checked_pairs} pairs checked)`
      : hits.map((p) => `${p.a} — ${p.b} (${p.kind})`).join('\n');
    v.stage.render();
  }

  _colour(names) {
    this.obstacles.children.forEach((m) => {
      m.material.color.set(names.has(m.userData.obstacle.name) ? COLOUR.hit : COLOUR.free);
    });
  }

  // For the tests: the drawn obstacles read back from three.js, in the root frame:
  // position, orientation [x, y, z, w], the geometry's extent in the obstacle's own frame
  // (min, max corners) and whether it is drawn in the collision colour.
  drawn() {
    return this.obstacles.children.map((m) => {
      m.geometry.computeBoundingBox();
      const box = m.geometry.boundingBox;
      return {
        name: m.userData.obstacle.name,
        shape: m.userData.obstacle.shape,
        position: m.position.toArray(),
        orientation: m.quaternion.toArray(),
        min: box.min.toArray(),
        max: box.max.toArray(),
        red: m.material.color.getHex() === COLOUR.hit,
      };
    });
  }
}
