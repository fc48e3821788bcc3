"""Schemathesis hooks for tests/schemathesis/run.sh.

Generated path parameters almost never name a world, region or job that exists, so without
these hooks every world route would answer 404 before its handler ran. run.sh creates a world
(with an authored region and an uploaded image) and an export job and passes their ids in the
environment; here each generated `id`, `rid`, `job` and image `hash` is replaced by the existing
one half of the time, so both the handlers and the 404 answers are exercised. Glb uploads (`model/gltf-binary`) are sent as the
raw bytes generated for them, as `application/octet-stream` bodies are.
"""

import os

import schemathesis
from hypothesis import strategies as st

EXISTING = {
    "id": os.environ.get("STRATA_WORLD_ID"),
    "rid": os.environ.get("STRATA_REGION_ID"),
    "job": os.environ.get("STRATA_JOB_ID"),
    "hash": os.environ.get("STRATA_IMAGE_HASH"),
}


schemathesis.serializer.alias("model/gltf-binary", "application/octet-stream")


@schemathesis.hook
def flatmap_path_parameters(context, path_parameters):
    if not path_parameters:
        return st.just(path_parameters)
    choices = []
    for name, existing in EXISTING.items():
        if existing and name in path_parameters:
            choices.append(name)
    if not choices:
        return st.just(path_parameters)

    def with_existing(flags):
        out = dict(path_parameters)
        for name, use in zip(choices, flags):
            if use:
                out[name] = EXISTING[name]
        return out

    return st.tuples(*(st.booleans() for _ in choices)).map(with_existing)
