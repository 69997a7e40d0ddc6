from enum import StrEnum


class IKResponseReasonType0(StrEnum):
    COLLISION = "collision"
    JOINT_LIMITS = "joint_limits"
    SINGULAR = "singular"
    TIMEOUT = "timeout"
    UNREACHABLE = "unreachable"

    def __str__(self) -> str:
        return str(self.value)
