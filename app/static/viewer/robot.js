// A robot on the stage: its URDF (GET /robots/{id}/urdf) loaded by urdf-loader with the
// meshes served by GET /robots/{id}/files/..., posed from configurations in the API's joint
// order (GET /robots/{id}: `joints`; mimic followers follow their leader).
import * as THREE from 'three';
import URDFLoader from 'urdf-loader';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';

// One material for every highlighted mesh (made once: a new one per check would leak).
const HIGHLIGHT = new THREE.MeshPhongMaterial({ color: 0xe02020, emissive: 0x400000 });

// Mesh URIs that start with files.uri_prefix are served at files.url + the rest.
function rewriteMeshUris(urdf, files) {
  if (!files) return urdf;
  return urdf.split(`"${files.uri_prefix}`).join(`"${files.url}`)
    .split(`'${files.uri_prefix}`).join(`'${files.url}`);
}

// The URDF link a mesh belongs to (its nearest link ancestor).
function ownerLink(object) {
  let o = object;
  while (o && !o.isURDFLink) o = o.parent;
  return o;
}

export class RobotView {
  constructor(detail, urdfRobot, stats) {
    this.detail = detail;
    this.root = urdfRobot;
    this.stats = stats;
    this._highlighted = [];
  }

  // Load the robot described by `detail` (GET /robots/{id}) from `urdfText`; resolves once
  // every mesh has loaded or failed. stats: {meshes (URDF visual meshes), loaded, failed,
  // primitives}.
  static load(detail, urdfText) {
    return new Promise((resolve) => {
      const manager = new THREE.LoadingManager();
      const loader = new URDFLoader(manager);
      const stats = { meshes: 0, loaded: 0, failed: 0, primitives: 0 };
      let parsed = false;
      let robot = null;
      const finish = () => {
        if (parsed && stats.loaded + stats.failed === stats.meshes) {
          resolve(new RobotView(detail, robot, stats));
        }
      };
      loader.loadMeshCb = (path, mgr, material, done) => {
        stats.meshes += 1;
        const settle = (obj, err) => {
          if (err || !obj) {
            stats.failed += 1;
            console.warn(`mesh ${path} not loaded:`, err);
          } else {
            stats.loaded += 1;
          }
          done(obj, err);
          finish();
        };
        if (/\.obj$/i.test(path)) {
          // The OBJ loader gives its own grey material: draw it in the URDF's colour, as
          // urdf-loader does for STL and Collada (e.g. an MJCF robot's material rgba).
          const coloured = (obj) => {
            obj.traverse((c) => { if (c.isMesh) c.material = material; });
            settle(obj);
          };
          new OBJLoader(mgr).load(path, coloured, null, (e) => settle(null, e));
        } else if (/\.(stl|dae)$/i.test(path)) {
          loader.defaultMeshLoader(path, mgr, material, settle);
        } else {
          settle(null, 'no loader for this format');
        }
      };
      robot = loader.parse(rewriteMeshUris(urdfText, detail.files));
      // Loaded meshes arrive later; the visuals' meshes now are the URDF's primitives.
      robot.traverse((o) => {
        if (o.isURDFVisual) {
          o.children.forEach((c) => { if (c.isMesh) stats.primitives += 1; });
        }
      });
      parsed = true;
      finish();
    });
  }

  // Pose the robot: q in the API's joint order.
  setConfig(q) {
    this.detail.joints.forEach((j, i) => this.root.setJointValue(j.name, q[i]));
    this.root.updateMatrixWorld(true);
  }

  // A frame's pose in the robot's root frame: {position, orientation [x, y, z, w], matrix}.
  framePose(name) {
    const obj = this.root.frames[name];
    if (!obj) return null;
    this.root.updateMatrixWorld(true);
    const m = this.root.matrixWorld.clone().invert().multiply(obj.matrixWorld);
    const p = new THREE.Vector3();
    const r = new THREE.Quaternion();
    m.decompose(p, r, new THREE.Vector3());
    const e = m.elements; // column-major
    const rows = [0, 1, 2, 3].map((i) => [e[i], e[4 + i], e[8 + i], e[12 + i]]);
    return { position: p.toArray(), orientation: [r.x, r.y, r.z, r.w], matrix: rows };
  }

  // Number of THREE.Mesh objects the robot draws.
  meshCount() {
    let n = 0;
    this.root.traverse((o) => { if (o.isMesh) n += 1; });
    return n;
  }

  // Colour the named links red (collisions); the rest back to their own materials.
  highlight(linkNames) {
    for (const [mesh, material] of this._highlighted) mesh.material = material;
    this._highlighted = [];
    for (const name of linkNames) {
      const link = this.root.links[name];
      if (!link) continue;
      link.traverse((o) => {
        if (!o.isMesh || ownerLink(o) !== link) return;
        this._highlighted.push([o, o.material]);
        o.material = HIGHLIGHT;
      });
    }
  }

  // Whether the link's own meshes are highlighted.
  isHighlighted(linkName) {
    const link = this.root.links[linkName];
    return this._highlighted.some(([mesh]) => ownerLink(mesh) === link);
  }

  // Take the robot off the stage and free its GPU resources: geometries, materials (the
  // URDF's and the meshes' own) and their textures.
  dispose() {
    this.highlight([]);
    this.root.removeFromParent();
    this.root.traverse((o) => {
      if (!o.isMesh) return;
      o.geometry?.dispose();
      [o.material].flat().forEach((m) => {
        Object.values(m).forEach((value) => { if (value?.isTexture) value.dispose(); });
        m.dispose();
      });
    });
  }
}
