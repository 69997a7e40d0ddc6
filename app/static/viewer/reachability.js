// A reachability map as a slice plane. The picker lists the robot's stored maps (GET
// /robots/{id}/reachability/maps); "Build" starts a coarse one (POST …/reachability, a
// write: it sends the page's API token when one is typed) and polls its job to the end. The
// picked map is shown as a horizontal plane at the centre height z of one voxel layer (the
// slider), textured with GET …/maps/{map_id}/slice.png?z=… and placed exactly over the
// map's bounds in x and y. The image's columns run along +x and its rows along +y (top row
// = largest y), as app/api/images.py slice_image draws them.
import * as THREE from 'three';
import { Latest } from './latest.js';

export class ReachabilityPanel {
  constructor(viewer) {
    this.viewer = viewer;
    this.section = document.getElementById('panel-reachability');
    this.section.innerHTML = `<h2>Reachability</h2>
      <label>Map <select id="map-picker" style="max-width: 240px">
        <option value="">none</option></select>
        <button id="map-refresh" type="button" title="List the maps again">↻</button></label>
      <label>Slice z <input id="map-layer" type="range" min="0" max="0" step="1" value="0">
        <output id="map-z"></output></label>
      <label>Build: voxel <input id="map-voxel" type="number" value="0.1" min="0.02"
        step="0.01" style="width: 4em"> m, samples <input id="map-samples" type="number"
        value="20000" min="1000" step="1000" style="width: 6em">
        <button id="map-build" type="button">Build</button></label>
      <p id="map-readout"></p>`;
    this.picker = document.getElementById('map-picker');
    this.layer = document.getElementById('map-layer');
    this.zOut = document.getElementById('map-z');
    this.readout = document.getElementById('map-readout');
    this.maps = []; // GET …/reachability/maps answer
    this.shown = null; // {map, layer, z, url, width, height} of the slice on the plane

    this.plane = new THREE.Mesh(
      new THREE.PlaneGeometry(1, 1), // unit square in the xy plane, scaled to the bounds
      new THREE.MeshBasicMaterial({
        side: THREE.DoubleSide, transparent: true, opacity: 0.85, depthWrite: false,
      }),
    );
    this.plane.name = 'reachability-slice';
    this.plane.visible = false;
    viewer.stage.world.add(this.plane);

    const report = (e) => viewer.report(e);
    this.lister = new Latest(() => this.listMaps(), report);
    this.slice = new Latest((map, layer) => this._slice(map, layer), report);
    document.getElementById('map-refresh').addEventListener('click', () => this.lister.request());
    this.builder = new Latest(() => this.buildMap(), report);
    document.getElementById('map-build').addEventListener('click', () => this.builder.request());
    this.picker.addEventListener('change', () => this.pick());
    this.layer.addEventListener('input', () => this.pick(Number(this.layer.value)));
  }

  build() {
    this.picker.replaceChildren(new Option('none', ''));
    this.hide();
    this.lister.request();
  }

  get map() { return this.maps.find((m) => m.map_id === this.picker.value) || null; }

  async listMaps() {
    const answer = await this.viewer.ask('/reachability/maps');
    if (!answer) return; // another robot was loaded meanwhile
    const { maps } = answer;
    const current = this.picker.value;
    this.maps = maps;
    this.picker.replaceChildren(new Option('none', ''), ...maps.map((m) => new Option(
      `${m.map_id.slice(0, 8)} (${m.frame}, ${m.voxel_size} m, ${m.shape.join('×')})`, m.map_id,
    )));
    this.picker.value = maps.some((m) => m.map_id === current) ? current : '';
  }

