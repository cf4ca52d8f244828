#!/usr/bin/env python3
"""Rewrites a single-grid checkpoint (format 3) in place into the legacy layout of earlier
versions: 3 ghosts a side instead of today's (read from the state's size), the checksum
recomputed. Today's reader widens such a state again (simulation.cpp, widen_legacy_ghosts).

Usage: legacy_checkpoint.py CHECKPOINT  (used by tests/reference/same_outputs.sh)
"""
import os
import re
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz"))
from readers_fuzz import Layout, fnv1a  # noqa: E402

N_VARS = 9  # src/core/registry.hpp
LEGACY_GHOSTS = 3

path = sys.argv[1]
data = open(path, "rb").read()
layout = Layout(data)
fields = {name: (off, size) for off, size, _, name in layout.fields}
off, size = fields["config"]
n = int(re.search(r"^N = (\d+)$", data[off:off + size].decode(), re.M).group(1))
if fields["finer count"] and struct.unpack_from("<Q", data, fields["finer count"][0])[0]:
    sys.exit("legacy_checkpoint.py: single-grid checkpoints only")
off, size = fields["u values"]
values = struct.unpack_from(f"<{size // 8}d", data, off)
total = len(values) // N_VARS
ghosts = (total - n) // 2
if N_VARS * (n + 2 * ghosts) != len(values) or ghosts < LEGACY_GHOSTS:
    sys.exit(f"legacy_checkpoint.py: {len(values)} values are not {N_VARS} x ({n} + 2 ghosts)")
legacy = []
for v in range(N_VARS):
    block = values[v * total:(v + 1) * total]
    legacy.extend(block[ghosts - LEGACY_GHOSTS:ghosts + n + LEGACY_GHOSTS])
count_off = fields["u count"][0]
body = bytearray(data[:-8])
new_values = struct.pack(f"<{len(legacy)}d", *legacy)
body[off:off + size] = new_values
struct.pack_into("<Q", body, count_off, len(legacy))
body += struct.pack("<Q", fnv1a(body))
open(path, "wb").write(bytes(body))
print(f"legacy_checkpoint.py: {path}: {ghosts} -> {LEGACY_GHOSTS} ghosts a side")
