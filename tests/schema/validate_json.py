#!/usr/bin/env python3
"""Every example's `derive --format json` and `solve --format json` validates against the
derivation schema (src/report/derivation.schema.json).
Usage: validate_json.py TACKLE SCHEMA EXAMPLES_DIR"""
import json
import pathlib
import subprocess
import sys

import jsonschema

tackle, schema_path, examples = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
schema = json.loads(pathlib.Path(schema_path).read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failures = 0
files = sorted(examples.glob("*.yaml"))
for f in files:
    for command in ("derive", "solve"):
        out = subprocess.run([tackle, command, str(f), "--format", "json"], capture_output=True, text=True)
        if out.returncode != 0:
            print(f"{f.name}: {command} exited {out.returncode}: {out.stderr.strip()}")
            failures += 1
            continue
        for error in validator.iter_errors(json.loads(out.stdout)):
            print(f"{f.name} ({command}): {'/'.join(map(str, error.absolute_path))}: {error.message}")
            failures += 1
print(f"{len(files)} examples, {failures} problems")
sys.exit(1 if failures else 0)
