from enum import StrEnum


class DHUnitsDocAngle(StrEnum):
    DEG = "deg"
    RAD = "rad"

    def __str__(self) -> str:
        return str(self.value)
