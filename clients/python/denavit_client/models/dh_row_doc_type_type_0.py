from enum import StrEnum


class DHRowDocTypeType0(StrEnum):
    CONTINUOUS = "continuous"
    PRISMATIC = "prismatic"
    REVOLUTE = "revolute"

    def __str__(self) -> str:
        return str(self.value)
