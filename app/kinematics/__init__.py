"""The Pinocchio core: models, forward kinematics, Jacobians, IK, analysis, collisions.

Usable from Python without the web layer::

    from app.robots.registry import Registry
    robot = Registry().get("panda")
    from app.kinematics.fk import forward_kinematics
    poses = forward_kinematics(robot, robot.neutral(), ["panda_hand_tcp"])
"""
