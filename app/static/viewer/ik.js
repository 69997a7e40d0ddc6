// A target gizmo at the tip (the robot's end effector): dragging it calls POST
// /robots/{id}/ik as it moves, seeded by the current configuration so the arm keeps its
// branch; "Other branches" asks for several solutions of the tip's pose and lists them.
// The target is in the robot's root frame: position in metres, quaternion [x, y, z, w].
import * as THREE from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import { Latest } from './latest.js';

// An iteration cap ends a search (a few ms), the clock only backs it up: the same drag gives
// the same answers on a busy machine, and an unreachable target fails fast.
export const IK_OPTIONS = { timeout_ms: 500, max_iterations: 1000, random_seed: 0 };

const fmt = (v, n = 4) => v.map((x) => x.toFixed(n)).join(', ');

export class IkPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.stage = viewer.stage;
    this.readout = document.getElementById('ik-readout');
    this.branchList = document.getElementById('branches');
    this.last = null; // {target, answer} of the last IK answer
    this.dragging = false;

    this.target = new THREE.Group();
    this.target.name = 'ik-target';
    this.target.add(new THREE.AxesHelper(0.08));
    this.marker = new THREE.Mesh(
      new THREE.SphereGeometry(0.012, 16, 12),
      new THREE.MeshBasicMaterial({ color: 0x1565c0 }),
    );
    this.target.add(this.marker);
    this.stage.world.add(this.target);

    this.controls = new TransformControls(this.stage.camera, this.stage.renderer.domElement);
    this.controls.setSize(0.8);
    this.controls.attach(this.target);
    this.stage.scene.add(this.controls.getHelper());
    this.controls.addEventListener('change', () => this.stage.render());
    this.controls.addEventListener('dragging-changed', (e) => {
      this.dragging = e.value;
      this.stage.controls.enabled = !e.value;
      if (!e.value) this.solve.request(this.targetPose());
    });
    this.controls.addEventListener('objectChange', () => {
      if (this.dragging) this.solve.request(this.targetPose());
    });
    this.solve = new Latest((target) => this._solve(target), (e) => viewer.report(e));

    document.getElementById('gizmo-toggle').addEventListener('change', (e) => {
      this.controls.enabled = e.target.checked;
      this.controls.getHelper().visible = e.target.checked;
      this.target.visible = e.target.checked;
      this.stage.render();
    });
    document.getElementById('gizmo-rotate').addEventListener('change', (e) => {
      this.controls.setMode(e.target.checked ? 'rotate' : 'translate');
      this.stage.render();
    });
    document.getElementById('branches-button').addEventListener('click', () => {
      this.branches().catch((err) => viewer.report(err));
    });
  }

  build() {
    this.branchList.replaceChildren();
    this.readout.textContent = '';
  }

  // The configuration changed: unless it came from this panel's own IK, the target
  // jumps back to the tip.
  update(source) {
    if (source !== 'ik' && !this.dragging) this.snapToTip();
  }

  snapToTip() {
    const pose = this.viewer.robot.framePose(this.viewer.detail.end_effector);
    if (!pose) return;
    this.target.position.fromArray(pose.position);
    this.target.quaternion.set(...pose.orientation);
    this.marker.material.color.set(0x1565c0);
    this.stage.render();
  }

  // The gizmo's pose in the root frame: {position, orientation [x, y, z, w]}.
  targetPose() {
    const p = this.target.position;
    const r = this.target.quaternion;
    return { position: [p.x, p.y, p.z], orientation: [r.x, r.y, r.z, r.w] };
  }

  async _solve(target) {
    const v = this.viewer;
    const answer = await v.ask('/ik', { target, seed: v.q.slice(), ...IK_OPTIONS });
    if (!answer) return; // another robot was loaded meanwhile
    this.last = { target, answer };
    if (answer.success) {
      v.setQ(answer.q, 'ik');
      this.readout.textContent =
        `reached: ${(answer.position_error * 1e3).toExponential(2)} mm, ` +
        `${answer.orientation_error.toExponential(2)} rad (${answer.method}, ` +
        `${answer.solve_time_ms.toFixed(2)} ms)`;
    } else {
      this.readout.textContent = `not reached: ${answer.status}` +
        (answer.detail ? ` (${answer.detail})` : '');
    }
    this.marker.material.color.set(answer.success ? 0x1565c0 : 0xe02020);
    this.stage.render();
  }

  // Several solutions for the tip's current pose, each with its branch; a click takes it.
  async branches() {
    const v = this.viewer;
    const target = v.robot.framePose(v.detail.end_effector);
    const answer = await v.ask('/ik', {
      target: { position: target.position, orientation: target.orientation },
      seed: v.q.slice(),
      num_solutions: 8,
      timeout_ms: 200,
    });
    if (!answer) return; // another robot was loaded meanwhile
    const items = answer.solutions.map((s, i) => {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.type = 'button';
      button.textContent = `${s.branch || `solution ${i + 1}`}: moves ≤ ` +
        `${s.seed_distance.toFixed(3)}, q = [${fmt(s.q, 2)}]`;
      button.addEventListener('click', () => v.setQ(s.q.slice(), 'branch'));
      li.append(button);
      return li;
    });
    this.branchList.replaceChildren(...items);
    this.lastBranches = answer;
  }

  // For the tests: the page position of a point on the gizmo's arrow for `axis` ('X',
  // 'Y', 'Z'), near its outer end, where no other handle overlaps it.
  handleScreenPoint(axis) {
    const picker = this.controls._gizmo.picker[this.controls.mode];
    const i = 'XYZ'.indexOf(axis);
    const tip = (h) => { h.geometry.computeBoundingBox(); return h.geometry.boundingBox.max.getComponent(i); };
    // Two pickers per axis (the arrow's + and − halves): the + one.
    const handle = picker.children.filter((c) => c.name === axis).sort((a, b) => tip(b) - tip(a))[0];
    this.controls.getHelper().updateMatrixWorld(true);
    const point = new THREE.Vector3();
    point.setComponent(i, 0.85 * handle.geometry.boundingBox.max.getComponent(i));
    point.applyMatrix4(handle.matrixWorld);
    return this.stage.screenOf(this.stage.world.worldToLocal(point).toArray());
  }
}
