from enum import StrEnum


class VelocityResponseDirection(StrEnum):
    FORWARD = "forward"
    INVERSE = "inverse"

    def __str__(self) -> str:
        return str(self.value)