  // Build a map of the tip's positions (no orientation bins) and show it when done.
  async buildMap() {
    const v = this.viewer;
    const robotId = v.detail.id;
    const body = {
      voxel_size: Number(document.getElementById('map-voxel').value),
      samples: Number(document.getElementById('map-samples').value),
      orientation_divisions: 0,
      seed: 0,
    };
    let job = await v.ask('/reachability', body);
    if (!job) return; // another robot was loaded meanwhile
    const jobPath = v.path(`/reachability/jobs/${encodeURIComponent(job.job_id)}`);
    while (job.status === 'queued' || job.status === 'running') {
      this.readout.textContent = `building: ${job.status}`;
      await new Promise((resolve) => { setTimeout(resolve, 250); });
      if (v.detail.id !== robotId) return; // another robot was picked meanwhile
      job = await v.api.get(jobPath);
    }
    if (job.status !== 'done') throw new Error(`map build ${job.status}: ${job.error || ''}`);
    await this.listMaps();
    this.picker.value = job.map_id;
    this.pick();
  }

  // Show the picked map at voxel layer `layer` (default: the middle one).
  pick(layer = null) {
    const map = this.map;
    if (!map) {
      this.hide();
      return;
    }
    const n = map.shape[2];
    this.layer.max = String(n - 1);
    const i = layer ?? Math.floor(n / 2);
    this.layer.value = String(i);
    this.slice.request(map, i);
  }

  hide() {
    this.plane.visible = false;
    this.shown = null;
    this.readout.textContent = '';
    this.zOut.textContent = '';
    this.viewer.stage.render();
  }

  // Centre height (m) of voxel layer i of the map.
  static layerZ(map, i) { return map.bounds.min[2] + (i + 0.5) * map.voxel_size; }

  async _slice(map, i) {
    const z = ReachabilityPanel.layerZ(map, i);
    const url = this.viewer.path(
      `/reachability/maps/${encodeURIComponent(map.map_id)}/slice.png?z=${z}`,
    );
    const png = await this.viewer.api.blob(url);
    // decoded bottom row first: with flipY off, texture v = 0 is the image's bottom (min y)
    const image = await createImageBitmap(png, { imageOrientation: 'flipY' });
    if (this.map !== map || Number(this.layer.value) !== i) return; // stale
    const texture = new THREE.Texture(image);
    texture.flipY = false;
    texture.colorSpace = THREE.SRGBColorSpace;
    texture.magFilter = THREE.NearestFilter;
    texture.needsUpdate = true;
    const old = this.plane.material.map;
    this.plane.material.map = texture;
    this.plane.material.needsUpdate = true;
    old?.image?.close?.();
    old?.dispose();
    const [x0, y0] = map.bounds.min;
    const [x1, y1] = map.bounds.max;
    this.plane.scale.set(x1 - x0, y1 - y0, 1);
    this.plane.position.set((x0 + x1) / 2, (y0 + y1) / 2, z);
    this.plane.visible = true;
    this.shown = { map_id: map.map_id, layer: i, z, url, width: image.width, height: image.height };
    this.zOut.textContent = `${z.toFixed(3)} m`;
    this.readout.textContent = `layer ${i + 1}/${map.shape[2]} at z = ${z.toFixed(4)} m; ` +
      `${map.reachable_voxels} reachable voxels; colour: best manipulability ` +
      `(max ${map.max_manipulability?.toExponential(3) ?? '—'}), grey: unreached`;
    this.viewer.stage.render();
  }

  // For the tests: the plane's corners in the root frame (the unit square through the
  // mesh's matrix) and the texture's image size.
  drawn() {
    if (!this.plane.visible) return null;
    this.plane.updateMatrix();
    const corner = (x, y) => new THREE.Vector3(x, y, 0).applyMatrix4(this.plane.matrix).toArray();
    const image = this.plane.material.map.image;
    return {
      ...this.shown,
      min: corner(-0.5, -0.5),
      max: corner(0.5, 0.5),
      texture: { width: image.width, height: image.height },
    };
  }

  // For the tests: the texture's RGBA at texel (u, v) counted from its first texel (v = 0:
  // the row texture coordinate 0 samples).
  texel(u, v) {
    const image = this.plane.material.map.image;
    const canvas = new OffscreenCanvas(image.width, image.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(image, 0, 0);
    return Array.from(ctx.getImageData(u, v, 1, 1).data);
  }
}
