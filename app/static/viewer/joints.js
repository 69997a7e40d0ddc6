// Joint sliders within the limits of GET /robots/{id} and the pose of a chosen frame by
// POST /robots/{id}/fk, shown next to the sliders (metres, quaternion [x, y, z, w]).
import { Latest } from './latest.js';

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
      row.append(name, input, value);
      box.append(row);
      return { input, value, joint };
    });
  }

  // The configuration changed (from anywhere): sliders follow, FK is asked again.
  update() {
    const q = this.viewer.q;
    this.sliders.forEach(({ input, value, joint }, i) => {
      input.value = q[i];
      value.textContent = q[i].toFixed(joint.type === 'prismatic' ? 4 : 3);
    });
    this.fk.request(q.slice(), this.frame.value);
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
