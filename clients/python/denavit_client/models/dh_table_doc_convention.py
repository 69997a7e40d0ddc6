from enum import StrEnum


class DHTableDocConvention(StrEnum):
    MODIFIED = "modified"
    STANDARD = "standard"

    def __str__(self) -> str:
        return str(self.value)
