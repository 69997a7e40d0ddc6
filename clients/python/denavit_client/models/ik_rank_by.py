from enum import StrEnum


class IKRankBy(StrEnum):
    CLEARANCE = "clearance"
    MANIPULABILITY = "manipulability"
    SEED_DISTANCE = "seed_distance"

    def __str__(self) -> str:
        return str(self.value)
