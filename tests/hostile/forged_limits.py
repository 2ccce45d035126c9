#!/usr/bin/env python3
"""Holds `gab decompress` to the forged-file bound: every .gab of at most
--max-bytes (1 KB) decodes or fails with one `gab: error:` line within
--memory-mb of address space (100; RLIMIT_AS, as `ulimit -v`) and, with
--seconds, that much wall time. A fuzzer's corpus is the usual input:

    tests/hostile/forged_limits.py --gab build/apps/gab --options-byte \\
        --seconds 1 build-fuzz/corpus-gab tests/fuzz/corpus/gab

Each file is resealed first (tests/fuzz/reseal_gab.py: its checksums
rewritten) so what a fuzzer built with GAB_FUZZ_SKIP_CHECKSUMS mutated reaches
the same decoder paths here; --options-byte drops the gab fuzzer's leading
byte. Prints one line per violation and a summary (files, decoded, failed,
the largest peak RSS and wall time); exits 1 when any file broke the bound.
Time is reported, and enforced only when --seconds is given (a loaded
machine makes a timed check flaky; ctest runs this without it).
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "fuzz"))
from capped import address_space_cap, one_error_line_last  # noqa: E402
from reseal_gab import reseal  # noqa: E402


def inputs(paths, max_bytes):
    for path in paths:
        names = [os.path.join(path, n) for n in sorted(os.listdir(path))] if os.path.isdir(path) else [path]
        for name in names:
            if os.path.isfile(name) and os.path.getsize(name) <= max_bytes:
                yield name


def run_capped(argv, memory_mb):
    """(exit status, stderr, wall seconds, peak RSS in MB) of argv under RLIMIT_AS."""
    start = time.monotonic()
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            preexec_fn=address_space_cap(memory_mb))
    stderr = proc.stderr.read().decode("utf-8", "replace")
    proc.stderr.close()
    _, status, usage = os.wait4(proc.pid, 0)
    seconds = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    return code, stderr, seconds, usage.ru_maxrss / 1024.0


def one_line_failure(stderr):
    """A failure within the bound: one error line, and not the CLI's "out of memory"."""
    return one_error_line_last(stderr) and "out of memory" not in stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--gab", required=True)
    parser.add_argument("--memory-mb", type=int, default=100)
    parser.add_argument("--seconds", type=float, default=0, help="enforce this wall time per file (0: report only)")
    parser.add_argument("--max-bytes", type=int, default=1024)
    parser.add_argument("--options-byte", action="store_true", help="drop each file's leading byte (the fuzzer's)")
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args()

    files = decoded = failed = 0
    violations = []
    worst_rss = worst_seconds = 0.0
    worst_name = ""
    with tempfile.TemporaryDirectory() as tmp:
        sealed = os.path.join(tmp, "in.gab")
        for name in inputs(args.paths, args.max_bytes + (1 if args.options_byte else 0)):
            with open(name, "rb") as f:
                data = f.read()
            with open(sealed, "wb") as f:
                f.write(reseal(data[1:] if args.options_byte else data))
            code, stderr, seconds, rss = run_capped(
                [args.gab, "decompress", "-i", sealed, "-o", os.path.join(tmp, "out.off")], args.memory_mb)
            files += 1
            worst_rss = max(worst_rss, rss)
            if seconds > worst_seconds:
                worst_seconds, worst_name = seconds, name
            if code == 0:
                decoded += 1
            elif code == 1 and one_line_failure(stderr):
                failed += 1
            else:
                last = stderr.strip().splitlines()[-1] if stderr.strip() else "(nothing on stderr)"
                violations.append("%s: exit %d: %s" % (name, code, last))
            if args.seconds > 0 and seconds > args.seconds:
                violations.append("%s: %.2f s" % (name, seconds))
    for line in violations:
        print("forged_limits: " + line)
    print("forged_limits: %d files of at most %d bytes: %d decoded, %d failed with one line, %d over the bound "
          "(%d MB of address space%s); peak RSS %.1f MB, slowest %.3f s (%s)"
          % (files, args.max_bytes, decoded, failed, len(violations), args.memory_mb,
             ", %.2f s" % args.seconds if args.seconds > 0 else "", worst_rss, worst_seconds,
             os.path.basename(worst_name)))
    if files == 0:
        print("forged_limits: no input files")
        return 1
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
