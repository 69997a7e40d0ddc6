from enum import StrEnum


class TwistReference(StrEnum):
    LOCAL = "local"
    WORLD = "world"

    def __str__(self) -> str:
        return str(self.value)
