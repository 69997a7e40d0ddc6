// A Cartesian path played back: a straight line of the tip (the end effector) from its
// current pose to the same orientation moved by (dx, dy, dz) metres in the root frame,
// planned by POST /robots/{id}/ik/path (start = the current configuration, one waypoint)
// and played back: the answer's `points` in order (play, or the scrub slider). The line
// asked for is drawn; the readout gives the fraction reached and, when it stopped, where
// and why (`failure`).
import * as THREE from 'three';
import { Latest } from './latest.js';

//: Planning options sent with every path: a fixed iteration cap and random seed make the
//: answer the same on every call (see the route's random_seed), 40 ms per point at most.
export const PATH_OPTIONS = { timeout_ms: 40, max_iterations: 500, random_seed: 0 };
const POINTS_PER_SECOND = 30;
const LINE_PIECES = 64;

export class PathPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.section = document.getElementById('panel-path');
    this.section.innerHTML = `<h2>Cartesian path</h2>
      <p>tip moves by dx, dy, dz (m, root frame)<br>
        <input id="path-dx" type="number" step="0.01" value="0" aria-label="dx" style="width: 6em">
        <input id="path-dy" type="number" step="0.01" value="0" aria-label="dy" style="width: 6em">
        <input id="path-dz" type="number" step="0.01" value="-0.05" aria-label="dz"
               style="width: 6em"></p>
      <button id="path-plan" type="button">Plan line</button>
      <button id="path-play" type="button" disabled>Play</button>
      <input id="path-scrub" type="range" min="0" max="0" step="1" value="0" disabled
             aria-label="Path point">
      <p id="path-readout"></p>`;
    this.inputs = ['dx', 'dy', 'dz'].map((k) => document.getElementById(`path-${k}`));
    this.playButton = document.getElementById('path-play');
    this.scrub = document.getElementById('path-scrub');
    this.readout = document.getElementById('path-readout');
    this.lastRequest = null; // the body of the last POST …/ik/path
    this.lastAnswer = null; // its answer
    this.index = -1; // the point shown
    this.playing = false;

    // the line asked for, drawn over the robot, with a dot at its end
    this.line = new THREE.Line(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0xef6c00, depthTest: false }),
    );
    this.line.name = 'cartesian-path';
    this.line.renderOrder = 10;
    this.line.visible = false;
    this.end = new THREE.Mesh(
      new THREE.SphereGeometry(0.008, 12, 8),
      new THREE.MeshBasicMaterial({ color: 0xef6c00, depthTest: false }),
    );
    this.end.renderOrder = 10;
    this.line.add(this.end);
    viewer.stage.world.add(this.line);

    this.planner = new Latest((delta) => this._plan(delta), (e) => this._failed(e));
    document.getElementById('path-plan').addEventListener('click', () => this.plan());
    this.playButton.addEventListener('click', () => (this.playing ? this.stop() : this.play()));
    this.scrub.addEventListener('input', () => {
      this.stop();
      this.showPoint(Number(this.scrub.value));
    });
  }

  build() {
    this.lastRequest = null;
    this.clear('');
  }

  // Nothing to play: no line, no answer, the readout says `text`.
  clear(text) {
    this.stop();
    this.lastAnswer = null;
    this.index = -1;
    this.line.visible = false;
    this.playButton.disabled = true;
    this.scrub.disabled = true;
    this.readout.textContent = text;
    this.viewer.stage.render();
  }

  // Plan the line for the (dx, dy, dz) of the inputs (metres, root frame).
  plan() {
    this.stop();
    this.planner.request(this.inputs.map((i) => Number(i.value)));
  }

  async _plan(delta) {
    const v = this.viewer;
    const q = v.q.slice();
    const frame = v.detail.end_effector;
    const fk = await v.ask('/fk', { q, frames: [frame] });
    if (!fk) return; // another robot was loaded meanwhile
    const start = fk.poses[frame];
    const to = start.position.map((x, i) => x + delta[i]);
    const body = {
      start: q,
      waypoints: [{ position: to, orientation: start.orientation }],
      ...PATH_OPTIONS,
    };
    this.readout.textContent = 'planning…';
    const answer = await v.ask('/ik/path', body);
    if (!answer) return; // another robot was loaded meanwhile
    this.lastRequest = body;
    this.lastAnswer = answer;
    this.line.geometry.dispose();
    // in short pieces: a long line that passes behind the camera is still drawn in front
    const [a, b] = [start.position, to].map((p) => new THREE.Vector3(...p));
    this.line.geometry = new THREE.BufferGeometry().setFromPoints(
      Array.from({ length: LINE_PIECES + 1 }, (_, k) => a.clone().lerp(b, k / LINE_PIECES)),
    );
    this.end.position.fromArray(to);
    this.line.visible = true;
    const n = answer.points.length;
    this.scrub.max = String(n - 1);
    this.scrub.disabled = n < 2;
    this.playButton.disabled = n < 2;
    this.index = 0;
    this.scrub.value = '0';
    this.readout.textContent = PathPanel.summary(answer);
    v.stage.render();
  }

  // A request the API refused (e.g. a line too long for the server's budget): nothing to play.
  _failed(err) {
    this.clear(`not planned: ${err.message || err}`);
    this.viewer.report(err);
  }

  // "fraction 0.73: stopped at s=0.7312 (singular: …)" or "fraction 1.00: complete".
  static summary(answer) {
    const head = `fraction ${answer.fraction.toFixed(2)}`;
    const n = `${answer.points.length} points`;
    const f = answer.failure;
    if (!f) return `${head}: complete, ${n}`;
    return `${head}: stopped at s=${f.s.toFixed(4)} (${f.reason}), ${n}; ${f.detail}`;
  }

  // Pose the robot at point i of the last answer.
  showPoint(i) {
    const points = this.lastAnswer?.points || [];
    if (i < 0 || i >= points.length) return;
    this.index = i;
    this.scrub.value = String(i);
    this.viewer.setQ(points[i].q.slice(), 'path');
  }

  play() {
    const points = this.lastAnswer?.points || [];
    if (points.length < 2) return;
    this.playing = true;
    this.playButton.textContent = 'Stop';
    const first = this.index >= points.length - 1 ? 0 : Math.max(this.index, 0);
    let t0 = null;
    const step = (now) => {
      if (!this.playing) return;
      t0 ??= now;
      const i = Math.min(first + Math.floor(((now - t0) / 1000) * POINTS_PER_SECOND),
        points.length - 1);
      if (i !== this.index) this.showPoint(i);
      if (i === points.length - 1) this.stop();
      else requestAnimationFrame(step);
    };
    this.showPoint(first);
    requestAnimationFrame(step);
  }

  stop() {
    this.playing = false;
    this.playButton.textContent = 'Play';
  }
}
