// Torque-ratio bars of the joints panel: POST /robots/{id}/dynamics with {q} (the robot at
// rest: the torques that hold it, N·m or N) on every configuration change, one request in
// flight and the latest wins (Latest, as every live query of the viewer). Each joint's bar
// is |τ| / effort limit (effort_ratios of the answer): 0–100 % wide, red ("over") past
// 100 %, the binding joint marked; the tooltip gives τ and the limit. A joint without a
// limit (null ratio) has an empty bar and says so. A robot without inertias answers 422
// missing-inertia: no bars, one line "no inertias in this robot's description"; any other
// failure is one line as well, never an error in the page's status. A URDF in which some
// moving body (a joint's child link with the links fixed to it) has no mass and no inertia
// says the same without asking: the answer could only be that 422 (the core's check,
// app/kinematics/dynamics.py check_inertias).
import { Latest } from './latest.js';

export const NO_INERTIAS = "no inertias in this robot's description";
const MISSING_INERTIA = 'missing-inertia';

const MIN_BODY = 1e-12; // kg and kg·m², the core's MIN_BODY_MASS

// Whether a link's own <inertial> has a mass or a rotational inertia.
function carries(link) {
  const node = link.urdfNode?.querySelector?.(':scope > inertial');
  if (!node) return false;
  const mass = Number(node.querySelector('mass')?.getAttribute('value') || 0);
  const inertia = node.querySelector('inertia');
  const moments = ['ixx', 'iyy', 'izz'].map((k) => Math.abs(Number(inertia?.getAttribute(k) || 0)));
  return mass > MIN_BODY || Math.max(...moments) > MIN_BODY;
}

// Whether the body that moves with `joint` (its child link and every link fixed to it)
// carries inertia.
function bodyCarries(joint) {
  const stack = joint.children.filter((c) => c.isURDFLink);
  while (stack.length) {
    const link = stack.pop();
    if (carries(link)) return true;
    link.children
      .filter((c) => c.isURDFJoint && c.jointType === 'fixed')
      .forEach((j) => stack.push(...j.children.filter((c) => c.isURDFLink)));
  }
  return false;
}

// Whether every moving body of the robot carries inertia (else dynamics answer 422).
export function hasInertias(root) {
  const joints = Object.values(root?.joints || {}).filter((j) => j.jointType !== 'fixed');
  return joints.length > 0 && joints.every(bodyCarries);
}

// τ for the tooltip: 3 decimals, without a "-0.000".
const fmt = (x) => (Math.abs(x) < 5e-4 ? 0 : x).toFixed(3);

const unit = (joint) => (joint && joint.type === 'prismatic' ? 'N' : 'N·m');

export class TorqueBars {
  constructor(viewer, note) {
    this.viewer = viewer;
    this.note = note;
    this.bars = new Map(); // joint name -> {bar, fill, joint}
    this.last = null; // {q, answer} of the last answer drawn
    this.inertias = false; // whether every moving body of the robot's URDF carries inertia
    this.fetch = new Latest((q) => this._fetch(q), () => {});
  }

  // A new robot: its bars follow (an answer for the old one finds another map and is dropped).
  reset() {
    this.bars = new Map();
  }

  // One bar (hidden until an answer comes) for the slider row of `joint`.
  bar(joint) {
    const bar = document.createElement('span');
    bar.className = 'torque-bar';
    bar.dataset.joint = joint.name;
    bar.hidden = true;
    const fill = document.createElement('span');
    fill.className = 'torque-fill';
    bar.append(fill);
    this.bars.set(joint.name, { bar, fill, joint });
    return bar;
  }

  build() {
    this.last = null;
    this.inertias = hasInertias(this.viewer.robot?.root);
    this._message(this.inertias ? '' : NO_INERTIAS);
  }

  update(q) {
    if (this.inertias) this.fetch.request(q.slice());
  }

  _message(text) {
    this.note.textContent = text;
    this.note.hidden = !text;
  }

  _hide(text) {
    this.bars.forEach(({ bar }) => { bar.hidden = true; });
    this._message(text);
  }

  async _fetch(q) {
    const v = this.viewer;
    const bars = this.bars;
    let answer;
    try {
      answer = await v.ask('/dynamics', { q });
    } catch (err) {
      if (bars !== this.bars) return;
      const kind = String(err.problem?.type || '').split('/').pop();
      this._hide(kind === MISSING_INERTIA ? NO_INERTIAS : `no torques: ${err.message || err}`);
      return;
    }
    if (!answer || bars !== this.bars) return; // another robot
    if (v.q.some((x, i) => x !== q[i]) && this.fetch.next !== null) return; // stale
    this.last = { q, answer };
    this._message('');
    answer.joint_names.forEach((name, i) => {
      const entry = bars.get(name);
      if (!entry) return;
      const { bar, fill, joint } = entry;
      const tau = answer.torques[i];
      const limit = answer.effort_limits[i];
      const ratio = answer.effort_ratios[i];
      const u = unit(joint);
      bar.hidden = false;
      bar.classList.toggle('no-limit', ratio === null);
      bar.classList.toggle('over', ratio !== null && ratio > 1);
      bar.classList.toggle('binding', name === answer.binding_joint);
      fill.style.width = ratio === null ? '0%' : `${Math.min(ratio, 1) * 100}%`;
      bar.title = `${name}: τ = ${fmt(tau)} ${u}, ` + (ratio === null
        ? 'no effort limit'
        : `limit ${limit} ${u} (${(ratio * 100).toFixed(1)} %)`) +
        (name === answer.binding_joint ? ' — binding joint' : '');
    });
  }
}
