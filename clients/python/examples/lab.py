"""A lab's session with the Python client: list robots, FK, IK of FK's pose, a Cartesian line,
a package upload with SRDF, a collision query with a scene, a coarse reachability build.

    python lab.py http://127.0.0.1:8000 panda_package.zip [--name lab_panda]

The package is a zip holding ``urdf/panda.urdf``, ``srdf/panda.srdf`` and the meshes the URDF
names (relative paths). With ``DENAVIT_API_TOKEN`` set in the environment the write
operations send it. Prints one JSON line of results; exits non-zero when an answer is not
what a working service gives. Checked under ``mypy --strict`` and run against a live server
by tests/clients.
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path
from typing import Any, TypeVar

import numpy as np
from denavit_client.api.collisions import check_collisions, create_scene
from denavit_client.api.inverse_kinematics import solve_ik, solve_ik_path
from denavit_client.api.kinematics import compute_fk
from denavit_client.api.reachability import build_reachability_map, get_reachability_job
from denavit_client.api.robots import list_robots, upload_robot_package
from denavit_client.arrays import pose_matrix, q_list
from denavit_client.client import AuthenticatedClient
from denavit_client.models import (
    BuildRequest,
    CollisionRequest,
    FKRequest,
    FKResponse,
    IKRequest,
    IKResponse,
    JobResponse,
    JobStatus,
    LineSegment,
    ObstacleIn,
    ObstacleShape,
    PackageUpload,
    PathRequest,
    Pose,
    Problem,
    SceneIn,
)
from denavit_client.session import connect
from denavit_client.types import File

ROBOT, EE = "ur5", "tool0"
T = TypeVar("T")
Q0 = np.array([0.3, -1.1, 1.4, -0.6, 1.2, 0.4])


def check(condition: bool, what: str) -> None:
    """Stop the session when an answer is not what a working service gives."""
    if not condition:
        raise SystemExit(f"lab: {what}")


def answer(value: T | Problem | None) -> T:
    """The answer of a call, or stop with the problem the service answered."""
    if isinstance(value, Problem):
        raise SystemExit(f"lab: {value.status} {value.type_}: {value.detail}")
    if value is None:
        raise SystemExit("lab: no answer")
    return value


def fk(client: AuthenticatedClient, q: np.ndarray) -> FKResponse:
    return answer(compute_fk.sync(ROBOT, client=client, body=FKRequest(q=q_list(q), frames=[EE])))


def main(argv: list[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(description="A lab session with the Denavit client.")
    parser.add_argument("url")
    parser.add_argument("package", type=Path)
    parser.add_argument("--name", default="lab_panda")
    args = parser.parse_args(argv)
    out: dict[str, Any] = {}
    with connect(args.url, os.environ.get("DENAVIT_API_TOKEN")) as client:
        # 1. The robots the service knows.
        robots = answer(list_robots.sync(client=client))
        out["robots"] = [r.id for r in robots.robots]
        check(ROBOT in out["robots"], f"{ROBOT} is not listed")

        # 2. FK, 3. IK fed with FK's answer pose.
        pose = fk(client, Q0).poses[EE]
        target = pose  # FK's answer is an IK target as it is
        ik: IKResponse = answer(
            solve_ik.sync(
                ROBOT,
                client=client,
                body=IKRequest(target=target, max_iterations=200, random_seed=0),
            )
        )
        check(ik.success, f"IK failed: {ik.detail}")
        T_goal, T_ik = pose_matrix(pose), pose_matrix(fk(client, np.array(ik.q)).poses[EE])
        out["ik_position_error"] = float(np.linalg.norm(T_ik[:3, 3] - T_goal[:3, 3]))
        out["ik_branches"] = [s.branch for s in ik.solutions]
        check(out["ik_position_error"] < 1e-4, "the IK solution does not reach FK's pose")

        # 4. A Cartesian line: 10 cm along x from the IK solution, orientation kept.
        end = [float(v) for v in pose_matrix(pose)[:3, 3] + [0.1, 0.0, 0.0]]
        line = LineSegment(type_="line", to=Pose(position=end, orientation=pose.orientation))
        path = answer(
            solve_ik_path.sync(ROBOT, client=client, body=PathRequest(start=ik.q, segments=[line]))
        )
        last = pose_matrix(fk(client, np.array(path.points[-1].q)).poses[EE])
        out["path_fraction"], out["path_points"] = path.fraction, len(path.points)
        out["path_end_error"] = float(np.linalg.norm(last[:3, 3] - end))
        check(path.fraction == 1.0, f"the line stopped at {path.fraction:.0%}")

        # 5. A description package with its SRDF (the meshes inside the archive).
        with args.package.open("rb") as archive:
            robot = answer(
                upload_robot_package.sync(
                    client=client,
                    body=PackageUpload(
                        name=args.name,
                        archive=File(payload=archive, file_name=args.package.name),
                        description="urdf/panda.urdf",
                        srdf="srdf/panda.srdf",
                    ),
                )
            )
        out["package_robot"], out["package_groups"] = robot.id, [g.name for g in robot.groups]

        # 6. A scene with a box around the Panda's base, and a collision query against it.
        box = ObstacleIn(
            name="pedestal",
            shape=ObstacleShape.BOX,
            size=[0.3, 0.3, 0.2],
            pose=Pose(position=[0.0, 0.0, 0.1], orientation=[0.0, 0.0, 0.0, 1.0]),
        )
        scene = answer(
            create_scene.sync(
                client=client, body=SceneIn(name=f"{args.name}_cell", obstacles=[box])
            )
        )
        hit = answer(
            check_collisions.sync(
                robot.id, client=client, body=CollisionRequest(q=robot.neutral, scene=scene.name)
            )
        )
        out["collision"] = hit.environment_collision
        out["collision_pairs"] = sorted(f"{p.a}|{p.b}" for p in hit.pairs)
        check(hit.environment_collision, "the pedestal does not touch the Panda's base")

        # 7. A coarse reachability map, polled to the end.
        job: JobResponse = answer(
            build_reachability_map.sync(
                ROBOT, client=client, body=BuildRequest(samples=2000, voxel_size=0.1)
            )
        )
        while job.status in (JobStatus.QUEUED, JobStatus.RUNNING):
            time.sleep(0.2)
            job = answer(get_reachability_job.sync(ROBOT, job.job_id, client=client))
        out["reachability"] = str(job.status)
        out["reachability_samples"] = job.progress.samples_done
        check(job.status == JobStatus.DONE, f"the build ended {job.status}: {job.error}")
    print(json.dumps(out))
    return out


if __name__ == "__main__":
    main()
