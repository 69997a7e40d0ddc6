from enum import StrEnum


class PathFailureReason(StrEnum):
    BRANCH = "branch"
    COLLISION = "collision"
    JOINT_LIMITS = "joint_limits"
    JOINT_STEP = "joint_step"
    SINGULAR = "singular"
    TIMEOUT = "timeout"
    UNREACHABLE = "unreachable"

    def __str__(self) -> str:
        return str(self.value)
