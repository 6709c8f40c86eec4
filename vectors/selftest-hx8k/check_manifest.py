#!/usr/bin/env python3
"""Checks every file of this package against manifest.json: its size and CRC-32 (zlib's, the
IEEE 802.3 polynomial), and the manifest itself against its manifest_crc32 (the CRC-32 of its text
with that value written as 0x00000000). Exit 0 when all match; 2 naming each file that is missing
or changed. The package's run scripts run it first."""
import json
import os
import re
import sys
import zlib

here = os.path.dirname(os.path.abspath(__file__))
problems = []
text = open(os.path.join(here, "manifest.json"), "rb").read()
try:
    manifest = json.loads(text)
except ValueError as error:
    print(f"check_manifest: manifest.json: not JSON ({error}): changed since the package was made", file=sys.stderr)
    sys.exit(2)
# The manifest's shape: a "files" list of {path, bytes, crc32}, each path a file of this package
# (relative, no ".." step), so that a damaged manifest is reported, not a traceback.
def entry_problem(entry):
    if not isinstance(entry, dict) or not isinstance(entry.get("path"), str) or \
            not isinstance(entry.get("bytes"), int) or not isinstance(entry.get("crc32"), str):
        return f"manifest.json: an entry of files is not {{path, bytes, crc32}}: {json.dumps(entry)[:80]}"
    parts = entry["path"].replace("\\", "/").split("/")
    if os.path.isabs(entry["path"]) or ".." in parts or entry["path"] == "":
        return f"manifest.json: {entry['path']!r} is not a path inside the package"
    return None


if not isinstance(manifest, dict) or not isinstance(manifest.get("files"), list):
    print("check_manifest: manifest.json: no \"files\" list: changed since the package was made", file=sys.stderr)
    sys.exit(2)
own = manifest.get("manifest_crc32", "")
unsigned = re.sub(rb'"manifest_crc32": "0x[0-9a-f]{8}"', b'"manifest_crc32": "0x00000000"', text)
if f"0x{zlib.crc32(unsigned):08x}" != own:
    problems.append(f"manifest.json: CRC-32 0x{zlib.crc32(unsigned):08x} of its text; its manifest_crc32 says {own} "
                    "(changed since the package was made)")
for entry in manifest["files"]:
    problem = entry_problem(entry)
    if problem:
        problems.append(problem)
        continue
    path = os.path.join(here, entry["path"])
    if not os.path.isfile(path):
        problems.append(f"{entry['path']}: missing")
        continue
    data = open(path, "rb").read()
    crc = f"0x{zlib.crc32(data):08x}"
    if len(data) != entry["bytes"] or crc != entry["crc32"]:
        problems.append(f"{entry['path']}: {len(data)} bytes, CRC-32 {crc}; the manifest says {entry['bytes']} bytes, "
                        f"CRC-32 {entry['crc32']} (changed since the package was made)")
for p in problems:
    print(f"check_manifest: {p}", file=sys.stderr)
if problems:
    sys.exit(2)
print(f"check_manifest: {len(manifest['files'])} files match manifest.json")
