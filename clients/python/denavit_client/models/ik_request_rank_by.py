from enum import StrEnum


class IKRequestRankBy(StrEnum):
    CLEARANCE = "clearance"
    MANIPULABILITY = "manipulability"
    SEED_DISTANCE = "seed_distance"

    def __str__(self) -> str:
        return str(self.value)
