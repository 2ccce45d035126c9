#!/usr/bin/env python3
"""tests/fuzz/reseal_gab.py restores what the encoder wrote: every golden
seed (tests/fuzz/corpus/gab) with all its checksums zeroed is refused by
`gab info` and, resealed, is byte for byte the seed again, which `gab info`
accepts. Usage: reseal_test.py GAB CORPUS_DIR
"""
import os
import struct
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz"))
from reseal_gab import checksum_offsets, reseal  # noqa: E402


def info_ok(gab, path):
    return subprocess.run([gab, "info", path], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE).returncode == 0


def main():
    gab, corpus = sys.argv[1], sys.argv[2]
    failures = checked = 0
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "f.gab")
        for name in sorted(os.listdir(corpus)):
            with open(os.path.join(corpus, name), "rb") as f:
                seed = f.read()[1:]  # the fuzzer's options byte
            offsets = checksum_offsets(seed)
            zeroed = bytearray(seed)
            for crc_at, _, _ in offsets:
                struct.pack_into("<I", zeroed, crc_at, 0)
            with open(path, "wb") as f:
                f.write(zeroed)
            refused = not info_ok(gab, path)
            restored = reseal(bytes(zeroed))
            with open(path, "wb") as f:
                f.write(restored)
            problems = []
            if len(offsets) < 3:
                problems.append("found %d checksums (a header, a connectivity block and a chunk at least)"
                                % len(offsets))
            if not refused:
                problems.append("gab info accepts the file with its checksums zeroed")
            if restored != seed:
                problems.append("resealed bytes differ from the seed")
            if not info_ok(gab, path):
                problems.append("gab info refuses the resealed file")
            for problem in problems:
                print("%s: %s" % (name, problem))
            failures += bool(problems)
            checked += 1
    print("reseal_test: %d seeds, %d failed" % (checked, failures))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
