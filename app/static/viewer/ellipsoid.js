// The manipulability ellipsoid at the tip (POST /robots/{id}/manipulability): semi-axes
// along the left singular vectors u_i, half-lengths σ_i (world axes: reference "world"),
// drawn at a fixed scale; translational (vx vy vz) or, on the toggle, rotational
// (wx wy wz). Colour: the inverse condition number σ_min/σ_max, red (0, singular) to
// green (1, isotropic); the readout gives the singularity verdict.
import * as THREE from 'three';
import { Latest } from './latest.js';

//: Metres drawn per unit of σ (m/s per rad/s translational, rad/s per rad/s rotational).
export const SCALE = { translation: 0.3, rotation: 0.1 };
const MIN_DRAWN = 1e-4; // a lost direction is drawn flat, not as nothing

export class EllipsoidPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.toggle = document.getElementById('ellipsoid-toggle');
    this.rotational = document.getElementById('ellipsoid-rotational');
    this.readout = document.getElementById('ellipsoid-readout');
    this.last = null; // {q, part, answer}
    this.mesh = new THREE.Mesh(
      new THREE.SphereGeometry(1, 48, 24),
      new THREE.MeshPhongMaterial({ transparent: true, opacity: 0.45, depthWrite: false }),
    );
    this.mesh.name = 'manipulability-ellipsoid';
    this.mesh.matrixAutoUpdate = false;
    this.mesh.visible = false;
    viewer.stage.world.add(this.mesh);
    this.fetch = new Latest((q, part) => this._fetch(q, part), (e) => viewer.report(e));
    this.toggle.addEventListener('change', () => this.update());
    this.rotational.addEventListener('change', () => this.update());
  }

  get part() { return this.rotational.checked ? 'rotation' : 'translation'; }

  update() {
    if (!this.toggle.checked) {
      this.mesh.visible = false;
      this.readout.textContent = '';
      this.viewer.stage.render();
      return;
    }
    this.fetch.request(this.viewer.q.slice(), this.part);
  }

  async _fetch(q, part) {
    const v = this.viewer;
    const answer = await v.ask('/manipulability', { q, part });
    if (!answer || !this.toggle.checked) return; // another robot, or switched off
    this.last = { q, part, answer };
    const tip = v.robot.framePose(answer.frame);
    const { axes, half_lengths: lengths } = answer.velocity_ellipsoid;
    const cols = axes.map((u, i) => new THREE.Vector3(...u)
      .multiplyScalar(Math.max(lengths[i] ?? 0, MIN_DRAWN) * SCALE[part]));
    if (cols.length === 3) {
      const m = new THREE.Matrix4().makeBasis(cols[0], cols[1], cols[2]);
      m.setPosition(...tip.position);
      this.mesh.matrix.copy(m);
      this.mesh.visible = true;
    } else {
      this.mesh.visible = false; // fewer than 3 task rows: nothing to draw in 3-D
    }
    const c = answer.inverse_condition;
    this.mesh.material.color.setHSL((1 / 3) * c, 0.85, 0.5, THREE.SRGBColorSpace);
    this.readout.textContent =
      `${part}: σ = [${answer.singular_values.map((s) => s.toFixed(4)).join(', ')}], ` +
      `1/κ = ${c.toFixed(3)}, w = ${answer.yoshikawa.toExponential(3)}; ` +
      (answer.singular ? `SINGULAR (rank ${answer.rank})` : 'not singular') +
      ` — drawn at ${SCALE[part]} m per unit`;
    v.stage.render();
  }

  // For the tests: the drawn ellipsoid read back from its matrix, in the root frame:
  // centre, unit axes and half-lengths in σ units.
  drawn() {
    if (!this.mesh.visible) return null;
    const m = this.mesh.matrix;
    const x = new THREE.Vector3(), y = new THREE.Vector3(), z = new THREE.Vector3();
    m.extractBasis(x, y, z);
    const scale = SCALE[this.last.part];
    const cols = [x, y, z];
    return {
      centre: new THREE.Vector3().setFromMatrixPosition(m).toArray(),
      axes: cols.map((c) => c.clone().normalize().toArray()),
      half_lengths: cols.map((c) => c.length() / scale),
      colour: this.mesh.material.color.getHexString(),
    };
  }
}
