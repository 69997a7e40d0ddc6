"""The HTTP layer: routes (:mod:`app.api.routes`, routes only, one module per area), wire
models (:mod:`app.api.schemas`, one module per area) and the plumbing they share beside
them:

- ``state``: what the app holds while it serves (stores, build jobs, work pools), made and
  closed by the lifespan; ``deps``: the typed dependencies routes take (``RobotDep``,
  ``SettingsDep``, ``RegistryDep``, the store deps);
- ``limits``: the server's caps on one request (batch sizes, IK budgets);
- ``body``: body decoding (fast paths for big batches); ``errors``: RFC 9457 problem
  details; ``responses``: the JSON response; ``security``: the write token;
- ``offload``: running work in the app's pools, cancelled when its client leaves;
- ``answers`` (FK, Jacobian), ``ik_answers`` (every IK answer), ``robot_answers`` (a
  robot's description, the 201 of a write): the wire bodies, shared by HTTP and the stream;
- ``ik_request`` (an IK request body to the core's options), ``ik_plan`` (one IK query:
  inline or pooled), ``obstacles`` (a request's ``obstacles`` or ``scene``);
- ``images``, ``static_files``, ``untrusted``: PNG slices, the docs' assets, served
  client files.
"""
