#!/usr/bin/env python3
"""Runs the gab CLI on hostile inputs under address-space caps (RLIMIT_AS, as
`ulimit -v`) and holds it to: exit 0, or exit 1 with one `gab: error:` line
last on stderr; never a signal (no terminate/SIGABRT), never a hang.

    tests/hostile/cli_under_caps.py --gab build/apps/gab [--caps 200,400,800] \\
        [--meshes DIR ...] [--gab-files DIR ...] [--big]

The inputs: files it writes (OFF, PLY and OBJ headers claiming billions of
elements, truncated and garbage files, a PLY with a huge list count),
bunny-small from ../shared/meshes when present, every .off/.ply/.obj under
each --meshes folder (e.g. /usr/share/assimp/models of assimp-testmodels),
every .gab in each --gab-files folder; with --big also /dev/zero and a 2 GB
sparse OFF whose header claims 100M vertices (slow: seconds each). Mesh
inputs run `compress`, `factor` and `diff`; .gab inputs (and the --big ones)
`info` and `decompress`. Prints
one line per violation and a summary; exits 1 when any.
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from capped import address_space_cap, one_error_line_last  # noqa: E402
MESH_EXTENSIONS = (".off", ".ply", ".obj")


def write_hostile_meshes(folder):
    """Small files whose headers or bodies lie; returns their paths."""
    files = {
        "claims.off": b"OFF\n2000000000 2000000000 0\n0 0 0\n1 0 0\n",
        "claims-negative.off": b"OFF\n-5 -7 0\n",
        "claims.ply": b"ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
                      b"property float z\nelement face 2000000000\nproperty list uchar int vertex_indices\n"
                      b"end_header\n0 0 0\n",
        "claims-binary.ply": b"ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
                             b"property float x\nproperty float y\nproperty float z\nelement face 1\n"
                             b"property list uint int vertex_indices\nend_header\n" + bytes(24),
        "huge-list.ply": b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         b"property float y\nproperty float z\nelement face 1\n"
                         b"property list uint int vertex_indices\nend_header\n" + bytes(36) +
                         b"\xff\xff\xff\x7f" + bytes(12),
        "far-index.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2000000000\n",
        "huge-coordinates.off": b"OFF\n3 1 0\n1e308 0 0\n-1e308 0 0\n0 1e308 0\n3 0 1 2\n",
        "truncated.off": b"OFF\n4 2 0\n0 0 0\n1 0",
        "garbage.ply": os.urandom(4096),
        "garbage.obj": bytes(range(256)) * 16,
        "empty.off": b"",
    }
    paths = []
    for name, data in files.items():
        path = os.path.join(folder, name)
        with open(path, "wb") as f:
            f.write(data)
        paths.append(path)
    return paths


def write_sparse_claim(folder):
    path = os.path.join(folder, "sparse-2gb.off")
    with open(path, "wb") as f:
        f.write(b"OFF\n100000000 200000000 0\n")
        f.truncate(2 << 30)
    return path


def listed(folders, extensions):
    for folder in folders:
        for root, _, names in os.walk(folder):
            for name in sorted(names):
                if name.lower().endswith(extensions):
                    yield os.path.join(root, name)


def run(argv, cap_mb, seconds):
    try:
        proc = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              preexec_fn=address_space_cap(cap_mb), timeout=seconds)
    except subprocess.TimeoutExpired:
        return "no answer within %d s" % seconds
    stderr = proc.stderr.decode("utf-8", "replace")
    lines = [line for line in stderr.splitlines() if line]
    if proc.returncode == 0:
        return None
    if proc.returncode != 1:
        return "exit %d: %s" % (proc.returncode, lines[-1] if lines else "(nothing on stderr)")
    if not one_error_line_last(stderr):
        return "exit 1 without one error line last: %r" % lines[-3:]
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--gab", required=True)
    parser.add_argument("--caps", default="200,400,800", help="address-space caps in MB, comma-separated")
    parser.add_argument("--meshes", action="append", default=[])
    parser.add_argument("--gab-files", action="append", default=[])
    parser.add_argument("--big", action="store_true")
    parser.add_argument("--seconds", type=int, default=120, help="a run taking longer is a hang")
    args = parser.parse_args()
    caps = [int(c) for c in args.caps.split(",")]

    with tempfile.TemporaryDirectory() as tmp:
        meshes = write_hostile_meshes(tmp)
        bunny = os.path.join(HERE, "..", "..", "..", "shared", "meshes", "bunny-small.off")
        if os.path.exists(bunny):
            meshes.append(bunny)
        meshes += list(listed(args.meshes, MESH_EXTENSIONS))
        gabs = list(listed(args.gab_files, (".gab",)))
        if os.path.exists(bunny):
            made = os.path.join(tmp, "bunny-small.gab")
            subprocess.run([args.gab, "compress", "-i", bunny, "-o", made], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            gabs.append(made)
        big = [write_sparse_claim(tmp), "/dev/zero"] if args.big else []

        out_gab, out_off = os.path.join(tmp, "out.gab"), os.path.join(tmp, "out.off")
        jobs = []
        for path in meshes + big:
            jobs.append((path, ["compress", "-i", path, "-o", out_gab]))
            jobs.append((path, ["factor", path]))
            jobs.append((path, ["diff", path, path, "--samples", "1000"]))
        for path in gabs + big:
            jobs.append((path, ["info", path]))
            jobs.append((path, ["decompress", "-i", path, "-o", out_off]))

        violations = []
        runs = 0
        for cap_mb in caps:
            for path, command in jobs:
                problem = run([args.gab] + command, cap_mb, args.seconds)
                runs += 1
                if problem:
                    violations.append("%s %s under %d MB: %s" % (command[0], path, cap_mb, problem))
    for line in violations:
        print("cli_under_caps: " + line)
    print("cli_under_caps: %d runs (%d inputs x their commands x caps %s MB): %d violations"
          % (runs, len(meshes) + len(big) + len(gabs), args.caps, len(violations)))
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
