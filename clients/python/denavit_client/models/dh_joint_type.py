from enum import StrEnum


class DHJointType(StrEnum):
    CONTINUOUS = "continuous"
    PRISMATIC = "prismatic"
    REVOLUTE = "revolute"

    def __str__(self) -> str:
        return str(self.value)
