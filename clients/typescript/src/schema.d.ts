// Generated from docs/openapi.json by clients/typescript/generate.mjs: do not edit.

export interface paths {
    "/robots/{robot_id}/fk": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Fk
         * @description Poses of frames at one configuration.
         *
         *     Out-of-limit configurations are computed, and flagged with ``within_limits: false``.
         */
        post: operations["compute_fk"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/fk/batch": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Fk Batch
         * @description Position and orientation of one frame for many configurations.
         *
         *     The body (up to ``DENAVIT_MAX_BATCH`` configurations) is decoded and computed in the
         *     work pool: decoding takes orjson and one NumPy conversion, and FK of serial chains is
         *     vectorised (see ``app.kinematics.chain.SerialChain``).
         */
        post: operations["compute_fk_batch"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/jacobian": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Jacobian
         * @description Geometric Jacobian of a frame at one configuration.
         */
        post: operations["compute_jacobian"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/ik": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Solve Ik
         * @description Joint configurations that place a frame at a target pose.
         *
         *     Damped least squares (Levenberg–Marquardt) on the SE(3) error with random restarts
         *     within the time budget, seeded by closed forms where the chain admits one (see
         *     docs/ik.md). Every solution is verified by forward kinematics and lies within the joint
         *     limits. An unreachable target is not an error: 200 with `success: false`, the best
         *     configuration found and its errors.
         */
        post: operations["solve_ik"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/ik/batch": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Solve Ik Batch
         * @description IK for many targets of one frame, in order, computed in the work pool.
         *
         *     With `chain_seeds` (default) each target is seeded with the previous solution, which
         *     keeps a trajectory on one branch; otherwise every target starts from `seed`. The
         *     request's total budget, targets × `timeout_ms`, may not exceed the server's
         *     `ik_max_request_s` (default 30 s; else 422 naming `targets`), and the work stops when
         *     the client disconnects.
         */
        post: operations["solve_ik_batch"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/health": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Health
         * @description The process is up and serving.
         */
        get: operations["get_health"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/ready": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Ready
         * @description Whether the service can serve: data directory writable, catalog available.
         */
        get: operations["get_ready"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/package": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Upload Robot Package
         * @description Add a robot from a description package (zip or tar.gz with its meshes); id ``name``.
         *
         *     Form fields: ``name``, ``archive`` (the file), ``description`` (path inside the archive
         *     of a ``.urdf``, ``.xacro`` or MJCF ``.xml``), optional ``srdf`` (path; a ``.xacro`` one
         *     is expanded like the description), ``xacro_args`` (JSON object of strings, numbers or
         *     booleans), ``srdf_xacro_args`` (the same, for a ``.xacro`` SRDF whose arguments
         *     differ), ``ee_frame`` and ``summary`` (short description).
         *
         *     The archive is unpacked safely (422 naming ``archive`` and the member otherwise): no
         *     absolute names, ``..``, drive letters or backslashes, no links, devices or duplicate
         *     names, at most ``DENAVIT_MAX_PACKAGE_FILES`` entries and
         *     ``DENAVIT_MAX_PACKAGE_UNPACKED_BYTES`` once unpacked (counted while decompressing).
         *     Mesh and texture references resolve inside the package: relative paths and
         *     ``file://<relative path>`` against the description's folder, ``package://<pkg>/…``
         *     against the package named ``<pkg>`` by a ``package.xml`` (or a top-level folder of the
         *     archive); ``package://example-robot-data/robots/<folder>/<path>`` names the archive's
         *     own copy when it has one (``<path>``, ``<folder>/<path>`` or ``robots/<folder>/<path>``
         *     under the description's folder or its nearest parent with one), else the catalog's file.
         *     A reference that leaves the package, an absolute path, another scheme or a missing file
         *     is a 422 naming it; every mesh is loaded (STL, COLLADA, OBJ or PLY) and one that cannot
         *     be read is a 422 naming it, so a 201 means collisions work. The stored URDF (GET
         *     /robots/{robot_id}/urdf) names every file ``package://files/<path in the archive>``,
         *     served at GET /robots/{robot_id}/files/<path in the archive>. Then the URDF is checked
         *     as in POST /robots/urdf. 413 past ``DENAVIT_MAX_PACKAGE_BYTES`` (the whole
         *     form); 409 if the id is taken. Nothing is stored on any refusal.
         */
        post: operations["upload_robot_package"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/files/{path}": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Robot File
         * @description A file of a robot's package: what its URDF's mesh URIs name, for viewers.
         *
         *     For a package robot, ``path`` is the file's path inside the uploaded archive (the URDF
         *     names it ``package://files/<path>``); for a catalog robot, the path inside its
         *     example-robot-data folder (``package://example-robot-data/robots/<folder>/<path>``).
         *     GET /robots/{robot_id} gives this mapping in ``files``. 404 for a missing file, a robot
         *     without files, or a path the file system cannot hold (a segment over 255 bytes); 422
         *     for a path with ``..``, ``.``, empty segments or backslashes.
         *
         *     The files are the client's, served as it sent them: every answer carries
         *     ``Content-Security-Policy: default-src 'none'; sandbox`` and ``X-Content-Type-Options:
         *     nosniff``, and every type but image/png and image/jpeg ``Content-Disposition:
         *     attachment``, so that a browser never runs a script a file holds (an XHTML, SVG or
         *     HTML document) in the service's origin. Viewers load them with fetch/XHR or ``<img>``,
         *     which ignore the disposition. ``Range`` is honoured (206); a malformed one is a 400, one
         *     outside the file a 416, both naming ``range``.
         */
        get: operations["get_robot_file"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/dh": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Import Dh Robot
         * @description Add a robot from a DH table; its id is the table's ``name``.
         *
         *     The body is the table as JSON, or as YAML with ``Content-Type: application/yaml`` (or
         *     ``text/yaml``); lengths in m/cm/mm and angles in rad/deg as its ``units`` say. The
         *     service converts it to URDF (frames ``dh_0`` … ``dh_n`` and ``tool``, the default end
         *     effector) and answers 201 with the robot's description. 409 if the id is taken by any
         *     robot; 422 naming the field for a bad table (``joints.2.lower``); YAML aliases are
         *     refused; 413 past 256 KiB (or ``DENAVIT_MAX_UPLOAD_BYTES`` if smaller).
         */
        post: operations["import_dh_robot"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/urdf": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Upload Urdf Robot
         * @description Add a robot from URDF text (and optional SRDF); its id is ``name``.
         *
         *     The XML is checked first, read as Pinocchio reads it (names taken literally, namespaces
         *     ignored): DTDs and entity declarations are refused, mesh filenames must be exactly
         *     ``package://<package>/<path>`` URIs without ``..`` or whitespace, joint axes need a norm
         *     of at least 1e-6, lengths and angles at most 1e6, and the links must form one tree with
         *     at least one actuated joint; then Pinocchio builds the model. The work a document may
         *     cause is bounded (422 naming the limit): XML elements, attributes (in total and per
         *     element), nesting depth, joints and movable joints (``DENAVIT_MAX_XML_*``,
         *     ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``). Text must be valid Unicode
         *     (no lone surrogates). 201 with the robot's description; 409 if the id is taken; 413
         *     past the upload limit.
         */
        post: operations["upload_urdf_robot"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Robot
         * @description Describe a robot: joints in order, frames, default end effector, neutral configuration.
         *
         *     ``files`` tells a viewer where the meshes are: a mesh URI of GET /robots/{robot_id}/urdf
         *     that starts with ``files.uri_prefix`` is served at ``files.url`` + the rest of the URI
         *     (``package://files/meshes/a.stl`` → ``/robots/{robot_id}/files/meshes/a.stl``).
         *
         *     Runs in the thread pool: the first request for a robot parses its URDF.
         */
        get: operations["get_robot"];
        put?: never;
        post?: never;
        /**
         * Delete Robot
         * @description Remove a user-added robot (every worker stops serving it); built-in robots: 403.
         */
        delete: operations["delete_robot"];
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * List Robots
         * @description List every robot: catalog robots, DH robots and user-added ones.
         */
        get: operations["list_robots"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/urdf": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Robot Urdf
         * @description The robot's URDF: the catalog file, the uploaded text, or the one generated from a
         *     DH table (links ``dh_0`` … ``dh_n`` and ``tool``; SI units).
         *
         *     The uploaded text is served as it was sent, so the answer is a download that a browser
         *     never runs: ``Content-Disposition: attachment; filename="<robot_id>.urdf"`` and
         *     ``Content-Security-Policy: default-src 'none'; sandbox``.
         */
        get: operations["get_robot_urdf"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/dh": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Robot Dh
         * @description The DH table a robot was built from, in SI units (m, rad) as validated on import.
         *
         *     JSON by default; YAML when the ``Accept`` header asks for ``application/yaml``, as a
         *     download (``<robot_id>.yaml``, the headers of GET /robots/{robot_id}/urdf). 404 for
         *     robots that were not built from a DH table (their URDF is at /robots/{robot_id}/urdf).
         */
        get: operations["get_robot_dh"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/manipulability": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Manipulability
         * @description Manipulability, singularity and ellipsoids of a frame at one configuration.
         */
        post: operations["compute_manipulability"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/manipulability/batch": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Manipulability Batch
         * @description Scalar manipulability measures for many configurations (computed off the event loop).
         */
        post: operations["compute_manipulability_batch"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/statics": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Statics
         * @description Joint torques τ = Jᵀ·F from a wrench at a frame, or the least-squares wrench from τ.
         */
        post: operations["compute_statics"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/dynamics": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Dynamics
         * @description Joint torques τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F at one state, each term, the mass
         *     and Coriolis matrices, the centre of mass and the effort ratios.
         *
         *     Velocities and accelerations are zeros when absent; a payload is a rigid body fixed to a
         *     frame; the wrench is the one the frame exerts on its environment (as in statics). With
         *     `group`, every vector and matrix is over the group's joints.
         */
        post: operations["compute_dynamics"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/dynamics/batch": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Dynamics Batch
         * @description Joint torques τ (RNEA) and gravity torques g(q) for many states (q, q̇, q̈), with an
         *     optional payload, computed off the event loop; up to ``DENAVIT_MAX_BATCH`` states.
         */
        post: operations["compute_dynamics_batch"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/dynamics/max_payload": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Max Payload
         * @description The largest payload mass the joints' effort limits hold at rest, at one configuration
         *     or along a path (its minimum and the sample it occurs at), the limiting joint and each
         *     joint's bound. A payload that loads no joint with a limit is unbounded (null).
         */
        post: operations["compute_max_payload"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Build Reachability Map
         * @description Start building a reachability map in the background; poll the returned job.
         */
        post: operations["build_reachability_map"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/jobs": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * List Reachability Jobs
         * @description Build jobs of this robot (started through any worker), oldest first.
         */
        get: operations["list_reachability_jobs"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/jobs/{job_id}": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Reachability Job
         * @description Status and progress (percent, samples/s, ETA) of a build.
         */
        get: operations["get_reachability_job"];
        put?: never;
        post?: never;
        /**
         * Cancel Reachability Job
         * @description Cancel a queued or running build; nothing is stored. Cancelling twice is fine.
         *
         *     The build stops within a moment (any worker may be running it); until then the answer
         *     and the job still say ``queued`` or ``running``: poll the job until it is ``cancelled``.
         */
        delete: operations["cancel_reachability_job"];
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/maps": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * List Reachability Maps
         * @description Stored maps of this robot, oldest first.
         */
        get: operations["list_reachability_maps"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/maps/{map_id}": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Reachability Map
         * @description One stored map's metadata.
         */
        get: operations["get_reachability_map"];
        put?: never;
        post?: never;
        /**
         * Delete Reachability Map
         * @description Delete a stored map.
         */
        delete: operations["delete_reachability_map"];
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/query": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Query Reachability
         * @description Look poses up in a map: O(1) each. Outside the map's box → not reachable.
         *
         *     Give ``poses`` (objects; orientation optional per pose) or the compact ``positions``
         *     (N×3) with optional ``orientations`` (N×4); a pose without orientation asks "reachable
         *     with any orientation" (the best over the voxel's bins).
         */
        post: operations["query_reachability"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/reachability/maps/{map_id}/slice.png": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Reachability Slice
         * @description Heat map of one voxel layer: colour = best manipulability over orientations (viridis,
         *     scaled to the map's maximum), light grey = unreached. Give exactly one of x, y, z.
         */
        get: operations["get_reachability_slice"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/collisions": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Check Collisions
         * @description Self-collision and collision with obstacles at one configuration.
         *
         *     Obstacles come inline (``obstacles``) or from a stored ``scene``. Links fixed to the
         *     world are not checked against obstacles; adjacent links and SRDF-disabled pairs are
         *     never checked (GET /robots/{robot_id}/collision_pairs lists the checked pairs).
         */
        post: operations["check_collisions"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/collisions/batch": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Check Collisions Batch
         * @description Check many configurations (e.g. a trajectory's waypoints) in the work pool.
         */
        post: operations["check_collisions_batch"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/collision_pairs": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Collision Pairs
         * @description The self-collision link pairs checked (after removing same-body, adjacent and
         *     SRDF-disabled pairs); computed from the URDF without loading meshes.
         */
        get: operations["get_collision_pairs"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/scenes": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * List Scenes
         * @description List the stored scenes.
         */
        get: operations["list_scenes"];
        put?: never;
        /**
         * Create Scene
         * @description Store a named set of obstacles (409 if the name is taken; persisted across restarts).
         */
        post: operations["create_scene"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/scenes/{name}": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Scene
         * @description A stored scene with its obstacles.
         */
        get: operations["get_scene"];
        put?: never;
        post?: never;
        /**
         * Delete Scene
         * @description Delete a stored scene.
         */
        delete: operations["delete_scene"];
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/ik/path": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Solve Ik Path
         * @description A joint path that moves a frame along lines and arcs, on one branch.
         *
         *     The path (position linear, orientation by slerp) is interpolated at `max_step`; each
         *     point is solved seeded by the previous solution and accepted only if no joint moves more
         *     than `max_joint_step`, the branch does not change and (with `avoid_collisions`) the
         *     configuration is collision-free. Between accepted points the path is densified until
         *     the joint-linear motion stays within `max_deviation` of the Cartesian path. A path that
         *     cannot be completed is not an error: 200 with `fraction` < 1, the points up to there,
         *     and `failure` (index, reason, detail) of the first point that failed. See docs/paths.md.
         *     The request's total budget, points × `timeout_ms`, may not exceed the server's
         *     `ik_max_request_s` (else 422 naming `max_step`), which is also the path's deadline (past
         *     it, the path stops with `failure.reason: timeout`); the work stops when the client leaves.
         */
        post: operations["solve_ik_path"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/velocity": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        get?: never;
        put?: never;
        /**
         * Compute Velocity
         * @description Forward twist J·q̇, or inverse q̇ = J⁺·twist damped near singularities.
         */
        post: operations["compute_velocity"];
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/metrics": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Get Metrics
         * @description The service's counters, summed over its worker processes (Prometheus text format).
         */
        get: operations["get_metrics"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
    "/robots/{robot_id}/stream": {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        /**
         * Robot stream (WebSocket)
         * @description FK, Jacobian, IK and dynamics of one robot over a WebSocket (docs/stream.md): connect with `ws://` (an HTTP/1.1 `Upgrade: websocket` request). OpenAPI cannot describe the messages; a plain HTTP request is answered 426 naming the upgrade. With DENAVIT_API_TOKEN set, the upgrade request carries the bearer token (or the first message is `{"token": ...}`).
         */
        get: operations["get_robot_stream"];
        put?: never;
        post?: never;
        delete?: never;
        options?: never;
        head?: never;
        patch?: never;
        trace?: never;
    };
}
export type webhooks = Record<string, never>;
export interface components {
    schemas: {
        /** @enum {string} */
        AngleUnit: "rad" | "deg";
        /**
         * ArcSegment
         * @description A circular arc from the previous pose through `via` to `to`; orientation by slerp to
         *     `via`'s on the first part of the arc and to `to`'s on the second.
         */
        ArcSegment: {
            /**
             * @description discriminator enum property added by openapi-typescript
             * @enum {string}
             */
            type: "arc";
            via: components["schemas"]["Pose"];
            to: components["schemas"]["Pose"];
        };
        /**
         * Bounds
         * @description An axis-aligned box of the root frame (m).
         */
        Bounds: {
            /**
             * Min
             * @description [x, y, z] lower corner (m).
             */
            min: number[];
            /**
             * Max
             * @description [x, y, z] upper corner (m); larger than min on every axis.
             */
            max: number[];
        };
        /**
         * BuildRequest
         * @description What to build: grid, orientation bins, manipulability rows, sampling.
         */
        BuildRequest: {
            /**
             * Frame
             * @description Frame whose poses are mapped; default the robot's end effector.
             */
            frame?: string | null;
            /**
             * Voxel Size
             * @description Edge of a position voxel (m). Default: the box's longest edge / 24 (with the default box, the chain's total length / 12: a coarse map of any arm), larger by steps of 5 % when voxels × orientation bins would exceed 16,777,216 cells.
             */
            voxel_size?: number | null;
            /** @description Box to cover (m, root frame); default a box that contains every reachable position (centred on the chain's first joint, half-size the chain's total length). */
            bounds?: components["schemas"]["Bounds"] | null;
            /**
             * Orientation Divisions
             * @description d: 4·d³ orientation bins (cubed 3-sphere, each ≈ 180°/d of rotation per axis); 0 = one bin (position-only map).
             * @default 4
             */
            orientation_divisions?: number;
            /** @description Manipulability rows: full (default) | translation | rotation. */
            part?: components["schemas"]["JacobianPart"] | null;
            /**
             * Rows
             * @description Explicit manipulability rows, e.g. ["vx", "vy"].
             */
            rows?: (string | number)[] | null;
            /**
             * Samples
             * @description Joint-space samples (grid: rounded); the default builds in well under a second on a 7-joint arm.
             * @default 200000
             */
            samples?: number;
            /**
             * @description random: uniform within joint limits | grid: g = round(samples^(1/k)) values per joint.
             * @default random
             */
            sampling?: components["schemas"]["ReachabilitySampling"];
            /**
             * Seed
             * @description Seed of the random samples.
             * @default 0
             */
            seed?: number;
            /**
             * @description Drop self-colliding samples using the collision module's geometry (mesh or convex hulls); one collision query per sample, far slower.
             * @default ignore
             */
            self_collision?: components["schemas"]["SelfCollisionMode"];
        };
        /**
         * CollisionBatchRequest
         * @description Many configurations (e.g. the waypoints of a trajectory).
         */
        CollisionBatchRequest: {
            /**
             * Obstacles
             * @description Obstacles in the robot's root frame.
             */
            obstacles?: components["schemas"]["ObstacleIn"][] | null;
            /**
             * Scene
             * @description Name of a stored scene (instead of obstacles).
             */
            scene?: string | null;
            /**
             * Margin
             * @description Safety margin (m): pairs closer than this count as in collision.
             * @default 0
             */
            margin?: number;
            /**
             * Distances
             * @description Compute every checked pair's distance and witness points (slower, especially with meshes).
             * @default false
             */
            distances?: boolean;
            /**
             * @description mesh: the URDF collision meshes (exact); convex: their convex hulls (faster, conservative, signed distances).
             * @default mesh
             */
            geometry?: components["schemas"]["CollisionGeometry"];
            /**
             * Configurations
             * @description N configurations, each one value per joint in joint order (rad, m); with `group`, rows of the group's joints only are accepted too (others neutral).
             */
            configurations: number[][];
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
        };
        /**
         * CollisionBatchResponse
         * @description Compact per-configuration answers: entry i for configuration i.
         */
        CollisionBatchResponse: {
            /** Robot Id */
            robot_id: string;
            geometry: components["schemas"]["CollisionGeometry"];
            /** Margin */
            margin: number;
            /** Count */
            count: number;
            /** Num In Collision */
            num_in_collision: number;
            /**
             * First Collision
             * @description Index of the first colliding configuration.
             */
            first_collision: number | null;
            /** In Collision */
            in_collision: boolean[];
            /** Self Collision */
            self_collision: boolean[];
            /** Environment Collision */
            environment_collision: boolean[];
            /**
             * Pairs
             * @description Per configuration: colliding [a, b] pairs.
             */
            pairs: string[][][];
            /**
             * Min Distance
             * @description Per configuration: smallest distance (m); only with distances.
             */
            min_distance?: number[] | null;
        };
        /** @enum {string} */
        CollisionGeometry: "mesh" | "convex";
        /** @enum {string} */
        CollisionPairKind: "self" | "environment";
        /**
         * CollisionPairsResponse
         * @description Which self-collision pairs are checked.
         */
        CollisionPairsResponse: {
            /** Robot Id */
            robot_id: string;
            /**
             * Links
             * @description Links with collision geometry.
             */
            links: string[];
            /**
             * Pairs
             * @description Checked link pairs [a, b].
             */
            pairs: string[][];
            /**
             * Srdf
             * @description Whether an SRDF disabled pairs.
             */
            srdf: boolean;
        };
        /**
         * CollisionRequest
         * @description A configuration to check.
         */
        CollisionRequest: {
            /**
             * Obstacles
             * @description Obstacles in the robot's root frame.
             */
            obstacles?: components["schemas"]["ObstacleIn"][] | null;
            /**
             * Scene
             * @description Name of a stored scene (instead of obstacles).
             */
            scene?: string | null;
            /**
             * Margin
             * @description Safety margin (m): pairs closer than this count as in collision.
             * @default 0
             */
            margin?: number;
            /**
             * Distances
             * @description Compute every checked pair's distance and witness points (slower, especially with meshes).
             * @default false
             */
            distances?: boolean;
            /**
             * @description mesh: the URDF collision meshes (exact); convex: their convex hulls (faster, conservative, signed distances).
             * @default mesh
             */
            geometry?: components["schemas"]["CollisionGeometry"];
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
        };
        /**
         * CollisionResponse
         * @description The verdict for one configuration.
         */
        CollisionResponse: {
            /** Robot Id */
            robot_id: string;
            /** @description The configuration checked, in joint order. */
            q: components["schemas"]["Configuration"];
            geometry: components["schemas"]["CollisionGeometry"];
            /** Margin */
            margin: number;
            /**
             * In Collision
             * @description Any pair closer than the margin.
             */
            in_collision: boolean;
            /**
             * Self Collision
             * @description Two links of the robot collide.
             */
            self_collision: boolean;
            /**
             * Environment Collision
             * @description A link collides with an obstacle.
             */
            environment_collision: boolean;
            /**
             * Min Distance
             * @description Smallest distance (m) over the checked pairs with distances; otherwise over the pairs in collision (null when none).
             */
            min_distance: number | null;
            /**
             * Pairs
             * @description Pairs in collision, or every checked pair with distances; closest first.
             */
            pairs: components["schemas"]["PairOut"][];
            /**
             * Checked Pairs
             * @description Number of link/link and link/obstacle pairs checked.
             */
            checked_pairs: number;
        };
        /** @description One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous joints, m for prismatic ones. */
        Configuration: number[];
        /** @enum {string} */
        DHConvention: "standard" | "modified";
        /**
         * DHGeometryDoc
         * @description Generated capsule geometry.
         */
        DHGeometryDoc: {
            /**
             * Radius
             * @description Capsule radius in metres (0: none).
             * @default 0.02
             */
            radius?: number | null;
        };
        /** @enum {string} */
        DHJointType: "revolute" | "prismatic" | "continuous";
        /**
         * DHRowDoc
         * @description One row: joint i's DH parameters.
         */
        DHRowDoc: {
            /**
             * Name
             * @description Joint name (default j<i>, 1-based).
             */
            name?: string | null;
            /**
             * @description Joint kind (null: revolute).
             * @default revolute
             */
            type?: components["schemas"]["DHJointType"] | null;
            /**
             * A
             * @description Link length (a_i; a_{i-1} in the modified convention).
             */
            a: number;
            /**
             * Alpha
             * @description Link twist (α_i; α_{i-1} in the modified convention).
             */
            alpha: number;
            /**
             * D
             * @description Link offset; the constant part for a prismatic joint.
             */
            d: number;
            /**
             * Theta
             * @description Joint angle offset (θ = q + theta for revolute joints).
             */
            theta: number;
            /**
             * Lower
             * @description Lower limit of q (table units).
             */
            lower?: number | null;
            /**
             * Upper
             * @description Upper limit of q (table units).
             */
            upper?: number | null;
            /**
             * Velocity
             * @description Velocity limit (units per second).
             */
            velocity?: number | null;
            /**
             * Effort
             * @description Effort limit (N·m or N).
             */
            effort?: number | null;
            /**
             * Mass
             * @description Mass of the link the row moves (kg, always SI); needed with com or inertia. Rows without it give a link without inertia (dynamics answer 422 missing-inertia).
             */
            mass?: number | null;
            /**
             * Com
             * @description The link's centre of mass [x, y, z] in frame i, the DH frame at the end of the row (as the Robotics Toolbox's r), in the table's length unit; default 0.
             */
            com?: number[] | null;
            /**
             * Inertia
             * @description The link's rotational inertia about its centre of mass in frame i's axes, [ixx, ixy, ixz, iyy, iyz, izz] (kg·m², always SI): positive semi-definite, each principal moment at most the sum of the other two; default 0 (a point mass).
             */
            inertia?: number[] | null;
        };
        /**
         * DHTableDoc
         * @description A Denavit–Hartenberg table (JSON, or YAML with ``Content-Type: application/yaml``).
         *
         *     ``standard``: A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); ``modified`` (Craig): A_i =
         *     Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). The robot's frames ``dh_0`` … ``dh_n`` are the
         *     DH frames (world pose B·A_1⋯A_i) and ``tool`` (the default end effector) is
         *     dh_n·T_tool.
         */
        DHTableDoc: {
            /**
             * Name
             * @description Robot id: 1-64 of a-z, 0-9, '_' and '-'.
             */
            name: string;
            /**
             * Description
             * @default
             */
            description?: string | null;
            convention: components["schemas"]["DHConvention"];
            units?: components["schemas"]["DHUnitsDoc"] | null;
            /** @description World → DH frame 0. */
            base?: components["schemas"]["DHTransformDoc"] | null;
            /** @description DH frame n → tool (TCP). */
            tool?: components["schemas"]["DHTransformDoc"] | null;
            geometry?: components["schemas"]["DHGeometryDoc"] | null;
            /** Joints */
            joints: components["schemas"]["DHRowDoc"][];
        };
        /**
         * DHTransformDoc
         * @description A fixed transform: translation ``xyz`` then rotation ``rpy`` (R = Rz·Ry·Rx).
         */
        DHTransformDoc: {
            /**
             * Xyz
             * @default [
             *       0,
             *       0,
             *       0
             *     ]
             */
            xyz?: number[] | null;
            /**
             * Rpy
             * @default [
             *       0,
             *       0,
             *       0
             *     ]
             */
            rpy?: number[] | null;
        };
        /**
         * DHUnitsDoc
         * @description Units of the table's numbers (the service converts to SI on import).
         */
        DHUnitsDoc: {
            /**
             * @description Unit of a, d, xyz, limits.
             * @default m
             */
            length?: components["schemas"]["LengthUnit"];
            /**
             * @description Unit of alpha, theta, rpy, limits.
             * @default rad
             */
            angle?: components["schemas"]["AngleUnit"];
        };
        /**
         * DynamicsBatchResponse
         * @description Row i belongs to state i; columns are `joint_names`.
         */
        DynamicsBatchResponse: {
            /** Robot Id */
            robot_id: string;
            /** Joint Names */
            joint_names: string[];
            /**
             * Torques
             * @description N×n joint torques τ (N·m, N).
             */
            torques: number[][];
            /**
             * Gravity Torques
             * @description N×n gravity torques g(q).
             */
            gravity_torques: number[][];
            /** @description The payload included, or null. */
            payload: components["schemas"]["PayloadOut"] | null;
        };
        /**
         * DynamicsRequest
         * @description A state (q, q̇, q̈), an optional payload and an optional wrench.
         */
        DynamicsRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Velocities
             * @description Joint velocities q̇. One value per joint in joint order (with `group`: one per joint of the group, in its order, is accepted too; the others take 0), or a joint name → value map; zeros when absent. Each value within ±1e+06.
             */
            velocities?: number[] | components["schemas"]["JointRates"] | null;
            /**
             * Accelerations
             * @description Joint accelerations q̈. One value per joint in joint order (with `group`: one per joint of the group, in its order, is accepted too; the others take 0), or a joint name → value map; zeros when absent. Each value within ±1e+06.
             */
            accelerations?: number[] | components["schemas"]["JointRates"] | null;
            /** @description A load fixed to a frame. */
            payload?: components["schemas"]["PayloadIn"] | null;
            /** @description A wrench a frame exerts on its environment (adds Jᵀ·F). */
            wrench?: components["schemas"]["WrenchIn"] | null;
        };
        /**
         * DynamicsResponse
         * @description τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F and its parts, over `joint_names` (the robot's
         *     joints, or with `group` the group's).
         */
        DynamicsResponse: {
            /** Robot Id */
            robot_id: string;
            q: components["schemas"]["Configuration"];
            /**
             * Joint Names
             * @description The joints of every vector and matrix, in order.
             */
            joint_names: string[];
            /**
             * Torques
             * @description τ, the joint torques (N·m; N for prismatic).
             */
            torques: number[];
            /**
             * Gravity Torques
             * @description g(q): the torques holding the arm still.
             */
            gravity_torques: number[];
            /**
             * Coriolis Torques
             * @description C(q, q̇)·q̇: Coriolis and centrifugal.
             */
            coriolis_torques: number[];
            /**
             * Inertial Torques
             * @description M(q)·q̈.
             */
            inertial_torques: number[];
            /**
             * Wrench Torques
             * @description Jᵀ·F (zeros without a wrench).
             */
            wrench_torques: number[];
            /**
             * Mass Matrix
             * @description M(q), n×n, symmetric positive definite (kg·m², kg for prismatic joints).
             */
            mass_matrix: number[][];
            /**
             * Coriolis Matrix
             * @description C(q, q̇), n×n (Christoffel symbols: Ṁ − 2C is skew-symmetric).
             */
            coriolis_matrix: number[][];
            /**
             * Center Of Mass
             * @description Centre of mass of the robot and payload (m, world frame).
             */
            center_of_mass: number[];
            /**
             * Total Mass
             * @description Mass of the robot and payload (kg).
             */
            total_mass: number;
            /**
             * Effort Limits
             * @description URDF effort limits (N·m, N); null where the URDF gives none.
             */
            effort_limits: (number | null)[];
            /**
             * Effort Ratios
             * @description |τ| / effort limit; null where there is no limit.
             */
            effort_ratios: (number | null)[];
            /**
             * Binding Joint
             * @description The joint with the largest effort ratio; null when no joint has a limit.
             */
            binding_joint: string | null;
            /** @description The payload included, or null. */
            payload: components["schemas"]["PayloadOut"] | null;
        };
        /**
         * Ellipsoid
         * @description An ellipsoid in task space (the task's rows as coordinates).
         */
        Ellipsoid: {
            /**
             * Axes
             * @description m unit axes (left singular vectors u_i).
             */
            axes: number[][];
            /**
             * Half Lengths
             * @description Half-length along each axis; null = infinite (lost direction).
             */
            half_lengths: (number | null)[];
        };
        /**
         * EndEffectorOut
         * @description An SRDF end effector: the tool group ``group`` attached at ``parent_link``.
         */
        EndEffectorOut: {
            /** Name */
            name: string;
            /** Parent Link */
            parent_link: string;
            /** Group */
            group: string;
            /** Parent Group */
            parent_group: string | null;
        };
        /**
         * FKBatchResponse
         * @description Compact arrays, row i for configuration i.
         */
        FKBatchResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            /**
             * Positions
             * @description N×3 positions (m) in the root frame.
             */
            positions: number[][];
            /**
             * Orientations
             * @description N×4 quaternions [x, y, z, w].
             */
            orientations: number[][];
        };
        /**
         * FKRequest
         * @description Configuration and the frames to place.
         */
        FKRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Frames
             * @description Frame names; default the end effector (with `group`: the group's tip); ["*"] for every frame.
             */
            frames?: string[] | null;
        };
        /**
         * FKResponse
         * @description Frame poses in the root frame.
         */
        FKResponse: {
            /** Robot Id */
            robot_id: string;
            /** @description The configuration used, in joint order. */
            q: components["schemas"]["Configuration"];
            /**
             * Poses
             * @description Frame name → pose in the root frame.
             */
            poses: {
                [key: string]: components["schemas"]["Pose"];
            };
            /**
             * Within Limits
             * @description Whether every joint lies within its limits.
             */
            within_limits: boolean;
            /**
             * Joints Outside Limits
             * @description Joints outside their limits.
             */
            joints_outside_limits: string[];
        };
        /**
         * FieldError
         * @description One validation failure.
         */
        FieldError: {
            /**
             * Field
             * @description Dotted path of the offending value in the request.
             */
            field: string;
            /**
             * Message
             * @description Why the value was rejected.
             */
            message: string;
        };
        /**
         * FrameOut
         * @description A named frame.
         */
        FrameOut: {
            /** Name */
            name: string;
            /**
             * Kind
             * @description link | fixed (URDF fixed joint) | joint.
             */
            kind: string;
            /**
             * Parent Joint
             * @description The actuated joint that moves it, if any.
             */
            parent_joint: string | null;
        };
        /**
         * GroupOut
         * @description A planning group of the SRDF, resolved against the model.
         */
        GroupOut: {
            /** Name */
            name: string;
            /**
             * Joints
             * @description Its configuration joints (actuated, no mimic followers), in joint order: a `q` of this length is accepted with `group`.
             */
            joints: string[];
            /**
             * Tip
             * @description Its default frame: its chain's tip_link, else the parent_link of an end effector attached to it, else its deepest link.
             */
            tip: string;
        };
        /**
         * Health
         * @description Liveness answer.
         */
        Health: {
            /**
             * Status
             * @description Always "ok".
             */
            status: string;
        };
        /**
         * IKBatchItem
         * @description Result for one target.
         */
        IKBatchItem: {
            /** Success */
            success: boolean;
            status: components["schemas"]["IKStatus"];
            q: components["schemas"]["Configuration"];
            /** Position Error */
            position_error: number;
            /** Orientation Error */
            orientation_error: number;
            /** Iterations */
            iterations: number;
            /** Restarts */
            restarts: number;
            /** Solve Time Ms */
            solve_time_ms: number;
            /** @description Why no solution was found (null on success): unreachable (the target position is beyond the chain's reach bound; the search is skipped) | joint_limits (reached only outside the limits, or the best configuration is pinned at a limit) | collision (every solution found collides) | singular (the search stalled at a singular configuration) | timeout (the time budget or max_iterations ended the search). See docs/ik.md. */
            reason: components["schemas"]["IKReason"] | null;
            /**
             * Detail
             * @description The reason in a sentence, with numbers.
             */
            detail: string | null;
        };
        /**
         * IKBatchRequest
         * @description Many targets for one frame.
         */
        IKBatchRequest: {
            /**
             * Frame
             * @description Frame to place; default the end effector (with `group`: its tip).
             */
            frame?: string | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * @description pose (default): full 6-D pose | position: the frame origin only, orientation free (3 task rows, fine for arms with fewer than 6 joints) | orientation: the rotation only.
             * @default pose
             */
            mode?: components["schemas"]["IKMode"];
            /**
             * Weights
             * @description Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); 0 frees a component (not checked against the tolerance).
             */
            weights?: number[] | null;
            tolerance?: components["schemas"]["Tolerance"];
            /**
             * Timeout Ms
             * @description Time budget (ms) per target; capped by the server's ik_max_timeout_ms.
             * @default 5
             */
            timeout_ms?: number;
            /**
             * Max Iterations
             * @description Cap on solver iterations (Jacobian evaluations).
             */
            max_iterations?: number | null;
            /**
             * Avoid Collisions
             * @description Return only solutions free of self-collision and of collision with `obstacles` / `scene` (other branches and restarts are searched within the budget).
             * @default false
             */
            avoid_collisions?: boolean;
            /**
             * Obstacles
             * @description With avoid_collisions: obstacles (root frame).
             */
            obstacles?: components["schemas"]["ObstacleIn"][] | null;
            /**
             * Scene
             * @description With avoid_collisions: a stored scene's name.
             */
            scene?: string | null;
            /**
             * Margin
             * @description With avoid_collisions: clearance (m) a solution must keep.
             * @default 0
             */
            margin?: number;
            /**
             * @description With avoid_collisions: meshes, or their convex hulls (faster).
             * @default mesh
             */
            collision_geometry?: components["schemas"]["CollisionGeometry"];
            /**
             * Random Seed
             * @description Seed of the random restarts: the same request gives the same answer, bit for bit, on any worker (unless the time budget ends the search: give max_iterations for a budget that does not depend on the machine's speed). Default: a fixed table of restarts, also reproducible.
             */
            random_seed?: number | null;
            /**
             * Seed
             * @description Start configuration: one value per joint (joint order; with `group`, one per joint of the group is accepted too), joint → value (others: middle of their limits), or the name of a named state of the SRDF (e.g. "ready"; GET /robots/{id} lists them). Default: the middle of the joint limits. Values within ±10000 (rad or m), as every configuration. IK answers always hold every joint.
             */
            seed?: number[] | components["schemas"]["JointPositions"] | string | null;
            /**
             * Targets
             * @description Targets, solved in order. Each as `target` of /ik.
             */
            targets: components["schemas"]["Pose"][];
            /**
             * Chain Seeds
             * @description Seed each target with the previous solution (trajectories); false: every target starts from `seed`, the targets are solved independently (spread over the server's batch worker processes), and with random_seed target i draws its restarts from its own generator, child i of SeedSequence(random_seed), so answers do not depend on how the batch is split.
             * @default true
             */
            chain_seeds?: boolean;
        };
        /**
         * IKBatchResponse
         * @description Results in target order.
         */
        IKBatchResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            mode: components["schemas"]["IKMode"];
            /** Joint Names */
            joint_names: string[];
            /**
             * Solved
             * @description How many targets succeeded.
             */
            solved: number;
            /** Results */
            results: components["schemas"]["IKBatchItem"][];
            /** Total Time Ms */
            total_time_ms: number;
            /**
             * Solver Version
             * @description The solver's name and version: with random_seed (and max_iterations), the same request gives the same answer, bit for bit, on any worker of the same solver_version.
             */
            solver_version: string;
        };
        /** @enum {string} */
        IKMode: "pose" | "position" | "orientation";
        /** @enum {string} */
        IKRankBy: "seed_distance" | "manipulability" | "clearance";
        /** @enum {string} */
        IKReason: "unreachable" | "joint_limits" | "collision" | "singular" | "timeout";
        /**
         * IKRequest
         * @description One IK query.
         */
        IKRequest: {
            /**
             * Frame
             * @description Frame to place; default the end effector (with `group`: its tip).
             */
            frame?: string | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * @description pose (default): full 6-D pose | position: the frame origin only, orientation free (3 task rows, fine for arms with fewer than 6 joints) | orientation: the rotation only.
             * @default pose
             */
            mode?: components["schemas"]["IKMode"];
            /**
             * Weights
             * @description Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); 0 frees a component (not checked against the tolerance).
             */
            weights?: number[] | null;
            tolerance?: components["schemas"]["Tolerance"];
            /**
             * Timeout Ms
             * @description Time budget (ms) per target; capped by the server's ik_max_timeout_ms.
             * @default 5
             */
            timeout_ms?: number;
            /**
             * Max Iterations
             * @description Cap on solver iterations (Jacobian evaluations).
             */
            max_iterations?: number | null;
            /**
             * Avoid Collisions
             * @description Return only solutions free of self-collision and of collision with `obstacles` / `scene` (other branches and restarts are searched within the budget).
             * @default false
             */
            avoid_collisions?: boolean;
            /**
             * Obstacles
             * @description With avoid_collisions: obstacles (root frame).
             */
            obstacles?: components["schemas"]["ObstacleIn"][] | null;
            /**
             * Scene
             * @description With avoid_collisions: a stored scene's name.
             */
            scene?: string | null;
            /**
             * Margin
             * @description With avoid_collisions: clearance (m) a solution must keep.
             * @default 0
             */
            margin?: number;
            /**
             * @description With avoid_collisions: meshes, or their convex hulls (faster).
             * @default mesh
             */
            collision_geometry?: components["schemas"]["CollisionGeometry"];
            /**
             * Random Seed
             * @description Seed of the random restarts: the same request gives the same answer, bit for bit, on any worker (unless the time budget ends the search: give max_iterations for a budget that does not depend on the machine's speed). Default: a fixed table of restarts, also reproducible.
             */
            random_seed?: number | null;
            /**
             * Seed
             * @description Start configuration: one value per joint (joint order; with `group`, one per joint of the group is accepted too), joint → value (others: middle of their limits), or the name of a named state of the SRDF (e.g. "ready"; GET /robots/{id} lists them). Default: the middle of the joint limits. Values within ±10000 (rad or m), as every configuration. IK answers always hold every joint.
             */
            seed?: number[] | components["schemas"]["JointPositions"] | string | null;
            /** @description Desired placement of the frame in the root (world) frame; a pose an answer returns (e.g. FK's) is accepted as is. Mode pose needs a position (`position` or `matrix`) and a rotation (`orientation`, `rpy` or `matrix`); mode position a position; mode orientation a rotation. Redundant fields must agree within 1e-9. */
            target: components["schemas"]["Pose"];
            /**
             * Num Solutions
             * @description Distinct solutions wanted: one per branch (shoulder/elbow/wrist flags where the arm has them, else clusters in joint space; see docs/ik.md).
             * @default 1
             */
            num_solutions?: number;
            /**
             * @description Order of the solutions: seed_distance (smallest largest-joint move first) | manipulability (largest Yoshikawa measure first) | clearance (largest distance to the obstacles first; needs avoid_collisions with obstacles or a scene).
             * @default seed_distance
             */
            rank_by?: components["schemas"]["IKRankBy"];
        };
        /**
         * IKResponse
         * @description Result; no solution is not an error (success false, best configuration found).
         */
        IKResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            mode: components["schemas"]["IKMode"];
            /** Success */
            success: boolean;
            status: components["schemas"]["IKStatus"];
            /** @description Best configuration (first solution, or lowest error). */
            q: components["schemas"]["Configuration"];
            joint_positions: components["schemas"]["JointPositions"];
            /**
             * Position Error
             * @description Of q: ‖p − p_t‖ (m).
             */
            position_error: number;
            /**
             * Orientation Error
             * @description Of q: rotation angle to the target (rad).
             */
            orientation_error: number;
            /**
             * Solutions
             * @description Distinct solutions, one per branch, in rank_by order.
             */
            solutions: components["schemas"]["IKSolutionOut"][];
            /** Iterations */
            iterations: number;
            /** Restarts */
            restarts: number;
            /** Solve Time Ms */
            solve_time_ms: number;
            /**
             * Method
             * @description analytic | numeric | analytic+numeric
             */
            method: string;
            /** @description Why no solution was found (null on success): unreachable (the target position is beyond the chain's reach bound; the search is skipped) | joint_limits (reached only outside the limits, or the best configuration is pinned at a limit) | collision (every solution found collides) | singular (the search stalled at a singular configuration) | timeout (the time budget or max_iterations ended the search). See docs/ik.md. */
            reason: components["schemas"]["IKReason"] | null;
            /**
             * Detail
             * @description The reason in a sentence, with numbers.
             */
            detail: string | null;
            /**
             * Solver Version
             * @description The solver's name and version: with random_seed (and max_iterations), the same request gives the same answer, bit for bit, on any worker of the same solver_version.
             */
            solver_version: string;
        };
        /**
         * IKSolutionOut
         * @description A verified solution.
         */
        IKSolutionOut: {
            /** @description Configuration in joint order (rad, m). */
            q: components["schemas"]["Configuration"];
            joint_positions: components["schemas"]["JointPositions"];
            /**
             * Position Error
             * @description ‖p − p_t‖ (m), by forward kinematics.
             */
            position_error: number;
            /**
             * Orientation Error
             * @description Rotation angle to the target (rad).
             */
            orientation_error: number;
            /**
             * Branch
             * @description Its branch: flags such as "shoulder_left/elbow_up/wrist_noflip" (UR-type and spherical-wrist 6R arms; planar 2-link arms: "elbow_up"/"elbow_down"), else "cluster_<k>" (joint-space clusters, cluster_0 nearest the seed).
             */
            branch: string;
            /**
             * Seed Distance
             * @description Largest single-joint move from the seed (rad or m; continuous joints around the circle).
             */
            seed_distance: number;
            /**
             * Manipulability
             * @description Yoshikawa measure ∏σ_i of the frame Jacobian over the moving joints.
             */
            manipulability: number;
            /**
             * Clearance
             * @description With obstacles: smallest robot–obstacle distance (m), else null.
             */
            clearance: number | null;
        };
        /** @enum {string} */
        IKStatus: "converged" | "not_converged" | "timeout";
        /** @enum {string} */
        JacobianPart: "full" | "translation" | "rotation";
        /** @enum {string} */
        JacobianReference: "world" | "local" | "world_spatial";
        /**
         * JacobianRequest
         * @description Configuration, frame and reference.
         */
        JacobianRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * @description world (default): origin velocity and angular velocity in world axes (Pinocchio LOCAL_WORLD_ALIGNED; the textbook geometric Jacobian) | local: the same in the frame's own axes (LOCAL) | world_spatial: spatial velocity at the world origin (WORLD).
             * @default world
             */
            reference?: components["schemas"]["JacobianReference"];
        };
        /**
         * JacobianResponse
         * @description The Jacobian, rows [vx, vy, vz, ωx, ωy, ωz], columns in joint order (with `group`:
         *     the group's joints, in the group's order).
         */
        JacobianResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            reference: components["schemas"]["JacobianReference"];
            q: components["schemas"]["Configuration"];
            /**
             * Jacobian
             * @description 6×n (with `group`: 6×k, k the group's joints); linear rows in m/rad or m/m.
             */
            jacobian: number[][];
            /**
             * Joint Names
             * @description The joint of each column.
             */
            joint_names: string[];
        };
        /** JobList */
        JobList: {
            /** Jobs */
            jobs: components["schemas"]["JobResponse"][];
        };
        /**
         * JobResponse
         * @description A build job.
         */
        JobResponse: {
            /** Job Id */
            job_id: string;
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            status: components["schemas"]["JobStatus"];
            /**
             * Map Id
             * @description The stored map, once done.
             */
            map_id: string | null;
            /** Error */
            error: string | null;
            progress: components["schemas"]["ProgressOut"];
        };
        /** @enum {string} */
        JobStatus: "queued" | "running" | "done" | "failed" | "cancelled";
        /**
         * JointLimits
         * @description Joint limits, SI units; ``null`` where the URDF gives none (continuous joints).
         */
        JointLimits: {
            /**
             * Lower
             * @description Lower position limit (rad or m).
             */
            lower: number | null;
            /**
             * Upper
             * @description Upper position limit (rad or m).
             */
            upper: number | null;
            /**
             * Velocity
             * @description Velocity limit (rad/s or m/s).
             */
            velocity: number | null;
            /**
             * Effort
             * @description Effort limit (N·m or N).
             */
            effort: number | null;
        };
        /**
         * JointOut
         * @description An actuated joint, in configuration order.
         */
        JointOut: {
            /** Name */
            name: string;
            /**
             * Type
             * @description revolute | prismatic | continuous.
             */
            type: string;
            /**
             * Parent
             * @description Parent link.
             */
            parent: string;
            /**
             * Child
             * @description Child link.
             */
            child: string;
            /**
             * Axis
             * @description Joint axis in the joint frame (URDF <axis>).
             */
            axis: number[];
            limits: components["schemas"]["JointLimits"];
            /**
             * Continuous
             * @description Unbounded revolute joint (one angle on the wire).
             */
            continuous: boolean;
        };
        /** @description Joint name → value: rad for revolute and continuous joints, m for prismatic ones, each within ±10000 (a value beyond is a 422 naming `<field>.<joint>`). */
        JointPositions: {
            [key: string]: number;
        };
        /** @description Joint name → value (rad/s or m/s for velocities, rad/s² or m/s² for accelerations); joints not named take 0. A mimic follower may be named when its value equals multiplier × its leader's. */
        JointRates: {
            [key: string]: number;
        };
        /** @enum {string} */
        LengthUnit: "m" | "cm" | "mm";
        /**
         * LineSegment
         * @description A straight line from the previous pose to `to` (orientation by slerp).
         */
        LineSegment: {
            /**
             * @description discriminator enum property added by openapi-typescript
             * @enum {string}
             */
            type: "line";
            to: components["schemas"]["Pose"];
        };
        /**
         * ManipulabilityBatchResponse
         * @description Compact arrays: entry i belongs to configuration i.
         */
        ManipulabilityBatchResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            reference: components["schemas"]["JacobianReference"];
            /** Rows */
            rows: string[];
            /** Joints */
            joints: string[];
            /** Yoshikawa */
            yoshikawa: number[];
            /** Min Singular Value */
            min_singular_value: number[];
            /** Max Singular Value */
            max_singular_value: number[];
            /** Inverse Condition */
            inverse_condition: number[];
            /**
             * Condition Number
             * @description null where singular.
             */
            condition_number: (number | null)[];
            /** Det Jjt */
            det_jjt: number[];
            /** Rank */
            rank: number[];
            /** Singular */
            singular: boolean[];
        };
        /**
         * ManipulabilityRequest
         * @description A configuration and the task to analyse.
         */
        ManipulabilityRequest: {
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             */
            frame?: string | null;
            /** @description Task rows: full (vx vy vz wx wy wz, default) | translation (vx vy vz) | rotation (wx wy wz). Give either part or rows. */
            part?: components["schemas"]["JacobianPart"] | null;
            /**
             * Rows
             * @description Explicit task rows by name (vx, vy, vz, wx, wy, wz) or index 0–5, e.g. ["vx", "vy"] for a planar arm in the x-y plane. Give either part or rows.
             */
            rows?: (string | number)[] | null;
            /**
             * @description world (default): origin velocity and angular velocity in world axes (Pinocchio LOCAL_WORLD_ALIGNED; the textbook geometric Jacobian) | local: the same in the frame's own axes (LOCAL) | world_spatial: spatial velocity at the world origin (WORLD).
             * @default world
             */
            reference?: components["schemas"]["JacobianReference"];
            /**
             * Relative Tolerance
             * @description Relative rank tolerance: σ_i counts toward the rank when σ_i > relative_tolerance·σ_max.
             * @default 1e-10
             */
            relative_tolerance?: number;
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
        };
        /**
         * ManipulabilityResponse
         * @description Manipulability measures of the task Jacobian J_t = J[rows][:, joints].
         */
        ManipulabilityResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            reference: components["schemas"]["JacobianReference"];
            q: components["schemas"]["Configuration"];
            /**
             * Rows
             * @description The task's Jacobian rows, in order.
             */
            rows: string[];
            /**
             * Joints
             * @description The task Jacobian's columns: the joints that move the frame.
             */
            joints: string[];
            /**
             * Yoshikawa
             * @description ∏σ_i (= √det(J_t J_tᵀ) when rows ≤ joints).
             */
            yoshikawa: number;
            /**
             * Singular Values
             * @description σ_1 ≥ … ≥ σ_p, p = min(rows, joints).
             */
            singular_values: number[];
            /** Min Singular Value */
            min_singular_value: number;
            /**
             * Inverse Condition
             * @description σ_min / σ_max (0 for a zero Jacobian).
             */
            inverse_condition: number;
            /**
             * Condition Number
             * @description σ_max / σ_min; null when singular.
             */
            condition_number: number | null;
            /**
             * Det Jjt
             * @description det(J_t J_tᵀ); exactly 0 when rows > joints.
             */
            det_jjt: number;
            /** Rank */
            rank: number;
            /**
             * Tolerance
             * @description Absolute threshold used for the rank: σ_i > this.
             */
            tolerance: number;
            /** Relative Tolerance */
            relative_tolerance: number;
            /**
             * Singular
             * @description rank < min(rows, joints).
             */
            singular: boolean;
            /** @description Axes u_i, half-lengths σ_i. */
            velocity_ellipsoid: components["schemas"]["Ellipsoid"];
            /** @description Axes u_i, half-lengths 1/σ_i. */
            force_ellipsoid: components["schemas"]["Ellipsoid"];
            /**
             * Lost Directions
             * @description Orthonormal basis of the left null space: task directions the frame cannot move in (coordinates over `rows`).
             */
            lost_directions: number[][];
            /**
             * Dependent Joints
             * @description Joints whose columns take part in a linear dependency (null-space support).
             */
            dependent_joints: string[];
            /**
             * Joint Null Space
             * @description Orthonormal basis of the null space: joint velocities (over `joints`) that do not move the task.
             */
            joint_null_space: number[][];
        };
        /** MapBounds */
        MapBounds: {
            /** Min */
            min: number[];
            /** Max */
            max: number[];
        };
        /**
         * MapInfo
         * @description A stored map's metadata.
         */
        MapInfo: {
            /** Map Id */
            map_id: string;
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            /** Created At */
            created_at: string;
            /** @description The grid's box (max = min + shape·voxel_size). */
            bounds: components["schemas"]["MapBounds"];
            /** Voxel Size */
            voxel_size: number;
            /**
             * Shape
             * @description Voxels along x, y, z.
             */
            shape: number[];
            /** Orientation Divisions */
            orientation_divisions: number;
            /** Orientation Bins */
            orientation_bins: number;
            /** Cells */
            cells: number;
            /** Rows */
            rows: string[];
            /**
             * Joints
             * @description The sampled joints (those that move the frame).
             */
            joints: string[];
            /** Samples */
            samples: number;
            sampling: components["schemas"]["ReachabilitySampling"];
            /** Seed */
            seed: number;
            self_collision: components["schemas"]["SelfCollisionMode"];
            /** Samples Per Second */
            samples_per_second: number | null;
            /** Build Seconds */
            build_seconds: number | null;
            /** Robot Fingerprint */
            robot_fingerprint: string;
            /** Reachable Cells */
            reachable_cells: number;
            /** Reachable Voxels */
            reachable_voxels: number;
            /** Max Manipulability */
            max_manipulability: number | null;
        };
        /** MapList */
        MapList: {
            /** Maps */
            maps: components["schemas"]["MapInfo"][];
        };
        /**
         * MaxDeviation
         * @description Largest deviation from the Cartesian path of the joint-linear motion between two
         *     returned points (the path is densified until it holds).
         */
        MaxDeviation: {
            /**
             * Position
             * @description Metres (default 0.001).
             * @default 0.001
             */
            position?: number;
            /**
             * Orientation
             * @description Radians (default 0.01).
             * @default 0.01
             */
            orientation?: number;
        };
        /**
         * MaxPayloadRequest
         * @description One configuration (`q` or `joint_positions`) or a `path` of configurations, the point
         *     the payload hangs from, and a tool already attached.
         */
        MaxPayloadRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Path
             * @description N configurations in joint order (with `group`: rows of the group's joints are accepted too), instead of `q`/`joint_positions`.
             */
            path?: number[][] | null;
            /**
             * Frame
             * @description The frame the payload hangs from; default the robot's tip (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * Com
             * @description The payload's centre of mass (m) in the frame's axes.
             * @default [
             *       0,
             *       0,
             *       0
             *     ]
             */
            com?: number[];
            /** @description A load already attached (a tool): its weight counts. */
            payload?: components["schemas"]["PayloadIn"] | null;
        };
        /**
         * MaxPayloadResponse
         * @description At one configuration, its bound; along a path, the bound of the sample where it is
         *     smallest (`min_sample`) and every sample's.
         */
        MaxPayloadResponse: {
            /**
             * Max Payload
             * @description The largest payload (kg) every joint's effort limit holds at rest; null = unbounded (the payload loads no joint that has a limit); 0 when the arm cannot hold itself.
             */
            max_payload: number | null;
            /**
             * Limiting Joint
             * @description The joint whose limit sets max_payload; null when unbounded.
             */
            limiting_joint: string | null;
            /**
             * Per Joint
             * @description Each joint's own bound (kg); null where the joint has no limit or the payload does not load it.
             */
            per_joint: {
                [key: string]: number | null;
            };
            /**
             * Gravity Torques
             * @description g(q) of the robot and any attached tool, without the payload (N·m, N).
             */
            gravity_torques: number[];
            /**
             * Torques At Max
             * @description g(q) with max_payload attached (= gravity_torques when unbounded).
             */
            torques_at_max: number[];
            /**
             * Holds Itself
             * @description Every |g_i| ≤ its limit without the payload.
             */
            holds_itself: boolean;
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            /** Com */
            com: number[];
            /** Joint Names */
            joint_names: string[];
            /**
             * Min Max Payload
             * @description Along a path: the smallest max_payload over its samples (null: unbounded everywhere, or no path).
             */
            min_max_payload?: number | null;
            /**
             * Min Sample
             * @description Along a path: the sample where max_payload is smallest.
             */
            min_sample?: number | null;
            /**
             * Samples
             * @description Along a path: each sample's bound, in order; null without a path.
             */
            samples?: components["schemas"]["MaxPayloadSample"][] | null;
        };
        /**
         * MaxPayloadSample
         * @description The payload bound at one configuration.
         */
        MaxPayloadSample: {
            /**
             * Max Payload
             * @description The largest payload (kg) every joint's effort limit holds at rest; null = unbounded (the payload loads no joint that has a limit); 0 when the arm cannot hold itself.
             */
            max_payload: number | null;
            /**
             * Limiting Joint
             * @description The joint whose limit sets max_payload; null when unbounded.
             */
            limiting_joint: string | null;
            /**
             * Per Joint
             * @description Each joint's own bound (kg); null where the joint has no limit or the payload does not load it.
             */
            per_joint: {
                [key: string]: number | null;
            };
            /**
             * Gravity Torques
             * @description g(q) of the robot and any attached tool, without the payload (N·m, N).
             */
            gravity_torques: number[];
            /**
             * Torques At Max
             * @description g(q) with max_payload attached (= gravity_torques when unbounded).
             */
            torques_at_max: number[];
            /**
             * Holds Itself
             * @description Every |g_i| ≤ its limit without the payload.
             */
            holds_itself: boolean;
        };
        /**
         * MaxStep
         * @description Largest Cartesian step between consecutive waypoints of the interpolated path.
         */
        MaxStep: {
            /**
             * Position
             * @description Metres (default 0.01).
             * @default 0.01
             */
            position?: number;
            /**
             * Orientation
             * @description Radians (default 0.05).
             * @default 0.05
             */
            orientation?: number;
        };
        /**
         * MimicJointOut
         * @description A mimic joint: it follows its leader and is not a configuration entry.
         */
        MimicJointOut: {
            /** Name */
            name: string;
            /**
             * Type
             * @description revolute | prismatic (the URDF type).
             */
            type: string;
            /**
             * Leader
             * @description The actuated joint it follows.
             */
            leader: string;
            /**
             * Multiplier
             * @description value = multiplier × value(leader) + offset.
             */
            multiplier: number;
            /**
             * Offset
             * @description Offset (rad or m).
             */
            offset: number;
        };
        /**
         * NamedStateOut
         * @description An SRDF group state: usable as an IK seed by name (``"seed": "ready"``).
         */
        NamedStateOut: {
            /** Name */
            name: string;
            /**
             * Group
             * @description The group it is a state of (null if not given).
             */
            group: string | null;
            /** @description Joint → value (rad or m). */
            joint_positions: components["schemas"]["JointPositions"];
        };
        /**
         * ObstacleIn
         * @description A box, sphere, cylinder or capsule in the robot's root frame.
         */
        ObstacleIn: {
            /**
             * Name
             * @description Unique name in the set.
             */
            name: string;
            /** @description Solid type. */
            shape: components["schemas"]["ObstacleShape"];
            /**
             * Size
             * @description box: full edge lengths [x, y, z] (m).
             */
            size?: number[] | null;
            /**
             * Radius
             * @description sphere, cylinder, capsule: radius (m).
             */
            radius?: number | null;
            /**
             * Length
             * @description cylinder: full height along local z (m); capsule: length of the segment between the hemisphere centres (m).
             */
            length?: number | null;
            /** @description Placement root ← obstacle; default the identity (a missing position is the origin, a missing rotation the identity). */
            pose?: components["schemas"]["Pose"] | null;
        };
        /**
         * ObstacleOut
         * @description A stored obstacle (normalised orientation).
         */
        ObstacleOut: {
            /** Name */
            name: string;
            shape: components["schemas"]["ObstacleShape"];
            /** Size */
            size?: number[] | null;
            /** Radius */
            radius?: number | null;
            /** Length */
            length?: number | null;
            /** @description Placement root ← obstacle (every field filled). */
            pose: components["schemas"]["Pose"];
        };
        /** @enum {string} */
        ObstacleShape: "box" | "sphere" | "cylinder" | "capsule";
        /**
         * PairOut
         * @description A checked pair: two links (self) or a link and an obstacle (environment).
         */
        PairOut: {
            /**
             * A
             * @description Link name.
             */
            a: string;
            /**
             * B
             * @description Link name (self) or obstacle name (environment).
             */
            b: string;
            kind: components["schemas"]["CollisionPairKind"];
            /**
             * In Collision
             * @description Closer than the margin.
             */
            in_collision: boolean;
            /**
             * Distance
             * @description Distance (m); negative = penetration depth where coal computes it (convex hulls, primitives); 0 for penetrating meshes.
             */
            distance: number | null;
            /**
             * Point A
             * @description Witness point on a, root frame (m); with distances.
             */
            point_a?: number[] | null;
            /**
             * Point B
             * @description Witness point on b, root frame (m); with distances.
             */
            point_b?: number[] | null;
        };
        /**
         * PathFailureOut
         * @description The first point that could not be reached, and why.
         */
        PathFailureOut: {
            /**
             * Index
             * @description Index of the failed waypoint of the interpolated path.
             */
            index: number;
            /**
             * S
             * @description Its path parameter in [0, 1].
             */
            s: number;
            /** @description Why the path stops there: an IK reason, or joint_step (a jump larger than max_joint_step) | branch (the point is on another branch). */
            reason: components["schemas"]["PathFailureReason"];
            /**
             * Detail
             * @description What went wrong, with numbers.
             */
            detail: string;
            /** @description Best configuration found for that point. */
            q: components["schemas"]["Configuration"];
            /**
             * Position Error
             * @description Of q (m).
             */
            position_error: number;
            /**
             * Orientation Error
             * @description Of q (rad).
             */
            orientation_error: number;
        };
        /** @enum {string} */
        PathFailureReason: "unreachable" | "joint_limits" | "collision" | "singular" | "timeout" | "joint_step" | "branch";
        /**
         * PathPointOut
         * @description One point of the joint path, verified by forward kinematics.
         */
        PathPointOut: {
            /** @description Configuration in joint order (rad, m). */
            q: components["schemas"]["Configuration"];
            /**
             * Position Error
             * @description ‖p − p_path(s)‖ (m).
             */
            position_error: number;
            /**
             * Orientation Error
             * @description Rotation angle to the path's pose (rad).
             */
            orientation_error: number;
            /**
             * S
             * @description Path parameter in [0, 1] of this point's pose.
             */
            s: number;
        };
        /**
         * PathRequest
         * @description A Cartesian path from a start configuration: waypoints or segments (exactly one).
         */
        PathRequest: {
            /**
             * Frame
             * @description Frame to place; default the end effector (with `group`: its tip).
             */
            frame?: string | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * @description pose (default): full 6-D pose | position: the frame origin only, orientation free (3 task rows, fine for arms with fewer than 6 joints) | orientation: the rotation only.
             * @default pose
             */
            mode?: components["schemas"]["IKMode"];
            /**
             * Weights
             * @description Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); 0 frees a component (not checked against the tolerance).
             */
            weights?: number[] | null;
            tolerance?: components["schemas"]["Tolerance"];
            /**
             * Timeout Ms
             * @description Time budget (ms) per target; capped by the server's ik_max_timeout_ms.
             * @default 5
             */
            timeout_ms?: number;
            /**
             * Max Iterations
             * @description Cap on solver iterations (Jacobian evaluations).
             */
            max_iterations?: number | null;
            /**
             * Avoid Collisions
             * @description Return only solutions free of self-collision and of collision with `obstacles` / `scene` (other branches and restarts are searched within the budget).
             * @default false
             */
            avoid_collisions?: boolean;
            /**
             * Obstacles
             * @description With avoid_collisions: obstacles (root frame).
             */
            obstacles?: components["schemas"]["ObstacleIn"][] | null;
            /**
             * Scene
             * @description With avoid_collisions: a stored scene's name.
             */
            scene?: string | null;
            /**
             * Margin
             * @description With avoid_collisions: clearance (m) a solution must keep.
             * @default 0
             */
            margin?: number;
            /**
             * @description With avoid_collisions: meshes, or their convex hulls (faster).
             * @default mesh
             */
            collision_geometry?: components["schemas"]["CollisionGeometry"];
            /**
             * Random Seed
             * @description Seed of the random restarts: the same request gives the same answer, bit for bit, on any worker (unless the time budget ends the search: give max_iterations for a budget that does not depend on the machine's speed). Default: a fixed table of restarts, also reproducible.
             */
            random_seed?: number | null;
            /**
             * Start
             * @description Start configuration: one value per joint (joint order; with `group`, one per joint of the group is accepted too), joint → value (others: middle of their limits), or a named state of the SRDF (e.g. "ready"). The path starts at the frame's pose there; it is the first point of the answer.
             */
            start: number[] | components["schemas"]["JointPositions"] | string;
            /**
             * Waypoints
             * @description Poses to pass through, joined by straight lines (instead of segments); each a Pose as the `target` of /ik (an FK pose as is; redundant fields must agree).
             */
            waypoints?: components["schemas"]["Pose"][] | null;
            /**
             * Segments
             * @description Lines and arcs, each from the previous segment's end (instead of waypoints). A target's missing orientation (mode position) or position (mode orientation) keeps the previous pose's.
             */
            segments?: (components["schemas"]["LineSegment"] | components["schemas"]["ArcSegment"])[] | null;
            max_step?: components["schemas"]["MaxStep"];
            /**
             * Max Joint Step
             * @description Largest move of any one joint between consecutive points (rad or m, default 0.1): a larger one is a jump (another branch, or a singularity), and the path stops there instead of returning it.
             * @default 0.1
             */
            max_joint_step?: number;
            max_deviation?: components["schemas"]["MaxDeviation"];
            /**
             * Branch
             * @description Branch the whole path must stay on (the `branch` of an IK solution, e.g. "shoulder_left/elbow_up/wrist_noflip"); the start must be on it. Without it, the path keeps the start's branch anyway.
             */
            branch?: string | null;
            /** @description Time-parameterize the joint path (time-optimal under joint velocity and acceleration limits, at rest at both ends): the answer's `timing` holds the time, velocity and acceleration of every point. */
            timing?: components["schemas"]["TimingIn"] | null;
        };
        /**
         * PathResponse
         * @description The joint path as far as it goes; `failure` says where and why it stopped.
         */
        PathResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            mode: components["schemas"]["IKMode"];
            /** Joint Names */
            joint_names: string[];
            /**
             * Fraction
             * @description Path parameter s reached (1.0: the whole path).
             */
            fraction: number;
            /**
             * Points
             * @description The start, then every accepted point.
             */
            points: components["schemas"]["PathPointOut"][];
            failure: components["schemas"]["PathFailureOut"] | null;
            /**
             * Branch
             * @description The start's branch label (null: no closed form).
             */
            branch: string | null;
            /**
             * Waypoints
             * @description Points of the interpolated path (before densifying).
             */
            waypoints: number;
            /**
             * Iterations
             * @description Solver iterations over the whole path.
             */
            iterations: number;
            /** Solve Time Ms */
            solve_time_ms: number;
            /** Solver Version */
            solver_version: string;
            /** @description With the request's `timing`: times, velocities and accelerations of the points (null otherwise). */
            timing: components["schemas"]["TimingOut"] | null;
        };
        /**
         * PayloadIn
         * @description A rigid load fixed to a frame: its mass, centre of mass and rotational inertia.
         */
        PayloadIn: {
            /**
             * Mass
             * @description Mass (kg), within [0, 10⁶].
             */
            mass: number;
            /**
             * Frame
             * @description The frame the load is fixed to; default the robot's tip (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * Com
             * @description Its centre of mass (m) in the frame's axes, from the frame's origin.
             * @default [
             *       0,
             *       0,
             *       0
             *     ]
             */
            com?: number[];
            /**
             * Inertia
             * @description Rotational inertia about the centre of mass in the frame's axes, the six URDF entries [ixx, ixy, ixz, iyy, iyz, izz] (kg·m²); absent: a point mass. It must be one a rigid body has (positive semi-definite, triangle inequality).
             */
            inertia?: number[] | null;
        };
        /**
         * PayloadOut
         * @description The payload the answer includes (the request's, with its defaults filled in).
         */
        PayloadOut: {
            /**
             * Mass
             * @description kg.
             */
            mass: number;
            /** Frame */
            frame: string;
            /**
             * Com
             * @description m, in the frame's axes.
             */
            com: number[];
            /**
             * Inertia
             * @description [ixx, ixy, ixz, iyy, iyz, izz] about the centre of mass (kg·m²).
             */
            inertia: number[];
        };
        /**
         * Pose
         * @description A frame's placement in the robot's root (world) frame, the same shape in and out.
         *
         *     Answers fill all four fields. A request may give any subset that states what its
         *     endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
         *     ``orientation``: a rotation; reachability queries: a position, the rotation optional;
         *     obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
         *     request is a 422 naming them. An answer's pose can be sent back as is.
         */
        Pose: {
            /**
             * Position
             * @description [x, y, z] in metres. A position is given by `position` or `matrix`.
             */
            position?: number[];
            /**
             * Orientation
             * @description Quaternion [x, y, z, w] (answers: unit, w ≥ 0); normalised if |q| is within 1e-3 of 1; q and −q are the same rotation. A rotation is given by `orientation`, `rpy` or `matrix`.
             */
            orientation?: number[];
            /**
             * Rpy
             * @description [roll, pitch, yaw] in rad, R = Rz(yaw)·Ry(pitch)·Rx(roll).
             */
            rpy?: number[];
            /**
             * Matrix
             * @description 4×4 homogeneous transform root ← frame (metres): a rigid transform (orthonormal rotation within 1e-6, determinant +1, last row [0, 0, 0, 1]).
             */
            matrix?: number[][];
        };
        /**
         * Problem
         * @description RFC 9457 problem details, the body of every error response.
         */
        Problem: {
            /**
             * Type
             * @description URI identifying the problem type.
             */
            type: string;
            /**
             * Title
             * @description Short summary of the problem type.
             */
            title: string;
            /**
             * Status
             * @description HTTP status code.
             */
            status: number;
            /**
             * Detail
             * @description Explanation specific to this occurrence.
             */
            detail: string;
            /**
             * Instance
             * @description The request path.
             */
            instance?: string | null;
            /**
             * Field
             * @description The request field to blame, if any.
             */
            field?: string | null;
            /**
             * Suggestions
             * @description Close matches for an unknown name.
             */
            suggestions?: string[] | null;
            /**
             * Errors
             * @description All validation failures.
             */
            errors?: components["schemas"]["FieldError"][] | null;
        };
        /**
         * ProgressOut
         * @description How far a build is.
         */
        ProgressOut: {
            /** Percent */
            percent: number;
            /** Samples Done */
            samples_done: number;
            /** Samples Total */
            samples_total: number;
            /** Samples Per Second */
            samples_per_second: number | null;
            /** Elapsed Seconds */
            elapsed_seconds: number;
            /**
             * Eta Seconds
             * @description Seconds left at the current rate.
             */
            eta_seconds: number | null;
        };
        /**
         * QueryResponse
         * @description Entry i answers pose i.
         */
        QueryResponse: {
            /** Map Id */
            map_id: string;
            /** Reachable */
            reachable: boolean[];
            /**
             * Manipulability
             * @description Best Yoshikawa manipulability seen in the pose's cell; null if unreachable.
             */
            manipulability: (number | null)[];
            /**
             * In Bounds
             * @description Whether the position lies inside the map's box.
             */
            in_bounds: boolean[];
        };
        /** @enum {string} */
        ReachabilitySampling: "random" | "grid";
        /**
         * Ready
         * @description Readiness answer: every check passed.
         */
        Ready: {
            /**
             * Status
             * @description "ready".
             */
            status: string;
            /**
             * Checks
             * @description Check name → "ok" (data_dir, catalog).
             */
            checks: {
                [key: string]: string;
            };
        };
        /**
         * RobotDetail
         * @description Everything a client needs to talk about a robot.
         */
        RobotDetail: {
            /** Id */
            id: string;
            /** Name */
            name: string;
            /** Source */
            source: string;
            /** Description */
            description: string;
            /**
             * Joints
             * @description Actuated joints in configuration order.
             */
            joints: components["schemas"]["JointOut"][];
            /**
             * Mimic Joints
             * @description Mimic joints (URDF <mimic>): not in configurations, moved by their leader. A joint_positions or seed map may name them (a ROS JointState of the whole robot) when the value is multiplier × leader + offset within 1e-9 (the leader's value from the same map, else its default).
             */
            mimic_joints: components["schemas"]["MimicJointOut"][];
            /**
             * Frames
             * @description Every named frame (links and fixed frames).
             */
            frames: components["schemas"]["FrameOut"][];
            /**
             * End Effector
             * @description Default frame of fk, jacobian and ik (the default tip): the ee_frame given at upload (or the catalog's choice), else the parent_link of the SRDF's first end effector, else the tip of the longest serial chain that is not a gripper finger (a finger: a link moved by one of at least two sibling branches made only of prismatic and mimic joints; among links held by the same joint, a link without geometry such as a TCP or tool0 first, then the farthest), else the deepest link.
             */
            end_effector: string;
            /**
             * Groups
             * @description SRDF planning groups (`group` in requests).
             */
            groups: components["schemas"]["GroupOut"][];
            /**
             * End Effectors
             * @description SRDF end effectors.
             */
            end_effectors: components["schemas"]["EndEffectorOut"][];
            /**
             * Named States
             * @description SRDF group states (IK seeds).
             */
            named_states: components["schemas"]["NamedStateOut"][];
            /**
             * Neutral
             * @description Neutral configuration (0, clipped to limits).
             */
            neutral: number[];
            /**
             * Has Collision Geometry
             * @description Whether the URDF has <collision>.
             */
            has_collision_geometry: boolean;
            /**
             * Collision Pairs
             * @description Self-collision link pairs [a, b] that collision checks test (same-body, adjacent and SRDF-disabled pairs removed).
             */
            collision_pairs: string[][];
            /** @description How the URDF's mesh URIs map to GET /robots/{robot_id}/files/{path} (catalog and package robots; null for others). */
            files?: components["schemas"]["RobotFilesOut"] | null;
        };
        /**
         * RobotFilesOut
         * @description Where a viewer fetches the files (meshes, textures) a robot's URDF names.
         */
        RobotFilesOut: {
            /**
             * Uri Prefix
             * @description Mesh URIs of the URDF that start with this prefix are files served here.
             */
            uri_prefix: string;
            /**
             * Url
             * @description Replace uri_prefix by this URL path (GET /robots/{robot_id}/files/{path}).
             */
            url: string;
        };
        /**
         * RobotList
         * @description All robots the service knows.
         */
        RobotList: {
            /** Robots */
            robots: components["schemas"]["RobotSummaryOut"][];
        };
        /**
         * RobotSummaryOut
         * @description One robot in the list.
         */
        RobotSummaryOut: {
            /**
             * Id
             * @description Robot id, used in every /robots/{robot_id} URL.
             */
            id: string;
            /**
             * Name
             * @description Human-readable name.
             */
            name: string;
            /**
             * Source
             * @description example-robot-data | dh | upload | package.
             */
            source: string;
            /**
             * Joints
             * @description Number of actuated joints (length of a configuration).
             */
            joints: number;
            /**
             * Description
             * @description Short description.
             * @default
             */
            description?: string;
        };
        /**
         * SceneIn
         * @description A new scene.
         */
        SceneIn: {
            /**
             * Name
             * @description Scene name (1-64 of A-Z a-z 0-9 _ -).
             */
            name: string;
            /**
             * Description
             * @default
             */
            description?: string;
            /**
             * Obstacles
             * @description The obstacles.
             */
            obstacles: components["schemas"]["ObstacleIn"][];
        };
        /**
         * SceneList
         * @description Every stored scene.
         */
        SceneList: {
            /** Scenes */
            scenes: components["schemas"]["SceneSummary"][];
        };
        /**
         * SceneOut
         * @description A stored scene.
         */
        SceneOut: {
            /** Name */
            name: string;
            /** Description */
            description: string;
            /** Obstacles */
            obstacles: components["schemas"]["ObstacleOut"][];
        };
        /**
         * SceneSummary
         * @description A scene in the list.
         */
        SceneSummary: {
            /** Name */
            name: string;
            /** Description */
            description: string;
            /**
             * Obstacles
             * @description Number of obstacles.
             */
            obstacles: number;
        };
        /** @enum {string} */
        SelfCollisionMode: "ignore" | "mesh" | "convex";
        /**
         * StaticsRequest
         * @description Exactly one of wrench (→ torques) or torques (→ wrench); with `group`, the torques are
         *     those of the group's joints (in the group's order).
         */
        StaticsRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * @description Axes of the wrench (as for the Jacobian). world: force and moment about the frame origin, world axes | local: frame axes | world_spatial: moment about the world origin.
             * @default world
             */
            reference?: components["schemas"]["JacobianReference"];
            /**
             * Wrench
             * @description [fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its environment.
             */
            wrench?: number[] | null;
            /**
             * Torques
             * @description Joint torques/forces in joint order (N·m, N).
             */
            torques?: number[] | null;
        };
        /**
         * StaticsResponse
         * @description τ = Jᵀ·F, forward or least-squares inverse.
         */
        StaticsResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            reference: components["schemas"]["JacobianReference"];
            q: components["schemas"]["Configuration"];
            /**
             * Wrench
             * @description [fx, fy, fz, mx, my, mz] (N, N·m).
             */
            wrench: number[];
            /**
             * Torques
             * @description Jᵀ·F in joint order (N·m, N).
             */
            torques: number[];
            /** Joint Names */
            joint_names: string[];
            /**
             * Residual
             * @description Given torques − Jᵀ·F (zeros when the wrench was given).
             */
            residual: number[];
            /** Residual Norm */
            residual_norm: number;
            /**
             * Rank
             * @description Rank of the 6×n Jacobian (σ_i > 1e-10·σ_max).
             */
            rank: number;
        };
        /**
         * TimingIn
         * @description Time-optimal parameterization of the joint path: the fastest rest-to-rest motion along
         *     it within joint velocity and acceleration limits (TOPP-RA), verified on the output.
         */
        TimingIn: {
            /**
             * Velocity Limits
             * @description Joint velocity limits (rad/s or m/s, each within [1e-6, 1e9]): one per joint in joint order (with `group`: one per joint of the group), or joint → limit (the others keep theirs). Default: the robot description's (URDF `<limit velocity>`); a joint that moves and has none (missing, 0) is an error naming timing.velocity_limits.<joint>.
             */
            velocity_limits?: number[] | {
                [key: string]: number;
            } | null;
            /**
             * Acceleration Limits
             * @description Joint acceleration limits (rad/s² or m/s², each within [1e-6, 1e9]), as velocity_limits; joints not given: acceleration_fraction × their velocity limit. Not with acceleration_fraction.
             */
            acceleration_limits?: number[] | {
                [key: string]: number;
            } | null;
            /**
             * Acceleration Fraction
             * @description Acceleration limit of every joint as a fraction of its velocity limit, per second: f gives a_max = f · v_max / (1 s) (v_max before velocity_scale). Default 1 (URDF has no acceleration limits). Not with acceleration_limits.
             */
            acceleration_fraction?: number | null;
            /**
             * Velocity Scale
             * @description Every velocity limit multiplied by this, in (0, 1].
             * @default 1
             */
            velocity_scale?: number;
        };
        /**
         * TimingOut
         * @description Times, joint velocities and accelerations at the path's points (joint order). The
         *     limits hold at every point and at samples between them (``time_scale``).
         */
        TimingOut: {
            /**
             * T
             * @description Time of each point (s), 0 at the first.
             */
            t: number[];
            /**
             * Velocities
             * @description Joint velocities at each point (rad/s or m/s); 0 at both ends.
             */
            velocities: number[][];
            /**
             * Accelerations
             * @description Joint accelerations at each point (rad/s² or m/s²), just after it (at the last point: just before).
             */
            accelerations: number[][];
            /**
             * Duration
             * @description Time of the last point (s).
             */
            duration: number;
            /**
             * Velocity Limits
             * @description The velocity limit applied to each joint; null: the joint does not move.
             */
            velocity_limits: (number | null)[];
            /**
             * Acceleration Limits
             * @description The acceleration limit applied to each joint; null: the joint does not move.
             */
            acceleration_limits: (number | null)[];
            /**
             * Time Scale
             * @description How much the motion was slowed after TOPP-RA so that every verified sample keeps its limits (1.0: not at all).
             */
            time_scale: number;
        };
        /**
         * Tolerance
         * @description Success thresholds.
         */
        Tolerance: {
            /**
             * Position
             * @description Largest position error ‖p − p_t‖ (m).
             * @default 0.00001
             */
            position?: number;
            /**
             * Orientation
             * @description Largest rotation angle to the target (rad).
             * @default 0.00001
             */
            orientation?: number;
        };
        /** @enum {string} */
        TwistReference: "world" | "local";
        /** @enum {string} */
        VelocityDirection: "forward" | "inverse";
        /**
         * VelocityRequest
         * @description A configuration plus exactly one of ``joint_velocities`` (forward) or ``twist``.
         */
        VelocityRequest: {
            /** @description One value per actuated joint, in the order of GET /robots/{id} (rad for revolute and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is accepted too. */
            q?: components["schemas"]["Configuration"] | null;
            /** @description Joint name → value (rad or m); joints not given take their neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader + offset within 1e-9 (see mimic_joints of GET /robots/{id}). */
            joint_positions?: components["schemas"]["JointPositions"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             */
            group?: string | null;
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * @description Axes of the twist: world (origin velocity and angular velocity in world axes, Pinocchio LOCAL_WORLD_ALIGNED) | local (the frame's own axes, LOCAL).
             * @default world
             */
            reference?: components["schemas"]["TwistReference"];
            /**
             * Joint Velocities
             * @description Forward: q̇, one per joint in joint order (rad/s, m/s); with `group`, one per joint of the group is accepted too (the others at rest).
             */
            joint_velocities?: number[] | null;
            /**
             * Twist
             * @description Inverse: [vx, vy, vz, wx, wy, wz] (m/s, rad/s) to realise.
             */
            twist?: number[] | null;
            /**
             * @description Inverse only: task rows to match (position: vx, vy, vz only; orientation: wx, wy, wz only).
             * @default pose
             */
            mode?: components["schemas"]["IKMode"];
            /**
             * Singular Threshold
             * @description Inverse: σ_min below which damping starts.
             * @default 0.01
             */
            singular_threshold?: number;
            /**
             * Max Damping
             * @description Inverse: damping λ at an exact singularity.
             * @default 0.1
             */
            max_damping?: number;
        };
        /**
         * VelocityResponse
         * @description Both directions fill ``twist`` and ``joint_velocities``; inverse adds its diagnostics.
         */
        VelocityResponse: {
            /** Robot Id */
            robot_id: string;
            /** Frame */
            frame: string;
            reference: components["schemas"]["TwistReference"];
            direction: components["schemas"]["VelocityDirection"];
            q: components["schemas"]["Configuration"];
            /**
             * Joint Velocities
             * @description q̇ in joint order (rad/s, m/s).
             */
            joint_velocities: number[];
            /**
             * Twist
             * @description J·q̇ = [vx, vy, vz, wx, wy, wz] (m/s, rad/s).
             */
            twist: number[];
            /**
             * Residual
             * @description Inverse: ‖J q̇ − twist‖ on the task rows.
             */
            residual?: number | null;
            /**
             * Damping
             * @description Inverse: damping λ used (0: none).
             */
            damping?: number | null;
            /**
             * Sigma Min
             * @description Inverse: smallest singular value of the task Jacobian.
             */
            sigma_min?: number | null;
        };
        /**
         * WrenchIn
         * @description A wrench a frame exerts on its environment (as in statics: τ = Jᵀ·F).
         */
        WrenchIn: {
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             */
            frame?: string | null;
            /**
             * @description Axes of the wrench (as for the Jacobian). world: force and moment about the frame origin, world axes | local: frame axes | world_spatial: moment about the world origin.
             * @default world
             */
            reference?: components["schemas"]["JacobianReference"];
            /**
             * Values
             * @description [fx, fy, fz, mx, my, mz] (N, N·m): the wrench the frame exerts on its environment.
             */
            values: number[];
        };
        /**
         * ManipulabilityBatchRequest
         * @description Many configurations, one task.
         */
        ManipulabilityBatchRequest: {
            /**
             * Frame
             * @description Frame; default the end effector (with `group`: the group's tip).
             * @default null
             */
            frame?: string | null;
            /**
             * @description Task rows: full (vx vy vz wx wy wz, default) | translation (vx vy vz) | rotation (wx wy wz). Give either part or rows.
             * @default null
             */
            part?: components["schemas"]["JacobianPart"] | null;
            /**
             * Rows
             * @description Explicit task rows by name (vx, vy, vz, wx, wy, wz) or index 0–5, e.g. ["vx", "vy"] for a planar arm in the x-y plane. Give either part or rows.
             * @default null
             */
            rows?: (string | number)[] | null;
            /**
             * @description world (default): origin velocity and angular velocity in world axes (Pinocchio LOCAL_WORLD_ALIGNED; the textbook geometric Jacobian) | local: the same in the frame's own axes (LOCAL) | world_spatial: spatial velocity at the world origin (WORLD).
             * @default world
             */
            reference?: components["schemas"]["JacobianReference"];
            /**
             * Relative Tolerance
             * @description Relative rank tolerance: σ_i counts toward the rank when σ_i > relative_tolerance·σ_max.
             * @default 1e-10
             */
            relative_tolerance?: number;
            /**
             * Configurations
             * @description N configurations, each one value per joint in joint order (rad, m); with `group`, rows of the group's joints only are accepted too (others neutral).
             */
            configurations: number[][];
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             * @default null
             */
            group?: string | null;
        };
        /**
         * DynamicsBatchRequest
         * @description Many states (q, q̇, q̈), one optional payload.
         */
        DynamicsBatchRequest: {
            /**
             * Configurations
             * @description N configurations, each one value per joint in joint order (rad, m); with `group`, rows of the group's joints only are accepted too (others neutral).
             */
            configurations: number[][];
            /**
             * Velocities
             * @description N rows of joint velocities, as wide as `configurations`' rows; zeros when absent.
             * @default null
             */
            velocities?: number[][] | null;
            /**
             * Accelerations
             * @description N rows of joint accelerations, as wide as `configurations`' rows; zeros when absent.
             * @default null
             */
            accelerations?: number[][] | null;
            /**
             * @description A load fixed to a frame.
             * @default null
             */
            payload?: components["schemas"]["PayloadIn"] | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             * @default null
             */
            group?: string | null;
        };
        /**
         * FKBatchRequest
         * @description Many configurations, one frame.
         */
        FKBatchRequest: {
            /**
             * Configurations
             * @description N configurations, each one value per joint in joint order (rad, m); with `group`, rows of the group's joints only are accepted too (others neutral).
             */
            configurations: number[][];
            /**
             * Frame
             * @description Frame to place; default the end effector (or the group's tip).
             * @default null
             */
            frame?: string | null;
            /**
             * Group
             * @description A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group, the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
             * @default null
             */
            group?: string | null;
        };
        /**
         * PackageUpload
         * @description A robot as a description package: an archive with its description and meshes.
         *
         *     Sent as ``multipart/form-data``; every field but ``archive`` is a text part.
         */
        PackageUpload: {
            /**
             * Name
             * @description Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).
             */
            name: string;
            /**
             * Archive
             * Format: binary
             * @description The package: a zip or tar.gz archive (size and entry limits: DENAVIT_MAX_PACKAGE_BYTES, _FILES, _UNPACKED_BYTES).
             */
            archive: Blob;
            /**
             * Description
             * @description Path inside the archive of the robot description: .urdf, .xacro or MJCF .xml (e.g. panda_description/urdf/panda.urdf).
             */
            description: string;
            /**
             * Srdf
             * @description Path of an SRDF file; one ending .xacro (e.g. ur_moveit_config/srdf/ur.srdf.xacro) is expanded like a .xacro description, with the same packages.
             * @default null
             */
            srdf?: string | null;
            /**
             * Xacro Args
             * @description JSON object of xacro arguments: names to strings, numbers or booleans ({"arm_id": "panda"}); also those of a .xacro SRDF unless srdf_xacro_args is given.
             * @default null
             */
            xacro_args?: string | null;
            /**
             * Srdf Xacro Args
             * @description JSON object of the arguments of a .xacro SRDF, when they differ from xacro_args ({"name": "ur5e", "prefix": ""}); same rules as xacro_args.
             * @default null
             */
            srdf_xacro_args?: string | null;
            /**
             * Ee Frame
             * @description Default end-effector frame (default: the SRDF end effector's parent link, else the tip of the longest serial chain that is not a gripper finger).
             * @default null
             */
            ee_frame?: string | null;
            /**
             * Summary
             * @description Short description of the robot.
             * @default
             */
            summary?: string;
        };
        /**
         * QueryRequest
         * @description Poses to look up in a map: ``poses``, or the compact ``positions``/``orientations``.
         */
        QueryRequest: {
            /**
             * Map Id
             * @description The map to query.
             */
            map_id: string;
            /**
             * Poses
             * @description Poses (root frame): each needs a position (`position` or `matrix`); without a rotation (`orientation`, `rpy` or `matrix`), any orientation (best over the voxel).
             * @default null
             */
            poses?: components["schemas"]["Pose"][] | null;
            /**
             * Positions
             * @description Compact form: N×3 positions (m).
             * @default null
             */
            positions?: number[][] | null;
            /**
             * Orientations
             * @description Compact form: N×4 quaternions [x, y, z, w] (omit: any orientation).
             * @default null
             */
            orientations?: number[][] | null;
        };
        /**
         * UrdfUpload
         * @description A robot given as URDF text (and optionally SRDF).
         */
        UrdfUpload: {
            /**
             * Name
             * @description Robot id: 1-64 of a-z, 0-9, '_' and '-' (used in /robots/{robot_id}).
             */
            name: string;
            /**
             * Urdf
             * @description URDF document. No DTD or entities; mesh filenames must be package://<package>/<path> URIs; only revolute, continuous, prismatic and fixed joints.
             */
            urdf: string;
            /**
             * Srdf
             * @description SRDF document: disabled collision pairs, planning groups (chain, joints, links, subgroups), end effectors and group states, checked against the URDF.
             * @default null
             */
            srdf?: string | null;
            /**
             * Ee Frame
             * @description Default end-effector frame (default: the parent_link of the SRDF's first end effector, else the tip of the longest serial chain that is not a gripper finger; see end_effector in GET /robots/{robot_id}).
             * @default null
             */
            ee_frame?: string | null;
            /**
             * Description
             * @description Short description.
             * @default
             */
            description?: string;
        };
    };
    responses: never;
    parameters: never;
    requestBodies: never;
    headers: {
        /** @description The request's id: the client's `X-Request-ID` when it is 1–128 characters of `[A-Za-z0-9._:/+=@-]`, else 24 random hex digits. Also in every log line of the request. */
        "X-Request-ID": string;
        /** @description Always `nosniff`: browsers keep to the declared content type. */
        "X-Content-Type-Options": "nosniff";
        /** @description The methods the path supports, e.g. `GET, HEAD, DELETE`. */
        Allow: string;
        /** @description Seconds to wait before sending the request again: sent when the service is shutting down (the request was cut off), not when it is not started. */
        "Retry-After": number;
        /** @description `Bearer`: the scheme the write endpoints expect. */
        "WWW-Authenticate": string;
        /** @description The URL of what was created (the robot, or the reachability job). */
        Location: string;
        /** @description `websocket`: the protocol this endpoint speaks. */
        Upgrade: string;
        /** @description `default-src 'none'; sandbox`: a client-supplied document is never run as a page. */
        "Content-Security-Policy": string;
        /** @description `attachment; filename=...` for a file not shown inline. */
        "Content-Disposition": string;
        /** @description The byte range sent (`bytes 0-9/124`), or on 416 the file size (`bytes *\/124`). */
        "Content-Range": string;
        /** @description `bytes`: a `Range` request is served. */
        "Accept-Ranges": string;
        /** @description The file's version (from its size and modification time), for `If-Range`. */
        ETag: string;
        /** @description When the file was stored (HTTP date). */
        "Last-Modified": string;
    };
    pathItems: never;
}
export type $defs = Record<string, never>;
export interface operations {
    compute_fk: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["FKRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["FKResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_fk_batch: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["FKBatchRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["FKBatchResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_jacobian: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["JacobianRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["JacobianResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    solve_ik: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["IKRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["IKResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    solve_ik_batch: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["IKBatchRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["IKBatchResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_health: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["Health"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_ready: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["Ready"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Not ready: `checks` says which check failed and why. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    upload_robot_package: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody: {
            content: {
                "multipart/form-data": components["schemas"]["PackageUpload"];
            };
        };
        responses: {
            /** @description Successful Response */
            201: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Location: components["headers"]["Location"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["RobotDetail"];
                };
            };
            /** @description The body is not JSON (or YAML). */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A bearer token is required. */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Wrong token, or a built-in robot. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The robot id is taken. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The body exceeds DENAVIT_MAX_PACKAGE_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unsupported Content-Type. */
            415: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_robot_file: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
                path: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description The file (model/stl, model/vnd.collada+xml, model/obj, image/png, image/jpeg, application/xml, or application/octet-stream), as a download. */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Content-Security-Policy": components["headers"]["Content-Security-Policy"];
                    "Content-Disposition": components["headers"]["Content-Disposition"];
                    "Accept-Ranges": components["headers"]["Accept-Ranges"];
                    ETag: components["headers"]["ETag"];
                    "Last-Modified": components["headers"]["Last-Modified"];
                    [name: string]: unknown;
                };
                content: {
                    "application/octet-stream": Blob;
                };
            };
            /** @description The byte ranges asked for by `Range`, with the same headers. */
            206: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Content-Security-Policy": components["headers"]["Content-Security-Policy"];
                    "Content-Disposition": components["headers"]["Content-Disposition"];
                    "Accept-Ranges": components["headers"]["Accept-Ranges"];
                    ETag: components["headers"]["ETag"];
                    "Last-Modified": components["headers"]["Last-Modified"];
                    "Content-Range": components["headers"]["Content-Range"];
                    [name: string]: unknown;
                };
                content: {
                    "application/octet-stream": Blob;
                };
            };
            /** @description A malformed `Range` header. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Content-Security-Policy": components["headers"]["Content-Security-Policy"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, or no such file. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A `Range` outside the file. */
            416: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Content-Security-Policy": components["headers"]["Content-Security-Policy"];
                    "Content-Range": components["headers"]["Content-Range"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    import_dh_robot: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["DHTableDoc"];
                "application/yaml": components["schemas"]["DHTableDoc"];
            };
        };
        responses: {
            /** @description Successful Response */
            201: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Location: components["headers"]["Location"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["RobotDetail"];
                };
            };
            /** @description The body is not JSON (or YAML). */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A bearer token is required. */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Wrong token, or a built-in robot. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The robot id is taken. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The body exceeds DENAVIT_MAX_UPLOAD_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unsupported Content-Type. */
            415: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    upload_urdf_robot: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["UrdfUpload"];
            };
        };
        responses: {
            /** @description Successful Response */
            201: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Location: components["headers"]["Location"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["RobotDetail"];
                };
            };
            /** @description The body is not JSON (or YAML). */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A bearer token is required. */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Wrong token, or a built-in robot. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The robot id is taken. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The body exceeds DENAVIT_MAX_UPLOAD_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unsupported Content-Type. */
            415: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_robot: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["RobotDetail"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The path belongs to another resource that does not support this method (e.g. `GET /robots/package` is the path of another operation); `Allow` lists the methods it supports. */
            405: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Allow: components["headers"]["Allow"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    delete_robot: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            204: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content?: never;
            };
            /** @description A bearer token is required. */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Wrong token, or a built-in robot. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The path belongs to another resource that does not support this method (e.g. `DELETE /robots/package` is the path of another operation); `Allow` lists the methods it supports. */
            405: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Allow: components["headers"]["Allow"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    list_robots: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["RobotList"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_robot_urdf: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description URDF, as a download (`<robot_id>.urdf`). */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Content-Security-Policy": components["headers"]["Content-Security-Policy"];
                    "Content-Disposition": components["headers"]["Content-Disposition"];
                    [name: string]: unknown;
                };
                content: {
                    "application/xml": string;
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_robot_dh: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    /** @description `default-src 'none'; sandbox`: a client-supplied document is never run as a page. */
                    "Content-Security-Policy"?: string;
                    "Content-Disposition": components["headers"]["Content-Disposition"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["DHTableDoc"];
                    "application/yaml": components["schemas"]["DHTableDoc"];
                };
            };
            /** @description Unknown robot, or not a DH robot. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_manipulability: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["ManipulabilityRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["ManipulabilityResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_manipulability_batch: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["ManipulabilityBatchRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["ManipulabilityBatchResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_statics: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["StaticsRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["StaticsResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_dynamics: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["DynamicsRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["DynamicsResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_dynamics_batch: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["DynamicsBatchRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["DynamicsBatchResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_max_payload: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["MaxPayloadRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["MaxPayloadResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    build_reachability_map: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["BuildRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            202: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Location: components["headers"]["Location"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["JobResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set). */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The bearer token is not valid, or the resource may not be changed. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Too many builds queued or running. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    list_reachability_jobs: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["JobList"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_reachability_job: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
                /** @description Build job id. */
                job_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["JobResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    cancel_reachability_job: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
                /** @description Build job id. */
                job_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["JobResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set). */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The bearer token is not valid, or the resource may not be changed. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The job has already finished. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    list_reachability_maps: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["MapList"];
                };
            };
            /** @description Unknown robot, frame, joint or other named resource. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_reachability_map: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
                /** @description Map id, as listed by …/reachability/maps. */
                map_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["MapInfo"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    delete_reachability_map: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
                /** @description Map id, as listed by …/reachability/maps. */
                map_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            204: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content?: never;
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set). */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The bearer token is not valid, or the resource may not be changed. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    query_reachability: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["QueryRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["QueryResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The map belongs to an older robot model. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_reachability_slice: {
        parameters: {
            query?: {
                /** @description Slice at this x (m). */
                x?: number | null;
                /** @description Slice at this y (m). */
                y?: number | null;
                /** @description Slice at this z (m). */
                z?: number | null;
                /** @description Pixels per voxel (default: ~512 px). */
                scale?: number | null;
            };
            header?: never;
            path: {
                /** @description Map id, as listed by …/reachability/maps. */
                map_id: string;
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description The heat map (PNG). */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "image/png": Blob;
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    check_collisions: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["CollisionRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["CollisionResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    check_collisions_batch: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["CollisionBatchRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["CollisionBatchResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_collision_pairs: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["CollisionPairsResponse"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    list_scenes: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["SceneList"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    create_scene: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["SceneIn"];
            };
        };
        responses: {
            /** @description Successful Response */
            201: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["SceneOut"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set). */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The bearer token is not valid, or the resource may not be changed. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A scene with this name exists. */
            409: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_scene: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Scene name (letters, digits, '_', '-'). */
                name: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["SceneOut"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    delete_scene: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Scene name (letters, digits, '_', '-'). */
                name: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Successful Response */
            204: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content?: never;
            };
            /** @description A write endpoint without `Authorization: Bearer <token>` (DENAVIT_API_TOKEN set). */
            401: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "WWW-Authenticate": components["headers"]["WWW-Authenticate"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The bearer token is not valid, or the resource may not be changed. */
            403: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    solve_ik_path: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["PathRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["PathResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    compute_velocity: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                /** @description Robot id, as listed by GET /robots. */
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody: {
            content: {
                "application/json": components["schemas"]["VelocityRequest"];
            };
        };
        responses: {
            /** @description Successful Response */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/json": components["schemas"]["VelocityResponse"];
                };
            };
            /** @description Malformed request body. */
            400: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description Unknown robot, frame or joint. */
            404: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES. */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A field failed validation; `field` names it. */
            422: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_metrics: {
        parameters: {
            query?: never;
            header?: never;
            path?: never;
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Prometheus text format 0.0.4: request counts and latency histograms per route template, requests in flight, IK outcomes, and per worker (`pid` label) resident memory, CPU time and start time. Every scrape reports the whole service, whichever worker answers it: counters are summed over all the worker processes of the service, including workers that have exited (a replaced worker's counts stay), so they never go down while the service runs; a restart of the service starts them from zero. `denavit_http_requests_in_flight` sums the live workers; `denavit_worker_processes{state}` counts the live and exited workers summed; `denavit_process_info{pid}` names the answering worker. A request is counted before the last byte of its response is sent. */
            200: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "text/plain; version=0.0.4; charset=utf-8": string;
                };
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
    get_robot_stream: {
        parameters: {
            query?: never;
            header?: never;
            path: {
                robot_id: string;
            };
            cookie?: never;
        };
        requestBody?: never;
        responses: {
            /** @description Switching Protocols: the WebSocket is open. */
            101: {
                headers: {
                    [name: string]: unknown;
                };
                content?: never;
            };
            /** @description The request body exceeds DENAVIT_MAX_BODY_BYTES (whatever the method). */
            413: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description A plain HTTP request: this endpoint needs the WebSocket upgrade. */
            426: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    Upgrade: components["headers"]["Upgrade"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
            /** @description The service cannot serve this now: not started, storage unavailable, or shutting down (the request was cut off by the graceful-shutdown timeout; `Retry-After`). Send it again later. */
            503: {
                headers: {
                    "X-Request-ID": components["headers"]["X-Request-ID"];
                    "X-Content-Type-Options": components["headers"]["X-Content-Type-Options"];
                    "Retry-After": components["headers"]["Retry-After"];
                    [name: string]: unknown;
                };
                content: {
                    "application/problem+json": components["schemas"]["Problem"];
                };
            };
        };
    };
}
