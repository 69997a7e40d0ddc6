// A lab's session with the TypeScript types and openapi-fetch: list robots, FK, IK of FK's
// pose, a Cartesian line, a package upload with SRDF, a collision query with a scene, a
// coarse reachability build (the steps of clients/python/examples/lab.py).
//
//     node dist/lab.js http://127.0.0.1:8000 panda_package.zip [name]
//
// The package is a zip holding urdf/panda.urdf, srdf/panda.srdf and the meshes the URDF
// names. With DENAVIT_API_TOKEN set in the environment the requests send it. Prints one JSON
// line of results; exits non-zero when an answer is not what a working service gives.
// Compiled with `tsc --strict` and run against a live server by tests/clients.
import { readFileSync } from "node:fs";
import { basename } from "node:path";
import createClient from "openapi-fetch";
import type { components, paths } from "./schema.js";

type Pose = components["schemas"]["Pose"];

const ROBOT = "ur5";
const EE = "tool0";
const Q0 = [0.3, -1.1, 1.4, -0.6, 1.2, 0.4];

function check(condition: boolean, what: string): void {
  if (!condition) throw new Error(`lab: ${what}`);
}

/** The answer of a call, or an error naming the problem the service answered. */
function answer<T>(result: { data?: T; error?: unknown; response: Response }): T {
  if (result.data === undefined) {
    throw new Error(`lab: ${result.response.status} ${JSON.stringify(result.error)}`);
  }
  return result.data;
}

function distance(a: number[], b: number[]): number {
  return Math.hypot(...a.map((v, i) => v - (b[i] ?? Number.NaN)));
}

async function main(): Promise<void> {
  const [url, packagePath, name = "lab_panda_ts"] = process.argv.slice(2);
  if (url === undefined || packagePath === undefined) {
    throw new Error("usage: node dist/lab.js <url> <package.zip> [name]");
  }
  const token = process.env["DENAVIT_API_TOKEN"];
  const api = createClient<paths>({
    baseUrl: url,
    headers: token ? { Authorization: `Bearer ${token}` } : {},
  });
  const robotPath = (robot_id: string) => ({ params: { path: { robot_id } } });
  const fk = async (q: number[]): Promise<Pose> => {
    const out = answer(
      await api.POST("/robots/{robot_id}/fk", { ...robotPath(ROBOT), body: { q, frames: [EE] } }),
    );
    const pose = out.poses[EE];
    if (pose === undefined) throw new Error(`lab: no pose of ${EE}`);
    return pose;
  };
  // An answer's pose always has all four fields; the one Pose schema makes them optional
  // because a pose in a request may give only some of them.
  const at = (pose: Pose): number[] => {
    if (pose.position === undefined) throw new Error("lab: a pose without a position");
    return pose.position;
  };
  const out: Record<string, unknown> = {};

  // 1. The robots the service knows.
  const robots = answer(await api.GET("/robots"));
  out["robots"] = robots.robots.map((r) => r.id);
  check(robots.robots.some((r) => r.id === ROBOT), `${ROBOT} is not listed`);

  // 2. FK, 3. IK fed with FK's answer pose.
  const pose = await fk(Q0);
  const target = pose; // FK's answer is an IK target as it is
  const ik = answer(
    await api.POST("/robots/{robot_id}/ik", {
      ...robotPath(ROBOT),
      body: { target, max_iterations: 200, random_seed: 0 },
    }),
  );
  check(ik.success, `IK failed: ${ik.detail}`);
  out["ik_position_error"] = distance(at(await fk(ik.q)), at(pose));
  out["ik_branches"] = ik.solutions.map((s) => s.branch);
  check((out["ik_position_error"] as number) < 1e-4, "the IK solution does not reach FK's pose");

  // 4. A Cartesian line: 10 cm along x from the IK solution, orientation kept.
  const [x = 0, y = 0, z = 0] = at(pose);
  const end = [x + 0.1, y, z];
  const path = answer(
    await api.POST("/robots/{robot_id}/ik/path", {
      ...robotPath(ROBOT),
      body: {
        start: ik.q,
        segments: [{ type: "line", to: { position: end, orientation: pose.orientation } }],
      },
    }),
  );
  const last = path.points[path.points.length - 1];
  if (last === undefined) throw new Error("lab: an empty path");
  out["path_fraction"] = path.fraction;
  out["path_points"] = path.points.length;
  out["path_end_error"] = distance(at(await fk(last.q)), end);
  check(path.fraction === 1, `the line stopped at ${path.fraction}`);

  // 5. A description package with its SRDF (the meshes inside the archive).
  const archive = new Blob([readFileSync(packagePath)], { type: "application/zip" });
  const robot = answer(
    await api.POST("/robots/package", {
      body: { name, archive, description: "urdf/panda.urdf", srdf: "srdf/panda.srdf" },
      bodySerializer(body) {
        const form = new FormData();
        for (const [key, value] of Object.entries(body)) {
          if (value instanceof Blob) form.append(key, value, basename(packagePath));
          else if (value !== null && value !== undefined) form.append(key, String(value));
        }
        return form;
      },
    }),
  );
  out["package_robot"] = robot.id;
  out["package_groups"] = robot.groups.map((g) => g.name);

  // 6. A scene with a box around the Panda's base, and a collision query against it.
  const scene = answer(
    await api.POST("/scenes", {
      body: {
        name: `${name}_cell`,
        obstacles: [
          {
            name: "pedestal",
            shape: "box",
            size: [0.3, 0.3, 0.2],
            pose: { position: [0, 0, 0.1], orientation: [0, 0, 0, 1] },
          },
        ],
      },
    }),
  );
  const hit = answer(
    await api.POST("/robots/{robot_id}/collisions", {
      ...robotPath(robot.id),
      body: { q: robot.neutral, scene: scene.name },
    }),
  );
  out["collision"] = hit.environment_collision;
  out["collision_pairs"] = hit.pairs.map((p) => `${p.a}|${p.b}`).sort();
  check(hit.environment_collision, "the pedestal does not touch the Panda's base");

  // 7. A coarse reachability map, polled to the end.
  let job = answer(
    await api.POST("/robots/{robot_id}/reachability", {
      ...robotPath(ROBOT),
      body: { samples: 2000, voxel_size: 0.1 },
    }),
  );
  while (job.status === "queued" || job.status === "running") {
    await new Promise((resolve) => setTimeout(resolve, 200));
    job = answer(
      await api.GET("/robots/{robot_id}/reachability/jobs/{job_id}", {
        params: { path: { robot_id: ROBOT, job_id: job.job_id } },
      }),
    );
  }
  out["reachability"] = job.status;
  out["reachability_samples"] = job.progress.samples_done;
  check(job.status === "done", `the build ended ${job.status}: ${job.error}`);
  console.log(JSON.stringify(out));
}

main().catch((error: unknown) => {
  console.error(error instanceof Error ? error.message : error);
  process.exit(1);
});
