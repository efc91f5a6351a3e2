"""Sample submissions for wall_follow_lab.toml: variants of examples/programs/wall_follow.c as
students hand them in — correct, too slow, not compiling, crashing, hanging, driving into walls,
or with the file misnamed.

    python3 lab_submissions.py DIR [--count N]

writes DIR/<student>/wall_follow.c; with --count, N students cycling through the variants
(for benchmarks), else one student per variant, named after it."""

from __future__ import annotations

import argparse
from pathlib import Path

MODEL = Path(__file__).resolve().parents[1] / "programs" / "wall_follow.c"

# variant -> (file name, [(text in the model solution, its replacement)])
VARIANTS = {
    "good": ("wall_follow.c", []),
    "slow": ("wall_follow.c", [("#define SPEED 200", "#define SPEED 80")]),
    "compile_error": (
        "wall_follow.c",
        [("int start = OSGetCount(), last_error = 0;", "int start = OSGetCount(), last_error = 0")],
    ),
    "crash": (
        "wall_follow.c",
        [
            (
                "        OSWait(PERIOD);",
                "        OSWait(PERIOD);\n"
                "        if (OSGetCount() - start > 5000)\n"
                "            *(volatile int *)0 = 1; /* a stray pointer */",
            )
        ],
    ),
    "hang": (
        "wall_follow.c",
        [
            (
                "        OSWait(PERIOD);",
                "        OSWait(PERIOD);\n"
                "        if (OSGetCount() - start > 3000)\n"
                "            for (volatile int spin = 0;; spin++)\n"
                "                ; /* computes for ever without a RoBIOS call */",
            )
        ],
    ),
    "bumper": ("wall_follow.c", [("if (front < DISTANCE + 60)", "if (0)")]),
    "misnamed": ("wallfollow.c", []),
}


def make_variant(variant: str) -> tuple[str, str]:
    name, edits = VARIANTS[variant]
    text = MODEL.read_text()
    for old, new in edits:
        assert old in text, f"{variant}: {old!r} is no longer in {MODEL}"
        text = text.replace(old, new)
    return name, text


def write_submissions(directory: Path, count: int | None = None) -> dict[str, str]:
    """Write the submissions; returns student -> variant."""
    names = list(VARIANTS)
    students = (
        {f"student{n + 1:02d}": names[n % len(names)] for n in range(count)}
        if count
        else {variant: variant for variant in names}
    )
    for student, variant in students.items():
        file, text = make_variant(variant)
        folder = directory / student
        folder.mkdir(parents=True, exist_ok=True)
        (folder / file).write_text(text)
    return students


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", type=Path)
    parser.add_argument("--count", type=int)
    arguments = parser.parse_args()
    made = write_submissions(arguments.directory, arguments.count)
    print(f"{len(made)} submission(s) in {arguments.directory}")
