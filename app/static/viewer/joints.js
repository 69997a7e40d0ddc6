// Joint sliders within the limits of GET /robots/{id} and the pose of a chosen frame by
// POST /robots/{id}/fk, shown next to the sliders (metres, quaternion [x, y, z, w]).
// Under each slider a torque bar: |τ| / effort limit of POST /robots/{id}/dynamics at the
// configuration, at rest (0–100 %, red past 100 %, the binding joint marked; the tooltip
// gives τ and the limit). A robot without inertias (422 missing-inertia) shows no bars and
// one line saying so; the torques never raise an error in the page's status line.
import { Latest } from './latest.js';
import { TorqueBars } from './torques.js';

const fmt = (v) => v.map((x) => x.toFixed(6)).join(', ');

export function limitsOf(joint) {
  if (joint.continuous || !joint.limits) return [-Math.PI, Math.PI];
  return [joint.limits.lower, joint.limits.upper];
}

export class JointsPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.sliders = [];
    this.lastFk = null; // {q, frame, pose} of the last FK answer
    this.frame = document.getElementById('frame-picker');
    this.readout = document.getElementById('fk-readout');
    this.fk = new Latest((q, frame) => this._fk(q, frame), (e) => viewer.report(e));
    this.torques = new TorqueBars(viewer, document.getElementById('torque-note'));
    this.frame.addEventListener('change', () => this.update());
    document.getElementById('reset-neutral').addEventListener('click', () => {
      viewer.setQ(viewer.detail.neutral.slice(), 'neutral');
    });
  }

  build(detail) {
    this.frame.replaceChildren(...detail.frames.map((f) => new Option(f.name, f.name)));
    this.frame.value = detail.end_effector;
    const box = document.getElementById('sliders');
    box.replaceChildren();
    this.torques.reset();
    this.sliders = detail.joints.map((joint, i) => {
      const [lo, hi] = limitsOf(joint);
      const row = document.createElement('label');
      row.className = 'slider';
      const name = document.createElement('span');
      name.textContent = joint.name;
      const input = document.createElement('input');
      Object.assign(input, { type: 'range', min: lo, max: hi, step: (hi - lo) / 1000 });
      input.dataset.joint = joint.name;
      const value = document.createElement('output');
      input.addEventListener('input', () => {
        const q = this.viewer.q.slice();
        q[i] = Number(input.value);
        this.viewer.setQ(q, 'slider');
      });
      const bar = this.torques.bar(joint);
      row.append(name, input, value, bar);
      box.append(row);
      return { input, value, joint };
    });
    this.torques.build(detail);
  }

  // The configuration changed (from anywhere): sliders follow, FK is asked again.
  update() {
    const q = this.viewer.q;
    this.sliders.forEach(({ input, value, joint }, i) => {
      input.value = q[i];
      value.textContent = q[i].toFixed(joint.type === 'prismatic' ? 4 : 3);
    });
    this.fk.request(q.slice(), this.frame.value);
    this.torques.update(q);
  }

  async _fk(q, frame) {
    const v = this.viewer;
    const answer = await v.ask('/fk', { q, frames: [frame] });
    if (!answer || (v.q.some((x, i) => x !== q[i]) && this.fk.next !== null)) return; // stale
    const pose = answer.poses[frame];
    this.lastFk = { q, frame, pose };
    this.readout.textContent =
      `${frame}\nposition  [${fmt(pose.position)}] m\n` +
      `orientation [${fmt(pose.orientation)}] (x, y, z, w)` +
      (answer.within_limits ? '' : `\noutside limits: ${answer.joints_outside_limits.join(', ')}`);
  }
}
