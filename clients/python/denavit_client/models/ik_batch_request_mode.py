from enum import StrEnum


class IKBatchRequestMode(StrEnum):
    ORIENTATION = "orientation"
    POSE = "pose"
    POSITION = "position"

    def __str__(self) -> str:
        return str(self.value)
