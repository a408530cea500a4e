# SPDX-License-Identifier: Apache-2.0
"""Validates JSON files against a JSON Schema (draft 2020-12) with Debian's python3-jsonschema:
an independent check of what our programs print. Usage: validate_json.py SCHEMA FILE...
Prints one line per invalid file and exits 1 if any is."""
import json
import sys

import jsonschema

schema = json.load(open(sys.argv[1]))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failed = 0
for path in sys.argv[2:]:
    for error in validator.iter_errors(json.load(open(path))):
        print(f"{path}: {'/'.join(map(str, error.absolute_path))}: {error.message}")
        failed = 1
sys.exit(failed)
