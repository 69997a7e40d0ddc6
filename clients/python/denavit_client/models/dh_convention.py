from enum import StrEnum


class DHConvention(StrEnum):
    MODIFIED = "modified"
    STANDARD = "standard"

    def __str__(self) -> str:
        return str(self.value)
