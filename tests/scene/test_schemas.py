"""The published JSON Schemas: valid, exported to docs/ (`make schemas`), and matching what we write."""

import jsonschema
import pytest

from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import KINDS, schema, schema_text, to_json
from eyesim.scene.loader import read_document
from scene_testing import CORPUS, REPO_ROOT, manifest


@pytest.mark.parametrize("kind", KINDS)
def test_schema_is_valid_draft_2020_12(kind):
    jsonschema.Draft202012Validator.check_schema(schema(kind))


@pytest.mark.parametrize("kind", KINDS)
def test_docs_copy_is_not_stale(kind):
    published = (REPO_ROOT / "docs" / "schemas" / f"{kind}.schema.json").read_text(encoding="utf-8")
    assert published == schema_text(kind), "docs/schemas is stale: run `make schemas`"


def test_what_we_write_validates():
    for relative, _ in manifest()[::3]:
        kind, document = read_document(CORPUS / relative, Diagnostics())
        jsonschema.validate(to_json(kind, document), schema(kind))


def test_no_additional_properties_anywhere():
    def walk(node):
        if isinstance(node, dict):
            if node.get("type") == "object" and "properties" in node:
                assert node.get("additionalProperties") is False
            for value in node.values():
                walk(value)
        elif isinstance(node, list):
            for value in node:
                walk(value)

    for kind in KINDS:
        walk(schema(kind))
