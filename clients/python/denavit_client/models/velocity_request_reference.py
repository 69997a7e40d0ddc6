from enum import StrEnum


class VelocityRequestReference(StrEnum):
    LOCAL = "local"
    WORLD = "world"

    def __str__(self) -> str:
        return str(self.value)
