"""The scenario of the OpenAPI examples: the requests, in order (tests/openapi_examples.py
says what each key of a request spec means, runs them and compares the answers).

One request per 2xx answer of every operation of the document, on the catalog's planar
2-link arm ``planar2`` (small answers), a scene, three uploaded robots (a DH table as JSON
and as YAML, a URDF, a package with a mesh) and a reachability map; then a table of error
requests, one per status the service answers, each on a named operation (``shared``: the
document's example of that status wherever an operation has none of its own).
"""

from __future__ import annotations

import base64
import io
import zipfile
from typing import Any

ROBOT = "planar2"
Q = [0.5, 1.0]  # rad
# A two-link package: package.xml, the URDF and an ASCII STL mesh (one triangle).
_STL = (
    b"solid tri\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0.1 0 0\n"
    b"vertex 0 0.1 0\nendloop\nendfacet\nendsolid tri\n"
)
_PKG_XML = b'<package format="3"><name>two_link</name><version>1.0.0</version></package>'
_URDF = (
    '<robot name="two_link"><link name="base"/>'
    '<link name="l1"><collision><geometry><mesh filename="meshes/tri.stl"/></geometry>'
    '</collision></link><link name="tool"/>'
    '<joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>'
    '<axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>'
    '<joint name="j2" type="revolute"><parent link="l1"/><child link="tool"/>'
    '<origin xyz="0.5 0 0"/><axis xyz="0 0 1"/>'
    '<limit lower="-3" upper="3" effort="1" velocity="1"/></joint></robot>'
)


