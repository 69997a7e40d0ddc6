"""Record the OpenAPI examples: run the scenario of tests/openapi_examples.py against fresh
in-process apps and write app/api/examples/exchanges.json (``make examples``).

Run it after changing a request or response model, then ``make openapi``;
tests/test_openapi_examples.py names every example whose answer no longer matches.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.openapi_examples import EXAMPLES, STATIC_EXAMPLES, run  # noqa: E402
from tests.openapi_scenario import EXCHANGES  # noqa: E402

HEADER = (
    "Recorded by scripts/record_examples.py (make examples) from the scenario in "
    "tests/openapi_examples.py; put into the OpenAPI document by "
    "app/middleware/openapi_examples.py. Do not edit by hand."
)


def main() -> None:
    exchanges = []
    for spec, answer in run(EXCHANGES):
        content = answer.pop("_content", None)
        if content is not None:  # binary: a file the document links to
            name = spec["name"] + "." + answer["content_type"].rsplit("/", 1)[-1]
            STATIC_EXAMPLES.mkdir(parents=True, exist_ok=True)
            (STATIC_EXAMPLES / name).write_bytes(content)
            answer["static"] = f"/static/examples/{name}"
        exchanges.append({"request": spec, "response": answer})
    text = json.dumps({"about": HEADER, "exchanges": exchanges}, indent=1, ensure_ascii=False)
    EXAMPLES.write_text(text + "\n")
    print(f"{EXAMPLES}: {len(exchanges)} exchanges")


if __name__ == "__main__":
    main()
