from enum import StrEnum


class BuildRequestSampling(StrEnum):
    GRID = "grid"
    RANDOM = "random"

    def __str__(self) -> str:
        return str(self.value)
