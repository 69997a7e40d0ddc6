from enum import StrEnum


class IKMode(StrEnum):
    ORIENTATION = "orientation"
    POSE = "pose"
    POSITION = "position"

    def __str__(self) -> str:
        return str(self.value)
