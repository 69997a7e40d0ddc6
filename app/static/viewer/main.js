// The viewer: picks a robot, poses it, and hands every change to the panels. Each panel is
// a class with optional `build(detail)` (a robot was loaded) and `update(source)` (the
// configuration changed; source: 'slider', 'ik', 'path', 'neutral', 'load', ...).
// `window.denavit` exposes the state to the browser tests (tests/browser).
import { api, robotPath, setupToken } from './api.js';
import { Stage } from './stage.js';
import { RobotView } from './robot.js';
import { Latest } from './latest.js';
import { JointsPanel } from './joints.js';
import { IkPanel } from './ik.js';
import { EllipsoidPanel } from './ellipsoid.js';
import { CollisionsPanel } from './collisions.js';
import { ReachabilityPanel } from './reachability.js';
import { PathPanel } from './path.js';

class Viewer {
  constructor() {
    this.api = api;
    this.stage = new Stage(document.getElementById('stage'));
    this.status = document.getElementById('status');
    this.robot = null;
    this.detail = null;
    this.q = [];
    this.panels = [];
    this.ready = false;
    this.choice = 0; // which load() is the latest choice: only it may render
    this.loading = 0; // load() calls not yet settled (the latest or an abandoned one)
  }

  path(suffix = '') { return robotPath(this.detail.id, suffix); }

  // Call the shown robot's route `suffix`: GET, or POST when there is a body. Resolves to
  // the API's answer, or to null when another robot was loaded before it came (the answer
  // belongs to the old robot: the caller drops it).
  async ask(suffix, body) {
    const { detail } = this;
    const url = this.path(suffix);
    const answer = await (body === undefined ? api.get(url) : api.post(url, body));
    return this.detail === detail ? answer : null;
  }

  report(err) {
    this.status.textContent = err ? String(err.message || err) : '';
    this.status.classList.toggle('error', Boolean(err));
  }

  async start() {
    setupToken();
    const picker = document.getElementById('robot-picker');
    const { robots } = await api.get('/robots');
    picker.replaceChildren(...robots.map((r) => new Option(`${r.id} (${r.source})`, r.id)));
    const wanted = document.body.dataset.robotId || robots[0]?.id;
    picker.addEventListener('change', () => this.load(picker.value).catch((e) => this.report(e)));
    picker.value = wanted;
    await this.load(wanted);
  }

  // Show robot `robotId`. Loads may finish out of order (a large robot chosen first, a
  // small one next): only the latest choice renders; an older load that finishes later is
  // dropped, its errors too.
  async load(robotId) {
    this.choice += 1;
    const choice = this.choice;
    const latest = () => choice === this.choice;
    this.loading += 1;
    this.ready = false;
    this.report(null);
    let view;
    try {
      const [detail, urdf] = await Promise.all([
        api.get(robotPath(robotId)), api.get(robotPath(robotId, '/urdf')),
      ]);
      if (!latest()) return;
      view = await RobotView.load(detail, urdf);
      if (!latest()) {
        view.dispose();
        return;
      }
    } catch (err) {
      if (latest()) throw err;
      return;
    } finally {
      this.loading -= 1;
    }
    const { detail } = view;
    if (this.robot) this.robot.dispose();
    this.robot = view;
    this.detail = detail;
    this.stage.world.add(view.root);
    history.replaceState(null, '', `/viewer/${encodeURIComponent(robotId)}`);
    document.title = `Denavit viewer: ${robotId}`;
    this.panels.forEach((p) => p.build?.(detail));
    this.setQ(detail.neutral.slice(), 'load');
    this.stage.frame(view.root);
    if (view.stats.failed) this.report(`${view.stats.failed} mesh(es) not loaded`);
    this.ready = true;
  }

  setQ(q, source) {
    this.q = q;
    this.robot.setConfig(q);
    this.stage.render();
    this.panels.forEach((p) => p.update?.(source));
  }
}

const viewer = new Viewer();
const panels = {
  joints: new JointsPanel(viewer),
  ik: new IkPanel(viewer),
  ellipsoid: new EllipsoidPanel(viewer),
  collisions: new CollisionsPanel(viewer),
  reachability: new ReachabilityPanel(viewer),
  path: new PathPanel(viewer),
};
viewer.panels.push(...Object.values(panels));

// The tests' window on the viewer (read-only use; the page itself never reads it).
window.denavit = {
  viewer,
  panels,
  idle: () => viewer.ready && viewer.loading === 0 && Latest.pending === 0,
};

viewer.start().catch((err) => {
  viewer.report(err);
  console.error('viewer failed to start:', err);
});
