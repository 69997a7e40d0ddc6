"""Cartesian paths: the tool along lines and arcs, one joint configuration per point.

The package, one concept per module:

- :mod:`.segments`: the Cartesian path itself (lines, arcs, explicit waypoints), its
  interpolation at ``max_step`` (position linear, orientation by slerp) and the pose at any
  path parameter;
- :mod:`.follow`: IK at each point seeded by the previous solution, step halving,
  densification to the deviation bound, the points reached;
- :mod:`.local`: the warm-started local solve of the next point (one compiled attempt from
  the previous point) and its independent verification;
- :mod:`.point_kernel`: that attempt and its checks (a forward kinematics of its own,
  limits, pose error, joint step, branch flags, the deviation at the middle) as one
  compiled call per point; :mod:`.walk_kernel`: runs of waypoints of one segment in one
  compiled call (no collision predicate), handing back the first that is not plain;
  :mod:`.pose_kernel`: a segment's pose in compiled code;
- :mod:`.failures`: the joint-step, branch and collision guards inside the solver, and the
  typed failure (``reason``, ``detail``) of the first point that cannot be reached;
- :mod:`.timing`: time-optimal parameterization of the joint path (toppra) under velocity
  and acceleration limits, verified on the output;
- :mod:`.limits`: those limits, from the robot's description or per joint.
"""
