#!/usr/bin/env python3
"""Rewrites the checksums of a .gab file so an ordinary build reads it as a
fuzzing build configured with GAB_FUZZ_SKIP_CHECKSUMS does (that build accepts
any stored CRC-32). Use it to replay what such a fuzzer found:

    tests/fuzz/reseal_gab.py [--options-byte] IN OUT

--options-byte drops the leading byte the gab and capi fuzzers read as their
options. The header's CRC is rewritten when the header parses as far as its
CRC; then (past a geometry-only file's connectivity hash) every whole frame
(u32 length, u32 CRC-32, payload) gets its CRC rewritten, up to the first
frame the file ends inside. Bytes are otherwise unchanged: the structure the
decoder sees is the fuzzer's.
"""
import struct
import sys
import zlib

MAGIC_AND_BYTES = 14  # magic[8], version, flags, bits, ordering, reconstruction, reserved
FLOATS = 40           # weight, box_min[3], step
GEOMETRY_ONLY = 1     # flag bit: a u64 connectivity hash follows the header


def skip_varint(data, at):
    """The offset past the varint at `at`, or None when the file ends in it."""
    while at < len(data):
        byte = data[at]
        at += 1
        if byte < 0x80:
            return at
    return None


def header_end(data):
    """The offset of the header's CRC, or None when the header is cut short."""
    at = skip_varint(data, MAGIC_AND_BYTES)            # n
    at = at and skip_varint(data, at)                  # faces
    at = at and skip_varint(data, at + FLOATS)         # anchors
    at = at and skip_varint(data, at)                  # chunks
    at = at and skip_varint(data, at)                  # sections
    return at if at and at + 4 <= len(data) else None


def checksum_offsets(data):
    """(checksum offset, covered start, covered end) of the header's CRC and
    of every whole frame's, in file order."""
    crc_at = header_end(data)
    if crc_at is None:
        return []
    found = [(crc_at, 0, crc_at)]
    at = crc_at + 4
    if data[9] & GEOMETRY_ONLY:
        at += 8  # the connectivity hash, not framed
    while at + 8 <= len(data):
        (length,) = struct.unpack_from("<I", data, at)
        if length > len(data) - at - 8:
            break
        found.append((at + 4, at + 8, at + 8 + length))
        at += 8 + length
    return found


def reseal(data):
    data = bytearray(data)
    for crc_at, begin, end in checksum_offsets(data):
        struct.pack_into("<I", data, crc_at, zlib.crc32(bytes(data[begin:end])))
    return bytes(data)


def main(argv):
    args = [a for a in argv if a != "--options-byte"]
    if len(args) != 2:
        sys.exit(__doc__)
    with open(args[0], "rb") as f:
        data = f.read()
    if "--options-byte" in argv:
        data = data[1:]
    with open(args[1], "wb") as f:
        f.write(reseal(data))


if __name__ == "__main__":
    main(sys.argv[1:])
