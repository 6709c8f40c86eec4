#!/usr/bin/env python3
"""Checks every file of this package against manifest.json: its size and CRC-32 (zlib's, the
IEEE 802.3 polynomial). Exit 0 when all match; 2 naming each file that is missing or changed.
run_icarus.sh and run_verilator.sh run it first."""
import json
import os
import sys
import zlib

here = os.path.dirname(os.path.abspath(__file__))
manifest = json.load(open(os.path.join(here, "manifest.json")))
problems = []
for entry in manifest["files"]:
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