def _zip(files: dict[str, bytes]) -> str:
    """A deterministic zip of ``files`` (fixed dates), base64."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in files.items():
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, data)
    return base64.b64encode(buf.getvalue()).decode()


_PACKAGE = _zip(
    {
        "two_link/package.xml": _PKG_XML,
        "two_link/robot.urdf": _URDF.encode(),
        "two_link/meshes/tri.stl": _STL,
    }
)
_DH_YAML = (
    "name: lab_rr\ndescription: A planar RR arm\nconvention: standard\n"
    "units: {length: m, angle: deg}\njoints:\n"
    "  - {name: j1, type: revolute, a: 0.4, alpha: 0, d: 0, theta: 0, lower: -170, upper: 170}\n"
    "  - {name: j2, type: revolute, a: 0.3, alpha: 0, d: 0, theta: 0, lower: -170, upper: 170}\n"
)
_DH_JSON = {
    "name": "lab_rrp",
    "description": "RR arm with a prismatic wrist",
    "convention": "standard",
    "units": {"length": "m", "angle": "deg"},
    "joints": [
        {"name": "j1", "type": "revolute", "a": 0.4, "alpha": 0, "d": 0.1, "theta": 0},
        {"name": "j2", "type": "revolute", "a": 0.3, "alpha": 180, "d": 0, "theta": 0},
        {
            "name": "j3",
            "type": "prismatic",
            "a": 0,
            "alpha": 0,
            "d": 0,
            "theta": 0,
            "lower": 0,
            "upper": 0.2,
        },
    ],
}
_BUILD = {
    "voxel_size": 0.1,
    "bounds": {"min": [-1.9, -1.9, -0.05], "max": [1.9, 1.9, 0.05]},
    "orientation_divisions": 2,
    "rows": ["vx", "vy"],
    "samples": 4000,
    "seed": 0,
}
_OBSTACLE = {
    "name": "post",
    "shape": "box",
    "size": [0.1, 0.1, 1.0],
    "pose": {"position": [1.2, 0.9, 0.0]},
}
_TARGET = {"position": [1.2, 0.6, 0.0]}
# Dynamics need the links' inertias: the catalog's UR5 has them (planar2 has none).
_UR5_Q = [0.0, -1.2, 1.1, -0.5, 1.2, 0.0]  # rad

#: The scenario, in order (see the module docstring).
EXCHANGES: list[dict[str, Any]] = [
    # Service
    {"name": "health", "operation": "get_health", "method": "GET", "path": "/health"},
    {"name": "ready", "operation": "get_ready", "method": "GET", "path": "/ready"},
    {"name": "metrics", "operation": "get_metrics", "method": "GET", "path": "/metrics"},
    # Robots (reading)
    {"name": "robots", "operation": "list_robots", "method": "GET", "path": "/robots"},
    {"name": "planar2", "operation": "get_robot", "method": "GET", "path": f"/robots/{ROBOT}"},
    {
        "name": "planar2-urdf",
        "operation": "get_robot_urdf",
        "method": "GET",
        "path": f"/robots/{ROBOT}/urdf",
    },
    {
        "name": "planar2-dh",
        "operation": "get_robot_dh",
        "method": "GET",
        "path": f"/robots/{ROBOT}/dh",
    },
    {
        "name": "planar2-dh-yaml",
        "operation": "get_robot_dh",
        "method": "GET",
        "path": f"/robots/{ROBOT}/dh",
        "headers": {"Accept": "application/yaml"},
    },
    {
        "name": "planar2-pairs",
        "operation": "get_collision_pairs",
        "method": "GET",
        "path": f"/robots/{ROBOT}/collision_pairs",
    },
    # Kinematics
    {
        "name": "fk",
        "operation": "compute_fk",
        "method": "POST",
        "path": f"/robots/{ROBOT}/fk",
        "json": {"q": Q},
    },
    {
        "name": "fk-batch",
        "operation": "compute_fk_batch",
        "method": "POST",
        "path": f"/robots/{ROBOT}/fk/batch",
        "json": {"configurations": [[0, 0], Q]},
    },
    {
        "name": "jacobian",
        "operation": "compute_jacobian",
        "method": "POST",
        "path": f"/robots/{ROBOT}/jacobian",
        "json": {"q": Q},
    },
    {
        "name": "ik",
        "operation": "solve_ik",
        "method": "POST",
        "path": f"/robots/{ROBOT}/ik",
        "json": {"target": _TARGET, "mode": "position", "random_seed": 0},
    },
    {
        "name": "ik-batch",
        "operation": "solve_ik_batch",
        "method": "POST",
        "path": f"/robots/{ROBOT}/ik/batch",
        "json": {
            "targets": [_TARGET, {"position": [0.3, 1.2, 0.0]}],
            "mode": "position",
            "random_seed": 0,
        },
    },
    {
        "name": "ik-path",
        "operation": "solve_ik_path",
        "method": "POST",
        "path": f"/robots/{ROBOT}/ik/path",
        "json": {
            "start": Q,
            "mode": "position",
            "random_seed": 0,
            "waypoints": [{"position": [1.0, 0.8, 0.0]}],
        },
    },
    {
        "name": "velocity",
        "operation": "compute_velocity",
        "method": "POST",
        "path": f"/robots/{ROBOT}/velocity",
        "json": {"q": Q, "joint_velocities": [0.1, -0.2]},
    },
    {
        "name": "manipulability",
        "operation": "compute_manipulability",
        "method": "POST",
        "path": f"/robots/{ROBOT}/manipulability",
        "json": {"q": Q, "rows": ["vx", "vy"]},
    },
    {
        "name": "manipulability-batch",
        "operation": "compute_manipulability_batch",
        "method": "POST",
        "path": f"/robots/{ROBOT}/manipulability/batch",
        "json": {"configurations": [[0.5, 0.0], Q], "rows": ["vx", "vy"]},
    },
    {
        "name": "statics",
        "operation": "compute_statics",
        "method": "POST",
        "path": f"/robots/{ROBOT}/statics",
        "json": {"q": Q, "wrench": [0.0, -10.0, 0.0, 0.0, 0.0, 0.0]},
    },
    # Dynamics
    {
        "name": "dynamics",
        "operation": "compute_dynamics",
        "method": "POST",
        "path": "/robots/ur5/dynamics",
        "json": {
            "q": _UR5_Q,
            "velocities": [0.5, 0.0, -0.3, 0.0, 0.0, 0.0],
            "accelerations": {"shoulder_lift_joint": 1.0},
            "payload": {"mass": 2.0, "com": [0.0, 0.0, 0.05]},
        },
    },
    {
        "name": "dynamics-batch",
        "operation": "compute_dynamics_batch",
        "method": "POST",
        "path": "/robots/ur5/dynamics/batch",
        "json": {
            "configurations": [[0.0] * 6, _UR5_Q],
            "velocities": [[0.0] * 6, [0.5, 0.0, -0.3, 0.0, 0.0, 0.0]],
        },
    },
    {
        "name": "max-payload",
        "operation": "compute_max_payload",
        "method": "POST",
        "path": "/robots/ur5/dynamics/max_payload",
        "json": {"q": _UR5_Q, "com": [0.0, 0.0, 0.05]},
    },
    {
        "name": "max-payload-path",
        "operation": "compute_max_payload",
        "method": "POST",
        "path": "/robots/ur5/dynamics/max_payload",
        "json": {"path": [_UR5_Q, [0.0, -1.57, 0.0, -1.57, 0.0, 0.0], [0.0] * 6]},
    },
    {
        "name": "collisions",
        "operation": "check_collisions",
        "method": "POST",
        "path": f"/robots/{ROBOT}/collisions",
        "json": {"q": Q, "obstacles": [_OBSTACLE], "distances": True},
    },
    {
        "name": "collisions-batch",
        "operation": "check_collisions_batch",
        "method": "POST",
        "path": f"/robots/{ROBOT}/collisions/batch",
        "json": {"configurations": [[0, 0], Q], "obstacles": [_OBSTACLE]},
    },
    # Scenes
    {
        "name": "scene-create",
        "operation": "create_scene",
        "method": "POST",
        "path": "/scenes",
        "json": {"name": "cell", "description": "A post by the arm", "obstacles": [_OBSTACLE]},
    },
    {"name": "scenes", "operation": "list_scenes", "method": "GET", "path": "/scenes"},
    {"name": "scene", "operation": "get_scene", "method": "GET", "path": "/scenes/cell"},
    {
        "name": "collisions-scene",
        "operation": "check_collisions",
        "method": "POST",
        "path": f"/robots/{ROBOT}/collisions",
        "json": {"q": [0.6, 0.2], "scene": "cell"},
    },
    {
        "name": "scene-taken",
        "operation": "create_scene",
        "method": "POST",
        "path": "/scenes",
        "json": {"name": "cell", "obstacles": []},
        "shared": True,
    },
    {
        "name": "scene-delete",
        "operation": "delete_scene",
        "method": "DELETE",
        "path": "/scenes/cell",
    },
    # Robots (writing)
    {
        "name": "dh-json",
        "operation": "import_dh_robot",
        "method": "POST",
        "path": "/robots/dh",
        "json": _DH_JSON,
    },
    {
        "name": "dh-yaml",
        "operation": "import_dh_robot",
        "method": "POST",
        "path": "/robots/dh",
        "text": _DH_YAML,
        "content_type": "application/yaml",
    },
    {
        "name": "urdf",
        "operation": "upload_urdf_robot",
        "method": "POST",
        "path": "/robots/urdf",
        "json": {
            "name": "lab_urdf",
            "urdf": _URDF.replace("meshes/tri.stl", "package://x/t.stl").replace(
                '<collision><geometry><mesh filename="package://x/t.stl"/></geometry></collision>',
                "",
            ),
            "ee_frame": "tool",
        },
    },
    {
        "name": "package",
        "operation": "upload_robot_package",
        "method": "POST",
        "path": "/robots/package",
        "form": {"name": "two_link", "description": "two_link/robot.urdf", "ee_frame": "tool"},
        "files": {"archive": ["two_link.zip", "application/zip", _PACKAGE]},
    },
    {
        "name": "package-file",
        "operation": "get_robot_file",
        "method": "GET",
        "path": "/robots/two_link/files/two_link/meshes/tri.stl",
    },
    {
        "name": "package-file-range",
        "operation": "get_robot_file",
        "method": "GET",
        "path": "/robots/two_link/files/two_link/meshes/tri.stl",
        "headers": {"Range": "bytes=0-9"},
    },
    {
        "name": "package-file-outside",
        "operation": "get_robot_file",
        "method": "GET",
        "path": "/robots/two_link/files/two_link/meshes/tri.stl",
        "headers": {"Range": "bytes=5000-"},
        "shared": True,
    },
    {
        "name": "robot-delete",
        "operation": "delete_robot",
        "method": "DELETE",
        "path": "/robots/lab_rr",
    },
    # Reachability
    {
        "name": "reachability-build",
        "operation": "build_reachability_map",
        "method": "POST",
        "path": f"/robots/{ROBOT}/reachability",
        "json": _BUILD,
        "bind": {"job_id": "job_id"},
        "volatile": ["status", "progress"],
    },
    {
        "name": "reachability-job",
        "operation": "get_reachability_job",
        "method": "GET",
        "path": f"/robots/{ROBOT}/reachability/jobs/{{job_id}}",
        "until": {"field": "status", "value": "done"},
        "bind": {"map_id": "map_id"},
    },
    {
        "name": "reachability-jobs",
        "operation": "list_reachability_jobs",
        "method": "GET",
        "path": f"/robots/{ROBOT}/reachability/jobs",
    },
    {
        "name": "reachability-maps",
        "operation": "list_reachability_maps",
        "method": "GET",
        "path": f"/robots/{ROBOT}/reachability/maps",
    },
    {
        "name": "reachability-map",
        "operation": "get_reachability_map",
        "method": "GET",
        "path": f"/robots/{ROBOT}/reachability/maps/{{map_id}}",
    },
    {
        "name": "reachability-query",
        "operation": "query_reachability",
        "method": "POST",
        "path": f"/robots/{ROBOT}/reachability/query",
        "json": {"map_id": "{map_id}", "positions": [[1.2, 0.6, 0.0], [3.0, 0.0, 0.0]]},
    },
    {
        "name": "reachability-slice",
        "operation": "get_reachability_slice",
        "method": "GET",
        "path": f"/robots/{ROBOT}/reachability/maps/{{map_id}}/slice.png?z=0",
    },
    {
        "name": "reachability-job-finished",
        "operation": "cancel_reachability_job",
        "method": "DELETE",
        "path": f"/robots/{ROBOT}/reachability/jobs/{{job_id}}",
    },
    {
        "name": "reachability-map-delete",
        "operation": "delete_reachability_map",
        "method": "DELETE",
        "path": f"/robots/{ROBOT}/reachability/maps/{{map_id}}",
    },
    {
        "name": "reachability-build-large",
        "operation": "build_reachability_map",
        "method": "POST",
        "path": f"/robots/{ROBOT}/reachability",
        "json": {**_BUILD, "samples": 50_000_000},
        "bind": {"job_id": "job_id"},
        "volatile": ["status", "progress"],
        "doc": False,
    },
    {
        "name": "reachability-cancel",
        "operation": "cancel_reachability_job",
        "method": "DELETE",
        "path": f"/robots/{ROBOT}/reachability/jobs/{{job_id}}",
        "volatile": ["status", "progress"],
    },
    # Errors: one request per status the service answers (the shared examples of the
    # statuses no operation above answered already).
    {
        "name": "malformed-json",
        "operation": "compute_fk",
        "method": "POST",
        "path": f"/robots/{ROBOT}/fk",
        "text": '{"q": [0.5, 1.0',
        "content_type": "application/json",
        "shared": True,
    },
    {
        "name": "no-token",
        "operation": "create_scene",
        "method": "POST",
        "path": "/scenes",
        "json": {"name": "cell", "obstacles": []},
        "app": "token",
        "shared": True,
    },
    {
        "name": "wrong-token",
        "operation": "create_scene",
        "method": "POST",
        "path": "/scenes",
        "json": {"name": "cell", "obstacles": []},
        "app": "token",
        "headers": {"Authorization": "Bearer not-the-token"},
        "shared": True,
    },
    {
        "name": "unknown-robot",
        "operation": "get_robot",
        "method": "GET",
        "path": "/robots/pand",
        "shared": True,
    },
    {
        "name": "method-not-allowed",
        "operation": "get_robot",
        "method": "GET",
        "path": "/robots/dh",
        "shared": True,
    },
    {
        "name": "too-large",
        "operation": "get_health",
        "method": "GET",
        "path": "/health",
        "filler": 67108865,
        "shared": True,
    },
    {
        "name": "unsupported-media-type",
        "operation": "import_dh_robot",
        "method": "POST",
        "path": "/robots/dh",
        "text": "name: x",
        "content_type": "text/plain",
        "shared": True,
    },
    {
        "name": "invalid-q",
        "operation": "compute_fk",
        "method": "POST",
        "path": f"/robots/{ROBOT}/fk",
        "json": {"q": [0.5]},
        "shared": True,
    },
    {
        "name": "missing-inertia",
        "operation": "compute_dynamics",
        "method": "POST",
        "path": "/robots/two_link/dynamics",
        "json": {"q": [0.5, 1.0]},
    },
    {
        "name": "upgrade-required",
        "operation": "get_robot_stream",
        "method": "GET",
        "path": f"/robots/{ROBOT}/stream",
        "shared": True,
    },
    {
        "name": "not-started",
        "operation": "create_scene",
        "method": "POST",
        "path": "/scenes",
        "json": {"name": "cell", "obstacles": []},
        "app": "unstarted",
        "shared": True,
    },
    {
        "name": "not-started-collisions",
        "operation": "check_collisions",
        "method": "POST",
        "path": f"/robots/{ROBOT}/collisions",
        "json": {"q": Q},
        "app": "unstarted",
        "doc": False,
    },
]
