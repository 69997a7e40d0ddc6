from enum import StrEnum


class IKReason(StrEnum):
    COLLISION = "collision"
    JOINT_LIMITS = "joint_limits"
    SINGULAR = "singular"
    TIMEOUT = "timeout"
    UNREACHABLE = "unreachable"

    def __str__(self) -> str:
        return str(self.value)
