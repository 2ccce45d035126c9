#!/usr/bin/env python3
"""Cuts the connectivity fuzzer's seeds (tests/fuzz/corpus/connectivity) out
of the .gab seeds: each is the input connectivity_fuzzer.cpp reads (flags,
counts, valence block length, the blocks). Run from the repository root:
    python3 tests/fuzz/make_connectivity_seeds.py
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
GAB = os.path.join(HERE, "corpus", "gab")
OUT = os.path.join(HERE, "corpus", "connectivity")


def varint(data, at):
    value, shift = 0, 0
    while True:
        byte = data[at]
        value |= (byte & 0x7F) << shift
        at, shift = at + 1, shift + 7
        if not byte & 0x80:
            return value, at


def header(data):
    """n, t and the offset just past the header (gab_format.h)."""
    n, at = varint(data, 14)
    t, at = varint(data, at)
    at += 40  # weight, box_min, step
    for _ in range(3):  # anchors, chunks, sections
        _, at = varint(data, at)
    return n, t, at + 4  # the header's CRC-32


def frame(data, at):
    length = struct.unpack_from("<I", data, at)[0]
    return data[at + 8:at + 8 + length], at + 8 + length


os.makedirs(OUT, exist_ok=True)
seen = set()
for name in sorted(os.listdir(GAB)):
    data = open(os.path.join(GAB, name), "rb").read()[1:]  # the options byte
    flags = data[9]
    if flags & 1:
        continue  # geometry only: a hash, no blocks
    n, t, at = header(data)
    valence, at = frame(data, at)
    order = b""
    if not flags & 8:
        order, at = frame(data, at)
    bits = 1 if flags & 8 else 0
    seed = struct.pack("<BHHH", bits, n - 1, t, len(valence)) + valence + order
    if seed in seen:
        continue  # the same torus's triangles, cut from another seed
    seen.add(seed)
    open(os.path.join(OUT, name), "wb").write(seed)
    print(name, len(seed), "bytes")
