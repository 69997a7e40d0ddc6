from enum import StrEnum


class VelocityDirection(StrEnum):
    FORWARD = "forward"
    INVERSE = "inverse"

    def __str__(self) -> str:
        return str(self.value)
